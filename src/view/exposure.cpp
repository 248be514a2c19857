// SPDX-License-Identifier: LGPL-3.0-or-later
// Motion blur by accumulation (notation in exposure.h).
#include "view/exposure.h"

#include <cmath>
#include <cstdio>

#include <exbsp/core/errors.h>
#include <exbsp/view/camera.h>
#include "view/accumulate.h"

namespace exbsp::view {

namespace {

point3 blend(const point3& a, const point3& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}
vector3 blend(const vector3& a, const vector3& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}

void check(const exposure_settings& s) {
  if (!(std::isfinite(s.shutter) && s.shutter > 0 && s.shutter <= 1))
    throw usage_error("exposure: shutter must be in (0, 1]");
  if (s.samples < 2 || s.samples > 1024) throw usage_error("exposure: samples must be in 2..1024");
}

}  // namespace

view_setup exposure_view(const view_setup& start, const exposure_settings& s, int k, int count) {
  if (k == 0) return start;
  const double t = s.shutter * k / (count - 1);
  view_setup v = start;
  v.cam = {blend(start.cam.eye, s.camera_end.eye, t),
           blend(start.cam.look_at, s.camera_end.look_at, t),
           blend(start.cam.up, s.camera_end.up, t)};
  v.model_view = look_at(v.cam);
  // The centre of projection keeps its place relative to the camera: its eye coordinates in
  // view 0, carried back to the world by the new camera (for the usual projections, at the
  // eye's origin or along the gaze: exactly the blended camera's eye and gaze).
  if (start.is_parallel()) {
    const vector3 d = transform_vector(start.model_view, start.direction);
    const vector3 along{0, 0, -length(d)};
    if (d.x == along.x && d.y == along.y && d.z == along.z) {
      v.direction = gaze_direction(v.cam);
    } else {
      const std::optional<hpoint> w = solve(v.model_view, {d.x, d.y, d.z, 0});
      if (!w) throw usage_error("exposure: a camera of the path is degenerate");
      v.direction = normalized({w->x, w->y, w->z});
    }
  } else {
    const point3 e = transform_point(start.model_view, start.cam.eye);
    if (e.x == 0 && e.y == 0 && e.z == 0) return v;  // v.cam.eye is the centre of projection
    const std::optional<hpoint> w = solve(v.model_view, {e.x, e.y, e.z, 1});
    if (!w || !(std::abs(w->w) > 0))
      throw usage_error("exposure: a camera of the path is degenerate");
    v.cam.eye = {w->x / w->w, w->y / w->w, w->z / w->w};
  }
  return v;
}

std::string exposure_stage(frame& f, const pipeline& per_view) {
  const exposure_settings& s = f.settings.exposure;
  check(s);
  const view_setup start = f.view;
  accumulate_views(
      f, per_view, static_cast<std::size_t>(s.samples),
      [&](std::size_t k) { return exposure_view(start, s, static_cast<int>(k), s.samples); },
      "exposure");
  char buf[160];
  std::snprintf(buf, sizeof buf, "%d samples over shutter %g (traversals of one BSP)", s.samples,
                s.shutter);
  return buf;
}

}  // namespace exbsp::view
