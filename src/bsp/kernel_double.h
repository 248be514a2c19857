// SPDX-License-Identifier: LGPL-3.0-or-later
// Simple_cartesian<double>: plain double predicates and constructions, no filter, no epsilon.
#pragma once
#include <CGAL/Simple_cartesian.h>

#include "bsp/kernel_traits.h"

namespace exbsp {

using double_kernel = CGAL::Simple_cartesian<double>;

template <>
struct kernel_traits<double_kernel> : kernel_traits_defaults<double_kernel> {
  static constexpr kernel_id id = kernel_id::double_;
  static constexpr bool exact = false;  // plain double everywhere, no filter
  static double to_double(double x) { return x; }
};

}  // namespace exbsp
