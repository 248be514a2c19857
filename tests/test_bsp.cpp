// SPDX-License-Identifier: LGPL-3.0-or-later
// Unit tests of the exact BSP: classification, every split case, coplanar handling,
// traversal rules, the painter's failure case, depth and limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <numeric>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include "bsp/bsp_tree.h"
#include "bsp/geometry_cgal.h"
#include "bsp/kernel_epeck.h"
#include "bsp/kernel_gmpq.h"
#include "support/test_helpers.h"

namespace {

using K = exbsp::epeck_kernel;
using P = K::Point_3;
using tri = std::array<P, 3>;
using exbsp::vec3d;

bool same_oriented_plane(const tri& piece, const tri& parent) {
  const auto n1 = CGAL::cross_product(piece[1] - piece[0], piece[2] - piece[0]);
  const auto n2 = CGAL::cross_product(parent[1] - parent[0], parent[2] - parent[0]);
  return CGAL::cross_product(n1, n2) == CGAL::NULL_VECTOR && n1 * n2 > 0 &&
         CGAL::coplanar(parent[0], parent[1], parent[2], piece[0]) &&
         CGAL::coplanar(parent[0], parent[1], parent[2], piece[1]) &&
         CGAL::coplanar(parent[0], parent[1], parent[2], piece[2]);
}

K::FT doubled_area_along(const tri& t, const K::Vector_3& n) {
  return CGAL::cross_product(t[1] - t[0], t[2] - t[0]) * n;
}

std::array<int, 3> signs(const tri& plane, const tri& t) {
  std::array<int, 3> s;
  for (int k = 0; k < 3; ++k) s[k] = CGAL::orientation(plane[0], plane[1], plane[2], t[k]);
  return s;
}

const tri plane_z0{P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)};  // normal +z

TEST(Classify, signs_to_classes) {
  using exbsp::geom::classification;
  EXPECT_EQ(exbsp::geom::classify_signs({0, 0, 0}), classification::coplanar);
  EXPECT_EQ(exbsp::geom::classify_signs({1, 0, 0}), classification::positive);
  EXPECT_EQ(exbsp::geom::classify_signs({1, 1, 1}), classification::positive);
  EXPECT_EQ(exbsp::geom::classify_signs({-1, 0, -1}), classification::negative);
  EXPECT_EQ(exbsp::geom::classify_signs({1, 0, -1}), classification::straddling);
  EXPECT_EQ(exbsp::geom::classify_signs({1, -1, -1}), classification::straddling);
}

// Each of the three cyclic positions of the lone vertex c, on each side.
TEST(Split, lone_vertex_each_relabelling_keeps_order_and_orientation) {
  for (int lone = 0; lone < 3; ++lone) {
    for (int side : {+1, -1}) {
      tri t;
      // lone vertex at z = 2*side, the other two at z = -side.
      const P base[3] = {P(0, 0, 0), P(4, 0, 0), P(0, 4, 0)};
      for (int k = 0; k < 3; ++k) {
        const double z = k == lone ? 2.0 * side : -1.0 * side;
        t[k] = P(base[k].x(), base[k].y(), z);
      }
      const auto s = signs(plane_z0, t);
      const auto pieces = exbsp::split_triangle<K>(plane_z0, t, s);
      ASSERT_EQ(pieces.count, 3);
      const P& c = t[lone];
      const P& a = t[(lone + 1) % 3];
      const P& b = t[(lone + 2) % 3];
      // A on [c,a] with z = 0, B on [b,c] with z = 0.
      const P A = pieces.piece[0][2];
      const P B = pieces.piece[1][1];
      EXPECT_EQ(A.z(), 0);
      EXPECT_EQ(B.z(), 0);
      EXPECT_TRUE(CGAL::collinear(c, a, A) && CGAL::collinear(b, c, B));
      EXPECT_EQ(pieces.piece[0], (tri{a, b, A}));
      EXPECT_EQ(pieces.piece[1], (tri{b, B, A}));
      EXPECT_EQ(pieces.piece[2], (tri{A, B, c}));
      EXPECT_EQ(pieces.side[0], -side);
      EXPECT_EQ(pieces.side[1], -side);
      EXPECT_EQ(pieces.side[2], side);
      const auto n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
      K::FT sum = 0;
      for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(same_oriented_plane(pieces.piece[i], t)) << "piece " << i;
        sum += doubled_area_along(pieces.piece[i], n);
      }
      EXPECT_EQ(sum, doubled_area_along(t, n)) << "pieces tile the triangle exactly";
    }
  }
}

TEST(Split, one_vertex_on_plane_each_relabelling) {
  for (int z = 0; z < 3; ++z) {
    tri t;
    const P base[3] = {P(0, 0, 0), P(3, 0, 0), P(0, 3, 0)};
    // vertex z on the plane, the next one above, the last one below.
    for (int k = 0; k < 3; ++k) {
      const double h = k == z ? 0.0 : k == (z + 1) % 3 ? 1.0 : -3.0;
      t[k] = P(base[k].x(), base[k].y(), h);
    }
    const auto pieces = exbsp::split_triangle<K>(plane_z0, t, signs(plane_z0, t));
    ASSERT_EQ(pieces.count, 2);
    const P& zv = t[z];
    const P& a = t[(z + 1) % 3];
    const P& b = t[(z + 2) % 3];
    const P X = pieces.piece[0][2];
    EXPECT_EQ(X.z(), 0);
    EXPECT_TRUE(CGAL::collinear(a, b, X));
    EXPECT_EQ(pieces.piece[0], (tri{zv, a, X}));
    EXPECT_EQ(pieces.piece[1], (tri{zv, X, b}));
    EXPECT_EQ(pieces.side[0], +1);
    EXPECT_EQ(pieces.side[1], -1);
    for (int i = 0; i < 2; ++i) EXPECT_TRUE(same_oriented_plane(pieces.piece[i], t));
  }
}

TEST(Split, non_straddling_input_is_rejected_not_aborted) {
  const tri t{P(0, 0, 1), P(1, 0, 1), P(0, 1, 1)};
  EXPECT_THROW(exbsp::split_triangle<K>(plane_z0, t, signs(plane_z0, t)), exbsp::usage_error);
}

TEST(Split, exact_intersection_of_inexact_decimals) {
  // 0.1 and 0.3 are not representable; the split point must still be exactly on the plane.
  const tri plane{P(0.1, 0, 0), P(0.1, 1, 0), P(0.1, 0, 1)};  // x = 0.1 plane
  const tri t{P(0, 0.3, 0.7), P(0.3, 0.1, 0.2), P(0.2, 0.9, 0.1)};
  const auto pieces = exbsp::split_triangle<K>(plane, t, signs(plane, t));
  for (int i = 0; i < pieces.count; ++i)
    for (const P& v : pieces.piece[i]) {
      EXPECT_GE(CGAL::orientation(plane[0], plane[1], plane[2], v) * pieces.side[i], 0);
    }
}

using exbsp_test::soup_of;

TEST(Tree, coplanar_both_orientations_stay_at_the_node) {
  const auto soup = soup_of({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                             {{{5, 5, 0}, {4, 6, 0}, {6, 6, 0}}},    // same plane, flipped
                             {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}},    // same triangle, flipped
                             {{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}}});  // parallel, above
  exbsp::build_options o;
  o.heuristic = "naive";
  const exbsp::bsp tree = exbsp::bsp::build(soup, o);
  EXPECT_EQ(tree.stats().nodes, 2u);
  EXPECT_EQ(tree.stats().splits, 0u);
  EXPECT_EQ(tree.stats().depth, 2u);
  // Root list keeps list order: faces 0, 1, 2.
  EXPECT_EQ(tree.fragment(0).face, 0u);
  EXPECT_EQ(tree.fragment(1).face, 1u);
  EXPECT_EQ(tree.fragment(2).face, 2u);
  // Eye above: negative side (root list) drawn first, then the face above.
  const auto order = tree.order_from_eye({0.2, 0.2, 5});
  EXPECT_EQ(order, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  const auto below = tree.order_from_eye({0.2, 0.2, -5});
  EXPECT_EQ(below, (std::vector<std::uint32_t>{3, 0, 1, 2}));
  // Eye exactly on the root plane: s = 0 -> negative, node list, positive.
  EXPECT_EQ(tree.order_from_eye({7, 7, 0}), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  // Front to back is the exact reverse.
  auto f2b = tree.order_from_eye({0.2, 0.2, 5}, false);
  std::reverse(f2b.begin(), f2b.end());
  EXPECT_EQ(f2b, order);
  // Parallel: looking down -z, the eye is above.
  EXPECT_EQ(tree.order_for_direction({0, 0, -1}), order);
  EXPECT_EQ(tree.order_for_direction({0, 0, 1}), below);
}

TEST(Tree, degenerate_triangles_are_skipped_and_counted) {
  auto soup = soup_of({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                       {{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}},    // collinear
                       {{{3, 3, 3}, {3, 3, 3}, {3, 3, 3}}}});  // a point
  const exbsp::bsp tree = exbsp::bsp::build(soup, {});
  EXPECT_EQ(tree.stats().input_triangles, 3u);
  EXPECT_EQ(tree.stats().degenerate_input, 2u);
  EXPECT_EQ(tree.stats().fragments, 1u);
}

TEST(Tree, empty_and_all_degenerate_input_give_an_empty_tree) {
  exbsp::triangle_soup soup;
  const exbsp::bsp tree = exbsp::bsp::build(soup, {});
  EXPECT_EQ(tree.stats().nodes, 0u);
  EXPECT_EQ(tree.stats().depth, 0u);
  EXPECT_TRUE(tree.order_from_eye({0, 0, 0}).empty());
}

TEST(Tree, non_finite_input_is_an_error) {
  exbsp::triangle_soup soup;
  soup.add_triangle({0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0});
  EXPECT_THROW(exbsp::bsp::build(soup, {}), exbsp::usage_error);
}

TEST(Tree, unknown_heuristic_is_an_error) {
  exbsp::build_options o;
  o.heuristic = "best";
  EXPECT_THROW(exbsp::bsp::build(soup_of({}), o), exbsp::usage_error);
}

// The painter's failure case: three long triangles in cyclic overlap seen from above
// (A over B over C over A). No depth sort of whole triangles can draw them; the BSP splits.
std::vector<std::array<vec3d, 3>> cyclic_triple() {
  // Each "stick" is a thin triangle spanning x in [-1, 3] in its own direction, tilted so it
  // is above the next one where they cross and below the previous one.
  std::vector<std::array<vec3d, 3>> tris;
  for (int i = 0; i < 3; ++i) {
    const double ang = i * 2.0943951023931957;  // 120 degrees
    const double cx = std::cos(ang), cy = std::sin(ang);
    const double px = -cy, py = cx;  // perpendicular
    const vec3d tail{-3 * cx + 0.3 * px, -3 * cy + 0.3 * py, 0.0};
    const vec3d tail2{-3 * cx - 0.3 * px, -3 * cy - 0.3 * py, 0.0};
    const vec3d tip{3 * cx, 3 * cy, 1.0};
    tris.push_back({tail, tail2, tip});
  }
  return tris;
}

TEST(Painter, cyclic_overlap_has_no_depth_order_but_bsp_splits_it) {
  const auto tris = cyclic_triple();
  const auto soup = soup_of(tris);
  // Pairwise "over" relation along the view direction -z (eye above at z = +100).
  // A point of the xy plane covered by both triangles: whose z is larger there?
  auto z_at = [](const std::array<vec3d, 3>& t, double x, double y, double& z) {
    const double x1 = t[1][0] - t[0][0], y1 = t[1][1] - t[0][1];
    const double x2 = t[2][0] - t[0][0], y2 = t[2][1] - t[0][1];
    const double det = x1 * y2 - x2 * y1;
    const double u = ((x - t[0][0]) * y2 - x2 * (y - t[0][1])) / det;
    const double v = (x1 * (y - t[0][1]) - (x - t[0][0]) * y1) / det;
    if (u < 0 || v < 0 || u + v > 1) return false;
    z = t[0][2] + u * (t[1][2] - t[0][2]) + v * (t[2][2] - t[0][2]);
    return true;
  };
  // above[i][j]: somewhere i is above j. A cycle means no order of whole triangles works.
  bool above[3][3] = {};
  for (double x = -3; x <= 3; x += 0.01)
    for (double y = -3; y <= 3; y += 0.01)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double zi, zj;
          if (i != j && z_at(tris[i], x, y, zi) && z_at(tris[j], x, y, zj) && zi > zj)
            above[i][j] = true;
        }
  // Every permutation draws some pair in the wrong order.
  std::array<int, 3> perm{0, 1, 2};
  bool some_order_works = false;
  do {
    bool ok = true;
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b)
        if (above[perm[a]][perm[b]]) ok = false;  // drawn first but is above somewhere
    some_order_works |= ok;
  } while (std::next_permutation(perm.begin(), perm.end()));
  ASSERT_FALSE(some_order_works) << "the test scene must be a true cycle";

  exbsp::build_options o;
  o.heuristic = "naive";
  const exbsp::bsp tree = exbsp::bsp::build(soup, o);
  EXPECT_GE(tree.stats().splits, 1u);
  // The BSP order for the eye above never draws a fragment before one it is above.
  const auto frags = tree.fragments_double();
  const auto order = tree.order_from_eye({0, 0, 100});
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const auto& fa = frags[order[a]].v;
      const auto& fb = frags[order[b]].v;
      // sample points of the later fragment b; where a covers them too, a must be lower.
      for (double u = 0.05; u < 1; u += 0.1)
        for (double v = 0.05; u + v < 1; v += 0.1) {
          const double x = fb[0][0] + u * (fb[1][0] - fb[0][0]) + v * (fb[2][0] - fb[0][0]);
          const double y = fb[0][1] + u * (fb[1][1] - fb[0][1]) + v * (fb[2][1] - fb[0][1]);
          double za, zb;
          if (z_at(fa, x, y, za) && z_at(fb, x, y, zb)) {
            EXPECT_LE(za, zb + 1e-9);
          }
        }
    }
}

// A degenerate tree: naive on n parallel stacked triangles has depth n. Everything is iterative.
TEST(Depth, naive_on_100000_stacked_triangles_builds_traverses_and_frees) {
  // Naive is quadratic here (every level classifies the rest): 100000 in the normal build,
  // 20000 under the sanitizers (still far deeper than any recursion could survive there).
  const std::size_t n = std::getenv("EXBSP_SANITIZED") ? 20000 : 100000;
  exbsp::triangle_soup soup;
  for (std::size_t i = 0; i < n; ++i) {
    const double z = static_cast<double>(i);
    soup.add_triangle({0, 0, z}, {1, 0, z}, {0, 1, z});
  }
  exbsp::build_options o;
  o.heuristic = "naive";
  {
    const exbsp::bsp tree = exbsp::bsp::build(soup, o);
    EXPECT_EQ(tree.stats().depth, n);
    EXPECT_EQ(tree.stats().nodes, n);
    const auto order = tree.order_from_eye({0.1, 0.1, -1});
    ASSERT_EQ(order.size(), n);
    // Eye below everything: the topmost triangle is farthest, drawn first.
    EXPECT_EQ(tree.fragment(order.front()).face, n - 1);
    EXPECT_EQ(tree.fragment(order.back()).face, 0u);
    const auto parallel = tree.order_for_direction({0, 0, -1});
    EXPECT_EQ(tree.fragment(parallel.front()).face, 0u);
  }  // destroyed here: flat vectors, no recursion
}

TEST(Limits, max_fragments_stops_with_limit_error) {
  const auto soup = soup_of(cyclic_triple());
  exbsp::build_options o;
  o.heuristic = "naive";
  o.max_fragments = 3;
  EXPECT_THROW(exbsp::bsp::build(soup, o), exbsp::limit_error);
  o.max_fragments = 100;
  EXPECT_NO_THROW(exbsp::bsp::build(soup, o));
}

TEST(Kernels, epeck_and_gmpq_give_identical_trees_and_orders) {
  const auto soup = soup_of(cyclic_triple());
  for (const char* h : {"naive", "min-split", "sampled", "random"}) {
    exbsp::build_options a, b;
    a.heuristic = b.heuristic = h;
    a.kernel = exbsp::kernel_id::epeck;
    b.kernel = exbsp::kernel_id::gmpq;
    const auto ta = exbsp::bsp::build(soup, a), tb = exbsp::bsp::build(soup, b);
    ASSERT_EQ(ta.fragment_count(), tb.fragment_count()) << h;
    for (std::size_t i = 0; i < ta.fragment_count(); ++i)
      EXPECT_EQ(ta.fragment_exact(i), tb.fragment_exact(i)) << h;
    EXPECT_EQ(ta.order_from_eye({1, 2, 3}), tb.order_from_eye({1, 2, 3})) << h;
  }
}

TEST(Kernels, inexact_kernels_refuse_exact_output) {
  exbsp::build_options o;
  o.kernel = exbsp::kernel_id::double_;
  const auto t = exbsp::bsp::build(soup_of(cyclic_triple()), o);
  EXPECT_THROW(t.fragment_exact(0), exbsp::usage_error);
}

TEST(MinSplit, picks_the_plane_with_fewest_straddlers_ties_to_earliest) {
  // Triangle 0's plane (x = 0) cuts both others; the planes of 1 (z = 0) and 2 (z = 5) each
  // cut only triangle 0: min-split must take 1, the earliest of the one-split planes.
  const auto soup = soup_of({{{{0, -1, -1}, {0, 1, -1}, {0, 0, 6}}},
                             {{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}},
                             {{{-1, -1, 5}, {1, -1, 5}, {0, 1, 5}}}});
  exbsp::build_options o;
  o.heuristic = "min-split";
  const auto t = exbsp::bsp::build(soup, o);
  EXPECT_EQ(t.fragment(0).face, 1u);
  o.heuristic = "naive";
  const auto naive = exbsp::bsp::build(soup, o);
  EXPECT_EQ(naive.fragment(0).face, 0u);
  EXPECT_EQ(naive.stats().splits, 2u);
}

}  // namespace
