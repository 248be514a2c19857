// SPDX-License-Identifier: LGPL-3.0-or-later
// Drawing sheets (`exbsp drawing`, src/drawing/): ISO option values, the layout of the views
// (they line up, first and third angle put them on opposite sides), hidden lines of parts whose
// images are known in closed form (oracles written here from the boxes' coordinates, not from
// the code under test), the hatched section against the exact cap's area, the files' sizes,
// units, layers, line widths and byte-identical repeats, errors, and folder runs.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <thread>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/clip/section_cap.h>
#include <exbsp/mesh/mesh_io.h>
#include "drawing/drawing.h"
#include "drawing/hatch.h"
#include "drawing/sheet_dxf.h"
#include "drawing/sheet_writers.h"
#include "scene/drawing_command.h"
#include "support/cli_support.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp;
using drawing::layer_id;
using drawing::point2;

/// OFF text of axis-aligned boxes (outward triangles), appended in order.
std::string boxes_off(const std::vector<std::array<double, 6>>& boxes) {
  std::string v, f;
  std::size_t base = 0;
  for (const auto& b : boxes) {
    for (int c = 0; c < 8; ++c)
      v += std::to_string(c & 1 ? b[3] : b[0]) + " " + std::to_string(c & 2 ? b[4] : b[1]) + " " +
           std::to_string(c & 4 ? b[5] : b[2]) + "\n";
    // Faces as quads (outward): -x, +x, -y, +y, -z, +z.
    const int q[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                         {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& quad : q)
      f += "4 " + std::to_string(base + quad[0]) + " " + std::to_string(base + quad[1]) + " " +
           std::to_string(base + quad[2]) + " " + std::to_string(base + quad[3]) + "\n";
    base += 8;
  }
  return "OFF\n" + std::to_string(base) + " " + std::to_string(boxes.size() * 6) + " 0\n" + v + f;
}

triangle_soup boxes_soup(const std::vector<std::array<double, 6>>& boxes) {
  return read_mesh_data(boxes_off(boxes), mesh_format::off, "boxes.off");
}

drawing::drawing_options line_options(std::vector<std::string> views) {
  drawing::drawing_options o;
  o.views = std::move(views);
  o.lines_only = true;
  o.date = "2026-01-01";
  return o;
}

/// The lines of `layer` whose points all lie in the box of view `v`.
std::vector<const drawing::sheet_polyline*> lines_in(const drawing::sheet& s,
                                                     const drawing::sheet_view& v, layer_id layer) {
  std::vector<const drawing::sheet_polyline*> out;
  for (const auto& l : s.lines) {
    if (l.layer != layer) continue;
    bool inside = true;
    for (const point2& p : l.points)
      inside = inside && p.x >= v.lower_left.x - 1e-9 && p.x <= v.lower_left.x + v.width + 1e-9 &&
               p.y >= v.lower_left.y - 1e-9 && p.y <= v.lower_left.y + v.height + 1e-9;
    if (inside) out.push_back(&l);
  }
  return out;
}

struct extent {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
};

extent extent_of(const std::vector<const drawing::sheet_polyline*>& lines) {
  extent e;
  for (const auto* l : lines)
    for (const point2& p : l->points) {
      e.x0 = std::min(e.x0, p.x);
      e.x1 = std::max(e.x1, p.x);
      e.y0 = std::min(e.y0, p.y);
      e.y1 = std::max(e.y1, p.y);
    }
  return e;
}

const drawing::sheet_view& view_named(const drawing::sheet& s, const std::string& name) {
  for (const auto& v : s.views)
    if (v.name == name) return v;
  throw std::runtime_error("no view " + name);
}

double distance_to_segment(point2 p, point2 a, point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/// Distance from p to the nearest segment of `lines`.
double distance_to_lines(point2 p, const std::vector<const drawing::sheet_polyline*>& lines) {
  double best = INFINITY;
  for (const auto* l : lines)
    for (std::size_t i = 0; i + 1 < l->points.size(); ++i)
      best = std::min(best, distance_to_segment(p, l->points[i], l->points[i + 1]));
  return best;
}

}  // namespace

TEST(DrawingOptions, IsoPaperSizesScalesUnitsAndTheirErrors) {
  // ISO 216, landscape.
  EXPECT_EQ(drawing::parse_paper("A4").width, 297);
  EXPECT_EQ(drawing::parse_paper("A4").height, 210);
  EXPECT_EQ(drawing::parse_paper("A3").width, 420);
  EXPECT_EQ(drawing::parse_paper("A0").width, 1189);
  EXPECT_EQ(drawing::parse_paper("A0").height, 841);
  EXPECT_EQ(drawing::parse_paper("500x300").width, 500);
  EXPECT_THROW(drawing::parse_paper("A7"), usage_error);
  EXPECT_THROW(drawing::parse_paper("5x300"), usage_error);
  EXPECT_THROW(drawing::parse_paper("nanx300"), usage_error);
  EXPECT_EQ(drawing::parse_scale("1:20").den, 20);
  EXPECT_EQ(drawing::parse_scale("5:1").num, 5);
  EXPECT_THROW(drawing::parse_scale("2:3"), usage_error);
  EXPECT_THROW(drawing::parse_scale("0:1"), usage_error);
  EXPECT_THROW(drawing::parse_scale("1:-2"), usage_error);
  EXPECT_EQ(drawing::unit_mm("in"), 25.4);
  EXPECT_EQ(drawing::unit_mm("m"), 1000);
  EXPECT_THROW(drawing::unit_mm("ft"), usage_error);
  // ISO 5455: ... 1:5, 1:2, 1:1, 2:1, 5:1, 10:1 ... in increasing order.
  const auto scales = drawing::standard_scales();
  for (std::size_t i = 1; i < scales.size(); ++i)
    EXPECT_LT(scales[i - 1].factor(), scales[i].factor());
  std::vector<std::string> names;
  for (const auto& s : scales) names.push_back(s.text());
  for (const char* iso : {"1:1000", "1:500", "1:200", "1:100", "1:50", "1:20", "1:10", "1:5", "1:2",
                          "1:1", "2:1", "5:1", "10:1", "20:1", "50:1"})
    EXPECT_NE(std::find(names.begin(), names.end(), iso), names.end()) << iso;
  const auto s = drawing::parse_section("AB=0,1,0,-2.5");
  EXPECT_EQ(s.letter, "AB");
  EXPECT_EQ(s.plane[3], -2.5);
  EXPECT_THROW(drawing::parse_section("a=0,1,0,0"), usage_error);
  EXPECT_THROW(drawing::parse_section("A=0,0,0,1"), usage_error);
  EXPECT_THROW(drawing::parse_section("A=0,1,0"), usage_error);
  EXPECT_THROW(drawing::parse_section("A=0,1,0,inf"), usage_error);
  EXPECT_THROW(drawing::parse_views("front,side"), usage_error);
  EXPECT_THROW(drawing::parse_views("front,front"), usage_error);
  EXPECT_EQ(drawing::dash_pattern(drawing::line_style::dashed, 0.25),
            (std::vector<double>{3, 0.75}));  // ISO 128-20 type 02: 12 d, 3 d
}

TEST(DrawingLayout, PrincipalViewsLineUpAndSitByTheProjectionMethod) {
  // A 40 x 20 x 10 box at 1:1: the front view is 40 wide and 10 high, the top 40 x 20, the left
  // 20 x 10 (oracle: the box's own sizes). Front and top share their x positions, front and
  // left their y positions; first angle puts top below and left on the right, third angle the
  // opposite.
  const triangle_soup box = boxes_soup({{0, 0, 0, 40, 20, 10}});
  for (const auto method :
       {drawing::projection_method::first_angle, drawing::projection_method::third_angle}) {
    auto o = line_options({"front", "top", "left"});
    o.projection = method;
    o.scale = drawing::drawing_scale{1, 1};
    const drawing::sheet s = drawing::make_sheet(box, "box", {}, o);
    const extent front = extent_of(lines_in(s, view_named(s, "front"), layer_id::visible));
    const extent top = extent_of(lines_in(s, view_named(s, "top"), layer_id::visible));
    const extent left = extent_of(lines_in(s, view_named(s, "left"), layer_id::visible));
    const double grid = 0.002;  // the drawing grid: 2 micrometres of paper
    EXPECT_NEAR(front.x1 - front.x0, 40, grid);
    EXPECT_NEAR(front.y1 - front.y0, 10, grid);
    EXPECT_NEAR(top.x1 - top.x0, 40, grid);
    EXPECT_NEAR(top.y1 - top.y0, 20, grid);
    EXPECT_NEAR(left.x1 - left.x0, 20, grid);
    EXPECT_NEAR(left.y1 - left.y0, 10, grid);
    EXPECT_NEAR(front.x0, top.x0, 1e-9);
    EXPECT_NEAR(front.x1, top.x1, 1e-9);
    EXPECT_NEAR(front.y0, left.y0, 1e-9);
    EXPECT_NEAR(front.y1, left.y1, 1e-9);
    if (method == drawing::projection_method::first_angle) {
      EXPECT_LT(top.y1, front.y0);
      EXPECT_GT(left.x0, front.x1);
    } else {
      EXPECT_GT(top.y0, front.y1);
      EXPECT_LT(left.x1, front.x0);
    }
    EXPECT_TRUE(lines_in(s, view_named(s, "front"), layer_id::hidden).empty());
    // Everything on the paper, inside the frame.
    for (const auto& l : s.lines)
      for (const point2& p : l.points) {
        EXPECT_GE(p.x, 0);
        EXPECT_LE(p.x, s.width);
        EXPECT_GE(p.y, 0);
        EXPECT_LE(p.y, s.height);
      }
  }
}

TEST(DrawingLayout, AutoScaleIsTheLargestStandardScaleThatFits) {
  // The drawing area of A3: 390 - 8 = 382 mm wide, 277 - 32 (title block) - 8 = 237 mm high;
  // each view has 2 mm of air on each side, views 14 mm apart. A 1000 x 400 x 300 box, views
  // front, top, left: at 1:5 the width is 200 + 80 + 14 + 8 = 302 mm (fits), at 1:2 it is 722.
  // A 4 x 2 x 1 box: at 50:1 200 + 100 + 22 = 322 mm wide, 50 + 100 + 22 = 172 high (fits);
  // at 100:1 it is 622.
  auto o = line_options({"front", "top", "left"});
  const drawing::sheet big =
      drawing::make_sheet(boxes_soup({{0, 0, 0, 1000, 400, 300}}), "big", {}, o);
  EXPECT_NEAR(view_named(big, "front").mm_per_model, 0.2, 1e-15);
  const drawing::sheet small =
      drawing::make_sheet(boxes_soup({{0, 0, 0, 4, 2, 1}}), "small", {}, o);
  EXPECT_NEAR(view_named(small, "front").mm_per_model, 50, 1e-12);
  o.scale = drawing::drawing_scale{1, 2};
  try {
    drawing::make_sheet(boxes_soup({{0, 0, 0, 1000, 400, 300}}), "big", {}, o);
    FAIL() << "1:2 cannot fit";
  } catch (const usage_error& e) {
    EXPECT_NE(std::string(e.what()).find("largest standard scale that fits is 1:5"),
              std::string::npos)
        << e.what();
  }
  // Inches: a 10 x 4 x 3 in box is 254 x 101.6 x 76.2 mm: at 1:1, 254 + 101.6 + 22 = 377.6 mm
  // wide (fits), so 1:1, 25.4 mm per model unit.
  o.scale.reset();
  o.units = "in";
  const drawing::sheet inches = drawing::make_sheet(boxes_soup({{0, 0, 0, 10, 4, 3}}), "in", {}, o);
  EXPECT_NEAR(view_named(inches, "front").mm_per_model, 25.4, 1e-12);
}

TEST(DrawingHiddenLines, ABoxBehindABoxIsDashedInFrontAndSolidFromAbove) {
  // Box A = [0,40] x [0,20] x [0,10]; box B = [10,20] x [30,40] x [2,8] stands behind A (larger
  // y) and is lower and narrower: from the front (viewer at -y) all of B is hidden by A, its
  // outline is the rectangle x in [10, 20], z in [2, 8]; from above both are visible.
  const triangle_soup soup = boxes_soup({{0, 0, 0, 40, 20, 10}, {10, 30, 2, 20, 40, 8}});
  auto o = line_options({"front", "top"});
  o.scale = drawing::drawing_scale{1, 1};
  const drawing::sheet s = drawing::make_sheet(soup, "boxes", {}, o);
  const auto& fv = view_named(s, "front");
  const auto hidden = lines_in(s, fv, layer_id::hidden);
  const auto visible = lines_in(s, fv, layer_id::visible);
  ASSERT_FALSE(hidden.empty());
  const extent a = extent_of(visible);  // the front view's visible lines: box A's outline
  // Sheet position of model (x, z) in the front view, from A's outline (x 0..40, z 0..10).
  const auto at = [&](double x, double z) { return point2{a.x0 + x, a.y0 + z}; };
  const point2 corners[4] = {at(10, 2), at(20, 2), at(20, 8), at(10, 8)};
  for (const auto* l : hidden) {
    EXPECT_EQ(l->style, drawing::line_style::dashed);
    EXPECT_EQ(l->width, 0.25);
    for (const point2& p : l->points) {
      double d = INFINITY;
      for (int k = 0; k < 4; ++k)
        d = std::min(d, distance_to_segment(p, corners[k], corners[(k + 1) % 4]));
      EXPECT_LT(d, 0.003) << "hidden point off B's outline: " << p.x << "," << p.y;
    }
  }
  // Every side of B's outline is drawn hidden (sampled), and none of it visible.
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i <= 20; ++i) {
      const double t = i / 20.0;
      const point2 p{corners[k].x + t * (corners[(k + 1) % 4].x - corners[k].x),
                     corners[k].y + t * (corners[(k + 1) % 4].y - corners[k].y)};
      EXPECT_LT(distance_to_lines(p, hidden), 0.003);
      if (i > 0 && i < 20) {
        EXPECT_GT(distance_to_lines(p, visible), 1.0);
      }
    }
  // From above, B's outline (x 10..20, y 30..40) is visible and nothing is hidden.
  const auto& tv = view_named(s, "top");
  EXPECT_TRUE(lines_in(s, tv, layer_id::hidden).empty());
  const extent t = extent_of(lines_in(s, tv, layer_id::visible));
  EXPECT_NEAR(t.x1 - t.x0, 40, 0.002);
  EXPECT_NEAR(t.y1 - t.y0, 40, 0.002);
  // A chain is one polyline: B's hidden outline is at most 4 chains (one per side when the
  // sides end at the edge-on faces' vertices), not dozens of two-point segments.
  EXPECT_LE(hidden.size(), 8u);
}

TEST(DrawingHatch, EvenOddRegionsWithHolesAndLinesOnTheirBoundary) {
  // A 30 x 20 square with a 10 x 10 hole: area 500; hatch lines at 45 degrees, spacing 1:
  // their total length times the spacing approximates the area, every endpoint lies on a ring.
  const std::vector<std::vector<point2>> rings = {{{0, 0}, {30, 0}, {30, 20}, {0, 20}},
                                                  {{10, 5}, {10, 15}, {20, 15}, {20, 5}}};
  EXPECT_NEAR(drawing::even_odd_area(rings), 500, 1e-12);
  const auto lines = drawing::hatch_lines(rings, 1.0);
  double length = 0;
  for (const auto& h : lines) {
    length += std::hypot(h.b.x - h.a.x, h.b.y - h.a.y);
    EXPECT_NEAR(h.b.y - h.a.y, h.b.x - h.a.x, 1e-9);  // 45 degrees
    for (const point2& p : {h.a, h.b}) {
      double d = INFINITY;
      for (const auto& r : rings)
        for (std::size_t i = 0; i < r.size(); ++i)
          d = std::min(d, distance_to_segment(p, r[i], r[(i + 1) % r.size()]));
      EXPECT_LT(d, 1e-9);
    }
    // The midpoint is inside the square and outside the hole.
    const point2 m{(h.a.x + h.b.x) / 2, (h.a.y + h.b.y) / 2};
    EXPECT_FALSE(m.x > 10 && m.x < 20 && m.y > 5 && m.y < 15);
  }
  EXPECT_NEAR(length * 1.0, 500, 500 * 0.03);
}

TEST(DrawingSection, HatchedRegionIsTheExactCapAndTheCuttingPlaneSitsOnTheTopView) {
  // Box [0,40] x [0,20] x [0,10] cut at y = 7 (kept y >= 7), seen along +y: the cap is the
  // 40 x 10 rectangle (area 400 model units). At 2:1 its hatch region has 1600 mm^2.
  const triangle_soup box = boxes_soup({{0, 0, 0, 40, 20, 10}});
  const section_result cut = section_with_cap(box, {0, 1, 0, -7});
  drawing::section_cut c;
  c.spec = drawing::parse_section("A=0,1,0,-7");
  c.cap_face = cut.cap_face;
  c.solid.face_count = box.face_count + 1;
  for (const auto& p : cut.points) c.solid.vertices.push_back(p.v);
  for (const auto& t : cut.kept) c.solid.triangles.push_back({t.p, t.face});
  for (const auto& t : cut.cap) c.solid.triangles.push_back({t.p, t.face});
  for (const auto& ch : cut.outline) {
    std::vector<std::array<double, 3>> loop;
    for (auto i : ch.p) loop.push_back(cut.points[i].v);
    c.loops.push_back(loop);
  }
  auto o = line_options({"front", "top"});
  o.sections = {c.spec};
  o.scale = drawing::drawing_scale{2, 1};
  const drawing::sheet s = drawing::make_sheet(box, "box", {c}, o);
  ASSERT_EQ(s.hatch_regions.size(), 1u);
  EXPECT_NEAR(drawing::even_odd_area(s.hatch_regions[0]), 1600, 1600 * 1e-9);
  const auto& sv = view_named(s, "section A");
  const auto hatch = lines_in(s, sv, layer_id::hatching);
  ASSERT_FALSE(hatch.empty());
  double length = 0;
  for (const auto* l : hatch)
    length += std::hypot(l->points[1].x - l->points[0].x, l->points[1].y - l->points[0].y);
  // Spacing 2 mm (the region is 20 mm high: at least 8 lines across): length * spacing ~ area.
  EXPECT_NEAR(length * 2, 1600, 1600 * 0.05);
  // The cutting-plane line: a chain line on the top view at y = 7 (model), i.e. horizontal.
  bool chain = false;
  for (const auto& l : s.lines)
    if (l.layer == layer_id::cutting_planes && l.style == drawing::line_style::chain) {
      chain = true;
      EXPECT_NEAR(l.points[0].y, l.points[1].y, 1e-9);
      const auto& tv = view_named(s, "top");
      const extent t = extent_of(lines_in(s, tv, layer_id::visible));
      EXPECT_NEAR(l.points[0].y, t.y0 + 7 * 2, 0.002);  // 7 model units above the box's front
    }
  EXPECT_TRUE(chain);
  bool label = false;
  for (const auto& t : s.texts) label = label || t.text == "SECTION A\u2013A";
  EXPECT_TRUE(label);
}

TEST(DrawingSection, OfARealMeshHatchesExactlyTheCapArea) {
  // fandisk cut through its middle: the hatch region (the exact outline loops, rounded once)
  // has the area of the exact cap's triangles (computed here from their corners), times the
  // scale squared, to 1e-9.
  const std::string path = exbsp_test::corpus_dir() + "fandisk.off";
  EXBSP_NEED_CORPUS(std::filesystem::exists(path), path);
  auto o = line_options({"front"});
  const triangle_soup part = read_mesh(path);
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& v : part.vertices) {
    lo = std::min(lo, v[1]);
    hi = std::max(hi, v[1]);
  }
  const double y = (lo + hi) / 2;
  o.sections = {drawing::parse_section("B=0,1,0," + std::to_string(-y))};
  const section_result cut = section_with_cap(part, o.sections[0].plane);
  long double cap = 0;
  for (const auto& t : cut.cap) {
    const auto& a = cut.points[t.p[0]].v;
    const auto& b = cut.points[t.p[1]].v;
    const auto& c = cut.points[t.p[2]].v;
    const long double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const long double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const long double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    cap += std::sqrt(nx * nx + ny * ny + nz * nz) / 2;
  }
  ASSERT_GT(cap, 0);
  const drawing::sheet s = scene::make_drawing_sheet(path, o, false, nullptr);
  ASSERT_EQ(s.hatch_regions.size(), 1u);
  const double k = view_named(s, "section B").mm_per_model;
  EXPECT_NEAR(drawing::even_odd_area(s.hatch_regions[0]) / (k * k), static_cast<double>(cap),
              static_cast<double>(cap) * 1e-9);
}

class DrawingCli : public exbsp_test::cli_fixture {};

TEST_F(DrawingCli, SheetsInMillimetresWithLayersIsoLinesAndIdenticalRepeats) {
  write("part.off", boxes_off({{0, 0, 0, 40, 20, 10}, {10, 30, 2, 20, 40, 8}}));
  for (const char* ext : {"svg", "pdf", "dxf"}) {
    const std::string args = std::string(
                                 "drawing part.off --sheet A4 --lines-only --date 2026-01-01 "
                                 "--section A=0,1,0,-5 -o a.") +
                             ext;
    auto r = run(args);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string first = exbsp_test::read_file(dir / (std::string("a.") + ext));
    r = run(args);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(first, exbsp_test::read_file(dir / (std::string("a.") + ext))) << ext;
  }
  const std::string svg = exbsp_test::read_file(dir / "a.svg");
  EXPECT_NE(svg.find("width=\"297mm\" height=\"210mm\" viewBox=\"0 0 297 210\""),
            std::string::npos);
  for (const char* layer : {"visible", "hidden", "hatching", "cutting-planes", "frame"})
    EXPECT_NE(
        svg.find(std::string("inkscape:groupmode=\"layer\" inkscape:label=\"") + layer + "\""),
        std::string::npos)
        << layer;
  EXPECT_NE(svg.find("stroke-width=\"0.5\" stroke-linecap=\"round\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-width=\"0.25\" stroke-linecap=\"butt\" stroke-linejoin=\"miter\" "
                     "stroke-dasharray=\"3 0.75\""),
            std::string::npos);
  const std::string pdf = exbsp_test::read_file(dir / "a.pdf");
  // A4 landscape in points: 297 and 210 mm at 72 / 25.4.
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 841.889764 595.275591 ]"), std::string::npos);
  const std::string dxf = exbsp_test::read_file(dir / "a.dxf");
  EXPECT_NE(dxf.find("$INSUNITS\n 70\n4"), std::string::npos);
  EXPECT_NE(dxf.find("HIDDEN"), std::string::npos);
  // --line-widths acts.
  ASSERT_EQ(run("drawing part.off --lines-only --line-widths 0.35,0.18 -o w.svg").status, 0);
  const std::string w = exbsp_test::read_file(dir / "w.svg");
  EXPECT_NE(w.find("stroke-width=\"0.35\""), std::string::npos);
  EXPECT_NE(w.find("stroke-dasharray=\"2.16 0.54\""), std::string::npos);
}

TEST_F(DrawingCli, BadRequestsStopWithExit2AndNoFile) {
  write("part.off", boxes_off({{0, 0, 0, 1000, 400, 300}}));
  const std::pair<const char*, const char*> cases[] = {
      {"drawing part.off --sheet A7 -o a.svg", "--sheet"},
      // The default views (front, top, left, iso) of this box fit at 1:10, not at 1:5.
      {"drawing part.off --scale 1:2 -o a.svg", "largest standard scale that fits is 1:10"},
      {"drawing part.off --scale 2:3 -o a.svg", "--scale"},
      {"drawing part.off -o a.png", ".svg, .pdf or .dxf"},
      {"drawing part.off --views front,side -o a.svg", "side"},
      {"drawing part.off --section A=0,0,0,1 -o a.svg", "--section"},
      {"drawing part.off --section A=0,1,0,-5000 -o a.svg", "does not cut"},
      {"drawing part.off --units ft -o a.svg", "--units"},
      {"drawing part.off --line-widths 0.5 -o a.svg", "--line-widths"},
      {"drawing missing.off -o a.svg", "missing.off"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.svg")) << args;
  }
}

TEST_F(DrawingCli, AFolderBecomesADrawingSetAndFinishedSheetsAreNotRedone) {
  std::filesystem::create_directory(dir / "parts");
  write("parts/a.off", boxes_off({{0, 0, 0, 4, 2, 1}}));
  write("parts/b.off", boxes_off({{0, 0, 0, 40, 20, 10}}));
  write("parts/notes.txt", "not a mesh");
  auto r = run("drawing parts -o sheets --formats pdf,svg --lines-only --date 2026-01-01");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f : {"a.pdf", "a.svg", "b.pdf", "b.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / "sheets" / f)) << f;
  // Identical to a single run of the same part.
  ASSERT_EQ(run("drawing parts/b.off -o b.svg --lines-only --date 2026-01-01 --title b").status, 0);
  EXPECT_EQ(exbsp_test::read_file(dir / "b.svg"), exbsp_test::read_file(dir / "sheets" / "b.svg"));
  r = run("drawing parts -o sheets --formats pdf,svg --lines-only --date 2026-01-01");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("kept 4 finished before"), std::string::npos) << r.err;
  r = run("drawing parts -o sheets --formats pdf --lines-only --date 2026-01-01 --force");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("wrote 2 files"), std::string::npos) << r.err;
  EXPECT_EQ(run("drawing parts -o sheets/x.pdf").status, 2);
  // A DXF holds the line drawing: made with the shaded fills (for the PDF) or without them (DXF
  // alone skips them), it is the same file.
  ASSERT_EQ(run("drawing parts -o both --formats pdf,dxf --date 2026-01-01 -q").status, 0);
  ASSERT_EQ(run("drawing parts -o dxf --formats dxf --date 2026-01-01 -q").status, 0);
  for (const char* f : {"a.dxf", "b.dxf"})
    EXPECT_EQ(exbsp_test::read_file(dir / "both" / f), exbsp_test::read_file(dir / "dxf" / f)) << f;
}

namespace {

/// The polylines of the <path> elements inside <g id="GROUP"> of an SVG (d attributes of
/// M/L commands with absolute coordinates).
std::vector<std::vector<point2>> svg_group_polylines(const std::string& svg,
                                                     const std::string& group) {
  std::vector<std::vector<point2>> out;
  const std::size_t g = svg.find("<g id=\"" + group + "\"");
  if (g == std::string::npos) return out;
  const std::size_t end = svg.find("</g>", g);
  std::size_t at = g;
  while ((at = svg.find(" d=\"", at)) != std::string::npos && at < end) {
    at += 4;
    const std::size_t close = svg.find('"', at);
    const std::string d = svg.substr(at, close - at);
    std::vector<double> numbers;
    for (std::size_t i = 0; i <= d.size(); ++i) {
      if (i < d.size() && (d[i] == 'M' || d[i] == 'L' || d[i] == ' ' || d[i] == ',')) {
        if (d[i] == 'M') {
          if (numbers.size() >= 4) {
            out.emplace_back();
            for (std::size_t k = 0; k + 1 < numbers.size(); k += 2)
              out.back().push_back({numbers[k], numbers[k + 1]});
          }
          numbers.clear();
        }
        continue;
      }
      if (i == d.size()) break;
      std::size_t used = 0;
      numbers.push_back(std::stod(d.substr(i), &used));
      i += used - 1;
    }
    if (numbers.size() >= 4) {
      out.emplace_back();
      for (std::size_t k = 0; k + 1 < numbers.size(); k += 2)
        out.back().push_back({numbers[k], numbers[k + 1]});
    }
    at = close;
  }
  return out;
}

}  // namespace

TEST_F(DrawingCli, ViewsAgreeWithRenderOfTheSameOrthographicView) {
  // The front and top views of fandisk against `exbsp render` of a scene with the same
  // orthographic view (gluLookAt along the view's axis, glOrtho on the view's box), edges
  // visible+hidden: the render's edge vertices, taken from pixels to the sheet's millimetres,
  // lie on the drawing's lines of the same kind, and the drawing's on the render's (0.01 mm).
  const std::string path = exbsp_test::corpus_dir() + "fandisk.off";
  EXBSP_NEED_CORPUS(std::filesystem::exists(path), path);
  auto o = line_options({"front", "top"});
  const drawing::sheet s = scene::make_drawing_sheet(path, o, false, nullptr);
  for (const std::string name : {"front", "top"}) {
    const auto& v = view_named(s, name);
    // A viewport of about 10 pixels per mm of the view's box, and the box in model units.
    const int w_px = static_cast<int>(std::lround(v.width * 10)),
              h_px = static_cast<int>(std::lround(v.height * 10));
    const double w_model = v.width / v.mm_per_model, h_model = v.height / v.mm_per_model;
    // The eye 1000 units back along the view's axis from a point of its centre line.
    const std::array<double, 3> c = {
        (v.left + w_model / 2) * v.right[0] + (v.bottom + h_model / 2) * v.up[0],
        (v.left + w_model / 2) * v.right[1] + (v.bottom + h_model / 2) * v.up[1],
        (v.left + w_model / 2) * v.right[2] + (v.bottom + h_model / 2) * v.up[2]};
    const double back = 1000;
    char scene[2048];
    std::snprintf(
        scene, sizeof scene,
        "{\"meshes\": [{\"file\": \"%s\"}],\n"
        " \"camera\": {\"eye\": [%.17g, %.17g, %.17g], \"look_at\": [%.17g, %.17g, %.17g], "
        "\"up\": [%.17g, %.17g, %.17g]},\n"
        " \"projection\": {\"type\": \"orthographic\", \"left\": %.17g, \"right\": %.17g, "
        "\"bottom\": %.17g, \"top\": %.17g, \"near\": 1, \"far\": 2000},\n"
        " \"viewport\": {\"width\": %d, \"height\": %d},\n"
        " \"svg\": {\"edges\": \"visible+hidden\"}}\n",
        path.c_str(), c[0] + back * v.towards_eye[0], c[1] + back * v.towards_eye[1],
        c[2] + back * v.towards_eye[2], c[0], c[1], c[2], v.up[0], v.up[1], v.up[2], -w_model / 2,
        w_model / 2, -h_model / 2, h_model / 2, w_px, h_px);
    write("view.json", scene);
    const auto r = run("render view.json -o view.svg -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = exbsp_test::read_file(dir / "view.svg");
    const double mm_per_px_x = v.width / w_px, mm_per_px_y = v.height / h_px;
    const auto to_sheet = [&](const std::string& group) {
      std::vector<drawing::sheet_polyline> lines;
      for (const auto& pl : svg_group_polylines(svg, group)) {
        drawing::sheet_polyline l;
        for (const point2& p : pl)
          l.points.push_back(
              {v.lower_left.x + p.x * mm_per_px_x, v.lower_left.y + (h_px - p.y) * mm_per_px_y});
        lines.push_back(std::move(l));
      }
      return lines;
    };
    const auto pointers = [](const std::vector<drawing::sheet_polyline>& lines) {
      std::vector<const drawing::sheet_polyline*> p;
      for (const auto& l : lines) p.push_back(&l);
      return p;
    };
    const auto rendered_visible_lines = to_sheet("visible-edges");
    const auto rendered_hidden_lines = to_sheet("hidden-edges");
    const auto rendered_visible = pointers(rendered_visible_lines);
    const auto rendered_hidden = pointers(rendered_hidden_lines);
    const auto drawn_visible = lines_in(s, v, layer_id::visible);
    const auto drawn_hidden = lines_in(s, v, layer_id::hidden);
    ASSERT_FALSE(drawn_visible.empty() || drawn_hidden.empty()) << name;
    ASSERT_FALSE(rendered_visible.empty() || rendered_hidden.empty()) << name;
    // Vertices of `a` farther than 0.01 mm from the lines of `b`. Hidden runs are also allowed
    // to end differently within 0.02 mm of a visible line: where a hidden and a visible run
    // nearly coincide, the hidden one loses what lies within 4 grid units of the visible one
    // (edge_paths.h), and a grid unit is a hundredth of a pixel, whose size differs here.
    const auto off = [&](const std::vector<const drawing::sheet_polyline*>& a,
                         const std::vector<const drawing::sheet_polyline*>& b, bool hidden) {
      std::size_t n = 0;
      for (const auto* l : a)
        for (const point2& p : l->points)
          if (distance_to_lines(p, b) > 0.01 &&
              !(hidden && std::min(distance_to_lines(p, drawn_visible),
                                   distance_to_lines(p, rendered_visible)) < 0.02))
            ++n;
      return n;
    };
    EXPECT_EQ(off(rendered_visible, drawn_visible, false), 0u) << name;
    EXPECT_EQ(off(drawn_visible, rendered_visible, false), 0u) << name;
    EXPECT_EQ(off(rendered_hidden, drawn_hidden, true), 0u) << name;
    EXPECT_EQ(off(drawn_hidden, rendered_hidden, true), 0u) << name;
  }
}

TEST_F(DrawingCli, ASceneGivesTitleBlockAndOptionsAndFlagsOverrideThem) {
  // A scene's "drawing" block sets the sheet's options (no camera needed: a drawing has its own
  // views); a flag given on the command line wins over the block; bad values name the JSON key.
  write("part.off", boxes_off({{0, 0, 0, 40, 20, 10}}));
  write("s.json",
        R"({"meshes": [{"file": "part.off"}], "drawing": {"title": "Bracket", "number": "B-7",
            "sheet": "A4", "projection": "third-angle", "views": ["front", "top"],
            "lines_only": true, "date": "2026-02-03", "scale": "1:1"}})");
  auto r = run("drawing s.json -o s.svg -q");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string svg = exbsp_test::read_file(dir / "s.svg");
  EXPECT_NE(svg.find("width=\"297mm\""), std::string::npos);
  for (const char* text : {">Bracket<", ">B-7<", ">third angle<", ">2026-02-03<", ">1:1<", ">A4<"})
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  EXPECT_EQ(svg.find("layer-fills\" fill=\"none\" stroke=\"#000000\">\n<path fill"),
            std::string::npos)
      << "lines_only from the scene: no fills";
  r = run("drawing s.json -o s2.svg -q --sheet A3 --title Other");
  ASSERT_EQ(r.status, 0) << r.err;
  svg = exbsp_test::read_file(dir / "s2.svg");
  EXPECT_NE(svg.find("width=\"420mm\""), std::string::npos);
  EXPECT_NE(svg.find(">Other<"), std::string::npos);
  EXPECT_NE(svg.find(">B-7<"), std::string::npos);
  const std::pair<const char*, const char*> bad[] = {
      {R"({"sheet": "A9"})", "/drawing/sheet"},
      {R"({"titel": "x"})", "/drawing/titel"},
      {R"({"sections": ["A=0,0,0,1"]})", "/drawing/sections/0"},
      {R"({"line_widths": [0.5]})", "/drawing/line_widths"},
      {R"({"lines_only": "yes"})", "/drawing/lines_only"},
  };
  for (const auto& [block, key] : bad) {
    write("b.json", std::string(R"({"meshes": [{"file": "part.off"}], "drawing": )") + block + "}");
    r = run("drawing b.json -o b.svg");
    EXPECT_EQ(r.status, 2) << block;
    EXPECT_NE(r.err.find(std::string("b.json: ") + key), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "b.svg"));
  }
}

TEST(DrawingLayout, AYUpModelDrawnWithUpYIsTheZUpModelsSheet) {
  // The z-up box [0,40] x [0,20] x [0,10] and the same box in y-up axes, (x, y, z) = (x, z_cad,
  // -y_cad): [0,40] x [0,10] x [-20,0]. With up = "y" the second gives the first one's sheet.
  auto o = line_options({"front", "top", "left", "iso"});
  o.scale = drawing::drawing_scale{1, 1};
  const drawing::sheet z_up =
      drawing::make_sheet(boxes_soup({{0, 0, 0, 40, 20, 10}}), "box", {}, o);
  o.up = "y";
  const drawing::sheet y_up =
      drawing::make_sheet(boxes_soup({{0, 0, -20, 40, 10, 0}}), "box", {}, o);
  ASSERT_EQ(z_up.views.size(), y_up.views.size());
  for (std::size_t k = 0; k < z_up.views.size(); ++k) {
    const auto& a = z_up.views[k];
    const auto& b = y_up.views[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_NEAR(a.lower_left.x, b.lower_left.x, 1e-9) << a.name;
    EXPECT_NEAR(a.lower_left.y, b.lower_left.y, 1e-9) << a.name;
    const extent ea = extent_of(lines_in(z_up, a, layer_id::visible));
    const extent eb = extent_of(lines_in(y_up, b, layer_id::visible));
    EXPECT_NEAR(ea.x0, eb.x0, 0.003) << a.name;
    EXPECT_NEAR(ea.x1, eb.x1, 0.003) << a.name;
    EXPECT_NEAR(ea.y0, eb.y0, 0.003) << a.name;
    EXPECT_NEAR(ea.y1, eb.y1, 0.003) << a.name;
  }
  o.up = "x";
  EXPECT_THROW(drawing::make_sheet(boxes_soup({{0, 0, 0, 1, 1, 1}}), "box", {}, o), usage_error);
}

TEST_F(DrawingCli, ASavedTreeDrawsTheSameSheetWithoutABuild) {
  // `build --save` then `drawing T.exbsp`: the part's views come from the loaded tree (no
  // build), and the lines are those of the mesh's own sheet; a section still cuts the input.
  write("part.off", boxes_off({{0, 0, 0, 40, 20, 10}, {10, 30, 2, 20, 40, 8}}));
  ASSERT_EQ(run("build part.off --save t.exbsp").status, 0);
  auto o = line_options({"front", "top", "left", "iso"});
  o.sections = {drawing::parse_section("A=0,1,0,-5")};
  const drawing::sheet from_mesh =
      scene::make_drawing_sheet((dir / "part.off").string(), o, false, nullptr);
  std::ostringstream log;
  const drawing::sheet from_tree =
      scene::make_drawing_sheet((dir / "t.exbsp").string(), o, false, &log);
  EXPECT_EQ(log.str().find("building the BSP of t.exbsp"), std::string::npos) << log.str();
  ASSERT_EQ(from_mesh.lines.size(), from_tree.lines.size());
  for (std::size_t i = 0; i < from_mesh.lines.size(); ++i) {
    ASSERT_EQ(from_mesh.lines[i].points.size(), from_tree.lines[i].points.size()) << i;
    for (std::size_t k = 0; k < from_mesh.lines[i].points.size(); ++k) {
      EXPECT_EQ(from_mesh.lines[i].points[k].x, from_tree.lines[i].points[k].x);
      EXPECT_EQ(from_mesh.lines[i].points[k].y, from_tree.lines[i].points[k].y);
    }
  }
  const auto r = run("drawing t.exbsp -o t.pdf -q");
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST(DrawingDxf, ASignalDuringTheWriteLeavesNoTemporaryFile) {
  // dxflib writes to a file name: its temporary file (TMPDIR/exbsp-dxf-*) is removed on a
  // signal like write_file_atomically's own. A watcher sends SIGTERM as soon as it appears.
  const std::filesystem::path dir = exbsp_test::make_temp_dir("dxf-signal");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::setenv("TMPDIR", dir.c_str(), 1);
    std::thread watcher([&dir] {
      for (;;) {
        for (const auto& e : std::filesystem::directory_iterator(dir))
          if (e.path().filename().string().rfind("exbsp-dxf-", 0) == 0) {
            ::kill(::getpid(), SIGTERM);
            return;
          }
        std::this_thread::sleep_for(std::chrono::microseconds(100));
      }
    });
    watcher.detach();
    drawing::sheet s;
    for (int i = 0; i < 2000000; ++i)
      s.lines.push_back({layer_id::visible,
                         drawing::line_style::continuous,
                         0.5,
                         false,
                         {{0.001 * i, 1}, {0.001 * i, 2}, {0.001 * i + 1, 3}}});
    try {
      (void)drawing::sheet_dxf(s);
    } catch (...) {
    }
    ::_exit(0);  // reached only when the signal came too late
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the write finished before the signal";
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  std::vector<std::string> left;
  for (const auto& e : std::filesystem::directory_iterator(dir)) left.push_back(e.path().string());
  EXPECT_TRUE(left.empty()) << left.front();
  std::filesystem::remove_all(dir);
}
