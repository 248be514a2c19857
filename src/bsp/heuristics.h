// SPDX-License-Identifier: LGPL-3.0-or-later
// Splitter heuristics of the BSP build (docs/contract.md "The BSP"): which fragment of a node's
// list gives the node its plane. Private to src/bsp; the tree (bsp_tree_impl.h) calls
// choose_splitter.
//
// Notation: a node's list holds n >= 2 fragments at positions 0..n-1 (list order). cls(i, j) is
// the exact classification of the fragment at position j against the plane of the fragment at
// position i (a fragment of the same input triangle as i is coplanar by construction). A
// heuristic returns a position. Every heuristic is deterministic: its result depends only on
// the list, the options, the seed and the node's path key, never on the number of threads.
//   naive      position 0;
//   min-split  the fewest straddlers over the whole list, ties to the earliest;
//   sampled    seeded candidates scored on an evenly spaced sample, W * splits + |pos - neg|;
//   random     one seeded position;
//   custom     build_options::score over build_options::score_candidates, lowest score wins,
//              ties to the earliest candidate.
#pragma once
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include "bsp/batch_classify.h"
#include "bsp/parallel.h"
#include "geom/split_pattern.h"

namespace exbsp {
namespace detail {

/// splitmix64: a fixed, portable mixing function (the same stream on every machine,
/// unlike std::uniform_int_distribution).
inline std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The tree's choosers (heuristic_table.h: each heuristic's row names one).
enum heuristic_id : int {
  heuristic_naive,
  heuristic_min_split,
  heuristic_sampled,
  heuristic_random,
  heuristic_custom
};

// min-split: the position whose plane straddles the fewest others, ties to the earliest.
// Candidates are ranked by the key (count, index). The best complete key so far bounds the
// rest: candidate j stops as soon as (count so far, j) can no longer beat it, so once a plane
// with 0 straddlers is found at i, every later candidate is skipped at once. A fragment found
// coplanar with an earlier candidate has the same count and loses the tie: it is skipped.
// Candidates run in parallel; the result does not depend on scheduling.
template <class Classify>
std::size_t choose_min_split(std::size_t n, const Classify& cls, unsigned threads) {
  std::vector<std::atomic<unsigned char>> same_plane(n);
  for (auto& f : same_plane) f.store(0, std::memory_order_relaxed);
  const auto key = [](std::uint64_t count, std::uint64_t index) { return count << 32 | index; };
  std::atomic<std::uint64_t> best{std::numeric_limits<std::uint64_t>::max()};
  const long long nn = static_cast<long long>(n);
  parallel_failure failure;
#pragma omp parallel for schedule(dynamic, 8) if (n > 64) num_threads(threads_for(threads))
  for (long long ii = 0; ii < nn; ++ii) {
    failure.run([&] {
      poll();  // cancellation (parallel.h)
      const auto i = static_cast<std::uint64_t>(ii);
      if (same_plane[i].load(std::memory_order_relaxed)) return;
      if (key(0, i) >= best.load(std::memory_order_relaxed)) return;
      std::uint64_t c = 0;
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const geom::classification k = cls(i, j);
        if (k == geom::classification::straddling) {
          if (key(++c, i) >= best.load(std::memory_order_relaxed)) return;  // cannot win
        } else if (k == geom::classification::coplanar && j > i) {
          same_plane[j].store(1, std::memory_order_relaxed);
        }
      }
      std::uint64_t b = best.load(std::memory_order_relaxed);
      const std::uint64_t mine = key(c, i);
      while (mine < b && !best.compare_exchange_weak(b, mine, std::memory_order_relaxed)) {
      }
    });
  }
  failure.rethrow();
  return static_cast<std::size_t>(best.load() & 0xffffffffu);
}

/// The sampled heuristic's candidate positions: all n when n <= max_candidates, otherwise
/// max_candidates seeded draws, sorted, duplicates removed.
inline std::vector<std::size_t> sampled_candidate_positions(std::size_t n,
                                                            std::size_t max_candidates,
                                                            std::uint64_t seed,
                                                            std::uint64_t node_key) {
  std::vector<std::size_t> candidates;
  if (n <= max_candidates) {
    for (std::size_t i = 0; i < n; ++i) candidates.push_back(i);
    return candidates;
  }
  const std::uint64_t h = mix64(seed ^ mix64(node_key + 0x51ed));
  for (std::size_t k = 0; k < max_candidates; ++k) candidates.push_back(mix64(h + k) % n);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  return candidates;
}

/// The sample a candidate is scored on: positions k * n / m, k = 0..m-1, m = min(n, samples).
inline std::size_t sample_size(std::size_t n, unsigned samples) {
  return std::min<std::size_t>(n, std::max(1u, samples));
}
inline std::size_t sample_position(std::size_t k, std::size_t n, std::size_t m) {
  return k * n / m;
}

// sampled: up to C candidates drawn with the seed, each scored on an evenly spaced sample
// of at most S fragments by W * splits + |positive - negative| (the split/balance score of
// classic BSP compilers); lowest score wins, ties to the earliest candidate. C, S, W are
// build_options::sampled_candidates, sampled_samples, sampled_split_weight (16, 512, 8).
// A candidate stops early once its splits alone cannot beat the best score.
//
// count(i, k0, k1, counts) adds the classifications of sample entries [k0, k1) (entry k is
// list position sample_position(k, n, m)) against candidate i's plane. Entries are counted in
// chunks of `chunk`, the early stop checked between chunks: a candidate that stops has
// W * splits >= the best score, so it could not have won with more entries counted, and the
// choice does not depend on the chunk size.
//
// plane_key(i) names a plane candidate i is known to lie in: equal keys mean one plane (the
// same source triangle, or sources known coplanar; different keys say nothing). A candidate
// with the key of an earlier one is skipped. (Keys rather than a pairwise test: the pairwise
// test cost 16 x 15 / 2 fragment lookups at every node of up to 16 fragments.) Why that cannot
// change the choice: both are scored on the same sample against the same plane, possibly reversed;
// reversing swaps positive and negative and keeps straddlers and coplanar fragments, so splits and
// |positive - negative|, hence the score, are equal. The earlier candidate was scored first, so the
// best score is already at most that score, and the later one, which needs a strictly lower score
// to win, cannot.
//
// on_best(i) is called when candidate i becomes the best so far, right after its last count:
// the winner was counted over the whole sample (a candidate that stopped early has a score of
// at least the best one, so never becomes the best).
template <class Count, class PlaneKey, class OnBest>
std::size_t choose_sampled_counts(std::size_t n, const Count& count, const PlaneKey& plane_key,
                                  const build_options& o, std::uint64_t node_key, std::size_t chunk,
                                  const OnBest& on_best) {
  const std::vector<std::size_t> candidates =
      sampled_candidate_positions(n, std::max(1u, o.sampled_candidates), o.seed, node_key);
  const std::size_t m = sample_size(n, o.sampled_samples);
  const long long weight = o.sampled_split_weight;
  std::size_t best = candidates.front();
  long long best_score = std::numeric_limits<long long>::max();
  std::vector<std::uint64_t> keys;  // of the candidates counted so far
  keys.reserve(candidates.size());
  for (const std::size_t i : candidates) {
    const std::uint64_t key = plane_key(i);
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    keys.push_back(key);
    side_counts c;
    for (std::size_t k = 0; k < m && weight * c.splits < best_score; k += chunk)
      count(i, k, std::min(m, k + chunk), c);
    const long long score = weight * c.splits + std::llabs(c.positive - c.negative);
    if (score < best_score) {
      best_score = score;
      best = i;
      on_best(i);
    }
  }
  return best;
}

/// choose_sampled_counts with cls(i, j) for each entry.
template <class Classify, class PlaneKey>
std::size_t choose_sampled(std::size_t n, const Classify& cls, const PlaneKey& plane_key,
                           const build_options& o, std::uint64_t node_key) {
  const std::size_t m = sample_size(n, o.sampled_samples);
  const auto count = [&](std::size_t i, std::size_t k0, std::size_t k1, side_counts& c) {
    for (std::size_t k = k0; k < k1; ++k) c.add(cls(i, sample_position(k, n, m)));
  };
  return choose_sampled_counts(n, count, plane_key, o, node_key, 1, [](std::size_t) {});
}

/// random: one position drawn with the seed and the node's path key.
inline std::size_t choose_random(std::size_t n, std::uint64_t seed, std::uint64_t node_key) {
  return mix64(seed ^ mix64(node_key)) % n;
}

/// Counts of one candidate's plane over positions position(k), k = 0..m-1 (the candidate
/// itself skipped).
template <class Classify, class Position>
void count_sides(std::size_t i, const Classify& cls, std::size_t m, const Position& position,
                 candidate_score_input& in) {
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t j = position(k);
    if (j == i) continue;
    const geom::classification c = cls(i, j);  // counted as side_counts::add counts
    in.straddling += c == geom::classification::straddling;
    in.positive += c == geom::classification::positive;
    in.negative += c == geom::classification::negative;
    in.coplanar += c == geom::classification::coplanar;
  }
}

/// Calls options.score; throws usage_error for a NaN score (it would make the choice
/// depend on the order of comparisons).
inline double checked_score(const build_options& o, const candidate_score_input& in) {
  const double s = o.score(in);
  if (std::isnan(s))
    throw usage_error("score callback returned NaN for candidate " + std::to_string(in.candidate) +
                      " (face " + std::to_string(in.face) + ")");
  return s;
}

// custom: options.score for each candidate, lowest score wins, ties to the earliest. With
// candidate_set::all every position is a candidate, counted against the whole list (in
// parallel over candidates, like min-split, but without its bound: a score is opaque); with
// candidate_set::sampled the sampled heuristic's candidates are counted on its sample.
// `ids(i)` gives the fragment at position i as {face, source}.
template <class Classify, class Ids>
std::size_t choose_scored(std::size_t n, const Classify& cls, const Ids& ids,
                          const build_options& o, std::uint64_t node_key, std::uint32_t depth) {
  const auto input_for = [&](std::size_t i) {
    candidate_score_input in;
    in.candidate = i;
    const auto id = ids(i);
    in.face = id.first;
    in.source = id.second;
    in.list_size = n;
    in.depth = depth;
    return in;
  };
  std::vector<std::size_t> candidates;
  std::vector<double> scores;
  if (o.score_candidates == candidate_set::sampled) {
    candidates =
        sampled_candidate_positions(n, std::max(1u, o.sampled_candidates), o.seed, node_key);
    const std::size_t m = sample_size(n, o.sampled_samples);
    for (std::size_t i : candidates) {
      poll();  // cancellation (parallel.h)
      candidate_score_input in = input_for(i);
      count_sides(
          i, cls, m, [&](std::size_t k) { return sample_position(k, n, m); }, in);
      scores.push_back(checked_score(o, in));
    }
  } else {
    candidates.resize(n);
    scores.resize(n);
    const long long nn = static_cast<long long>(n);
    parallel_failure failure;
#pragma omp parallel for schedule(dynamic, 8) if (n > 64) num_threads(threads_for(o.threads))
    for (long long ii = 0; ii < nn; ++ii) {
      failure.run([&] {
        poll();  // cancellation (parallel.h)
        const auto i = static_cast<std::size_t>(ii);
        candidate_score_input in = input_for(i);
        count_sides(
            i, cls, n, [](std::size_t k) { return k; }, in);
        candidates[i] = i;
        scores[i] = checked_score(o, in);
      });
    }
    failure.rethrow();
  }
  std::size_t best = 0;  // index into candidates: the first lowest score
  for (std::size_t k = 1; k < candidates.size(); ++k)
    if (scores[k] < scores[best]) best = k;
  return candidates[best];
}

}  // namespace detail
}  // namespace exbsp
