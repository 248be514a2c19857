// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of the public API additions of the package: exact coordinates as GMP rationals
// (bsp/exact_gmp.h) and cancelling a build from the progress callback (build_options::progress,
// build_cancelled). Degenerate cases first.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/bsp/exact_gmp.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/soup.h>

namespace {

using exbsp::bsp;
using exbsp::build_options;
using exbsp::kernel_id;
using exbsp::triangle_soup;

// Two triangles crossing: face 1 straddles face 0's plane z = 0 and is split there, at points
// with non-dyadic coordinates (1/3 and 2/3 below).
triangle_soup crossing_pair() {
  triangle_soup soup;
  soup.add_triangle({0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  soup.add_triangle({0, 0, -1}, {1, 0, 2}, {0, 1, 2});
  return soup;
}

// `count` random small triangles in the unit cube (fixed seed): a tree of thousands of nodes.
triangle_soup random_triangles(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, 1.0), off(-0.05, 0.05);
  triangle_soup soup;
  for (int i = 0; i < count; ++i) {
    const exbsp::vec3d a{pos(rng), pos(rng), pos(rng)};
    soup.add_triangle(a, {a[0] + off(rng), a[1] + off(rng), a[2] + off(rng)},
                      {a[0] + off(rng), a[1] + off(rng), a[2] + off(rng)});
  }
  return soup;
}

build_options naive(kernel_id k) {
  build_options o;
  o.kernel = k;
  o.heuristic = "naive";
  return o;
}

// ---- exact coordinates as mpq_class ----

TEST(ExactGmp, EmptyTreeHasNoFragmentToAskFor) {
  const bsp tree = bsp::build(triangle_soup{}, naive(kernel_id::exact));
  EXPECT_EQ(tree.fragment_count(), 0u);
  EXPECT_THROW(exbsp::fragment_exact_mpq(tree, 0), exbsp::usage_error);
}

TEST(ExactGmp, IndexOutOfRangeIsUsageError) {
  const bsp tree = bsp::build(crossing_pair(), naive(kernel_id::exact));
  EXPECT_THROW(exbsp::fragment_exact_mpq(tree, tree.fragment_count()), exbsp::usage_error);
}

TEST(ExactGmp, InexactKernelsHaveNoExactCoordinates) {
  for (kernel_id k : {kernel_id::epick, kernel_id::double_}) {
    const bsp tree = bsp::build(crossing_pair(), naive(k));
    ASSERT_GT(tree.fragment_count(), 0u);
    EXPECT_THROW(exbsp::fragment_exact_mpq(tree, 0), exbsp::usage_error) << exbsp::to_string(k);
  }
}

TEST(ExactGmp, SplitPointsAreTheExactRationals) {
  // Face 1 from (0,0,-1) to (1,0,2) and to (0,1,2) crosses z = 0 at t = 1/3: (1/3, 0, 0) and
  // (0, 1/3, 0), which no double holds.
  const bsp tree = bsp::build(crossing_pair(), naive(kernel_id::exact));
  ASSERT_EQ(tree.stats().splits, 1u);
  bool seen_x = false, seen_y = false;
  for (std::size_t i = 0; i < tree.fragment_count(); ++i) {
    const exbsp::exact_triangle_mpq e = exbsp::fragment_exact_mpq(tree, i);
    for (const auto& p : e) {
      if (p[0] == mpq_class(1, 3) && p[1] == 0 && p[2] == 0) seen_x = true;
      if (p[0] == 0 && p[1] == mpq_class(1, 3) && p[2] == 0) seen_y = true;
    }
  }
  EXPECT_TRUE(seen_x);
  EXPECT_TRUE(seen_y);
}

TEST(ExactGmp, SameValuesAsTheTextOnEveryExactKernel) {
  const triangle_soup soup = random_triangles(300, 7);
  for (kernel_id k : {kernel_id::exact, kernel_id::epeck, kernel_id::gmpq}) {
    SCOPED_TRACE(exbsp::to_string(k));
    const bsp tree = bsp::build(soup, naive(k));
    ASSERT_GT(tree.stats().splits, 0u);
    for (std::size_t i = 0; i < tree.fragment_count(); ++i) {
      const exbsp::exact_triangle text = tree.fragment_exact(i);
      const exbsp::exact_triangle_mpq q = exbsp::fragment_exact_mpq(tree, i);
      for (int v = 0; v < 3; ++v)
        for (int a = 0; a < 3; ++a) {
          ASSERT_EQ(q[v][a], mpq_class(text[v][a])) << "fragment " << i;
          // Canonical: the text of the value is the value's own text.
          ASSERT_EQ(q[v][a].get_str(), text[v][a]) << "fragment " << i;
        }
    }
  }
}

TEST(ExactGmp, ExactKernelsAgreeOnEveryCoordinate) {
  const triangle_soup soup = random_triangles(200, 11);
  const bsp a = bsp::build(soup, naive(kernel_id::exact));
  const bsp b = bsp::build(soup, naive(kernel_id::gmpq));
  ASSERT_EQ(a.fragment_count(), b.fragment_count());
  for (std::size_t i = 0; i < a.fragment_count(); ++i)
    ASSERT_EQ(exbsp::fragment_exact_mpq(a, i), exbsp::fragment_exact_mpq(b, i)) << "fragment " << i;
}

// ---- cancellation ----

struct caller_stop {  // not an exbsp::error: any exception type must come through unchanged
  int code;
};

TEST(Cancel, EmptyInputCallsProgressOnceAndCanCancel) {
  build_options o = naive(kernel_id::exact);
  int calls = 0;
  o.progress = [&](const exbsp::build_progress&) {
    ++calls;
    throw exbsp::build_cancelled();
  };
  EXPECT_THROW(bsp::build(triangle_soup{}, o), exbsp::build_cancelled);
  EXPECT_EQ(calls, 1);
}

TEST(Cancel, ThrowingOnTheFinalReportStillReturnsNoTree) {
  // The last call reports the complete tree; throwing there cancels too.
  const triangle_soup soup = crossing_pair();
  build_options o = naive(kernel_id::exact);
  int calls = 0;
  o.progress = [&](const exbsp::build_progress& p) {
    ++calls;
    if (p.fragments_placed == 4) throw exbsp::build_cancelled("stop at the end");
  };
  try {
    bsp::build(soup, o);
    FAIL() << "no exception";
  } catch (const exbsp::build_cancelled& e) {
    EXPECT_STREQ(e.what(), "stop at the end");
    EXPECT_TRUE(dynamic_cast<const exbsp::error*>(&e) != nullptr);
  }
  EXPECT_EQ(calls, 1);
}

TEST(Cancel, DefaultMessage) { EXPECT_STREQ(exbsp::build_cancelled().what(), "build cancelled"); }

// Cancels once the build has made `after_nodes` nodes, with 1 and 2 threads and every kernel
// family: the caller's exception arrives unchanged, progress is not called after it threw, and
// a later build with the same options gives the tree an uncancelled build gives.
void cancel_midway(kernel_id kernel, const std::string& heuristic, int triangles,
                   std::size_t after_nodes) {
  const triangle_soup soup = random_triangles(triangles, 3);
  build_options plain;
  plain.kernel = kernel;
  plain.heuristic = heuristic;
  const bsp reference = bsp::build(soup, plain);
  ASSERT_GT(reference.stats().nodes, after_nodes + 512)
      << "the input must outlast the cancel point";
  for (unsigned threads : {1u, 2u}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    build_options o = plain;
    o.threads = threads;
    std::atomic<int> calls{0}, calls_after_throw{0};
    std::atomic<bool> thrown{false};
    o.progress = [&](const exbsp::build_progress& p) {
      ++calls;
      if (thrown) ++calls_after_throw;
      EXPECT_LE(p.fragments_placed, p.fragments_total);
      if (p.nodes >= after_nodes) {
        thrown = true;
        throw caller_stop{42};
      }
    };
    try {
      bsp::build(soup, o);
      FAIL() << "the build was not cancelled";
    } catch (const caller_stop& e) {
      EXPECT_EQ(e.code, 42);
    }
    EXPECT_TRUE(thrown);
    EXPECT_EQ(calls_after_throw, 0);
    EXPECT_GE(calls, 1);

    o.progress = nullptr;
    const bsp again = bsp::build(soup, o);
    EXPECT_EQ(again.stats().fragments, reference.stats().fragments);
    EXPECT_EQ(again.stats().nodes, reference.stats().nodes);
    EXPECT_EQ(again.order_from_eye({2, 3, 5}), reference.order_from_eye({2, 3, 5}));
  }
}

TEST(Cancel, FirstReportExactKernel) { cancel_midway(kernel_id::exact, "sampled", 3000, 0); }
TEST(Cancel, MidwayExactKernel) { cancel_midway(kernel_id::exact, "sampled", 3000, 1024); }
TEST(Cancel, MidwayExactMinSplit) { cancel_midway(kernel_id::exact, "min-split", 1000, 300); }
TEST(Cancel, MidwayEpeck) { cancel_midway(kernel_id::epeck, "sampled", 3000, 1024); }
TEST(Cancel, MidwayDoubleKernel) { cancel_midway(kernel_id::double_, "naive", 3000, 1024); }

TEST(Cancel, ProgressCallsNeverOverlap) {
  const triangle_soup soup = random_triangles(3000, 5);
  build_options o;
  o.threads = 2;
  std::atomic<int> inside{0}, overlaps{0}, calls{0};
  o.progress = [&](const exbsp::build_progress&) {
    if (inside.fetch_add(1) != 0) ++overlaps;
    ++calls;
    volatile double spin = 0;  // stay inside long enough for another thread to arrive
    for (int i = 0; i < 20000; ++i) spin = spin + i;
    inside.fetch_sub(1);
  };
  const bsp tree = bsp::build(soup, o);
  EXPECT_EQ(overlaps, 0);
  EXPECT_GE(calls, 2);
  EXPECT_GT(tree.stats().nodes, 1024u);
}

}  // namespace
