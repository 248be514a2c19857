// SPDX-License-Identifier: LGPL-3.0-or-later
// The parallel build (src/bsp/bsp_tree_impl.h: OpenMP with atomics): every parallel part runs
// with 1, 2 and 4 threads and must give the same tree, order and exact points. These are the
// tests the ThreadSanitizer build runs (scripts/test --tsan): each one drives a parallel
// region that shares state between threads.
//
//   - the subtrees below the first 16 pending nodes, built in parallel (every kernel);
//   - min-split's candidate loop (lists over 64 fragments) with its shared best key;
//   - the side tests of lists over 65536 fragments;
//   - the exact kernel's shared tables: lazily made exact planes (compare-exchange), exact
//     values of points (a locked map), point ids claimed in blocks;
//   - an exception (the fragment limit) thrown inside a parallel region and rethrown outside;
//   - the exact kernel's first rounding of its points to doubles (fragments_double);
//   - the SVG drawing's threads (src/view/vector_drawing.cpp): the edges on their own thread,
//     T-junctions mended ahead of the coverage walk by a helper, regions and underlay groups
//     over the cores.
//
// Inputs are small enough for ThreadSanitizer's slowdown (5-15x).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/view/render.h>
#include "support/inputs.h"
#include "support/observable.h"

namespace {

using exbsp::build_options;
using exbsp::kernel_id;
using exbsp::triangle_soup;
using exbsp::vec3d;

/// What a user observes of the tree built from `soup` with `threads` threads
/// (support/observable.h), for two eyes and a direction.
std::string observable(const triangle_soup& soup, build_options o, unsigned threads) {
  o.threads = threads;
  o.parallel_min_fragments = 0;  // these inputs are small: build their subtrees in parallel
  return exbsp_test::observable(exbsp::bsp::build(soup, o),
                                {vec3d{-3, 40, 25}, vec3d{7.5, 7.5, 7.5}, vec3d{0.3, -1, 0.2}});
}

void expect_same_for_1_2_and_4_threads(const triangle_soup& soup, const build_options& o,
                                       const std::string& what) {
  const std::string one = observable(soup, o, 1);
  EXPECT_EQ(one, observable(soup, o, 2)) << what << ": 2 threads";
  EXPECT_EQ(one, observable(soup, o, 4)) << what << ": 4 threads";
}

/// A random soup with near-degenerate triangles mixed in: vertices one ulp off the planes of
/// others, so that the exact kernel's filter fails and exact planes and values are made
/// concurrently in several subtrees.
triangle_soup soup_with_near_coplanar(std::size_t n, std::uint64_t seed) {
  triangle_soup s = exbsp_test::make_random_soup(n, seed);
  const std::size_t base = s.triangles.size();
  for (std::size_t i = 0; i < base; i += 7) {
    const auto& t = s.triangles[i];
    vec3d a = s.vertices[t.v[0]], b = s.vertices[t.v[1]], c = s.vertices[t.v[2]];
    // The same plane's points: midpoints of two edges (rounded), one nudged by one ulp.
    vec3d m{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
    vec3d q{(b[0] + c[0]) / 2, (b[1] + c[1]) / 2, (b[2] + c[2]) / 2};
    q[2] = std::nextafter(q[2], 1e300);
    s.add_triangle(m, q, {a[0] + 0.3, a[1] - 0.2, a[2] + 0.9});
  }
  return s;
}

TEST(ParallelBuild, every_kernel_and_heuristic_gives_the_same_tree_for_1_2_and_4_threads) {
  const triangle_soup soup = exbsp_test::make_random_soup(300, 7);
  for (kernel_id k : {kernel_id::exact, kernel_id::epeck, kernel_id::epick, kernel_id::double_})
    for (const std::string& h : exbsp::heuristic_names()) {
      build_options o;
      o.kernel = k;
      o.heuristic = h;
      o.seed = 3;
      expect_same_for_1_2_and_4_threads(soup, o, exbsp::to_string(k) + " " + h);
    }
}

TEST(ParallelBuild, gmpq_gives_the_same_tree_for_1_2_and_4_threads) {
  const triangle_soup soup = exbsp_test::make_random_soup(60, 2);
  build_options o;
  o.kernel = kernel_id::gmpq;
  o.heuristic = "sampled";
  expect_same_for_1_2_and_4_threads(soup, o, "gmpq");
}

TEST(ParallelBuild, min_split_candidates_over_64_are_scored_in_parallel) {
  // The sticks: every plane of one layer splits every stick of the other, so many candidates
  // tie and the shared best key (count, index) decides.
  const triangle_soup soup = exbsp_test::make_sticks(24);
  ASSERT_GT(soup.triangles.size(), 64u);
  for (kernel_id k : {kernel_id::exact, kernel_id::epeck}) {
    build_options o;
    o.kernel = k;
    o.heuristic = "min-split";
    expect_same_for_1_2_and_4_threads(soup, o, exbsp::to_string(k));
  }
}

TEST(ParallelBuild, exact_planes_and_values_are_made_concurrently) {
  const triangle_soup soup = soup_with_near_coplanar(400, 11);
  for (const char* h : {"sampled", "random"}) {
    build_options o;
    o.heuristic = h;
    o.seed = 1;
    expect_same_for_1_2_and_4_threads(soup, o, h);
  }
}

TEST(ParallelBuild, the_first_rounding_of_exact_points_runs_in_parallel_and_rounds_as_epeck) {
  // fragments_double() of the exact kernel computes the exact values of its constructed
  // points on all cores (over 1024 points): the same bits as Epeck's correctly rounded output.
  const triangle_soup soup = exbsp_test::make_random_soup(1500, 5);
  build_options o;
  o.threads = 2;
  const exbsp::bsp exact = exbsp::bsp::build(soup, o);
  ASSERT_GT(exact.stats().splits, 1024u) << "too few constructed points for the parallel loop";
  o.kernel = kernel_id::epeck;
  const exbsp::bsp epeck = exbsp::bsp::build(soup, o);
  const std::vector<exbsp::fragment_d> a = exact.fragments_double(), b = epeck.fragments_double();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].face, b[i].face) << i;
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(std::signbit(a[i].v[v][k]), std::signbit(b[i].v[v][k])) << i;
    ASSERT_EQ(a[i].v, b[i].v) << "fragment " << i;
  }
}

TEST(ParallelBuild, side_tests_of_a_list_over_65536_fragments_run_in_parallel) {
  // 70000 small triangles: the root's list is over the threshold of the parallel side tests.
  const triangle_soup soup = exbsp_test::make_random_soup(70000, 5);
  build_options o;
  o.heuristic = "sampled";
  o.threads = 1;
  const exbsp::build_stats one = exbsp::bsp::build(soup, o).stats();
  o.threads = 2;
  const exbsp::build_stats two = exbsp::bsp::build(soup, o).stats();
  EXPECT_EQ(one.fragments, two.fragments);
  EXPECT_EQ(one.splits, two.splits);
  EXPECT_EQ(one.nodes, two.nodes);
  EXPECT_EQ(one.depth, two.depth);
}

TEST(ParallelBuild, the_fragment_limit_thrown_inside_a_parallel_region_reaches_the_caller) {
  const triangle_soup soup = exbsp_test::make_random_soup(2000, 9);
  for (kernel_id k : {kernel_id::exact, kernel_id::epeck}) {
    build_options o;
    o.kernel = k;
    o.heuristic = "random";
    o.threads = 2;
    o.max_fragments =
        7000;  // past the first 16 nodes (built on one thread), half what the tree needs
    EXPECT_THROW(exbsp::bsp::build(soup, o), exbsp::limit_error) << exbsp::to_string(k);
  }
}

/// Two interpenetrating UV spheres (closed meshes: shared edges, silhouettes, creases at the
/// poles) whose fragments meet in T-junctions where the BSP split one side of an edge only.
triangle_soup two_spheres(int slices, int stacks) {
  triangle_soup s;
  for (const vec3d& c : {vec3d{0, 0, 0}, vec3d{0.8, 0.3, 0.2}}) {
    auto at = [&](int i, int j) {
      const double th = M_PI * j / stacks, ph = 2 * M_PI * i / slices;
      return vec3d{c[0] + std::sin(th) * std::cos(ph), c[1] + std::sin(th) * std::sin(ph),
                   c[2] + std::cos(th)};
    };
    for (int j = 0; j < stacks; ++j)
      for (int i = 0; i < slices; ++i) {
        const vec3d a = at(i, j), b = at(i + 1, j), d = at(i, j + 1), e = at(i + 1, j + 1);
        if (j > 0) s.add_triangle(a, d, b);
        if (j + 1 < stacks) s.add_triangle(b, d, e);
      }
  }
  return s;
}

TEST(ParallelDrawing, the_svg_drawing_is_the_same_each_time_its_threads_run) {
  build_options o;
  o.keep_input = true;
  o.threads = 1;
  const exbsp::bsp tree = exbsp::bsp::build(two_spheres(48, 24), o);
  const triangle_soup& soup = tree.input();
  for (const char* name : {"iso", "front"}) {
    const exbsp::view::fitted_view v = exbsp::view::fit_view(soup, 320, 240, name);
    const std::string first = exbsp::view::render_tree_svg(tree, v, 320, 240, {}, "visible+hidden");
    EXPECT_NE(first.find("<path"), std::string::npos) << name;
    for (int run = 0; run < 3; ++run)
      EXPECT_EQ(first, exbsp::view::render_tree_svg(tree, v, 320, 240, {}, "visible+hidden"))
          << name << ", run " << run;
  }
}

}  // namespace
