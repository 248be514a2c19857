// The viewing transform gluLookAt(eye, look_at, up).
//
// Notation: gaze g = look_at - eye, view-up t = up. The camera basis is
//   w = -g / |g|,   u = (t x w) / |t x w|,   v = w x u,
// and the viewing matrix is Mv = R_uvw * T(-eye), where R_uvw has rows u, v, w. In eye
// coordinates the camera sits at the origin looking down -z with +y up (as OpenGL).
#pragma once
#include "view/matrix.h"

namespace exbsp::view {

/// The orthonormal camera frame of gluLookAt.
struct camera_basis {
  vector3 u, v, w;  ///< right, up, backwards (w = -gaze direction)
};

/// A camera exactly as gluLookAt takes it.
struct camera {
  point3 eye;
  point3 look_at;
  vector3 up;
};

/// The gluLookAt basis. Throws usage_error when an input is not finite, eye == look_at, up is
/// zero, or up is parallel to the gaze (sine of the angle between them below 1e-9).
camera_basis look_at_basis(const point3& eye, const point3& look_at, const vector3& up);

/// gluLookAt: Mv = R_uvw * T(-eye). Throws like look_at_basis.
mat4 look_at(const point3& eye, const point3& look_at, const vector3& up);
inline mat4 look_at(const camera& c) { return look_at(c.eye, c.look_at, c.up); }

/// Unit gaze direction (look_at - eye) / |look_at - eye|. Throws usage_error when eye == look_at.
vector3 gaze_direction(const camera& c);

}  // namespace exbsp::view
