// SPDX-License-Identifier: LGPL-3.0-or-later
// The pluggable heuristic (heuristic "custom", build_options::score): a callback that
// reproduces min-split or sampled gives exactly their tree; the same tree for every exact
// kernel and every thread count; what the callback sees; errors and exceptions propagate.
// Notation: "observable" (support/observable.h) is everything a user can see of a tree as one
// string; its first line ends with the heuristic's name, which same_tree ignores.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include "support/generators.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp_test;
using exbsp::vec3d;

/// A soup of the given triangles, one face each.
exbsp::triangle_soup soup_of(const std::vector<std::array<vec3d, 3>>& tris) {
  exbsp::triangle_soup s;
  for (const auto& t : tris) s.add_triangle(t[0], t[1], t[2]);
  return s;
}

/// Three sticks overlapping cyclically (no depth order without a split) and a far triangle.
exbsp::triangle_soup cyclic_soup() {
  return soup_of({{{{0, 0, 0}, {4, 0, 1}, {4, 1, 1}}},
                  {{{4, 0, 0}, {2, 4, 1}, {1, 4, 1}}},
                  {{{2, 4, 0}, {0, 0, 1}, {0, 1, 1}}},
                  {{{-3, -3, 5}, {3, -3, 5}, {0, 3, 5}}}});
}

/// observable() without the heuristic's name at the end of its first line.
std::string tree_text(const exbsp::triangle_soup& soup, const exbsp::build_options& o) {
  std::string s = observable(exbsp::bsp::build(soup, o), eyes_for(soup));
  const std::size_t eol = s.find('\n');
  return s.erase(s.rfind(' ', eol), eol - s.rfind(' ', eol));
}

exbsp::build_options custom(std::function<double(const exbsp::candidate_score_input&)> score,
                            exbsp::candidate_set set = exbsp::candidate_set::all) {
  exbsp::build_options o;
  o.heuristic = "custom";
  o.score = std::move(score);
  o.score_candidates = set;
  return o;
}

double min_split_score(const exbsp::candidate_score_input& in) {
  return static_cast<double>(in.straddling);
}

/// The sampled heuristic's score with its default weight (8).
double sampled_score(const exbsp::candidate_score_input& in) {
  return 8.0 * static_cast<double>(in.straddling) +
         std::fabs(static_cast<double>(in.positive) - static_cast<double>(in.negative));
}

/// A score of its own (splits, balance and a bonus for planes carrying many fragments).
double mixed_score(const exbsp::candidate_score_input& in) {
  return 3.0 * static_cast<double>(in.straddling) +
         std::fabs(static_cast<double>(in.positive) - static_cast<double>(in.negative)) -
         0.5 * static_cast<double>(in.coplanar) + 1e-3 * in.depth;
}

// --- degenerate input and misuse first ---------------------------------------------------------

TEST(CustomHeuristic, empty_single_and_all_degenerate_input_never_call_the_score) {
  std::atomic<int> calls{0};
  const auto o = custom([&](const exbsp::candidate_score_input&) { return ++calls, 0.0; });
  exbsp::triangle_soup flat =
      soup_of({{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}, {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}});
  for (const auto& soup :
       {exbsp::triangle_soup{}, soup_of({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}), flat}) {
    const auto t = exbsp::bsp::build(soup, o);
    EXPECT_EQ(t.stats().heuristic, "custom");
  }
  EXPECT_EQ(exbsp::bsp::build(flat, o).stats().degenerate_input, 2u);
  EXPECT_EQ(calls.load(), 0);
}

TEST(CustomHeuristic, custom_without_score_and_score_without_custom_are_usage_errors) {
  exbsp::build_options o;
  o.heuristic = "custom";
  EXPECT_THROW(exbsp::bsp::build(cyclic_soup(), o), exbsp::usage_error);
  o = custom(min_split_score);
  o.heuristic = "min-split";
  EXPECT_THROW(exbsp::bsp::build(cyclic_soup(), o), exbsp::usage_error);
  // "custom" is accepted by build, not listed with the built-in heuristics.
  const auto& names = exbsp::heuristic_names();
  EXPECT_EQ(std::find(names.begin(), names.end(), "custom"), names.end());
}

TEST(CustomHeuristic, nan_score_is_a_usage_error) {
  EXPECT_THROW(exbsp::bsp::build(cyclic_soup(), custom([](const auto&) { return std::nan(""); })),
               exbsp::usage_error);
}

TEST(CustomHeuristic, exception_from_the_score_propagates_out_of_build) {
  struct score_failed : std::runtime_error {
    using std::runtime_error::runtime_error;
  };
  // At the root (the sequential top of the build) and deep down (inside the parallel
  // subtrees), with one and several threads.
  exbsp::triangle_soup deep;  // 12 crossing triangles: the build reaches depth 12
  for (int k = 0; k < 12; ++k) {
    const double a = k * 0.157;
    deep.add_triangle({std::cos(a) * 5, std::sin(a) * 5, -1},
                      {-std::cos(a) * 5, -std::sin(a) * 5, -1}, {0.1 * k, 0.05 * k, 3});
  }
  for (std::uint32_t at_depth : {1u, 6u})
    for (unsigned threads : {1u, 2u, 4u}) {
      auto o = custom([&](const exbsp::candidate_score_input& in) -> double {
        if (in.depth >= at_depth)
          throw score_failed("no score at depth " + std::to_string(in.depth));
        return min_split_score(in);
      });
      o.threads = threads;
      EXPECT_THROW(exbsp::bsp::build(deep, o), score_failed)
          << "depth " << at_depth << ", threads " << threads;
    }
  // The build does reach that depth without the exception.
  EXPECT_GE(exbsp::bsp::build(deep, custom(min_split_score)).stats().depth, 7u);
}

// --- what the callback sees ----------------------------------------------------------------------

TEST(CustomHeuristic, counts_cover_the_list_and_name_the_candidate) {
  const auto soup = cyclic_soup();
  std::mutex m;
  std::vector<exbsp::candidate_score_input> root;
  const auto o = custom([&](const exbsp::candidate_score_input& in) {
    EXPECT_EQ(in.positive + in.negative + in.straddling + in.coplanar, in.list_size - 1);
    EXPECT_GE(in.list_size, 2u);
    EXPECT_LT(in.candidate, in.list_size);
    std::lock_guard<std::mutex> lock(m);
    if (in.depth == 1) root.push_back(in);
    return min_split_score(in);
  });
  exbsp::bsp::build(soup, o);
  ASSERT_EQ(root.size(), 4u);  // every fragment of the root list, once
  std::sort(root.begin(), root.end(),
            [](const auto& a, const auto& b) { return a.candidate < b.candidate; });
  for (std::uint32_t i = 0; i < 4; ++i) {
    EXPECT_EQ(root[i].candidate, i);
    EXPECT_EQ(root[i].face, i);
    EXPECT_EQ(root[i].source, i);
  }
  // The far triangle's plane (z = 5) has every stick below it, and cuts none.
  EXPECT_EQ(root[3].straddling, 0u);
  EXPECT_EQ(root[3].negative, 3u);
  // Each stick's plane cuts another stick: the cycle.
  EXPECT_GE(root[0].straddling + root[1].straddling + root[2].straddling, 1u);
}

TEST(CustomHeuristic, sampled_candidates_are_counted_on_the_sample) {
  // 40 triangles, 4 candidates, a sample of 10: counts cover at most 10 fragments.
  exbsp::triangle_soup soup;
  for (int k = 0; k < 40; ++k) soup.add_triangle({0, 0, 1.0 * k}, {1, 0, 1.0 * k}, {0, 1, 1.0 * k});
  std::atomic<int> root_calls{0};
  auto o = custom(
      [&](const exbsp::candidate_score_input& in) {
        const std::size_t counted = in.positive + in.negative + in.straddling + in.coplanar;
        const std::size_t sample = std::min<std::size_t>(in.list_size, 10);
        EXPECT_LE(counted, sample);
        EXPECT_GE(counted, sample - 1);  // the candidate itself is not counted when in the sample
        if (in.depth == 1) ++root_calls;
        return sampled_score(in);
      },
      exbsp::candidate_set::sampled);
  o.sampled_candidates = 4;
  o.sampled_samples = 10;
  exbsp::bsp::build(soup, o);
  EXPECT_GE(root_calls.load(), 1);
  EXPECT_LE(root_calls.load(), 4);
}

// --- reproducing the built-in heuristics ---------------------------------------------------------

TEST(CustomHeuristic, straddling_count_over_all_candidates_is_min_split_exactly) {
  exbsp::build_options ms;
  ms.heuristic = "min-split";
  std::size_t checked = 0;
  for (const char* name :
       {"cube.off", "tetrahedron.off", "cross.off", "pyramid.off", "joint.off"}) {
    const soup_case* mesh = cad_mesh(name);
    if (!mesh) continue;
    const auto soup = mesh->soup();
    EXPECT_EQ(tree_text(soup, custom(min_split_score)), tree_text(soup, ms)) << name;
    ++checked;
  }
  EXPECT_EQ(tree_text(cyclic_soup(), custom(min_split_score)), tree_text(cyclic_soup(), ms));
  if (checked == 0) GTEST_SKIP() << "CGAL corpus missing (run scripts/setup)";
}

RC_GTEST_PROP(CustomHeuristic, reproduces_min_split_and_sampled_on_every_generator, ()) {
  const soup_case c =
      *rc::gen::oneOf(any_small_soup(), coplanar_stack(), vertex_on_plane(), cyclic_sticks());
  const exbsp::triangle_soup soup = c.soup();
  exbsp::build_options ms, sa;
  ms.heuristic = "min-split";
  sa.heuristic = "sampled";
  sa.seed = *rc::gen::arbitrary<std::uint64_t>();
  sa.sampled_candidates = *rc::gen::inRange(1u, 6u);  // fewer candidates than fragments, often
  sa.sampled_samples = *rc::gen::inRange(1u, 8u);
  auto cs = custom(sampled_score, exbsp::candidate_set::sampled);
  cs.seed = sa.seed;
  cs.sampled_candidates = sa.sampled_candidates;
  cs.sampled_samples = sa.sampled_samples;
  RC_ASSERT(tree_text(soup, custom(min_split_score)) == tree_text(soup, ms));
  RC_ASSERT(tree_text(soup, cs) == tree_text(soup, sa));
}

// --- determinism ---------------------------------------------------------------------------------

TEST(CustomHeuristic, same_tree_for_every_exact_kernel_and_thread_count) {
  std::vector<exbsp::triangle_soup> soups{cyclic_soup()};
  for (const char* name : {"cube.off", "cross.off", "joint.off"})
    if (const soup_case* mesh = cad_mesh(name)) soups.push_back(mesh->soup());
  for (const auto set : {exbsp::candidate_set::all, exbsp::candidate_set::sampled})
    for (const auto& soup : soups) {
      auto o = custom(mixed_score, set);
      o.threads = 1;
      const std::string reference = tree_text(soup, o);
      for (const auto kernel :
           {exbsp::kernel_id::exact, exbsp::kernel_id::epeck, exbsp::kernel_id::gmpq})
        for (unsigned threads : {1u, 2u, 5u}) {
          if (kernel == exbsp::kernel_id::gmpq && soup.triangles.size() > 100) continue;  // minutes
          o.kernel = kernel;
          o.threads = threads;
          EXPECT_EQ(tree_text(soup, o), reference)
              << soup.source << ": " << exbsp::to_string(kernel) << ", " << threads << " threads";
        }
    }
}

TEST(CustomHeuristic, ties_go_to_the_earliest_candidate) {
  // A constant score: every candidate ties, so the first of the list wins at every node: naive.
  exbsp::build_options naive;
  naive.heuristic = "naive";
  const auto soup = cad_mesh("cross.off") ? cad_mesh("cross.off")->soup() : cyclic_soup();
  EXPECT_EQ(tree_text(soup, custom([](const auto&) { return 1.0; })), tree_text(soup, naive));
  // Scores that differ only in sign of zero tie as well.
  EXPECT_EQ(tree_text(soup, custom([](const exbsp::candidate_score_input& in) {
                        return in.candidate % 2 ? -0.0 : 0.0;
                      })),
            tree_text(soup, naive));
}

}  // namespace
