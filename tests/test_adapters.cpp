// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the mesh adapters (src/adapters/): OpenMesh TriMesh / PolyMesh and CGAL FaceGraphs
// (Surface_mesh, Polyhedron_3) to a triangle_soup (fan triangulation and face ids as
// docs/contract.md section 2), and BSP fragments and sections back to those meshes (face ids kept,
// every triangle a face, shared vertices where the mesh allows). Degenerate cases first.
#include <gtest/gtest.h>

// OpenMesh's PropertyT::push_back copies an uninitialised VectorT; GCC 12 reports that
// (-Wmaybe-uninitialized) wherever the template is instantiated (as in test_mesh.cpp).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#pragma GCC diagnostic pop

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include <exbsp/adapters/cgal_face_graph.h>
#include <exbsp/adapters/openmesh.h>
#include <exbsp/bsp/engine.h>
#include <exbsp/clip/section.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/soup.h>

namespace {

using exbsp::triangle_soup;
using exbsp::vec3d;

struct double_traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<double_traits>;
using tri_mesh = OpenMesh::TriMesh_ArrayKernelT<double_traits>;
using float_poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<>;  // float points

using epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using surface_mesh = CGAL::Surface_mesh<epick::Point_3>;
using polyhedron = CGAL::Polyhedron_3<epick>;

// The unit cube's corners and its six quads, outward (as scene::make_box).
const std::array<vec3d, 8> cube_corners{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
const std::array<std::array<int, 4>, 6> cube_quads{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

template <class Mesh>
Mesh openmesh_cube(const vec3d& shift = {0, 0, 0}) {
  Mesh m;
  std::vector<typename Mesh::VertexHandle> v;
  for (const vec3d& p : cube_corners)
    v.push_back(
        m.add_vertex(typename Mesh::Point(p[0] + shift[0], p[1] + shift[1], p[2] + shift[2])));
  for (const auto& q : cube_quads) m.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  return m;
}

template <class FaceGraph>
FaceGraph cgal_cube() {
  FaceGraph g;
  using vd = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  auto points = get(CGAL::vertex_point, g);
  std::vector<vd> v;
  for (const vec3d& p : cube_corners) {
    v.push_back(add_vertex(g));
    put(points, v.back(), epick::Point_3(p[0], p[1], p[2]));
  }
  for (const auto& q : cube_quads)
    CGAL::Euler::add_face(std::array<vd, 4>{v[q[0]], v[q[1]], v[q[2]], v[q[3]]}, g);
  return g;
}

// The soup's triangles as corner coordinates with face ids, for comparisons.
std::vector<std::pair<std::uint32_t, std::array<vec3d, 3>>> triangles_of(const triangle_soup& s) {
  std::vector<std::pair<std::uint32_t, std::array<vec3d, 3>>> out;
  for (const auto& t : s.triangles)
    out.push_back({t.face, {s.vertices[t.v[0]], s.vertices[t.v[1]], s.vertices[t.v[2]]}});
  return out;
}

// The cube as exbsp's own soup: the reference for the adapters.
triangle_soup soup_cube() {
  triangle_soup s;
  s.vertices.assign(cube_corners.begin(), cube_corners.end());
  std::uint32_t f = 0;
  for (const auto& q : cube_quads)
    s.add_polygon(
        {std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2]), std::uint32_t(q[3])}, f++);
  s.face_count = f;
  return s;
}

// ---- OpenMesh -> soup ----

TEST(OpenMeshToSoup, EmptyMeshGivesEmptySoup) {
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(poly_mesh{});
  EXPECT_TRUE(s.vertices.empty());
  EXPECT_TRUE(s.triangles.empty());
  EXPECT_EQ(s.face_count, 0u);
  EXPECT_EQ(s.source, "OpenMesh mesh");
}

TEST(OpenMeshToSoup, IsolatedVerticesAreKeptUnused) {
  poly_mesh m;
  m.add_vertex({1, 2, 3});
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(m, "points");
  ASSERT_EQ(s.vertices.size(), 1u);
  EXPECT_EQ(s.vertices[0], (vec3d{1, 2, 3}));
  EXPECT_TRUE(s.triangles.empty());
}

TEST(OpenMeshToSoup, NonFiniteCoordinateIsInputErrorNamingTheMesh) {
  poly_mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({std::numeric_limits<double>::quiet_NaN(), 0, 0});
  try {
    exbsp::openmesh::soup_from_mesh(m, "part.om");
    FAIL();
  } catch (const exbsp::input_error& e) {
    EXPECT_EQ(e.file(), "part.om");
    EXPECT_NE(std::string(e.what()).find("vertex 1"), std::string::npos) << e.what();
  }
}

TEST(OpenMeshToSoup, DegenerateFacesAreKeptAndCountedByTheBuild) {
  // A collinear triangle and a quad with three collinear corners: both stay in the soup; the
  // build skips and counts the one exactly degenerate triangle.
  poly_mesh m;
  const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({2, 0, 0});
  const auto d = m.add_vertex({0, 0, 1}), e = m.add_vertex({1, 0, 1}), f = m.add_vertex({2, 1, 1});
  ASSERT_TRUE(m.add_face(a, b, c).is_valid());
  ASSERT_TRUE(m.add_face(d, e, f, m.add_vertex({0, 1, 1})).is_valid());
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(m);
  EXPECT_EQ(s.face_count, 2u);
  ASSERT_EQ(s.triangles.size(), 3u);
  const exbsp::bsp tree = exbsp::bsp::build(s);
  EXPECT_EQ(tree.stats().input_triangles, 3u);
  EXPECT_EQ(tree.stats().degenerate_input, 1u);
  EXPECT_EQ(tree.stats().fragments, 2u);
}

TEST(OpenMeshToSoup, PolygonsAreFanTriangulatedWithFaceIds) {
  // A pentagon, a triangle and a quad: 3 + 1 + 2 triangles, fans from each face's first corner.
  poly_mesh m;
  std::vector<poly_mesh::VertexHandle> v;
  for (int i = 0; i < 5; ++i)
    v.push_back(m.add_vertex({std::cos(i * 1.2566), std::sin(i * 1.2566), 0}));
  const auto p = m.add_vertex({0, 0, 3}), q = m.add_vertex({1, 0, 3}), r = m.add_vertex({1, 1, 3}),
             t = m.add_vertex({0, 1, 3});
  const auto u = m.add_vertex({5, 5, 5});
  m.add_face(std::vector<poly_mesh::VertexHandle>(v.begin(), v.end()));
  m.add_face(p, q, u);
  m.add_face(t, p, r, m.add_vertex({-1, 2, 3}));
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(m);
  ASSERT_EQ(s.face_count, 3u);
  ASSERT_EQ(s.triangles.size(), 3u + 1u + 2u);
  // Reference: the same polygons through triangle_soup::add_polygon (docs/contract.md "Input").
  triangle_soup ref;
  ref.vertices = s.vertices;
  for (const auto f : m.faces()) {
    std::vector<std::uint32_t> corners;
    for (const auto vh : m.fv_range(f)) corners.push_back(static_cast<std::uint32_t>(vh.idx()));
    ref.add_polygon(corners, static_cast<std::uint32_t>(f.idx()));
  }
  EXPECT_EQ(triangles_of(s), triangles_of(ref));
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(s.triangles[i].face, 0u);
  EXPECT_EQ(s.triangles[3].face, 1u);
  EXPECT_EQ(s.triangles[4].face, 2u);
  EXPECT_EQ(s.triangles[5].face, 2u);
}

TEST(OpenMeshToSoup, FloatPointsWidenExactlyAndTriMeshWorks) {
  const float_poly_mesh fm = openmesh_cube<float_poly_mesh>({0.1, 0, 0});
  const triangle_soup fs = exbsp::openmesh::soup_from_mesh(fm);
  EXPECT_EQ(fs.vertices[0][0], static_cast<double>(0.1f));  // the float's value, not 0.1
  EXPECT_EQ(fs.triangles.size(), 12u);

  tri_mesh tm;
  const auto a = tm.add_vertex({0, 0, 0}), b = tm.add_vertex({1, 0, 0}),
             c = tm.add_vertex({0, 1, 0});
  tm.add_face(a, b, c);
  const triangle_soup ts = exbsp::openmesh::soup_from_mesh(tm);
  ASSERT_EQ(ts.triangles.size(), 1u);
  EXPECT_EQ(ts.triangles[0].v, (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST(OpenMeshToSoup, DeletedFacesAreSkippedAndIdsAreHandleIndices) {
  poly_mesh m = openmesh_cube<poly_mesh>();
  m.request_face_status();
  m.request_edge_status();
  m.request_vertex_status();
  m.delete_face(poly_mesh::FaceHandle(1), false);
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(m);
  EXPECT_EQ(s.triangles.size(), 10u);
  std::set<std::uint32_t> faces;
  for (const auto& t : s.triangles) faces.insert(t.face);
  EXPECT_EQ(faces, (std::set<std::uint32_t>{0, 2, 3, 4, 5}));
}

TEST(OpenMeshToSoup, CubeMatchesExbspsOwnSoup) {
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(openmesh_cube<poly_mesh>());
  EXPECT_EQ(triangles_of(s), triangles_of(soup_cube()));
}

// ---- fragments and sections -> OpenMesh ----

// Face ids of `m` in face order, and the corners of each face.
template <class Mesh>
std::vector<std::pair<std::uint32_t, std::array<vec3d, 3>>> openmesh_triangles(const Mesh& m) {
  OpenMesh::FPropHandleT<std::uint32_t> ids;
  EXPECT_TRUE(m.get_property_handle(ids, exbsp::openmesh::face_id_property));
  std::vector<std::pair<std::uint32_t, std::array<vec3d, 3>>> out;
  for (const auto f : m.faces()) {
    std::array<vec3d, 3> c{};
    int k = 0;
    for (const auto v : m.fv_range(f)) {
      const auto p = m.point(v);
      if (k < 3) c[k] = {p[0], p[1], p[2]};
      ++k;
    }
    EXPECT_EQ(k, 3);
    out.push_back({m.property(ids, f), c});
  }
  return out;
}

// The same triangles up to a cyclic shift of each one's corners (OpenMesh may start a face's
// corner cycle elsewhere).
bool same_up_to_rotation(const std::array<vec3d, 3>& a, const std::array<vec3d, 3>& b) {
  for (int s = 0; s < 3; ++s)
    if (a[0] == b[s] && a[1] == b[(s + 1) % 3] && a[2] == b[(s + 2) % 3]) return true;
  return false;
}

template <class Mesh>
void expect_mesh_holds_fragments(const Mesh& m, const std::vector<exbsp::fragment_d>& frags,
                                 const std::vector<std::uint32_t>& order) {
  const auto got = openmesh_triangles(m);
  ASSERT_EQ(got.size(), order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    EXPECT_EQ(got[k].first, frags[order[k]].face) << "face " << k;
    EXPECT_TRUE(same_up_to_rotation(got[k].second, frags[order[k]].v)) << "face " << k;
  }
}

TEST(OpenMeshFromExbsp, NoFragmentsAddNothingButTheProperty) {
  tri_mesh m;
  exbsp::openmesh::append_fragments(m, {});
  EXPECT_EQ(m.n_faces(), 0u);
  OpenMesh::FPropHandleT<std::uint32_t> ids;
  EXPECT_TRUE(m.get_property_handle(ids, exbsp::openmesh::face_id_property));
}

TEST(OpenMeshFromExbsp, CoincidentCornersGetTheirOwnVertices) {
  exbsp::triangle_list list;
  list.corners.push_back({vec3d{0, 0, 0}, vec3d{0, 0, 0}, vec3d{1, 0, 0}});  // two corners equal
  list.corners.push_back({vec3d{0, 0, 0}, vec3d{1, 0, 0}, vec3d{0, 1, 0}});
  list.faces = {7, 8};
  poly_mesh m;
  const auto ids = exbsp::openmesh::append_triangles(m, list);
  ASSERT_EQ(m.n_faces(), 2u);
  EXPECT_EQ(m.property(ids, poly_mesh::FaceHandle(0)), 7u);
  EXPECT_EQ(m.property(ids, poly_mesh::FaceHandle(1)), 8u);
  EXPECT_EQ(m.n_vertices(), 3u + 3u);  // the degenerate one's own three, then 3 shared
}

TEST(OpenMeshFromExbsp, OrderOutOfRangeIsUsageError) {
  tri_mesh m;
  EXPECT_THROW(exbsp::openmesh::append_fragments(m, {}, {0}), exbsp::usage_error);
}

TEST(OpenMeshFromExbsp, CubeRoundTripIsClosedWithSharedVertices) {
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(openmesh_cube<poly_mesh>());
  const exbsp::bsp tree = exbsp::bsp::build(s);
  const auto frags = tree.fragments_double();
  const auto order = tree.order_from_eye({3, 4, 5});
  tri_mesh m;
  exbsp::openmesh::append_fragments(m, frags, order);
  expect_mesh_holds_fragments(m, frags, order);
  EXPECT_EQ(m.n_vertices(), 8u);
  for (const auto h : m.halfedges()) EXPECT_FALSE(m.is_boundary(h));
  // And back again: the same soup triangles, face ids included (up to triangle order).
  const triangle_soup again = exbsp::openmesh::soup_from_mesh(m);
  EXPECT_EQ(again.triangles.size(), 12u);
}

TEST(OpenMeshFromExbsp, IntersectingCubesGiveEveryFragmentAFace) {
  // Two interpenetrating cubes: the BSP splits faces, and fragments meet along non-manifold
  // edges; every fragment still becomes a face with its face id.
  triangle_soup s = exbsp::openmesh::soup_from_mesh(openmesh_cube<poly_mesh>());
  s.append(exbsp::openmesh::soup_from_mesh(openmesh_cube<poly_mesh>({0.5, 0.25, 0.125})));
  const exbsp::bsp tree = exbsp::bsp::build(s);
  ASSERT_GT(tree.stats().splits, 0u);
  const auto frags = tree.fragments_double();
  std::vector<std::uint32_t> all(frags.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
  poly_mesh m;
  exbsp::openmesh::append_fragments(m, frags);
  expect_mesh_holds_fragments(m, frags, all);
}

TEST(OpenMeshFromExbsp, SectionOfCubeIsClosedWithCapFace) {
  const triangle_soup s = exbsp::openmesh::soup_from_mesh(openmesh_cube<poly_mesh>());
  const exbsp::section_result r = exbsp::section_with_cap(s, {1, 1, 1, -1.5});  // a hexagonal cut
  ASSERT_TRUE(r.closed);
  ASSERT_FALSE(r.cap.empty());
  tri_mesh m;
  const auto ids = exbsp::openmesh::append_section(m, r);
  EXPECT_EQ(m.n_faces(), r.kept.size() + r.cap.size());
  for (const auto h : m.halfedges()) EXPECT_FALSE(m.is_boundary(h));
  std::size_t caps = 0;
  for (const auto f : m.faces()) {
    const std::uint32_t id = m.property(ids, f);
    EXPECT_LE(id, r.cap_face);
    caps += id == r.cap_face;
  }
  EXPECT_EQ(caps, r.cap.size());
  EXPECT_EQ(r.cap_face, 6u);
}

// ---- CGAL FaceGraph -> soup ----

TEST(CgalToSoup, EmptyGraphGivesEmptySoup) {
  const triangle_soup s = exbsp::cgal::soup_from_face_graph(surface_mesh{});
  EXPECT_TRUE(s.triangles.empty());
  EXPECT_EQ(s.face_count, 0u);
}

TEST(CgalToSoup, SurfaceMeshCubeMatchesExbspsOwnSoup) {
  const triangle_soup s = exbsp::cgal::soup_from_face_graph(cgal_cube<surface_mesh>());
  EXPECT_EQ(s.face_count, 6u);
  EXPECT_EQ(triangles_of(s), triangles_of(soup_cube()));
}

TEST(CgalToSoup, PolyhedronCubeHasTheSameTrianglesAndFaceIds) {
  const polyhedron p = cgal_cube<polyhedron>();
  const triangle_soup s = exbsp::cgal::soup_from_face_graph(p, "cube polyhedron");
  EXPECT_EQ(s.source, "cube polyhedron");
  EXPECT_EQ(s.face_count, 6u);
  ASSERT_EQ(s.triangles.size(), 12u);
  // Polyhedron_3 may start each face's corner cycle at another corner: compare per face the
  // set of corners, and the fan shape (two triangles per quad, sharing the first corner).
  const triangle_soup ref = soup_cube();
  for (std::uint32_t f = 0; f < 6; ++f) {
    std::set<vec3d> mine, theirs;
    for (const auto& t : triangles_of(s))
      if (t.first == f) mine.insert(t.second.begin(), t.second.end());
    for (const auto& t : triangles_of(ref))
      if (t.first == f) theirs.insert(t.second.begin(), t.second.end());
    EXPECT_EQ(mine, theirs) << "face " << f;
    EXPECT_EQ(s.triangles[2 * f].v[0], s.triangles[2 * f + 1].v[0]);
  }
}

TEST(CgalToSoup, DegenerateFaceIsKeptAndCountedByTheBuild) {
  surface_mesh g;
  const auto a = g.add_vertex({0, 0, 0}), b = g.add_vertex({1, 1, 1}), c = g.add_vertex({2, 2, 2});
  const auto d = g.add_vertex({0, 0, 5}), e = g.add_vertex({1, 0, 5}), f = g.add_vertex({0, 1, 5});
  g.add_face(a, b, c);
  g.add_face(d, e, f);
  const triangle_soup s = exbsp::cgal::soup_from_face_graph(g);
  ASSERT_EQ(s.triangles.size(), 2u);
  const exbsp::bsp tree = exbsp::bsp::build(s);
  EXPECT_EQ(tree.stats().degenerate_input, 1u);
  EXPECT_EQ(tree.stats().fragments, 1u);
  EXPECT_EQ(tree.fragment(0).face, 1u);
}

TEST(CgalToSoup, EpeckPointsMadeFromDoublesConvertExactly) {
  CGAL::Surface_mesh<CGAL::Epeck::Point_3> g;
  const auto a = g.add_vertex({0.1, 0.2, 0.3}), b = g.add_vertex({1, 0, 0}),
             c = g.add_vertex({0, 1, 0});
  g.add_face(a, b, c);
  const triangle_soup s = exbsp::cgal::soup_from_face_graph(g);
  EXPECT_EQ(s.vertices[0], (vec3d{0.1, 0.2, 0.3}));
}

// ---- fragments and sections -> CGAL ----

TEST(CgalFromExbsp, SurfaceMeshRoundTripKeepsFaceIdsAndIsClosed) {
  const triangle_soup s = exbsp::cgal::soup_from_face_graph(cgal_cube<surface_mesh>());
  const exbsp::bsp tree = exbsp::bsp::build(s);
  const auto frags = tree.fragments_double();
  const auto order = tree.order_for_direction({-1, -2, -3});
  surface_mesh out;
  auto ids =
      out.add_property_map<surface_mesh::Face_index, std::uint32_t>("f:exbsp_face_id", 0).first;
  exbsp::cgal::append_fragments(out, frags, ids, order);
  ASSERT_EQ(out.number_of_faces(), order.size());
  EXPECT_EQ(out.number_of_vertices(), 8u);
  EXPECT_TRUE(CGAL::is_closed(out));
  std::size_t k = 0;
  for (const auto f : out.faces()) {
    EXPECT_EQ(ids[f], frags[order[k]].face);
    std::array<vec3d, 3> c{};
    int j = 0;
    for (const auto v : vertices_around_face(out.halfedge(f), out)) {
      const auto& p = out.point(v);
      c[j++] = {p.x(), p.y(), p.z()};
    }
    EXPECT_TRUE(same_up_to_rotation(c, frags[order[k]].v)) << "face " << k;
    ++k;
  }
  // Soup of the result: 12 triangles with the cube's face ids.
  const triangle_soup again = exbsp::cgal::soup_from_face_graph(out);
  EXPECT_EQ(again.triangles.size(), 12u);
}

TEST(CgalFromExbsp, IntersectingPartsGiveEveryFragmentAFace) {
  triangle_soup s = soup_cube();
  triangle_soup shifted = soup_cube();
  for (vec3d& v : shifted.vertices) v = {v[0] + 0.5, v[1] + 0.5, v[2] + 0.5};
  s.append(shifted);
  const exbsp::bsp tree = exbsp::bsp::build(s);
  ASSERT_GT(tree.stats().splits, 0u);
  polyhedron p;
  auto ids = get(CGAL::dynamic_face_property_t<std::uint32_t>(), p);
  const auto frags = tree.fragments_double();
  exbsp::cgal::append_fragments(p, frags, ids);
  ASSERT_EQ(num_faces(p), frags.size());
  std::map<std::uint32_t, std::size_t> per_face_mesh, per_face_frags;
  for (const auto f : faces(p)) ++per_face_mesh[get(ids, f)];
  for (const auto& f : frags) ++per_face_frags[f.face];
  EXPECT_EQ(per_face_mesh, per_face_frags);
}

TEST(CgalFromExbsp, SectionIntoPolyhedronIsClosed) {
  const exbsp::section_result r = exbsp::section_with_cap(soup_cube(), {0, 0, 1, -0.25});
  ASSERT_TRUE(r.closed);
  polyhedron p;
  auto ids = get(CGAL::dynamic_face_property_t<std::uint32_t>(), p);
  exbsp::cgal::append_section(p, r, ids);
  EXPECT_EQ(num_faces(p), r.kept.size() + r.cap.size());
  EXPECT_TRUE(CGAL::is_closed(p));
  std::size_t caps = 0;
  for (const auto f : faces(p)) caps += get(ids, f) == r.cap_face;
  EXPECT_EQ(caps, r.cap.size());
}

}  // namespace
