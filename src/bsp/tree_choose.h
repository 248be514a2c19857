// SPDX-License-Identifier: LGPL-3.0-or-later
// basic_bsp_tree<G>::choose_splitter: the heuristic dispatch (heuristic_table.h: the four
// built-in choosers, or a score through the custom machinery) and the cache of static
// filters the sampled heuristic sweeps candidates with. Part of bsp_tree_impl.h; notation:
// bsp_tree.h; the choosers themselves: heuristics.h.
#pragma once
#include "bsp/tree_build.h"  // its includes, build_context and classify

namespace exbsp {

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

}  // namespace exbsp
