// SPDX-License-Identifier: LGPL-3.0-or-later
// basic_bsp_tree<G> across machines (exact geometry only; exbsp/bsp/distributed.h is the public
// side). A build grows its top levels breadth-first until the frontier holds 16 cells, then
// grows each cell's subtree on its own: a cell's subtree depends only on the soup, the options
// and the cell (its fragments in list order, its side, depth and path key, from which every
// heuristic seed below it comes). So the coordinator grows the top
// (top_only), writes each cell (write_cell), workers grow them (grow_cell) and the coordinator
// appends the parts in frontier order (append_part): the tree a local build makes, node for node
// and fragment for fragment.
//
// Bytes (little-endian, tree_file.h's writer): a cell is "EXBSPCEL", u32 version, u32 cell
// index, i32 side, u32 depth, u64 path key, u64 fragments of the whole build so far, u64
// fragment limit (0: none), then its fragments as a saved tree writes them (the constructed
// points they use, renumbered, then the fragments). A part is "EXBSPPRT", u32 version, u32
// cell index, u64 splits, u64 node count and the parked nodes (u32 plane, u32 count, i32
// negative, i32 positive: indices within the part), then its fragments, whose point ids below
// V + C (input vertices and the cell's C points) are the cell's own: only points made by the
// worker are written. Points keep their identity through the round trip (one id per id), so
// the saved tree renumbers them as it would the local build's.
#pragma once
#include <chrono>
#include <limits>
#include <cstring>
#include <string>
#include <string_view>

#include <exbsp/core/errors.h>
#include "bsp/tree_build.h"

namespace exbsp {

namespace distributed_format {
inline constexpr char cell_magic[8] = {'E', 'X', 'B', 'S', 'P', 'C', 'E', 'L'};
inline constexpr char part_magic[8] = {'E', 'X', 'B', 'S', 'P', 'P', 'R', 'T'};
inline constexpr std::uint32_t version = 1;

/// Checks the magic and version at the start of `in` (input_error naming the bytes).
inline void expect_header(tree_file::reader& in, const char (&magic)[8], const char* what) {
  const std::string_view m = in.bytes("magic", 8);
  if (std::memcmp(m.data(), magic, 8) != 0)
    in.fail_at(0, "magic", std::string("not ") + what + " of a distributed exbsp build");
  const std::uint32_t v = in.u32("version");
  if (v != version)
    in.fail_at(
        8, "version",
        "version " + std::to_string(v) + " (this exbsp reads " + std::to_string(version) + ")");
}
}  // namespace distributed_format

template <class G>
basic_bsp_tree<G>::basic_bsp_tree(const triangle_soup& soup, const build_options& options, top_only)
    : geom_(soup) {
  build_options scored;
  const auto [heuristic, effective] = detail::heuristic_for(options, scored);
  build_context ctx(*effective, heuristic, std::chrono::steady_clock::now());
  frontier_ = grow_top(soup, options, ctx);
  stats_.splits = ctx.splits.load();
  max_fragments_ = options.max_fragments;
  top_total_ = ctx.total_fragments.load();
  cell_origins_.resize(frontier_.size());
  for (std::size_t i = 0; i < frontier_.size(); ++i) {
    cell_origins_[i].parent = frontier_[i].parent;
    cell_origins_[i].side = frontier_[i].side;
  }
}

template <class G>
std::string basic_bsp_tree<G>::write_cell(std::size_t i) {
  work& w = frontier_.at(i);
  std::vector<fragment> fragments;
  fragments.reserve(w.list.size());
  for (const std::uint32_t ref : w.list) fragments.push_back(pool_[ref]);  // top refs: pool_
  tree_file::writer out;
  out.bytes(distributed_format::cell_magic, 8);
  out.u32(distributed_format::version);
  out.u32(static_cast<std::uint32_t>(i));
  out.i32(w.side);
  out.u32(w.depth);
  out.u64(w.key);
  out.u64(top_total_);
  out.u64(max_fragments_);
  geom_.write_fragments(out, fragments, 0, &cell_origins_[i].points);
  w = work{};
  ++cells_written_;
  if (cells_written_ == frontier_.size()) std::vector<fragment>().swap(pool_);
  return std::move(out.data());
}

template <class G>
std::string basic_bsp_tree<G>::grow_cell(const triangle_soup& soup, const build_options& options,
                                         std::string_view cell) {
  using clock = std::chrono::steady_clock;
  tree_file::reader in(cell, "cell");
  distributed_format::expect_header(in, distributed_format::cell_magic, "a cell");
  const std::uint32_t index = in.u32("index");
  const std::int32_t side = in.i32("side");
  const std::uint32_t depth = in.u32("depth");
  const std::uint64_t key = in.u64("key");
  const std::uint64_t total = in.u64("total");
  const std::uint64_t limit = in.u64("max_fragments");
  if ((side != 1 && side != -1) || depth < 2 || depth > node::max_depth)
    in.fail("side", "side " + std::to_string(side) + ", depth " + std::to_string(depth) +
                        ": not a cell below the root");
  build_options o = options;
  o.max_fragments = static_cast<std::size_t>(limit);
  basic_bsp_tree<G> t(soup, worker{});
  std::vector<char> usable(soup.triangles.size(), 0);
  for (std::size_t k = 0; k < soup.triangles.size(); ++k) {
    fragment f;
    usable[k] = t.geom_.add_source(soup, static_cast<std::uint32_t>(k), f) ? 1 : 0;
  }
  t.geom_.read_fragments(in, soup, usable, t.pool_, {});
  if (in.remaining()) in.fail("end", std::to_string(in.remaining()) + " bytes after the fragments");
  if (t.pool_.empty()) in.fail("fragments", "a cell without fragments");
  const std::uint32_t known_end = t.geom_.point_id_end();

  build_options scored;
  const auto [heuristic, effective] = detail::heuristic_for(o, scored);
  build_context ctx(*effective, heuristic, clock::now());
  ctx.sources = soup.triangles.size();
  for (const vec3d& v : soup.vertices)
    for (int k = 0; k < 3; ++k) {
      ctx.lo[k] = std::min(ctx.lo[k], v[k]);
      ctx.hi[k] = std::max(ctx.hi[k], v[k]);
    }
  ctx.total_fragments.store(static_cast<std::size_t>(total));
  ctx.check_limit(0);
  work w;
  w.list.resize(t.pool_.size());
  for (std::size_t k = 0; k < w.list.size(); ++k) w.list[k] = static_cast<std::uint32_t>(k);
  w.parent = -1;
  w.side = side;
  w.depth = depth;
  w.key = key;
  if constexpr (detail::has_centres<G>::value)
    w.blocks = detail::make_blocks(
        w.list, [&](std::uint32_t ref) { return detail::fragment_box(t.geom_, t.pool_[ref]); });
  subtree part;
  detail::parallel_failure failure;
  t.grow_part(w, part, ctx, failure);

  tree_file::writer out;
  out.bytes(distributed_format::part_magic, 8);
  out.u32(distributed_format::version);
  out.u32(index);
  out.u64(ctx.splits.load());
  out.u64(part.parked.size());
  for (const parked_node& p : part.parked) {
    out.u32(p.plane_source);
    out.u32(p.count);
    out.i32(p.negative);
    out.i32(p.positive);
  }
  t.geom_.write_fragments(out, part.pieces, known_end, nullptr);
  return std::move(out.data());
}

template <class G>
void basic_bsp_tree<G>::append_part(const triangle_soup& soup, std::size_t i,
                                    std::string_view bytes) {
  if (i != parts_appended_ || i >= cell_origins_.size())
    throw usage_error("append_part: part " + std::to_string(i) + " out of order (expected " +
                      std::to_string(parts_appended_) + " of " +
                      std::to_string(cell_origins_.size()) + ")");
  const std::string name = "part " + std::to_string(i);
  tree_file::reader in(bytes, name);
  distributed_format::expect_header(in, distributed_format::part_magic, "a part");
  const std::uint32_t index = in.u32("index");
  if (index != i) in.fail("index", "the part of cell " + std::to_string(index));
  const std::uint64_t splits = in.u64("splits");
  subtree part;
  part.root_parent = cell_origins_[i].parent;
  part.root_side = cell_origins_[i].side;
  const std::size_t count = in.count("nodes", 16, std::numeric_limits<std::uint32_t>::max());
  part.parked.resize(count);
  std::vector<char>& usable = usable_;  // the input triangles with a plane, found once
  if (usable.empty()) {
    usable.assign(soup.triangles.size(), 0);
    for (std::size_t k = 0; k < soup.triangles.size(); ++k) {
      fragment f;
      usable[k] = geom_.add_source(soup, static_cast<std::uint32_t>(k), f) ? 1 : 0;
    }
  }
  std::uint64_t held = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t at = in.offset();
    parked_node& p = part.parked[k];
    p.plane_source = in.u32("nodes");
    p.count = in.u32("nodes");
    p.negative = in.i32("nodes");
    p.positive = in.i32("nodes");
    const std::string field = tree_file::indexed("nodes", k);
    if (p.plane_source >= soup.triangles.size() || !usable[p.plane_source])
      in.fail_at(at, field, "plane " + std::to_string(p.plane_source) + " is not an input plane");
    if (p.count == 0) in.fail_at(at, field, "a node without fragments");
    for (const std::int32_t child : {p.negative, p.positive})
      if (child != -1 &&
          (child <= static_cast<std::int64_t>(k) || static_cast<std::size_t>(child) >= count))
        in.fail_at(at, field, "child " + std::to_string(child) + " is neither -1 nor a later node");
    held += p.count;
  }
  if (count == 0) in.fail("nodes", "a part without nodes");
  geom_.read_fragments(in, soup, usable, part.pieces, cell_origins_[i].points);
  if (in.remaining()) in.fail("end", std::to_string(in.remaining()) + " bytes after the fragments");
  if (held != part.pieces.size())
    in.fail("fragments", "the nodes hold " + std::to_string(held) + " fragments, the part has " +
                             std::to_string(part.pieces.size()));
  stats_.splits += static_cast<std::size_t>(splits);
  cell_origins_[i].points = {};
  ++parts_appended_;
  append_subtree(part, append_fragments(part));
}

template <class G>
void basic_bsp_tree<G>::finish_parts(double seconds) {
  if (parts_appended_ != cell_origins_.size())
    throw usage_error("finish: " + std::to_string(parts_appended_) + " of " +
                      std::to_string(cell_origins_.size()) + " parts appended");
  if (max_fragments_ && fragments_.size() > max_fragments_)
    throw limit_error("fragment limit exceeded: the tree needs more than " +
                      std::to_string(max_fragments_) + " fragments (--max-fragments)");
  stats_.fragments = fragments_.size();
  stats_.nodes = nodes_.size();
  stats_.build_seconds = seconds;
  stats_.peak_rss_bytes = peak_rss_bytes();
}

}  // namespace exbsp
