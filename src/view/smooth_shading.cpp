// SPDX-License-Identifier: LGPL-3.0-or-later
// Smooth (Gouraud) shading (notation in smooth_shading.h).
#include "view/smooth_shading.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <exbsp/core/errors.h>
#include "view/lighting.h"

namespace exbsp::view {

namespace {

point3 to_p(const vec3d& v) { return {v[0], v[1], v[2]}; }

/// The vertices of the soup welded by exact position: weld[v] is the first vertex index with
/// v's coordinates (bitwise, -0 and 0 apart: a weld never merges distinct doubles).
std::vector<std::uint32_t> welded(const triangle_soup& soup) {
  struct key_hash {
    std::size_t operator()(const vec3d& p) const {
      std::uint64_t h = 0x9e3779b97f4a7c15ull;
      for (double c : p) {
        std::uint64_t bits;
        std::memcpy(&bits, &c, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ull;
        h ^= h >> 29;
      }
      return static_cast<std::size_t>(h);
    }
  };
  struct key_equal {
    bool operator()(const vec3d& a, const vec3d& b) const {
      return std::memcmp(a.data(), b.data(), sizeof a) == 0;
    }
  };
  std::unordered_map<vec3d, std::uint32_t, key_hash, key_equal> first;
  first.reserve(soup.vertices.size());
  std::vector<std::uint32_t> weld(soup.vertices.size());
  for (std::uint32_t v = 0; v < soup.vertices.size(); ++v)
    weld[v] = first.emplace(soup.vertices[v], v).first->second;
  return weld;
}

}  // namespace

void smooth_corner_colors(frame& f) {
  const lighting_settings& s = f.settings.lighting;
  if (!f.tree) throw usage_error("lighting: smooth shading needs the tree (the build stage)");
  const triangle_soup& soup = f.soup;
  const std::size_t nt = soup.triangles.size();
  // Area vectors and unit normals of the input triangles.
  std::vector<vector3> area(nt), unit(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& v = soup.triangles[t].v;
    const point3 a = to_p(soup.vertices[v[0]]), b = to_p(soup.vertices[v[1]]),
                 c = to_p(soup.vertices[v[2]]);
    area[t] = 0.5 * cross(b - a, c - a);
    const double len = length(area[t]);
    unit[t] = len > 0 && std::isfinite(len) ? (1.0 / len) * area[t] : vector3{0, 0, 0};
  }
  // Triangles around each welded vertex (a counting sort: offsets, then entries).
  const std::vector<std::uint32_t> weld = welded(soup);
  std::vector<std::uint32_t> start(soup.vertices.size() + 1, 0);
  for (const soup_triangle& t : soup.triangles)
    for (std::uint32_t v : t.v) ++start[weld[v] + 1];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<std::uint32_t> around(start.back());
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::uint32_t t = 0; t < nt; ++t)
      for (std::uint32_t v : soup.triangles[t].v) around[next[weld[v]]++] = t;
  }
  const double cos_crease = std::cos(s.crease_deg * 3.14159265358979323846 / 180);
  // N(t, corner k), made when a fragment of t is drawn (most triangles of a big mesh are not).
  std::vector<std::array<vector3, 3>> corner_normal(nt);
  std::vector<char> made(nt, 0);
  const auto normals_of = [&](std::uint32_t t) -> const std::array<vector3, 3>& {
    if (!made[t]) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = weld[soup.triangles[t].v[k]];
        vector3 sum{0, 0, 0};
        for (std::uint32_t j = start[v]; j < start[v + 1]; ++j) {
          const std::uint32_t u = around[j];
          if (u == t || dot(unit[u], unit[t]) >= cos_crease) sum = sum + area[u];
        }
        const double len = length(sum);
        corner_normal[t][k] = len > 0 && std::isfinite(len) ? (1.0 / len) * sum : unit[t];
      }
      made[t] = 1;
    }
    return corner_normal[t];
  };
  f.corner_colors.assign(f.fragments.size(), {});
  for (std::uint32_t idx : f.order) {
    const fragment_d& fr = f.fragments.at(idx);
    const std::uint32_t t = f.tree->fragment_source(idx);
    const std::array<vector3, 3>& n = normals_of(t);
    const auto& tv = soup.triangles[t].v;
    const point3 a = to_p(soup.vertices[tv[0]]), b = to_p(soup.vertices[tv[1]]),
                 c = to_p(soup.vertices[tv[2]]);
    const vector3 m = cross(b - a, c - a);
    const double mm = dot(m, m);
    // Two-sided: the fragment's flat normal decides for its three corners (lighting.h).
    const vector3 flat = shading_normal(fr, f.view, false);
    const vector3 facing = shading_normal(fr, f.view, s.two_sided);
    const double flip = dot(flat, facing) < 0 ? -1 : 1;
    for (int k = 0; k < 3; ++k) {
      const point3 p = to_p(fr.v[k]);
      vector3 normal = facing;  // a degenerate source: the flat normal
      if (mm > 0 && std::isfinite(mm)) {
        // Barycentric coordinates of p in (a, b, c) from the sub-triangles' area vectors.
        const double la = dot(cross(b - p, c - p), m) / mm, lb = dot(cross(c - p, a - p), m) / mm;
        const double lc = 1 - la - lb;
        const vector3 sum = la * n[0] + lb * n[1] + lc * n[2];
        const double len = length(sum);
        if (len > 0 && std::isfinite(len)) normal = (flip / len) * sum;
      }
      f.corner_colors[idx][k] = lit_color(f.color_of(fr.face), normal, p, f.view, s);
    }
  }
}

perspective_weights::perspective_weights(const fragment_d& fragment, const view_setup& view) {
  const mat4 m = view.projection * view.model_view;
  const viewport& vp = view.vp;
  for (int k = 0; k < 3; ++k) {
    const hpoint c = m * to_p(fragment.v[k]);
    // Window x = vp.x + (X / W + 1) width / 2, times W; the same for y.
    w_[k] = c.w;
    xw_[k] = (vp.x + 0.5 * vp.width) * c.w + 0.5 * vp.width * c.x;
    yw_[k] = (vp.y + 0.5 * vp.height) * c.w + 0.5 * vp.height * c.y;
  }
}

bool perspective_weights::at(double x, double y, std::array<double, 3>& k) const {
  // The point of the fragment seen at (x, y) is sum b_k P_k with sum b_k (xw_k - x w_k) = 0,
  // sum b_k (yw_k - y w_k) = 0 and sum b_k = 1: b is the cross product of the two rows.
  const std::array<double, 3> r1{xw_[0] - x * w_[0], xw_[1] - x * w_[1], xw_[2] - x * w_[2]};
  const std::array<double, 3> r2{yw_[0] - y * w_[0], yw_[1] - y * w_[1], yw_[2] - y * w_[2]};
  const double b0 = r1[1] * r2[2] - r1[2] * r2[1], b1 = r1[2] * r2[0] - r1[0] * r2[2],
               b2 = r1[0] * r2[1] - r1[1] * r2[0];
  const double sum = b0 + b1 + b2;
  if (!(std::abs(sum) > 0) || !std::isfinite(sum)) return false;
  k = {b0 / sum, b1 / sum, b2 / sum};
  return true;
}

corner_interpolator::corner_interpolator(const fragment_d& fragment,
                                         const std::array<rgb8, 3>& colors, const view_setup& view)
    : weights_(fragment, view), colors_(colors) {}

rgb8 corner_interpolator::at(double x, double y, rgb8 fallback) const {
  std::array<double, 3> k;
  if (!weights_.at(x, y, k)) return fallback;
  const auto channel = [&](std::uint8_t c0, std::uint8_t c1, std::uint8_t c2) {
    const double v = k[0] * c0 + k[1] * c1 + k[2] * c2;
    return static_cast<std::uint8_t>(std::lround(std::min(255.0, std::max(0.0, v))));
  };
  return {channel(colors_[0].r, colors_[1].r, colors_[2].r),
          channel(colors_[0].g, colors_[1].g, colors_[2].g),
          channel(colors_[0].b, colors_[1].b, colors_[2].b)};
}

}  // namespace exbsp::view
