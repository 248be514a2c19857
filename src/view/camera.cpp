// gluLookAt. Notation (camera.h): g = look_at - eye, t = up, w = -g/|g|,
// u = t x w / |t x w|, v = w x u, Mv = R_uvw T(-eye).
#include "view/camera.h"

#include "mesh/errors.h"

namespace exbsp::view {

camera_basis look_at_basis(const point3& eye, const point3& look_at, const vector3& up) {
  if (!is_finite(eye) || !is_finite(look_at) || !is_finite(up))
    throw usage_error("look_at: non-finite camera input");
  const vector3 g = look_at - eye;
  const double glen = length(g);
  if (!(glen > 0)) throw usage_error("look_at: eye and look_at are the same point");
  const double tlen = length(up);
  if (!(tlen > 0)) throw usage_error("look_at: the up vector is zero");
  const vector3 w = (-1.0 / glen) * g;
  const vector3 txw = cross(up, w);
  const double s = length(txw);
  if (!(s > 1e-9 * tlen)) throw usage_error("look_at: the up vector is parallel to the view direction");
  camera_basis b;
  b.w = w;
  b.u = (1.0 / s) * txw;
  b.v = cross(b.w, b.u);
  return b;
}

mat4 look_at(const point3& eye, const point3& look_at, const vector3& up) {
  const camera_basis b = look_at_basis(eye, look_at, up);
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

vector3 gaze_direction(const camera& c) {
  const vector3 g = c.look_at - c.eye;
  if (!is_finite(g) || !(length(g) > 0)) throw usage_error("gaze_direction: eye and look_at are the same point");
  return normalized(g);
}

}  // namespace exbsp::view
