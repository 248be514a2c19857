// SPDX-License-Identifier: GPL-3.0-or-later
// The geometry floor's outward-closed certificate (geom/closed_shells.h): meshes whose back
// faces no outside viewer sees. Degenerate cases first (flat, one-ulp, touching, folded,
// inverted, open); then CGAL's Polygon_mesh_processing (GPL, test-only) as the independent
// oracle on the CGAL corpus.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <exbsp/mesh/mesh_io.h>
#include "geom/closed_shells.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp;
using exbsp_test::add_box;
using exbsp_test::add_quad;
using geom::shell_verdict;

triangle_soup box(const vec3d& lo = {0, 0, 0}, const vec3d& hi = {1, 1, 1}) {
  triangle_soup s;
  add_box(s, lo, hi);
  return s;
}

void reverse_all(triangle_soup& s, std::size_t first = 0) {
  for (std::size_t t = first; t < s.triangles.size(); ++t)
    std::swap(s.triangles[t].v[1], s.triangles[t].v[2]);
}

shell_verdict verdict(const triangle_soup& s) {
  std::vector<std::uint32_t> all(s.triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<std::uint32_t>(t);
  return geom::shell_verdict_of(s, all);
}

/// A tetrahedron over the base (0,0,0), (1,0,0), (0,1,0) (turned to -z) with apex (0.3, 0.3, h):
/// outward for h > 0, inward for h < 0, flat and folded onto its base for h = 0.
triangle_soup tetrahedron(double h) {
  triangle_soup s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, h}};
  s.add_polygon({0, 2, 1}, 0);
  s.add_polygon({0, 1, 3}, 1);
  s.add_polygon({1, 2, 3}, 2);
  s.add_polygon({2, 0, 3}, 3);
  return s;
}

TEST(ClosedShells, AnOutwardBoxIsCertifiedAndItsReverseIsNot) {
  EXPECT_EQ(verdict(box()), shell_verdict::outward_closed);
  triangle_soup inward = box();
  reverse_all(inward);
  EXPECT_EQ(verdict(inward), shell_verdict::not_outward);
}

TEST(ClosedShells, OpenOrInconsistentlyTurnedBoxesAreNotClosed) {
  triangle_soup open = box();
  open.triangles.resize(open.triangles.size() - 2);  // the +x quad left out
  EXPECT_EQ(verdict(open), shell_verdict::not_closed);
  triangle_soup flipped = box();
  std::swap(flipped.triangles[3].v[1], flipped.triangles[3].v[2]);  // one triangle turned
  EXPECT_EQ(verdict(flipped), shell_verdict::not_closed);
  EXPECT_EQ(verdict(triangle_soup{}), shell_verdict::empty);
}

TEST(ClosedShells, ADegenerateTriangleRefusesTheMesh) {
  triangle_soup s = box();
  const auto base = static_cast<std::uint32_t>(s.vertices.size());
  s.vertices.insert(s.vertices.end(), {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}});  // on one line
  s.add_polygon({base, base + 1, base + 2}, 99);
  EXPECT_EQ(verdict(s), shell_verdict::degenerate_triangle);
  triangle_soup far = box();
  far.vertices[0][0] = std::numeric_limits<double>::infinity();  // no plane through it
  EXPECT_EQ(verdict(far), shell_verdict::degenerate_triangle);
}

TEST(ClosedShells, FlatTetrahedraOneUlpEitherSideOfTheirBaseAreDecidedExactly) {
  // The smallest positive double as the apex height: the volume underflows in double, only
  // the exact sum decides its sign.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(verdict(tetrahedron(tiny)), shell_verdict::outward_closed);
  EXPECT_EQ(verdict(tetrahedron(-tiny)), shell_verdict::not_outward);
  EXPECT_EQ(verdict(tetrahedron(std::nextafter(1.0, 2.0) - 1)), shell_verdict::outward_closed);
  EXPECT_EQ(verdict(tetrahedron(1)), shell_verdict::outward_closed);
  // Apex in the base's plane: the three sides fold onto the base (coplanar, overlapping).
  EXPECT_EQ(verdict(tetrahedron(0)), shell_verdict::self_intersecting);
}

TEST(ClosedShells, APillowOfTwoOppositeTrianglesIntersectsItself) {
  triangle_soup s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.add_polygon({0, 1, 2}, 0);
  s.add_polygon({0, 2, 1}, 1);
  EXPECT_EQ(verdict(s), shell_verdict::self_intersecting);
}

TEST(ClosedShells, AVertexPushedThroughTheOppositeFaceIntersects) {
  // A box whose top is a fan of four triangles to a centre pushed below the bottom: each fan
  // triangle shares corners with bottom triangles and crosses them away from those corners.
  for (double z : {-0.5, 0.0, 0.5}) {
    triangle_soup s;
    const vec3d c{0.5, 0.5, z};
    const auto quad = [&](const vec3d& a, const vec3d& b, const vec3d& cc, const vec3d& d) {
      add_quad(s, a, b, cc, d);
    };
    quad({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0});
    quad({0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1});
    quad({0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0});
    quad({0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0});
    quad({1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1});
    const std::array<vec3d, 4> top{{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
    for (int k = 0; k < 4; ++k) {
      const auto base = static_cast<std::uint32_t>(s.vertices.size());
      s.vertices.insert(s.vertices.end(), {top[k], top[(k + 1) % 4], c});
      s.add_polygon({base, base + 1, base + 2}, 10 + static_cast<std::uint32_t>(k));
    }
    // Centre above the bottom (0.5): a dented box, certified; on it (0): the fan touches the
    // bottom's diagonal; below it: through the bottom.
    EXPECT_EQ(verdict(s), z > 0 ? shell_verdict::outward_closed : shell_verdict::self_intersecting)
        << "centre at z = " << z;
  }
}

TEST(ClosedShells, SeparateShellsEachCountAndTouchingAtAVertexIsAllowed) {
  triangle_soup two = box();
  add_box(two, {3, 0, 0}, {4, 1, 1});
  EXPECT_EQ(verdict(two), shell_verdict::outward_closed);
  // A small inward shell beside a large outward one: the total volume is positive, the small
  // shell's is not (its inside would have winding number -1).
  triangle_soup mixed = box({0, 0, 0}, {10, 10, 10});
  const std::size_t first = mixed.triangles.size();
  add_box(mixed, {20, 0, 0}, {21, 1, 1});
  reverse_all(mixed, first);
  EXPECT_EQ(verdict(mixed), shell_verdict::not_outward);
  // Boxes meeting at one corner only, and two interpenetrating boxes.
  triangle_soup corner = box();
  add_box(corner, {1, 1, 1}, {2, 2, 2});
  EXPECT_EQ(verdict(corner), shell_verdict::outward_closed);
  triangle_soup clash = box();
  add_box(clash, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  EXPECT_EQ(verdict(clash), shell_verdict::self_intersecting);
  // Boxes sharing one edge: four triangles at it (each direction used twice).
  triangle_soup edge = box();
  add_box(edge, {1, 1, 0}, {2, 2, 1});
  EXPECT_EQ(verdict(edge), shell_verdict::not_closed);
}

TEST(ClosedShells, MeshesAreJudgedOneByOneAsTheFrameAssignsFaces) {
  triangle_soup s = box();                                  // mesh 0: faces 0..5
  add_quad(s, {5, 0, 0}, {6, 0, 0}, {6, 1, 0}, {5, 1, 0});  // mesh 1: face 6, open
  add_box(s, {8, 0, 0}, {9, 1, 1});                         // mesh 2: faces 7..12
  EXPECT_EQ(geom::outward_closed_meshes(s, {0, 6, 7, 13}), (std::vector<std::uint8_t>{1, 0, 1}));
  EXPECT_EQ(geom::outward_closed_meshes(s, {}), (std::vector<std::uint8_t>{0}));
  // Two boxes that clash, in separate meshes: each is certified on its own.
  triangle_soup clash = box();
  add_box(clash, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  EXPECT_EQ(geom::outward_closed_meshes(clash, {0, 6, 12}), (std::vector<std::uint8_t>{1, 1}));
}

// ---- the CGAL corpus against CGAL's own tests (GPL, in the tests only) ----------------------

TEST(ClosedShells, TheCorpusAgreesWithPolygonMeshProcessing) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using mesh = CGAL::Surface_mesh<K::Point_3>;
  namespace PMP = CGAL::Polygon_mesh_processing;
  int compared = 0, certified = 0;
  for (const char* name : {"cube",
                           "joint",
                           "pinion",
                           "couplingdown",
                           "fandisk",
                           "bunny00",
                           "refined_elephant",
                           "cross",
                           "anchor_dense",
                           "rotor",
                           "spool",
                           "blade",
                           "turbine",
                           "elephant",
                           "tripod",
                           "blobby_3cc",
                           "open_cube",
                           "elephant-with-holes",
                           "eight",
                           "knot1",
                           "double-torus-example",
                           "cube-meshed",
                           "tetra_intersected_by_triangle",
                           "fold",
                           "mech-holes-shark"}) {
    const std::string path = exbsp_test::corpus_dir() + name + ".off";
    mesh m;
    if (!PMP::IO::read_polygon_mesh(path, m)) continue;  // missing or not a polygon mesh
    PMP::triangulate_faces(m);
    const triangle_soup soup = read_mesh(path);
    std::vector<std::uint32_t> all(soup.triangles.size());
    for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<std::uint32_t>(t);
    const shell_verdict v = geom::shell_verdict_of(soup, all);
    // The oracle: closed, no self-intersection, and every connected component outward.
    bool oracle = CGAL::is_closed(m) && !PMP::does_self_intersect(m);
    if (oracle) {
      auto fcc = m.add_property_map<mesh::Face_index, std::size_t>("f:cc").first;
      const std::size_t n = PMP::connected_components(m, fcc);
      for (std::size_t c = 0; c < n && oracle; ++c) {
        mesh part;
        std::vector<std::size_t> keep{c};
        part = m;
        auto pfcc = part.property_map<mesh::Face_index, std::size_t>("f:cc").first;
        PMP::keep_connected_components(part, keep, pfcc);
        part.collect_garbage();
        oracle = PMP::is_outward_oriented(part);
      }
    }
    EXPECT_EQ(v == shell_verdict::outward_closed, oracle)
        << name << ": verdict " << static_cast<int>(v);
    ++compared;
    certified += v == shell_verdict::outward_closed;
  }
  EXBSP_NEED_CORPUS(compared >= 8, "the CGAL corpus");
  EXPECT_GE(certified, 5);
}

}  // namespace
