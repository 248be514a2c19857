// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact edge visibility (view/edge_visibility.h) and the geometry under it (geom/): exact
// determinants and crossings, feature edges, and the runs of edges in the degenerate
// configurations of standard views: edges exactly behind a fan diagonal, exactly behind a
// feature edge, exactly in an occluder's plane, faces seen edge-on.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <exbsp/view/camera.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/projection.h>
#include "geom/feature_edges.h"
#include "geom/homogeneous_det.h"
#include "geom/soup_cache.h"
#include "geom/weld.h"
#include "support/test_helpers.h"
#include "view/edge_visibility.h"

namespace {

using namespace exbsp;
using namespace exbsp::view;
using exbsp_test::add_quad;
using geom::crossing;
using geom::det_value;
using geom::hpoint;

// ---- determinants and crossings ----------------------------------------------------------

TEST(HomogeneousDet, SignIsTheOrientationUpToTheConventionAndExactFarFromTheOrigin) {
  const geom::rounding_guard guard;
  const hpoint a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, above{0, 0, 1}, below{0, 0, -1};
  // D(a, b, c, p) = -orientation(a, b, c, p): p on n's side gives -1.
  EXPECT_EQ(det_value(a, b, c, above).sign(), -1);
  EXPECT_EQ(det_value(a, b, c, below).sign(), 1);
  // Four points of the plane z = x around 1e8 (exactly coplanar; the rounded products leave
  // the interval undecided, the exact value is 0), and one just off it.
  const double o = 1e8;
  const hpoint p{o + 0.1, o + 0.2, o + 0.1}, q{o + 0.7, o - 0.5, o + 0.7},
      r{o - 0.3, o + 0.9, o - 0.3}, s{o + 0.3, o + 0.3, o + 0.3};
  EXPECT_EQ(det_value(p, q, r, s).sign(), 0);
  const hpoint off{o + 0.3, o + 0.3, std::nextafter(o + 0.3, 2 * o)};
  EXPECT_NE(det_value(p, q, r, off).sign(), 0);
  // A direction row (w = 0): D(a, b, c, (v, 0)) = -n . v.
  EXPECT_EQ(det_value(a, b, c, hpoint{0, 0, 1, 0}).sign(), -1);
  EXPECT_EQ(det_value(a, b, c, hpoint{1, 1, 0, 0}).sign(), 0);
}

TEST(HomogeneousDet, CrossingsOfDifferentFunctionsAtTheSameParameterCompareEqual) {
  const geom::rounding_guard guard;
  // The segment A = (0, 0, 0) -> B = (4, 0, 0) meets the plane x = 1 at t = 1/4 and the plane
  // 3x = 3 (other points) at t = 1/4 too; the plane x = 3 at t = 3/4.
  const hpoint A{0, 0, 0}, B{4, 0, 0};
  auto plane_x = [&](double x, double scale) {
    const hpoint p{x, 0, 0}, q{x, scale, 0}, r{x, 0, scale};
    return crossing::between(det_value(p, q, r, A), det_value(p, q, r, B));
  };
  const crossing quarter = plane_x(1, 1), quarter2 = plane_x(1, 7.5), three = plane_x(3, 2);
  EXPECT_EQ(geom::compare(quarter, quarter2), 0);
  EXPECT_EQ(geom::compare(quarter, three), -1);
  EXPECT_EQ(geom::compare(three, quarter2), 1);
  EXPECT_EQ(geom::compare(crossing::at_zero(), quarter), -1);
  EXPECT_EQ(geom::compare(crossing::at_one(), three), 1);
  EXPECT_DOUBLE_EQ(three.to_double(), 0.75);
}

TEST(HomogeneousDet, ProductsOfTheSameDeterminantsInOtherRowOrdersAreDecidedLikeGmp) {
  const geom::rounding_guard guard;
  // The shortcut for equal rows in another order must agree with the exact rational
  // difference of products, computed here from each determinant's exact value, for every
  // order of the rows (even and odd) and every pairing, including crossings of the plane
  // through the eye and the shared side of two neighbouring triangles (equal parameters).
  const hpoint eye{0.1, -3, 7.25}, u{1, 2, 0.5}, w{-1.5, 0.25, 3}, A{0.3, 0.7, -2}, B{2, -1, 4};
  const std::array<hpoint, 4> ra{eye, u, w, A}, rb{eye, u, w, B};
  std::array<int, 4> order{0, 1, 2, 3};
  auto permuted = [&](const std::array<hpoint, 4>& r) {
    return det_value(r[order[0]], r[order[1]], r[order[2]], r[order[3]]);
  };
  const det_value a(ra[0], ra[1], ra[2], ra[3]), b(rb[0], rb[1], rb[2], rb[3]);
  int equal = 0, decided = 0;
  do {
    const det_value pa = permuted(ra), pb = permuted(rb);
    EXPECT_EQ(pa.sign(), a.sign() * a.same_rows_sign(pa));
    for (const auto& [p, q, r, s] : {std::array<const det_value*, 4>{&pa, &pb, &a, &b},
                                     {&pa, &b, &a, &pb},
                                     {&a, &pb, &pa, &b},
                                     {&pb, &pa, &b, &a},
                                     {&pa, &b, &a, &b}}) {
      const mpq_class v = p->exact() * q->exact() - r->exact() * s->exact();
      EXPECT_EQ(geom::sign_of_difference_of_products(*p, *q, *r, *s), sgn(v));
      equal += sgn(v) == 0;
      decided += 1;
    }
    const crossing x = crossing::between(a, b), y = crossing::between(pa, pb);
    EXPECT_EQ(geom::compare(x, y), 0);
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(decided, 24 * 5);
  EXPECT_GT(equal, 0);
  EXPECT_LT(equal, decided);  // pa b - a b = (u - 1) a b: not zero for the odd orders
  // Rows that differ in one bit are not the same rows.
  const det_value c(eye, u, w, hpoint{std::nextafter(A.x, 1.0), A.y, A.z});
  EXPECT_EQ(a.same_rows_sign(c), 0);
  EXPECT_EQ(det_value(eye, u, u, A).same_rows_sign(det_value(eye, u, u, A)), 0);
}

// ---- welding and feature edges -----------------------------------------------------------

TEST(Weld, MinusZeroAndZeroAreOnePointAndNothingElseIsRounded) {
  const geom::welded_ids w =
      geom::weld({{0.0, 1, 2}, {-0.0, 1, 2}, {0.0, 1, std::nextafter(2.0, 3.0)}, {0, 1, 2}});
  EXPECT_EQ(w.count, 2u);
  EXPECT_EQ(w.id[0], w.id[1]);
  EXPECT_EQ(w.id[0], w.id[3]);
  EXPECT_NE(w.id[0], w.id[2]);
}

/// Unit cube [0,1]^3 as 6 quads (12 triangles), normals outward.
triangle_soup unit_cube(double x0 = 0, double y0 = 0, double z0 = 0, double sx = 1, double sy = 1,
                        double sz = 1) {
  triangle_soup s;
  const vec3d p[8] = {{x0, y0, z0},
                      {x0 + sx, y0, z0},
                      {x0 + sx, y0 + sy, z0},
                      {x0, y0 + sy, z0},
                      {x0, y0, z0 + sz},
                      {x0 + sx, y0, z0 + sz},
                      {x0 + sx, y0 + sy, z0 + sz},
                      {x0, y0 + sy, z0 + sz}};
  const int q[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                       {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (const auto& f : q) add_quad(s, p[f[0]], p[f[1]], p[f[2]], p[f[3]]);
  return s;
}

TEST(FeatureEdges, ACubeHasTwelveCreasesAndNoFanDiagonal) {
  const geom::view_features v = geom::find_feature_edges(unit_cube(), hpoint{3, 2.5, 4}, 30);
  EXPECT_EQ(v.edges.size(), 12u);
  for (const geom::feature_edge& e : v.edges) EXPECT_EQ(e.kind, geom::feature_kind::crease);
  // Each triangle of a quad: two sides are cube edges, the diagonal is not.
  for (std::uint8_t sides : v.feature_sides) EXPECT_EQ(__builtin_popcount(sides), 2);
}

TEST(FeatureEdges, FacingIsExactForAFaceSeenEdgeOn) {
  // The eye in the plane of the top face z = 1 (far away, exactly): the top face is edge-on.
  const triangle_soup s = unit_cube();
  const geom::view_features v = geom::find_feature_edges(s, hpoint{0.5, -7, 1}, 30);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tv = s.triangles[t].v;
    const bool top =
        s.vertices[tv[0]][2] == 1 && s.vertices[tv[1]][2] == 1 && s.vertices[tv[2]][2] == 1;
    if (top) {
      EXPECT_EQ(v.facing[t], 0);
    }
  }
}

/// The facing of (a, b, c) for viewer e, in exact rationals (the test's own oracle).
int rational_facing(const vec3d& a, const vec3d& b, const vec3d& c, const hpoint& e) {
  mpq_class u[3], v[3], w[3];
  const double ev[3] = {e.x, e.y, e.z};
  for (int k = 0; k < 3; ++k) {
    u[k] = mpq_class(b[k]) - mpq_class(a[k]);
    v[k] = mpq_class(c[k]) - mpq_class(a[k]);
    w[k] = e.w ? mpq_class(ev[k]) - mpq_class(a[k]) : mpq_class(ev[k]);
  }
  const mpq_class d = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
                      w[2] * (u[0] * v[1] - u[1] * v[0]);
  return sgn(d);
}

TEST(FeatureEdges, FilteredFacingAgreesWithRationalsOnAndOneUlpOffThePlane) {
  // Viewers exactly in the triangle's plane (points a + s (b - a) + t (c - a) with dyadic s, t
  // on integer corners; directions b - a), then one ulp off it in each coordinate; at the
  // origin, near 1e8 (where the rounded determinant cannot decide), at 1e-300 (underflow) and
  // 1e150 (overflow); and random ones.
  std::mt19937_64 rng(20261128);
  std::uniform_int_distribution<int> coord(-50, 50);
  std::uniform_real_distribution<double> any(-10, 10);
  int compared = 0, zeros = 0;
  for (int round = 0; round < 400; ++round) {
    for (const double scale : {1.0, 1e-300, 1e150}) {
      for (const double shift : {0.0, 1e8}) {
        if (scale != 1.0 && shift != 0.0) continue;
        vec3d p[3];
        for (vec3d& q : p)
          for (double& x : q) x = shift + scale * coord(rng);
        const double s = coord(rng) / 4.0, t = coord(rng) / 4.0;
        hpoint on{p[0][0] + s * (p[1][0] - p[0][0]) + t * (p[2][0] - p[0][0]),
                  p[0][1] + s * (p[1][1] - p[0][1]) + t * (p[2][1] - p[0][1]),
                  p[0][2] + s * (p[1][2] - p[0][2]) + t * (p[2][2] - p[0][2]), 1};
        const hpoint along{p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2], 0};
        std::vector<hpoint> viewers{
            on, along, {any(rng), any(rng), any(rng), 1}, {any(rng), any(rng), any(rng), 0}};
        for (const hpoint& base : {on, along})
          for (int k = 0; k < 3; ++k)
            for (const double dir : {-1.0, 1.0}) {
              hpoint e = base;
              double& x = k == 0 ? e.x : k == 1 ? e.y : e.z;
              x = std::nextafter(x, dir * HUGE_VAL);
              viewers.push_back(e);
            }
        for (const hpoint& e : viewers) {
          if (e.w == 0 && e.x == 0 && e.y == 0 && e.z == 0) continue;
          const int exact = rational_facing(p[0], p[1], p[2], e);
          EXPECT_EQ(geom::facing_filtered(p[0], p[1], p[2], e), exact);
          EXPECT_EQ(geom::facing(p[0], p[1], p[2], e), exact);
          ++compared;
          zeros += exact == 0;
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
  EXPECT_GT(zeros, 500);  // the on-plane viewers really are on the plane
}

TEST(FeatureEdges, ASilhouetteSeparatesAFrontFaceFromOneThatIsNot) {
  // A smooth fold: two quads at 10 degrees (no crease at 30), seen so that one faces the eye
  // and the other is seen edge-on: the fold is a silhouette.
  triangle_soup s;
  const double t = std::tan(10 * M_PI / 180);
  add_quad(s, {-1, 0, 1}, {0, 0, 1}, {0, 0, -1}, {-1, 0, -1});  // y = 0, normal +y
  add_quad(s, {0, 0, 1}, {1, t, 1}, {1, t, -1}, {0, 0, -1});    // y = t x, consistently oriented
  // The eye (2, 2t, 0) lies exactly in the second quad's plane (2t is exact): edge-on, while
  // the first quad faces it.
  const geom::view_features v = geom::find_feature_edges(s, hpoint{2, 2 * t, 0}, 30);
  std::size_t silhouettes = 0;
  for (const geom::feature_edge& e : v.edges)
    silhouettes += e.kind == geom::feature_kind::silhouette;
  EXPECT_EQ(silhouettes, 1u);
}

TEST(FeatureEdges, AKeptEdgeGraphServesEveryViewAndIsRemadeWhenTheSoupChangesByOneUlp) {
  // Oracle: the edges found from scratch for each viewer (the graph made again each time).
  triangle_soup s = unit_cube();
  add_quad(s, {0, 0, 1}, {1, 0, 1}, {1.5, 0, 1.2}, {0.5, 0, 1.2});  // a fin: boundary + creases
  geom::soup_cache cache;
  const std::shared_ptr<const geom::edge_graph> first = cache.edge_graph_for(s, 30);
  const hpoint viewers[] = {{3, 2.5, 4}, {0.5, -7, 1}, {-2, 0.5, 0.5}, {0, 0, 1, 0}, {1, -1, 1, 0}};
  for (const hpoint& e : viewers) {
    const std::shared_ptr<const geom::edge_graph> g = cache.edge_graph_for(s, 30);
    EXPECT_EQ(g, first);  // kept
    const geom::view_features kept = geom::find_feature_edges(*g, s, e);
    const geom::view_features fresh = geom::find_feature_edges(s, e, 30);
    ASSERT_EQ(kept.edges.size(), fresh.edges.size());
    for (std::size_t i = 0; i < kept.edges.size(); ++i) {
      EXPECT_EQ(kept.edges[i].a, fresh.edges[i].a);
      EXPECT_EQ(kept.edges[i].b, fresh.edges[i].b);
      EXPECT_EQ(kept.edges[i].kind, fresh.edges[i].kind);
    }
    EXPECT_EQ(kept.facing, fresh.facing);
    EXPECT_EQ(kept.feature_sides, fresh.feature_sides);
  }
  EXPECT_NE(cache.edge_graph_for(s, 45), first);  // another crease angle
  const std::shared_ptr<const geom::edge_graph> at45 = cache.edge_graph_for(s, 45);
  s.vertices[0][0] = std::nextafter(s.vertices[0][0], 1.0);
  EXPECT_NE(cache.edge_graph_for(s, 45), at45);  // one coordinate one ulp off
  s.triangles[0].face += 1;
  const std::shared_ptr<const geom::edge_graph> refaced = cache.edge_graph_for(s, 45);
  EXPECT_EQ(refaced->edges.size(), geom::edge_graph_of(s, 45).edges.size());
  EXPECT_EQ(cache.edge_graph_for(s, 45), refaced);
}

TEST(FeatureEdges, TheKeptProductsOfASoupAreMadeAgainEachOnItsOwnKey) {
  // The closed-mesh verdicts and the edge graph share the soup's copy but not their keys.
  triangle_soup s = unit_cube();
  geom::soup_cache cache;
  const auto graph = cache.edge_graph_for(s, 30);
  const auto closed = cache.outward_closed_for(s, {});
  EXPECT_EQ(*closed, (std::vector<std::uint8_t>{1}));
  EXPECT_EQ(cache.outward_closed_for(s, {}), closed);         // kept
  EXPECT_EQ(cache.edge_graph_for(s, 30), graph);              // kept across the other product
  const auto split = cache.outward_closed_for(s, {0, 3, 6});  // two meshes of three faces
  EXPECT_NE(split, closed);
  EXPECT_EQ(*split, (std::vector<std::uint8_t>{0, 0}));  // each half is open
  EXPECT_EQ(cache.edge_graph_for(s, 30), graph);
  std::swap(s.triangles[0].v[1], s.triangles[0].v[2]);  // one triangle turned: not closed
  EXPECT_EQ(*cache.outward_closed_for(s, {}), (std::vector<std::uint8_t>{0}));
  EXPECT_NE(cache.edge_graph_for(s, 30), graph);
}

// ---- runs ---------------------------------------------------------------------------------

/// A parallel (orthographic) frame looking from `eye` towards `at` (direction at - eye).
frame parallel_frame(triangle_soup soup, const point3& eye, const point3& at, const vector3& up,
                     double half = 2) {
  frame f;
  f.soup = std::move(soup);
  f.view.kind = projection_kind::orthographic;
  f.view.cam = {eye, at, up};
  f.view.model_view = look_at(f.view.cam);
  f.view.projection = ortho(-half, half, -half, half, 0.1, 100);
  f.view.vp = {0, 0, 400, 400, 0, 1};
  const double dx = at.x - eye.x, dy = at.y - eye.y, dz = at.z - eye.z;
  const double n = std::sqrt(dx * dx + dy * dy + dz * dz);
  f.view.direction = {dx / n, dy / n, dz / n};
  return f;
}

/// The runs of the edge from a to b (either direction), as (t0, t1, visible) from a.
std::vector<edge_run> runs_of(const edge_visibility& ev, const triangle_soup& s, const vec3d& a,
                              const vec3d& b) {
  std::vector<edge_run> out;
  for (const edge_run& r : ev.runs) {
    const geom::feature_edge& e = ev.features.edges[r.edge];
    const vec3d &p = s.vertices[e.a], &q = s.vertices[e.b];
    if (p == a && q == b) out.push_back(r);
    if (p == b && q == a) out.push_back({r.edge, 1 - r.t1, 1 - r.t0, r.visible});
  }
  std::sort(out.begin(), out.end(),
            [](const edge_run& x, const edge_run& y) { return x.t0 < y.t0; });
  return out;
}

/// A square [0,1]^2 at z = 1 (two triangles, diagonal (0,0)-(1,1)) facing +z, and a free edge
/// (a degenerate-free sliver triangle's boundary) behind it: a thin triangle at z = 0 whose
/// long side is the edge under test.
triangle_soup square_and_sliver(const vec3d& a, const vec3d& b) {
  triangle_soup s;
  add_quad(s, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
  s.add_triangle(a, b, {a[0], a[1], a[2] - 0.5});  // in a plane containing the view direction
  return s;
}

TEST(EdgeRuns, AnEdgeExactlyBehindAFanDiagonalIsHidden) {
  // Parallel view along -z: the edge (0,0,0)-(1,1,0) lies exactly behind the square's diagonal,
  // which is not a feature edge: the ray hits the surface, so the edge is hidden throughout.
  const triangle_soup s = square_and_sliver({0, 0, 0}, {1, 1, 0});
  frame f = parallel_frame(s, {0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0});
  const edge_visibility ev = visible_runs(f, 30);
  const auto r = runs_of(ev, f.soup, {0, 0, 0}, {1, 1, 0});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].visible);
}

TEST(EdgeRuns, AnEdgeExactlyBehindABoundaryEdgeIsVisible) {
  // The edge (0,0,0)-(1,0,0) lies exactly behind the square's boundary edge y = 0: touching a
  // feature edge hides nothing.
  const triangle_soup s = square_and_sliver({0, 0, 0}, {1, 0, 0});
  frame f = parallel_frame(s, {0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0});
  const auto r = runs_of(visible_runs(f, 30), f.soup, {0, 0, 0}, {1, 0, 0});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(r[0].visible);
}

TEST(EdgeRuns, HiddenIntervalEndsExactlyAtTheOccludersOutline) {
  // The edge (-1, 0.5, 0)-(3, 0.5, 0) behind the square: hidden exactly on [1/4, 1/2].
  const triangle_soup s = square_and_sliver({-1, 0.5, 0}, {3, 0.5, 0});
  frame f = parallel_frame(s, {0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0}, 4);
  const auto r = runs_of(visible_runs(f, 30), f.soup, {-1, 0.5, 0}, {3, 0.5, 0});
  ASSERT_EQ(r.size(), 3u);
  EXPECT_TRUE(r[0].visible);
  EXPECT_FALSE(r[1].visible);
  EXPECT_TRUE(r[2].visible);
  EXPECT_DOUBLE_EQ(r[1].t0, 0.25);
  EXPECT_DOUBLE_EQ(r[1].t1, 0.5);
}

TEST(EdgeRuns, TwoFrontFacesSharingAnEdgeLeaveNoVisibleGapBehindIt) {
  // Two coplanar quads side by side (one face each: their shared edge is not a feature edge)
  // in front of an edge that crosses behind the shared edge: hidden throughout the union.
  triangle_soup s;
  add_quad(s, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
  add_quad(s, {1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1});
  s.add_triangle({0.5, 0.5, 0}, {1.5, 0.5, 0}, {0.5, 0.5, -0.5});
  frame f = parallel_frame(s, {1, 0.5, 10}, {1, 0.5, 0}, {0, 1, 0}, 3);
  const auto r = runs_of(visible_runs(f, 30), f.soup, {0.5, 0.5, 0}, {1.5, 0.5, 0});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].visible);
}

TEST(EdgeRuns, CubeFrontParallelViewHidesNothingAndDrawsEveryFrontEdge) {
  // Looking along -z at the cube's front face z = 1: the back square coincides with the front
  // one (its rays touch the front face's feature edges), the receding edges are points.
  frame f = parallel_frame(unit_cube(), {0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0});
  const edge_visibility ev = visible_runs(f, 30);
  for (const edge_run& r : ev.runs) EXPECT_TRUE(r.visible);
  const auto bottom = runs_of(ev, f.soup, {0, 0, 1}, {1, 0, 1});
  ASSERT_EQ(bottom.size(), 1u);
  EXPECT_TRUE(bottom[0].visible);
}

TEST(EdgeRuns, CubeFrontPerspectiveHidesTheBackSquareAndTheRecedingEdges) {
  frame f = exbsp_test::perspective_frame(unit_cube(), {},
                                          {{0.5, 0.5, 4}, {0.5, 0.5, 0.5}, {0, 1, 0}}, 300, 300);
  const edge_visibility ev = visible_runs(f, 30);
  for (const edge_run& r : ev.runs) {
    const geom::feature_edge& e = ev.features.edges[r.edge];
    const bool front = f.soup.vertices[e.a][2] == 1 && f.soup.vertices[e.b][2] == 1;
    EXPECT_EQ(r.visible, front) << "edge " << r.edge;
    EXPECT_EQ(r.t0, 0);
    EXPECT_EQ(r.t1, 1);
  }
}

TEST(EdgeRuns, IsometricParallelViewHidesExactlyTheThreeSpokesOfTheBackCorner) {
  // Direction (-1, 1, -1) from the eye at (1, -1, 1) + c: the corner (0, 1, 0) is the hidden
  // one; its three edges are hidden, the nine others visible (the two corners on the axis
  // through the centre coincide in the image).
  frame f = parallel_frame(unit_cube(), {5.5, -4.5, 5.5}, {0.5, 0.5, 0.5}, {0, 0, 1});
  const edge_visibility ev = visible_runs(f, 30);
  std::size_t hidden = 0, visible = 0;
  for (const edge_run& r : ev.runs) {
    const geom::feature_edge& e = ev.features.edges[r.edge];
    const vec3d back{0, 1, 0};
    const bool spoke = f.soup.vertices[e.a] == back || f.soup.vertices[e.b] == back;
    EXPECT_EQ(r.visible, !spoke);
    EXPECT_EQ(r.t1 - r.t0, 1);
    (r.visible ? visible : hidden) += 1;
  }
  EXPECT_EQ(hidden, 3u);
  EXPECT_EQ(visible, 9u);
}

TEST(EdgeRuns, AFaceSeenEdgeOnHidesNothing) {
  // A quad in the plane x = 0.5 containing the view direction, between the eye and an edge.
  triangle_soup s;
  add_quad(s, {0.5, -1, 2}, {0.5, 2, 2}, {0.5, 2, 5}, {0.5, -1, 5});
  s.add_triangle({0.5, 0, 0}, {0.5, 1, 0}, {0.5, 0, -1});
  frame f = parallel_frame(s, {0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0});
  const auto r = runs_of(visible_runs(f, 30), f.soup, {0.5, 0, 0}, {0.5, 1, 0});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(r[0].visible);
}

}  // namespace
