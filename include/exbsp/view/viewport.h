// SPDX-License-Identifier: LGPL-3.0-or-later
// The viewport transform (glViewport + glDepthRange) from normalized device coordinates
// (ndc, after the perspective divide, view volume [-1, 1]^3) to window coordinates.
//
// Window coordinates as OpenGL: x to the right, y UP, origin at the bottom-left corner of the
// window; pixel (i, j) covers [i, i+1] x [j, j+1] and its centre is (i + 1/2, j + 1/2).
// Images are stored top row first (PNG): image row r holds window pixel row j = height - 1 - r,
// whose top edge is at window y = height - r.
#pragma once
#include <exbsp/core/export.h>
#include <exbsp/view/matrix.h>

namespace exbsp::view {

/// A point in window coordinates; z is the depth in [depth_near, depth_far].
struct window_point {
  double x = 0, y = 0, z = 0;
};

/// glViewport(x, y, width, height) and glDepthRange(depth_near, depth_far).
struct viewport {
  int x = 0, y = 0;
  int width = 0, height = 0;
  double depth_near = 0, depth_far = 1;
};

/// Window coordinates of an ndc point: x_w = x + (x_ndc + 1) width / 2, y_w likewise,
/// z_w = depth_near + (z_ndc + 1)(depth_far - depth_near) / 2.
EXBSP_EXPORT window_point to_window(const viewport& vp, double x_ndc, double y_ndc, double z_ndc);

/// The same map as a 4x4 matrix acting on (x_ndc, y_ndc, z_ndc, 1).
EXBSP_EXPORT mat4 viewport_matrix(const viewport& vp);

/// Image row (0 = top) of window pixel row j in a window of the given height.
inline int image_row(int j, int height) { return height - 1 - j; }

}  // namespace exbsp::view
