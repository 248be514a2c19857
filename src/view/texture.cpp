// SPDX-License-Identifier: LGPL-3.0-or-later
// Textures: sampling (notation in exbsp/view/texture.h) and the fragments' texture coordinates
// (view/texture_uvs.h).
#include <exbsp/view/texture.h>

#include <cmath>
#include <gmpxx.h>
#include <string>

#include <exbsp/core/errors.h>
#include "geom/rational.h"
#include "view/texture_uvs.h"

namespace exbsp::view {

texture::texture(image texels_in, filter_kind filter_in, wrap_kind wrap_in)
    : texels(std::move(texels_in)), filter(filter_in), wrap(wrap_in) {
  const std::vector<std::uint8_t>& d = texels.data();
  if (d.empty()) throw usage_error("texture: the image is empty");
  std::uint64_t sum[3] = {0, 0, 0};
  for (std::size_t k = 0; k < d.size(); ++k) sum[k % 3] += d[k];
  const std::uint64_t n = d.size() / 3;
  const auto mean_of = [&](int c) { return static_cast<std::uint8_t>((sum[c] + n / 2) / n); };
  mean = {mean_of(0), mean_of(1), mean_of(2)};
}

namespace {

/// Index i wrapped into 0..n-1 (repeat) or clamped to it.
int wrapped(long long i, int n, texture::wrap_kind wrap) {
  if (wrap == texture::wrap_kind::clamp) return static_cast<int>(i < 0 ? 0 : i >= n ? n - 1 : i);
  const long long m = i % n;
  return static_cast<int>(m < 0 ? m + n : m);
}

/// floor(x) as an integer, x limited to +-2^52 first (far outside any texture: repeat keeps
/// the phase of such huge coordinates only approximately, clamp exactly).
long long floor_index(double x) {
  constexpr double limit = 4503599627370496.0;
  return static_cast<long long>(std::floor(std::fmax(-limit, std::fmin(limit, x))));
}

}  // namespace

rgb8 texture::sample(double u, double v) const {
  const int w = texels.width(), h = texels.height();
  if (!std::isfinite(u) || !std::isfinite(v)) return texels.pixel(0, 0);
  if (filter == filter_kind::nearest)
    return texels.pixel(wrapped(floor_index(u * w), w, wrap), wrapped(floor_index(v * h), h, wrap));
  const double a = u * w - 0.5, b = v * h - 0.5;
  const long long i0 = floor_index(a), j0 = floor_index(b);
  const double alpha = a - std::floor(a), beta = b - std::floor(b);
  const int ia = wrapped(i0, w, wrap), ib = wrapped(i0 + 1, w, wrap);
  const int ja = wrapped(j0, h, wrap), jb = wrapped(j0 + 1, h, wrap);
  const rgb8 t00 = texels.pixel(ia, ja), t10 = texels.pixel(ib, ja), t01 = texels.pixel(ia, jb),
             t11 = texels.pixel(ib, jb);
  const auto channel = [&](std::uint8_t c00, std::uint8_t c10, std::uint8_t c01, std::uint8_t c11) {
    const double value = (1 - alpha) * (1 - beta) * c00 + alpha * (1 - beta) * c10 +
                         (1 - alpha) * beta * c01 + alpha * beta * c11;
    return static_cast<std::uint8_t>(std::lround(std::fmin(255.0, std::fmax(0.0, value))));
  };
  return {channel(t00.r, t10.r, t01.r, t11.r), channel(t00.g, t10.g, t01.g, t11.g),
          channel(t00.b, t10.b, t01.b, t11.b)};
}

const char* to_string(texture::filter_kind f) {
  return f == texture::filter_kind::nearest ? "nearest" : "linear";
}

const char* to_string(texture::wrap_kind w) {
  return w == texture::wrap_kind::repeat ? "repeat" : "clamp";
}

namespace {

using q3 = std::array<mpq_class, 3>;

q3 exact_of(const vec3d& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }

/// The texture coordinates at point p of the plane of triangle (a, b, c) with corner UVs `uv`:
/// barycentric coordinates from the 2D projection that drops the largest component of the
/// normal (exact: p lies in the plane), the UVs interpolated exactly, each rounded once.
/// A degenerate triangle (no fragment comes from one): corner a's UV.
vec2d uv_at(const q3& p, const std::array<q3, 3>& t, const std::array<vec2d, 3>& uv) {
  const q3 e1 = {t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
  const q3 e2 = {t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
  const q3 n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0]};
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (abs(n[k]) > abs(n[drop])) drop = k;
  if (sgn(n[drop]) == 0) return uv[0];
  const int x = (drop + 1) % 3, y = (drop + 2) % 3;  // n[drop] = e1[x] e2[y] - e1[y] e2[x]
  const mpq_class px = p[x] - t[0][x], py = p[y] - t[0][y];
  const mpq_class lb = (px * e2[y] - py * e2[x]) / n[drop];
  const mpq_class lc = (e1[x] * py - e1[y] * px) / n[drop];
  const mpq_class la = 1 - lb - lc;
  vec2d out;
  for (int c = 0; c < 2; ++c) {
    const mpq_class value =
        la * mpq_class(uv[0][c]) + lb * mpq_class(uv[1][c]) + lc * mpq_class(uv[2][c]);
    out[c] = geom::rational_to_double(value.get_mpq_t());
  }
  return out;
}

}  // namespace

void texture_uvs(frame& f) {
  f.fragment_uvs.clear();
  if (!f.textured()) return;
  const triangle_soup& soup = f.soup;
  f.fragment_uvs.assign(f.fragments.size(), {});
  const bool exact = f.tree && is_exact(f.tree->kernel());
  for (std::size_t i = 0; i < f.fragments.size(); ++i) {
    const fragment_d& fr = f.fragments[i];
    if (!f.texture_of(fr.face)) continue;
    const std::size_t source = f.tree ? f.tree->fragment_source(i) : i;
    if (source >= soup.triangles.size() || !soup.has_uvs())
      throw usage_error("texture: fragment " + std::to_string(i) +
                        " of a textured mesh has no texture coordinates (its source triangle is "
                        "not in the frame's soup, or the soup has no UVs)");
    const std::array<vec2d, 3>& uv = soup.triangle_uvs[source];
    if (!f.tree) {
      f.fragment_uvs[i] = uv;
      continue;
    }
    const auto& tv = soup.triangles[source].v;
    const std::array<q3, 3> corners = {exact_of(soup.vertices[tv[0]]),
                                       exact_of(soup.vertices[tv[1]]),
                                       exact_of(soup.vertices[tv[2]])};
    if (exact) {
      const exact_triangle e = f.tree->fragment_exact(i);
      for (int k = 0; k < 3; ++k)
        f.fragment_uvs[i][k] =
            uv_at({mpq_class(e[k][0]), mpq_class(e[k][1]), mpq_class(e[k][2])}, corners, uv);
    } else if (fr.finite()) {  // a non-finite fragment is left out by transform+clip
      for (int k = 0; k < 3; ++k) f.fragment_uvs[i][k] = uv_at(exact_of(fr.v[k]), corners, uv);
    }
  }
}

}  // namespace exbsp::view
