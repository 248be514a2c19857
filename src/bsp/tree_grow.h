// SPDX-License-Identifier: LGPL-3.0-or-later
// basic_bsp_tree<G>::grow_node: one node of the build: its splitter (tree_choose.h), the
// partition of its list by exact signs, the splits (the section 3 pattern) and its children.
// Part of bsp_tree_impl.h; notation: bsp_tree.h.
#pragma once
#include "bsp/tree_build.h"  // its includes, build_context and classify

namespace exbsp {

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
  // Split points are shared within the node only (G::split shares SEG(p, q, plane) between
  // the node's fragments until the scratch's plane changes): a node that follows one with the
  // same plane starts afresh, so which points are shared depends on the tree, not on the order
  // nodes are grown in (an insert, tree_insert.h, grows them in another order).
  part.scratch.plane = ~std::uint32_t{0};
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

}  // namespace exbsp
