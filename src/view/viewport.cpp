// SPDX-License-Identifier: LGPL-3.0-or-later
// Viewport transform: ndc [-1, 1]^3 -> window coordinates (notation in viewport.h).
#include <exbsp/view/viewport.h>

namespace exbsp::view {

window_point to_window(const viewport& vp, double x, double y, double z) {
  return {vp.x + (x + 1) * (0.5 * vp.width), vp.y + (y + 1) * (0.5 * vp.height),
          vp.depth_near + (z + 1) * (0.5 * (vp.depth_far - vp.depth_near))};
}

mat4 viewport_matrix(const viewport& vp) {
  mat4 m = mat4::identity();
  m(0, 0) = 0.5 * vp.width;
  m(0, 3) = vp.x + 0.5 * vp.width;
  m(1, 1) = 0.5 * vp.height;
  m(1, 3) = vp.y + 0.5 * vp.height;
  m(2, 2) = 0.5 * (vp.depth_far - vp.depth_near);
  m(2, 3) = vp.depth_near + 0.5 * (vp.depth_far - vp.depth_near);
  return m;
}

}  // namespace exbsp::view
