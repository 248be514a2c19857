// SPDX-License-Identifier: LGPL-3.0-or-later
// basic_bsp_tree<G>, incremental insertion (bsp::inserted; the course notes' add(root, T)):
// the naive build's tree of a soup whose first triangles are an old naive tree's input, made
// from a copy of that tree. Part of bsp_tree_impl.h; notation: bsp_tree.h.
//
// Why it is the build's tree. With the naive heuristic a node's splitter is the first
// fragment of its list; the new triangles come after the old ones in every list (lists keep
// order, pieces replace their parent), so every old node keeps its splitter, and every old
// fragment its place. The new fragments reaching a node are, in list order, the ones the
// build would distribute there after the old ones: they are classified against the node's
// plane with the build's exact signs (a fragment of the node's own source is coplanar by
// construction), coplanar ones are appended to its list, straddling ones split by the build's
// split into its ordered pieces, and the lists passed on to the children. Reaching an empty
// side, a list is what the build would grow a new subtree from: the same step makes each new
// node, its first fragment the splitter. Each node is reached by one list (its parent's), so
// the split points shared within a node are the build's (tree_grow.h shares them within a
// node only; old and new fragments never share one: a new fragment's points are made from
// the new vertices). Last, the nodes are put in the order the build creates them and the
// fragments node by node (lay_out_in_build_order).
#pragma once
#include <deque>

#include "bsp/tree_build.h"  // its includes, build_context and classify

namespace exbsp {

template <class G>
basic_bsp_tree<G>::basic_bsp_tree(const basic_bsp_tree& old, const triangle_soup& soup,
                                  const insert_options& options, inserting)
    : geom_(soup) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const std::size_t old_triangles = old.stats_.input_triangles;
  stats_ = old.stats_;
  stats_.input_triangles = soup.triangles.size();

  // The old tree in this geometry: its sources (the old degenerate ones already counted),
  // points, fragments and nodes.
  for (std::size_t i = 0; i < old_triangles; ++i) {
    fragment f;
    geom_.add_source(soup, static_cast<std::uint32_t>(i), f);
  }
  fragments_ = old.fragments_;
  geom_.import_points(old.geom_, fragments_);
  nodes_ = old.nodes_;

  std::vector<fragment> list;  // the new triangles in order
  for (std::size_t i = old_triangles; i < soup.triangles.size(); ++i) {
    fragment f;
    if (geom_.add_source(soup, static_cast<std::uint32_t>(i), f))
      list.push_back(f);
    else
      ++stats_.degenerate_input;
  }
  const std::size_t old_fragments = fragments_.size();
  std::size_t total = old_fragments + list.size();
  const auto check_limit = [&] {
    if (options.max_fragments && total > options.max_fragments)
      throw limit_error("fragment limit exceeded: the tree needs more than " +
                        std::to_string(options.max_fragments) + " fragments (--max-fragments)");
  };
  check_limit();

  // The walk: one list per node reached, an explicit stack (naive trees are deep).
  struct reach {
    std::vector<fragment> list;
    std::int32_t node;    ///< the node, or -1: a new node below `parent`
    std::int32_t parent;  ///< for a new node
    std::int32_t side;
    std::uint32_t depth;
  };
  std::vector<std::pair<std::uint32_t, fragment>> added;  // (node, fragment), in list order
  std::vector<reach> stack;
  if (!list.empty()) stack.push_back({std::move(list), nodes_.empty() ? -1 : 0, -1, 0, 1});
  typename G::scratch scratch;
  std::size_t reached = 0;
  const auto report = [&] {
    options.progress({old_fragments + added.size(), total, nodes_.size(),
                      std::chrono::duration<double>(clock::now() - start).count()});
  };
  while (!stack.empty()) {
    reach r = std::move(stack.back());
    stack.pop_back();
    std::int32_t id = r.node;
    if (id < 0) {  // a new node: the first fragment of its list splits it (naive)
      if (r.depth > node::max_depth)
        throw limit_error("bsp build: the tree is deeper than " + std::to_string(node::max_depth));
      id = static_cast<std::int32_t>(nodes_.size());
      node nd;
      nd.plane_source = r.list.front().source;
      nd.parent = r.parent;
      nd.side_in_parent = r.side;
      nd.depth = r.depth;
      nd.count = 0;
      if (r.parent >= 0) (r.side > 0 ? nodes_[r.parent].positive : nodes_[r.parent].negative) = id;
      nodes_.push_back(nd);
    }
    const std::uint32_t plane = nodes_[id].plane_source;
    scratch.plane = ~std::uint32_t{0};  // split points shared within this node only
    std::vector<fragment> negative, positive;
    for (const fragment& f : r.list) {
      const std::array<int, 3> s =
          f.source == plane ? std::array<int, 3>{0, 0, 0} : signs_against(plane, f);
      switch (geom::classify_signs(s)) {
        case geom::classification::coplanar:
          added.emplace_back(static_cast<std::uint32_t>(id), f);
          break;
        case geom::classification::positive:
          positive.push_back(f);
          break;
        case geom::classification::negative:
          negative.push_back(f);
          break;
        case geom::classification::straddling: {
          const geom::split_pattern pattern = geom::make_split_pattern(s);
          std::array<fragment, 3> pieces;
          geom_.split(plane, f, pattern, pieces, scratch);
          ++stats_.splits;
          total += static_cast<std::size_t>(pattern.pieces - 1);
          check_limit();
          for (int k = 0; k < pattern.pieces; ++k)
            (pattern.side[k] > 0 ? positive : negative).push_back(pieces[k]);
          break;
        }
      }
    }
    const node nd = nodes_[id];
    const std::uint32_t below = static_cast<std::uint32_t>(nd.depth) + 1;
    if (!positive.empty()) stack.push_back({std::move(positive), nd.positive, id, +1, below});
    if (!negative.empty()) stack.push_back({std::move(negative), nd.negative, id, -1, below});
    if (options.progress && (++reached & 255) == 0) report();
  }

  lay_out_in_build_order(added);
  stats_.fragments = fragments_.size();
  stats_.nodes = nodes_.size();
  stats_.depth = 0;
  for (const node& nd : nodes_) stats_.depth = std::max<std::size_t>(stats_.depth, nd.depth);
  stats_.build_seconds =
      old.stats_.build_seconds + std::chrono::duration<double>(clock::now() - start).count();
  stats_.peak_rss_bytes = peak_rss_bytes();
  if (options.progress) report();
}

template <class G>
void basic_bsp_tree<G>::lay_out_in_build_order(
    const std::vector<std::pair<std::uint32_t, fragment>>& added) {
  const std::size_t n = nodes_.size();
  // The build's node order (tree_build.h): grow_top pops its queue's front and pushes the
  // positive child, then the negative one, while fewer than frontier_size are pending; each
  // pending cell is then grown from a stack (grow_part), the negative child popped first.
  std::vector<std::uint32_t> order;
  order.reserve(n);
  std::deque<std::uint32_t> queue;
  if (n) queue.push_back(0);
  while (!queue.empty() && queue.size() < frontier_size) {
    const std::uint32_t k = queue.front();
    queue.pop_front();
    order.push_back(k);
    if (nodes_[k].positive >= 0) queue.push_back(static_cast<std::uint32_t>(nodes_[k].positive));
    if (nodes_[k].negative >= 0) queue.push_back(static_cast<std::uint32_t>(nodes_[k].negative));
  }
  std::vector<std::uint32_t> stack;
  for (const std::uint32_t cell : queue) {
    stack.push_back(cell);
    while (!stack.empty()) {
      const std::uint32_t k = stack.back();
      stack.pop_back();
      order.push_back(k);
      if (nodes_[k].positive >= 0) stack.push_back(static_cast<std::uint32_t>(nodes_[k].positive));
      if (nodes_[k].negative >= 0) stack.push_back(static_cast<std::uint32_t>(nodes_[k].negative));
    }
  }
  std::vector<std::int32_t> renamed(n);
  for (std::size_t i = 0; i < n; ++i) renamed[order[i]] = static_cast<std::int32_t>(i);

  // The added fragments grouped by node, in list order (a counting sort).
  std::vector<std::uint32_t> added_first(n + 1, 0);
  for (const auto& a : added) ++added_first[a.first + 1];
  for (std::size_t k = 0; k < n; ++k) added_first[k + 1] += added_first[k];
  std::vector<std::uint32_t> by_node(added.size());
  {
    std::vector<std::uint32_t> next(added_first.begin(), added_first.end() - 1);
    for (std::size_t i = 0; i < added.size(); ++i)
      by_node[next[added[i].first]++] = static_cast<std::uint32_t>(i);
  }

  std::vector<fragment> fragments;
  fragments.reserve(fragments_.size() + added.size());
  std::vector<node> nodes(n);
  for (std::size_t i = 0; i < n; ++i) {
    const node& from = nodes_[order[i]];
    node& to = nodes[i];
    to = from;
    to.first = static_cast<std::uint32_t>(fragments.size());
    fragments.insert(fragments.end(), fragments_.begin() + from.first,
                     fragments_.begin() + from.first + from.count);
    for (std::uint32_t j = added_first[order[i]]; j < added_first[order[i] + 1]; ++j)
      fragments.push_back(added[by_node[j]].second);
    to.count = static_cast<std::uint32_t>(fragments.size() - to.first);
    to.parent = from.parent < 0 ? -1 : renamed[from.parent];
    to.negative = from.negative < 0 ? -1 : renamed[from.negative];
    to.positive = from.positive < 0 ? -1 : renamed[from.positive];
  }
  fragments_ = std::move(fragments);
  nodes_ = std::move(nodes);
}

}  // namespace exbsp
