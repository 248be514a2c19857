// SPDX-License-Identifier: LGPL-3.0-or-later
// Certified fast orientation of double points against a plane through three double points.
//
// Notation: plane points a, b, c (doubles); e1 = b - a, e2 = c - a; n = e1 x e2;
// for a point p, q = p - a and f(p) = n . q = orientation(a, b, c, p).
// Everything is computed in double together with an upper bound on its rounding error
// (u = 2^-53, generous constant factors); when |f^| exceeds the bound, its sign is the exact
// sign. Otherwise (or when magnitudes leave [1e-80, 1e80], where underflow or overflow
// would void the bound) the caller falls back to the exact predicate. The answer, when
// given, is therefore identical to the exact one: this is a pure speed-up.
#pragma once
#include <algorithm>
#include <cfloat>
#include <cmath>

#include <exbsp/mesh/soup.h>

namespace exbsp {

/// What the filter needs of a plane through a (80 bytes): the rounded normal n and, per
/// component, coef = err + 8u|n| where err bounds the normal's rounding error, so that
/// |f(p) - f^(p)| <= coef . |p - a| (before scaling); spread = sum of |n| + err, how far f
/// moves per unit of a point's radius.
struct fast_plane_core {
  vec3d a{}, n{}, coef{};
  double spread = 0;
  bool valid = false;
};

/// The core and the plane's other two points (for the shared-vertex test of fast_sign).
struct fast_plane : fast_plane_core {
  vec3d b{}, c{};
};

namespace detail {
inline bool safe_magnitude(double x) {
  const double m = std::fabs(x);
  return m == 0 || (m >= 1e-80 && m <= 1e80);
}
}  // namespace detail

inline fast_plane make_fast_plane(const vec3d& a, const vec3d& b, const vec3d& c) {
  constexpr double u = 1.1102230246251565e-16;  // 2^-53
  fast_plane p;
  p.a = a;
  p.b = b;
  p.c = c;
  vec3d err{};
  const vec3d e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const vec3d e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  for (int k = 0; k < 3; ++k)
    if (!detail::safe_magnitude(e1[k]) || !detail::safe_magnitude(e2[k]) ||
        !detail::safe_magnitude(a[k]))
      return p;
  const double t[6] = {e1[1] * e2[2], e1[2] * e2[1], e1[2] * e2[0],
                       e1[0] * e2[2], e1[0] * e2[1], e1[1] * e2[0]};
  for (int k = 0; k < 3; ++k) {
    p.n[k] = t[2 * k] - t[2 * k + 1];
    // e1, e2 carry a relative error <= u each, products <= 3u, the difference u more.
    err[k] = 8 * u * (std::fabs(t[2 * k]) + std::fabs(t[2 * k + 1]));
    if (!detail::safe_magnitude(p.n[k]) && p.n[k] != 0) return p;
    p.coef[k] = err[k] + 8 * u * std::fabs(p.n[k]);
    p.spread += std::fabs(p.n[k]) + err[k];
  }
  p.valid = true;
  return p;
}

/// Evaluates f(x) = orientation value of a point x known to lie within `radius` (max norm)
/// of the double point `point` (radius 0: x is exactly `point`): writes the double value v
/// and a bound such that |f(x) - v| <= bound. Returns false when the magnitudes leave the
/// range where the bound holds (the caller must then compute exactly). Plane: fast_plane_core
/// or a type with the same members (valid, a, n, coef, spread) holding bounds at least as large.
template <class Plane>
inline bool fast_eval(const Plane& p, const vec3d& point, double radius, double& v, double& bound) {
  constexpr double u = 1.1102230246251565e-16;
  if (!p.valid) return false;
  // The plane's magnitudes were checked once (make_fast_plane). Here a difference q_k is exact
  // when it is subnormal, a product that underflows errs by less than 2^-1074 (covered by the
  // absolute 1e-290 term), and anything that overflows makes v or the bound infinite or NaN,
  // which is refused below.
  const double q0 = point[0] - p.a[0], q1 = point[1] - p.a[1], q2 = point[2] - p.a[2];
  v = p.n[0] * q0 + p.n[1] * q1 + p.n[2] * q2;
  const double b =
      p.coef[0] * std::fabs(q0) + p.coef[1] * std::fabs(q1) + p.coef[2] * std::fabs(q2);
  // A point known only to within `radius` moves f by at most |n| . (radius, radius, radius).
  bound = (b + radius * p.spread) * (1 + 8 * u) + 1e-290;  // products stay normal
  // Finite v means no sum or product overflowed; NaN fails both comparisons.
  return std::fabs(v) < HUGE_VAL && bound < HUGE_VAL;
}

/// Sign of orientation(a, b, c, x) for a point x known to lie within `radius` (max norm) of
/// the double point `point` (radius 0: x is exactly `point`): -1, 0 or +1 when certified,
/// 2 when the caller must use the exact predicate.
inline int fast_sign(const fast_plane_core& p, const vec3d& point, double radius = 0) {
  double v, bound;
  if (!fast_eval(p, point, radius, v, bound)) return 2;
  if (v > bound) return 1;
  if (v < -bound) return -1;
  return 2;
}

/// fast_sign, and 0 for a vertex shared with the plane's triangle (adjacent mesh triangles).
inline int fast_sign(const fast_plane& p, const vec3d& point, double radius = 0) {
  const int s = fast_sign(static_cast<const fast_plane_core&>(p), point, radius);
  if (s != 2) return s;
  if (radius == 0 && (point == p.a || point == p.b || point == p.c)) return 0;
  return 2;
}

/// A plane's filter with one static error bound for every point of a bounding box: all exact
/// points of a build lie in the convex hull of the input, hence in its bounding box [lo, hi],
/// and a point's centre c lies within its radius r of its exact position. With
/// Q_k >= |x_k - a_k| over the box, fast_eval's bound at c is at most b0 + r b1 (both rounded
/// up here), so a side test is v = n . (c - a) and one comparison |v| > b0 + r b1: no per-point
/// error term. Where that fails, fast_sign (tighter) and the exact predicate follow.
struct static_plane {
  vec3d a{}, n{};
  double b0 = 0, b1 = 0;
  bool valid = false;
};

/// The static filter of plane p over the box [lo, hi] (which must hold every exact point the
/// filter is asked about). Invalid (every test falls back) when p is, or when the box reaches
/// past 1e80, where v could overflow.
inline static_plane make_static_plane(const fast_plane_core& p, const vec3d& lo, const vec3d& hi) {
  constexpr double u = 1.1102230246251565e-16;
  static_plane s;
  if (!p.valid) return s;
  double sum_qc = 0, sum_c = 0;
  for (int k = 0; k < 3; ++k) {
    if (!(std::fabs(lo[k]) <= 1e80 && std::fabs(hi[k]) <= 1e80)) return s;
    // |x_k - a_k| <= Q_k for x in the box; rounded up by the factor.
    const double q = std::max(hi[k] - p.a[k], p.a[k] - lo[k]) * (1 + 4 * u);
    sum_qc += p.coef[k] * q;
    sum_c += p.coef[k];
  }
  // fast_eval: bound = (coef . |q^| + r spread)(1 + 8u) + 1e-290, |q^_k| <= (Q_k + r)(1 + u).
  // The extra (1 + 16u) covers the rounding of these sums and of b0 + r b1 at the test.
  s.b0 = (sum_qc * (1 + u) * (1 + 8 * u) + 1e-290) * (1 + 16 * u);
  s.b1 = (sum_c * (1 + u) + p.spread) * (1 + 8 * u) * (1 + 16 * u);
  s.a = p.a;
  s.n = p.n;
  s.valid = std::isfinite(s.b0) && std::isfinite(s.b1);
  return s;
}

/// Sign of f at the exact point within r of centre c, by the static filter: -1 or +1 when
/// certified, 0 when not (the caller must then ask fast_sign or the exact predicate).
/// Precondition: s.valid, and the exact point lies in the box s was made for.
inline int static_sign(const static_plane& s, const vec3d& c, double r) {
  const double v = s.n[0] * (c[0] - s.a[0]) + s.n[1] * (c[1] - s.a[1]) + s.n[2] * (c[2] - s.a[2]);
  const double t = s.b0 + r * s.b1;
  return (v > t) - (v < -t);
}

/// Sign of f over a whole box: every point x with lo_k - r <= x_k <= hi_k + r. -1 or +1 when
/// every such point is certified strictly on that side, 0 otherwise (not known, or the box
/// touches or crosses the plane). The box's centre m and half-widths R (rounded up) feed
/// fast_eval's bound: f(x) = f(m) + N . (x - m) with |N_k| <= |n_k| + coef_k.
inline int fast_box_sign(const fast_plane_core& p, const vec3d& lo, const vec3d& hi, double r) {
  constexpr double u = 1.1102230246251565e-16;
  if (!p.valid) return 0;
  double v = 0, bound = 0;
  for (int k = 0; k < 3; ++k) {
    const double m = 0.5 * lo[k] + 0.5 * hi[k];
    const double half = (std::max(hi[k] - m, m - lo[k]) + r) * (1 + 4 * u) + DBL_MIN;
    const double q = m - p.a[k];
    v += p.n[k] * q;
    bound += p.coef[k] * std::fabs(q) + (std::fabs(p.n[k]) + p.coef[k]) * half;
  }
  bound = bound * (1 + 16 * u) + 1e-290;
  if (!(std::fabs(v) < HUGE_VAL && bound < HUGE_VAL)) return 0;
  return (v > bound) - (v < -bound);
}

}  // namespace exbsp
