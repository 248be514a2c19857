// SPDX-License-Identifier: LGPL-3.0-or-later
// Definitions of basic_bsp_tree<G>. Included only by the per-kernel translation units
// (bsp_<kernel>.cpp), which instantiate them explicitly.
// Notation: see bsp_tree.h. The splitter heuristics are in heuristics.h.
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
  // frontier size is fixed, so the tree is the same for any number of threads.
  build_context ctx(*effective, heuristic, start);
  // This thread also reports from inside long heuristic steps (cancellation, parallel.h).
  detail::build_poller poller{[&ctx] {
                                ctx.report(ctx.placed.load(std::memory_order_relaxed),
                                           ctx.nodes.load(std::memory_order_relaxed));
                              },
                              start + std::chrono::milliseconds(100)};
  const detail::scoped_poller polling(options.progress ? &poller : nullptr);
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
  constexpr std::size_t frontier_size = 16;
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

  std::vector<work> frontier(std::make_move_iterator(queue.begin()),
                             std::make_move_iterator(queue.end()));
  queue.clear();
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
      part.root_parent = frontier[static_cast<std::size_t>(i)].parent;
      part.root_side = frontier[static_cast<std::size_t>(i)].side;
      frontier[static_cast<std::size_t>(i)].parent = -1;  // local to the part from here on
      std::vector<work> stack;
      stack.push_back(std::move(frontier[static_cast<std::size_t>(i)]));
      while (!stack.empty() && !failure.failed()) {
        work w = std::move(stack.back());
        stack.pop_back();
        grow_node(std::move(w), part, ctx,
                  [&](work&& child) { stack.push_back(std::move(child)); });
      }
      // The part waits for the merge holding only its live fragments and nodes, without
      // growth slack; its build scratch is freed first.
      part.release_scratch();
      collect_fragments(part);
      park_nodes(part);
    });
  }
  failure.rethrow();
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
  stats_.build_seconds = std::chrono::duration<double>(clock::now() - start).count();
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

template <class G>
template <class PushChild>
void basic_bsp_tree<G>::grow_node(work&& w, subtree& part, build_context& ctx,
                                  PushChild&& push_child) {
  const auto fragment_at = [&](std::uint32_t ref) -> const fragment& { return resolve(part, ref); };
  const build_options& options = ctx.options;
  const std::size_t splitter = choose_splitter(w.list, part, ctx, w.key, w.depth);
  const std::uint32_t plane_source = fragment_at(w.list[splitter]).source;

  const auto id = static_cast<std::int32_t>(part.nodes.size());
  node nd;
  nd.plane_source = plane_source;
  nd.first = static_cast<std::uint32_t>(part.node_fragments.size());
  nd.parent = w.parent;
  nd.side_in_parent = w.side;
  if (w.depth > node::max_depth)
    throw limit_error("bsp build: the tree is deeper than " + std::to_string(node::max_depth));
  nd.depth = w.depth;
  if (w.parent >= 0)
    (w.side > 0 ? part.nodes[w.parent].positive : part.nodes[w.parent].negative) = id;

  // Side tests first (in parallel for very long lists: they dominate degenerate trees), then
  // the sequential, order-keeping distribution with the exact splits. With G::has_centres the
  // list comes in blocks (batch_classify.h): a block certified on one side moves whole, the
  // others are tested fragment by fragment with the static filter first.
  constexpr bool batched = detail::has_centres<G>::value;
  const std::size_t n = w.list.size();
  part.signs.resize(n);
  const auto test_fragment = [&](std::size_t j) {
    // A fragment lies exactly in its source's plane: coplanar by construction. (Exact
    // kernels would find the same; rounded ones could not, and would loop forever.)
    const fragment& f = fragment_at(w.list[j]);
    if (f.source == plane_source) {
      part.signs[j] = {0, 0, 0};
      return;
    }
    std::array<int, 3> sj{};
    if constexpr (batched) {
      if (part.sample_signs) {  // the sampled heuristic's signs (choose_splitter)
        for (int k = 0; k < 3; ++k) {
          sj[k] = part.sample.best_sign(j, k);
          if (sj[k] == detail::sample_batch<G>::unknown_code)
            sj[k] = geom_.sign(plane_source, part.plane_filter, f, k);
        }
      } else {
        const static_plane& sp = part.static_filter;
        for (int k = 0; k < 3; ++k)
          sj[k] = sp.valid ? static_sign(sp, geom_.centre(f.v[k]), geom_.radius(f.v[k])) : 0;
        if (sj[0] == 0 || sj[1] == 0 || sj[2] == 0) {
          if (part.classes.same(f.source, plane_source)) {  // in the plane (batch_classify.h)
            part.signs[j] = {0, 0, 0};
            return;
          }
          for (int k = 0; k < 3; ++k)
            if (sj[k] == 0) sj[k] = geom_.sign(plane_source, part.plane_filter, f, k);
        }
      }
    } else {
      sj = signs_against(plane_source, f);
    }
    part.signs[j] = {static_cast<std::int8_t>(sj[0]), static_cast<std::int8_t>(sj[1]),
                     static_cast<std::int8_t>(sj[2])};
  };
  // Tasks: with blocks, the blocks not certified whole (their box tested here, cheaply, so
  // that the threads start only when many fragments need testing); otherwise every fragment.
  std::vector<std::uint32_t>& tasks = part.tasks;
  tasks.clear();
  std::size_t tested = n;
  if constexpr (batched) {
    static_filter_of(part, ctx, plane_source);  // read by test_fragment
    const fast_plane_core& filter = part.plane_filter;
    part.block_signs.resize(w.blocks.size());
    tested = 0;
    for (std::size_t b = 0; b < w.blocks.size(); ++b) {
      const int s = detail::box_sign(filter, w.blocks[b].box);
      part.block_signs[b] = static_cast<std::int8_t>(s);
      if (s == 0) {
        tasks.push_back(static_cast<std::uint32_t>(b));
        tested += w.blocks[b].count;
      }
    }
  }
  const std::size_t nt = batched ? tasks.size() : n;
  const auto test_task = [&](std::size_t t) {
    if constexpr (batched) {
      const detail::list_block& b = w.blocks[tasks[t]];
      for (std::size_t j = b.begin; j < b.begin + b.count; ++j) test_fragment(j);
    } else {
      test_fragment(t);
    }
  };
  if (tested > 65536) {
    detail::parallel_failure failure;
    const auto count = static_cast<long long>(nt);
#pragma omp parallel for schedule(static) num_threads(detail::threads_for(options.threads))
    for (long long tt = 0; tt < count; ++tt)
      failure.run([&] { test_task(static_cast<std::size_t>(tt)); });
    failure.rethrow();
  } else {
    // No OpenMP region at all for the usual short list: libgomp sets up a team (an aligned
    // allocation and a futex wake-up) even when an `if` clause turns the region serial,
    // measured at 3% of pinion's build, one region per node.
    for (std::size_t t = 0; t < nt; ++t) test_task(t);
  }
  detail::block_list_builder negative, positive;
  const auto distribute = [&](std::size_t j) {
    const std::uint32_t ref = w.list[j];
    const std::array<int, 3> s{part.signs[j][0], part.signs[j][1], part.signs[j][2]};
    const auto box_of = [&](const fragment& f) {
      if constexpr (batched)
        return detail::fragment_box(geom_, f);
      else
        return detail::point_box{};
    };
    // The box of list position j, from the sample's arrays when they hold the whole list.
    const auto box_at = [&](std::size_t j) {
      if constexpr (batched)
        if (part.sample_signs) return part.sample.box(j);
      return box_of(fragment_at(w.list[j]));
    };
    switch (geom::classify_signs(s)) {
      case geom::classification::coplanar:
        part.node_fragments.push_back(ref);
        break;
      case geom::classification::positive:
        positive.add(ref, box_at(j));
        break;
      case geom::classification::negative:
        negative.add(ref, box_at(j));
        break;
      case geom::classification::straddling: {
        const geom::split_pattern pattern = geom::make_split_pattern(s);
        std::array<fragment, 3> pieces;
        geom_.split(plane_source, fragment_at(ref), pattern, pieces, part.scratch);
        ctx.splits.fetch_add(1, std::memory_order_relaxed);
        ctx.check_limit(static_cast<std::size_t>(pattern.pieces - 1));
        for (int k = 0; k < pattern.pieces; ++k) {
          (pattern.side[k] > 0 ? positive : negative)
              .add(local_ref | static_cast<std::uint32_t>(part.pieces.size()), box_of(pieces[k]));
          part.pieces.push_back(pieces[k]);
        }
        break;
      }
    }
  };
  if constexpr (batched) {
    for (std::size_t t = 0; t < w.blocks.size(); ++t) {
      const detail::list_block& b = w.blocks[t];
      if (part.block_signs[t] != 0) {
        (part.block_signs[t] > 0 ? positive : negative).add_block(&w.list[b.begin], b);
      } else {
        for (std::size_t j = b.begin; j < b.begin + b.count; ++j) distribute(j);
      }
    }
    positive.close();
    negative.close();
  } else {
    for (std::size_t j = 0; j < n; ++j) distribute(j);
  }
  nd.count = static_cast<std::uint32_t>(part.node_fragments.size() - nd.first);
  part.nodes.push_back(nd);
  const std::uint64_t key = w.key;
  const std::uint32_t depth = w.depth;
  w.list.clear();
  w.list.shrink_to_fit();
  w.blocks.clear();
  w.blocks.shrink_to_fit();
  if (!positive.list.empty())
    push_child({std::move(positive.list), id, +1, depth + 1, detail::mix64(key * 2 + 1),
                batched ? std::move(positive.blocks) : std::vector<detail::list_block>{}});
  if (!negative.list.empty())
    push_child({std::move(negative.list), id, -1, depth + 1, detail::mix64(key * 2),
                batched ? std::move(negative.blocks) : std::vector<detail::list_block>{}});

  const std::size_t placed = ctx.placed.fetch_add(nd.count, std::memory_order_relaxed) + nd.count;
  const std::size_t nodes = ctx.nodes.fetch_add(1, std::memory_order_relaxed) + 1;
  if (options.progress && (nodes & 255) == 0) ctx.report(placed, nodes);
}

template <class G>
const static_plane& basic_bsp_tree<G>::static_filter_of(subtree& part, const build_context& ctx,
                                                        std::uint32_t plane) const {
  if constexpr (detail::has_centres<G>::value) {  // the only geometries with filters
    if (part.static_filter_source != plane) {
      // 3 KB; without it, making the filters again cost 3-6% of small meshes' builds.
      constexpr std::size_t recent = 32;
      if (part.recent_filters.empty()) part.recent_filters.resize(recent);
      typename subtree::plane_filters& slot = part.recent_filters[plane % recent];
      if (slot.source != plane) {
        slot.core = geom_.filter(plane);
        slot.source = plane;
      }
      part.plane_filter = slot.core;
      part.static_filter = make_static_plane(slot.core, ctx.lo, ctx.hi);
      part.static_filter_source = plane;
    }
  }
  return part.static_filter;
}

template <class G>
std::size_t basic_bsp_tree<G>::choose_splitter(const std::vector<std::uint32_t>& list,
                                               subtree& part, const build_context& ctx,
                                               std::uint64_t node_key, std::uint32_t depth) const {
  const std::size_t n = list.size();
  part.sample_signs = false;
  if (n <= 1) return 0;
  // cls(i, j): list[j] against list[i]'s plane; the same source is coplanar by construction.
  const auto cls = [&](std::size_t i, std::size_t j) {
    const fragment& candidate = resolve(part, list[i]);
    const fragment& other = resolve(part, list[j]);
    return other.source == candidate.source ? geom::classification::coplanar
                                            : classify(candidate.source, other);
  };
  // A plane list[i] lies in (choose_sampled_counts' plane_key): its source triangle's. (The
  // exact kernel's branch below keys by coplanar class instead.)
  const auto source_key = [&](std::size_t i) -> std::uint64_t {
    return resolve(part, list[i]).source;
  };
  const build_options& o = ctx.options;
  switch (ctx.heuristic) {
    case detail::heuristic_naive:
      return 0;
    case detail::heuristic_min_split:
      return detail::choose_min_split(n, cls, o.threads);
    case detail::heuristic_sampled:
      if constexpr (detail::has_centres<G>::value) {
        // The sample gathered once, then swept by each candidate's static filter.
        const std::size_t m = detail::sample_size(n, o.sampled_samples);
        part.sample.gather(geom_, m, [&](std::size_t k) -> const fragment& {
          return resolve(part, list[detail::sample_position(k, n, m)]);
        });
        const auto count = [&](std::size_t i, std::size_t k0, std::size_t k1,
                               detail::side_counts& c) {
          const std::uint32_t plane = resolve(part, list[i]).source;
          const static_plane& sp = static_filter_of(part, ctx, plane);
          part.sample.count(geom_, plane, sp, part.plane_filter, k0, k1, c, part.classes,
                            ctx.sources);
        };
        const auto plane_key = [&](std::size_t i) -> std::uint64_t {
          return part.classes.root(resolve(part, list[i]).source);
        };
        const std::size_t best = detail::choose_sampled_counts(
            n, count, plane_key, o, node_key, 16, [&](std::size_t) { part.sample.keep_best(); });
        // A sample of the whole list (sample_position(k, n, n) = k): the winner's kept codes
        // are its exact signs by list position, for grow_node's partition.
        part.sample_signs = m == n;
        return best;
      } else {
        return detail::choose_sampled(n, cls, source_key, o, node_key);
      }
    case detail::heuristic_random:
      return detail::choose_random(n, o.seed, node_key);
    case detail::heuristic_custom: {
      const auto ids = [&](std::size_t i) {
        const fragment& f = resolve(part, list[i]);
        return std::make_pair(f.face, f.source);
      };
      return detail::choose_scored(n, cls, ids, o, node_key, depth);
    }
  }
  return 0;
}

template <class G>
std::size_t basic_bsp_tree<G>::node_of_fragment(std::size_t i) const {
  // Nodes are created in build order and append their fragments as they are created,
  // so node.first is non-decreasing with the node index.
  if (i >= fragments_.size()) throw usage_error("node_of_fragment: index out of range");
  const auto it = std::upper_bound(nodes_.begin(), nodes_.end(), i,
                                   [](std::size_t v, const node& nd) { return v < nd.first; });
  return static_cast<std::size_t>(std::prev(it) - nodes_.begin());
}

template <class G>
std::vector<std::uint32_t> basic_bsp_tree<G>::order_from_eye(const vec3d& eye,
                                                             bool back_to_front) const {
  return traverse([&](std::uint32_t plane) { return geom_.side_of_eye(plane, eye); },
                  back_to_front);
}

template <class G>
std::vector<std::uint32_t> basic_bsp_tree<G>::order_for_direction(const vec3d& d,
                                                                  bool back_to_front) const {
  return traverse([&](std::uint32_t plane) { return geom_.side_of_direction(plane, d); },
                  back_to_front);
}

/// The kernel-specific implementation behind exbsp::bsp.
template <class G>
class bsp_kernel_impl final : public bsp_impl {
 public:
  bsp_kernel_impl(const triangle_soup& soup, const build_options& options)
      : input_{{},
               0,
               options.sampled_candidates,
               options.sampled_samples,
               options.sampled_split_weight,
               soup},
        tree_(soup, options) {
    init_planes(soup);
  }
  /// A saved tree (tree_file.h).
  bsp_kernel_impl(tree_file::reader& in, tree_file::common_part&& common)
      : input_(std::move(common)), tree_(input_, in) {
    init_planes(input_.soup);
  }
  const build_stats& stats() const override { return tree_.stats(); }
  kernel_id kernel() const override { return G::id; }
  std::size_t fragment_count() const override { return tree_.fragments().size(); }
  fragment_d fragment(std::size_t i) const override {
    if (i >= tree_.fragments().size()) throw usage_error("fragment: index out of range");
    tree_.geometry().prepare_output(tree_.fragments());
    return tree_.geometry().to_double(tree_.fragments()[i]);
  }
  void visit_exact(std::size_t i, const exact_visitor& visit) const override {
    if (i >= tree_.fragments().size()) throw usage_error("fragment_exact: index out of range");
    tree_.geometry().visit_exact(tree_.fragments()[i], visit);
  }
  std::vector<std::uint32_t> order_from_eye(const vec3d& e, bool back_to_front) const override {
    return tree_.order_from_eye(e, back_to_front);
  }
  std::vector<std::uint32_t> order_for_direction(const vec3d& d,
                                                 bool back_to_front) const override {
    return tree_.order_for_direction(d, back_to_front);
  }
  std::vector<bsp::ancestor> ancestors(std::size_t i) const override {
    std::vector<bsp::ancestor> out;
    const auto& nodes = tree_.nodes();
    std::int32_t at = static_cast<std::int32_t>(tree_.node_of_fragment(i));
    while (nodes[at].parent >= 0) {
      out.push_back({nodes[nodes[at].parent].plane_source, nodes[at].side_in_parent});
      at = nodes[at].parent;
    }
    std::reverse(out.begin(), out.end());
    return out;
  }
  void write_tree(tree_file::writer& out) const override {
    tree_file::write_common(out, tree_.stats(), input_);
    tree_.write_tree(out);
  }

  std::size_t node_count() const override { return tree_.nodes().size(); }
  const triangle_soup& input() const override { return input_.soup; }
  bsp_node node(std::size_t k) const override {
    if (k >= tree_.nodes().size()) throw usage_error("node: index out of range");
    const auto& nd = tree_.nodes()[k];
    return {static_cast<std::uint32_t>(k),
            nd.plane_source,
            planes_[k],
            nd.first,
            nd.count,
            nd.negative,
            nd.positive,
            nd.parent,
            nd.side_in_parent};
  }
  void traverse(const vec3d& at, bool direction, bsp_visitor& visitor,
                bool back_to_front) const override {
    const auto& geom = tree_.geometry();
    const auto side_of = [&](std::uint32_t plane) {
      return direction ? geom.side_of_direction(plane, at) : geom.side_of_eye(plane, at);
    };
    tree_.walk(
        side_of, back_to_front,
        [&](std::int32_t k, int s) { visitor.enter(node(static_cast<std::size_t>(k)), s); },
        [&](std::int32_t k) { visitor.fragments(node(static_cast<std::size_t>(k))); },
        [&](std::int32_t k, int side) { visitor.cell(node(static_cast<std::size_t>(k)), side); });
  }

 private:
  void init_planes(const triangle_soup& soup) {
    planes_.reserve(tree_.nodes().size());
    for (const auto& nd : tree_.nodes()) {
      const soup_triangle& t = soup.triangles[nd.plane_source];
      planes_.push_back({soup.vertices[t.v[0]], soup.vertices[t.v[1]], soup.vertices[t.v[2]]});
    }
  }

  tree_file::common_part input_;  ///< the soup and options, for saving (its stats are unused)
  basic_bsp_tree<G> tree_;
  std::vector<std::array<vec3d, 3>> planes_;  ///< per node: its plane's three input points
};

}  // namespace exbsp

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
