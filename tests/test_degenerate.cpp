// SPDX-License-Identifier: LGPL-3.0-or-later
// The degenerate-input suite of the exact BSP: coplanar stacks in both orientations with
// crossers (some with a vertex exactly on the stack's plane), vertices on one, two and three
// node planes, vertices one ulp (and one subnormal) off a plane, coordinates near 1e9 with
// 1e-3 features and near 1e-300, needles and caps, shared edges, T-junctions, duplicates and
// reversed copies, and cyclic overlaps of n >= 3 triangles that no depth sort can draw.
// Every case is checked against every invariant of tests/HARD_CASES.md, exactly, for every
// heuristic, in Epeck (and Gmpq for the fixed cases); orders are checked for eyes exactly on
// node planes and at split points. Generators and checker: tests/support/.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <functional>
#include <set>

#include "support/generators.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp_test;
using EK = exbsp::epeck_kernel;
using GK = exbsp::gmpq_kernel;
using EP = EK::Point_3;

/// Every invariant, every heuristic, both exact kernels (Gmpq, unfiltered, with a smaller ray
/// budget unless `with_gmpq` is false), the standard viewpoints plus `eyes` and `directions`.
void expect_every_invariant(const soup_case& c, const std::vector<vec3d>& eyes = {},
                            const std::vector<vec3d>& directions = {}, std::size_t max_rays = 160,
                            bool with_gmpq = true) {
  for (const std::string& h : exbsp::heuristic_names()) {
    check_options o;
    o.seed = 20261121;
    o.eyes = eyes;
    o.directions = directions;
    o.max_rays = max_rays;
    const check_report re = build_and_check<EK>(c, h, o, 7);
    EXPECT_TRUE(re.ok()) << c.kind << " / epeck / " << h << ": " << re.text() << "\n" << to_off(c);
    if (!with_gmpq) continue;
    o.max_rays = 32;
    o.viewpoints = 3;
    const check_report rg = build_and_check<GK>(c, h, o, 7);
    EXPECT_TRUE(rg.ok()) << c.kind << " / gmpq / " << h << ": " << rg.text();
  }
}

/// Check options with at most `viewpoints` standard viewpoints (runtime budget).
check_options budget(std::size_t viewpoints) {
  check_options o;
  o.viewpoints = viewpoints;
  return o;
}

exbsp::bsp_tree<EK> build_naive(const exbsp::triangle_soup& soup) {
  exbsp::build_options o;
  o.heuristic = "naive";
  return exbsp::bsp_tree<EK>(soup, o);
}

std::vector<std::size_t> fragments_of_source(const exbsp::bsp_tree<EK>& t, std::uint32_t source) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < t.fragments().size(); ++i)
    if (t.fragments()[i].source == source) out.push_back(i);
  return out;
}

const tri_d stack_a{{{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}}};

// --- Coplanar stacks --------------------------------------------------------------------------

TEST(CoplanarStack, overlapping_triangles_in_both_orientations_stay_at_one_node_in_list_order) {
  const soup_case c = case_of("stack", {stack_a,
                                        flipped(stack_a),
                                        {{{-1, -1, 0}, {3, 0, 0}, {0, 3, 0}}},
                                        flipped({{{-1, -1, 0}, {3, 0, 0}, {0, 3, 0}}}),
                                        stack_a,
                                        {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}});
  const exbsp::triangle_soup soup = c.soup();
  for (const std::string& h : exbsp::heuristic_names()) {
    exbsp::build_options o;
    o.heuristic = h;
    const exbsp::bsp_tree<EK> t(soup, o);
    EXPECT_EQ(t.stats().nodes, 1u) << h;
    EXPECT_EQ(t.stats().splits, 0u) << h;
    ASSERT_EQ(t.fragments().size(), 6u) << h;
    for (std::uint32_t i = 0; i < 6; ++i)
      EXPECT_EQ(t.fragments()[i].face, i) << h << ": the node list keeps list order";
    const std::vector<std::uint32_t> in_order{0, 1, 2, 3, 4, 5};
    EXPECT_EQ(t.order_from_eye(EP(0, 0, 5)), in_order);
    EXPECT_EQ(t.order_from_eye(EP(0, 0, -5)), in_order);
    EXPECT_EQ(t.order_from_eye(EP(9, 9, 0)), in_order) << "eye in the plane";
  }
  expect_every_invariant(c);
}

TEST(CoplanarStack, crosser_with_a_vertex_exactly_on_the_stack_plane_splits_into_two_pieces_on_it) {
  // The crosser's vertex (0.5, 0.25, 0) lies in the stack plane inside the stack triangles.
  const tri_d crosser{{{0.5, 0.25, 0}, {-1, 3, 1}, {2, 3, -1}}};
  const soup_case c = case_of("stack + on-plane crosser", {stack_a, flipped(stack_a), crosser});
  const exbsp::triangle_soup soup = c.soup();
  const auto t = build_naive(soup);
  EXPECT_EQ(t.stats().splits, 1u);
  EXPECT_EQ(t.stats().fragments, 4u) << "a two-piece split adds one fragment";
  const auto pieces = fragments_of_source(t, 2);
  ASSERT_EQ(pieces.size(), 2u);
  // Pieces (z, a, X) and (z, X, b): both start with the on-plane vertex z and have exactly
  // two vertices (z and X) on the plane z = 0.
  for (std::size_t i : pieces) {
    EXPECT_EQ(t.fragments()[i].v[0], EP(0.5, 0.25, 0));
    int on_plane = 0;
    for (const EP& p : t.fragments()[i].v) on_plane += p.z() == 0 ? 1 : 0;
    EXPECT_EQ(on_plane, 2);
  }
  expect_every_invariant(c, {{0.5, 0.25, 0}, {0.5, 0.25, 7}, {3, 3, 0}}, {{1, 0, 0}, {0, 0, -1}});
}

TEST(CoplanarStack, crossers_touching_the_plane_with_a_vertex_or_an_edge_are_not_split) {
  const soup_case c =
      case_of("stack + touching", {stack_a,
                                   flipped(stack_a),
                                   {{{0, 0, 0}, {1, 3, 1}, {-1, 3, 2}}},     // vertex on the plane
                                   {{{-1, 0, 0}, {1, 0, 0}, {0, 1, -2}}}});  // edge in the plane
  const auto t = build_naive(c.soup());
  EXPECT_EQ(t.stats().splits, 0u);
  EXPECT_EQ(t.stats().nodes, 3u);
  expect_every_invariant(c, {{0, 0, 0}, {0, 0.5, 0}, {0, 0, 1}});
}

TEST(CoplanarStack, a_crosser_as_splitter_cuts_every_stack_triangle_in_both_orientations) {
  const tri_d crosser{{{0, -3, -1}, {0, 3, -1}, {0, 0, 2}}};  // the plane x = 0
  const soup_case c = case_of(
      "crosser first",
      {crosser, stack_a, flipped(stack_a), {{{-1, -1, 0}, {1, -1, 0}, {0, 0, 0}}}, stack_a});
  const auto t = build_naive(c.soup());
  // Every stack triangle has a vertex on x = 0 and the other two on either side: two pieces each.
  EXPECT_EQ(t.stats().splits, 4u);
  EXPECT_EQ(t.stats().fragments, 9u);
  expect_every_invariant(c, {{0, 0, 0}, {0, 1, 5}, {1, 0, 0}});
}

RC_GTEST_PROP(CoplanarStack, random_stacks_with_crossers_satisfy_every_invariant, ()) {
  rc_assert_invariants_for_every_heuristic<EK>(*coplanar_stack());
}

// --- Vertices exactly on other triangles' planes ----------------------------------------------

TEST(VertexOnPlane, a_vertex_on_three_node_planes_and_eyes_at_their_common_point) {
  // Triangles in x = 0, y = 0 and z = 0, all crossing each other, and triangles with a vertex
  // at the origin (on all three planes) or on their lines of intersection.
  const soup_case c = case_of("corner", {{{{0, -2, -2}, {0, 3, -1}, {0, -1, 3}}},
                                         {{{-2, 0, -2}, {-1, 0, 3}, {3, 0, -1}}},
                                         {{{-2, -2, 0}, {3, -1, 0}, {-1, 3, 0}}},
                                         {{{0, 0, 0}, {1, -1, 1}, {-1, 1, 1}}},
                                         {{{0, 0, 0}, {1, 1, -1}, {-1, -1, -1}}},
                                         {{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}},
                                         {{{0, 0, 2}, {1, 0, -1}, {-1, 0, -1}}}});
  expect_every_invariant(c, {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0.5, 0.5}},
                         {{1, 1, 0}, {0, 0, 1}});
}

RC_GTEST_PROP(VertexOnPlane, vertices_on_one_two_and_three_planes_satisfy_every_invariant, ()) {
  rc_assert_invariants_for_every_heuristic<EK>(*vertex_on_plane());
}

// --- Near-coplanar ----------------------------------------------------------------------------

TEST(NearCoplanar, vertices_one_ulp_above_and_below_z_equals_0_1_are_classified_exactly) {
  const double h = 0.1, up = std::nextafter(h, 1.0), down = std::nextafter(h, 0.0);
  const soup_case c = case_of(
      "ulp", {{{{-1, -1, h}, {1, -1, h}, {0, 1, h}}},
              {{{-0.5, -0.5, up}, {0.5, -0.5, down}, {0, 0.5, h}}},  // straddles, vertex on plane
              {{{-0.5, 0.5, up}, {0.5, 0.5, up}, {0, -0.5, up}}},    // entirely 1 ulp above
              {{{-0.7, 0.1, down}, {0.6, 0.2, up}, {0.1, 0.9, down}}}});  // straddles, 3 pieces
  const auto t = build_naive(c.soup());
  // The root (the exact triangle, naive) keeps only itself: nothing one ulp off is coplanar.
  EXPECT_EQ(t.nodes()[0].count, 1u);
  EXPECT_GE(t.stats().splits, 2u);
  // Both straddlers are cut at the root: each has pieces with a vertex exactly on z = 0.1;
  // the one-ulp-above triangle is never cut by the root plane.
  for (std::uint32_t s : {1u, 3u}) {
    bool on_plane = false;
    for (std::size_t i : fragments_of_source(t, s))
      for (const EP& p : t.fragments()[i].v) on_plane |= p.z() == h;
    EXPECT_TRUE(on_plane) << "source " << s;
  }
  for (std::size_t i : fragments_of_source(t, 2))
    for (const EP& p : t.fragments()[i].v) EXPECT_GT(p.z(), h);
  expect_every_invariant(c, {{0, 0, h}, {0, 0, up}, {0.3, 0.3, down}}, {{1, 0, 0}});
}

TEST(NearCoplanar, subnormal_offsets_from_z_equals_0_are_split_exactly) {
  const double tiny = std::nextafter(0.0, 1.0);  // 4.9e-324
  const soup_case c =
      case_of("subnormal", {{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}},
                            {{{-0.5, -0.5, tiny}, {0.5, -0.5, -tiny}, {0, 0.5, tiny}}},
                            {{{-0.5, 0.5, tiny}, {0.5, 0.5, tiny}, {0, -0.5, 0}}}});
  const auto t = build_naive(c.soup());
  EXPECT_EQ(t.nodes()[0].count, 1u);
  EXPECT_GE(t.stats().splits, 1u);
  bool on_plane = false;  // the root cuts triangle 1 exactly at z = 0
  for (std::size_t i : fragments_of_source(t, 1))
    for (const EP& p : t.fragments()[i].v) on_plane |= p.z() == 0;
  EXPECT_TRUE(on_plane);
  for (std::size_t i : fragments_of_source(t, 2))
    for (const EP& p : t.fragments()[i].v)
      EXPECT_GE(p.z(), 0) << "triangle 2 touches z = 0 and is not cut by it";
  expect_every_invariant(c, {{0, 0, 0}, {0, 0, tiny}, {0.1, 0.1, -tiny}});
}

TEST(NearCoplanar, one_ulp_off_the_sloped_plane_y_equals_x) {
  auto on = [](double x, double z, int ulps) { return vec3d{x, ulps_from(x, ulps), z}; };
  const soup_case c =
      case_of("sloped ulp", {{{on(-1, -1, 0), on(1, -1, 0), on(0.3, 1, 0)}},
                             {{on(0.1, 0.2, 1), on(0.7, -0.3, -1), on(-0.6, 0.4, 1)}},
                             {{on(0.2, 0.1, 1), on(0.6, 0.5, 1), on(-0.3, -0.2, 1)}},
                             {{on(0.25, 0.3, 0), on(0.8, -0.3, 0), on(-0.5, 0.6, 0)}}});
  expect_every_invariant(c, {on(0.5, 0, 0), on(0.5, 0, 1)}, {{1, 1, 0}, {1, -1, 0}});
}

RC_GTEST_PROP(NearCoplanar, one_ulp_and_subnormal_offsets_satisfy_every_invariant, ()) {
  rc_assert_invariants_for_every_heuristic<EK>(*near_coplanar(), 64, budget(4));
}

// --- Scale disparity --------------------------------------------------------------------------

TEST(ScaleDisparity, coordinates_near_1e9_with_millimetre_features_crossing_a_huge_triangle) {
  const double X = 1234567890.125, Y = -987654321.5, Z = 555555555.25;
  const soup_case c = case_of(
      "1e9", {{{{X - 1e9, Y - 1e9, Z}, {X + 1e9, Y, Z}, {X, Y + 1e9, Z}}},
              {{{X, Y, Z - 1e-3}, {X + 2e-3, Y, Z + 1e-3}, {X, Y + 2e-3, Z + 1e-3}}},
              {{{X + 1e-3, Y, Z}, {X + 1e-3, Y + 3e-3, Z - 2e-3}, {X + 1e-3, Y - 1e-3, Z + 2e-3}}},
              {{{X - 1e9, Y, Z - 1e9}, {X + 1e9, Y + 1e-3, Z + 1e9}, {X, Y + 1e9, Z}}}});
  const auto t = build_naive(c.soup());
  EXPECT_GE(t.stats().splits, 2u);
  expect_every_invariant(c, {{X, Y, Z}, {X + 1e-3, Y, Z + 1}}, {{0, 0, -1}});
}

TEST(ScaleDisparity, coordinates_near_1e_minus_300_whose_products_underflow_in_double) {
  const double s = 1e-300;
  const soup_case c =
      case_of("1e-300",
              {{{{-s, -s, 0}, {s, -s, 0}, {0, s, 0}}},
               {{{-s, 0, -s}, {s, 0, -s}, {0, 0.5 * s, s}}},
               {{{0.3 * s, -s, -0.2 * s}, {0.1 * s, s, 0.7 * s}, {-0.9 * s, 0.2 * s, -0.4 * s}}}});
  const auto t = build_naive(c.soup());
  EXPECT_GE(t.stats().splits, 2u) << "the tiny triangles really cross each other";
  expect_every_invariant(c, {{0, 0, 0}, {s, s, s}}, {{0, 0, 1}});
}

TEST(ScaleDisparity, unit_triangles_crossed_by_1e_minus_300_triangles) {
  const double s = 1e-300;
  const soup_case c = case_of("mixed", {{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}},
                                        {{{-s, -s, -s}, {s, -s, s}, {0, s, s}}},
                                        {{{0, 0, -s}, {s, 0, s}, {0, s, 0}}},
                                        {{{-0.5, 0.25, -1}, {0.5, 0.25, 1}, {0, 0.25, 1}}}});
  expect_every_invariant(c, {{0, 0, 0}, {0, 0, s}, {0, 0, 1}}, {{0, 0, -1}, {1, 0, 0}});
}

RC_GTEST_PROP(ScaleDisparity, huge_and_tiny_coordinates_satisfy_every_invariant, ()) {
  // Near 1e-300 no interval filter helps (products underflow): every predicate is exact, so
  // fewer viewpoints and rays than elsewhere.
  rc_assert_invariants_for_every_heuristic<EK>(*scale_disparity(), 40, budget(3));
}

/// The soup transformed by an exact similarity: coordinates cyclically permuted and multiplied
/// by +-2^k with an even number of sign changes (determinant > 0), so every orientation keeps
/// its sign and every split point is transformed exactly.
soup_case exactly_transformed(const soup_case& c, int k, int shift, bool flip_two) {
  soup_case out = c;
  out.kind += " x2^" + std::to_string(k);
  for (tri_d& t : out.tris)
    for (vec3d& p : t) {
      const vec3d q = p;
      for (std::size_t a = 0; a < 3; ++a) {
        double x = std::ldexp(q[(a + static_cast<std::size_t>(shift)) % 3], k);
        if (flip_two && a < 2) x = -x;
        p[a] = x;
      }
    }
  return out;
}

bool transform_is_exact(const soup_case& c, int k) {
  for (const tri_d& t : c.tris)
    for (const vec3d& p : t)
      for (double x : p)
        if (!std::isfinite(std::ldexp(x, k)) || std::ldexp(std::ldexp(x, k), -k) != x) return false;
  return true;
}

RC_GTEST_PROP(ScaleDisparity,
              exact_similarities_down_to_1e_minus_300_and_up_to_1e150_give_the_same_tree, ()) {
  const soup_case c = *any_small_soup();
  int k = *rc::gen::element(-1000, -700, -40, 30, 500);
  if (!transform_is_exact(c, k)) k = 0;
  const int shift = *rc::gen::inRange(0, 3);
  const bool flip = *rc::gen::arbitrary<bool>();
  const soup_case d = exactly_transformed(c, k, shift, flip);
  const exbsp::triangle_soup sa = c.soup(), sb = d.soup();
  auto map_point = [&](const EP& p) {
    const EK::FT s = k >= 0 ? EK::FT(std::ldexp(1.0, k)) : EK::FT(1) / EK::FT(std::ldexp(1.0, -k));
    const EK::FT q[3] = {p.x() * s, p.y() * s, p.z() * s};
    EK::FT r[3];
    for (std::size_t a = 0; a < 3; ++a)
      r[a] = flip && a < 2 ? -q[(a + static_cast<std::size_t>(shift)) % 3]
                           : q[(a + static_cast<std::size_t>(shift)) % 3];
    return EP(r[0], r[1], r[2]);
  };
  for (const std::string& h : exbsp::heuristic_names()) {
    exbsp::build_options o;
    o.heuristic = h;
    o.seed = 99;
    const exbsp::bsp_tree<EK> ta(sa, o), tb(sb, o);
    RC_ASSERT(ta.stats().splits == tb.stats().splits);
    RC_ASSERT(ta.stats().depth == tb.stats().depth);
    RC_ASSERT(ta.nodes().size() == tb.nodes().size());
    RC_ASSERT(ta.fragments().size() == tb.fragments().size());
    for (std::size_t i = 0; i < ta.nodes().size(); ++i) {
      RC_ASSERT(ta.nodes()[i].plane_source == tb.nodes()[i].plane_source);
      RC_ASSERT(ta.nodes()[i].negative == tb.nodes()[i].negative);
      RC_ASSERT(ta.nodes()[i].count == tb.nodes()[i].count);
    }
    for (std::size_t i = 0; i < ta.fragments().size(); ++i)
      for (std::size_t v = 0; v < 3; ++v)
        RC_ASSERT(map_point(ta.fragments()[i].v[v]) == tb.fragments()[i].v[v]);
    const EP eye(0.375, -1.25, 2.5);
    RC_ASSERT(ta.order_from_eye(eye) == tb.order_from_eye(map_point(eye)));
  }
}

// --- Slivers ----------------------------------------------------------------------------------

TEST(Slivers, needles_and_caps_with_angles_near_0_and_180_degrees_crossing_planes) {
  std::vector<tri_d> tris{{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}}};
  for (int e = 3; e <= 15; e += 3) {
    const double eps = std::pow(10.0, -e);
    tris.push_back({{{-0.5, 0.1 * e - 0.8, -1},
                     {0.5, 0.1 * e - 0.8, 1},
                     {0.5, 0.1 * e - 0.8 + eps, 1}}});  // needle
    tris.push_back(
        {{{0.1 * e - 0.8, -1, -1}, {0.1 * e - 0.8, 1, 1}, {0.1 * e - 0.8 + eps, 0, 0}}});  // cap
  }
  tris.push_back(
      {{{0.3, 0.2, -1}, {0.3, 0.2, 1}, {0.3 + 1e-15, 0.2, 0}}});  // a needle pierced at its middle
  const soup_case c = case_of("needles and caps", tris);
  const auto t = build_naive(c.soup());
  EXPECT_EQ(t.stats().degenerate_input, 0u);
  EXPECT_GE(t.stats().splits, 10u);
  expect_every_invariant(c, {{0, 0, 0}, {0.3, 0.2, 0}}, {{0, 0, 1}, {1e-15, 1, 0}});
}

RC_GTEST_PROP(Slivers, random_needles_and_caps_satisfy_every_invariant, ()) {
  rc_assert_invariants_for_every_heuristic<EK>(*slivers(), 80, budget(4));
}

// --- Shared edges, T-junctions, duplicates, both orientations --------------------------------

TEST(MeshLike, shared_edges_t_junction_duplicate_and_reversed_copy_share_their_nodes) {
  // Two squares sharing an edge; the right one's left edge has a T-junction at (1, 0.5, 0);
  // a duplicate of triangle 0, a reversed copy of triangle 1, and a crosser through everything.
  const soup_case c = case_of("mesh", {{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}},
                                       {{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}},
                                       {{{1, 0, 0}, {2, 0, 0}, {1, 0.5, 0}}},
                                       {{{1, 0.5, 0}, {2, 0, 0}, {2, 1, 0}}},
                                       {{{1, 0.5, 0}, {2, 1, 0}, {1, 1, 0}}},
                                       {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}},
                                       {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}}},
                                       {{{1, -1, -1}, {1, 2, -1}, {1, 0.5, 1}}},
                                       {{{0.5, -1, 1}, {1.5, 2, 1}, {1, 0.5, -1}}}});
  for (const std::string& h : exbsp::heuristic_names()) {
    exbsp::build_options o;
    o.heuristic = h;
    const exbsp::triangle_soup soup = c.soup();
    const exbsp::bsp_tree<EK> t(soup, o);
    // A duplicate is cut exactly like its original: same pieces at the same nodes.
    const auto a = fragments_of_source(t, 0), b = fragments_of_source(t, 5);
    ASSERT_EQ(a.size(), b.size()) << h;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(t.node_of_fragment(a[k]), t.node_of_fragment(b[k])) << h;
      EXPECT_EQ(t.fragments()[a[k]].v, t.fragments()[b[k]].v) << h;
    }
    // A reversed copy may be triangulated differently, but lies at the same nodes.
    std::set<std::size_t> na, nb;
    for (std::size_t i : fragments_of_source(t, 1)) na.insert(t.node_of_fragment(i));
    for (std::size_t i : fragments_of_source(t, 6)) nb.insert(t.node_of_fragment(i));
    EXPECT_EQ(na, nb) << h;
  }
  expect_every_invariant(c, {{1, 0.5, 0}, {1, 0.5, 3}, {1, 1, 0}}, {{0, 0, -1}, {0, 1, 0}});
}

RC_GTEST_PROP(MeshLike,
              height_fields_with_t_junctions_duplicates_and_reversed_copies_satisfy_every_invariant,
              ()) {
  rc_assert_invariants_for_every_heuristic<EK>(*mesh_like());
}

TEST(DegenerateInput,
     collinear_and_point_triangles_inside_a_coplanar_stack_are_skipped_and_counted) {
  const soup_case c = case_of("collinear in stack",
                              {stack_a,
                               {{{-2, -2, 0}, {0, 0, 0}, {2, 2, 0}}},  // collinear, in the plane
                               {{{0, 0, -1}, {0, 0, 0}, {0, 0, 1}}},   // collinear, crossing it
                               {{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}},    // a point
                               {{{0, -1, -1}, {0, 1, 1}, {0, 1, -1}}}});
  const auto t = build_naive(c.soup());
  EXPECT_EQ(t.stats().degenerate_input, 3u);
  EXPECT_EQ(t.stats().input_triangles, 5u);
  expect_every_invariant(c, {{0, 0, 0}, {1, 1, 1}});
}

// --- Cyclic overlaps --------------------------------------------------------------------------

using P2 = EK::Point_2;

/// The part of convex polygon `poly` on the closed left of the directed line (a, b). Exact.
std::vector<P2> clip_left(const std::vector<P2>& poly, const P2& a, const P2& b) {
  std::vector<P2> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P2& p = poly[i];
    const P2& q = poly[(i + 1) % poly.size()];
    const int sp = CGAL::orientation(a, b, p), sq = CGAL::orientation(a, b, q);
    if (sp >= 0) out.push_back(p);
    if (sp * sq < 0) {
      const EK::FT fp = CGAL::area(a, b, p), fq = CGAL::area(a, b, q);
      out.push_back(p + (q - p) * (fp / (fp - fq)));
    }
  }
  return out;
}

/// z of the plane of t above (x, y). Precondition: t is not vertical.
EK::FT height_at(const std::array<EP, 3>& t, const P2& p) {
  const auto n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
  return t[0].z() - (n.x() * (p.x() - t[0].x()) + n.y() * (p.y() - t[0].y())) / n.z();
}

/// True when a is strictly above b somewhere, seen along -z: the projections of a and b
/// overlap in a region of positive area and z_a - z_b (linear there) is positive at one of its
/// vertices, hence on an open part of it. Exact and complete.
bool over_somewhere(const tri_d& a, const tri_d& b) {
  const std::array<EP, 3> A{exact_point<EK>(a[0]), exact_point<EK>(a[1]), exact_point<EK>(a[2])};
  const std::array<EP, 3> B{exact_point<EK>(b[0]), exact_point<EK>(b[1]), exact_point<EK>(b[2])};
  auto flat = [](const EP& p) { return P2(p.x(), p.y()); };
  std::vector<P2> pa{flat(A[0]), flat(A[1]), flat(A[2])}, pb{flat(B[0]), flat(B[1]), flat(B[2])};
  if (CGAL::orientation(pa[0], pa[1], pa[2]) == CGAL::COLLINEAR ||
      CGAL::orientation(pb[0], pb[1], pb[2]) == CGAL::COLLINEAR)
    return false;  // vertical: no area seen from above
  if (CGAL::orientation(pa[0], pa[1], pa[2]) == CGAL::CLOCKWISE) std::swap(pa[1], pa[2]);
  std::vector<P2> overlap = pb;
  for (std::size_t e = 0; e < 3 && !overlap.empty(); ++e)
    overlap = clip_left(overlap, pa[e], pa[(e + 1) % 3]);
  if (overlap.size() < 3) return false;
  EK::FT area2 = 0;
  for (std::size_t i = 0; i < overlap.size(); ++i) {
    const P2& p = overlap[i];
    const P2& q = overlap[(i + 1) % overlap.size()];
    area2 += p.x() * q.y() - q.x() * p.y();
  }
  if (area2 == 0) return false;
  for (const P2& p : overlap)
    if (height_at(A, p) > height_at(B, p)) return true;
  return false;
}

/// True when the "over somewhere" relation of the triangles has a cycle: no order of whole
/// triangles draws them correctly from above.
bool has_depth_cycle(const std::vector<tri_d>& tris) {
  const std::size_t n = tris.size();
  std::vector<std::vector<std::size_t>> over(n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      if (a != b && over_somewhere(tris[a], tris[b])) over[a].push_back(b);
  std::vector<int> colour(n, 0);
  std::function<bool(std::size_t)> dfs = [&](std::size_t a) {
    colour[a] = 1;
    for (std::size_t b : over[a])
      if (colour[b] == 1 || (colour[b] == 0 && dfs(b))) return true;
    colour[a] = 2;
    return false;
  };
  for (std::size_t a = 0; a < n; ++a)
    if (colour[a] == 0 && dfs(a)) return true;
  return false;
}

TEST(CyclicOverlap, regular_pinwheels_of_3_to_8_sticks_are_true_depth_cycles_and_get_split) {
  for (int n = 3; n <= 8; ++n) {
    std::vector<tri_d> tris;
    for (int k = 0; k < n; ++k) {
      const double phi = 6.283185307179586 * k / n;
      const vec3d radial{std::cos(phi), std::sin(phi), 0}, along{-std::sin(phi), std::cos(phi), 0};
      const vec3d tail = add(radial, scale(-5, along)), tip = add(radial, scale(5, along));
      tris.push_back({add(tail, scale(0.25, radial)), sub(tail, scale(0.25, radial)),
                      vec3d{tip[0], tip[1], 5}});
    }
    ASSERT_TRUE(has_depth_cycle(tris)) << n << " sticks";
    const soup_case c = case_of("pinwheel " + std::to_string(n), tris);
    const auto t = build_naive(c.soup());
    EXPECT_GE(t.stats().splits, 1u) << n;
    expect_every_invariant(c, {{0, 0, 100}, {0, 0, 2.5}, {0.1, -0.2, 1}},
                           {{0, 0, -1}, {0.05, 0.1, -1}}, 64, n <= 4);
  }
}

RC_GTEST_PROP(CyclicOverlap,
              random_pinwheels_of_3_to_8_sticks_are_drawn_correctly_from_above_and_everywhere, ()) {
  const soup_case c = *cyclic_sticks(3, 8);
  const bool cyclic = has_depth_cycle(c.tris);
  RC_CLASSIFY(cyclic, "true depth cycle");
  check_options o = budget(3);
  o.eyes = {{0, 0, 100}, {0, 0, 3}};
  o.directions = {{0, 0, -1}};
  rc_assert_invariants_for_every_heuristic<EK>(c, 64, o);
  if (cyclic) {
    // No order of whole triangles works from above, so every heuristic must have split.
    for (const std::string& h : exbsp::heuristic_names()) {
      exbsp::build_options b;
      b.heuristic = h;
      RC_ASSERT(exbsp::bsp_tree<EK>(c.soup(), b).stats().splits >= 1u);
    }
  }
}

// --- Eyes exactly at every split point and on every node plane --------------------------------

TEST(Eyes, exactly_at_every_fragment_vertex_and_on_every_node_plane_of_a_split_scene) {
  const soup_case c = case_of("split scene", {stack_a,
                                              {{{0.5, 0.25, 0}, {-1, 3, 1}, {2, 3, -1}}},
                                              {{{0, -3, -1}, {0, 3, -1}, {0, 0, 2}}},
                                              {{{-2, 0, -2}, {2, 0.5, -2}, {0, 0.25, 2}}}});
  const exbsp::triangle_soup soup = c.soup();
  for (const std::string& h : exbsp::heuristic_names()) {
    exbsp::build_options o;
    o.heuristic = h;
    const exbsp::bsp_tree<EK> t(soup, o);
    const auto v = view_of<EK>(t, soup);
    check_report r;
    std::vector<viewpoint<EK>> eyes;
    for (const auto& f : v.fragments)
      for (const EP& p : f) eyes.push_back({true, p, {}, "eye at a fragment vertex"});
    for (const auto& nd : v.nodes) {
      const auto& p = v.sources[nd.plane_source];
      eyes.push_back({true,
                      p[0] + (p[1] - p[0]) * EK::FT(3) - (p[2] - p[0]) * EK::FT(2),
                      {},
                      "eye on a node plane"});
      eyes.push_back({false, CGAL::ORIGIN, p[2] - p[1], "direction parallel to a node plane"});
    }
    for (const auto& vp : eyes) check_orders(t, v, vp, 64, r);
    EXPECT_TRUE(r.ok()) << h << ": " << r.text();
  }
}

}  // namespace
