// SPDX-License-Identifier: LGPL-3.0-or-later
// Saved trees: the kernel-independent half of a tree's own part (the nodes) and the loading
// constructor of basic_bsp_tree<G>. Included by bsp_tree_impl.h, instantiated with the tree.
// Notation: tree_file.h; layout and checks: docs/tree-file.md.
//
// The loaded nodes must form the tree a build makes: node 0 is the root, every other node is
// the child of exactly one node with a smaller index (so the structure is a tree, acyclic,
// and parents, sides and depths follow in one pass, without recursion), each node holds at
// least one fragment, their lists are consecutive runs covering all fragments in order, and
// one of a node's fragments comes from the triangle whose plane the node uses.
#pragma once
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <exbsp/core/errors.h>
#include "bsp/bsp_tree.h"
#include "bsp/tree_file.h"

namespace exbsp {

template <class G>
void basic_bsp_tree<G>::write_tree(tree_file::writer& out) const {
  geom_.write_fragments(out, fragments_);
  out.u64(nodes_.size());
  for (const node& nd : nodes_) {
    out.u32(nd.plane_source);
    out.u32(nd.count);
    out.i32(nd.negative);
    out.i32(nd.positive);
  }
}

template <class G>
basic_bsp_tree<G>::basic_bsp_tree(const tree_file::common_part& common, tree_file::reader& in)
    : geom_(common.soup) {
  using tree_file::indexed;
  const triangle_soup& soup = common.soup;
  stats_ = common.stats;
  stats_.kernel = to_string(G::id);

  // The input triangles, with the build's degenerate test.
  std::vector<char> usable(soup.triangles.size(), 0);
  std::size_t degenerate = 0;
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    fragment f;
    if (geom_.add_source(soup, static_cast<std::uint32_t>(i), f))
      usable[i] = 1;
    else
      ++degenerate;
  }
  geom_.read_fragments(in, soup, usable, fragments_);
  const std::size_t fragment_count = fragments_.size();

  const std::size_t count = in.count("nodes", 16, fragment_count);
  if ((count == 0) != (fragment_count == 0))
    in.fail("nodes",
            std::to_string(count) + " nodes for " + std::to_string(fragment_count) + " fragments");
  nodes_.resize(count);  // parent -1, depth 1 until set
  std::size_t first = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = in.offset();
    const std::string field = indexed("nodes", i);
    node& nd = nodes_[i];
    nd.plane_source = in.u32("nodes");
    nd.count = in.u32("nodes");
    nd.negative = in.i32("nodes");
    nd.positive = in.i32("nodes");
    if (nd.plane_source >= soup.triangles.size() || !usable[nd.plane_source])
      in.fail_at(
          at, field,
          "plane " + std::to_string(nd.plane_source) + " is not a non-degenerate input triangle");
    if (nd.count == 0 || nd.count > fragment_count - first)
      in.fail_at(at, field,
                 "fragment count " + std::to_string(nd.count) + " (" +
                     std::to_string(fragment_count - first) + " fragments left)");
    nd.first = static_cast<std::uint32_t>(first);
    first += nd.count;
    bool has_splitter = false;
    for (std::size_t k = nd.first; k < first && !has_splitter; ++k)
      has_splitter = fragments_[k].source == nd.plane_source;
    if (!has_splitter)
      in.fail_at(at, field,
                 "no fragment of the node lies in triangle " + std::to_string(nd.plane_source));
    if (i > 0 && nd.parent < 0) in.fail_at(at, field, "not a child of an earlier node");
    if (nd.parent >= 0 && nodes_[nd.parent].depth == node::max_depth)
      in.fail_at(at, field, "deeper than " + std::to_string(node::max_depth));
    nd.depth = nd.parent < 0 ? 1 : nodes_[nd.parent].depth + 1;
    for (const auto& [child, side] :
         {std::pair<std::int32_t, int>{nd.negative, -1}, {nd.positive, +1}}) {
      if (child == -1) continue;
      if (child <= static_cast<std::int64_t>(i) || static_cast<std::size_t>(child) >= count)
        in.fail_at(at, field, "child " + std::to_string(child) + " is neither -1 nor a later node");
      node& c = nodes_[child];
      if (c.parent >= 0)
        in.fail_at(at, field, "node " + std::to_string(child) + " has two parents");
      c.parent = static_cast<std::int32_t>(i);
      c.side_in_parent = side;
    }
  }
  if (first != fragment_count)
    in.fail("nodes", "the nodes hold " + std::to_string(first) + " of " +
                         std::to_string(fragment_count) + " fragments");
  std::size_t depth = 0;
  for (const node& nd : nodes_) depth = std::max<std::size_t>(depth, nd.depth);

  // The stats must describe this tree.
  const auto check = [&](const char* field, std::size_t stored, std::size_t actual) {
    if (stored != actual)
      in.fail_at(common.stats_offset, field,
                 std::to_string(stored) + " but the tree has " + std::to_string(actual));
  };
  check("stats.input_triangles", common.stats.input_triangles, soup.triangles.size());
  check("stats.degenerate_input", common.stats.degenerate_input, degenerate);
  check("stats.fragments", common.stats.fragments, fragment_count);
  check("stats.nodes", common.stats.nodes, count);
  check("stats.depth", common.stats.depth, depth);
  // Each split replaces one fragment by two or three.
  const std::size_t inputs = soup.triangles.size() - degenerate, splits = common.stats.splits;
  if (fragment_count < inputs || splits > fragment_count - inputs ||
      2 * splits < fragment_count - inputs)
    in.fail_at(common.stats_offset, "stats.splits",
               std::to_string(splits) + " splits cannot turn " + std::to_string(inputs) +
                   " triangles into " + std::to_string(fragment_count) + " fragments");
  stats_.depth = depth;
}

}  // namespace exbsp
