// SPDX-License-Identifier: LGPL-3.0-or-later
#include "geom/rational.h"

#include <mpfr.h>

#include <algorithm>
#include <string>

namespace exbsp::geom {

std::string rational_to_string(mpq_srcptr q) {
  // mpq_get_str writes "p/q" or "p" for canonical values.
  const std::size_t size =
      mpz_sizeinbase(mpq_numref(q), 10) + mpz_sizeinbase(mpq_denref(q), 10) + 3;
  std::string out(size, '\0');
  mpq_get_str(&out[0], 10, q);
  out.resize(std::char_traits<char>::length(out.c_str()));
  return out;
}

double rational_to_double(mpq_srcptr q) {
  // Rounding the exact quotient once to 53 bits in the double's exponent range, then
  // subnormalizing, gives the round-to-nearest double everywhere (subnormals included).
  const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
  mpfr_set_emin(-1073);
  mpfr_set_emax(1024);
  mpfr_t r;
  mpfr_init2(r, 53);
  int ternary = mpfr_set_q(r, q, MPFR_RNDN);
  ternary = mpfr_subnormalize(r, ternary, MPFR_RNDN);
  (void)ternary;
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  mpfr_set_emin(emin);
  mpfr_set_emax(emax);
  return d;
}

double quotient_to_double(mpz_srcptr num, mpz_srcptr den) {
  if (mpz_sgn(num) == 0) return 0.0;
  // num and den held exactly, their quotient rounded once to 53 bits (MPFR's default exponent
  // range is far wider than a double's, so nothing is lost on the way). Where the quotient
  // lies in the double's normal range, that rounding is the double's own; below it a double
  // has fewer bits, so those rare values go through the reduced rational and
  // rational_to_double's subnormalization.
  const auto precision = [](mpz_srcptr z) {
    return static_cast<mpfr_prec_t>(std::max<std::size_t>(mpz_sizeinbase(z, 2), MPFR_PREC_MIN));
  };
  mpfr_t a, b, r;
  mpfr_init2(a, precision(num));
  mpfr_init2(b, precision(den));
  mpfr_init2(r, 53);
  mpfr_set_z(a, num, MPFR_RNDN);  // exact: precision = size in bits
  mpfr_set_z(b, den, MPFR_RNDN);
  mpfr_div(r, a, b, MPFR_RNDN);
  const bool normal = mpfr_get_exp(r) > -1021;  // |r| >= 2^-1021 > DBL_MIN
  const double d = mpfr_get_d(r, MPFR_RNDN);    // exact when normal: r has 53 bits
  mpfr_clear(a);
  mpfr_clear(b);
  mpfr_clear(r);
  if (normal) return d;
  mpq_t q;
  mpq_init(q);
  mpq_set_num(q, num);
  mpq_set_den(q, den);
  mpq_canonicalize(q);
  const double rounded = rational_to_double(q);
  mpq_clear(q);
  return rounded;
}

}  // namespace exbsp::geom
