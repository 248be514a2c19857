// SPDX-License-Identifier: LGPL-3.0-or-later
// The matrices of the course material (../shared/course, docs/contract.md "Command line":
// `exbsp matrices`), beside the OpenGL matrices the pipeline uses (camera.h, projection.h,
// viewport.h). Each is a plain mat4 (row-major, acting on column vectors).
//
// Viewing and projection (seed 000, Shirley's notation): the camera looks down -z, so the near
// and far planes are z = n and z = f with n = -near > f = -far. World to screen is
//   M = Mvp * Morth * Mp * Mv,
//   Mv     the camera basis: rows u, v, w and -e (gluLookAt's model_view),
//   Mp     = [[n,0,0,0],[0,n,0,0],[0,0,n+f,-f n],[0,0,1,0]]: the frustum to the box
//          [l,r] x [b,t] x [f,n] (l, r, b, t: the window on the near plane),
//   Morth  = the box to the canonical volume [-1,1]^3 (z = n goes to +1, z = f to -1),
//   Mvp    = [[nx/2,0,0,(nx-1)/2],[0,ny/2,0,(ny-1)/2],[0,0,1,0],[0,0,0,1]]: canonical x, y to
//          pixel coordinates with pixel centres at integers (exbsp's window coordinates
//          minus 1/2; docs/contract.md "Pixels").
// A parallel view drops Mp. Against OpenGL: the same x and y after the division by w; the
// canonical z is OpenGL's negated (OpenGL sends the near plane to -1).
//
// Normalisation of the six-parameter camera (seed 002): position P, look direction L, up U,
// height angle theta_h, aspect a (width / height: tan(theta_w / 2) = a tan(theta_h / 2)), near
// and far. p' = Dpersp * Sfar * Sxy * Mrot * Ttrans * p with
//   Ttrans = T(-P),   Mrot = rows u, v, w (w = -L / |L|, gluLookAt's basis),
//   Sxy    = diag(1 / tan(theta_w / 2), 1 / tan(theta_h / 2), 1, 1): the side planes through
//            the corners (+-1, +-1) at distance 1,
//   Sfar   = diag(1 / far, 1 / far, 1 / far, 1): the far plane at z = -1, the near one at -k,
//            k = near / far,
//   Dpersp = [[1,0,0,0],[0,1,0,0],[0,0,1/(k-1),k/(k-1)],[0,0,-1,0]]: the truncated pyramid
//            to the canonical parallel volume [-1,1]^2 x [0,1], near at z = 0 and far at 1
//            (the z axis turned round), the depth a z-buffer keeps: OpenGL's (z_ndc + 1) / 2.
#pragma once
#include <exbsp/view/camera.h>
#include <exbsp/view/matrix.h>

namespace exbsp::view::course {

/// Mp for the near and far planes z = n and z = f (n = -near, f = -far).
mat4 perspective_mp(double n, double f);

/// Morth: [l,r] x [b,t] x [f,n] to [-1,1]^3 (n > f).
mat4 orthographic(double l, double r, double b, double t, double n, double f);

/// Mvp for an nx x ny pixel screen.
mat4 viewport_mvp(int nx, int ny);

/// Ttrans = T(-position).
mat4 translation_to_origin(const point3& position);

/// Mrot: rows u, v, w of the camera basis.
mat4 rotation_of(const camera_basis& b);

/// Sxy for the half angles' tangents.
mat4 scale_xy(double tan_half_width, double tan_half_height);

/// Sfar: a uniform scale by 1 / far.
mat4 scale_far(double far_dist);

/// Dpersp for k = near / far (0 < k < 1).
mat4 perspective_dpersp(double k);

}  // namespace exbsp::view::course
