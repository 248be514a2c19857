// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of the mesh module: the triangle soup and the OFF/OBJ/PLY/STL readers (docs/contract.md
// section 2). Samples live in tests/data/ and the malformed corpus in tests/data/bad/ with its
// manifest EXPECTED.tsv; tests/data/make_samples.py writes both. OpenMesh serves as an
// independent oracle for the well-formed samples (counts, and coordinates to float precision)
// and shows why exbsp has its own readers (float coordinates, dropped faces).
#include <gtest/gtest.h>

// OpenMesh's PropertyT::push_back copies an uninitialised VectorT; GCC 12 reports that
// (-Wmaybe-uninitialized) wherever the template is instantiated.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/mesh/soup.h>
#include "support/test_helpers.h"

namespace {

using exbsp::input_error;
using exbsp::mesh_format;
using exbsp::read_mesh;
using exbsp::read_mesh_data;
using exbsp::triangle_soup;
using exbsp::vec3d;

const std::string data_dir = EXBSP_TEST_DATA;

std::string sample(const std::string& name) { return data_dir + "/" + name; }

// ---- the box of tests/data (see make_samples.py) ----

const double box_x[2] = {0.1, 1.7};
const double box_y[2] = {-2.3, 0.6};
const double box_z[2] = {0.25, 3.3};
const int box_corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<std::vector<std::uint32_t>> box_faces = {
    {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// Corner i of the box; `as_float` rounds each coordinate to float first (binary STL, float PLY).
vec3d box_vertex(std::size_t i, bool as_float) {
  vec3d p = {box_x[box_corners[i][0]], box_y[box_corners[i][1]], box_z[box_corners[i][2]]};
  if (as_float)
    for (double& c : p) c = static_cast<double>(static_cast<float>(c));
  return p;
}

// The box's 12 triangles, fan-triangulated from each quad's first vertex, in file order.
std::vector<std::array<std::uint32_t, 3>> box_triangles() {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& f : box_faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) out.push_back({f[0], f[i], f[i + 1]});
  return out;
}

// Checks that `s` is the box: 8 vertices, 12 triangles whose corners are exactly the expected
// doubles, in fan order. `faces_are_quads`: face id = triangle / 2 (else = triangle, STL).
void expect_box(const triangle_soup& s, bool as_float, bool faces_are_quads) {
  ASSERT_EQ(s.vertices.size(), 8u);
  ASSERT_EQ(s.triangles.size(), 12u);
  EXPECT_EQ(s.face_count, faces_are_quads ? 6u : 12u);
  const auto expected = box_triangles();
  for (std::size_t t = 0; t < 12; ++t) {
    EXPECT_EQ(s.triangles[t].face, faces_are_quads ? t / 2 : t) << "triangle " << t;
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(s.vertices.at(s.triangles[t].v[k]), box_vertex(expected[t][k], as_float))
          << "triangle " << t << " corner " << k;
  }
}

// Same vertex order as the file (OFF, OBJ, PLY): vertex i is corner i and indices match.
void expect_box_indices(const triangle_soup& s) {
  const auto expected = box_triangles();
  ASSERT_EQ(s.triangles.size(), expected.size());
  for (std::size_t t = 0; t < expected.size(); ++t)
    EXPECT_EQ(s.triangles[t].v, expected[t]) << "triangle " << t;
}

// read_mesh must throw input_error; returns it for further checks.
input_error expect_input_error(const std::string& path) {
  try {
    read_mesh(path);
  } catch (const input_error& e) {
    return e;
  }
  ADD_FAILURE() << path << ": no input_error thrown";
  return input_error(path, 0, "none");
}

std::string le_bytes(std::uint32_t v, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += static_cast<char>((v >> (8 * i)) & 0xff);
  return s;
}

std::string be_bytes(std::uint32_t v, std::size_t n) {
  std::string s = le_bytes(v, n);
  std::reverse(s.begin(), s.end());
  return s;
}

std::string float_le(float f) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  return le_bytes(bits, 4);
}

// ---- soup ----

TEST(TriangleSoup, AddPolygonFansFromFirstVertexAndRejectsBadInput) {
  triangle_soup s;
  for (int i = 0; i < 5; ++i) s.vertices.push_back({double(i), 0.0, 0.0});
  s.add_polygon({4, 3, 2, 1, 0}, 7);
  ASSERT_EQ(s.triangles.size(), 3u);
  EXPECT_EQ(s.triangles[0].v, (std::array<std::uint32_t, 3>{4, 3, 2}));
  EXPECT_EQ(s.triangles[1].v, (std::array<std::uint32_t, 3>{4, 2, 1}));
  EXPECT_EQ(s.triangles[2].v, (std::array<std::uint32_t, 3>{4, 1, 0}));
  EXPECT_EQ(s.face_count, 8u);
  EXPECT_THROW(s.add_polygon({0, 1}, 8), exbsp::usage_error);
  EXPECT_THROW(s.add_polygon({0, 1, 5}, 8), exbsp::usage_error);
}

TEST(TriangleSoup, AppendShiftsVertexIndicesAndFaceIds) {
  triangle_soup a, b;
  a.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  b.add_triangle({0, 0, 1}, {1, 0, 1}, {0, 1, 1});
  b.add_triangle({0, 0, 2}, {1, 0, 2}, {0, 1, 2});
  a.append(b);
  ASSERT_EQ(a.triangles.size(), 3u);
  EXPECT_EQ(a.face_count, 3u);
  EXPECT_EQ(a.triangles[2].face, 2u);
  EXPECT_EQ(a.vertices[a.triangles[2].v[0]], (vec3d{0, 0, 2}));
}

// ---- good path, every format ----

/// A sample of the unit box (tests/data/samples) in one format and form.
struct box_sample {
  const char* file;
  bool as_float;         ///< coordinates stored as floats (widened exactly)
  bool faces_are_quads;  ///< six quads fanned into twelve triangles, in the box's vertex order
  const char* what;      ///< the form the sample tests (the test's name)
};

class BoxSample : public ::testing::TestWithParam<box_sample> {};

TEST_P(BoxSample, reads_the_unit_box) {
  const box_sample& b = GetParam();
  const triangle_soup s = read_mesh(sample(b.file));
  expect_box(s, b.as_float, b.faces_are_quads);
  if (b.faces_are_quads) expect_box_indices(s);  // STL has no indices: merged vertices
  EXPECT_EQ(s.source, sample(b.file));
}

INSTANTIATE_TEST_SUITE_P(
    Formats, BoxSample,
    ::testing::Values(
        box_sample{"cube.off", false, true, "off_quads_fan_triangulated_in_file_order"},
        box_sample{"cube_coff.off", false, true, "coff_with_comments_vertex_and_face_colours"},
        box_sample{"cube_relative.obj", false, true,
                   "obj_relative_indices_slash_forms_and_ignored_statements"},
        box_sample{"cube_ascii.ply", false, true, "ply_ascii_colours_flags_and_an_extra_element"},
        // y and z are declared float but ascii text means the double
        box_sample{"cube_ascii_extras.ply", false, true,
                   "ply_ascii_properties_before_the_index_list_nan_normals_float_lists_crlf"},
        box_sample{"cube_binary_le.ply", false, true, "ply_binary_little_endian_doubles"},
        box_sample{"cube_binary_be.ply", true, true, "ply_binary_big_endian_floats_widen_exactly"},
        box_sample{"cube_ascii.stl", false, false, "stl_ascii_merges_exactly_equal_vertices"},
        box_sample{"cube_binary.stl", true, false,
                   "stl_binary_whose_header_starts_with_solid_is_read_as_binary"}),
    [](const ::testing::TestParamInfo<box_sample>& i) { return std::string(i.param.what); });

TEST(OffReader, CountsOnTheHeaderLineAndNoEdgeCount) {
  const triangle_soup s =
      read_mesh_data("OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", mesh_format::off, "m.off");
  EXPECT_EQ(s.vertices.size(), 3u);
  EXPECT_EQ(s.triangles.size(), 1u);
}

TEST(OffReader, NoffAndStoffAllowExtraColumnsPlainOffDoesNot) {
  const std::string body = "3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
  EXPECT_EQ(read_mesh_data("NOFF\n" + body, mesh_format::off, "n.off").triangles.size(), 1u);
  EXPECT_EQ(read_mesh_data("STCNOFF\n" + body, mesh_format::off, "n.off").triangles.size(), 1u);
  EXPECT_EQ(exbsp_test::mesh_data_error("OFF\n" + body, mesh_format::off).line(), 3u);
}

TEST(OffReader, ZeroFacesGiveAnEmptySoup) {
  const triangle_soup s = read_mesh_data("OFF\n1 0 0\n0 0 0\n", mesh_format::off, "p.off");
  EXPECT_EQ(s.vertices.size(), 1u);
  EXPECT_TRUE(s.triangles.empty());
  EXPECT_EQ(s.face_count, 0u);
}

TEST(ObjReader, RelativeIndicesCountFromTheVerticesDefinedSoFar) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
      "v 5 5 5\nv 6 5 5\nv 5 6 5\nvt 0 0\nvt 1 0\nf -3/1 -2/2/2 -1//3\nf 1 -2 6\n";
  const triangle_soup s = read_mesh_data(obj, mesh_format::obj, "r.obj");
  ASSERT_EQ(s.triangles.size(), 3u);
  EXPECT_EQ(s.triangles[0].v, (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(s.triangles[1].v, (std::array<std::uint32_t, 3>{3, 4, 5}));
  EXPECT_EQ(s.triangles[2].v, (std::array<std::uint32_t, 3>{0, 4, 5}));
  EXPECT_EQ(s.triangles[2].face, 2u);
}

TEST(ObjReader, WComponentVertexColoursAndLineContinuation) {
  const std::string obj =
      "v 0 0 0 1\nv 1 0 0 0.5 0.2 0.3\nv 0 1 0 1 0.1 0.2 0.3\nf 1 \\\n 2 \\\n3\n";
  const triangle_soup s = read_mesh_data(obj, mesh_format::obj, "w.obj");
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.vertices[1], (vec3d{1, 0, 0}));  // w is ignored, not divided by
}

TEST(PlyReader, FacesBeforeVerticesAreCheckedOnceAllElementsAreRead) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element vertex 3\nproperty short x\nproperty short y\nproperty char z\nend_header\n"
      "3 2 1 0\n0 0 0\n-7 0 0\n0 300 -128\n";
  const triangle_soup s = read_mesh_data(ply, mesh_format::ply, "fv.ply");
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.triangles[0].v, (std::array<std::uint32_t, 3>{2, 1, 0}));
  EXPECT_EQ(s.vertices[2], (vec3d{0, 300, -128}));
}

TEST(PlyReader, BinaryBigEndianIntegerCoordinatesAndUshortIndexLists) {
  std::string ply =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty int x\nproperty uint y\n"
      "property short z\nelement face 1\nproperty list ushort ushort vertex_indices\nend_header\n";
  const std::int32_t xs[3] = {-5, 7, 0};
  const std::uint32_t ys[3] = {0, 4000000000u, 1};
  for (int i = 0; i < 3; ++i)
    ply +=
        be_bytes(static_cast<std::uint32_t>(xs[i]), 4) + be_bytes(ys[i], 4) + be_bytes(0xFFFF, 2);
  ply += be_bytes(3, 2) + be_bytes(0, 2) + be_bytes(1, 2) + be_bytes(2, 2);
  const triangle_soup s = read_mesh_data(ply, mesh_format::ply, "be.ply");
  ASSERT_EQ(s.vertices.size(), 3u);
  EXPECT_EQ(s.vertices[0], (vec3d{-5, 0, -1}));
  EXPECT_EQ(s.vertices[1], (vec3d{7, 4000000000.0, -1}));
  ASSERT_EQ(s.triangles.size(), 1u);
}

TEST(PlyReader, VertexOnlyFileGivesNoTriangles) {
  const triangle_soup s = read_mesh_data(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3\n",
      mesh_format::ply, "points.ply");
  EXPECT_EQ(s.vertices.size(), 1u);
  EXPECT_TRUE(s.triangles.empty());
}

TEST(StlReader, BinaryWithZeroTrianglesIsAnEmptySoup) {
  const std::string stl = std::string(80, ' ') + le_bytes(0, 4);
  const triangle_soup s = read_mesh_data(stl, mesh_format::stl, "zero.stl");
  EXPECT_TRUE(s.vertices.empty());
  EXPECT_TRUE(s.triangles.empty());
}

TEST(StlReader, AsciiKeywordsIgnoreCaseSeveralSolidsAndPolygonFacetsFan) {
  const std::string stl =
      "SOLID a name with spaces\nFACET NORMAL nan nan nan\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\n"
      "VERTEX 1 1 0\nVERTEX 0 1 0\nENDLOOP\nENDFACET\nENDSOLID a name with spaces\n"
      "solid\nfacet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 -0 1 endloop "
      "endfacet\n"
      "endsolid\n";
  const triangle_soup s = read_mesh_data(stl, mesh_format::stl, "multi.stl");
  ASSERT_EQ(s.triangles.size(), 3u);
  EXPECT_EQ(s.face_count, 2u);
  EXPECT_EQ(s.triangles[0].face, 0u);
  EXPECT_EQ(s.triangles[1].face, 0u);
  EXPECT_EQ(s.triangles[2].face, 1u);
  EXPECT_EQ(s.vertices.size(), 5u);  // (0,0,0) and (1,0,0) are shared by both solids
  EXPECT_EQ(s.triangles[2].v[0], 0u);
  EXPECT_EQ(s.triangles[2].v[1], 1u);
}

TEST(StlReader, BinaryTrianglesKeepFileOrderAndExactFloatValues) {
  std::string stl = std::string(80, '\0') + le_bytes(2, 4);
  const float tri[2][9] = {{0.1f, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0.3f, 0.3f, 1e-30f}};
  for (const auto& t : tri) {
    stl += std::string(12, '\0');
    for (float c : t) stl += float_le(c);
    stl += std::string(2, '\0');
  }
  const triangle_soup s = read_mesh_data(stl, mesh_format::stl, "two.stl");
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.vertices[0][0], static_cast<double>(0.1f));
  EXPECT_EQ(s.vertices[s.triangles[1].v[2]], (vec3d{double(0.3f), double(0.3f), double(1e-30f)}));
  EXPECT_EQ(s.triangles[1].v[0], s.triangles[0].v[1]);  // merged
}

TEST(LineEndings, CrlfFilesReadLikeLfFilesInEveryTextFormat) {
  const std::string off = "OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
  const std::string obj = "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n";
  const std::string ply =
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nelement face 1\r\nproperty list uchar int "
      "vertex_indices\r\nend_header\r\n"
      "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
  const std::string stl =
      "solid t\r\nfacet normal 0 0 1\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 0 0\r\nvertex 0 1 "
      "0\r\n"
      "endloop\r\nendfacet\r\nendsolid t\r\n";
  for (const triangle_soup& s : {read_mesh_data(off, mesh_format::off, "c.off"),
                                 read_mesh_data(obj, mesh_format::obj, "c.obj"),
                                 read_mesh_data(ply, mesh_format::ply, "c.ply"),
                                 read_mesh_data(stl, mesh_format::stl, "c.stl")}) {
    ASSERT_EQ(s.triangles.size(), 1u) << s.source;
    EXPECT_EQ(s.vertices[s.triangles[0].v[1]], (vec3d{1, 0, 0})) << s.source;
  }
  // Line numbers count CRLF lines once.
  const std::string bad = "OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 9\r\n";
  EXPECT_EQ(exbsp_test::mesh_data_error(bad, mesh_format::off).line(), 6u);
}

// ---- triangulation, face ids, non-manifold input ----

TEST(FanTriangulation, PentagonTriangleHexagonKeepFaceIdsAndOrder) {
  const triangle_soup s = read_mesh(sample("fan.off"));
  const std::vector<std::array<std::uint32_t, 3>> expected = {{0, 1, 2},   {0, 2, 3},  {0, 3, 4},
                                                              {5, 6, 7},   {8, 9, 10}, {8, 10, 11},
                                                              {8, 11, 12}, {8, 12, 13}};
  const std::vector<std::uint32_t> faces = {0, 0, 0, 1, 2, 2, 2, 2};
  ASSERT_EQ(s.triangles.size(), expected.size());
  for (std::size_t t = 0; t < expected.size(); ++t) {
    EXPECT_EQ(s.triangles[t].v, expected[t]) << t;
    EXPECT_EQ(s.triangles[t].face, faces[t]) << t;
  }
  EXPECT_EQ(s.face_count, 3u);
}

TEST(FanTriangulation, SameOrderInEveryPolygonFormat) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4 5\n";
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n5 0 1 2 3 4\n";
  const std::string off = "OFF\n5 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n5 0 1 2 3 4\n";
  for (const triangle_soup& s : {read_mesh_data(obj, mesh_format::obj, "f.obj"),
                                 read_mesh_data(ply, mesh_format::ply, "f.ply"),
                                 read_mesh_data(off, mesh_format::off, "f.off")}) {
    ASSERT_EQ(s.triangles.size(), 3u) << s.source;
    EXPECT_EQ(s.triangles[0].v, (std::array<std::uint32_t, 3>{0, 1, 2})) << s.source;
    EXPECT_EQ(s.triangles[1].v, (std::array<std::uint32_t, 3>{0, 2, 3})) << s.source;
    EXPECT_EQ(s.triangles[2].v, (std::array<std::uint32_t, 3>{0, 3, 4})) << s.source;
  }
}

TEST(NonManifold, SharedEdgeDuplicateFlippedAndDegenerateFacesLoadCompletely) {
  for (const char* name : {"nonmanifold.off", "nonmanifold.obj"}) {
    const triangle_soup s = read_mesh(sample(name));
    const std::vector<std::array<std::uint32_t, 3>> expected = {{0, 1, 2}, {0, 1, 3}, {1, 0, 4},
                                                                {0, 1, 2}, {2, 1, 0}, {0, 1, 5}};
    ASSERT_EQ(s.triangles.size(), expected.size()) << name;
    EXPECT_EQ(s.vertices.size(), 6u) << name;
    for (std::size_t t = 0; t < expected.size(); ++t) {
      EXPECT_EQ(s.triangles[t].v, expected[t]) << name << " triangle " << t;
      EXPECT_EQ(s.triangles[t].face, t) << name;
    }
  }
}

TEST(NonManifold, RepeatedIndexInOneFaceIsKeptAsADegenerateTriangle) {
  const triangle_soup s =
      read_mesh_data("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n", mesh_format::off, "d.off");
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.triangles[0].v, (std::array<std::uint32_t, 3>{0, 0, 1}));
}

// ---- the exact-decimal rule ----

TEST(ExactDecimal, CoordinatesAreTheNearestDoubleToTheText) {
  const triangle_soup s = read_mesh(sample("exact_decimal.off"));
  ASSERT_EQ(s.vertices.size(), 6u);
  const auto& v = s.vertices;
  EXPECT_EQ(v[0][0], 0.1);
  EXPECT_EQ(v[0][1], 0.1);  // 0.1000000000000000055511151231257827 -> the same double
  EXPECT_EQ(v[0][2], 0.30000000000000004);
  EXPECT_NE(v[0][2], 0.3);
  EXPECT_EQ(v[1][0], 0.001);
  EXPECT_EQ(v[1][1], 0.0);
  EXPECT_TRUE(std::signbit(v[1][1]));  // -0 keeps its sign
  EXPECT_EQ(v[1][2], 0.5);
  EXPECT_EQ(v[2][0], 5.0);
  EXPECT_EQ(v[2][1], 2.0);
  EXPECT_EQ(v[2][2], 100.0);
  EXPECT_EQ(v[3][0], 9007199254740992.0);  // 2^53 + 1 is a tie: rounds to even
  EXPECT_EQ(v[3][1], 2.2250738585072011e-308);
  EXPECT_EQ(v[3][2], 0.0);  // 1e-400 underflows to the nearest double, +0
  EXPECT_FALSE(std::signbit(v[3][2]));
  EXPECT_EQ(v[4][0], std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(v[4][1], 0.0);
  EXPECT_TRUE(std::signbit(v[4][1]));
  EXPECT_EQ(v[4][2], std::numeric_limits<double>::max());
  EXPECT_EQ(v[5][0], 1.0);
  EXPECT_EQ(v[5][1], 123456789012345678901234567890.0);
  EXPECT_EQ(v[5][2], 0.000001);
}

TEST(ExactDecimal, PointOneIsNotItsFloatRounding) {
  const triangle_soup s =
      read_mesh_data("v 0.1 0.2 0.3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", mesh_format::obj, "p.obj");
  EXPECT_EQ(s.vertices[0][0], 0.1);
  EXPECT_NE(s.vertices[0][0], static_cast<double>(0.1f));
  EXPECT_EQ(s.vertices[0][1], 0.2);
  EXPECT_EQ(s.vertices[0][2], 0.3);
}

TEST(ExactDecimal, SeventeenDigitTextOfRandomDoublesReadsBackBitForBit) {
  std::mt19937_64 rng(20240601);  // fixed seed
  std::string off = "OFF\n1000 0 0\n";
  std::vector<double> values;
  while (values.size() < 3000) {
    const std::uint64_t bits = rng();
    double d = 0.0;
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    values.push_back(d);
  }
  for (std::size_t i = 0; i < values.size(); i += 3) {
    char line[128];
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", values[i], values[i + 1],
                  values[i + 2]);
    off += line;
  }
  const triangle_soup s = read_mesh_data(off, mesh_format::off, "random.off");
  ASSERT_EQ(s.vertices.size(), 1000u);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double got = s.vertices[i / 3][i % 3];
    EXPECT_EQ(std::memcmp(&got, &values[i], sizeof got), 0) << "value " << i << ": " << values[i];
  }
}

TEST(ExactDecimal, AllFormatsAgreeOnTheSameDecimalText) {
  const std::string x = "0.7071067811865476", y = "-1234.5678e-3", z = "3.0000000000000004";
  const triangle_soup off =
      read_mesh_data("OFF\n3 1 0\n" + x + " " + y + " " + z + "\n1 0 0\n0 1 0\n3 0 1 2\n",
                     mesh_format::off, "a.off");
  const triangle_soup obj = read_mesh_data(
      "v " + x + " " + y + " " + z + "\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", mesh_format::obj, "a.obj");
  const triangle_soup ply = read_mesh_data(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
          x + " " + y + " " + z + "\n1 0 0\n0 1 0\n3 0 1 2\n",
      mesh_format::ply, "a.ply");
  const triangle_soup stl =
      read_mesh_data("solid\nfacet normal 0 0 0\nouter loop\nvertex " + x + " " + y + " " + z +
                         "\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n",
                     mesh_format::stl, "a.stl");
  const vec3d expected = {0.7071067811865476, -1.2345678, 3.0000000000000004};
  for (const triangle_soup* s : {&off, &obj, &ply, &stl})
    EXPECT_EQ(s->vertices[0], expected) << s->source;
}

// ---- errors outside the corpus ----

TEST(MeshErrors, MissingFileIsAnInputErrorWithLineZero) {
  const input_error e = expect_input_error(sample("no_such_file.off"));
  EXPECT_EQ(e.line(), 0u);
  EXPECT_NE(std::string(e.what()).find("no_such_file.off"), std::string::npos);
  EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
}

TEST(MeshErrors, DirectoryIsUnreadable) {
  const std::string dir =
      (std::filesystem::temp_directory_path() / "exbsp_test_mesh_dir.off").string();
  std::filesystem::create_directories(dir);
  const input_error e = expect_input_error(dir);
  EXPECT_EQ(e.line(), 0u);
  EXPECT_NE(std::string(e.what()).find("cannot"), std::string::npos) << e.what();
  std::filesystem::remove(dir);
}

TEST(MeshErrors, UnknownOrMissingExtensionListsTheSupportedFormats) {
  for (const char* path : {"model.3ds", "model", "dir.v2/model"}) {
    const input_error e = expect_input_error(path);
    EXPECT_EQ(e.line(), 0u);
    EXPECT_NE(std::string(e.what()).find(".off, .obj, .ply, .stl"), std::string::npos) << e.what();
  }
}

TEST(MeshErrors, ExtensionIsCaseInsensitive) {
  EXPECT_EQ(exbsp::mesh_format_for_path("A.OFF"), mesh_format::off);
  EXPECT_EQ(exbsp::mesh_format_for_path("dir/b.Obj"), mesh_format::obj);
  EXPECT_EQ(exbsp::mesh_format_for_path("c.PLY"), mesh_format::ply);
  EXPECT_EQ(exbsp::mesh_format_for_path("d.sTl"), mesh_format::stl);
}

TEST(MeshErrors, MessageIsFileColonLineColonWhat) {
  const input_error e = exbsp_test::mesh_data_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 12 1\n",
                                                    mesh_format::off, "part.off");
  EXPECT_STREQ(e.what(), "part.off:6: vertex index 12 out of range (3 vertices)");
  EXPECT_EQ(e.file(), "part.off");
}

TEST(MeshErrors, GarbageBytesAreEscapedInMessages) {
  const input_error e =
      exbsp_test::mesh_data_error(std::string("\x01\x02\xff OFF\n", 8), mesh_format::off);
  const std::string what = e.what();
  EXPECT_NE(what.find("'\\x01\\x02\\xff'"), std::string::npos) << what;
}

// Huge declared counts must fail when the data runs out, never by trying to allocate first:
// an attempted allocation of billions of vertices would surface as std::bad_alloc or
// std::length_error, not input_error (and would take long).
TEST(HugeDeclaredCounts, FailAtTheEndOfTheDataWithoutAllocating) {
  const auto start = std::chrono::steady_clock::now();
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(
      exbsp_test::mesh_data_error("OFF\n4000000000 4000000000 0\n" + tri, mesh_format::off).line(),
      5u);
  EXPECT_EQ(
      exbsp_test::mesh_data_error("OFF\n3 4294967295 0\n" + tri + "3 0 1 2\n", mesh_format::off)
          .line(),
      6u);
  EXPECT_EQ(
      exbsp_test::mesh_data_error("OFF\n3 1 0\n" + tri + "2000000000 0 1 2\n", mesh_format::off)
          .line(),
      6u);
  const std::string ply_head =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4294967295\nproperty float x\nproperty "
      "float y\n"
      "property float z\nelement face 4294967295\nproperty list uint int "
      "vertex_indices\nend_header\n";
  EXPECT_EQ(exbsp_test::mesh_data_error(ply_head + std::string(36, '\0'), mesh_format::ply).line(),
            0u);
  const std::string ply_list =
      "ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list uint int "
      "vertex_indices\nend_header\n" +
      le_bytes(0xFFFFFFFFu, 4) + le_bytes(0, 4);
  const input_error list_error = exbsp_test::mesh_data_error(ply_list, mesh_format::ply);
  EXPECT_NE(std::string(list_error.what()).find("unexpected end of file"), std::string::npos)
      << list_error.what();
  const std::string stl = std::string(80, 'x') + le_bytes(0xFFFFFFFFu, 4) + std::string(100, '\0');
  EXPECT_EQ(exbsp_test::mesh_data_error(stl, mesh_format::stl).line(), 0u);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(MeshErrors, EveryReaderRejectsAnEmptyBuffer) {
  for (mesh_format f : {mesh_format::off, mesh_format::obj, mesh_format::ply, mesh_format::stl}) {
    const input_error e = exbsp_test::mesh_data_error("", f, "empty");
    EXPECT_EQ(e.line(), 0u);
    EXPECT_NE(std::string(e.what()).find("empty file"), std::string::npos);
  }
}

// ---- the malformed corpus ----

TEST(BadCorpus, EveryFileThrowsInputErrorWithTheExpectedLineAndMessage) {
  const std::vector<exbsp_test::bad_input> cases = exbsp_test::bad_input_manifest();
  for (const exbsp_test::bad_input& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string path = data_dir + "/bad/" + c.file;
    try {
      read_mesh(path);
      ADD_FAILURE() << c.file << ": loaded without an error";
    } catch (const input_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.line(), c.line) << what;
      EXPECT_EQ(e.file(), path);
      EXPECT_NE(what.find(c.file), std::string::npos) << what;
      EXPECT_NE(what.find(c.message), std::string::npos)
          << "message: " << what << "\nwanted: " << c.message;
      if (c.line != 0) {
        EXPECT_EQ(what.rfind(path + ":" + std::to_string(c.line) + ": ", 0), 0u) << what;
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << c.file << ": wrong exception type: " << e.what();
    }
  }
}

TEST(BadCorpus, ManifestListsEveryFileOnceAndHasAtLeastThirtyCases) {
  const std::vector<exbsp_test::bad_input> cases = exbsp_test::bad_input_manifest();
  EXPECT_GE(cases.size(), 30u);
  std::set<std::string> listed;
  for (const exbsp_test::bad_input& c : cases)
    EXPECT_TRUE(listed.insert(c.file).second) << "listed twice: " << c.file;
  std::set<std::string> present;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir + "/bad")) {
    const std::string name = entry.path().filename().string();
    if (name != "EXPECTED.tsv") present.insert(name);
  }
  EXPECT_EQ(listed, present);
  // Each format has truncated, empty and garbage cases.
  for (const char* prefix : {"off_", "obj_", "ply_", "stl_"}) {
    int empty = 0, garbage = 0;
    for (const exbsp_test::bad_input& c : cases) {
      if (c.file.rfind(prefix, 0) != 0) continue;
      empty += c.file.find("empty") != std::string::npos;
      garbage += c.file.find("garbage") != std::string::npos;
    }
    EXPECT_GE(empty, 1) << prefix;
    EXPECT_GE(garbage, 1) << prefix;
  }
}

// ---- OpenMesh as an independent oracle ----

using om_mesh = OpenMesh::PolyMesh_ArrayKernelT<>;  // float points

struct double_traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using om_mesh_d = OpenMesh::PolyMesh_ArrayKernelT<double_traits>;

class quiet_openmesh {  // OpenMesh logs warnings for skipped properties; keep the test log readable
 public:
  quiet_openmesh() {
    omerr().disable();
    omlog().disable();
  }
  ~quiet_openmesh() {
    omerr().enable();
    omlog().enable();
  }
};

bool float_close(double ours, double openmesh) {
  return std::abs(ours - openmesh) <= 1e-6 * std::max(1.0, std::abs(ours));
}

// Samples OpenMesh reads completely (as manifold polygon meshes). cube_coff.off and
// cube_ascii_extras.ply are not listed: OpenMesh 9 loads them without their faces.
TEST(OpenMeshOracle, WellFormedSamplesAgreeInCountsAndCoordinatesToFloatPrecision) {
  quiet_openmesh quiet;
  for (const char* name : {"cube.off", "cube_relative.obj", "cube_ascii.ply", "cube_binary_le.ply",
                           "cube_binary_be.ply", "cube_ascii.stl", "cube_binary.stl", "fan.off"}) {
    SCOPED_TRACE(name);
    const triangle_soup ours = read_mesh(sample(name));
    om_mesh om;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(om, sample(name)));
    EXPECT_EQ(om.n_vertices(), ours.vertices.size());
    EXPECT_EQ(om.n_faces(), ours.face_count);
    // Every OpenMesh face has the corners of our triangles with that face id, in cyclic order.
    std::vector<std::vector<vec3d>> our_faces(ours.face_count);
    for (const exbsp::soup_triangle& t : ours.triangles) {
      auto& f = our_faces[t.face];
      if (f.empty()) f.push_back(ours.vertices[t.v[0]]);
      f.push_back(ours.vertices[t.v[1]]);
      if (&t == &ours.triangles.back() || (&t)[1].face != t.face)
        f.push_back(ours.vertices[t.v[2]]);
    }
    ASSERT_EQ(om.n_faces(), our_faces.size());
    for (const auto fh : om.faces()) {
      std::vector<vec3d> corners;
      for (const auto vh : om.fv_range(fh)) {
        const auto p = om.point(vh);
        corners.push_back({p[0], p[1], p[2]});
      }
      const auto& mine = our_faces[static_cast<std::size_t>(fh.idx())];
      ASSERT_EQ(corners.size(), mine.size()) << "face " << fh.idx();
      // OpenMesh may start the cycle at another corner: find our first corner in its list.
      std::size_t shift = corners.size();
      for (std::size_t k = 0; k < corners.size(); ++k)
        if (float_close(mine[0][0], corners[k][0]) && float_close(mine[0][1], corners[k][1]) &&
            float_close(mine[0][2], corners[k][2]))
          shift = k;
      ASSERT_LT(shift, corners.size()) << "face " << fh.idx();
      for (std::size_t k = 0; k < mine.size(); ++k)
        for (std::size_t a = 0; a < 3; ++a)
          EXPECT_TRUE(float_close(mine[k][a], corners[(k + shift) % corners.size()][a]))
              << "face " << fh.idx() << " corner " << k << ": " << mine[k][a] << " vs "
              << corners[(k + shift) % corners.size()][a];
    }
  }
}

TEST(OpenMeshOracle, OpenMeshReadsPointOneAsAFloatEvenIntoDoublePointsWeReadTheNearestDouble) {
  quiet_openmesh quiet;
  for (const char* name : {"cube.off", "cube_relative.obj"}) {
    om_mesh_d om;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(om, sample(name))) << name;
    const double openmesh_x = om.point(om.vertex_handle(0))[0];
    const double our_x = read_mesh(sample(name)).vertices[0][0];
    EXPECT_EQ(our_x, 0.1) << name;
    EXPECT_EQ(openmesh_x, static_cast<double>(0.1f)) << name;  // 0.10000000149011612
    EXPECT_NE(openmesh_x, our_x) << name;
  }
}

TEST(OpenMeshOracle, OpenMeshDropsAFaceWithABadIndexWeThrow) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "exbsp_test_mesh_bad_index.off").string();
  {
    std::ofstream out(path);
    out << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 7\n";
  }
  quiet_openmesh quiet;
  om_mesh om;
  EXPECT_TRUE(OpenMesh::IO::read_mesh(om, path));
  EXPECT_EQ(om.n_faces(), 1u);  // the second face is gone and read_mesh reports success
  const input_error e = expect_input_error(path);
  EXPECT_EQ(e.line(), 8u);
  EXPECT_NE(std::string(e.what()).find("vertex index 7 out of range (4 vertices)"),
            std::string::npos)
      << e.what();
  std::filesystem::remove(path);
}

TEST(OpenMeshOracle, OpenMeshSplitsNonManifoldInputWeKeepItAsIs) {
  quiet_openmesh quiet;
  om_mesh om;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(om, sample("nonmanifold.off")));
  const triangle_soup ours = read_mesh(sample("nonmanifold.off"));
  EXPECT_EQ(ours.vertices.size(), 6u);
  EXPECT_GT(om.n_vertices(), ours.vertices.size());  // "complex" faces got duplicated vertices
  EXPECT_EQ(ours.triangles.size(), 6u);
}

}  // namespace
