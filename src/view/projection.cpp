// SPDX-License-Identifier: LGPL-3.0-or-later
// glOrtho, glFrustum, gluPerspective and the PHIGS-style oblique shear (notation in projection.h).
#include <exbsp/view/projection.h>

#include <cmath>

#include <exbsp/core/errors.h>

namespace exbsp::view {

namespace {
constexpr double pi = 3.14159265358979323846;

bool all_finite(std::initializer_list<double> xs) {
  for (double x : xs)
    if (!std::isfinite(x)) return false;
  return true;
}
}  // namespace

mat4 ortho(double l, double r, double b, double t, double n, double f) {
  if (!all_finite({l, r, b, t, n, f})) throw usage_error("ortho: non-finite parameter");
  if (l == r || b == t || n == f)
    throw usage_error("ortho: empty view volume (left == right, bottom == top or near == far)");
  mat4 m;
  m(0, 0) = 2 / (r - l);
  m(0, 3) = -(r + l) / (r - l);
  m(1, 1) = 2 / (t - b);
  m(1, 3) = -(t + b) / (t - b);
  m(2, 2) = -2 / (f - n);
  m(2, 3) = -(f + n) / (f - n);
  m(3, 3) = 1;
  return m;
}

mat4 frustum(double l, double r, double b, double t, double n, double f) {
  if (!all_finite({l, r, b, t, n, f})) throw usage_error("frustum: non-finite parameter");
  if (!(n > 0) || !(f > n)) throw usage_error("frustum: need 0 < near < far");
  if (l == r || b == t) throw usage_error("frustum: empty window (left == right or bottom == top)");
  mat4 m;
  m(0, 0) = 2 * n / (r - l);
  m(0, 2) = (r + l) / (r - l);
  m(1, 1) = 2 * n / (t - b);
  m(1, 2) = (t + b) / (t - b);
  m(2, 2) = -(f + n) / (f - n);
  m(2, 3) = -2 * f * n / (f - n);
  m(3, 2) = -1;
  return m;
}

mat4 perspective(double fovy_deg, double aspect, double n, double f) {
  if (!all_finite({fovy_deg, aspect, n, f})) throw usage_error("perspective: non-finite parameter");
  if (!(fovy_deg > 0 && fovy_deg < 180))
    throw usage_error("perspective: fovy must be in (0, 180) degrees");
  if (!(aspect > 0)) throw usage_error("perspective: aspect must be positive");
  if (!(n > 0) || !(f > n)) throw usage_error("perspective: need 0 < near < far");
  const double tan_half = std::tan(fovy_deg * (pi / 360.0));
  mat4 m;
  m(0, 0) = 1 / (aspect * tan_half);
  m(1, 1) = 1 / tan_half;
  m(2, 2) = -(f + n) / (f - n);
  m(2, 3) = -2 * f * n / (f - n);
  m(3, 2) = -1;
  return m;
}

mat4 oblique_shear(const vector3& dop, double pivot_z) {
  if (!is_finite(dop) || !std::isfinite(pivot_z))
    throw usage_error("oblique_shear: non-finite input");
  if (!(dop.z < 0))
    throw usage_error(
        "oblique_shear: the direction of projection must point into the scene (z < 0 in eye "
        "coordinates)");
  const double shx = -dop.x / dop.z, shy = -dop.y / dop.z;
  mat4 m = mat4::identity();
  m(0, 2) = shx;
  m(0, 3) = -shx * pivot_z;
  m(1, 2) = shy;
  m(1, 3) = -shy * pivot_z;
  return m;
}

mat4 oblique(double l, double r, double b, double t, double n, double f, const vector3& dop,
             double pivot_z) {
  return ortho(l, r, b, t, n, f) * oblique_shear(dop, pivot_z);
}

}  // namespace exbsp::view
