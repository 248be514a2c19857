// Simple_cartesian<double>: plain double predicates and constructions, no filter, no epsilon.
#pragma once
#include <CGAL/Simple_cartesian.h>

#include "bsp/kernel_traits.h"

namespace exbsp {

using double_kernel = CGAL::Simple_cartesian<double>;

template <>
struct kernel_traits<double_kernel> {
  static constexpr kernel_id id = kernel_id::double_;
  /// Whether the certified double filter (fast_orientation.h) may answer side tests.
  static constexpr bool fast_path = false;
  static bool approximate(const double_kernel::Point_3&, vec3d&, double&) { return false; }
  static constexpr bool exact = false;
  static void collapse(const double_kernel::Point_3&) {}
  static void collapse_vector(const double_kernel::Vector_3&) {}
  static constexpr bool direct_intersection = false;  ///< generic formula in the kernel's own FT
  template <class... A>
  static double_kernel::Point_3 intersection(const A&...) { return {}; }
  static mpq_srcptr rational(const double&) { return nullptr; }
  static double to_double(double x) { return x; }
};

}  // namespace exbsp
