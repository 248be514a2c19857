// SPDX-License-Identifier: LGPL-3.0-or-later
// The sampled heuristic's shortcuts (src/bsp/heuristics.h, bsp_tree_impl.h, batch_classify.h):
// candidates in the plane of an earlier candidate are skipped, the exact kernel remembers
// exact signs in a bounded table, and the winner's signs may serve the partition. None may
// change the tree. The reference is the same rule without any shortcut: the "custom"
// heuristic over the sampled candidates with score W * straddling + |positive - negative|
// (choose_scored: every candidate counted on the whole sample with plain exact
// classifications), and gmpq's sampled tree.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "bsp/heuristics.h"  // built with OpenMP (tests/CMakeLists.txt)
#include "support/generators.h"
#include "support/observable.h"

namespace {

using exbsp::build_options;
using exbsp::triangle_soup;
using exbsp::vec3d;
using exbsp_test::soup_case;

/// The sampled heuristic's rule without its shortcuts (see the top of this file).
build_options reference_of(build_options o) {
  o.heuristic = "custom";
  o.score_candidates = exbsp::candidate_set::sampled;
  const long long w = o.sampled_split_weight;
  o.score = [w](const exbsp::candidate_score_input& in) {
    const long long d = static_cast<long long>(in.positive) - static_cast<long long>(in.negative);
    return static_cast<double>(w * static_cast<long long>(in.straddling) + std::llabs(d));
  };
  return o;
}

const std::vector<vec3d>& eyes() {
  static const std::vector<vec3d> e{{-3, 40, 25}, {0.3, 0.2, -7}, {7.5, 7.5, 7.5}};
  return e;
}

/// The exact sampled tree equals the shortcut-free reference (exact kernel) and gmpq's
/// sampled tree (unless with_gmpq is false), observably (tree statistics, node planes, order from
/// several eyes); returns whether both hold.
bool expect_same_as_reference(const triangle_soup& soup, build_options o, const std::string& what,
                              bool with_gmpq = true) {
  o.heuristic = "sampled";
  o.kernel = exbsp::kernel_id::exact;
  // The observable's first line names the heuristic: dropped.
  const auto seen = [&](const build_options& b) {
    const std::string s = exbsp_test::observable(exbsp::bsp::build(soup, b), eyes());
    return s.substr(s.find('\n'));
  };
  const std::string fast = seen(o), plain = seen(reference_of(o));
  build_options g = o;
  g.kernel = exbsp::kernel_id::gmpq;
  const std::string gmpq = with_gmpq ? seen(g) : fast;
  EXPECT_TRUE(fast == plain) << what << ": exact sampled vs custom reference";
  EXPECT_TRUE(fast == gmpq) << what << ": exact vs gmpq";
  return fast == plain && fast == gmpq;
}

/// A fan of n triangles around the origin in the plane z, every other one reversed (the
/// same plane, either orientation: one coplanar class), shared vertices on the rim.
void add_fan(triangle_soup& s, int n, double z) {
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < n; ++k) {
    const double a0 = 2 * pi * k / n, a1 = 2 * pi * (k + 1) / n;
    const vec3d o{0, 0, z}, p{std::cos(a0), std::sin(a0), z}, q{std::cos(a1), std::sin(a1), z};
    if (k % 2)
      s.add_triangle(o, q, p);
    else
      s.add_triangle(o, p, q);
  }
}

/// Fans of coplanar triangles (several per plane, in both orientations) crossed by upright
/// triangles, which split them: nodes then hold many candidates in one plane, and split
/// siblings of one source.
triangle_soup crossed_fans(int per_fan, int fans, int uprights) {
  triangle_soup s;
  for (int f = 0; f < fans; ++f) add_fan(s, per_fan, 0.25 * f);
  for (int u = 0; u < uprights; ++u) {
    const double x = -0.9 + 1.8 * (u + 0.5) / uprights;
    s.add_triangle({x, -1.5, -0.5}, {x + 0.1, 1.5, -0.5}, {x, 0.1, 0.25 * fans + 0.5});
  }
  return s;
}

TEST(SampledShortcuts, fans_of_coplanar_candidates_give_the_reference_tree) {
  for (const auto& [per_fan, fans, uprights] :
       std::vector<std::array<int, 3>>{{12, 1, 3}, {24, 3, 5}, {40, 4, 9}, {64, 2, 17}}) {
    const triangle_soup soup = crossed_fans(per_fan, fans, uprights);
    for (const unsigned candidates : {1u, 4u, 16u, 64u})
      for (const unsigned samples : {3u, 16u, 512u})
        for (const std::uint64_t seed : {0u, 7u}) {
          build_options o;
          o.sampled_candidates = candidates;
          o.sampled_samples = samples;
          o.seed = seed;
          expect_same_as_reference(soup, o,
                                   std::to_string(per_fan) + "x" + std::to_string(fans) + "+" +
                                       std::to_string(uprights) + " c" +
                                       std::to_string(candidates) + " s" + std::to_string(samples) +
                                       " seed " + std::to_string(seed));
        }
  }
}

RC_GTEST_PROP(SampledShortcuts, every_generator_gives_the_reference_tree, ()) {
  const soup_case c = *rc::gen::oneOf(exbsp_test::any_small_soup(), exbsp_test::coplanar_stack(),
                                      exbsp_test::vertex_on_plane(), exbsp_test::near_coplanar(),
                                      exbsp_test::slivers(), exbsp_test::mesh_like());
  build_options o;
  o.seed = *rc::gen::arbitrary<std::uint64_t>();
  o.sampled_candidates = static_cast<unsigned>(*rc::gen::inRange(1, 20));
  o.sampled_samples = static_cast<unsigned>(*rc::gen::inRange(1, 40));
  RC_ASSERT(expect_same_as_reference(c.soup(), o, c.kind));
}

TEST(SampledShortcuts, cad_subsets_give_the_reference_tree) {
  const auto files = exbsp_test::present_cad_meshes();
  if (files.empty()) GTEST_SKIP() << "CGAL corpus missing";
  rc::check("cad subsets", [&] {
    // Large enough for lists longer than a sample; gmpq is too slow here (exact = gmpq is
    // test_exact_kernel's).
    const soup_case c = *exbsp_test::cad_subset(files, 300);
    build_options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    o.sampled_samples = static_cast<unsigned>(*rc::gen::element(64, 512));
    RC_ASSERT(expect_same_as_reference(c.soup(), o, c.kind, false));
  });
}

// choose_sampled_counts alone: candidates in groups of one plane (each member possibly
// reversed, which swaps its positive and negative counts). Skipping the later members of a
// group must give the choice made when every candidate is counted.
RC_GTEST_PROP(SampledShortcuts, skipping_repeated_planes_keeps_the_choice, ()) {
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(2, 40));
  const int groups = *rc::gen::inRange(1, 6);
  std::vector<int> group(n), reversed(n);
  for (std::size_t i = 0; i < n; ++i) {
    group[i] = *rc::gen::inRange(0, groups);
    reversed[i] = *rc::gen::inRange(0, 2);
  }
  // Per group and sample entry: 0 coplanar, 1 positive, 2 negative, 3 straddling.
  std::vector<std::vector<int>> cls(static_cast<std::size_t>(groups));
  for (auto& g : cls) g = *rc::gen::container<std::vector<int>>(n, rc::gen::inRange(0, 4));
  build_options o;
  o.seed = *rc::gen::arbitrary<std::uint64_t>();
  o.sampled_candidates = static_cast<unsigned>(*rc::gen::inRange(1, 24));
  o.sampled_samples = static_cast<unsigned>(*rc::gen::inRange(1, 48));
  const auto count = [&](std::size_t i, std::size_t k0, std::size_t k1,
                         exbsp::detail::side_counts& c) {
    for (std::size_t k = k0; k < k1; ++k) {
      int x = cls[static_cast<std::size_t>(group[i])][k];
      if (reversed[i] && (x == 1 || x == 2)) x = 3 - x;
      c.positive += x == 1;
      c.negative += x == 2;
      c.splits += x == 3;
    }
  };
  const auto group_key = [&](std::size_t i) { return std::uint64_t(group[i]); };
  const auto own_key = [](std::size_t i) { return std::uint64_t(i); };  // no two alike
  const std::uint64_t key = *rc::gen::arbitrary<std::uint64_t>();
  const auto ignore = [](std::size_t) {};
  for (const std::size_t chunk : {1u, 16u}) {
    std::size_t last_best = n;
    const std::size_t chosen = exbsp::detail::choose_sampled_counts(
        n, count, group_key, o, key, chunk, [&](std::size_t i) { last_best = i; });
    RC_ASSERT(chosen == last_best);  // on_best reports the winner last
    RC_ASSERT(chosen ==
              exbsp::detail::choose_sampled_counts(n, count, own_key, o, key, chunk, ignore));
  }
}

}  // namespace
