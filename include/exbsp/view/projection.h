// SPDX-License-Identifier: LGPL-3.0-or-later
// Projection matrices, OpenGL conventions: eye coordinates look down -z; near and far are
// positive distances in front of the eye (planes z_eye = -near and z_eye = -far); the result
// is in clip coordinates where the view volume is -w <= x, y, z <= w, and z_ndc = -1 at near.
//
// Oblique parallel projection (PHIGS style): the direction of projection dop (eye coordinates,
// pointing from the eye into the scene, dop.z < 0) need not be the view-plane normal. A shear
//   x' = x + shx (z - z_p),  y' = y + shy (z - z_p),  z' = z,   shx = -dop.x/dop.z, shy =
//   -dop.y/dop.z
// maps dop onto -z and leaves the plane z = z_p (the view plane, containing the window)
// fixed; the sheared volume is then projected orthographically: oblique = ortho * shear.
#pragma once
#include <exbsp/core/export.h>
#include <exbsp/view/matrix.h>

namespace exbsp::view {

/// glOrtho(l, r, b, t, n, f). Throws usage_error for l == r, b == t, n == f or non-finite input.
EXBSP_EXPORT mat4 ortho(double left, double right, double bottom, double top, double near_dist,
                        double far_dist);

/// glFrustum(l, r, b, t, n, f); l, r, b, t are measured on the near plane.
/// Throws usage_error unless 0 < n < f, l != r, b != t, all finite.
EXBSP_EXPORT mat4 frustum(double left, double right, double bottom, double top, double near_dist,
                          double far_dist);

/// gluPerspective(fovy, aspect, n, f), fovy in degrees.
/// Throws usage_error unless 0 < fovy < 180, aspect > 0, 0 < n < f, all finite.
EXBSP_EXPORT mat4 perspective(double fovy_deg, double aspect, double near_dist, double far_dist);

/// The oblique shear of the notation above, fixing the plane z_eye = pivot_z.
/// Throws usage_error unless dop_eye is finite with dop_eye.z < 0.
EXBSP_EXPORT mat4 oblique_shear(const vector3& dop_eye, double pivot_z = 0);

/// Oblique parallel projection: ortho(l, r, b, t, n, f) * oblique_shear(dop_eye, pivot_z).
/// The window (l, r, b, t) lies in the view plane z_eye = pivot_z. Throws like its parts.
EXBSP_EXPORT mat4 oblique(double left, double right, double bottom, double top, double near_dist,
                          double far_dist, const vector3& dop_eye, double pivot_z = 0);

}  // namespace exbsp::view
