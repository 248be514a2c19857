// SPDX-License-Identifier: LGPL-3.0-or-later
// Thin-lens depth of field by accumulation (notation in depth_of_field.h).
#include "view/depth_of_field.h"

#include "view/accumulate.h"

#include <cmath>
#include <cstdio>

#include <exbsp/core/errors.h>

namespace exbsp::view {

namespace {
constexpr double golden_angle = 2.39996322972865332;  // pi (3 - sqrt 5)

void check(const depth_of_field_settings& s) {
  if (!(std::isfinite(s.focal_length) && s.focal_length > 0))
    throw usage_error("depth_of_field: focal_length must be > 0");
  if (!(std::isfinite(s.aperture) && s.aperture > 0))
    throw usage_error("depth_of_field: aperture must be > 0");
  if (!(std::isfinite(s.focus_distance) && s.focus_distance > s.focal_length))
    throw usage_error("depth_of_field: focus_distance must be greater than focal_length");
  if (s.samples < 2 || s.samples > 1024)
    throw usage_error("depth_of_field: samples must be in 2..1024");
}
}  // namespace

double circle_of_confusion(const depth_of_field_settings& s, double u) {
  return s.aperture * s.focal_length * std::fabs(u - s.focus_distance) /
         (u * (s.focus_distance - s.focal_length));
}

double circle_of_confusion_pixels(const depth_of_field_settings& s, const view_setup& view,
                                  double u) {
  return s.aperture * std::fabs(u - s.focus_distance) * view.vp.height * view.projection(1, 1) /
         (2 * u * s.focus_distance);
}

std::vector<lens_offset> lens_samples(int count, double aperture) {
  if (count < 1) throw usage_error("lens_samples: count must be >= 1");
  if (!(std::isfinite(aperture) && aperture >= 0))
    throw usage_error("lens_samples: aperture must be finite and >= 0");
  std::vector<lens_offset> out(static_cast<std::size_t>(count));
  for (int k = 1; k < count; ++k) {
    const double r = 0.5 * aperture * std::sqrt((k - 0.5) / (count - 1));
    const double a = k * golden_angle;
    out[static_cast<std::size_t>(k)] = {r * std::cos(a), r * std::sin(a)};
  }
  return out;
}

view_setup lens_view(const view_setup& view, const lens_offset& lens, double focus_distance) {
  if (view.is_parallel())
    throw usage_error("depth_of_field: needs a perspective or frustum projection");
  if (!(std::isfinite(focus_distance) && focus_distance > 0))
    throw usage_error("depth_of_field: focus_distance must be > 0");
  const camera_basis b = look_at_basis(view.cam.eye, view.cam.look_at, view.cam.up);
  const vector3 shift = lens.dx * b.u + lens.dy * b.v;
  view_setup v = view;
  v.cam.eye = view.cam.eye + shift;
  v.cam.look_at = view.cam.look_at + shift;
  v.model_view = look_at(v.cam);
  v.projection(0, 2) -= lens.dx * view.projection(0, 0) / focus_distance;
  v.projection(1, 2) -= lens.dy * view.projection(1, 1) / focus_distance;
  return v;
}

std::string depth_of_field_stage(frame& f, const pipeline& per_view) {
  const depth_of_field_settings& s = f.settings.depth_of_field;
  check(s);
  if (f.view.is_parallel())
    throw usage_error("depth_of_field: needs a perspective or frustum projection");
  const std::vector<lens_offset> lens = lens_samples(s.samples, s.aperture);
  const view_setup centre = f.view;
  accumulate_views(
      f, per_view, lens.size(),
      [&](std::size_t k) { return lens_view(centre, lens[k], s.focus_distance); },
      "depth_of_field");

  char buf[160];
  std::snprintf(buf, sizeof buf,
                "%d lens samples (traversals of one BSP), aperture %g, focus at %g, f %g",
                s.samples, s.aperture, s.focus_distance, s.focal_length);
  return buf;
}

}  // namespace exbsp::view
