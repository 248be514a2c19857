// Conversions of exact rationals (GMP mpq) for output: reduced "p/q" strings and the
// correctly rounded (nearest, ties to even) double.
#pragma once
#include <gmp.h>

#include <string>

namespace exbsp {

/// The reduced rational as "p/q", or "p" when q = 1. Precondition: q is canonical.
std::string rational_to_string(mpq_srcptr q);

/// The double nearest to q (round to nearest, ties to even), via MPFR.
double rational_to_double(mpq_srcptr q);

/// Peak resident set size of this process in bytes (Linux VmHWM), 0 when unknown.
std::size_t peak_rss_bytes();

}  // namespace exbsp
