// SPDX-License-Identifier: LGPL-3.0-or-later
// Explicit instantiation of the BSP for the gmpq kernel (one object per CGAL header set).
#include "bsp/kernel_gmpq.h"
#include "bsp/bsp_tree_impl.h"
#include "bsp/geometry_cgal.h"

EXBSP_INSTANTIATE_BSP(exbsp::cgal_geometry<exbsp::gmpq_kernel>, gmpq)
