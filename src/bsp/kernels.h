// SPDX-License-Identifier: LGPL-3.0-or-later
// The kernels, one row each: everything the library and the command line know of a kernel is in
// its row (issue 26), so that adding one is one new file (bsp_<name>.cpp: the geometry and
// EXBSP_INSTANTIATE_BSP) and one row in kernels.cpp. Names, parsing, exactness, the build, saved
// trees' kernel codes and loaders, the command line's help and memory budget all read this
// table; tests/test_tables.cpp walks it and adds a kernel from a test-only file.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "bsp/bsp_impl.h"
#include "bsp/tree_file.h"

namespace exbsp {

struct kernel_row {
  kernel_id id;
  std::string name;         ///< --kernel NAME, build_stats::kernel, JSON
  bool exact = false;       ///< exact constructions: the same tree and order on every machine
  std::uint32_t file_code;  ///< saved trees' kernel code (docs/tree-file.md): stable, never reused
  /// Bytes one fragment costs in a command, tree nodes, lists and the process's slack included
  /// (the command line's default --max-fragments: resources.h).
  std::uint64_t bytes_per_fragment;
  /// The same for `exbsp build` alone (no frame, no document): what a build and its saving cost.
  std::uint64_t build_bytes_per_fragment;
  std::string description;  ///< one phrase for --help: what the number type is
  std::unique_ptr<bsp_impl> (*make)(const triangle_soup&, const build_options&);
  std::unique_ptr<bsp_impl> (*load)(tree_file::reader&, tree_file::common_part&&);
};

/// Every kernel, the default (exact) first, then epeck, gmpq, epick, double, then any added
/// with add_kernel.
const std::vector<kernel_row>& kernel_table();

/// The row of `id`; usage_error for a kernel that is not in the table.
const kernel_row& kernel_row_of(kernel_id id);

/// The row with saved-tree kernel code `code`, or nullptr.
const kernel_row* kernel_row_of_file_code(std::uint32_t code);

/// Adds a kernel to the table (a test's kernel, or a plug-in linked into a program). Its id,
/// name and file code must be new (usage_error otherwise). Call it before any build or lookup
/// runs on another thread: the table is not locked.
void add_kernel(kernel_row row);

}  // namespace exbsp

/// Declares the two factories of a kernel that EXBSP_INSTANTIATE_BSP(G, NAME) defines
/// (bsp_tree_impl.h): make_bsp_NAME builds a tree; tree_file::load_NAME reads the kernel's part
/// of a saved tree's body from `in` (positioned after the common part) for the soup and stats
/// of `common`, validating everything. Its row in kernels.cpp names them.
#define EXBSP_DECLARE_BSP_FACTORIES(NAME)                                                \
  namespace exbsp {                                                                      \
  std::unique_ptr<bsp_impl> make_bsp_##NAME(const triangle_soup&, const build_options&); \
  namespace tree_file {                                                                  \
  std::unique_ptr<bsp_impl> load_##NAME(reader& in, common_part&& common);               \
  }                                                                                      \
  }
