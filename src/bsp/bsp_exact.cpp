// SPDX-License-Identifier: LGPL-3.0-or-later
// Explicit instantiation of the BSP for exbsp's own exact geometry (geometry_exact.h).
#include "bsp/bsp_tree_impl.h"
#include "bsp/geometry_exact.h"
#include "bsp/tree_distributed.h"  // distributed builds use the exact kernel only

EXBSP_INSTANTIATE_BSP(exbsp::exact_geometry, exact)
