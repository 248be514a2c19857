// SPDX-License-Identifier: LGPL-3.0-or-later
// basic_bsp_tree<G>, the build's orchestration: classification, the shared state of one build
// (build_context), the constructor that runs the top levels breadth-first and then the
// pending subtrees in parallel, and the merge of each subtree into the tree. Part of
// bsp_tree_impl.h (included only by the per-kernel translation units); notation: bsp_tree.h.
#pragma once
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <iterator>
#include <mutex>
#include <string>
#include <utility>

#include <exbsp/core/errors.h>
#include "bsp/bsp_impl.h"
#include "bsp/bsp_tree.h"
#include "bsp/exact_output.h"
#include "bsp/heuristic_table.h"
#include "bsp/heuristics.h"
#include "bsp/kernels.h"
#include "bsp/parallel.h"
#include "bsp/tree_file_impl.h"

namespace exbsp {

/// Classification of f against the plane; skips the third predicate when the first two
/// already have opposite signs.
template <class G>
geom::classification basic_bsp_tree<G>::classify(std::uint32_t plane, const fragment& f) const {
  const int s0 = geom_.sign(plane, f, 0);
  const int s1 = geom_.sign(plane, f, 1);
  if (s0 * s1 < 0) return geom::classification::straddling;
  return geom::classify_signs({s0, s1, geom_.sign(plane, f, 2)});
}

/// Shared state of one build: options and the counters updated by all threads.
template <class G>
struct basic_bsp_tree<G>::build_context {
  build_context(const build_options& o, detail::heuristic_id h,
                std::chrono::steady_clock::time_point t)
      : options(o), heuristic(h), start(t) {}
  const build_options& options;
  detail::heuristic_id heuristic;
  /// Bounding box of the input vertices: it holds every exact point of the build (static
  /// filters of batch_classify.h).
  vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  std::size_t sources = 0;  ///< input triangles (source ids are below)
  std::chrono::steady_clock::time_point start;
  std::atomic<std::size_t> total_fragments{0}, splits{0}, placed{0}, nodes{0};
  std::mutex progress_mutex;
  bool progress_threw = false;  ///< guarded by progress_mutex
  /// Calls options.progress on this thread unless another thread is inside it (then this
  /// report is skipped): one call at a time, from any thread, so a cancelling exception
  /// arrives while any part of the tree is still being built. What it throws propagates, and
  /// progress is not called again.
  void report(std::size_t placed_now, std::size_t nodes_now) {
    const std::unique_lock<std::mutex> lock(progress_mutex, std::try_to_lock);
    if (!lock.owns_lock() || progress_threw) return;
    try {
      options.progress(
          {placed_now, total_fragments.load(std::memory_order_relaxed), nodes_now,
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    } catch (...) {
      progress_threw = true;
      throw;
    }
  }
  /// Counts `added` new fragments; throws limit_error beyond options.max_fragments.
  void check_limit(std::size_t added) {
    const std::size_t total = total_fragments.fetch_add(added, std::memory_order_relaxed) + added;
    if (options.max_fragments && total > options.max_fragments)
      throw limit_error("fragment limit exceeded: the tree needs more than " +
                        std::to_string(options.max_fragments) + " fragments (--max-fragments)");
  }
};

template <class G>
basic_bsp_tree<G>::basic_bsp_tree(const triangle_soup& soup, const build_options& options)
    : geom_(soup) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  build_options scored;  // a heuristic row's score, when the heuristic is one (heuristic_table.h)
  const auto [heuristic, effective] = detail::heuristic_for(options, scored);
  build_context ctx(*effective, heuristic, start);
  // This thread also reports from inside long heuristic steps (cancellation, parallel.h).
  detail::build_poller poller{[&ctx] {
                                ctx.report(ctx.placed.load(std::memory_order_relaxed),
                                           ctx.nodes.load(std::memory_order_relaxed));
                              },
                              start + std::chrono::milliseconds(100)};
  const detail::scoped_poller polling(options.progress ? &poller : nullptr);
  std::vector<work> frontier = grow_top(soup, options, ctx);
  grow_frontier(frontier, ctx);
}

template <class G>
auto basic_bsp_tree<G>::grow_top(const triangle_soup& soup, const build_options& options,
                                 build_context& ctx) -> std::vector<work> {
  stats_.kernel = to_string(G::id);
  stats_.heuristic = options.heuristic;
  stats_.seed = options.seed;
  stats_.input_triangles = soup.triangles.size();

  for (std::size_t i = 0; i < soup.vertices.size(); ++i)
    for (double x : soup.vertices[i])
      if (!std::isfinite(x))
        throw usage_error("bsp build: vertex " + std::to_string(i) +
                          " has a non-finite coordinate");

  // Input triangles; the exactly degenerate (collinear) ones are skipped and counted.
  // Fragments live in pool_ (inputs, then the top levels' pieces) and in each subtree's
  // pieces (split parents stay there, dead, until the merge); work lists hold refs, so moving
  // a list down the tree moves 4 bytes per fragment.
  pool_.reserve(soup.triangles.size());
  std::vector<std::uint32_t> root_list;
  root_list.reserve(soup.triangles.size());
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    fragment f;
    if (!geom_.add_source(soup, static_cast<std::uint32_t>(i), f)) {
      ++stats_.degenerate_input;
      continue;
    }
    root_list.push_back(static_cast<std::uint32_t>(pool_.size()));
    pool_.push_back(f);
  }

  // The build runs in two phases with the same per-node step (grow): the top levels
  // breadth-first on this thread until there are `frontier_size` pending subtrees, then those
  // subtrees in parallel, each into its own node list and piece pool, merged in frontier order.
  // Heuristic seeds come from each node's path key, not from a creation counter, and the
  // frontier size is fixed, so the tree is the same for any number of threads (and for a
  // build whose subtrees grow on other machines: tree_distributed.h).
  ctx.sources = soup.triangles.size();
  for (const vec3d& v : soup.vertices)
    for (int k = 0; k < 3; ++k) {
      ctx.lo[k] = std::min(ctx.lo[k], v[k]);
      ctx.hi[k] = std::max(ctx.hi[k], v[k]);
    }
  ctx.check_limit(root_list.size());
  std::deque<work> queue;
  if (!root_list.empty()) {
    std::vector<detail::list_block> blocks;
    if constexpr (detail::has_centres<G>::value)
      blocks = detail::make_blocks(
          root_list, [&](std::uint32_t ref) { return detail::fragment_box(geom_, pool_[ref]); });
    queue.push_back({std::move(root_list), -1, 0, 1, 1, std::move(blocks)});
  }
  subtree top;
  while (!queue.empty() && queue.size() < frontier_size) {
    work w = std::move(queue.front());
    queue.pop_front();
    grow_node(std::move(w), top, ctx, [&](work&& child) { queue.push_back(std::move(child)); });
  }
  top.release_scratch();
  // Top pieces join the shared read-only pool; refs to them become plain pool indices.
  const auto top_base = static_cast<std::uint32_t>(pool_.size());
  pool_.reserve(pool_.size() + top.pieces.size());
  for (fragment& f : top.pieces) pool_.push_back(std::move(f));
  std::vector<fragment>().swap(top.pieces);
  const auto remap = [](std::uint32_t ref, std::uint32_t base) {
    return (ref & local_ref) ? base + (ref & ~local_ref) : ref;
  };
  for (std::uint32_t& ref : top.node_fragments) ref = remap(ref, top_base);
  for (work& w : queue)
    for (std::uint32_t& ref : w.list) ref = remap(ref, top_base);
  collect_fragments(top);
  park_nodes(top);
  append_subtree(top, append_fragments(top));
  return {std::make_move_iterator(queue.begin()), std::make_move_iterator(queue.end())};
}

template <class G>
void basic_bsp_tree<G>::grow_frontier(std::vector<work>& frontier, build_context& ctx) {
  const build_options& options = ctx.options;
  std::vector<subtree> parts(frontier.size());
  detail::parallel_failure failure;
  const long long count = static_cast<long long>(frontier.size());
  // Few fragments left (options.parallel_min_fragments): one thread. Such a build takes
  // milliseconds, and waking a second thread, then waiting at the end for the slowest part,
  // cost more than it saved (measured on 2 busy cores: part 3.0 ms on one thread, 11.7 ms on
  // two; blade 41 ms against 62 ms).
  std::size_t pending = 0;
  for (const work& w : frontier) pending += w.list.size();
#pragma omp parallel for schedule(dynamic, 1) if (pending >= options.parallel_min_fragments) \
    num_threads(detail::threads_for(options.threads))
  for (long long i = 0; i < count; ++i) {
    failure.run([&] {
      subtree& part = parts[static_cast<std::size_t>(i)];
      grow_part(frontier[static_cast<std::size_t>(i)], part, ctx, failure);
    });
  }
  failure.rethrow();
  merge_parts(parts, ctx);
}

template <class G>
void basic_bsp_tree<G>::grow_part(work& cell, subtree& part, build_context& ctx,
                                  const detail::parallel_failure& failure) {
  part.root_parent = cell.parent;
  part.root_side = cell.side;
  cell.parent = -1;  // local to the part from here on
  std::vector<work> stack;
  stack.push_back(std::move(cell));
  while (!stack.empty() && !failure.failed()) {
    work w = std::move(stack.back());
    stack.pop_back();
    grow_node(std::move(w), part, ctx, [&](work&& child) { stack.push_back(std::move(child)); });
  }
  // The part waits for the merge holding only its live fragments and nodes, without
  // growth slack; its build scratch is freed first.
  part.release_scratch();
  collect_fragments(part);
  park_nodes(part);
}

template <class G>
void basic_bsp_tree<G>::merge_parts(std::vector<subtree>& parts, build_context& ctx) {
  const build_options& options = ctx.options;
  // The side tests are done: the exact values they memoised go before the merge (output
  // makes again those it needs).
  if constexpr (detail::has_centres<G>::value) geom_.forget_exact_values();
  // Merge in frontier order. Memory: the fragments first, each part's freed as soon as they
  // are copied, then the nodes; both final arrays are reserved exactly. The peak (the node
  // step) holds the final fragments, the final nodes and the parked ones: no growth slack, no
  // dead split parents, no refs.
  std::size_t fragment_total = fragments_.size(), node_total = nodes_.size();
  for (const subtree& part : parts) {
    fragment_total += part.pieces.size();
    node_total += part.parked.size();
  }
  std::vector<fragment>().swap(pool_);  // every part holds copies of the fragments it uses
  fragments_.reserve(fragment_total);
  std::vector<std::uint32_t> fragment_bases;
  fragment_bases.reserve(parts.size());
  for (subtree& part : parts) fragment_bases.push_back(append_fragments(part));
  nodes_.reserve(node_total);
  for (std::size_t i = 0; i < parts.size(); ++i) append_subtree(parts[i], fragment_bases[i]);
  stats_.splits = ctx.splits.load();
  stats_.fragments = fragments_.size();
  stats_.nodes = nodes_.size();
  stats_.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - ctx.start).count();
  stats_.peak_rss_bytes = peak_rss_bytes();
  if (options.progress)
    options.progress(
        {fragments_.size(), ctx.total_fragments.load(), nodes_.size(), stats_.build_seconds});
}

template <class G>
void basic_bsp_tree<G>::collect_fragments(subtree& part) const {
  std::vector<fragment> live;
  live.reserve(part.node_fragments.size());
  for (std::uint32_t ref : part.node_fragments) live.push_back(resolve(part, ref));
  part.pieces = std::move(live);
  std::vector<std::uint32_t>().swap(part.node_fragments);
}

template <class G>
std::uint32_t basic_bsp_tree<G>::append_fragments(subtree& part) {
  const auto base = static_cast<std::uint32_t>(fragments_.size());
  fragments_.insert(fragments_.end(), part.pieces.begin(), part.pieces.end());
  std::vector<fragment>().swap(part.pieces);
  return base;
}

template <class G>
void basic_bsp_tree<G>::park_nodes(subtree& part) {
  part.parked.reserve(part.nodes.size());
  for (const node& nd : part.nodes)
    part.parked.push_back({nd.plane_source, nd.count, nd.negative, nd.positive});
  std::vector<node>().swap(part.nodes);
}

template <class G>
void basic_bsp_tree<G>::append_subtree(subtree& part, std::uint32_t fragment_base) {
  const std::size_t node_base = nodes_.size();
  std::uint32_t first = fragment_base;
  const auto global = [&](std::int32_t local) {
    return local < 0 ? -1 : static_cast<std::int32_t>(node_base) + local;
  };
  for (const parked_node& p : part.parked) {
    node nd;
    nd.plane_source = p.plane_source;
    nd.first = first;
    nd.count = p.count;
    first += p.count;
    nd.negative = global(p.negative);
    nd.positive = global(p.positive);
    nodes_.push_back(nd);
  }
  std::vector<parked_node>().swap(part.parked);
  if (nodes_.size() == node_base) return;
  if (part.root_parent >= 0) {  // the part's root hangs below a node built earlier
    node& root = nodes_[node_base];
    node& parent = nodes_[static_cast<std::size_t>(part.root_parent)];
    root.parent = part.root_parent;
    root.side_in_parent = part.root_side;
    root.depth = parent.depth + 1;
    (part.root_side > 0 ? parent.positive : parent.negative) = static_cast<std::int32_t>(node_base);
  }
  // Parents, sides and depths from the children links: a node comes before its children.
  for (std::size_t k = node_base; k < nodes_.size(); ++k) {
    const node& nd = nodes_[k];
    for (const auto& [child, side] :
         {std::pair<std::int32_t, int>{nd.negative, -1}, {nd.positive, +1}}) {
      if (child < 0) continue;
      node& c = nodes_[static_cast<std::size_t>(child)];
      c.parent = static_cast<std::int32_t>(k);
      c.side_in_parent = side;
      c.depth = nd.depth + 1;
    }
    stats_.depth = std::max<std::size_t>(stats_.depth, nd.depth);
  }
}

}  // namespace exbsp
