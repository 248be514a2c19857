// SPDX-License-Identifier: LGPL-3.0-or-later
// Simple_cartesian<CGAL::Gmpq>: plain exact rationals, no filtering (the slow reference).
#pragma once
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include "bsp/kernel_traits.h"
#include "geom/rational.h"

namespace exbsp {

using gmpq_kernel = CGAL::Simple_cartesian<CGAL::Gmpq>;

template <>
struct kernel_traits<gmpq_kernel> : kernel_traits_defaults<gmpq_kernel> {
  static constexpr kernel_id id = kernel_id::gmpq;
  static constexpr bool exact = true;  // no filter: the slow reference on purpose
  static mpq_srcptr rational(const gmpq_kernel::FT& x) { return x.mpq(); }
  static gmpq_kernel::FT from_rational(mpq_srcptr q) { return CGAL::Gmpq(q); }
  static double to_double(const gmpq_kernel::FT& x) { return geom::rational_to_double(x.mpq()); }
};

}  // namespace exbsp
