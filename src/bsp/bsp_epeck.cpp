// SPDX-License-Identifier: LGPL-3.0-or-later
// Explicit instantiation of the BSP for the epeck kernel (one object per CGAL header set).
#include "bsp/kernel_epeck.h"
#include "bsp/bsp_tree_impl.h"
#include "bsp/geometry_cgal.h"

EXBSP_INSTANTIATE_BSP(exbsp::cgal_geometry<exbsp::epeck_kernel>, epeck)
