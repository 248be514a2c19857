// SPDX-License-Identifier: LGPL-3.0-or-later
// Distributed builds (include/exbsp/bsp/distributed.h, src/bsp/tree_distributed.h): the tree
// grown from cells shipped as bytes must be the tree bsp::build makes, byte for byte
// (serialize_reproducible), for every heuristic, on real meshes, rotated ones and hard soups,
// whatever order the parts come back in; malformed or mismatched bytes give input_error and
// never a tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <exbsp/bsp/distributed.h>
#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include "support/inputs.h"
#include "support/test_helpers.h"

namespace {

using exbsp::build_options;
using exbsp::distributed_build;
using exbsp::triangle_soup;

/// The parts of `plan`'s cells, built here, added in `order` (a permutation of the cells).
exbsp::bsp finish_in_order(distributed_build& plan, const std::vector<std::size_t>& order) {
  std::vector<std::string> parts(plan.cell_count());
  for (std::size_t i = 0; i < parts.size(); ++i)
    parts[i] = distributed_build::build_cell(plan.input(), plan.cell(i));
  for (const std::size_t i : order) plan.add_part(i, parts[i]);
  return plan.finish();
}

/// Expects the distributed build of `soup` to give the local tree; returns its cell count.
std::size_t expect_same_tree(const triangle_soup& soup, const build_options& o,
                             const std::string& what) {
  const exbsp::bsp local = exbsp::bsp::build(soup, o);
  distributed_build plan(soup, o);
  const std::size_t cells = plan.cell_count();
  std::vector<std::size_t> order(plan.cell_count());
  std::iota(order.begin(), order.end(), 0);
  std::reverse(order.begin(), order.end());  // the last part first: joined only at the end
  const exbsp::bsp shipped = finish_in_order(plan, order);
  EXPECT_EQ(local.stats().fragments, shipped.stats().fragments) << what;
  EXPECT_EQ(local.stats().splits, shipped.stats().splits) << what;
  EXPECT_EQ(local.stats().nodes, shipped.stats().nodes) << what;
  EXPECT_EQ(local.stats().depth, shipped.stats().depth) << what;
  EXPECT_TRUE(local.serialize_reproducible() == shipped.serialize_reproducible())
      << what << ": the saved trees differ";
  EXPECT_EQ(local.order_from_eye({3.25, -40, 17}), shipped.order_from_eye({3.25, -40, 17})) << what;
  return cells;
}

/// The soup turned by a rotation (doubles, rounded: coplanar faces stop being exactly so)
/// and moved, as a part placed in an assembly.
triangle_soup placed(triangle_soup s, double angle, exbsp::vec3d move) {
  const double c = std::cos(angle), si = std::sin(angle);
  for (exbsp::vec3d& v : s.vertices) {
    const double x = c * v[0] - si * v[1], y = si * v[0] + c * v[1];
    const double y2 = c * y - si * v[2], z2 = si * y + c * v[2];
    v = {x + move[0], y2 + move[1], z2 + move[2]};
  }
  return s;
}

TEST(Distributed, SameTreeAsTheLocalBuildForEveryHeuristicOnSoups) {
  for (const char* heuristic : {"naive", "sampled", "random", "min-split"}) {
    for (std::uint64_t seed : {1u, 7u}) {
      build_options o;
      o.heuristic = heuristic;
      o.seed = seed;
      EXPECT_EQ(expect_same_tree(exbsp_test::make_random_soup(300, seed), o,
                                 std::string(heuristic) + " seed " + std::to_string(seed)),
                16u);
    }
  }
}

TEST(Distributed, SameTreeOnCoplanarStacksAndSharedPoints) {
  // Stacks of coplanar triangles and a row of triangles crossing them: zero signs, shared
  // split points (one point per edge and plane, used by both neighbours) and deep lists, in
  // a random soup (which makes the top branch out to the 16 cells).
  triangle_soup s = exbsp_test::make_random_soup(300, 9);
  const auto face0 = static_cast<std::uint32_t>(s.face_count);
  for (int k = 0; k < 200; ++k) {
    const auto b = static_cast<std::uint32_t>(s.vertices.size());
    const double z = k % 5;  // five planes, 40 triangles in each
    s.vertices.push_back({0.0 + k, 0, z});
    s.vertices.push_back({4.0 + k, 0.5, z});
    s.vertices.push_back({1.0 + k, 3, z});
    s.triangles.push_back({{b, b + 1, b + 2}, face0 + static_cast<std::uint32_t>(k)});
  }
  for (int k = 0; k < 200; ++k) {
    const auto b = static_cast<std::uint32_t>(s.vertices.size());
    s.vertices.push_back({0.5 + k, -1, -1});
    s.vertices.push_back({0.5 + k, 4, -1});
    s.vertices.push_back({0.5 + k, 1.5, 6});
    s.triangles.push_back({{b, b + 1, b + 2}, face0 + 200 + static_cast<std::uint32_t>(k)});
  }
  s.face_count = face0 + 400;
  for (const char* heuristic : {"naive", "sampled"}) {
    build_options o;
    o.heuristic = heuristic;
    EXPECT_EQ(expect_same_tree(s, o, heuristic), 16u) << heuristic;
  }
}

TEST(Distributed, SameTreeOnCadMeshesAndAPlacedCopy) {
  for (const char* name : {"fandisk.off", "pinion.off", "rotor.off", "couplingdown.off"}) {
    const std::string path = exbsp_test::corpus_dir() + name;
    EXBSP_NEED_CORPUS(std::ifstream(path).good(), path);
    const triangle_soup soup = exbsp::read_mesh(path);
    EXPECT_EQ(expect_same_tree(soup, {}, name), 16u) << name;
    EXPECT_EQ(
        expect_same_tree(placed(soup, 0.3, {1.5, -2.25, 0.125}), {}, std::string(name) + " placed"),
        16u)
        << name;
  }
}

TEST(Distributed, BuildHereIsTheLocalTree) {
  const triangle_soup soup = exbsp_test::make_random_soup(200, 3);
  EXPECT_TRUE(exbsp::bsp::build(soup).serialize_reproducible() ==
              distributed_build::build_here(soup).serialize_reproducible());
}

TEST(Distributed, ATreeSmallerThanTheFrontierHasNoCells) {
  const triangle_soup soup = exbsp_test::make_random_soup(3, 5);
  distributed_build plan(soup);
  EXPECT_EQ(plan.cell_count(), 0u);
  EXPECT_TRUE(plan.finish().serialize_reproducible() ==
              exbsp::bsp::build(soup).serialize_reproducible());
}

TEST(Distributed, RefusesWhatCannotTravel) {
  const triangle_soup soup = exbsp_test::make_random_soup(50, 1);
  build_options o;
  o.kernel = exbsp::kernel_id::epeck;
  EXPECT_THROW(distributed_build(soup, o), exbsp::usage_error);
  build_options custom;
  custom.heuristic = "custom";
  custom.score = [](const exbsp::candidate_score_input& in) { return double(in.straddling); };
  EXPECT_THROW(distributed_build(soup, custom), exbsp::usage_error);
}

TEST(Distributed, MisuseIsAUsageError) {
  distributed_build plan(exbsp_test::make_random_soup(300, 2));
  ASSERT_GT(plan.cell_count(), 1u);
  EXPECT_THROW(plan.cell(plan.cell_count()), exbsp::usage_error);
  const std::string part = distributed_build::build_cell(plan.input(), plan.cell(0));
  EXPECT_THROW(plan.finish(), exbsp::usage_error);  // parts missing
  plan.add_part(0, part);
  EXPECT_THROW(plan.add_part(0, part), exbsp::usage_error);  // twice
  EXPECT_THROW(plan.add_part(plan.cell_count(), part), exbsp::usage_error);
}

TEST(Distributed, MalformedOrMismatchedBytesAreInputErrors) {
  const triangle_soup soup = exbsp_test::make_random_soup(300, 4);
  distributed_build plan(soup);
  ASSERT_GT(plan.cell_count(), 2u);
  const std::string& input = plan.input();
  const std::string& cell = plan.cell(1);
  // Truncated input and cell, a cell given as the input, a part of another cell.
  EXPECT_THROW(distributed_build::build_cell(input.substr(0, input.size() / 2), cell),
               exbsp::input_error);
  EXPECT_THROW(distributed_build::build_cell(input, cell.substr(0, cell.size() - 3)),
               exbsp::input_error);
  EXPECT_THROW(distributed_build::build_cell(cell, cell), exbsp::input_error);
  const std::string part0 = distributed_build::build_cell(input, plan.cell(0));
  const std::string part1 = distributed_build::build_cell(input, cell);
  EXPECT_THROW(plan.add_part(0, part1), exbsp::input_error);
  // A damaged point id in the part: caught by the checks, never a tree.
  std::string damaged = part0;
  damaged[damaged.size() - 8] = static_cast<char>(0xff);
  damaged[damaged.size() - 7] = static_cast<char>(0xff);
  try {
    distributed_build fresh(soup);
    fresh.add_part(0, damaged);
    for (std::size_t i = 1; i < fresh.cell_count(); ++i)
      fresh.add_part(i, distributed_build::build_cell(fresh.input(), fresh.cell(i)));
    (void)fresh.finish();
    ADD_FAILURE() << "a damaged part made a tree";
  } catch (const exbsp::input_error& e) {
    EXPECT_NE(std::string(e.what()).find("part 0"), std::string::npos) << e.what();
  }
}

TEST(Distributed, TheFragmentLimitHoldsAsInTheLocalBuild) {
  const triangle_soup soup = exbsp_test::make_random_soup(300, 6);
  const std::size_t fragments = exbsp::bsp::build(soup).stats().fragments;
  build_options o;
  o.max_fragments = fragments - 1;
  EXPECT_THROW(distributed_build::build_here(soup, o), exbsp::limit_error);
  o.max_fragments = fragments;
  EXPECT_EQ(distributed_build::build_here(soup, o).stats().fragments, fragments);
}

}  // namespace
