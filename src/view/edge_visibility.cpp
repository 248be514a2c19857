// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact edge visibility (notation in edge_visibility.h).
#include "view/edge_visibility.h"

#include <algorithm>
#include <cmath>

#include <exbsp/view/pipeline.h>
#include "geom/soup_cache.h"
#include "view/clip_stage.h"

namespace exbsp::view {

using geom::crossing;
using geom::det_value;

geom::hpoint viewer_of(const frame& f) {
  if (f.view.is_parallel())
    return {-f.view.direction.x, -f.view.direction.y, -f.view.direction.z, 0};
  return {f.view.cam.eye.x, f.view.cam.eye.y, f.view.cam.eye.z, 1};
}

namespace {

/// Window-space boxes of the occluding triangles in square cells over the viewport (CSR).
class occluder_grid {
 public:
  occluder_grid(const frame& f, const geom::view_features& features) : vp_(f.view.vp) {
    const double area = static_cast<double>(vp_.width) * vp_.height;
    cell_ = std::max(4.0, std::sqrt(area / 16384.0));
    nx_ = std::max(1, static_cast<int>(std::ceil(vp_.width / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(vp_.height / cell_)));
    const triangle_soup& s = f.soup;
    const mat4 pm = f.view.projection * f.view.model_view;
    // Window position of every vertex; w <= 0: at or behind the eye.
    std::vector<window_point>& win = win_;
    win.resize(s.vertices.size());
    std::vector<char> ahead(s.vertices.size());
    for (std::size_t i = 0; i < s.vertices.size(); ++i) {
      const hpoint h = pm * to_point(s.vertices[i]);
      ahead[i] = h.w > 0 && std::isfinite(h.w);
      if (ahead[i]) win[i] = to_window(vp_, h.x / h.w, h.y / h.w, h.z / h.w);
    }
    soup_ = &s;
    std::vector<std::array<int, 4>> range(s.triangles.size(), {0, -1, 0, -1});
    screened_.assign(s.triangles.size(), 0);
    side_margin_.assign(3 * s.triangles.size(), 0.0);
    std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      if (features.facing[t] == 0) continue;  // edge-on or degenerate: hides nothing
      const auto& v = s.triangles[t].v;
      const int in_front = ahead[v[0]] + ahead[v[1]] + ahead[v[2]];
      if (in_front == 0) continue;  // behind the eye: no segment to the eye meets it
      if (in_front < 3) {
        everywhere_.push_back(static_cast<std::uint32_t>(t));
        continue;
      }
      double x0 = win[v[0]].x, x1 = x0, y0 = win[v[0]].y, y1 = y0;
      for (int k = 1; k < 3; ++k) {
        x0 = std::min(x0, win[v[k]].x);
        x1 = std::max(x1, win[v[k]].x);
        y0 = std::min(y0, win[v[k]].y);
        y1 = std::max(y1, win[v[k]].y);
      }
      const std::array<int, 4> r = cells_of(x0, x1, y0, y1);
      if (r[1] < r[0] || r[3] < r[2]) continue;  // outside the viewport
      range[t] = r;
      // Images this far out are kept without the image test (their rounding is not small).
      const double far = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
      screened_[t] = far < max_screened;
      // Read only for screened triangles, whose sides are shorter than 2 max_screened: their
      // squares cannot overflow, so a plain root does (std::hypot's guard costs a libm call).
      for (int k = 0; k < 3 && screened_[t]; ++k) {
        const window_point& u = win[v[k]];
        const window_point& w = win[v[(k + 1) % 3]];
        const double dx = w.x - u.x, dy = w.y - u.y;
        side_margin_[3 * t + static_cast<std::size_t>(k)] = margin * std::sqrt(dx * dx + dy * dy);
      }
      for (int cy = r[2]; cy <= r[3]; ++cy)
        for (int cx = r[0]; cx <= r[1]; ++cx) ++count[index(cx, cy) + 1];
    }
    for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
    start_ = count;
    items_.resize(count.back());
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      const std::array<int, 4>& r = range[t];
      for (int cy = r[2]; cy <= r[3]; ++cy)
        for (int cx = r[0]; cx <= r[1]; ++cx)
          items_[count[index(cx, cy)]++] = static_cast<std::uint32_t>(t);
    }
    stamp_.assign(s.triangles.size(), 0);
  }

  /// The candidates for the window segment (a, b): each triangle once, without those whose
  /// image lies apart from the segment's (image_apart).
  void gather(const window_point& a, const window_point& b, std::vector<std::uint32_t>& out) {
    out.clear();
    ++round_;
    for (std::uint32_t t : everywhere_) take(t, out);
    seg_a_ = a;
    seg_b_ = b;
    seg_len_ = std::hypot(b.x - a.x, b.y - a.y);
    seg_screened_ =
        std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)}) < max_screened;
    const double y0 = std::min(a.y, b.y), y1 = std::max(a.y, b.y);
    const std::array<int, 4> rows = cells_of(std::min(a.x, b.x), std::max(a.x, b.x), y0, y1);
    for (int cy = rows[2]; cy <= rows[3]; ++cy) {
      // The part of the segment within this row of cells (with the margin).
      const double ry0 = vp_.y + cy * cell_ - margin, ry1 = vp_.y + (cy + 1) * cell_ + margin;
      double xa = std::min(a.x, b.x), xb = std::max(a.x, b.x);
      if (b.y != a.y) {
        const double ta = std::clamp((ry0 - a.y) / (b.y - a.y), 0.0, 1.0);
        const double tb = std::clamp((ry1 - a.y) / (b.y - a.y), 0.0, 1.0);
        const double pa = a.x + ta * (b.x - a.x), pb = a.x + tb * (b.x - a.x);
        xa = std::min(pa, pb);
        xb = std::max(pa, pb);
      }
      const std::array<int, 4> r = cells_of(xa, xb, ry0 + margin, ry0 + margin);
      for (int cx = r[0]; cx <= r[1]; ++cx)
        for (std::uint32_t k = start_[index(cx, cy)]; k < start_[index(cx, cy) + 1]; ++k)
          take(items_[k], out);
    }
  }

 private:
  static constexpr double margin = 0.01;  ///< pixels: far above the projection's rounding

  std::size_t index(int cx, int cy) const { return static_cast<std::size_t>(cy) * nx_ + cx; }

  /// Cells met by the window box [x0, x1] x [y0, y1] grown by the margin, clamped to the
  /// grid: {cx0, cx1, cy0, cy1}, empty when the box misses the viewport.
  std::array<int, 4> cells_of(double x0, double x1, double y0, double y1) const {
    auto cell = [&](double v, double origin, int n) {
      const double c = std::floor((v - origin) / cell_);
      return static_cast<int>(std::clamp(c, -1.0, static_cast<double>(n)));
    };
    int cx0 = cell(x0 - margin, vp_.x, nx_), cx1 = cell(x1 + margin, vp_.x, nx_);
    int cy0 = cell(y0 - margin, vp_.y, ny_), cy1 = cell(y1 + margin, vp_.y, ny_);
    if (cx1 < 0 || cy1 < 0 || cx0 >= nx_ || cy0 >= ny_) return {0, -1, 0, -1};
    return {std::max(cx0, 0), std::min(cx1, nx_ - 1), std::max(cy0, 0), std::min(cy1, ny_ - 1)};
  }

  void take(std::uint32_t t, std::vector<std::uint32_t>& out) {
    if (stamp_[t] == round_) return;
    stamp_[t] = round_;
    if (seg_screened_ && screened_[t] && image_apart(t)) return;
    out.push_back(t);
  }

  /// True when a line (the segment's, or one through a side of triangle t's image) has the
  /// segment's image on one side and t's on the other, more than `margin` apart. A point of
  /// the edge that t hides projects into t's image, so then t hides none of it. A test in
  /// doubles, hence the margin: the images are rounded by far less than it (max_screened).
  bool image_apart(std::uint32_t t) const {
    const auto& v = soup_->triangles[t].v;
    const window_point p[3] = {win_[v[0]], win_[v[1]], win_[v[2]]};
    const window_point &a = seg_a_, &b = seg_b_;
    // Signed distance times the length of (u, w), of q from the line u -> w.
    auto side = [](const window_point& u, const window_point& w, const window_point& q) {
      return (w.x - u.x) * (q.y - u.y) - (w.y - u.y) * (q.x - u.x);
    };
    const double len = seg_len_;
    if (len > 0) {
      const double s0 = side(a, b, p[0]), s1 = side(a, b, p[1]), s2 = side(a, b, p[2]);
      const double m = margin * len;
      if ((s0 > m && s1 > m && s2 > m) || (s0 < -m && s1 < -m && s2 < -m)) return true;
    }
    const double turn = side(p[0], p[1], p[2]);
    if (turn == 0) return false;
    for (int k = 0; k < 3; ++k) {
      const window_point& u = p[k];
      const window_point& w = p[(k + 1) % 3];
      const double m = side_margin_[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(k)];
      // Outside the side u -> w: the side away from the third corner.
      const double sa = turn > 0 ? -side(u, w, a) : side(u, w, a);
      const double sb = turn > 0 ? -side(u, w, b) : side(u, w, b);
      if (sa > m && sb > m) return true;
    }
    return false;
  }

  /// Window coordinates (pixels) beyond which the image test is not used: there a double's
  /// rounding stays under 1e-9 pixel, far below the margin.
  static constexpr double max_screened = 1e6;

  viewport vp_;
  const triangle_soup* soup_ = nullptr;
  std::vector<window_point> win_;
  std::vector<char> screened_;  ///< per triangle: its image is small enough for image_apart
  window_point seg_a_, seg_b_;
  double seg_len_ = 0;  ///< the segment's image length
  /// margin times the image length of side k of triangle t, at 3 t + k (screened triangles).
  std::vector<double> side_margin_;
  bool seg_screened_ = false;
  double cell_ = 8;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> start_, items_, everywhere_;
  std::vector<std::uint64_t> stamp_;
  std::uint64_t round_ = 0;
};

struct hidden_interval {
  crossing lo, hi;
};

/// The interval of the edge (A, B) that triangle t hides, if it has positive length.
bool hidden_by(const triangle_soup& s, const geom::view_features& features, std::uint32_t t,
               const geom::hpoint& eye, const geom::hpoint& A, const geom::hpoint& B,
               hidden_interval& out) {
  const auto& v = s.triangles[t].v;
  const geom::hpoint p[3] = {geom::point_of(s.vertices[v[0]]), geom::point_of(s.vertices[v[1]]),
                             geom::point_of(s.vertices[v[2]])};
  const int m = features.facing[t];
  crossing lo = crossing::at_zero(), hi = crossing::at_one();
  // One constraint m f(p(t)) >= 0 (> 0 when strict): narrows [lo, hi]; false when nothing of
  // positive length is left.
  auto narrow = [&](const det_value& fa, const det_value& fb, bool strict) {
    const int sa = m * fa.sign(), sb = m * fb.sign();
    if (sa == 0 && sb == 0) return !strict;
    if (sa <= 0 && sb <= 0) return false;
    if (sa >= 0 && sb >= 0) return true;
    crossing c = crossing::between(fa, fb);
    if (sa < 0) {
      if (geom::compare(c, lo) > 0) lo = std::move(c);
    } else if (geom::compare(c, hi) < 0) {
      hi = std::move(c);
    }
    return geom::compare(lo, hi) < 0;
  };
  if (!narrow(det_value(p[0], p[1], p[2], A), det_value(p[0], p[1], p[2], B), true)) return false;
  for (int k = 0; k < 3; ++k) {
    const geom::hpoint& u = p[k];
    const geom::hpoint& w = p[(k + 1) % 3];
    const bool strict = features.feature_sides[t] >> k & 1u;
    if (!narrow(det_value(eye, u, w, A), det_value(eye, u, w, B), strict)) return false;
  }
  out = {std::move(lo), std::move(hi)};
  return true;
}

}  // namespace

std::shared_ptr<geom::soup_cache> new_soup_cache() { return std::make_shared<geom::soup_cache>(); }

edge_visibility visible_runs(const frame& f, double crease_deg) {
  edge_visibility out;
  const geom::hpoint eye = viewer_of(f);
  const std::shared_ptr<const geom::edge_graph> graph =
      f.soup_products
          ? f.soup_products->edge_graph_for(f.soup, crease_deg)
          : std::make_shared<const geom::edge_graph>(geom::edge_graph_of(f.soup, crease_deg));
  out.features = geom::find_feature_edges(*graph, f.soup, eye);
  const geom::view_features& features = out.features;
  const triangle_soup& s = f.soup;
  occluder_grid grid(f, features);
  const mat4 pm = f.view.projection * f.view.model_view;
  std::vector<std::uint32_t> candidates;
  std::vector<hidden_interval> hidden;
  std::vector<std::pair<double, double>> merged;
  std::vector<std::pair<const crossing*, const crossing*>> runs;
  for (std::size_t i = 0; i < features.edges.size(); ++i) {
    const geom::feature_edge& e = features.edges[i];
    const vec3d& va = s.vertices[e.a];
    const vec3d& vb = s.vertices[e.b];
    hpoint ca, cb;
    if (!clip_segment_to_view_volume(pm * to_point(va), pm * to_point(vb), ca, cb)) continue;
    const window_point wa = to_window(f.view.vp, ca.x / ca.w, ca.y / ca.w, ca.z / ca.w);
    const window_point wb = to_window(f.view.vp, cb.x / cb.w, cb.y / cb.w, cb.z / cb.w);
    grid.gather(wa, wb, candidates);
    const geom::hpoint A = geom::point_of(va), B = geom::point_of(vb);
    merged.clear();
    runs.clear();
    {
      const geom::rounding_guard guard;
      hidden.clear();
      hidden_interval h;
      for (std::uint32_t t : candidates) {
        if (t == e.tris[0] || t == e.tris[1]) continue;  // the edge lies in their planes
        if (hidden_by(s, features, t, eye, A, B, h)) hidden.push_back(std::move(h));
      }
      std::sort(hidden.begin(), hidden.end(),
                [](const hidden_interval& x, const hidden_interval& y) {
                  return geom::compare(x.lo, y.lo) < 0;
                });
      // Union: each merged interval keeps the first lo and the largest hi that reaches it.
      for (const hidden_interval& x : hidden) {
        if (!runs.empty() && geom::compare(x.lo, *runs.back().second) <= 0) {
          if (geom::compare(x.hi, *runs.back().second) > 0) runs.back().second = &x.hi;
        } else {
          runs.push_back({&x.lo, &x.hi});
        }
      }
    }
    // Doubles for the drawing, rounded to nearest (outside the guard's upward rounding).
    for (const auto& [lo, hi] : runs) merged.push_back({lo->to_double(), hi->to_double()});
    double at = 0;
    auto emit = [&](double t0, double t1, bool visible) {
      if (t1 > t0) out.runs.push_back({static_cast<std::uint32_t>(i), t0, t1, visible});
    };
    for (const auto& [lo, hi] : merged) {
      emit(at, lo, true);
      emit(lo, hi, false);
      at = hi;
    }
    emit(at, 1, true);
  }
  return out;
}

}  // namespace exbsp::view
