// SPDX-License-Identifier: LGPL-3.0-or-later
// Incremental insertion (bsp::inserted / bsp::insert, src/bsp/tree_insert.h): a naive tree
// that takes new triangles must become, byte for byte (serialize_reproducible) and order for
// order, the tree bsp::build makes with the naive heuristic of the concatenated input (old
// triangles, then new ones: triangle_soup::append), on hard soups cut anywhere, in several
// inserts, in every kernel, and on real meshes; the original tree and its copies stay as they
// were; other heuristics, bad input, the fragment limit and cancellation are refused and leave
// the tree unchanged.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include "support/generators.h"
#include "support/inputs.h"
#include "support/test_helpers.h"

namespace {

using exbsp::bsp;
using exbsp::build_options;
using exbsp::kernel_id;
using exbsp::triangle_soup;
using exbsp::vec3d;

build_options naive(kernel_id k = kernel_id::exact) {
  build_options o;
  o.kernel = k;
  o.heuristic = "naive";
  return o;
}

/// Triangles [begin, end) of `s` as a soup of their own: the vertices they use, in first use
/// order (shared within the part, as in `s`), face ids made to start at 0.
triangle_soup part_of(const triangle_soup& s, std::size_t begin, std::size_t end) {
  triangle_soup out;
  out.source = s.source;
  std::map<std::uint32_t, std::uint32_t> ids;
  std::uint32_t first_face = ~0u;
  for (std::size_t i = begin; i < end; ++i) first_face = std::min(first_face, s.triangles[i].face);
  for (std::size_t i = begin; i < end; ++i) {
    std::vector<std::uint32_t> v;
    for (std::uint32_t id : s.triangles[i].v) {
      const auto [it, added] = ids.emplace(id, static_cast<std::uint32_t>(out.vertices.size()));
      if (added) out.vertices.push_back(s.vertices[id]);
      v.push_back(it->second);
    }
    out.add_polygon(v, s.triangles[i].face - first_face);
  }
  return out;
}

/// The soup with equal coordinates welded into one vertex: triangles then share vertex ids
/// (and the build shares split points between neighbours).
triangle_soup welded(const triangle_soup& s) {
  triangle_soup out;
  out.source = s.source;
  std::map<vec3d, std::uint32_t> ids;
  for (const auto& t : s.triangles) {
    std::vector<std::uint32_t> v;
    for (std::uint32_t id : t.v) {
      const auto [it, added] =
          ids.emplace(s.vertices[id], static_cast<std::uint32_t>(out.vertices.size()));
      if (added) out.vertices.push_back(s.vertices[id]);
      v.push_back(it->second);
    }
    out.add_polygon(v, t.face);
  }
  return out;
}

/// What differs between two trees ("" when nothing): stats, saved bytes, fragments' sources,
/// and orders for `eyes` (perspective) and the same vectors as directions.
std::string difference(const bsp& a, const bsp& b, const std::vector<vec3d>& eyes) {
  std::string out;
  exbsp::for_each_stat_count(a.stats(), [&](const char* name, std::size_t value) {
    exbsp::for_each_stat_count(b.stats(), [&](const char* other, std::size_t v) {
      if (std::string(name) == other && v != value)
        out += std::string(name) + " " + std::to_string(value) + " vs " + std::to_string(v) + "; ";
    });
  });
  if (a.serialize_reproducible() != b.serialize_reproducible()) out += "saved bytes differ; ";
  for (const vec3d& e : eyes) {
    if (a.order_from_eye(e) != b.order_from_eye(e)) out += "order from an eye differs; ";
    if (e != vec3d{0, 0, 0} && a.order_for_direction(e) != b.order_for_direction(e))
      out += "order for a direction differs; ";
  }
  return out;
}

/// Builds parts[0] naively, inserts the other parts one call each (alternating inserted and
/// insert), and returns that tree and the naive build of the concatenation.
std::pair<bsp, bsp> inserted_and_built(const std::vector<triangle_soup>& parts,
                                       const build_options& o) {
  triangle_soup all = parts.front();
  bsp tree = bsp::build(parts.front(), o);
  for (std::size_t i = 1; i < parts.size(); ++i) {
    all.append(parts[i]);
    if (i % 2)
      tree = tree.inserted(parts[i]);
    else
      tree.insert(parts[i]);
  }
  return {tree, bsp::build(all, o)};
}

std::vector<triangle_soup> cut(const triangle_soup& s, std::vector<std::size_t> at) {
  std::sort(at.begin(), at.end());
  std::vector<triangle_soup> parts;
  std::size_t begin = 0;
  for (std::size_t c : at) {
    parts.push_back(part_of(s, begin, c));
    begin = c;
  }
  parts.push_back(part_of(s, begin, s.triangles.size()));
  return parts;
}

/// Inside a property: the soup cut at 1..3 random places (empty parts allowed) gives, inserted
/// part by part, the naive build of the whole in kernel k.
void rc_check_cut(const triangle_soup& soup, kernel_id k) {
  const std::size_t n = soup.triangles.size();
  const int cuts = exbsp_test::pick_int(1, 3);
  std::vector<std::size_t> at;
  for (int i = 0; i < cuts; ++i) at.push_back(*rc::gen::inRange<std::size_t>(0, n + 1));
  std::vector<vec3d> eyes;
  for (int i = 0; i < 4; ++i) eyes.push_back(exbsp_test::pick_point(-20, 20));
  // Eyes on the input's vertices: exactly on node planes.
  for (int i = 0; i < 2 && !soup.vertices.empty(); ++i)
    eyes.push_back(soup.vertices[*rc::gen::inRange<std::size_t>(0, soup.vertices.size())]);
  const auto [tree, built] = inserted_and_built(cut(soup, at), naive(k));
  RC_TAG(built.stats().splits > 0 ? "splits" : "no splits");
  const std::string diff = difference(tree, built, eyes);
  if (!diff.empty()) RC_FAIL(diff);
}

triangle_soup soup_of(const exbsp_test::soup_case& c) {
  const triangle_soup s = c.soup();
  return *rc::gen::element(0, 1) ? welded(s) : s;
}

RC_GTEST_PROP(Insert, cut_soups_inserted_part_by_part_equal_the_naive_build_exact, ()) {
  const exbsp_test::soup_case c = *exbsp_test::any_small_soup();
  RC_TAG(c.kind);
  rc_check_cut(soup_of(c), kernel_id::exact);
}

RC_GTEST_PROP(Insert, coplanar_stacks_and_planes_through_vertices_in_every_kernel, ()) {
  const exbsp_test::soup_case c =
      *rc::gen::oneOf(exbsp_test::coplanar_stack(), exbsp_test::vertex_on_plane(),
                      exbsp_test::near_coplanar(), exbsp_test::mesh_like());
  const kernel_id k = *rc::gen::element(kernel_id::exact, kernel_id::epeck, kernel_id::gmpq,
                                        kernel_id::epick, kernel_id::double_);
  RC_TAG(exbsp::to_string(k));
  rc_check_cut(soup_of(c), k);
}

// Duplicate triangles (the same vertex ids, and copies with their own vertices), triangles
// one ulp off a plane, and degenerate ones, in one soup cut everywhere.
TEST(Insert, DuplicatesUlpNeighboursAndDegenerateTrianglesCutAtEveryPosition) {
  triangle_soup s;
  s.vertices = {{0, 0, 0},
                {4, 0, 0},
                {0, 4, 0},
                {-1, 1, -1},
                {3, 1, 2},
                {1, 3, 2},
                {0, 0, std::nextafter(0.0, 1.0)},
                {4, 0, 0},
                {0, 4, std::nextafter(0.0, -1.0)},
                {1, 1, 0},
                {2, 2, 0},
                {3, 3, 0},
                {2, -1, 1},
                {2, 5, 1},
                {2, 1, -3}};
  const std::vector<std::array<std::uint32_t, 3>> tris = {
      {0, 1, 2}, {3, 4, 5}, {0, 1, 2}, {6, 7, 8},    {9, 10, 11}, {12, 13, 14},
      {2, 1, 0}, {3, 4, 5}, {0, 4, 2}, {12, 14, 13}, {9, 10, 11}, {1, 5, 3}};
  for (std::uint32_t f = 0; f < tris.size(); ++f)
    s.add_polygon({tris[f][0], tris[f][1], tris[f][2]}, f);
  const std::vector<vec3d> eyes{{0.5, 0.5, 5}, {1, 1, 0}, {2, 1, 0.5}, {-3, 7, -2}};
  for (std::size_t a = 0; a <= s.triangles.size(); ++a)
    for (std::size_t b = a; b <= s.triangles.size(); ++b) {
      const auto [tree, built] = inserted_and_built(cut(s, {a, b}), naive());
      EXPECT_EQ(difference(tree, built, eyes), "") << "cut at " << a << ", " << b;
    }
  const auto [tree, built] = inserted_and_built(cut(s, {5}), naive());
  EXPECT_EQ(tree.stats().degenerate_input, 2u);
  EXPECT_EQ(tree.stats().input_triangles, s.triangles.size());
}

TEST(Insert, RandomSoupsAndSticksInManyInserts) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    // Sticks: two triangles per stick share an edge, so their split points are shared.
    const triangle_soup s =
        seed == 3 ? exbsp_test::make_sticks(30) : exbsp_test::make_random_soup(200, seed);
    std::vector<std::size_t> at;
    for (std::size_t c = 20; c < s.triangles.size(); c += 20 + 13 * seed) at.push_back(c);
    for (kernel_id k : {kernel_id::exact, kernel_id::epeck}) {
      const auto [tree, built] = inserted_and_built(cut(s, at), naive(k));
      EXPECT_GT(built.stats().splits, 0u);
      EXPECT_EQ(difference(tree, built, {{3.25, -40, 17}, {0, 0, 0}, {-7, 2, 9}}), "")
          << "seed " << seed << " kernel " << exbsp::to_string(k);
    }
  }
}

TEST(Insert, CorpusMeshesSplitInHalves) {
  for (const char* name : {"joint.off", "fandisk.off"}) {
    const std::string path = exbsp_test::corpus_dir() + name;
    EXBSP_NEED_CORPUS(std::ifstream(path).good(), path);
    const triangle_soup s = exbsp::read_mesh(path);
    const std::size_t half = s.triangles.size() / 2;
    const std::vector<triangle_soup> parts = cut(s, {half});
    triangle_soup all = parts[0];
    all.append(parts[1]);
    const auto t0 = std::chrono::steady_clock::now();
    const bsp old = bsp::build(parts[0], naive());
    const auto t1 = std::chrono::steady_clock::now();
    const bsp tree = old.inserted(parts[1]);
    const auto t2 = std::chrono::steady_clock::now();
    const bsp built = bsp::build(all, naive());
    const auto t3 = std::chrono::steady_clock::now();
    const auto ms = [](auto a, auto b) {
      return std::chrono::duration<double, std::milli>(b - a).count();
    };
    std::cout << name << ": half built " << ms(t0, t1) << " ms, insert of the other half "
              << ms(t1, t2) << " ms, naive build of the whole " << ms(t2, t3) << " ms ("
              << built.stats().fragments << " fragments)\n";
    EXPECT_EQ(difference(tree, built, {{3.25, -40, 17}, {100, 100, 100}, {0.1, 0.2, -0.3}}), "")
        << name;
    // The last 1% into the tree of the rest (the incremental case): timed for the report.
    const std::size_t most = all.triangles.size() - all.triangles.size() / 100;
    const bsp rest = bsp::build(part_of(all, 0, most), naive());
    const auto t4 = std::chrono::steady_clock::now();
    const bsp topped = rest.inserted(part_of(all, most, all.triangles.size()));
    const auto t5 = std::chrono::steady_clock::now();
    std::cout << name << ": insert of the last " << all.triangles.size() - most << " triangles "
              << ms(t4, t5) << " ms (" << topped.stats().fragments - rest.stats().fragments
              << " new fragments)\n";
    // The last triangles one at a time.
    bsp one_by_one = bsp::build(part_of(all, 0, all.triangles.size() - 5), naive());
    for (std::size_t i = all.triangles.size() - 5; i < all.triangles.size(); ++i)
      one_by_one.insert(part_of(all, i, i + 1));
    triangle_soup again = part_of(all, 0, all.triangles.size() - 5);
    for (std::size_t i = all.triangles.size() - 5; i < all.triangles.size(); ++i)
      again.append(part_of(all, i, i + 1));
    EXPECT_EQ(difference(one_by_one, bsp::build(again, naive()), {{3.25, -40, 17}}), "") << name;
  }
}

TEST(Insert, LoadedAndEmptyTreesTakeTriangles) {
  const triangle_soup s = exbsp_test::make_random_soup(120, 5);
  const std::vector<triangle_soup> parts = cut(s, {70});
  const bsp loaded = bsp::deserialize(bsp::build(parts[0], naive()).serialize(), "<insert test>");
  triangle_soup all = parts[0];
  all.append(parts[1]);
  EXPECT_EQ(difference(loaded.inserted(parts[1]), bsp::build(all, naive()), {{1, 2, 30}}), "");

  triangle_soup empty;
  const bsp none = bsp::build(empty, naive());
  EXPECT_EQ(none.node_count(), 0u);
  triangle_soup from_empty = empty;
  from_empty.append(s);
  EXPECT_EQ(difference(none.inserted(s), bsp::build(from_empty, naive()), {{1, 2, 30}}), "");
}

TEST(Insert, ADeepChainTakesTrianglesWithoutRecursion) {
  // Parallel triangles z = i: the naive tree is a chain as deep as the soup is long.
  // As Depth.naive_on_100000_stacked_triangles_builds_traverses_and_frees (test_bsp).
  const std::size_t n = std::getenv("EXBSP_SANITIZED") ? 20000 : 100000;
  triangle_soup s;
  for (std::size_t i = 0; i < n; ++i) {
    const double z = static_cast<double>(i);
    s.add_triangle({0, 0, z}, {1, 0, z}, {0, 1, z});
  }
  bsp tree = bsp::build(s, naive());
  ASSERT_EQ(tree.stats().depth, n);
  triangle_soup more;
  const double mid = n / 2.0;
  more.add_triangle({0, 0, n + 0.5}, {1, 0, n + 0.5}, {0, 1, n + 0.5});  // below the deepest
  more.add_triangle({0, 0, mid - 0.5}, {2, 0, mid + 0.5}, {0, 2, mid});  // across one node
  more.add_triangle({0, 0, -0.5}, {1, 0, -0.5}, {0, 1, -0.5});           // above the root
  tree.insert(more);
  EXPECT_EQ(tree.stats().depth, n + 1);
  EXPECT_EQ(tree.stats().splits, 1u);
  EXPECT_EQ(tree.stats().nodes, n + 4);
  triangle_soup all = s;
  all.append(more);
  EXPECT_EQ(difference(tree, bsp::build(all, naive()), {{0.25, 0.25, -1}}), "");
}

TEST(Insert, TheOriginalAndItsCopiesStayAsTheyWere) {
  const triangle_soup s = exbsp_test::make_random_soup(150, 9);
  const std::vector<triangle_soup> parts = cut(s, {100});
  const bsp original = bsp::build(parts[0], naive());
  const std::string before = original.serialize_reproducible();
  const std::vector<std::uint32_t> order_before = original.order_from_eye({1, 2, 30});
  bsp copy = original;
  const bsp other_copy = copy;
  copy.insert(parts[1]);
  const bsp third = original.inserted(parts[1]);
  EXPECT_EQ(original.serialize_reproducible(), before);
  EXPECT_EQ(other_copy.serialize_reproducible(), before);
  EXPECT_EQ(original.order_from_eye({1, 2, 30}), order_before);
  EXPECT_EQ(original.stats().input_triangles, parts[0].triangles.size());
  EXPECT_EQ(copy.stats().input_triangles, s.triangles.size());
  EXPECT_EQ(copy.serialize_reproducible(), third.serialize_reproducible());
  // New face ids continue after the old ones.
  EXPECT_EQ(copy.input().face_count, parts[0].face_count + parts[1].face_count);
  EXPECT_EQ(copy.input().triangles.back().face,
            parts[0].face_count + parts[1].triangles.back().face);
}

TEST(Insert, NothingInsertedGivesTheSameTree) {
  const triangle_soup s = exbsp_test::make_random_soup(80, 4);
  for (kernel_id k : {kernel_id::exact, kernel_id::gmpq, kernel_id::double_}) {
    const bsp tree = bsp::build(s, naive(k));
    EXPECT_EQ(tree.inserted(triangle_soup{}).serialize_reproducible(),
              tree.serialize_reproducible());
  }
}

TEST(Insert, OtherHeuristicsAndTreesWithoutInputAreRefused) {
  const triangle_soup s = exbsp_test::make_random_soup(40, 3);
  triangle_soup more;
  more.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  for (const char* h : {"sampled", "min-split", "random"}) {
    build_options o;
    o.heuristic = h;
    const bsp tree = bsp::build(s, o);
    std::string message;
    try {
      (void)tree.inserted(more);
    } catch (const exbsp::usage_error& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("naive"), std::string::npos) << h << ": " << message;
    EXPECT_NE(message.find(h), std::string::npos) << message;
  }
  build_options o = naive();
  o.keep_input = false;
  EXPECT_THROW((void)bsp::build(s, o).inserted(more), exbsp::usage_error);

  const bsp tree = bsp::build(s, naive());
  triangle_soup bad = more;
  bad.triangles[0].v[2] = 7;
  EXPECT_THROW((void)tree.inserted(bad), exbsp::usage_error);
  bad = more;
  bad.vertices[1][0] = NAN;
  EXPECT_THROW((void)tree.inserted(bad), exbsp::usage_error);
}

TEST(Insert, TheFragmentLimitAndCancellationLeaveTheTreeUnchanged) {
  const triangle_soup s = exbsp_test::make_random_soup(300, 11);
  const std::vector<triangle_soup> parts = cut(s, {150});
  triangle_soup all = parts[0];
  all.append(parts[1]);
  const std::size_t needed = bsp::build(all, naive()).stats().fragments;
  bsp tree = bsp::build(parts[0], naive());
  const std::string before = tree.serialize_reproducible();
  exbsp::insert_options limited;
  limited.max_fragments = needed - 1;
  EXPECT_THROW(tree.insert(parts[1], limited), exbsp::limit_error);
  EXPECT_EQ(tree.serialize_reproducible(), before);

  exbsp::insert_options cancelled;
  std::size_t calls = 0;
  cancelled.progress = [&](const exbsp::build_progress& p) {
    ++calls;
    EXPECT_LE(p.fragments_placed, p.fragments_total);
    throw exbsp::build_cancelled("cancelled");
  };
  EXPECT_THROW(tree.insert(parts[1], cancelled), exbsp::build_cancelled);
  EXPECT_EQ(calls, 1u);
  EXPECT_EQ(tree.serialize_reproducible(), before);

  limited.max_fragments = needed;
  exbsp::build_progress last{};
  limited.progress = [&](const exbsp::build_progress& p) { last = p; };
  tree.insert(parts[1], limited);
  EXPECT_EQ(tree.stats().fragments, needed);
  EXPECT_EQ(last.fragments_placed, needed);
  EXPECT_EQ(last.nodes, tree.node_count());
}

}  // namespace
