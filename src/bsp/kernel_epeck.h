// CGAL Epeck: lazy exact kernel. Its exact number type is mpq_class or boost's gmp_rational
// depending on CGAL's configuration; mpq_of reads the GMP rational of either.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gmpxx.h>

#include "bsp/exact_output.h"
#include "bsp/kernel_traits.h"

namespace exbsp {

inline mpq_srcptr mpq_of(const mpq_class& q) { return q.get_mpq_t(); }
template <class Number>
mpq_srcptr mpq_of(const Number& q) { return q.backend().data(); }

using epeck_kernel = CGAL::Exact_predicates_exact_constructions_kernel;

template <>
struct kernel_traits<epeck_kernel> {
  static constexpr kernel_id id = kernel_id::epeck;
  /// Whether the certified double filter (fast_orientation.h) may answer side tests.
  static constexpr bool fast_path = true;
  /// Whether constructed points have exact double coordinates.
  static constexpr bool constructions_are_doubles = false;
  static constexpr bool exact = true;
  /// Computing the exact value prunes the lazy DAG below the point (memory and later speed).
  static void collapse(const epeck_kernel::Point_3& p) { CGAL::exact(p); }
  static mpq_srcptr rational(const epeck_kernel::FT& x) { return mpq_of(CGAL::exact(x)); }
  static double to_double(const epeck_kernel::FT& x) { return rational_to_double(rational(x)); }
};

}  // namespace exbsp
