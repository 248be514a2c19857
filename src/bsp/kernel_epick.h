// SPDX-License-Identifier: LGPL-3.0-or-later
// CGAL Epick: exact (filtered) predicates on double coordinates, rounded constructions.
// kernel_traits specialisations have the same members in every kernel (kernel_traits.h lists
// them, kernel_epeck.h is the other CGAL one); only the bodies differ.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "bsp/kernel_traits.h"

namespace exbsp {

using epick_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

template <>
struct kernel_traits<epick_kernel> : kernel_traits_defaults<epick_kernel> {
  static constexpr kernel_id id = kernel_id::epick;
  static constexpr bool exact = false;
  static constexpr bool fast_path = true;
  static bool approximate(const epick_kernel::Point_3& p, vec3d& centre, double& radius) {
    centre = {p.x(), p.y(), p.z()};
    radius = 0;
    return true;
  }
  static double to_double(double x) { return x; }
};

}  // namespace exbsp
