// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact sections (clip/section.h, `exbsp section`, scene "clip_planes"). Every check is exact,
// on GMP rationals parsed from the result's "p/q" strings:
//   - closed: kept ∪ cap uses every directed edge as often as its reverse (a manifold: each
//     edge exactly twice), points merged exactly (distinct indices, distinct rationals);
//   - the vector area Σ (b-a)×(c-a) of kept ∪ cap is zero (a closed surface);
//   - cap orientation: every cap triangle's normal is a positive multiple of -(A,B,C);
//   - outline: every point on the plane, loops closed, loop edges = cap boundary reversed;
//   - tiling: for every input face, its pieces kept by P and by -P add up to its vector area
//     (in-plane faces counted twice), so nothing is lost or doubled;
//   - the split pieces equal clip::split_triangle's (the section 3 convention).
// Degenerate cuts first: through vertices, along edges, containing a face (both sides),
// tangent, through a non-manifold vertex, one ulp off a face, nested islands and holes.
// Corpus meshes (data/meshes) are skipped with a message when missing (a failure under
// EXBSP_REQUIRE_CORPUS=1, as in CI).
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include <exbsp/clip/section.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/png_io.h>
#include "geom/rational.h"
#include "scene/render.h"
#include "scene/scene.h"
#include "support/cli_support.h"
#include "support/exact_triangle_clip.h"
#include "support/inputs.h"
#include "support/test_helpers.h"

namespace {

namespace fs = std::filesystem;
using exbsp::section_plane;
using exbsp::section_result;
using exbsp::triangle_soup;
using exbsp::vec3d;
using q3 = std::array<mpq_class, 3>;

/// The exact points of r, parsed from their "p/q" strings.
std::vector<q3> exact_points(const section_result& r) {
  std::vector<q3> out(r.points.size());
  for (std::size_t j = 0; j < r.points.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      out[j][k] = mpq_class(r.points[j].exact[k]);
      out[j][k].canonicalize();
    }
  return out;
}

using exbsp_test::cross;
using exbsp_test::dot;
using exbsp_test::sub;

/// Exact vector area (twice the area vector) of a triangle of the result.
q3 area2(const std::vector<q3>& pts, const exbsp::section_triangle& t) {
  const q3 &a = pts[t.p[0]], &b = pts[t.p[1]], &c = pts[t.p[2]];
  return cross(sub(b, a), sub(c, a));
}

q3 plane_normal(const section_plane& p) {
  return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])};
}

mpq_class plane_value(const section_plane& p, const q3& x) {
  return mpq_class(p[0]) * x[0] + mpq_class(p[1]) * x[1] + mpq_class(p[2]) * x[2] + mpq_class(p[3]);
}

/// Directed edge balance of a triangle list (point indices): (u,v) uses minus (v,u) uses.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_balance(
    const std::vector<exbsp::section_triangle>& tris) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> net;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t.p[k], b = t.p[(k + 1) % 3];
      if (a < b) ++net[{a, b}];
      if (b < a) --net[{b, a}];
    }
  for (auto it = net.begin(); it != net.end();)
    it = it->second == 0 ? net.erase(it) : std::next(it);
  return net;
}

/// All the exact invariants of a section of a closed input (see the top of the file).
void expect_closed_section(const section_result& r) {
  ASSERT_TRUE(r.closed);
  const std::vector<q3> pts = exact_points(r);
  // Points merged exactly: distinct indices are distinct rationals.
  std::set<std::array<std::string, 3>> distinct;
  for (const auto& p : r.points) distinct.insert(p.exact);
  EXPECT_EQ(distinct.size(), r.points.size());
  // Closed: every directed edge balanced by its reverse.
  std::vector<exbsp::section_triangle> all = r.kept;
  all.insert(all.end(), r.cap.begin(), r.cap.end());
  EXPECT_TRUE(edge_balance(all).empty()) << edge_balance(all).size() << " unbalanced edges";
  // Closed surface: zero vector area; cap facing -n.
  const q3 n = plane_normal(r.plane);
  q3 total{0, 0, 0};
  for (const auto& t : all) {
    const q3 a = area2(pts, t);
    for (int k = 0; k < 3; ++k) total[k] += a[k];
  }
  EXPECT_EQ(total[0], 0);
  EXPECT_EQ(total[1], 0);
  EXPECT_EQ(total[2], 0);
  for (const auto& t : r.cap) {
    const q3 a = area2(pts, t);
    EXPECT_LT(dot(a, n), 0) << "cap triangle not facing -(A,B,C)";
    const q3 c = cross(a, n);
    EXPECT_TRUE(c[0] == 0 && c[1] == 0 && c[2] == 0) << "cap triangle not in the plane";
    for (std::uint32_t p : t.p) EXPECT_EQ(plane_value(r.plane, pts.at(p)), 0);
  }
  // Outline: closed loops on the plane; their edges are the cap's boundary reversed.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> loop_net;
  for (const auto& c : r.outline) {
    EXPECT_TRUE(c.closed);
    EXPECT_GE(c.p.size(), 3u);
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      EXPECT_EQ(plane_value(r.plane, pts.at(c.p[i])), 0);
      const std::uint32_t a = c.p[i], b = c.p[(i + 1) % c.p.size()];
      if (a < b) ++loop_net[{a, b}];
      if (b < a) --loop_net[{b, a}];
    }
  }
  for (auto it = loop_net.begin(); it != loop_net.end();)
    it = it->second == 0 ? loop_net.erase(it) : std::next(it);
  auto cap_net = edge_balance(r.cap);
  for (auto& e : cap_net) e.second = -e.second;
  EXPECT_EQ(loop_net, cap_net);
}

/// Σ of the cap's vector areas dotted with n (= -2 × cap area × |n|... as a rational).
mpq_class cap_area2_along_n(const section_result& r) {
  const std::vector<q3> pts = exact_points(r);
  mpq_class s = 0;
  for (const auto& t : r.cap) s += dot(area2(pts, t), plane_normal(r.plane));
  return s;
}

/// Face by face, the pieces kept by P and by -P tile the input face (in-plane faces twice).
void expect_tiling(const triangle_soup& soup, const section_plane& p) {
  const section_plane neg{-p[0], -p[1], -p[2], -p[3]};
  const section_result a = exbsp::section_with_cap(soup, p), b = exbsp::section_with_cap(soup, neg);
  std::vector<q3> sum(soup.face_count, q3{0, 0, 0});
  for (const section_result* r : {&a, &b}) {
    const std::vector<q3> pts = exact_points(*r);
    for (const auto& t : r->kept) {
      const q3 x = area2(pts, t);
      for (int k = 0; k < 3; ++k) sum[t.face][k] += x[k];
    }
  }
  std::vector<q3> expected(soup.face_count, q3{0, 0, 0});
  for (const auto& t : soup.triangles) {
    q3 v[3];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) v[i][k] = mpq_class(soup.vertices[t.v[i]][k]);
    const q3 x = cross(sub(v[1], v[0]), sub(v[2], v[0]));
    const bool in_plane =
        plane_value(p, v[0]) == 0 && plane_value(p, v[1]) == 0 && plane_value(p, v[2]) == 0;
    for (int k = 0; k < 3; ++k) expected[t.face][k] += in_plane ? 2 * x[k] : x[k];
  }
  for (std::uint32_t f = 0; f < soup.face_count; ++f)
    EXPECT_EQ(sum[f], expected[f]) << "face " << f;
}

/// Outward-oriented box [lo, hi] (12 triangles); `inward` reverses it (a cavity).
void add_box(triangle_soup& s, const vec3d& lo, const vec3d& hi, bool inward = false) {
  const auto base = static_cast<std::uint32_t>(s.vertices.size());
  for (int i = 0; i < 8; ++i)
    s.vertices.push_back({i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    std::vector<std::uint32_t> idx{base + q[0], base + q[1], base + q[2], base + q[3]};
    if (inward) std::reverse(idx.begin(), idx.end());
    s.add_polygon(idx, s.face_count++);
  }
}

triangle_soup unit_cube() {
  triangle_soup s;
  add_box(s, {0, 0, 0}, {1, 1, 1});
  return s;
}

// --- degenerate cuts ---------------------------------------------------------------------

TEST(Section, box_is_oriented_outward_and_closed) {
  const section_result r = exbsp::section_with_cap(unit_cube(), {0, 0, 1, 10});  // everything kept
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.kept.size(), 12u);
  EXPECT_TRUE(r.cap.empty());
  EXPECT_TRUE(r.outline.empty());
  const std::vector<q3> pts = exact_points(r);
  for (const auto& t : r.kept) {  // outward: the normal points away from the centre
    const q3 a = area2(pts, t), c = pts.at(t.p[0]);
    EXPECT_GT(dot(a, sub(c, {mpq_class(1, 2), mpq_class(1, 2), mpq_class(1, 2)})), 0);
  }
}

TEST(Section, plain_cut_of_a_cube_has_a_unit_square_cap) {
  const section_plane p{0, 0, 1, -0.5};
  const section_result r = exbsp::section_with_cap(unit_cube(), p);
  expect_closed_section(r);
  ASSERT_EQ(r.outline.size(), 1u);
  EXPECT_EQ(cap_area2_along_n(r), -2);  // area 1, facing -z
  expect_tiling(unit_cube(), p);
}

TEST(Section, plane_through_three_vertices) {
  const section_plane p{1, 1, 1, -1};  // through (1,0,0), (0,1,0), (0,0,1)
  const section_result r = exbsp::section_with_cap(unit_cube(), p);
  expect_closed_section(r);
  ASSERT_EQ(r.outline.size(), 1u);
  // The three corners and where the face diagonals cross the plane (collinear points).
  EXPECT_EQ(r.outline[0].p.size(), 6u);
  EXPECT_EQ(cap_area2_along_n(r),
            -3);  // triangle of area sqrt(3)/2; (2 area n̂)·n = 2 * sqrt3/2 * sqrt3
  expect_tiling(unit_cube(), p);
  expect_closed_section(exbsp::section_with_cap(unit_cube(), {-1, -1, -1, 1}));
}

TEST(Section, diagonal_plane_along_two_edges) {
  const section_plane p{1, -1, 0, 0};  // x = y: contains the edges x=y=0 and x=y=1
  const section_result r = exbsp::section_with_cap(unit_cube(), p);
  expect_closed_section(r);
  // The cut rectangle: sqrt(2) by 1; 2 area (n̂·n) = 2 sqrt2 sqrt2 = 4.
  EXPECT_EQ(cap_area2_along_n(r), -4);
  expect_tiling(unit_cube(), p);
}

TEST(Section, plane_containing_a_face_keeps_the_whole_solid_on_its_side) {
  const section_result r =
      exbsp::section_with_cap(unit_cube(), {0, 0, 1, 0});  // z >= 0: bottom face in the plane
  expect_closed_section(r);
  EXPECT_EQ(r.kept.size(), 12u);
  EXPECT_TRUE(r.cap.empty());
  EXPECT_TRUE(r.outline.empty());
  EXPECT_EQ(r.stats.in_plane, 2u);
  expect_tiling(unit_cube(), {0, 0, 1, 0});
}

TEST(Section, plane_containing_a_face_with_the_solid_removed_keeps_a_double_sided_face) {
  const section_result r = exbsp::section_with_cap(unit_cube(), {0, 0, -1, 0});  // z <= 0
  expect_closed_section(r);
  EXPECT_EQ(r.kept.size(), 2u);  // the bottom face, facing -z
  EXPECT_EQ(r.stats.in_plane, 2u);
  ASSERT_EQ(r.outline.size(), 1u);
  EXPECT_EQ(cap_area2_along_n(r), -2);  // the face again, facing +z = -(0,0,-1)
}

TEST(Section, tangent_planes_cut_nothing) {
  for (const section_plane& p :
       {section_plane{1, 1, 0, -2}, section_plane{-1, -1, 0, 2},      // along edge x=y=1
        section_plane{1, 1, 1, -3}, section_plane{-1, -1, -1, 3}}) {  // at vertex (1,1,1)
    const section_result r = exbsp::section_with_cap(unit_cube(), p);
    expect_closed_section(r);
    EXPECT_TRUE(r.outline.empty());
    EXPECT_TRUE(r.cap.empty());
    EXPECT_TRUE(r.kept.size() == 0 || r.kept.size() == 12u);
    EXPECT_EQ(r.stats.split, 0u);
  }
}

TEST(Section, plane_through_a_non_manifold_vertex) {
  triangle_soup s;
  add_box(s, {0, 0, 0}, {1, 1, 1});
  add_box(s, {1, 1, 1}, {2, 2, 2});  // shares the vertex (1,1,1)
  for (const section_plane& p : {section_plane{1, 1, 1, -3}, section_plane{0, 0, 1, -1},
                                 section_plane{0, 0, -1, 1}, section_plane{1, -1, 0, 0}}) {
    SCOPED_TRACE(testing::Message() << p[0] << "," << p[1] << "," << p[2] << "," << p[3]);
    const section_result r = exbsp::section_with_cap(s, p);
    expect_closed_section(r);
    expect_tiling(s, p);
  }
  // x = y: two rectangles touching at the shared vertex, as two simple loops.
  const section_result r = exbsp::section_with_cap(s, {1, -1, 0, 0});
  EXPECT_EQ(r.outline.size(), 2u);
  // x+y+z = 3 only touches both cubes at the shared vertex: nothing to cut.
  EXPECT_TRUE(exbsp::section_with_cap(s, {1, 1, 1, -3}).outline.empty());
  expect_closed_section(
      exbsp::section_with_cap(s, {1, 1, -2, 0}));  // through the vertex, cutting both
}

TEST(Section, one_ulp_off_a_face) {
  const double below = std::nextafter(1.0, 0.0);
  const section_plane p{0, 0, 1, -below};  // z >= 1 - 2^-53: a slab one ulp thick
  const section_result r = exbsp::section_with_cap(unit_cube(), p);
  expect_closed_section(r);
  EXPECT_EQ(cap_area2_along_n(r), -2);
  for (const auto& t : r.cap)
    for (std::uint32_t i : t.p)
      EXPECT_EQ(r.points[i].exact[2], "9007199254740991/9007199254740992");
  expect_tiling(unit_cube(), p);
  // A plane tilted by 2^-60 through the top edge x = 0: the top face straddles it.
  const section_plane tilt{std::ldexp(1.0, -60), 0, 1, -1};
  const section_result t = exbsp::section_with_cap(unit_cube(), tilt);
  expect_closed_section(t);
  EXPECT_GT(t.stats.split, 0u);
  expect_tiling(unit_cube(), tilt);
}

TEST(Section, collinear_sliver_closing_a_t_junction) {
  // A cube whose top face has an extra vertex m in the middle of its edge a-b (y = 0); the
  // wall below still uses a-b, and the collinear triangle (a, m, b) closes the T-junction.
  triangle_soup s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},  {0, 0, 1},
                {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.5, 0, 1}};
  const std::vector<std::vector<std::uint32_t>> faces{{0, 2, 3, 1}, {8, 5, 7, 6, 4}, {0, 1, 5, 4},
                                                      {2, 6, 7, 3}, {0, 4, 6, 2},    {1, 3, 7, 5},
                                                      {4, 5, 8}};
  for (const auto& f : faces) s.add_polygon(f, s.face_count++);
  for (const section_plane& p : {section_plane{1, 0, 0, -0.25}, section_plane{1, 0, 0, -0.5},
                                 section_plane{1, 0.5, -1, 0.5}, section_plane{-1, 0, 0, 0.75}}) {
    SCOPED_TRACE(testing::Message() << p[0] << "," << p[1] << "," << p[2] << "," << p[3]);
    const section_result r = exbsp::section_with_cap(s, p);
    EXPECT_EQ(r.stats.degenerate_input, 1u);
    expect_closed_section(r);
    expect_tiling(s, p);
  }
}

TEST(Section, holes_and_nested_islands) {
  triangle_soup s;
  add_box(s, {0, 0, 0}, {10, 10, 10});
  add_box(s, {2, 2, 2}, {8, 8, 8}, true);  // cavity
  add_box(s, {4, 4, 4}, {6, 6, 6});        // island inside the cavity
  const section_plane p{0, 0, 1, -5};
  const section_result r = exbsp::section_with_cap(s, p);
  expect_closed_section(r);
  EXPECT_EQ(r.outline.size(), 3u);
  EXPECT_EQ(cap_area2_along_n(r), -2 * (100 - 36 + 4));
  // Loops run counter-clockwise seen from the kept side (+z) for outer boundaries, clockwise
  // for the hole: signed areas in the xy plane 100, -36, 4.
  std::multiset<mpq_class> areas;
  const std::vector<q3> pts = exact_points(r);
  for (const auto& c : r.outline) {
    mpq_class a2 = 0;
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      const q3 u = pts.at(c.p[i]), v = pts.at(c.p[(i + 1) % c.p.size()]);
      a2 += u[0] * v[1] - u[1] * v[0];
    }
    areas.insert(a2 / 2);
  }
  EXPECT_EQ(areas, (std::multiset<mpq_class>{-36, 4, 100}));
  expect_tiling(s, p);
  // A slanted cut through all three.
  expect_closed_section(exbsp::section_with_cap(s, {0.25, 0.5, 1, -8.5}));
}

TEST(Section, touching_solids_with_t_junctions_are_refined_to_stay_closed) {
  triangle_soup s;
  add_box(s, {0, 0, 0}, {1, 1, 1});
  add_box(s, {1, 0.25, 0}, {2, 0.75, 1});  // shares part of the face x = 1, not its vertices
  for (const section_plane& p :
       {section_plane{0, 0, 1, -0.5}, section_plane{0.125, 0.25, 1, -0.75}}) {
    const section_result r = exbsp::section_with_cap(s, p);
    expect_closed_section(r);
    EXPECT_GT(r.stats.split_constraints, 0u);
  }
}

TEST(Section, overlapping_solids_cover_the_overlap_twice) {
  triangle_soup s;
  add_box(s, {0, 0, 0}, {2, 2, 2});
  add_box(s, {1, 1, 1}, {3, 3, 3});  // a second closed solid through the first
  const section_result r = exbsp::section_with_cap(s, {0, 0, 1, -1.5});
  expect_closed_section(r);
  EXPECT_GT(r.stats.cap_steiner_points, 0u);      // the loops cross at (2,1) and (1,2)
  EXPECT_EQ(cap_area2_along_n(r), -2 * (4 + 4));  // two squares of area 4, the overlap twice
}

TEST(Section, many_small_integer_planes_hit_vertices_edges_and_faces_and_stay_closed) {
  // Planes with coefficients in -2..2 and D in -6..6 (halves) through boxes on a unit grid:
  // most pass through vertices, along edges or contain faces. Fixed seed.
  triangle_soup s;
  add_box(s, {0, 0, 0}, {4, 4, 4});
  add_box(s, {1, 1, 1}, {3, 3, 3}, true);  // cavity
  add_box(s, {4, 1, 0}, {5, 3, 2});        // touching the outer box along part of a face
  add_box(s, {-1, -1, -1}, {0, 0, 0});     // touching at the vertex (0,0,0)
  std::uint64_t state = 12;
  auto next = [&state](int lo, int hi) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + static_cast<int>((state >> 33) % static_cast<std::uint64_t>(hi - lo + 1));
  };
  int cut = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const section_plane p{double(next(-2, 2)), double(next(-2, 2)), double(next(-2, 2)),
                          next(-12, 12) / 2.0};
    if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue;
    SCOPED_TRACE(testing::Message() << p[0] << "," << p[1] << "," << p[2] << "," << p[3]);
    const section_result r = exbsp::section_with_cap(s, p);
    expect_closed_section(r);
    expect_tiling(s, p);
    cut += !r.cap.empty();
    if (HasFailure()) break;
  }
  EXPECT_GT(cut, 50);
}

TEST(Section, open_input_gives_open_polylines_and_no_cap) {
  triangle_soup s = unit_cube();
  s.triangles.erase(s.triangles.begin() + 2, s.triangles.begin() + 4);  // drop the top face
  const section_result r = exbsp::section_with_cap(s, {0, 0, 1, -0.5});
  EXPECT_FALSE(r.closed);
  EXPECT_TRUE(r.cap.empty());
  ASSERT_EQ(r.outline.size(), 1u);  // the four walls still make a closed loop
  EXPECT_TRUE(r.outline[0].closed);
  triangle_soup w;  // one wall: an open polyline
  w.add_triangle({0, 0, 0}, {1, 0, 0}, {1, 0, 1});
  w.add_triangle({0, 0, 0}, {1, 0, 1}, {0, 0, 1});
  const section_result o = exbsp::section_with_cap(w, {0, 0, 1, -0.5});
  ASSERT_EQ(o.outline.size(), 1u);
  EXPECT_FALSE(o.outline[0].closed);
  EXPECT_EQ(o.outline[0].p.size(), 3u);
}

TEST(Section, pieces_follow_the_section_3_split_convention) {
  using K = exbsp_test::oracle::epeck;
  triangle_soup s;
  s.add_triangle({0, 0, 0}, {1, 0, 1}, {0, 1, 0.25});  // no vertex on the plane
  s.add_triangle({0, 0, 0.5}, {1, 0, 1}, {0, 1, 0});   // one vertex on the plane
  s.add_triangle({0.3, 0, 1}, {1, 0, 0},
                 {0, 1, 0.7});  // c alone on the negative side... and others
  const section_result r = exbsp::section_with_cap(s, {0, 0, 1, -0.5});
  const exbsp_test::oracle::exact_plane<K> plane{K::Point_3(0, 0, 0.5), K::Point_3(1, 0, 0.5),
                                                 K::Point_3(0, 1, 0.5)};
  std::vector<std::array<std::array<std::string, 3>, 3>> expected, got;
  auto text = [](const K::FT& x) {
    std::ostringstream o;
    o << CGAL::exact(x);
    return o.str();
  };
  for (const auto& t : s.triangles) {
    exbsp_test::oracle::exact_triangle<K> e;
    for (int i = 0; i < 3; ++i) {
      const vec3d& v = s.vertices[t.v[i]];
      e.v[i] = K::Point_3(v[0], v[1], v[2]);
    }
    for (const auto& piece : exbsp_test::oracle::split_triangle(e, plane).positive) {
      std::array<std::array<std::string, 3>, 3> x;
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
          mpq_class q(text(piece.v[i][k]));
          q.canonicalize();
          x[i][k] = q.get_str();
        }
      expected.push_back(x);
    }
  }
  for (const auto& t : r.kept) {
    std::array<std::array<std::string, 3>, 3> x;
    for (int i = 0; i < 3; ++i) x[i] = r.points[t.p[i]].exact;
    got.push_back(x);
  }
  EXPECT_EQ(got, expected);
}

TEST(Section, bad_planes_are_usage_errors) {
  EXPECT_THROW(exbsp::section_with_cap(unit_cube(), {0, 0, 0, 1}), exbsp::usage_error);
  EXPECT_THROW(exbsp::section_with_cap(unit_cube(), {NAN, 0, 1, 1}), exbsp::usage_error);
  EXPECT_THROW(exbsp::section_with_cap(unit_cube(), {0, 0, 1, INFINITY}), exbsp::usage_error);
  EXPECT_THROW(exbsp::clip_soup_with_caps(unit_cube(), {{0, 0, 1, 0}, {0, 0, 0, 0}}),
               exbsp::usage_error);
}

// The LGPL core's section() (section.h) is the same cut without the cap: same kept triangles,
// points and outline wherever the cap subdivides nothing (docs/licence.md: the cap needs
// CGAL's GPL triangulation and lives in exbsp::gpl).
TEST(Section, core_section_is_the_capped_section_without_its_cap) {
  for (const section_plane& p : {section_plane{0, 0, 1, -0.5}, section_plane{1, 1, 1, -1.5},
                                 section_plane{0, 0, 1, 0}, section_plane{-1, -1, -1, 1}}) {
    const section_result core = exbsp::section(unit_cube(), p);
    const section_result capped = exbsp::section_with_cap(unit_cube(), p);
    EXPECT_TRUE(core.cap.empty());
    EXPECT_EQ(core.stats.cap_triangles, 0u);
    EXPECT_EQ(core.closed, capped.closed);
    ASSERT_EQ(core.kept.size(), capped.kept.size());
    for (std::size_t i = 0; i < core.kept.size(); ++i) {
      EXPECT_EQ(core.kept[i].face, capped.kept[i].face);
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(core.points[core.kept[i].p[k]].exact, capped.points[capped.kept[i].p[k]].exact);
    }
    ASSERT_EQ(core.outline.size(), capped.outline.size());
    for (std::size_t i = 0; i < core.outline.size(); ++i)
      EXPECT_EQ(core.outline[i].p.size(), capped.outline[i].p.size());
  }
  EXPECT_THROW(exbsp::section(unit_cube(), {0, 0, 0, 1}), exbsp::usage_error);
  EXPECT_THROW(exbsp::clip_soup(unit_cube(), {{0, 0, 0, 0}}), exbsp::usage_error);
}

// --- several planes (scenes) ---------------------------------------------------------------

TEST(Section, clip_soup_with_caps_stays_closed_and_cuts_earlier_caps) {
  triangle_soup s;
  add_box(s, {0, 0, 0}, {10, 10, 10});
  add_box(s, {2, 2, 2}, {8, 8, 8}, true);
  const std::vector<section_plane> planes{{0, 0, -1, 5}, {-1, 0, 0, 5}, {1, 1, 1, -3}};
  const triangle_soup c = exbsp::clip_soup_with_caps(s, planes);
  EXPECT_EQ(c.face_count, s.face_count + 3);
  // Rounded to doubles, but every point here is a dyadic rational with few bits: exact.
  const section_result r =
      exbsp::section_with_cap(c, {0, 0, 1, 100});  // keeps everything: re-reads c exactly
  expect_closed_section(r);
  std::set<std::uint32_t> cap_faces;
  for (const auto& t : c.triangles)
    if (t.face >= s.face_count) cap_faces.insert(t.face);
  EXPECT_EQ(cap_faces, (std::set<std::uint32_t>{s.face_count, s.face_count + 1, s.face_count + 2}));
  // Every cap triangle of plane 0 (z = 5) lies in the kept side of planes 1 and 2.
  for (const auto& t : c.triangles) {
    if (t.face != s.face_count) continue;
    for (std::uint32_t v : t.v) {
      const vec3d& p = c.vertices[v];
      EXPECT_EQ(p[2], 5);
      EXPECT_LE(p[0], 5);
      EXPECT_GE(p[0] + p[1] + p[2], 3);
    }
  }
  const triangle_soup nocap = exbsp::clip_soup(s, planes);
  EXPECT_EQ(nocap.face_count, s.face_count);
  for (const auto& t : nocap.triangles) EXPECT_LT(t.face, s.face_count);
}

// --- the CAD corpus ----------------------------------------------------------------------

class Corpus : public testing::TestWithParam<const char*> {};

TEST_P(Corpus, slanted_and_axis_cuts_through_the_middle_are_exact_and_closed) {
  const std::string path = std::string(EXBSP_SOURCE_DIR) + "/data/meshes/" + GetParam();
  EXBSP_NEED_CORPUS(fs::exists(path), path);
  const triangle_soup s = exbsp::read_mesh(path);
  vec3d lo = s.vertices[0], hi = s.vertices[0];
  for (const vec3d& v : s.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  const vec3d c{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  std::vector<double> xs;
  for (const vec3d& v : s.vertices) xs.push_back(v[0]);
  std::nth_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(xs.size() / 2), xs.end());
  const section_plane planes[] = {{0.3, -0.5, 0.8, -(0.3 * c[0] - 0.5 * c[1] + 0.8 * c[2])},
                                  {0, 0, 1, -c[2]},
                                  {1, 0, 0, -xs[xs.size() / 2]}};  // through a vertex
  for (const section_plane& p : planes) {
    SCOPED_TRACE(testing::Message() << p[0] << "," << p[1] << "," << p[2] << "," << p[3]);
    const section_result r = exbsp::section_with_cap(s, p);
    if (&p != &planes[2]) {  // (the vertex plane may contain a face, as for cube.off)
      EXPECT_GT(r.stats.split, 0u);
      EXPECT_FALSE(r.outline.empty());
    }
    if (&p == &planes[0])
      std::printf("[ info     ] %s: %s, %zu triangles, section %.3f s\n", GetParam(),
                  r.closed ? "closed" : "open", s.triangles.size(), r.stats.seconds);
    if (r.closed) {
      expect_closed_section(r);
      EXPECT_LT(cap_area2_along_n(r), 0);
    } else {
      EXPECT_TRUE(r.cap.empty());
    }
    expect_tiling(s, p);
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, Corpus,
                         testing::Values("fandisk.off", "cube.off", "sphere.off", "joint.off",
                                         "elephant.off", "cheese.off", "mech-holes-shark.off",
                                         "3torus.off", "blobby_3cc.off"),
                         [](const testing::TestParamInfo<const char*>& i) {
                           std::string n = i.param;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

// --- the command line ----------------------------------------------------------------------

using run_result = exbsp_test::cli_result;
const auto& slurp = exbsp_test::read_file;

class SectionCli : public exbsp_test::cli_fixture {
 protected:
  void SetUp() override {
    cli_fixture::SetUp();
    write("cube.off",
          "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
          "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n");
  }
};

TEST_F(SectionCli, json_has_kept_outline_and_cap_with_exact_rationals) {
  const run_result r = run("section cube.off --plane 0.1,0.2,1,-0.3");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("closed").get<bool>());
  ASSERT_FALSE(j.at("kept").empty());
  for (const auto& f : j.at("kept")) {
    EXPECT_TRUE(f.contains("face"));
    EXPECT_EQ(f.at("v").size(), 3u);
    EXPECT_EQ(f.at("exact").size(), 3u);
  }
  ASSERT_EQ(j.at("outline").size(), 1u);
  EXPECT_TRUE(j.at("outline")[0].at("closed").get<bool>());
  // On the plane exactly, with 0.1 and 0.2 and 0.3 meaning their doubles (not 1/10...).
  for (const auto& p : j.at("outline")[0].at("exact")) {
    q3 x;
    for (int k = 0; k < 3; ++k) x[k] = mpq_class(p[k].get<std::string>());
    EXPECT_EQ(plane_value({0.1, 0.2, 1, -0.3}, x), 0);
  }
  EXPECT_FALSE(j.at("cap").empty());
  // Every printed double is the nearest double of its exact rational (cut points included).
  for (const char* list : {"kept", "outline", "cap"})
    for (const auto& f : j.at(list))
      for (std::size_t i = 0; i < f.at("v").size(); ++i)
        for (int k = 0; k < 3; ++k) {
          mpq_class q(f.at("exact")[i][k].get<std::string>());
          q.canonicalize();
          EXPECT_EQ(q.get_str(), f.at("exact")[i][k].get<std::string>()) << "not reduced";
          EXPECT_EQ(exbsp::geom::rational_to_double(q.get_mpq_t()), f.at("v")[i][k].get<double>());
        }
  // A negative first number is a value, not an option.
  const run_result neg = run("section cube.off --plane -1,0,0,0.5");
  ASSERT_EQ(neg.status, 0) << neg.err;
  EXPECT_EQ(nlohmann::json::parse(neg.out).at("plane")[0], -1);
}

TEST_F(SectionCli, off_output_is_a_closed_mesh_and_svg_draws_the_loop) {
  ASSERT_EQ(run("section cube.off --plane 1,1,1,-1.5 -o cut.off").status, 0);
  const triangle_soup s = exbsp::read_mesh((dir / "cut.off").string());
  const section_result r = exbsp::section_with_cap(s, {0, 0, 1, 100});
  EXPECT_TRUE(r.closed);
  const run_result svg = run("section cube.off --plane 1,1,1,-1.5 -o cut.svg");
  ASSERT_EQ(svg.status, 0) << svg.err;
  const std::string text = slurp(dir / "cut.svg");
  EXPECT_NE(text.find("<path id=\"cap\""), std::string::npos);
  EXPECT_NE(text.find(" Z"), std::string::npos);
}

TEST_F(SectionCli, bad_input_exits_2_names_the_option_and_writes_nothing) {
  const std::size_t before = file_count();
  for (const char* args :
       {"section cube.off --plane 0,0,1 -o a.json", "section cube.off --plane 0,0,0,1 -o a.json",
        "section cube.off --plane 0,0,1,nan -o a.json",
        "section cube.off --plane 0,0,1,x -o a.json",
        "section cube.off --plane 0,0,1,1,2 -o a.json", "section cube.off -o a.json",
        "section cube.off --plane 0,0,1,0 -o a.txt"}) {
    SCOPED_TRACE(args);
    const run_result r = run(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
    EXPECT_TRUE(r.err.find("--plane") != std::string::npos ||
                r.err.find("--output") != std::string::npos)
        << r.err;
    EXPECT_EQ(file_count(), before);
  }
  std::ofstream(dir / "bad.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n";
  const run_result r = run("section bad.off --plane 0,0,1,0 -o a.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.off"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "a.json"));
}

// --- scenes: "clip_planes" and "caps" ----------------------------------------------------

/// Writes the box [lo, hi] (outward) as an OFF file.
void write_box_off(const fs::path& path, const vec3d& lo, const vec3d& hi) {
  triangle_soup s;
  add_box(s, lo, hi);
  exbsp_test::write_file(path, exbsp_test::off_text(s));
}

class SectionScene : public SectionCli {
 protected:
  /// A scene of a grey cube [0,1]^3 and a blue slab crossing it, seen from above in glOrtho,
  /// with `extra` spliced in (clip planes, caps).
  std::string scene_text(const std::string& extra) {
    write_box_off(dir / "box.off", {0, 0, 0}, {1, 1, 1});
    write_box_off(dir / "slab.off", {-0.5, 0.4, 0.2}, {1.5, 0.6, 0.4});
    return R"({"meshes": [{"file": "box.off", "color": [100, 100, 100]}, {"file": "slab.off", "color": [0, 0, 255]}],
 "camera": {"eye": [0.5, 0.5, 5], "look_at": [0.5, 0.5, 0], "up": [0, 1, 0]},
 "projection": {"type": "orthographic", "left": -1, "right": 1, "bottom": -1, "top": 1, "near": 1, "far": 10},
 "viewport": {"width": 200, "height": 200}, "background": [255, 255, 255])" +
           extra + "}";
  }
  /// The key of the scene_error that parsing `extra` raises ("(no error)" when it parses).
  std::string error_key(const std::string& extra) {
    return exbsp_test::error_key(
        [&] { exbsp::scene::parse_scene_text(scene_text(extra), (dir / "s.json").string()); });
  }
};

TEST_F(SectionScene, bad_clip_planes_and_caps_name_their_key) {
  EXPECT_EQ(error_key(R"(, "clip_planes": [[0, 0, -1, 0.5]], "caps": {"color": [255, 0, 0]})"),
            "(no error)");
  EXPECT_EQ(error_key(R"(, "clip_planes": 3)"), "/clip_planes");
  EXPECT_EQ(
      error_key(
          R"(, "clip_planes": [[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0]])"),
      "/clip_planes");
  EXPECT_EQ(error_key(R"(, "clip_planes": [[0, 0, 1, 0], [0, 0, 1]])"), "/clip_planes/1");
  EXPECT_EQ(error_key(R"(, "clip_planes": [[0, 0, 1, 0], [0, 0, 1, "x"]])"), "/clip_planes/1/3");
  EXPECT_EQ(error_key(R"(, "clip_planes": [[0, 0, 0, 1]])"), "/clip_planes/0");
  EXPECT_EQ(error_key(R"(, "clip_planes": [[0, 0, 1, 1e999]])"),
            "");  // a JSON syntax error: a scene_error without a key
  EXPECT_EQ(error_key(R"(, "clip_planes": [[0, 0, 1, 0]], "caps": 1)"), "/caps");
  EXPECT_EQ(error_key(R"(, "clip_planes": [[0, 0, 1, 0]], "caps": {"color": [256, 0, 0]})"),
            "/caps/color/0");
}

TEST_F(SectionScene, bad_scene_exits_2_naming_the_key_and_writes_nothing) {
  std::ofstream(dir / "bad.json") << scene_text(R"(, "clip_planes": [[0, 0, 0, 1]])");
  const run_result r = run("render bad.json -o out.png");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/clip_planes/0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST_F(SectionScene, geometry_is_cut_with_caps_in_their_colour_and_stays_closed) {
  const auto s = exbsp::scene::parse_scene_text(
      scene_text(
          R"(, "clip_planes": [[0, 0, -1, 0.5], [1, 0, 0, -0.25]], "caps": {"color": [255, 0, 0]})"),
      (dir / "s.json").string());
  const exbsp::scene::scene_geometry g = exbsp::scene::load_geometry(s);
  // box: 12 triangle faces + 2 caps; slab: 12 + 2 (the slab is cut by x >= 0.25 too).
  ASSERT_EQ(g.soup.face_count, 28u);
  EXPECT_EQ(g.face_offsets, (std::vector<std::uint32_t>{0, 14, 28}));
  for (std::uint32_t f : {12u, 13u, 26u, 27u})
    EXPECT_EQ(g.face_colors[f], (exbsp::view::rgb8{255, 0, 0})) << f;
  for (std::uint32_t f : {0u, 11u})
    EXPECT_EQ(g.face_colors[f], (exbsp::view::rgb8{100, 100, 100})) << f;
  EXPECT_EQ(g.face_colors[14], (exbsp::view::rgb8{0, 0, 255}));
  for (const auto& t : g.soup.triangles)
    for (std::uint32_t v : t.v) {
      EXPECT_LE(g.soup.vertices[v][2], 0.5);
      EXPECT_GE(g.soup.vertices[v][0], 0.25);
    }
  // Dyadic coordinates round exactly: the soup read back is closed, caps and all.
  expect_closed_section(exbsp::section_with_cap(g.soup, {0, 0, 1, 100}));
}

TEST_F(SectionScene, cut_part_renders_in_one_bsp_with_an_uncut_intersecting_part) {
  std::ofstream(dir / "s.json") << scene_text(
      R"(, "clip_planes": [[0, 0, -1, 0.5]], "caps": {"color": [255, 0, 0]})");
  std::ostringstream log;
  exbsp::render_command({(dir / "s.json").string(), (dir / "s.png").string(), false}, log);
  const exbsp::view::image img = exbsp::view::read_png((dir / "s.png").string());
  // Pixel (i, j) sees world (x, y) = (i/100 - 0.5, j/100 - 0.5) from above.
  const exbsp::view::rgb8 cap{255, 0, 0}, slab{0, 0, 255}, white{255, 255, 255};
  EXPECT_EQ(img.pixel(100, 100), cap);  // the cap hides the slab inside the box
  EXPECT_EQ(img.pixel(75, 75), cap);
  EXPECT_EQ(img.pixel(25, 100), slab);  // the slab outside the box, uncut
  EXPECT_EQ(img.pixel(175, 100), slab);
  EXPECT_EQ(img.pixel(180, 180), white);
  // Without caps the open box shows its inside: the slab through it and the floor.
  std::ofstream(dir / "n.json") << scene_text(R"(, "clip_planes": [[0, 0, -1, 0.5]])");
  exbsp::render_command({(dir / "n.json").string(), (dir / "n.png").string(), false}, log);
  const exbsp::view::image open = exbsp::view::read_png((dir / "n.png").string());
  EXPECT_EQ(open.pixel(100, 100), slab);
  EXPECT_EQ(open.pixel(75, 75), (exbsp::view::rgb8{100, 100, 100}));
}

TEST(SectionSceneExample, example_scene_renders) {
  const std::string path = std::string(EXBSP_SOURCE_DIR) + "/scenes/section.json";
  const auto s = exbsp::scene::load_scene(path);
  EXPECT_EQ(s.clip_planes.size(), 2u);
  EXPECT_TRUE(s.caps);
  const exbsp::scene::scene_geometry g = exbsp::scene::load_geometry(s);
  EXPECT_GT(g.soup.face_count, g.face_offsets.size());
}

}  // namespace
