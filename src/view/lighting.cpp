// SPDX-License-Identifier: LGPL-3.0-or-later
// Flat Lambert shading (notation in lighting.h).
#include "view/lighting.h"

#include <algorithm>
#include <cmath>

namespace exbsp::view {

namespace {
std::uint8_t scale_channel(std::uint8_t c, double k) {
  return static_cast<std::uint8_t>(std::lround(std::min(255.0, std::max(0.0, c * k))));
}
}  // namespace

rgb8 lambert_color(rgb8 base, const vector3& unit_normal, const lighting_settings& s) {
  const vector3 l = normalized(s.direction);
  const double k = s.ambient + s.intensity * std::max(0.0, dot(unit_normal, l));
  return {scale_channel(base.r, k), scale_channel(base.g, k), scale_channel(base.b, k)};
}

vector3 shading_normal(const fragment_d& fr, const view_setup& view, bool two_sided) {
  const point3 a = to_point(fr.v[0]), b = to_point(fr.v[1]), c = to_point(fr.v[2]);
  const vector3 n = cross(b - a, c - a);
  const double len = length(n);
  if (!(len > 0) || !std::isfinite(len)) return {0, 0, 0};
  vector3 unit = (1.0 / len) * n;
  if (two_sided) {
    const vector3 v = view.is_parallel() ? -view.direction : view.cam.eye - a;
    if (dot(unit, v) < 0) unit = -unit;
  }
  return unit;
}

std::string lighting_stage(frame& f) {
  const lighting_settings& s = f.settings.lighting;
  normalized(s.direction);  // throws usage_error for a zero or non-finite direction
  f.fragment_colors.assign(f.fragments.size(), rgb8{});
  for (std::uint32_t idx : f.order) {
    const fragment_d& fr = f.fragments.at(idx);
    f.fragment_colors[idx] =
        lambert_color(f.color_of(fr.face), shading_normal(fr, f.view, s.two_sided), s);
  }
  return std::to_string(f.order.size()) + " fragments lit, " +
         (s.two_sided ? "two-sided" : "one-sided");
}

}  // namespace exbsp::view
