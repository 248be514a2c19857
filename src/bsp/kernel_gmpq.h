// Simple_cartesian<CGAL::Gmpq>: plain exact rationals, no filtering (the slow reference).
#pragma once
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include "bsp/exact_output.h"
#include "bsp/kernel_traits.h"

namespace exbsp {

using gmpq_kernel = CGAL::Simple_cartesian<CGAL::Gmpq>;

template <>
struct kernel_traits<gmpq_kernel> {
  static constexpr kernel_id id = kernel_id::gmpq;
  /// Whether the certified double filter (fast_orientation.h) may answer side tests.
  static constexpr bool fast_path = false;
  static bool approximate(const gmpq_kernel::Point_3&, vec3d&, double&) { return false; }
  static constexpr bool exact = true;
  static void collapse(const gmpq_kernel::Point_3&) {}
  static void collapse_vector(const gmpq_kernel::Vector_3&) {}
  static constexpr bool direct_intersection = false;  ///< generic formula in the kernel's own FT
  template <class... A>
  static gmpq_kernel::Point_3 intersection(const A&...) { return {}; }
  static mpq_srcptr rational(const gmpq_kernel::FT& x) { return x.mpq(); }
  static double to_double(const gmpq_kernel::FT& x) { return rational_to_double(x.mpq()); }
};

}  // namespace exbsp
