// SPDX-License-Identifier: LGPL-3.0-or-later
// The clipping toolbox in users' hands: convex regions as half-spaces (clip/convex_region.h),
// Sutherland–Hodgman split into pieces for concave input, concave clipping with holes
// (clip/polygon_boolean.h) against an exact rational reference, clip-space clipping against
// hand-computed cases and an exact reference, and `exbsp clip` (scene/clip_input.h): its JSON/SVG
// output, --verbose outcodes, and bad input (exit 2, key named, nothing written).
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include <exbsp/clip/convex_hull.h>
#include <exbsp/clip/convex_region.h>
#include <exbsp/clip/homogeneous.h>
#include <exbsp/clip/homogeneous_segment.h>
#include <exbsp/clip/polygon_boolean.h>
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

/// run_clip with `algorithm` refuses the input's region: a scene_error naming /region whose
/// message contains `reason`.
void expect_region_refused(const scene::clip_input& in, const std::string& algorithm,
                           const std::string& reason) {
  try {
    scene::run_clip(in, algorithm, nullptr);
    ADD_FAILURE() << algorithm << " was not refused";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.key(), "/region");
    EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
  }
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
  for (const char* algorithm : {"cohen-sutherland", "liang-barsky"})
    expect_region_refused(in, algorithm, "use cyrus-beck");
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

// --- concave clipping (clip/polygon_boolean.h): an exact reference ---------------------------
// The reference knows nothing of CGAL: exact rationals (GMP) decide whether a point is inside,
// outside or on the boundary of a set of rings (even-odd crossing count, an edge through the
// point is the boundary), and the shoelace formula gives exact areas. A sample point that is on
// no boundary is inside the result exactly when it is inside the subject and the region.

using ring = std::vector<vec2d>;
using clip::polygon_with_holes2;

enum class where { outside, boundary, inside };

/// Sign of (b - a) x (p - a), exact.
int orientation(const vec2d& a, const vec2d& b, const vec2d& p) {
  const mpq_class v = (mpq_class(b[0]) - a[0]) * (mpq_class(p[1]) - a[1]) -
                      (mpq_class(b[1]) - a[1]) * (mpq_class(p[0]) - a[0]);
  return sgn(v);
}

where locate(const std::vector<ring>& rings, const vec2d& p) {
  bool inside = false;
  for (const ring& r : rings)
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
      const vec2d &a = r[j], &b = r[i];
      const bool in_box = std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
                          std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
      if (in_box && orientation(a, b, p) == 0) return where::boundary;
      // The ray to +x crosses the edge (half-open in y, so a vertex counts once).
      if ((a[1] <= p[1]) != (b[1] <= p[1]) && orientation(a, b, p) == (b[1] > a[1] ? 1 : -1))
        inside = !inside;
    }
  return inside ? where::inside : where::outside;
}

std::vector<ring> rings_of(const polygon_with_holes2& p) {
  std::vector<ring> out{p.outer};
  out.insert(out.end(), p.holes.begin(), p.holes.end());
  return out;
}

std::vector<ring> rings_of(const std::vector<polygon_with_holes2>& ps) {
  std::vector<ring> out;
  for (const auto& p : ps) {
    const auto r = rings_of(p);
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

/// Twice the signed area, exact.
mpq_class twice_area(const ring& r) {
  mpq_class a = 0;
  for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
    a += mpq_class(r[j][0]) * r[i][1] - mpq_class(r[i][0]) * r[j][1];
  return a;
}

/// The area of a result, exact (holes are clockwise: their signed area is negative). Checks
/// the orientations on the way.
mpq_class result_area(const std::vector<polygon_with_holes2>& ps) {
  mpq_class a = 0;
  for (const auto& p : ps) {
    EXPECT_GT(twice_area(p.outer), 0) << "outer rings are counter-clockwise";
    a += twice_area(p.outer);
    for (const auto& h : p.holes) {
      EXPECT_LT(twice_area(h), 0) << "holes are clockwise";
      a += twice_area(h);
    }
  }
  return a / 2;
}

/// Compares the result with the reference on a grid of steps x steps points of [lo, hi]^2 (cell
/// centres, dyadic when lo, hi and steps are); returns how many points were on no boundary.
int expect_matches_reference(const polygon_with_holes2& subject, const polygon_with_holes2& region,
                             const std::vector<polygon_with_holes2>& result, double lo, double hi,
                             int steps) {
  const auto s_rings = rings_of(subject), r_rings = rings_of(region), k_rings = rings_of(result);
  int checked = 0, failures = 0;
  for (int i = 0; i < steps; ++i)
    for (int j = 0; j < steps; ++j) {
      const vec2d p{lo + (hi - lo) * (i + 0.5) / steps, lo + (hi - lo) * (j + 0.5) / steps};
      const where s = locate(s_rings, p), r = locate(r_rings, p), k = locate(k_rings, p);
      if (s == where::boundary || r == where::boundary || k == where::boundary) continue;
      ++checked;
      const bool expected = s == where::inside && r == where::inside;
      if ((k == where::inside) != expected && ++failures <= 5)
        ADD_FAILURE() << "(" << p[0] << ", " << p[1] << "): in the result " << (k == where::inside)
                      << ", in subject and region " << expected;
    }
  return checked;
}

/// The U of the Sutherland–Hodgman tests, twice as large: [0, 6]^2 less the notch (2, 4) x (2, 6].
const ring big_u{{0, 0}, {6, 0}, {6, 6}, {4, 6}, {4, 2}, {2, 2}, {2, 6}, {0, 6}};
/// An L ([1, 7] x [1, 3] and [1, 3] x [3, 7], clockwise) with a square hole inside its foot.
const polygon_with_holes2 l_with_hole{{{1, 7}, {3, 7}, {3, 3}, {7, 3}, {7, 1}, {1, 1}},
                                      {{{3, 1.25}, {3.5, 1.25}, {3.5, 1.75}, {3, 1.75}}}};

/// `r` without vertices between two collinear edges (exact), starting at its smallest vertex.
ring without_collinear(ring r) {
  for (std::size_t i = 0; i < r.size() && r.size() > 3;) {
    const std::size_t prev = (i + r.size() - 1) % r.size(), next = (i + 1) % r.size();
    if (orientation(r[prev], r[i], r[next]) == 0)
      r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
    else
      ++i;
  }
  std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
  return r;
}

TEST(PolygonBoolean, UAgainstAnLWithAHoleByHand) {
  const clip::polygon_region region(l_with_hole);
  const auto result = region.intersect({big_u, {}});
  // U ∩ L = [1, 6] x [1, 2] ∪ [1, 2] x [2, 6] ∪ [4, 6] x [2, 3]: 5 + 4 + 2 = 11, one polygon
  // keeping the L's hole (0.5 x 0.5) whole.
  ASSERT_EQ(result.size(), 1u);
  EXPECT_EQ(result_area(result), mpq_class(43, 4));
  EXPECT_EQ(without_collinear(result[0].outer),
            (ring{{1, 1}, {6, 1}, {6, 3}, {4, 3}, {4, 2}, {2, 2}, {2, 6}, {1, 6}}));
  ASSERT_EQ(result[0].holes.size(), 1u);
  EXPECT_EQ(without_collinear(result[0].holes[0]),
            (ring{{3, 1.25}, {3, 1.75}, {3.5, 1.75}, {3.5, 1.25}}));  // clockwise
  EXPECT_GT(expect_matches_reference({big_u, {}}, l_with_hole, result, -1, 8, 72), 4000);
}

TEST(PolygonBoolean, TwoPiecesAndASubjectWithAHole) {
  // A bar across both arms of the U: two squares.
  const clip::polygon_region bar({{{-1, 3}, {7, 3}, {7, 5}, {-1, 5}}, {}});
  const auto arms = bar.intersect({big_u, {}});
  ASSERT_EQ(arms.size(), 2u);
  EXPECT_EQ(result_area(arms), 8);
  EXPECT_EQ(without_collinear(arms[0].outer), (ring{{0, 3}, {2, 3}, {2, 5}, {0, 5}}));
  EXPECT_EQ(without_collinear(arms[1].outer), (ring{{4, 3}, {6, 3}, {6, 5}, {4, 5}}));
  // A square frame [0, 4]^2 less (1, 3)^2 against [2, 6] x [-1, 5]: the frame's hole reaches the
  // region's edge x = 2 along a segment, so the result is a C, not a polygon with a hole.
  const polygon_with_holes2 frame{{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                                  {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}};
  const polygon_with_holes2 right{{{2, -1}, {6, -1}, {6, 5}, {2, 5}}, {}};
  const auto c = clip::polygon_region(right).intersect(frame);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].holes.empty());
  EXPECT_EQ(result_area(c), 6);
  EXPECT_EQ(without_collinear(c[0].outer),
            (ring{{2, 0}, {4, 0}, {4, 4}, {2, 4}, {2, 3}, {3, 3}, {3, 1}, {2, 1}}));
  EXPECT_GT(expect_matches_reference(frame, right, c, -1, 7, 64), 3000);
  // The frame inside a larger square keeps its hole, clockwise.
  const auto whole =
      clip::polygon_region({{{-1, -1}, {5, -1}, {5, 5}, {-1, 5}}, {}}).intersect(frame);
  ASSERT_EQ(whole.size(), 1u);
  ASSERT_EQ(whole[0].holes.size(), 1u);
  EXPECT_EQ(result_area(whole), 12);
}

TEST(PolygonBoolean, RegularizedDegenerateCases) {
  const clip::polygon_region square({{{1, 0}, {2, 0}, {2, 1}, {1, 1}}, {}});
  // Touching along an edge only, or at a corner only: nothing of positive area.
  EXPECT_TRUE(square.intersect({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}}).empty());
  EXPECT_TRUE(square.intersect({{{0, 1}, {1, 1}, {0, 2}}, {}}).empty());
  // Coincident edges: [0, 2] x [0, 1] against [1, 2] x [0, 1] is the square itself.
  const auto same = square.intersect({{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {}});
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].outer, (ring{{1, 0}, {2, 0}, {2, 1}, {1, 1}}));
  // A square frame [0, 10]^2 less [2, 8]^2: a polygon wholly inside the hole, or equal to it,
  // is outside; one overlapping the hole's edge keeps the part in the frame.
  const polygon_with_holes2 frame{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                  {{{2, 2}, {8, 2}, {8, 8}, {2, 8}}}};
  const clip::polygon_region framed(frame);
  EXPECT_TRUE(framed.intersect({{{3, 3}, {4, 3}, {4, 4}, {3, 4}}, {}}).empty());
  EXPECT_TRUE(framed.intersect({{{2, 2}, {8, 2}, {8, 8}, {2, 8}}, {}}).empty());
  const auto across = framed.intersect({{{1, 1}, {3, 1}, {3, 3}, {1, 3}}, {}});
  EXPECT_EQ(result_area(across), 3);
  // Both orientations and a repeated closing vertex give the same result.
  ring cw = big_u;
  std::reverse(cw.begin(), cw.end());
  cw.push_back(cw.front());
  const clip::polygon_region l(l_with_hole);
  const auto a = l.intersect({big_u, {}}), b = l.intersect({cw, {}});
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a[0].outer, b[0].outer);
  EXPECT_EQ(a[0].holes, b[0].holes);
}

TEST(PolygonBoolean, StarPolygonsAgainstTheReference) {
  // Random star-shaped (mostly concave) polygons with integer vertices; the region has a square
  // hole around its centre. Their crossings are not dyadic: the result is rounded, and every
  // sample point (a multiple of 1/8 off the integer lines) is far from a boundary it is not on.
  std::mt19937 rng(29);
  auto star = [&](double cx, double cy, double rmin, double rmax, int n) {
    std::uniform_real_distribution<double> radius(rmin, rmax), jitter(-0.3, 0.3);
    ring r;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * std::acos(-1.0) * (k + jitter(rng)) / n, d = radius(rng);
      r.push_back({std::round(cx + d * std::cos(a)), std::round(cy + d * std::sin(a))});
    }
    return r;
  };
  int cases = 0;
  for (int attempt = 0; attempt < 40 && cases < 8; ++attempt) {
    const polygon_with_holes2 region{star(0, 0, 8, 15, 12), {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}};
    const polygon_with_holes2 subject{
        star(std::round(std::uniform_real_distribution<double>(-6, 6)(rng)), 3, 2, 12, 9), {}};
    if (!clip::ring_problem(region.outer).empty() || !clip::ring_problem(subject.outer).empty())
      continue;  // rounding made a ring cross itself: draw again
    ++cases;
    const auto result = clip::polygon_region(region).intersect(subject);
    EXPECT_GT(expect_matches_reference(subject, region, result, -16, 16, 64), 3000);
    for (const auto& p : result) {  // orientation, and every vertex in both closed sets
      EXPECT_GT(twice_area(p.outer), 0);
      for (const auto& h : p.holes) EXPECT_LT(twice_area(h), 0);
    }
  }
  EXPECT_EQ(cases, 8);
}

TEST(PolygonBoolean, SegmentsKeepTheirPartsInTheClosedRegion) {
  const clip::polygon_region l(l_with_hole);
  using seg = clip::segment2;
  auto parts = [&](const seg& s) {
    std::vector<std::array<vec2d, 2>> out;
    for (const seg& p : l.clip_segment(s)) out.push_back({p.p0, p.p1});
    return out;
  };
  using parts_t = std::vector<std::array<vec2d, 2>>;
  // Through the hole: two parts.
  EXPECT_EQ(parts({{0, 1.5}, {8, 1.5}}),
            (parts_t{{{{1, 1.5}, {3, 1.5}}}, {{{3.5, 1.5}, {7, 1.5}}}}));
  // Along the boundary (the L's bottom edge, and along the hole's bottom edge): inside.
  EXPECT_EQ(parts({{0, 1}, {8, 1}}), (parts_t{{{{1, 1}, {7, 1}}}}));
  EXPECT_EQ(parts({{0, 1.25}, {8, 1.25}}), (parts_t{{{{1, 1.25}, {7, 1.25}}}}));
  // Touching the corner (7, 3) only: that point.
  EXPECT_EQ(parts({{8, 2}, {6, 4}}), (parts_t{{{{7, 3}, {7, 3}}}}));
  // Inside the hole, outside, wholly inside (kept bit for bit), reversed (ordered from p0).
  EXPECT_TRUE(parts({{3.1, 1.3}, {3.2, 1.4}}).empty());
  EXPECT_TRUE(parts({{8, 8}, {9, 9}}).empty());
  EXPECT_EQ(parts({{1.1, 2.1}, {2.9, 6.3}}), (parts_t{{{{1.1, 2.1}, {2.9, 6.3}}}}));
  EXPECT_EQ(parts({{2, 8}, {2, 0}}), (parts_t{{{{2, 7}, {2, 1}}}}));
  // A point.
  EXPECT_EQ(parts({{7, 2}, {7, 2}}), (parts_t{{{{7, 2}, {7, 2}}}}));
  EXPECT_TRUE(parts({{3.25, 1.5}, {3.25, 1.5}}).empty());
  // Against the reference: points along random segments between integer points.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-1, 9);
  const auto rings = rings_of(l_with_hole);
  for (int n = 0; n < 200; ++n) {
    const seg s{{double(coord(rng)), double(coord(rng))}, {double(coord(rng)), double(coord(rng))}};
    const auto kept = l.clip_segment(s);
    const vec2d d{s.p1[0] - s.p0[0], s.p1[1] - s.p0[1]};
    const double dd = d[0] * d[0] + d[1] * d[1];
    if (dd == 0) continue;
    auto t_of = [&](const vec2d& p) {
      return ((p[0] - s.p0[0]) * d[0] + (p[1] - s.p0[1]) * d[1]) / dd;
    };
    for (int k = 0; k <= 256; ++k) {
      const double t = k / 256.0;
      const vec2d p{s.p0[0] + t * d[0], s.p0[1] + t * d[1]};  // exact: dyadic
      const bool expected = locate(rings, p) != where::outside;
      bool covered = false, near_end = false;
      for (const seg& part : kept) {
        const double t0 = t_of(part.p0), t1 = t_of(part.p1);
        near_end = near_end || std::fabs(t - t0) < 1e-9 || std::fabs(t - t1) < 1e-9;
        covered = covered || (t0 - 1e-12 <= t && t <= t1 + 1e-12);
      }
      if (!near_end) {
        EXPECT_EQ(covered, expected) << "segment " << n << " t = " << t;
      }
    }
  }
}

TEST(PolygonBoolean, InvalidRingsAreRefused) {
  EXPECT_EQ(clip::ring_problem({{0, 0}, {1, 0}, {1, 1}, {0, 0}}), "");
  EXPECT_NE(clip::ring_problem({{0, 0}, {1, 0}, {0, 0}, {1, 0}}).find("fewer than 3 distinct"),
            std::string::npos);
  EXPECT_NE(clip::ring_problem({{0, 0}, {2, 2}, {2, 0}, {0, 2}}).find("not simple"),
            std::string::npos);  // a bow tie
  EXPECT_NE(clip::ring_problem({{0, 0}, {1, 0}, {2, 0}}).find("not simple"), std::string::npos);
  EXPECT_NE(clip::ring_problem({{0, 0}, {1, NAN}, {2, 0}}), "");
  EXPECT_TRUE(clip::ring_inside({{1, 1}, {2, 1}, {2, 2}}, {{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
  EXPECT_TRUE(clip::ring_inside({{0, 0}, {2, 1}, {2, 2}}, {{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
  EXPECT_FALSE(clip::ring_inside({{1, 1}, {4, 1}, {2, 2}}, {{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
  EXPECT_THROW(clip::polygon_region({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}), usage_error);
  EXPECT_THROW(clip::polygon_region({{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {{{1, 1}, {4, 1}, {2, 2}}}}),
               usage_error);
  const clip::polygon_region ok({{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {}});
  EXPECT_THROW(ok.intersect({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}), usage_error);
  EXPECT_THROW(ok.clip_segment({{0, 0}, {NAN, 1}}), usage_error);
}

// --- clip space (clip/homogeneous.h, clip/homogeneous_segment.h) -------------------------------

TEST(ClipSpace, TriangleCrossingTwoPlanesByHand) {
  // A = (1, 1, 0, 2) inside; B = (6, 0, 1, 3) beyond x = w; C = (2, 6, 0, 3) beyond y = w.
  // Plane x <= w (d = w - x: A 1, B -3, C 1), edges interpolated from their lexicographically
  // smaller end: A B at t = 1/4 gives P = (9/4, 3/4, 1/4, 9/4); C B at t = 1/4 gives
  // Q = C + (B - C) / 4 = (3, 9/2, 1/4, 3). Polygon A P Q C.
  // Plane y <= w (d = w - y: A 1, P 3/2, Q -3/2, C -3): A C at t = 1/4 gives (5/4, 9/4, 0, 9/4);
  // P Q at t = 1/2 gives (21/8, 21/8, 1/4, 21/8), on both planes. Sutherland–Hodgman's order:
  // that crossing, A, P, the other crossing.
  const auto in = parse(R"({"region": {"clip_space": true},
    "polygons": [[[1, 1, 0, 2], [6, 0, 1, 3], [2, 6, 0, 3]]]})");
  const json r = scene::run_clip(in, "", nullptr);
  EXPECT_EQ(r["dimension"], 4);
  EXPECT_EQ(r["polygons"][0],
            json::parse("[[1.25, 2.25, 0, 2.25], [1, 1, 0, 2], "
                        "[2.25, 0.75, 0.25, 2.25], [2.625, 2.625, 0.25, 2.625]]"));
  // The divide: x / w, y / w, z / w of each, correctly rounded.
  EXPECT_EQ(r["ndc"]["polygons"][0], (json{{1.25 / 2.25, 1, 0},
                                           {0.5, 0.5, 0},
                                           {1, 0.75 / 2.25, 0.25 / 2.25},
                                           {1, 1, 0.25 / 2.625}}));
}

TEST(ClipSpace, SegmentCrossingWZeroKeepsItsFrontPartOnly) {
  // From (1, 0, 0, 2) in front of the eye (NDC x = 1/2) to (1, 0, 0, -2) behind it. Divided
  // naively, the ends are at x = 1/2 and x = -1/2 and the segment between them is the wrong
  // ("internal") one: the projected line runs from 1/2 out through infinity (w = 0 at t = 1/2)
  // and back from -infinity to -1/2. In clip space: w - x is 1 and -3, so it leaves by x = w at
  // t = 1/4, (1, 0, 0, 1); w + x (3, -1) would cut at t = 3/4, y and z at t = 1/2: what is kept is
  // t in [0, 1/4], NDC x from 1/2 to 1, never the part through x = 0.
  const auto in = parse(R"({"region": {"clip_space": true}, "segments": [
    [[1, 0, 0, 2], [1, 0, 0, -2]], [[0, 0, 0, -1], [0.5, 0, 0, -2]], [[-1, 0, 0, -2], [-1, 0, 0, -2]],
    [[0, 0, 0, 0], [0, 0, 0, 1]], [[0, 0, -4, 2], [0, 0, 4, 2]]]})");
  for (const char* algorithm : {"cohen-sutherland", "liang-barsky"}) {
    const json r = scene::run_clip(in, algorithm, nullptr);
    EXPECT_EQ(r["segments"][0], json::parse("[[1, 0, 0, 2], [1, 0, 0, 1]]")) << algorithm;
    EXPECT_EQ(r["ndc"]["segments"][0], json::parse("[[0.5, 0, 0], [1, 0, 0]]"));
    // Wholly behind the eye: nothing, even where -p would be inside (OpenGL's rule: w >= 0).
    EXPECT_TRUE(r["segments"][1].is_null());
    EXPECT_TRUE(r["segments"][2].is_null());
    // The 4D origin is on every plane: kept, but it has no NDC point.
    EXPECT_EQ(r["segments"][3], json::parse("[[0, 0, 0, 0], [0, 0, 0, 1]]"));
    EXPECT_EQ(r["ndc"]["segments"][3], json::parse("[null, [0, 0, 0]]"));
    // Through the near and far planes: z from -w to w, NDC z from -1 to 1.
    EXPECT_EQ(r["segments"][4], json::parse("[[0, 0, -2, 2], [0, 0, 2, 2]]"));
    EXPECT_EQ(r["ndc"]["segments"][4], json::parse("[[0, 0, -1], [0, 0, 1]]"));
  }
  const json lb = scene::run_clip(in, "liang-barsky", nullptr);
  EXPECT_EQ(lb["t"][0], json::parse("[0, 0.25]"));
  EXPECT_EQ(lb["t"][4], json::parse("[0.25, 0.75]"));
  const json cs = scene::run_clip(in, "", nullptr);
  EXPECT_EQ(cs["algorithm"]["segments"], "cohen-sutherland");
  EXPECT_EQ(cs["outcodes"][0], json::parse("[0, 63]"));  // w < 0 with x, y, z = 0: every plane
}

TEST(ClipSpace, EveryKeptPointIsInTheVolumeAndTheSegmentsMatchAnExactReference) {
  // Random segments and triangles with w of either sign. Exact reference for segments: the
  // kept interval [t0, t1] from d_k(P(t)) = (1 - t) d_k(a) + t d_k(b) >= 0 in rationals.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> xyz(-4, 4), w(-2, 4);
  auto point = [&] { return clip::vec4d{xyz(rng), xyz(rng), xyz(rng), w(rng)}; };
  const double tolerance = 16 * std::numeric_limits<double>::epsilon() * 8;  // |values| <= 8
  auto in_volume = [&](const clip::vec4d& p) {
    for (int k = 0; k < 3; ++k)
      if (!(-p[3] - tolerance <= p[k] && p[k] <= p[3] + tolerance)) return false;
    return p[3] >= -tolerance;
  };
  int kept_segments = 0, kept_polygons = 0;
  for (int n = 0; n < 2000; ++n) {
    const clip::vec4d a = point(), b = point();
    mpq_class t0 = 0, t1 = 1;
    bool empty = false;
    for (int k = 0; k < 6; ++k) {
      const int axis = k / 2;
      const mpq_class sign = k % 2 ? -1 : 1;  // d_k = w + x, w - x, ...
      const mpq_class da = mpq_class(a[3]) + sign * a[axis];
      const mpq_class db = mpq_class(b[3]) + sign * b[axis];
      if (da < 0 && db < 0) empty = true;
      if (da < 0 && db >= 0) t0 = std::max(t0, mpq_class(da / (da - db)));
      if (db < 0 && da >= 0) t1 = std::min(t1, mpq_class(da / (da - db)));
    }
    empty = empty || t0 > t1;
    for (int cs = 0; cs < 2; ++cs) {
      clip::vec4d p, q;
      double s0 = 0, s1 = 1;
      const bool ok = cs ? clip::homogeneous_cohen_sutherland(a, b, p, q, &s0, &s1)
                         : clip::homogeneous_liang_barsky(a, b, p, q, &s0, &s1);
      if (!empty && t1 - t0 > mpq_class(1, 1 << 20)) {
        EXPECT_TRUE(ok) << n;
        EXPECT_NEAR(s0, t0.get_d(), 1e-12) << n;
        EXPECT_NEAR(s1, t1.get_d(), 1e-12) << n;
      }
      if (empty) {
        EXPECT_FALSE(ok) << n;
      }
      if (ok) {
        ++kept_segments;
        EXPECT_TRUE(in_volume(p) && in_volume(q)) << n;
      }
    }
    clip::homogeneous_polygon tri;
    tri.positions = {a, b, point()};
    const auto kept = clip::homogeneous_clip(tri);
    kept_polygons += kept.empty() ? 0 : 1;
    for (const auto& v : kept.positions) EXPECT_TRUE(in_volume(v)) << n;
  }
  EXPECT_GT(kept_segments, 400);
  EXPECT_GT(kept_polygons, 100);
}

// --- exbsp clip: polygon and clip_space regions -----------------------------------------------

const char* const l_region_json =
    R"({"polygon": {"outer": [[1, 7], [3, 7], [3, 3], [7, 3], [7, 1], [1, 1]],
                    "holes": [[[3, 1.25], [3.5, 1.25], [3.5, 1.75], [3, 1.75]]]}})";

TEST(ClipInput, PolygonRegionClipsPolygonsWithHolesAndSegments) {
  const auto in = parse(std::string(R"({"region": )") + l_region_json + R"(,
    "segments": [[[0, 1.5], [8, 1.5]], [[8, 8], [9, 9]]],
    "polygons": [[[0, 0], [6, 0], [6, 6], [4, 6], [4, 2], [2, 2], [2, 6], [0, 6]]],
    "polygons_with_holes": [{"outer": [[3, 0], [8, 0], [8, 2], [3, 2]],
                             "holes": [[[5, 1.25], [5.5, 1.25], [5.5, 1.75], [5, 1.75]]]}]})");
  for (const char* algorithm : {"", "weiler-atherton"}) {
    std::ostringstream log;
    const json r = scene::run_clip(in, algorithm, &log);
    EXPECT_EQ(r["algorithm"]["polygons"], "weiler-atherton");
    EXPECT_EQ(r["segments"], json::parse("[[[[1, 1.5], [3, 1.5]], [[3.5, 1.5], [7, 1.5]]], []]"));
    ASSERT_EQ(r["polygons"].size(), 1u);
    ASSERT_EQ(r["polygons"][0].size(), 1u);
    EXPECT_EQ(r["polygons"][0][0]["outer"],
              json::parse("[[1, 1], [6, 1], [6, 3], [4, 3], [4, 2], [2, 2], [2, 6], [1, 6]]"));
    EXPECT_EQ(r["polygons"][0][0]["holes"],
              json::parse("[[[3, 1.25], [3, 1.75], [3.5, 1.75], [3.5, 1.25]]]"));
    // [3, 7] x [1, 2] less both holes (1/4 each): the subject's stays a hole, the L's lies on
    // the subject's edge x = 3 and becomes a notch.
    ASSERT_EQ(r["polygons_with_holes"][0].size(), 1u);
    const json& k = r["polygons_with_holes"][0][0];
    std::vector<ring> rings{k["outer"].get<ring>()};
    for (const auto& h : k["holes"]) rings.push_back(h.get<ring>());
    mpq_class area = 0;
    for (const auto& ring_ : rings) area += twice_area(ring_);
    EXPECT_EQ(area / 2, mpq_class(7, 2));
    EXPECT_EQ(k["holes"].size(), 1u);
    EXPECT_NE(log.str().find("segment 0: 2 parts in the region"), std::string::npos) << log.str();
    EXPECT_NE(log.str().find("polygon with holes 0: 4 vertices, 1 holes -> 1 polygon"),
              std::string::npos)
        << log.str();
  }
  const std::string svg = scene::clip_svg(in, scene::run_clip(in, "", nullptr));
  EXPECT_NE(svg.find("<path id=\"region\""), std::string::npos);
  // The region and each result with its holes as one even-odd path of several closed rings.
  const std::size_t region = svg.find("<path id=\"region\"");
  EXPECT_NE(svg.find("Z M", region), std::string::npos);
  EXPECT_NE(svg.find("fill-rule=\"evenodd\"", region), std::string::npos);
  const std::size_t result = svg.find("<g id=\"result\"");
  ASSERT_NE(result, std::string::npos);
  EXPECT_NE(svg.find("fill-rule=\"evenodd\"", result), std::string::npos);
  EXPECT_EQ(svg.find("id=\"textbook\""), std::string::npos);
}

TEST(ClipInput, PolygonRegionAndWeilerAthertonGoTogether) {
  const auto in = parse(std::string(R"({"region": )") + l_region_json +
                        R"(, "polygons": [[[0, 0], [1, 0], [0, 1]]]})");
  for (const char* algorithm :
       {"sutherland-hodgman", "cohen-sutherland", "liang-barsky", "cyrus-beck"})
    expect_region_refused(in, algorithm, "weiler-atherton only");
  for (const char* region : {R"({"rect": [0, 0, 1, 1]})", R"({"convex": [[0, 0], [1, 0], [0, 1]]})",
                             R"({"clip_space": true})"}) {
    const auto other = parse(std::string(R"({"region": )") + region + "}");
    expect_region_refused(other, "weiler-atherton", "against a polygon region");
  }
}

TEST(ClipInput, BadPolygonRegionsAndClipSpaceInputNameTheKey) {
  auto with = [](const std::string& region, const std::string& rest = "") {
    return error_key(R"({"region": )" + region + rest + "}");
  };
  EXPECT_EQ(with(R"({"polygon": {"outer": [[0, 0], [1, 0], [0, 0]]}})"), "/region/polygon/outer");
  EXPECT_EQ(with(R"({"polygon": {"outer": [[0, 0], [2, 2], [2, 0], [0, 2]]}})"),
            "/region/polygon/outer");  // a bow tie
  EXPECT_EQ(with(R"({"polygon": {"outer": [[0, 0], [1, 0], [1, 1, 1]]}})"),
            "/region/polygon/outer/2");
  EXPECT_EQ(with(R"({"polygon": {"holes": []}})"), "/region/polygon/outer");
  EXPECT_EQ(with(R"({"polygon": {"outer": [[0, 0], [4, 0], [0, 4]], "hole": []}})"),
            "/region/polygon/hole");
  EXPECT_EQ(with(R"({"polygon": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]],
                    "holes": [[[1, 1], [2, 1], [2, 2]], [[1, 3], [5, 3], [2, 3.5]]]}})"),
            "/region/polygon/holes/1");  // pokes out of the outer ring
  EXPECT_EQ(with(R"({"polygon": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]],
                    "holes": [[[1, 1], [3, 3], [3, 1], [1, 3]]]}})"),
            "/region/polygon/holes/0");  // crosses itself
  EXPECT_EQ(with(R"({"polygon": [[0, 0], [1, 0], [0, 1]]})"), "/region/polygon");
  std::string message;
  exbsp_test::error_key(
      [] {
        parse(R"({"region": {"polygon": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]],
                    "holes": [[[1, 3], [5, 3], [2, 3.5]]]}}})");
      },
      &message);
  EXPECT_NE(message.find("not inside the outer ring"), std::string::npos) << message;
  const std::string square = R"({"polygon": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]]}})";
  EXPECT_EQ(with(square, R"(, "polygons": [[[0, 0], [2, 2], [2, 0], [0, 2]]])"), "/polygons/0");
  EXPECT_EQ(with(square, R"(, "polygons_with_holes": [{"outer": [[0, 0], [1, 0], [0, 1]],
                             "holes": [[[0.1, 0.1], [0.2, 0.1], [5, 5]]]}])"),
            "/polygons_with_holes/0/holes/0");
  EXPECT_EQ(
      with(square, R"(, "polygons_with_holes": [{"outer": [[0, 0], [1, 0], [0, 1]], "x": 1}])"),
      "/polygons_with_holes/0/x");
  EXPECT_EQ(with(R"({"rect": [0, 0, 1, 1]})",
                 R"(, "polygons_with_holes": [{"outer": [[0, 0], [1, 0], [0, 1]]}])"),
            "/polygons_with_holes");
  EXPECT_EQ(with(R"({"clip_space": false})"), "/region/clip_space");
  EXPECT_EQ(with(R"({"clip_space": true})", R"(, "segments": [[[0, 0, 0, 1], [0, 0, 1]]])"),
            "/segments/0/1");
  EXPECT_EQ(with(R"({"clip_space": true})", R"(, "polygons": [[[0, 0, 0, 1], [1, 0, 0, 1]]])"),
            "/polygons/0");
  // Clip space takes the homogeneous box clippers only.
  const auto cs =
      parse(R"({"region": {"clip_space": true}, "segments": [[[0, 0, 0, 1], [1, 1, 1, 1]]]})");
  EXPECT_THROW(scene::run_clip(cs, "cyrus-beck", nullptr), scene_error);
  EXPECT_THROW(scene::run_clip(cs, "sutherland-hodgman", nullptr), scene_error);
  EXPECT_THROW(scene::clip_svg(cs, scene::run_clip(cs, "", nullptr)), scene_error);
  std::ostringstream log;
  scene::run_clip(cs, "", &log);
  EXPECT_NE(log.str().find("p1 outcode 000000 (inside)"), std::string::npos) << log.str();
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

TEST_F(ClipCli, PolygonRegionJsonAndSvg) {
  write("in.json", std::string(R"({"region": )") + l_region_json + R"(,
    "segments": [[[0, 1.5], [8, 1.5]]],
    "polygons_with_holes": [{"outer": [[0, 0], [6, 0], [6, 6], [4, 6], [4, 2], [2, 2], [2, 6], [0, 6]]}]})");
  run_result r = run("clip in.json -o out.json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read_file(dir / "out.json"));
  EXPECT_EQ(j["algorithm"]["polygons"], "weiler-atherton");
  EXPECT_EQ(j["segments"][0].size(), 2u);
  EXPECT_EQ(j["polygons_with_holes"][0][0]["holes"].size(), 1u);
  EXPECT_TRUE(j["polygons"].empty());
  r = run("clip in.json --algorithm weiler-atherton -o out.svg");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = read_file(dir / "out.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
  r = run("clip in.json --algorithm sutherland-hodgman -o refused.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/region: a polygon region"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "refused.json"));
}

TEST_F(ClipCli, ClipSpaceJson) {
  write("in.json", R"({"region": {"clip_space": true}, "segments": [[[1, 0, 0, 2], [1, 0, 0, -2]]],
    "polygons": [[[1, 1, 0, 2], [6, 0, 1, 3], [2, 6, 0, 3]]]})");
  run_result r = run("clip in.json --algorithm liang-barsky -v");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["dimension"], 4);
  EXPECT_EQ(j["segments"][0], json::parse("[[1, 0, 0, 2], [1, 0, 0, 1]]"));
  EXPECT_EQ(j["ndc"]["segments"][0], json::parse("[[0.5, 0, 0], [1, 0, 0]]"));
  EXPECT_EQ(j["polygons"][0].size(), 4u);
  EXPECT_NE(r.err.find("p1 outcode 111111 (x<-w|x>w|y<-w|y>w|z<-w|z>w)"), std::string::npos)
      << r.err;
  r = run("clip in.json -o out.svg");  // 4D: no drawing
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(dir / "out.svg"));
}

TEST_F(ClipCli, BadPolygonAndClipSpaceInputExit2NamingTheKeyAndWriteNothing) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"region": {"polygon": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]],
          "holes": [[[1, 1], [3, 3], [3, 1], [1, 3]]]}}})",
       "/region/polygon/holes/0: the ring is not simple"},
      {R"({"region": {"polygon": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]],
          "holes": [[[1, 3], [5, 3], [2, 3.5]]]}}})",
       "/region/polygon/holes/0: the hole is not inside the outer ring"},
      {R"({"region": {"polygon": {"outer": [[0, 0], [4, 0], [4, 0]]}}})",
       "/region/polygon/outer: the ring has fewer than 3 distinct points"},
      {R"({"region": {"rect": [0, 0, 1, 1]}, "polygons_with_holes": []})",
       "/polygons_with_holes: polygons with holes are clipped against a polygon region only"},
      {R"({"region": {"clip_space": true}, "segments": [[[0, 0, 0, 1], [0, 0, "z", 1]]]})",
       "/segments/0/1/2: must be a number"},
  };
  for (const auto& [input, message] : cases)
    for (const char* out : {"out.json", "out.svg"}) {
      write("bad.json", input);
      const run_result r = run(std::string("clip bad.json -o ") + out);
      EXPECT_EQ(r.status, 2) << input;
      EXPECT_NE(r.err.find(std::string("bad.json: ") + message), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(dir / out));
    }
  write("rect.json",
        R"({"region": {"rect": [0, 0, 1, 1]}, "polygons": [[[0, 0], [1, 0], [0, 1]]]})");
  const run_result r = run("clip rect.json --algorithm weiler-atherton -o out.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/region: weiler-atherton clips against a polygon region"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
}

}  // namespace
