#include "bsp/exact_output.h"

#include <mpfr.h>

#include <fstream>
#include <memory>

namespace exbsp {

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

std::size_t peak_rss_bytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      std::size_t kb = 0;
      status >> kb;
      return kb * 1024;
    }
    std::getline(status, key);
  }
  return 0;
}

}  // namespace exbsp
