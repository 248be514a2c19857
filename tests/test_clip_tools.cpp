// SPDX-License-Identifier: LGPL-3.0-or-later
// The clipping toolbox in users' hands: convex regions as half-spaces (clip/convex_region.h),
// Sutherland–Hodgman split into pieces for concave input, and `exbsp clip` (scene/clip_input.h):
// its JSON/SVG output, --verbose outcodes, and bad input (exit 2, key named, nothing written).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include <exbsp/clip/convex_hull.h>
#include <exbsp/clip/convex_region.h>
#include <exbsp/clip/sutherland_hodgman.h>
#include <exbsp/core/errors.h>
#include "support/cli_support.h"
#include "scene/clip_input.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp;
using clip::vec2d;
using clip::vec3d;
using json = nlohmann::json;
namespace fs = std::filesystem;

double signed_area(const std::vector<vec2d>& p) {
  double a = 0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    a += p[j][0] * p[i][1] - p[i][0] * p[j][1];
  return a / 2;
}

// --- convex regions ---------------------------------------------------------------------------

TEST(ConvexRegion, DegeneratePolygonsAreRefused) {
  EXPECT_THROW(clip::convex_polygon_half_planes({{0, 0}, {1, 0}}), usage_error);
  EXPECT_THROW(clip::convex_polygon_half_planes({{0, 0}, {1, 0}, {2, 0}}),
               usage_error);  // zero area
  EXPECT_THROW(clip::convex_polygon_half_planes({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}),
               usage_error);  // reflex
  EXPECT_THROW(clip::convex_polygon_half_planes({{0, 0}, {1, 0}, {NAN, 1}}), usage_error);
}

TEST(ConvexRegion, RepeatedAndCollinearVerticesAreAllowed) {
  const auto h =
      clip::convex_polygon_half_planes({{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}});
  EXPECT_EQ(h.size(), 5u);  // one per edge of nonzero length
  for (const auto& p : h) EXPECT_GE(p.value({1, 1}), 0);
}

TEST(ConvexRegion, BothOrientationsGiveTheSameRegion) {
  const std::vector<vec2d> ccw{{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  const std::vector<vec2d> cw(ccw.rbegin(), ccw.rend());
  for (const auto& poly : {ccw, cw}) {
    const auto h = clip::convex_polygon_half_planes(poly);
    ASSERT_EQ(h.size(), 4u);
    for (const auto& p : h) {
      EXPECT_GT(p.value({2, 1.5}), 0);        // inside
      EXPECT_EQ(p.value({0, 0}) >= 0, true);  // corner: on the boundary
    }
    bool outside = false;
    for (const auto& p : h) outside = outside || p.value({5, 1}) < 0;
    EXPECT_TRUE(outside);
  }
}

TEST(ConvexRegion, HullOfCoplanarPointsIsRefused) {
  EXPECT_THROW(clip::convex_hull_half_spaces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}),
               usage_error);
  EXPECT_THROW(clip::convex_hull_half_spaces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), usage_error);
}

TEST(ConvexRegion, HullOfACubeContainsExactlyTheCube) {
  std::vector<vec3d> pts;
  for (int i = 0; i < 8; ++i)
    pts.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  pts.push_back({0.5, 0.5, 0.5});  // an interior point changes nothing
  const auto h = clip::convex_hull_half_spaces(pts);
  EXPECT_EQ(h.size(), 12u);  // two triangles per square face
  auto inside = [&](const vec3d& p) {
    for (const auto& s : h)
      if (s.value(p) < 0) return false;
    return true;
  };
  EXPECT_TRUE(inside({0.5, 0.5, 0.5}));
  EXPECT_TRUE(inside({1, 1, 1}));
  EXPECT_FALSE(inside({1.01, 0.5, 0.5}));
  EXPECT_FALSE(inside({0.5, -0.01, 0.5}));
}

TEST(ConvexRegion, PolyhedronFromFaces) {
  // A tetrahedron, faces in mixed orientation.
  const vec3d a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  const auto h = clip::convex_polyhedron_half_spaces({{a, b, c}, {a, d, b}, {a, c, d}, {b, d, c}});
  ASSERT_EQ(h.size(), 4u);
  for (const auto& s : h) EXPECT_GT(s.value({0.1, 0.1, 0.1}), 0);
  // Not convex: a vertex of one face far outside another face's plane.
  EXPECT_THROW(
      clip::convex_polyhedron_half_spaces({{a, b, c}, {a, d, b}, {a, c, d}, {b, {0, 0, -5}, c}}),
      usage_error);
  EXPECT_THROW(clip::convex_polyhedron_half_spaces({{a, b, c}, {a, b, b}, {a, c, d}, {b, d, c}}),
               usage_error);
}

// --- Sutherland–Hodgman pieces ----------------------------------------------------------------

TEST(SutherlandHodgmanPieces, ConvexInputGivesTheTextbookResult) {
  const std::vector<vec2d> tri{{-1, -1}, {3, -1}, {1, 3}};
  const auto region = clip::window_half_planes(clip::make_window(0, 2, 0, 2));
  const auto whole = clip::sutherland_hodgman_clip(tri, region);
  const auto pieces = clip::sutherland_hodgman_pieces(tri, region);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0], whole);
}

TEST(SutherlandHodgmanPieces, ConcaveUSplitsIntoTwoPiecesWithoutConnectingEdge) {
  // A U (counter-clockwise) whose two arms cross the line y = 2; keep y <= 2... no: keep y >= 2.
  const std::vector<vec2d> u{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const std::vector<clip::half_plane2> above{{0, 1, -2}};  // y - 2 >= 0
  const auto whole = clip::sutherland_hodgman_clip(u, above);
  // The textbook result is one polygon running along y = 2 from one arm to the other.
  EXPECT_EQ(whole.size(), 8u);
  EXPECT_NEAR(signed_area(whole), 2.0, 1e-12);
  const auto pieces = clip::sutherland_hodgman_pieces(u, above);
  ASSERT_EQ(pieces.size(), 2u);
  double total = 0;
  for (const auto& p : pieces) {
    EXPECT_EQ(p.size(), 4u);
    EXPECT_NEAR(signed_area(p), 1.0, 1e-12);  // each arm 1 x 1, counter-clockwise like the input
    total += signed_area(p);
  }
  EXPECT_NEAR(total, signed_area(whole), 1e-12);
}

TEST(SutherlandHodgmanPieces, ClockwiseInputKeepsItsOrientation) {
  std::vector<vec2d> u{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  std::reverse(u.begin(), u.end());
  const auto pieces = clip::sutherland_hodgman_pieces(u, {{0, 1, -2}});
  ASSERT_EQ(pieces.size(), 2u);
  for (const auto& p : pieces) EXPECT_NEAR(signed_area(p), -1.0, 1e-12);
}

TEST(SutherlandHodgmanPieces, CombShapeAgainstAWindowGivesEveryTooth) {
  // Spine [0, 8] x [0, 1]; teeth [1, 2], [3, 4], [5, 6], [7, 8] x [1, 4] and [0, 0.5] x [0, 4].
  const std::vector<vec2d> comb{{0, 0}, {8, 0}, {8, 4}, {7, 4},   {7, 1},   {6, 1}, {6, 4},
                                {5, 4}, {5, 1}, {4, 1}, {4, 4},   {3, 4},   {3, 1}, {2, 1},
                                {2, 4}, {1, 4}, {1, 1}, {0.5, 1}, {0.5, 4}, {0, 4}};
  const auto region = clip::window_half_planes(clip::make_window(-1, 9, 2, 3));
  const auto pieces = clip::sutherland_hodgman_pieces(comb, region);
  EXPECT_EQ(pieces.size(), 5u);
  double total = 0;
  for (const auto& p : pieces) total += signed_area(p);
  EXPECT_NEAR(total, 0.5 + 4 * 1.0, 1e-12);
}

TEST(SutherlandHodgmanPieces, PinchedAtAVertexOnTheLineStaysOnePiece) {
  // A notch whose tip (2, 2) lies exactly on the line y = 2: the kept part touches the line
  // there from above. A vertex with f = 0 is kept (closed half-space), so the kept vertices
  // form one run and the result is one (pinched) polygon, as the textbook gives it.
  const std::vector<vec2d> poly{{0, 0}, {4, 0}, {4, 4}, {3, 4}, {2, 2}, {1, 4}, {0, 4}};
  const auto pieces = clip::sutherland_hodgman_pieces(poly, {{0, 1, -2}});
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(signed_area(pieces[0]), 6.0, 1e-12);
}

TEST(SutherlandHodgmanPieces, TouchingTheLineFromOutsideAddsNoPiece) {
  // The same notch upside down: its tip touches y = 2 from below, the kept part is a strip.
  const std::vector<vec2d> poly{{0, 0}, {1, 0}, {2, 2}, {3, 0}, {4, 0}, {4, 4}, {0, 4}};
  const auto pieces = clip::sutherland_hodgman_pieces(poly, {{0, 1, -2}});
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(signed_area(pieces[0]), 8.0, 1e-12);
}

TEST(SutherlandHodgmanPieces, Planar3DPolygon) {
  // The U of the 2D test in the plane z = x (a tilted plane), clipped by y >= 2.
  const std::vector<vec3d> u{{0, 0, 0}, {3, 0, 3}, {3, 3, 3}, {2, 3, 2},
                             {2, 1, 2}, {1, 1, 1}, {1, 3, 1}, {0, 3, 0}};
  const auto pieces = clip::sutherland_hodgman_pieces(u, {{{0, 1, 0}, -2}});
  EXPECT_EQ(pieces.size(), 2u);
}

TEST(SutherlandHodgmanPieces, NothingLeft) {
  const std::vector<vec2d> tri{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_TRUE(clip::sutherland_hodgman_pieces(tri, {{1, 0, -5}}).empty());
  EXPECT_TRUE(
      clip::sutherland_hodgman_pieces(tri, {{-1, 0, 0}}).empty());  // only the edge x = 0 left
}

// --- exbsp clip: the library side -------------------------------------------------------------

scene::clip_input parse(const std::string& text) {
  return scene::parse_clip_input(json::parse(text), "in.json");
}

std::string error_key(const std::string& text) {
  return exbsp_test::error_key([&] { parse(text); });
}

TEST(ClipInput, BadInputNamesTheKey) {
  EXPECT_EQ(error_key(R"({"segments": []})"), "/region");
  EXPECT_EQ(error_key(R"({"region": {"rect": [0, 0, 1]}})"), "/region/rect");
  EXPECT_EQ(error_key(R"({"region": {"rect": [0, 0, -1, 1]}})"), "/region/rect/2");
  EXPECT_EQ(error_key(R"({"region": {"box": [0, 0, 0, 1, 1, "x"]}})"), "/region/box/5");
  EXPECT_EQ(error_key(R"({"region": {"disc": 1}})"), "/region/disc");
  EXPECT_EQ(error_key(R"({"region": {"convex": [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]}})"),
            "/region/convex");
  EXPECT_EQ(error_key(R"({"region": {"convex": [[0, 0], [2, 0], [2, 2, 1]]}})"),
            "/region/convex/2");
  EXPECT_EQ(error_key(R"({"region": {"halfspaces": [[1, 0, 0], [0, 0, 1]]}})"),
            "/region/halfspaces/1");
  EXPECT_EQ(
      error_key(
          R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [[[0, 0], [1, 1]], [[0, 0], [1, 1, 1]]]})"),
      "/segments/1/1");
  EXPECT_EQ(
      error_key(R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [[[0, 0], [1, 1]], [[0, 0]]]})"),
      "/segments/1");
  EXPECT_EQ(error_key(R"({"region": {"rect": [0, 0, 1, 1]}, "polygons": [[[0, 0], [1, 1]]]})"),
            "/polygons/0");
  EXPECT_EQ(
      error_key(R"({"region": {"rect": [0, 0, 1, 1]}, "polygons": [[[0, 0], [1, 1], [1, null]]]})"),
      "/polygons/0/2/1");
  EXPECT_EQ(error_key(R"({"region": {"rect": [0, 0, 1, 1]}, "segment": []})"), "/segment");
}

TEST(ClipInput, SegmentsAgainstAConvexRegionGoToCyrusBeckAndTheBoxClippersNeedARectOrBox) {
  const auto in = parse(
      R"({"region": {"convex": [[0, 0], [2, 0], [0, 2]]}, "segments": [[[-1, 0.5], [3, 0.5]]]})");
  for (const char* algorithm : {"", "cyrus-beck"}) {
    std::ostringstream log;
    const json r = scene::run_clip(in, algorithm, &log);
    EXPECT_EQ(r["algorithm"]["segments"], "cyrus-beck");
    // Enters by the edge x = 0 at t = 1/4, leaves by x + y = 2 at x = 1.5, t = 5/8.
    EXPECT_EQ(r["segments"][0], json::parse("[[0, 0.5], [1.5, 0.5]]"));
    EXPECT_EQ(r["t"][0], json::parse("[0.25, 0.625]"));
    EXPECT_NE(log.str().find("segment 0: kept t in [0.25, 0.625]"), std::string::npos) << log.str();
  }
  for (const char* algorithm : {"cohen-sutherland", "liang-barsky"}) {
    try {
      scene::run_clip(in, algorithm, nullptr);
      FAIL() << algorithm;
    } catch (const scene_error& e) {
      EXPECT_EQ(e.key(), "/region");
      EXPECT_NE(std::string(e.what()).find("use cyrus-beck"), std::string::npos) << e.what();
    }
  }
  const auto rect = parse(R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [[[0, 0], [1, 1]]]})");
  EXPECT_THROW(scene::run_clip(rect, "sutherland-hodgman", nullptr), scene_error);
  EXPECT_THROW(scene::run_clip(rect, "bresenham", nullptr), usage_error);
}

TEST(ClipInput, AFrustumRegionClipsSegmentsAndPolygonsInEyeCoordinates) {
  // glFrustum(-1, 1, -1, 1, 1, 3): at depth z the volume is |x|, |y| <= -z, -3 <= z <= -1.
  const auto in = parse(R"({"region": {"frustum": [-1, 1, -1, 1, 1, 3]},
    "segments": [[[0, 0, 0], [0, 0, -5]], [[-4, 0, -2], [4, 0, -2]], [[5, 5, -2], [6, 5, -2]]],
    "polygons": [[[-4, -4, -2], [4, -4, -2], [4, 4, -2], [-4, 4, -2]]]})");
  const json r = scene::run_clip(in, "", nullptr);
  EXPECT_EQ(r["algorithm"]["segments"], "cyrus-beck");
  EXPECT_EQ(r["segments"][0], json::parse("[[0, 0, -1], [0, 0, -3]]"));   // near and far planes
  EXPECT_EQ(r["segments"][1], json::parse("[[-2, 0, -2], [2, 0, -2]]"));  // the side planes
  EXPECT_TRUE(r["segments"][2].is_null());
  ASSERT_EQ(r["polygons"][0].size(), 4u);  // the square [-2, 2]^2 at z = -2
  for (const auto& p : r["polygons"][0]) {
    EXPECT_EQ(std::abs(p[0].get<double>()), 2);
    EXPECT_EQ(std::abs(p[1].get<double>()), 2);
    EXPECT_EQ(p[2].get<double>(), -2);
  }
  EXPECT_EQ(error_key(R"({"region": {"frustum": [-1, 1, -1, 1, 0, 3]}})"), "/region/frustum/4");
  EXPECT_EQ(error_key(R"({"region": {"frustum": [-1, 1, -1, 1, 2, 1]}})"), "/region/frustum/5");
  EXPECT_EQ(error_key(R"({"region": {"frustum": [1, -1, -1, 1, 1, 3]}})"), "/region/frustum/1");
  EXPECT_EQ(error_key(R"({"region": {"frustum": [-1, 1, -1, 1, 1]}})"), "/region/frustum");
}

TEST(ClipInput, CohenSutherlandAndLiangBarskyAgree) {
  const auto in = parse(R"({"region": {"rect": [0, 0, 4, 2]},
    "segments": [[[-1, 1], [5, 1]], [[-1, -1], [-1, 5]], [[1, 1], [2, 1]], [[-2, 0], [2, 4]]]})");
  std::ostringstream log;
  const json cs = scene::run_clip(in, "cohen-sutherland", &log);
  const json lb = scene::run_clip(in, "liang-barsky", nullptr);
  EXPECT_EQ(cs["segments"], lb["segments"]);
  EXPECT_EQ(cs["segments"][0], json::parse("[[0, 1], [4, 1]]"));
  EXPECT_TRUE(cs["segments"][1].is_null());
  EXPECT_EQ(cs["segments"][2], json::parse("[[1, 1], [2, 1]]"));
  EXPECT_EQ(cs["segments"][3], json::parse("[[0, 2], [0, 2]]"));  // touches the corner only
  EXPECT_EQ(cs["outcodes"][0], json::parse("[1, 2]"));
  EXPECT_EQ(lb["t"][0], json::parse("[0.16666666666666666, 0.8333333333333334]"));
  EXPECT_NE(log.str().find("segment 0: p0 outcode 0001 (left), p1 outcode 0010 (right): clipped"),
            std::string::npos)
      << log.str();
  EXPECT_NE(log.str().find("segment 1: p0 outcode 0101 (left|bottom), p1 outcode 1001 (left|top): "
                           "trivially rejected"),
            std::string::npos)
      << log.str();
}

TEST(ClipInput, BoxAndConvexHull3D) {
  const auto in = parse(R"({"region": {"box": [0, 0, 0, 1, 1, 1]},
    "segments": [[[-1, 0.5, 0.5], [2, 0.5, 0.5]]], "polygons": [[[-1, -1, 0.5], [2, -1, 0.5], [2, 2, 0.5], [-1, 2, 0.5]]]})");
  const json r = scene::run_clip(in, "", nullptr);
  EXPECT_EQ(r["segments"][0], json::parse("[[0, 0.5, 0.5], [1, 0.5, 0.5]]"));
  EXPECT_EQ(r["polygons"][0].size(), 4u);
  EXPECT_EQ(r["outcodes"][0], json::parse("[1, 2]"));
  const auto hull = parse(R"({"region": {"convex": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]},
    "polygons": [[[-1, -1, 0.25], [2, -1, 0.25], [2, 2, 0.25], [-1, 2, 0.25]]]})");
  const json h = scene::run_clip(hull, "", nullptr);
  EXPECT_EQ(h["polygons"][0].size(), 3u);  // the tetrahedron's section is a triangle
  EXPECT_THROW(scene::clip_svg(hull, h), scene_error);
}

TEST(ClipInput, ConcavePolygonReportsPieces) {
  const auto in = parse(R"({"region": {"halfspaces": [[0, 1, -2]]},
    "polygons": [[[0, 0], [3, 0], [3, 3], [2, 3], [2, 1], [1, 1], [1, 3], [0, 3]]]})");
  const json r = scene::run_clip(in, "sutherland-hodgman", nullptr);
  EXPECT_EQ(r["polygons"][0].size(), 8u);
  EXPECT_EQ(r["pieces"][0].size(), 2u);
  const std::string svg = scene::clip_svg(in, r);
  EXPECT_NE(svg.find("id=\"region\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"result\""), std::string::npos);
}

// --- exbsp clip: the command line -------------------------------------------------------------

using run_result = exbsp_test::cli_result;
using exbsp_test::read_file;

class ClipCli : public exbsp_test::cli_fixture {};

TEST_F(ClipCli, JsonSvgAndVerbose) {
  write("in.json", R"({"region": {"rect": [0, 0, 4, 2]}, "segments": [[[-1, 1], [5, 1]]],
    "polygons": [[[1, -1], [3, 1], [1, 3]]]})");
  run_result r = run("clip in.json --verbose");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["segments"][0], json::parse("[[0, 1], [4, 1]]"));
  EXPECT_NE(r.err.find("p0 outcode 0001 (left)"), std::string::npos) << r.err;
  r = run("clip in.json --algorithm liang-barsky -o out.svg");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read_file(dir / "out.svg").find("<svg"), std::string::npos);
  r = run("clip in.json -o out.json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(read_file(dir / "out.json"))["segments"], j["segments"]);
}

TEST_F(ClipCli, BadInputExits2NamingTheKeyAndWritesNothing) {
  write("bad.json",
        R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [[[0, 0], [1, 1]], [[0, 0], [1, 1]],
    [[0, 0], [1, 1]], [[0, 0], [1, "y"]]]})");
  for (const char* out : {"out.json", "out.svg"}) {
    const run_result r = run(std::string("clip bad.json -o ") + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("bad.json: /segments/3/1/1: must be a number"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / out));
  }
  write("concave.json",
        R"({"region": {"convex": [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]}, "polygons": []})");
  run_result r = run("clip concave.json -o out.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/region/convex: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
  r = run("clip missing.json");
  EXPECT_EQ(r.status, 2);
  r = run("clip concave.json -o out.txt");
  EXPECT_EQ(r.status, 2);
  r = run("clip concave.json --algorithm nope");
  EXPECT_EQ(r.status, 2);
}

}  // namespace
