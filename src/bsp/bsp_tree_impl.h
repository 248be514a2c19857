// SPDX-License-Identifier: LGPL-3.0-or-later
// Definitions of basic_bsp_tree<G>, by job: the build's orchestration (tree_build.h), one
// node (tree_grow.h), the splitter's choice (tree_choose.h) and the facade over one tree with
// its traversals (tree_kernel_impl.h). Included only by the per-kernel translation units
// (bsp_<kernel>.cpp), which instantiate them explicitly with EXBSP_INSTANTIATE_BSP.
// Notation: see bsp_tree.h. The splitter heuristics are in heuristics.h.
#pragma once
#include "bsp/kernels.h"
#include "bsp/tree_build.h"
#include "bsp/tree_choose.h"
#include "bsp/tree_grow.h"
#include "bsp/tree_insert.h"
#include "bsp/tree_kernel_impl.h"

/// Explicit instantiation of the tree for one geometry G, with the factories make_bsp_<NAME>
/// and tree_file::load_<NAME> that the kernel's row names (kernels.h). Used once per kernel
/// translation unit.
#define EXBSP_INSTANTIATE_BSP(G, NAME)                                                           \
  EXBSP_DECLARE_BSP_FACTORIES(NAME)                                                              \
  namespace exbsp {                                                                              \
  template class basic_bsp_tree<G>;                                                              \
  std::unique_ptr<bsp_impl> make_bsp_##NAME(const triangle_soup& soup, const build_options& o) { \
    return std::make_unique<bsp_kernel_impl<G>>(soup, o);                                        \
  }                                                                                              \
  std::unique_ptr<bsp_impl> tree_file::load_##NAME(tree_file::reader& in,                        \
                                                   tree_file::common_part&& c) {                 \
    return std::make_unique<bsp_kernel_impl<G>>(in, std::move(c));                               \
  }                                                                                              \
  }
