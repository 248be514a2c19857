// CGAL Epick: exact (filtered) predicates on double coordinates, rounded constructions.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "bsp/kernel_traits.h"

namespace exbsp {

using epick_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

template <>
struct kernel_traits<epick_kernel> {
  static constexpr kernel_id id = kernel_id::epick;
  /// Whether the certified double filter (fast_orientation.h) may answer side tests.
  static constexpr bool fast_path = true;
  static bool approximate(const epick_kernel::Point_3& p, vec3d& centre, double& radius) {
    centre = {p.x(), p.y(), p.z()};
    radius = 0;
    return true;
  }
  static constexpr bool exact = false;
  static void collapse(const epick_kernel::Point_3&) {}
  static void collapse_vector(const epick_kernel::Vector_3&) {}
  static constexpr bool direct_intersection = false;  ///< generic formula in the kernel's own FT
  template <class... A>
  static epick_kernel::Point_3 intersection(const A&...) { return {}; }
  static mpq_srcptr rational(const double&) { return nullptr; }
  static double to_double(double x) { return x; }
};

}  // namespace exbsp
