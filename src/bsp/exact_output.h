// Conversions of exact rationals (GMP mpq) for output: reduced "p/q" strings and the
// correctly rounded (nearest, ties to even) double.
#pragma once
#include <gmp.h>

#include <array>
#include <functional>
#include <string>

namespace exbsp {

/// Receives exact coordinates: vertex k (0..2), axis (0..2) and the canonical rational, valid
/// during the call.
using exact_visitor = std::function<void(int k, int axis, mpq_srcptr value)>;

/// The reduced rational as "p/q", or "p" when q = 1. Precondition: q is canonical.
std::string rational_to_string(mpq_srcptr q);

/// The exact coordinates that visit_exact(visitor) reports, as text [vertex][axis].
template <class VisitExact>
std::array<std::array<std::string, 3>, 3> exact_text(VisitExact&& visit_exact) {
  std::array<std::array<std::string, 3>, 3> out;
  visit_exact(
      exact_visitor([&](int k, int axis, mpq_srcptr q) { out[k][axis] = rational_to_string(q); }));
  return out;
}

/// The double nearest to q (round to nearest, ties to even), via MPFR.
double rational_to_double(mpq_srcptr q);

/// The double nearest to num / den (den > 0; the fraction need not be reduced), rounded
/// like rational_to_double, without the gcd a canonical mpq would cost.
double quotient_to_double(mpz_srcptr num, mpz_srcptr den);

/// Peak resident set size of this process in bytes (Linux VmHWM), 0 when unknown.
std::size_t peak_rss_bytes();

}  // namespace exbsp
