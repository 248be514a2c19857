// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact rationals (GMP mpq) for output, shared by the tree (bsp), the section (clip) and the
// bindings: the GMP rational behind an exact CGAL number, reduced "p/q" text and the
// correctly rounded (nearest, ties to even) double.
#pragma once
#include <gmp.h>
#include <gmpxx.h>

#include <string>

#include <exbsp/core/export.h>

namespace exbsp::geom {

/// The GMP rational of an exact number: Epeck's exact number type is mpq_class or boost's
/// gmp_rational depending on CGAL's configuration; this reads either.
inline mpq_srcptr mpq_of(const mpq_class& q) { return q.get_mpq_t(); }
template <class Number>
mpq_srcptr mpq_of(const Number& q) {
  return q.backend().data();
}
inline mpq_ptr mutable_mpq_of(mpq_class& q) { return q.get_mpq_t(); }
template <class Number>
mpq_ptr mutable_mpq_of(Number& q) {
  return q.backend().data();
}

/// The reduced rational as "p/q", or "p" when q = 1. Precondition: q is canonical.
std::string rational_to_string(mpq_srcptr q);

/// The double nearest to q (round to nearest, ties to even), via MPFR. Exported from the
/// shared core: the render and gpl libraries round their exact values with it too.
EXBSP_EXPORT double rational_to_double(mpq_srcptr q);

/// The double nearest to num / den (den > 0; the fraction need not be reduced), rounded
/// like rational_to_double, without the gcd a canonical mpq would cost.
double quotient_to_double(mpz_srcptr num, mpz_srcptr den);

}  // namespace exbsp::geom
