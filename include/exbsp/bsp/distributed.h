// SPDX-License-Identifier: LGPL-3.0-or-later
// A BSP build spread over machines (from Python: docs/python.md "Distributed builds"): the same
// tree as bsp::build, node for node, with the subtrees below the top levels grown anywhere.
//
// bsp::build grows its top levels until 16 cells are pending, then each cell's subtree on its
// own: a subtree depends only on the soup, the options and its cell (fragments in list order,
// side, depth and the path key that seeds every heuristic choice below it). So:
//
//   exbsp::distributed_build plan(soup, options);              // the top, on this machine
//   for (i < plan.cell_count())                                 // anywhere, in any order:
//     parts[i] = exbsp::distributed_build::build_cell(plan.input(), plan.cell(i));
//   for (i ...) plan.add_part(i, parts[i]);                      // any order
//   exbsp::bsp tree = plan.finish();                             // == bsp::build(soup, options)
//
// input(), cell(i) and the parts are bytes (a few dozen per fragment): ship them with any
// transport (the Python module's exbsp.build_distributed uses Dask). finish() checks the whole
// tree as bsp::deserialize checks a saved tree, so malformed or mismatched parts give an
// input_error, never a wrong tree. Exact kernel only (the default): its point identities are what
// the bytes carry. The "custom" heuristic's callback cannot travel: usage_error.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>

namespace exbsp {

class EXBSP_EXPORT distributed_build {
 public:
  /// Grows the top levels of bsp::build(soup, options) and writes the frontier's cells.
  /// Throws usage_error for a kernel other than exact, a score callback or the "custom"
  /// heuristic, and what bsp::build throws for bad options or input.
  distributed_build(const triangle_soup& soup, const build_options& options = {});
  distributed_build(distributed_build&&) noexcept;
  distributed_build& operator=(distributed_build&&) noexcept;
  ~distributed_build();

  /// What every worker needs besides its cell: the soup and the options (ship it once).
  const std::string& input() const;
  /// Frontier cells (at most 16; none when the top levels hold the whole tree).
  std::size_t cell_count() const;
  /// Cell i's bytes: its place in the tree and its fragments, exact.
  const std::string& cell(std::size_t i) const;
  /// A worker's job: the subtree of `cell` (bytes of cell(i)) for `input` (bytes of input()),
  /// as bytes for add_part. Thread-safe; depends on the bytes only. Throws input_error for
  /// malformed bytes, limit_error beyond options.max_fragments.
  static std::string build_cell(std::string_view input, std::string_view cell);
  /// Adds the part grown from cell i (each cell once, in any order; parts are joined in
  /// frontier order as soon as the ones before them are in).
  void add_part(std::size_t i, std::string part);
  /// The tree, once every part is in: bsp::build(soup, options)'s tree and stats (but
  /// build_seconds, the time since the constructor started, and peak_rss_bytes, this
  /// process's). Byte-identical serialize_reproducible(). Usable once.
  bsp finish();

  /// bsp::build through the distributed path in this process, one cell after the other: the
  /// reference the tests compare with.
  static bsp build_here(const triangle_soup& soup, const build_options& options = {});

 private:
  class impl;
  std::unique_ptr<impl> impl_;
};

}  // namespace exbsp
