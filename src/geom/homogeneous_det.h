// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact signs and exact comparisons of 4 x 4 determinants of homogeneous double points.
//
// Notation: a point of projective 3-space is h = (x, y, z, w) with double x, y, z and w = 1 (a
// point) or w = 0 (a direction: a point at infinity, e.g. the viewer of a parallel view).
//   D(h0, h1, h2, h3) = det [h0; h1; h2; h3]   (rows (x, y, z, w))
// For four points, D(a, b, c, p) = orientation(a, b, c, p) = (b - a) x (c - a) . (p - a) up to
// the sign of a row permutation; D is linear in each row, so along a segment p(t) = A + t (B -
// A), D(h0, h1, h2, p(t)) = D(.., A) + t (D(.., B) - D(.., A)): affine in t.
//
// A det_value keeps the interval of its value (CGAL's Interval_nt, computed under upward
// rounding) and its four rows, and computes the exact rational value (GMP) only when the
// interval cannot decide a sign or a comparison. Every answer is therefore the exact one, the
// same on every machine; the interval is a pure speed-up.
#pragma once
#include <CGAL/Interval_nt.h>
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <memory>

#include <exbsp/core/export.h>

namespace exbsp::geom {

/// A homogeneous point: w = 1 (a point) or 0 (a direction).
struct hpoint {
  double x = 0, y = 0, z = 0;
  int w = 1;
};

inline hpoint point_of(const std::array<double, 3>& p) { return {p[0], p[1], p[2], 1}; }

/// det [r0; r1; r2] = r0 . (r1 x r2) of three double rows, evaluated in double (rounding to
/// nearest, so outside a rounding_guard), and its permanent (the sum of the absolute values of
/// its six products): the evaluation errs by about 5u x the permanent (u = 2^-53), which lets a
/// caller decide the sign in double and fall back to det_value when the bound does not.
struct rounded_det3 {
  double value = 0, permanent = 0;
};
inline rounded_det3 det3_in_double(const double (&r)[3][3]) {
  rounded_det3 d;
  d.value = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) +
            r[0][1] * (r[1][2] * r[2][0] - r[1][0] * r[2][2]) +
            r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
  d.permanent = std::abs(r[0][0]) * (std::abs(r[1][1] * r[2][2]) + std::abs(r[1][2] * r[2][1])) +
                std::abs(r[0][1]) * (std::abs(r[1][2] * r[2][0]) + std::abs(r[1][0] * r[2][2])) +
                std::abs(r[0][2]) * (std::abs(r[1][0] * r[2][1]) + std::abs(r[1][1] * r[2][0]));
  return d;
}

/// The interval type of this file: valid only while a rounding_guard is alive.
using interval = CGAL::Interval_nt_advanced;

/// Sets the rounding mode that `interval` needs for its scope (CGAL::Protect_FPU_rounding).
/// Double arithmetic in that scope rounds upward: keep plain double work outside it.
using rounding_guard = CGAL::Protect_FPU_rounding<true>;

/// D(h0, h1, h2, h3) as a filtered exact value (notation). Precondition: at least one row has
/// w = 1 and all coordinates are finite. Construct and compare only under a rounding_guard.
class det_value {
 public:
  det_value() = default;
  EXBSP_EXPORT det_value(const hpoint& h0, const hpoint& h1, const hpoint& h2, const hpoint& h3);

  /// Exact sign (-1, 0, 1).
  EXBSP_EXPORT int sign() const;
  /// The exact value (computed once, on first use).
  EXBSP_EXPORT const mpq_class& exact() const;
  const interval& approx() const { return approx_; }
  /// +1 or -1 when `other` has the rows of this one (bit for bit) in an even or odd order:
  /// then its value is this one's times that sign, exactly. 0 otherwise, and when two rows of
  /// this one are equal.
  EXBSP_EXPORT int same_rows_sign(const det_value& other) const;
  /// A double near the value (the exact one rounded when it was computed).
  EXBSP_EXPORT double to_double() const;

 private:
  std::array<hpoint, 4> rows_{};
  interval approx_{0};
  mutable std::shared_ptr<const mpq_class> exact_;
};

/// Exact sign of p q - r s.
EXBSP_EXPORT int sign_of_difference_of_products(const det_value& p, const det_value& q,
                                                const det_value& r, const det_value& s);

/// A parameter t = a / (a - b) on a segment where an affine function with values a at t = 0
/// and b at t = 1 vanishes; a and b are nonzero with opposite signs, so 0 < t < 1. The ends
/// t = 0 and t = 1 are the constants `zero` and `one`.
struct crossing {
  enum class kind_type { zero, one, inner };
  kind_type kind = kind_type::zero;
  det_value a, b;

  static crossing at_zero() { return {}; }
  static crossing at_one() {
    crossing c;
    c.kind = kind_type::one;
    return c;
  }
  static crossing between(const det_value& a, const det_value& b) {
    return {kind_type::inner, a, b};
  }
  /// A double near t.
  EXBSP_EXPORT double to_double() const;
};

/// Exact comparison of two crossings on the same segment: -1, 0 or 1 as x <, =, > y.
EXBSP_EXPORT int compare(const crossing& x, const crossing& y);

}  // namespace exbsp::geom
