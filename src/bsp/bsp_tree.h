// SPDX-License-Identifier: LGPL-3.0-or-later
// The BSP tree, templated on a geometry G (geometry_cgal.h for the CGAL kernels,
// geometry_exact.h for exbsp's own exact points), explicitly instantiated in bsp_<kernel>.cpp.
//
// Notation (docs/contract.md "The BSP"):
//   triangle (a,b,c), normal n = (b-a)x(c-a), f(p) = sign of orientation(a,b,c,p):
//   f > 0 on the side n points to. A node's plane is the plane of its splitter's SOURCE
//   input triangle (three input points, doubles): a fragment lies exactly in its source's
//   plane with the same orientation, so every side test is one orientation predicate on
//   three input points and one (possibly constructed) point: G::sign.
//   Classification of a triangle with signs (s0,s1,s2): all 0 -> coplanar; all >= 0 ->
//   positive; all <= 0 -> negative; otherwise straddling (then split, split_pattern.h).
// Everything is iterative: building, traversal and destruction use explicit stacks or flat
// vectors, so a degenerate tree of depth 10^5 cannot overflow the stack.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/mesh/soup.h>
#include "bsp/batch_classify.h"
#include "geom/split_pattern.h"
#include "bsp/tree_file.h"

namespace exbsp {
namespace detail {
class parallel_failure;
}

/// The tree for geometry G; bsp_tree<K> is the tree for CGAL kernel K (geometry_cgal.h).
template <class G>
class basic_bsp_tree {
 public:
  /// A stored triangle: G's representation, with .source (input triangle index) and .face.
  using fragment = typename G::fragment;

  /// A node: the plane of input triangle `plane_source`, its coplanar fragments
  /// fragments()[first, first+count) in list order, children (-1: none), parent and the
  /// side (+1/-1) of the parent's plane it lies on, and its depth (root: 1). 28 bytes: the
  /// side and the depth share one word (a deeper tree is a limit_error).
  struct node {
    node() : side_in_parent(0), depth(1) {}
    static constexpr std::uint32_t max_depth = (1u << 30) - 1;
    std::uint32_t plane_source = 0;
    std::uint32_t first = 0, count = 0;
    std::int32_t negative = -1, positive = -1, parent = -1;
    std::int32_t side_in_parent : 2;
    std::uint32_t depth : 30;
  };
  static_assert(sizeof(node) == 28, "a node is seven 32-bit words");

  /// Builds the tree. Throws usage_error (unknown heuristic, non-finite coordinates),
  /// limit_error (options.max_fragments exceeded).
  basic_bsp_tree(const triangle_soup& soup, const build_options& options);

  /// Distributed builds (tree_distributed.h; exact geometry only): the top levels of the
  /// build above, stopped at the frontier, whose cells are then written (write_cell), grown
  /// elsewhere (grow_cell) and appended in frontier order (append_part, finish_parts).
  struct top_only {};
  basic_bsp_tree(const triangle_soup& soup, const build_options& options, top_only);
  std::size_t cell_count() const { return frontier_.size(); }
  /// Frontier cell i's bytes: its side, depth, path key and fragments (it can be written
  /// once: its fragment list is freed).
  std::string write_cell(std::size_t i);
  /// A worker's job: grows the subtree of a cell written by write_cell for the same soup and
  /// options, and returns the part's bytes (its nodes and fragments).
  static std::string grow_cell(const triangle_soup& soup, const build_options& options,
                               std::string_view cell);
  /// Appends the part grown from cell i (every cell once, in order, after write_cell(i));
  /// `soup` is the one the tree was made from. Throws input_error for malformed bytes.
  void append_part(const triangle_soup& soup, std::size_t i, std::string_view part);
  /// After the last part: the stats of the whole tree, timed from `seconds`.
  void finish_parts(double seconds);

  /// Incremental insertion (tree_insert.h, bsp::inserted): the tree the naive build makes of
  /// `soup`, whose first old.stats().input_triangles triangles (and first vertices) are the
  /// input of `old`, a naive tree; the others are walked down a copy of `old`. Throws
  /// limit_error beyond options.max_fragments, and what options.progress throws.
  struct inserting {};
  basic_bsp_tree(const basic_bsp_tree& old, const triangle_soup& soup,
                 const insert_options& options, inserting);

  /// Loads a saved tree (tree_file_impl.h): the kernel's part of a tree file's body from `in`
  /// for the soup and stats of `common`. Throws input_error for anything inconsistent.
  basic_bsp_tree(const tree_file::common_part& common, tree_file::reader& in);
  /// Writes the kernel's part of a tree file's body (tree_file_impl.h).
  void write_tree(tree_file::writer& out) const;

  const build_stats& stats() const { return stats_; }
  const std::vector<fragment>& fragments() const { return fragments_; }
  const std::vector<node>& nodes() const { return nodes_; }
  const G& geometry() const { return geom_; }
  /// Index of the node whose coplanar list holds fragment i.
  std::size_t node_of_fragment(std::size_t i) const;

  /// Fragment indices back to front (or front to back) for a perspective eye.
  std::vector<std::uint32_t> order_from_eye(const vec3d& eye, bool back_to_front = true) const;
  /// Same for a parallel projection with direction of projection d (eye into the scene).
  std::vector<std::uint32_t> order_for_direction(const vec3d& d, bool back_to_front = true) const;
  /// The same for an eye or direction in the geometry's own exact types (CGAL kernels: K
  /// points and vectors, e.g. an eye exactly at a split point).
  template <class Eye>
  std::vector<std::uint32_t> order_from_eye(const Eye& eye, bool back_to_front = true) const {
    return traverse([&](std::uint32_t plane) { return geom_.side_of_eye(plane, eye); },
                    back_to_front);
  }
  template <class Direction>
  std::vector<std::uint32_t> order_for_direction(const Direction& d,
                                                 bool back_to_front = true) const {
    return traverse([&](std::uint32_t plane) { return geom_.side_of_direction(plane, d); },
                    back_to_front);
  }

  /// The traversal of bsp/traversal.h, iterative: enter(node, s) when a node is reached,
  /// list(node) at its coplanar list's place, cell(node, side) at an empty side's place.
  /// s = side_of(plane source): s > 0 or 0: negative side, list, positive side; s < 0: positive,
  /// list, negative (back to front; front to back visits the near side first).
  template <class SideOf, class Enter, class List, class Cell>
  void walk(SideOf&& side_of, bool back_to_front, Enter&& enter, List&& list, Cell&& cell) const {
    if (nodes_.empty()) return;
    struct task {
      std::int32_t node;
      std::int8_t then;  ///< 0: reach the node; +1 / -1: its list, then that side's cell if empty
    };
    std::vector<task> stack{{0, 0}};
    while (!stack.empty()) {
      const task t = stack.back();
      stack.pop_back();
      const node& nd = nodes_[t.node];
      if (t.then != 0) {
        list(t.node);
        if ((t.then > 0 ? nd.positive : nd.negative) < 0) cell(t.node, static_cast<int>(t.then));
        continue;
      }
      const int s = side_of(nd.plane_source);
      enter(t.node, s);
      const int near = s < 0 ? -1 : 1;
      const int first = back_to_front ? -near : near;
      const std::int32_t first_child = first > 0 ? nd.positive : nd.negative;
      const std::int32_t second_child = first > 0 ? nd.negative : nd.positive;
      if (second_child >= 0) stack.push_back({second_child, 0});
      stack.push_back({t.node, static_cast<std::int8_t>(-first)});
      if (first_child >= 0)
        stack.push_back({first_child, 0});
      else
        cell(t.node, first);
    }
  }

 private:
  /// The build's top levels grow breadth-first until this many cells are pending
  /// (grow_top; lay_out_in_build_order follows the same rule).
  static constexpr std::size_t frontier_size = 16;
  /// Refs to fragments: a pool_ index, or local_ref | index into a subtree's own pieces.
  static constexpr std::uint32_t local_ref = 0x80000000u;
  struct work {
    std::vector<std::uint32_t> list;  ///< fragment refs, in list order
    std::int32_t parent;              ///< parent node (index in the subtree being grown), -1: none
    std::int32_t side;
    std::uint32_t depth;
    std::uint64_t key;  ///< path key: root 1, children mix64(2 key + (side > 0))
    std::vector<detail::list_block> blocks;  ///< G::has_centres: runs of list with their boxes
  };
  /// A grown subtree's node waiting for the merge: what append_subtree cannot derive (16
  /// bytes rather than 28: first, parent, side and depth follow from counts and children).
  struct parked_node {
    std::uint32_t plane_source, count;
    std::int32_t negative, positive;
  };
  /// Nodes, fragment refs and pieces of one independently grown subtree; once grown, its
  /// parked nodes and (collect_fragments) the fragments they hold.
  struct subtree {
    std::vector<node> nodes;
    std::vector<parked_node> parked;
    std::vector<std::uint32_t> node_fragments;
    std::vector<fragment> pieces;
    std::int32_t root_parent = -1;
    std::int32_t root_side = 0;
    typename G::scratch scratch;
    std::vector<std::array<std::int8_t, 3>> signs;  ///< per list position, reused node to node
    std::vector<std::int8_t> block_signs;           ///< per list block, reused node to node
    std::vector<std::uint32_t> tasks;               ///< blocks to test fragment by fragment
    detail::sample_batch<G> sample;                 ///< the sampled heuristic's gathered sample
    /// G::filter of one input plane (made from its vertices).
    struct plane_filters {
      std::uint32_t source = ~0u;
      fast_plane_core core;
    };
    static_plane static_filter;    ///< of input plane static_filter_source (static_filter_of)
    fast_plane_core plane_filter;  ///< G::filter of that plane, from which static_filter is made
    std::uint32_t static_filter_source = ~0u;
    /// Filters made recently, by source modulo its size (static_filter_of): small nodes ask
    /// the same planes again, since every fragment of a list of at most 16 is a candidate.
    std::vector<plane_filters> recent_filters;
    /// Whether sample.best_sign() gives the exact signs of the node's list against its plane.
    bool sample_signs = false;
    detail::coplanar_sources classes;  ///< sources found in one plane, by this subtree
    /// Frees the build scratch above (scratch .. recent_filters) once the subtree is grown.
    void release_scratch() {
      // Assigning a value-initialised object, not `= {}`: for a vector, `= {}` is the
      // initializer-list assignment, which empties it but keeps its memory (and a map's
      // clear() keeps its buckets).
      scratch = decltype(scratch)();
      signs = decltype(signs)();
      block_signs = decltype(block_signs)();
      tasks = decltype(tasks)();
      sample = decltype(sample)();
      classes = decltype(classes)();
      recent_filters = decltype(recent_filters)();
    }
  };
  struct build_context;
  /// The build's top levels (into nodes_ and fragments_); returns the frontier's cells.
  std::vector<work> grow_top(const triangle_soup& soup, const build_options& options,
                             build_context& ctx);
  /// The frontier's subtrees (in parallel), then merge_parts.
  void grow_frontier(std::vector<work>& frontier, build_context& ctx);
  /// Grows one frontier cell into `part` (collected and parked, ready for the merge).
  void grow_part(work& cell, subtree& part, build_context& ctx,
                 const detail::parallel_failure& failure);
  /// Appends the parts in frontier order and sets the stats.
  void merge_parts(std::vector<subtree>& parts, build_context& ctx);
  template <class PushChild>
  void grow_node(work&& w, subtree& part, build_context& ctx, PushChild&& push_child);
  /// Replaces a grown subtree's pieces by copies of the fragments its nodes hold, node by node
  /// (dead split parents dropped), and frees its refs.
  void collect_fragments(subtree& part) const;
  /// Appends a collected subtree's fragments to fragments_ and frees them; returns where they
  /// start.
  std::uint32_t append_fragments(subtree& part);
  /// Replaces a grown subtree's nodes by parked ones.
  static void park_nodes(subtree& part);
  /// Appends a parked subtree's nodes, whose fragments start at fragment_base, to nodes_.
  void append_subtree(subtree& part, std::uint32_t fragment_base);
  /// The fragment a ref names: a pool_ index, or one of `part`'s own pieces.
  const fragment& resolve(const subtree& part, std::uint32_t ref) const {
    return (ref & local_ref) ? part.pieces[ref & ~local_ref] : pool_[ref];
  }
  std::array<int, 3> signs_against(std::uint32_t plane, const fragment& f) const {
    return {geom_.sign(plane, f, 0), geom_.sign(plane, f, 1), geom_.sign(plane, f, 2)};
  }
  geom::classification classify(std::uint32_t plane, const fragment& f) const;
  /// Back to front (docs/contract.md "The BSP") with side_of(plane source) = sign of the eye
  /// against a node's plane; iterative.
  template <class SideOf>
  std::vector<std::uint32_t> traverse(SideOf side_of, bool back_to_front) const {
    std::vector<std::uint32_t> out;
    out.reserve(fragments_.size());
    const auto none = [](std::int32_t, int) {};
    walk(
        side_of, true, none,
        [&](std::int32_t k) {
          for (std::uint32_t i = 0; i < nodes_[k].count; ++i) out.push_back(nodes_[k].first + i);
        },
        none);
    if (!back_to_front) std::reverse(out.begin(), out.end());
    return out;
  }

  /// The static filter (fast_orientation.h) of input plane `plane` over the input's box, kept
  /// in `part` for the last plane asked: a node's plane was mostly just a candidate's.
  const static_plane& static_filter_of(subtree& part, const build_context& ctx,
                                       std::uint32_t plane) const;
  /// The list position of the splitter (heuristics.h).
  std::size_t choose_splitter(const std::vector<std::uint32_t>& list, subtree& part,
                              const build_context& ctx, std::uint64_t node_key,
                              std::uint32_t depth) const;

  /// After an insert: puts nodes_ in the order the build creates them (the top levels
  /// breadth-first until 16 cells are pending, then each cell's subtree depth-first, negative
  /// side first) and fragments_ node by node, each node's old fragments then its `added` ones
  /// (node index, fragment; in list order).
  void lay_out_in_build_order(const std::vector<std::pair<std::uint32_t, fragment>>& added);

  G geom_;
  std::vector<fragment> pool_;  ///< build time only: inputs and top pieces, by index
  std::vector<fragment> fragments_;
  std::vector<node> nodes_;
  build_stats stats_;
  /// A distributed build (top_only): the frontier's cells until they are written, where each
  /// one's subtree hangs, the ids of the points each cell's bytes carry (in file order), and
  /// the top's options (kept for the limit check of the parts).
  std::vector<work> frontier_;
  struct cell_origin {
    std::int32_t parent = -1, side = 0;
    std::vector<std::uint32_t> points;
  };
  std::vector<cell_origin> cell_origins_;
  std::size_t max_fragments_ = 0, top_total_ = 0, cells_written_ = 0, parts_appended_ = 0;
  std::vector<char> usable_;  ///< append_part: which input triangles have a plane
  /// A worker's tree: the geometry of the soup, nothing built.
  struct worker {};
  basic_bsp_tree(const triangle_soup& soup, worker) : geom_(soup) {}
};

template <class K>
class cgal_geometry;
template <class K>
using bsp_tree = basic_bsp_tree<cgal_geometry<K>>;

}  // namespace exbsp
