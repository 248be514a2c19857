// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact 2D orientation of double points, used by the rasterizer's edge functions.
//
// orient2d(a, b, c) = sign of det [a - c, b - c] = sign of (b - a) x (c - a): +1 when c is to
// the LEFT of the directed line a -> b (counter-clockwise triangle in a y-up frame), -1 when to
// the right, 0 when the three points are exactly collinear. A floating-point filter with a
// proven error bound (Shewchuk's orient2d stage A) decides almost every call; the rest fall
// back to CGAL's exact predicate, so the sign is always exact and orient2d(a, b, c) ==
// -orient2d(b, a, c) for all inputs: the basis of the top-left rule's "exactly once".
#pragma once
#include <cmath>

namespace exbsp::view {

/// Exact sign, no filter (CGAL Epick Orientation_2). Inputs must be finite.
int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy);

/// Exact sign with a fast filter. Inputs must be finite.
inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double detleft = (ax - cx) * (by - cy);
  const double detright = (ay - cy) * (bx - cx);
  const double det = detleft - detright;
  // 4 eps >= Shewchuk's ccwerrboundA = (3 + 16 eps) eps, eps = 2^-53.
  const double bound = 4.4408920985006262e-16 * (std::fabs(detleft) + std::fabs(detright));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return orient2d_exact(ax, ay, bx, by, cx, cy);
}

}  // namespace exbsp::view
