// SPDX-License-Identifier: LGPL-3.0-or-later
// Kernel traits: what the BSP's CGAL geometry (geometry_cgal.h) needs to know about a CGAL
// kernel beyond its types. Each kernel's specialisation lives in its own header
// (kernel_<name>.h) so that a translation unit includes only the CGAL headers of the kernel
// it instantiates; it derives from kernel_traits_defaults and states only what differs.
#pragma once
#include <gmp.h>

#include <exbsp/bsp/engine.h>

namespace exbsp {

/// Primary template, specialised per kernel (each states id and exact).
template <class K>
struct kernel_traits;

/// What a kernel has unless it says otherwise: no double filter, nothing to collapse, no
/// rationals. (Split points are geom/cut_plane.h's, per kernel.)
template <class K>
struct kernel_traits_defaults {
  /// May the certified double filter (fast_orientation.h) answer side tests?
  static constexpr bool fast_path = false;
  /// Centre and radius (max norm) of a double box around the point, for the filter.
  static bool approximate(const typename K::Point_3&, vec3d&, double&) { return false; }
  /// Drop lazy DAGs after a construction (Epeck).
  static void collapse(const typename K::Point_3&) {}
  static void collapse_vector(const typename K::Vector_3&) {}
  static mpq_srcptr rational(const typename K::FT&) { return nullptr; }
  /// The FT of a rational (exact kernels; saved trees).
  static typename K::FT from_rational(mpq_srcptr) { return {}; }
};

}  // namespace exbsp
