// SPDX-License-Identifier: LGPL-3.0-or-later
// The kernel table (kernels.h): one row per kernel.
#include "bsp/kernels.h"

#include <exbsp/core/errors.h>
#include "core/named_table.h"
#include "core/name_list.h"

// Each kernel's factories, defined by EXBSP_INSTANTIATE_BSP in its bsp_<name>.cpp.
EXBSP_DECLARE_BSP_FACTORIES(exact)
EXBSP_DECLARE_BSP_FACTORIES(epeck)
EXBSP_DECLARE_BSP_FACTORIES(gmpq)
EXBSP_DECLARE_BSP_FACTORIES(epick)
EXBSP_DECLARE_BSP_FACTORIES(double)

namespace exbsp {

namespace {

// Bytes per fragment. Epeck and gmpq: about 1,000 measured (naive heuristic on 128 + 128
// sticks: 2.1 M fragments in 2.1 GB), rounded up for the heavier gmpq numbers. exact (and the
// double-based inexact kernels): the whole command's peak resident set per fragment on
// refined_elephant (254,565 fragments), measured with /usr/bin/time (2026-11-24): build 218
// bytes, order 358 (its document is streamed, not held), render 620; the budget is the largest,
// rounded up. Remeasured 2026-11-28 on the assemblies of bench/assembly.py (exact): render to
// PNG 433 bytes at 1M triangles, to SVG 694 at 1M and 773 at 300k, drawing 855 and order 193 at
// 300k. The SVG and the drawing exceed 640, but the budget takes half the available memory, so
// they stay within it up to 1,280 bytes per fragment. `exbsp build` alone has its own figure:
// exact 256 (its peak resident set per fragment: 131 bytes at 1M triangles, 130 at 300k, 218 on
// refined_elephant), so that a 10M-triangle assembly (35M fragments, about 5 GB) is not
// stopped on a 24 GB machine; the other kernels keep their command figure for it (epick 293,
// double 265 and epeck 959 measured at 300k: within it).
named_table<kernel_row>& table() {
  static named_table<kernel_row> rows({
      {kernel_id::exact, "exact", true, 1, 640, 256, "exbsp's own exact points, default",
       make_bsp_exact, tree_file::load_exact},
      {kernel_id::epeck, "epeck", true, 2, 1300, 1300, "CGAL lazy exact", make_bsp_epeck,
       tree_file::load_epeck},
      {kernel_id::gmpq, "gmpq", true, 3, 1300, 1300, "plain exact rationals", make_bsp_gmpq,
       tree_file::load_gmpq},
      {kernel_id::epick, "epick", false, 4, 640, 640, "exact predicates, rounded splits",
       make_bsp_epick, tree_file::load_epick},
      {kernel_id::double_, "double", false, 5, 640, 640, "plain double", make_bsp_double,
       tree_file::load_double},
  });
  return rows;
}

}  // namespace

const std::vector<kernel_row>& kernel_table() { return table().rows(); }

const kernel_row& kernel_row_of(kernel_id id) {
  for (const kernel_row& r : table().rows())
    if (r.id == id) return r;
  throw usage_error("unknown kernel (id " + std::to_string(static_cast<int>(id)) + ")");
}

const kernel_row* kernel_row_of_file_code(std::uint32_t code) {
  for (const kernel_row& r : table().rows())
    if (r.file_code == code) return &r;
  return nullptr;
}

void add_kernel(kernel_row row) {
  if (row.name.empty() || !row.make || !row.load)
    throw usage_error("add_kernel: a kernel needs a name, a build and a load function");
  if (row.bytes_per_fragment == 0 || row.build_bytes_per_fragment == 0)
    throw usage_error(
        "add_kernel: kernel '" + row.name +
        "' needs its bytes per fragment (the default --max-fragments divides by them)");
  for (const kernel_row& r : table().rows())
    if (r.id == row.id || r.name == row.name || r.file_code == row.file_code)
      throw usage_error("add_kernel: kernel '" + row.name +
                        "' repeats the id, name or file code of '" + r.name + "'");
  table().add(std::move(row));
}

const std::vector<std::string>& kernel_names() { return table().names(); }

std::string to_string(kernel_id k) {
  for (const kernel_row& r : table().rows())
    if (r.id == k) return r.name;
  return "unknown";
}

kernel_id parse_kernel(const std::string& name) {
  if (const kernel_row* r = table().find(name)) return r->id;
  throw usage_error("unknown kernel '" + name + "' (expected " + name_list(table().names(), "or") +
                    ")");
}

bool is_exact(kernel_id k) {
  for (const kernel_row& r : table().rows())
    if (r.id == k) return r.exact;
  return false;
}

}  // namespace exbsp
