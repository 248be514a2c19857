// Kernel traits: what the BSP code needs to know about a CGAL kernel beyond its types.
// Each kernel's specialisation lives in its own header (kernel_<name>.h) so that a
// translation unit includes only the CGAL headers of the kernel it instantiates.
#pragma once
#include <gmp.h>

#include "bsp/engine.h"

namespace exbsp {

/// Primary template, specialised per kernel:
///   static constexpr kernel_id id; static constexpr bool exact;
///   static constexpr bool fast_path;          // may the certified double filter answer?
///   static void collapse(Point_3&);           // drop lazy DAGs after a construction
///   static bool approximate(Point_3, vec3d& centre, double& radius);  // for the filter
///   static double to_double(const FT&);       // nearest double
///   static mpq_srcptr rational(const FT&);    // exact kernels only
template <class K>
struct kernel_traits;

}  // namespace exbsp
