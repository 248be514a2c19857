// SPDX-License-Identifier: LGPL-3.0-or-later
// The viewing transform gluLookAt(eye, look_at, up).
//
// Notation: gaze g = look_at - eye, view-up t = up. The camera basis is
//   w = -g / |g|,   u = (t x w) / |t x w|,   v = w x u,
// and the viewing matrix is Mv = R_uvw * T(-eye), where R_uvw has rows u, v, w. In eye
// coordinates the camera sits at the origin looking down -z with +y up (as OpenGL).
#pragma once
#include <exbsp/core/export.h>
#include <exbsp/view/matrix.h>

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
EXBSP_EXPORT camera_basis look_at_basis(const point3& eye, const point3& look_at,
                                        const vector3& up);

/// gluLookAt: Mv = R_uvw * T(-eye). Throws like look_at_basis.
EXBSP_EXPORT mat4 look_at(const point3& eye, const point3& look_at, const vector3& up);
inline mat4 look_at(const camera& c) { return look_at(c.eye, c.look_at, c.up); }

/// The basis of a camera looking along `look` (any length > 0) with view-up `up`: the
/// gluLookAt basis with g = look (the seeds' six-parameter camera: position, look, up).
/// Throws usage_error like look_at_basis (zero look, zero up, up parallel to look).
EXBSP_EXPORT camera_basis look_direction_basis(const vector3& look, const vector3& up);

/// Mv = R_uvw * T(-eye) for the basis of look_direction_basis(look, up). Throws like it.
EXBSP_EXPORT mat4 look_along(const point3& eye, const vector3& look, const vector3& up);

/// polarView: Mv = T(0, 0, -distance) * Rz(-twist) * Rx(elevation) * Rz(azimuth) * T(-look_at),
/// R as glRotated (degrees, counter-clockwise about the axis). Throws usage_error for
/// non-finite input.
EXBSP_EXPORT mat4 polar_view(double distance, double twist_deg, double elevation_deg,
                             double azimuth_deg, const point3& look_at);

/// pilotView: Mv = Ry(roll) * Rx(pitch) * Rz(heading) * T(-position), R as glRotated.
/// Throws usage_error for non-finite input.
EXBSP_EXPORT mat4 pilot_view(const point3& position, double roll_deg, double pitch_deg,
                             double heading_deg);

/// The gluLookAt camera of a rigid viewing matrix Mv = [R | t] (rows of R orthonormal): eye =
/// -R^T t, look_at = eye - look_distance * (row 2 of R), up = row 1 of R. Used to give every
/// camera form an eye point (back-to-front order) and a look-at point (orbits).
EXBSP_EXPORT camera camera_of(const mat4& model_view, double look_distance);

/// Unit gaze direction (look_at - eye) / |look_at - eye|. Throws usage_error when eye == look_at.
EXBSP_EXPORT vector3 gaze_direction(const camera& c);

}  // namespace exbsp::view
