// CGAL Epeck: lazy exact kernel. Its exact number type is mpq_class or boost's gmp_rational
// depending on CGAL's configuration; mpq_of reads the GMP rational of either.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>

#include "bsp/exact_output.h"
#include "bsp/kernel_traits.h"

namespace exbsp {

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

using epeck_kernel = CGAL::Exact_predicates_exact_constructions_kernel;

template <>
struct kernel_traits<epeck_kernel> : kernel_traits_defaults<epeck_kernel> {
  static constexpr kernel_id id = kernel_id::epeck;
  static constexpr bool fast_path = true;
  /// Centre and radius (max norm, rounded up) of the point's interval approximation, which
  /// is tight once the point has been collapsed to its exact value.
  static bool approximate(const epeck_kernel::Point_3& p, vec3d& centre, double& radius) {
    const auto& a = CGAL::approx(p);
    radius = 0;
    for (int k = 0; k < 3; ++k) {
      const double lo = a[k].inf(), hi = a[k].sup();
      if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) return false;
      centre[k] = lo + 0.5 * (hi - lo);
      radius = std::max(radius, (hi - lo) * (1 + 1e-15));
    }
    return true;
  }
  static constexpr bool exact = true;
  /// Computing the exact value prunes the lazy DAG below the point (memory and later speed).
  static void collapse(const epeck_kernel::Point_3& p) { CGAL::exact(p); }
  static void collapse_vector(const epeck_kernel::Vector_3& v) { CGAL::exact(v); }

  /// The point where [p,q] meets the plane through a with normal n, computed directly on the
  /// exact values as X = (fp q - fq p) / (fp - fq), fp = n.(p - a), fq = n.(q - a), and
  /// wrapped as a one-level lazy point: the same exact point as p + fp/(fp - fq) (q - p)
  /// without a dozen lazy nodes evaluated (and their intervals refreshed) one by one.
  static constexpr bool direct_intersection = true;
  static epeck_kernel::Point_3 intersection(const epeck_kernel::Point_3& a,
                                            const epeck_kernel::Vector_3& n,
                                            const epeck_kernel::Point_3& p,
                                            const epeck_kernel::Point_3& q) {
    using EK = epeck_kernel::Exact_kernel;
    using ET = EK::FT;
    const EK::Point_3& ea = CGAL::exact(a);
    const EK::Vector_3& en = CGAL::exact(n);
    const EK::Point_3& ep = CGAL::exact(p);
    const EK::Point_3& eq = CGAL::exact(q);
    const ET fp = en * (ep - ea);
    const ET fq = en * (eq - ea);
    const ET den = fp - fq;
    const ET x = (fp * eq.x() - fq * ep.x()) / den;
    const ET y = (fp * eq.y() - fq * ep.y()) / den;
    const ET z = (fp * eq.z() - fq * ep.z()) / den;
    epeck_kernel::Point_3 out{epeck_kernel::FT(x), epeck_kernel::FT(y), epeck_kernel::FT(z)};
    CGAL::exact(out);
    return out;
  }
  static mpq_srcptr rational(const epeck_kernel::FT& x) { return mpq_of(CGAL::exact(x)); }
  static epeck_kernel::FT from_rational(mpq_srcptr q) {
    epeck_kernel::Exact_kernel::FT e;
    mpq_set(mutable_mpq_of(e), q);
    return epeck_kernel::FT(e);
  }
  static double to_double(const epeck_kernel::FT& x) { return rational_to_double(rational(x)); }
};

}  // namespace exbsp
