// SPDX-License-Identifier: LGPL-3.0-or-later
// The course material's matrices (notation in course_matrices.h).
#include "view/course_matrices.h"

namespace exbsp::view::course {

mat4 perspective_mp(double n, double f) {
  return mat4::from_rows({n, 0, 0, 0, 0, n, 0, 0, 0, 0, n + f, -f * n, 0, 0, 1, 0});
}

mat4 orthographic(double l, double r, double b, double t, double n, double f) {
  return mat4::from_rows({2 / (r - l), 0, 0, -(r + l) / (r - l),  //
                          0, 2 / (t - b), 0, -(t + b) / (t - b),  //
                          0, 0, 2 / (n - f), -(n + f) / (n - f),  //
                          0, 0, 0, 1});
}

mat4 viewport_mvp(int nx, int ny) {
  return mat4::from_rows({nx / 2.0, 0, 0, (nx - 1) / 2.0,  //
                          0, ny / 2.0, 0, (ny - 1) / 2.0,  //
                          0, 0, 1, 0,                      //
                          0, 0, 0, 1});
}

mat4 translation_to_origin(const point3& p) {
  return mat4::from_rows({1, 0, 0, -p.x, 0, 1, 0, -p.y, 0, 0, 1, -p.z, 0, 0, 0, 1});
}

mat4 rotation_of(const camera_basis& b) {
  return mat4::from_rows({b.u.x, b.u.y, b.u.z, 0,  //
                          b.v.x, b.v.y, b.v.z, 0,  //
                          b.w.x, b.w.y, b.w.z, 0,  //
                          0, 0, 0, 1});
}

mat4 scale_xy(double tan_half_width, double tan_half_height) {
  return mat4::from_rows(
      {1 / tan_half_width, 0, 0, 0, 0, 1 / tan_half_height, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
}

mat4 scale_far(double far_dist) {
  const double s = 1 / far_dist;
  return mat4::from_rows({s, 0, 0, 0, 0, s, 0, 0, 0, 0, s, 0, 0, 0, 0, 1});
}

mat4 perspective_dpersp(double k) {
  return mat4::from_rows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 / (k - 1), k / (k - 1), 0, 0, -1, 0});
}

}  // namespace exbsp::view::course
