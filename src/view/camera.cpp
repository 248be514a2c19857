// SPDX-License-Identifier: LGPL-3.0-or-later
// gluLookAt. Notation (camera.h): g = look_at - eye, t = up, w = -g/|g|,
// u = t x w / |t x w|, v = w x u, Mv = R_uvw T(-eye). polar_view and pilot_view are products
// of glRotated-style rotations (transforms.h) exactly as camera.h writes them.
#include <exbsp/view/camera.h>

#include <exbsp/core/errors.h>
#include <exbsp/view/transforms.h>

namespace exbsp::view {

camera_basis look_at_basis(const point3& eye, const point3& look_at, const vector3& up) {
  if (!is_finite(eye) || !is_finite(look_at) || !is_finite(up))
    throw usage_error("look_at: non-finite camera input");
  return look_direction_basis(look_at - eye, up);
}

camera_basis look_direction_basis(const vector3& g, const vector3& up) {
  if (!is_finite(g) || !is_finite(up)) throw usage_error("look_at: non-finite camera input");
  if (g.x == 0 && g.y == 0 && g.z == 0)
    throw usage_error("look_at: eye and look_at are the same point");
  if (up.x == 0 && up.y == 0 && up.z == 0) throw usage_error("look_at: the up vector is zero");
  // Lengths whose squares overflow or underflow (an eye at 1e300) go through normalized(),
  // which scales first; ordinary ones keep the plain formulas (and their roundings).
  const auto ordinary = [](double len) { return len > 1e-150 && len < 1e150; };
  const double glen = length(g);
  const vector3 w = ordinary(glen) ? (-1.0 / glen) * g : normalized(-1.0 * g);
  const double up_len = length(up);
  const vector3 t = ordinary(up_len) ? up : normalized(up);
  const double tlen = ordinary(up_len) ? up_len : 1.0;
  const vector3 txw = cross(t, w);
  const double s = length(txw);
  if (!(s > 1e-9 * tlen))
    throw usage_error("look_at: the up vector is parallel to the view direction");
  camera_basis b;
  b.w = w;
  b.u = (1.0 / s) * txw;
  b.v = cross(b.w, b.u);
  return b;
}

mat4 look_at(const point3& eye, const point3& look_at, const vector3& up) {
  if (!is_finite(eye) || !is_finite(look_at)) throw usage_error("look_at: non-finite camera input");
  return look_along(eye, look_at - eye, up);
}

mat4 look_along(const point3& eye, const vector3& look, const vector3& up) {
  if (!is_finite(eye)) throw usage_error("look_at: non-finite camera input");
  const camera_basis b = look_direction_basis(look, up);
  const vector3 e{eye.x, eye.y, eye.z};
  mat4 r = mat4::identity();
  const vector3 rows[3] = {b.u, b.v, b.w};
  for (int i = 0; i < 3; ++i) {
    r(i, 0) = rows[i].x;
    r(i, 1) = rows[i].y;
    r(i, 2) = rows[i].z;
    r(i, 3) = -dot(rows[i], e);
  }
  return r;
}

mat4 polar_view(double distance, double twist_deg, double elevation_deg, double azimuth_deg,
                const point3& look_at) {
  if (!std::isfinite(distance) || !std::isfinite(twist_deg) || !std::isfinite(elevation_deg) ||
      !std::isfinite(azimuth_deg) || !is_finite(look_at))
    throw usage_error("polar_view: non-finite input");
  return translate({0, 0, -distance}) * rotate(-twist_deg, {0, 0, 1}) *
         rotate(elevation_deg, {1, 0, 0}) * rotate(azimuth_deg, {0, 0, 1}) *
         translate({-look_at.x, -look_at.y, -look_at.z});
}

mat4 pilot_view(const point3& position, double roll_deg, double pitch_deg, double heading_deg) {
  if (!is_finite(position) || !std::isfinite(roll_deg) || !std::isfinite(pitch_deg) ||
      !std::isfinite(heading_deg))
    throw usage_error("pilot_view: non-finite input");
  return rotate(roll_deg, {0, 1, 0}) * rotate(pitch_deg, {1, 0, 0}) *
         rotate(heading_deg, {0, 0, 1}) * translate({-position.x, -position.y, -position.z});
}

camera camera_of(const mat4& m, double look_distance) {
  const vector3 rows[3] = {
      {m(0, 0), m(0, 1), m(0, 2)}, {m(1, 0), m(1, 1), m(1, 2)}, {m(2, 0), m(2, 1), m(2, 2)}};
  const double t[3] = {m(0, 3), m(1, 3), m(2, 3)};
  const vector3 eye = -(t[0] * rows[0] + t[1] * rows[1] + t[2] * rows[2]);
  camera c;
  c.eye = {eye.x, eye.y, eye.z};
  c.look_at = c.eye - look_distance * rows[2];
  c.up = rows[1];
  return c;
}

vector3 gaze_direction(const camera& c) {
  const vector3 g = c.look_at - c.eye;
  if (!is_finite(g) || !(length(g) > 0))
    throw usage_error("gaze_direction: eye and look_at are the same point");
  return normalized(g);
}

}  // namespace exbsp::view
