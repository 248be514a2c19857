// SPDX-License-Identifier: LGPL-3.0-or-later
// Fog (notation in fog.h).
#include "view/fog.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <exbsp/core/errors.h>

namespace exbsp::view {

namespace {

/// Inverse by Gauss–Jordan elimination with partial pivoting; false when singular.
bool invert(const mat4& m, mat4& inverse) {
  double a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m(r, c);
      a[r][c + 4] = r == c ? 1 : 0;
    }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
    if (!(std::fabs(a[pivot][col]) > 0)) return false;
    if (pivot != col)
      for (int c = 0; c < 8; ++c) std::swap(a[pivot][c], a[col][c]);
    const double p = a[col][col];
    for (int c = 0; c < 8; ++c) a[col][c] /= p;
    for (int r = 0; r < 4; ++r) {
      if (r == col || a[r][col] == 0) continue;
      const double f = a[r][col];
      for (int c = 0; c < 8; ++c) a[r][c] -= f * a[col][c];
    }
  }
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) inverse(r, c) = a[r][c + 4];
  return is_finite(inverse);
}

std::uint8_t mix(std::uint8_t surface, std::uint8_t fog, double v) {
  const double c = v * surface + (1 - v) * fog;
  return static_cast<std::uint8_t>(std::lround(std::min(255.0, std::max(0.0, c))));
}

}  // namespace

double fog_visibility(const fog_settings& s, double d) {
  if (!(d > 0)) d = 0;
  if (s.mode == fog_mode::linear) {
    if (d <= s.start) return 1;
    if (d >= s.end) return 0;
    return (s.end - d) / (s.end - s.start);
  }
  return std::exp(-s.density * d);
}

fog_shading make_fog_shading(const fog_settings& s, const view_setup& view) {
  fog_shading f;
  f.settings = s;
  f.vp = view.vp;
  f.radial = !view.is_parallel();
  if (!invert(view.projection, f.inverse_projection))
    throw usage_error("fog: the projection matrix is singular");
  return f;
}

double eye_distance(const fog_shading& fog, double x, double y, double z) {
  const viewport& vp = fog.vp;
  const double range = vp.depth_far - vp.depth_near;
  const hpoint ndc{2 * (x - vp.x) / vp.width - 1, 2 * (y - vp.y) / vp.height - 1,
                   range != 0 ? 2 * (z - vp.depth_near) / range - 1 : 0, 1};
  const hpoint e = fog.inverse_projection * ndc;
  if (!(e.w != 0)) return std::numeric_limits<double>::infinity();
  const double ex = e.x / e.w, ey = e.y / e.w, ez = e.z / e.w;
  return fog.radial ? std::sqrt(ex * ex + ey * ey + ez * ez) : -ez;
}

rgb8 fog_color(const fog_shading& fog, rgb8 base, double d) {
  const double v = fog_visibility(fog.settings, d);
  const rgb8 c = fog.settings.color;
  return {mix(base.r, c.r, v), mix(base.g, c.g, v), mix(base.b, c.b, v)};
}

std::string fog_stage(frame& f) {
  f.fog = make_fog_shading(f.settings.fog, f.view);
  const fog_shading fog = *f.fog;
  f.shader = sample_shader{[fog](rgb8 c, double x, double y, double z) {
                             return fog_color(fog, c, eye_distance(fog, x, y, z));
                           },
                           fog.settings.color};
  const fog_settings& s = f.settings.fog;
  char buf[128];
  if (s.mode == fog_mode::linear)
    std::snprintf(buf, sizeof buf, "linear %g..%g, %s distance", s.start, s.end,
                  f.fog->radial ? "radial" : "planar");
  else
    std::snprintf(buf, sizeof buf, "exp density %g, %s distance", s.density,
                  f.fog->radial ? "radial" : "planar");
  return buf;
}

}  // namespace exbsp::view
