// SPDX-License-Identifier: LGPL-3.0-or-later
// CGAL Epeck: lazy exact kernel. Its exact number type is mpq_class or boost's gmp_rational
// depending on CGAL's configuration; geom::mpq_of reads the GMP rational of either.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>

#include "bsp/kernel_traits.h"
#include "geom/rational.h"

namespace exbsp {

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

  static mpq_srcptr rational(const epeck_kernel::FT& x) { return geom::mpq_of(CGAL::exact(x)); }
  static epeck_kernel::FT from_rational(mpq_srcptr q) {
    epeck_kernel::Exact_kernel::FT e;
    mpq_set(geom::mutable_mpq_of(e), q);
    return epeck_kernel::FT(e);
  }
  static double to_double(const epeck_kernel::FT& x) {
    return geom::rational_to_double(rational(x));
  }
};

}  // namespace exbsp
