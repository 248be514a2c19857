// SPDX-License-Identifier: LGPL-3.0-or-later
// Vector output (view/vector_drawing.h, svg_writer.h, vector_pdf.h): visible regions, edges,
// SVG and PDF.
//
// Oracles: (1) the regions themselves, sampled at pixel centres with the nonzero rule
// (sample_regions below), against exbsp's PNG — no browser needed; (2) the SVG rasterized by
// headless Chromium and the PDF by poppler (poppler-utils), against the PNG and against Mesa's
// z-buffer image of the same triangles, camera and viewport (OSMesa, osmesa_zbuffer.h): at
// least 99.5% equal pixels with anti-aliasing off (CSS shape-rendering: crispEdges on the
// inlined SVG; pdftocairo -antialias none), and, anti-aliased as a user sees them, no interior
// pixel of a flat face differing from its colour (no seams). The browser test SKIPS, with a
// message, when chromium or pdftoppm is missing (scripts/setup installs both, so CI runs it);
// without OSMesa it fails, as test_oracle_gl does.
// Scenes are compared without their raster-only effects (antialias, depth_of_field: vector
// output ignores them) and without fog (flat per region in vector output, per pixel in PNG);
// scenes with a viewport inside a larger image are compared as placed images.
// Curves and lines: a 1-pixel stroke whose centre line runs exactly along a pixel boundary
// covers two half pixels, and renderers break that tie differently (scenes/ortho2d.json's
// horizontal line at window y = 100: exbsp's line rule, line_raster.h, paints the row above,
// like its polygon top-left rule; Chromium and cairo paint the row below), and a stroke's
// staircase may differ from the PNG's DDA by a pixel: a curve pixel matching the same curve
// colour one pixel away counts as equal. Mesa draws no curves: pixels within one pixel of a
// curve of the PNG are left out of the z-buffer comparison.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
#include <exbsp/view/vector_drawing.h>
#include "scene/demo_scene.h"
#include "scene/render.h"
#include "scene/scene.h"
#include "view/effects.h"
#include "view/lighting.h"
#include "view/placement.h"
#include "view/svg_writer.h"
#include "view/vector_pdf.h"
#include "view/visible_cover.h"
#include "view/visible_strips.h"
#include "support/test_helpers.h"

#include "support/osmesa_zbuffer.h"

namespace fs = std::filesystem;
using namespace exbsp;
using namespace exbsp::view;

namespace {

/// One fresh directory per run (mkdtemp), made on first use.
const fs::path& temp_path() {
  static const fs::path dir = exbsp_test::make_temp_dir("test_vector");
  return dir;
}

std::string temp_dir() { return temp_path().string(); }

/// Removes temp_dir() at exit when every test passed (unless EXBSP_KEEP_TEST_OUTPUT is set);
/// otherwise says where the documents and screenshots are.
class output_cleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    const char* keep = std::getenv("EXBSP_KEEP_TEST_OUTPUT");
    const fs::path d = temp_path();
    if (!fs::exists(d)) return;
    if (::testing::UnitTest::GetInstance()->Passed() &&
        !(keep && *keep && std::string(keep) != "0")) {
      std::error_code ec;
      fs::remove_all(d, ec);
    } else {
      std::cout << "test_vector: documents and screenshots kept in " << d.string() << "\n";
    }
  }
};
[[maybe_unused]] ::testing::Environment* const cleanup_env =
    ::testing::AddGlobalTestEnvironment(new output_cleanup);

// ---- frames -------------------------------------------------------------------------------

/// A frame of a scene (or the demo when `name` is empty) ready for the per-view stages, with
/// the effects that vector output cannot reproduce pixel for pixel removed.
frame scene_frame(const std::string& name, scene::scene& s) {
  s = name.empty() ? scene::demo_scene()
                   : scene::load_scene(std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json");
  s.effects.erase(std::remove_if(s.effects.begin(), s.effects.end(),
                                 [](const std::string& e) {
                                   return e == "antialias" || e == "depth_of_field" || e == "fog" ||
                                          e == "exposure";
                                 }),
                  s.effects.end());
  scene::scene_geometry g = scene::load_geometry(s);
  frame f;
  f.view = scene::make_view_setup(s);
  f.background = s.background;
  f.face_colors = std::move(g.face_colors);
  f.soup = std::move(g.soup);
  f.mesh_face_offsets = std::move(g.face_offsets);
  f.settings = s.effect_settings;
  // SVG and PDF fill their regions flat (effect_settings.h); the smooth raster has an oracle of
  // its own (test_oracle_gl, Mesa's GL_SMOOTH). Compared here: the flat PNG.
  f.settings.lighting.smooth = false;
  f.curves = s.curves;
  f.vector = s.vector;
  return f;
}

void run(frame& f, const std::vector<std::string>& effects, output_kind out) {
  standard_pipeline(effects, out, !f.curves.empty()).run(f, nullptr);
}

using exbsp_test::add_quad;
using exbsp_test::perspective_frame;

// ---- the region oracle -------------------------------------------------------------------

/// Nonzero winding number of the rings at grid point (x, y) (test_helpers.h).
int winding(const std::vector<std::vector<grid_point>>& rings, double x, double y) {
  return exbsp_test::winding_number(rings, x, y);
}

struct sampled {
  image picture;
  int max_overlap = 0;          ///< most regions covering one pixel centre
  std::size_t overlapping = 0;  ///< pixel centres covered by two or more regions
};

/// The drawing's regions painted at pixel centres (nonzero rule), in the drawing's order.
sampled sample_regions(const vector_drawing& d) {
  sampled out{image(d.width, d.height, d.background), 0};
  std::vector<int> count(static_cast<std::size_t>(d.width) * d.height, 0);
  for (const vector_path& p : d.paths) {
    if (p.kind != vector_path::kind_type::region) continue;  // underlays lie under regions
    long long x0 = p.rings[0][0].x, x1 = x0, y0 = p.rings[0][0].y, y1 = y0;
    for (const auto& r : p.rings)
      for (const grid_point& q : r) {
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
      }
    for (long long j = std::max(0LL, y0 / 100 - 1);
         j <= std::min<long long>(d.height - 1, y1 / 100 + 1); ++j)
      for (long long i = std::max(0LL, x0 / 100 - 1);
           i <= std::min<long long>(d.width - 1, x1 / 100 + 1); ++i)
        if (winding(p.rings, 100.0 * i + 50, 100.0 * j + 50) != 0) {
          out.picture.set_pixel(static_cast<int>(i), static_cast<int>(j), p.color);
          int& c = count[static_cast<std::size_t>(j * d.width + i)];
          out.max_overlap = std::max(out.max_overlap, ++c);
          if (c == 2) ++out.overlapping;
        }
  }
  return out;
}

double equal_fraction(const image& a, const image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return 0;
  std::size_t same = 0;
  for (int j = 0; j < a.height(); ++j)
    for (int i = 0; i < a.width(); ++i) same += a.pixel(i, j) == b.pixel(i, j);
  return static_cast<double>(same) / (static_cast<double>(a.width()) * a.height());
}

/// Pixels whose 5 x 5 neighbourhood in `reference` has one colour (inside a flat face or the
/// background, two pixels from any edge) and whose colour in `shot` differs by more than
/// `tolerance` levels in a channel: seams. (Anti-aliased renderers blend a region's edge over
/// its underlay of the same colour with 8-bit arithmetic, which may round c to c - 1; a seam
/// lets the background through, tens of levels.)
std::size_t interior_differences(const image& reference, const image& shot,
                                 std::size_t* interior = nullptr, int tolerance = 2) {
  auto near = [&](rgb8 a, rgb8 b) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
           std::abs(a.b - b.b) <= tolerance;
  };
  std::size_t bad = 0, inner = 0;
  for (int j = 2; j + 2 < reference.height(); ++j)
    for (int i = 2; i + 2 < reference.width(); ++i) {
      const rgb8 c = reference.pixel(i, j);
      bool flat = true;
      for (int dj = -2; dj <= 2 && flat; ++dj)
        for (int di = -2; di <= 2 && flat; ++di) flat = reference.pixel(i + di, j + dj) == c;
      if (!flat) continue;
      ++inner;
      bad += !near(shot.pixel(i, j), c);
    }
  if (interior) *interior = inner;
  return bad;
}

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n{""};  // the built-in demo
    for (const auto& e : fs::directory_iterator(std::string(EXBSP_SOURCE_DIR) + "/scenes"))
      if (e.path().extension() == ".json") n.push_back(e.path().stem().string());
    std::sort(n.begin() + 1, n.end());
    return n;
  }();
  return names;
}

std::string label(const std::string& name) { return name.empty() ? std::string("(demo)") : name; }

// ---- degenerate visibility ---------------------------------------------------------------

std::vector<const vector_path*> regions_of(const vector_drawing& d) {
  std::vector<const vector_path*> r;
  for (const vector_path& p : d.paths)
    if (p.kind == vector_path::kind_type::region) r.push_back(&p);
  return r;
}

/// `s` seen from (0, 0, 5) towards the origin at 80 x 60 (face colours red and blue), drawn
/// to SVG.
frame front_view_svg(triangle_soup s) {
  frame f = perspective_frame(std::move(s), {{200, 0, 0}, {0, 0, 200}},
                              {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, 80, 60);
  run(f, {}, output_kind::svg);
  return f;
}

TEST(VisibleRegions, AFaceSeenEdgeOnHasNoRegion) {
  triangle_soup s;
  add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});  // faces the eye
  add_quad(s, {-0.5, 0, -1}, {0.5, 0, -1}, {0.5, 0, 1},
           {-0.5, 0, 1});  // in the plane y = 0 through the eye
  frame f = front_view_svg(std::move(s));
  const vector_drawing d = visible_drawing(f);
  const auto r = regions_of(d);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0]->face, 0u);
  EXPECT_EQ(r[0]->rings.size(), 1u);  // the edge-on face cuts no slit into it
  // Its edges are still drawn (as a line) when edges are asked for.
  f.vector.edges = vector_options::edges_kind::visible;
  EXPECT_GT(count_paths(visible_drawing(f)).visible_edges, 0u);
}

TEST(VisibleRegions, CoplanarOverlappingFacesOfTwoMeshesTileTheirUnion) {
  triangle_soup s;
  add_quad(s, {-1, -1, 0}, {0.5, -1, 0}, {0.5, 1, 0}, {-1, 1, 0});
  add_quad(s, {-0.5, -0.5, 0}, {1, -0.5, 0}, {1, 0.5, 0}, {-0.5, 0.5, 0});
  frame f = perspective_frame(std::move(s), {{200, 0, 0}, {0, 0, 200}},
                              {{0.3, 0.2, 5}, {0, 0, 0}, {0, 1, 0}}, 160, 120);
  f.mesh_face_offsets = {0, 1, 2};  // one face per mesh
  run(f, {}, output_kind::png);
  const image png = f.picture;
  const vector_drawing d = visible_drawing(f);
  const auto r = regions_of(d);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NE(r[0]->mesh, r[1]->mesh);
  const sampled got = sample_regions(d);
  EXPECT_EQ(got.max_overlap, 1);  // no pixel centre in both
  EXPECT_GE(equal_fraction(got.picture, png), 0.995);
  EXPECT_EQ(svg_document(d).find("<g id=\"mesh-1\">") != std::string::npos, true);
}

/// Area of closed grid rings (signed sum: holes count negative when wound the other way).
double rings_area(const std::vector<std::vector<grid_point>>& rings) {
  double a = 0;
  for (const auto& r : rings)
    for (std::size_t k = 0; k < r.size(); ++k) {
      const grid_point& p = r[k];
      const grid_point& q = r[(k + 1) % r.size()];
      a += static_cast<double>(p.x) * static_cast<double>(q.y) -
           static_cast<double>(q.x) * static_cast<double>(p.y);
    }
  return a / 2;
}

TEST(Underlays, OnePerMeshInTheAreaWeightedMeanColourCoveringExactlyItsRegions) {
  // One mesh of two faces of different colours sharing an edge (a lit part's neighbouring
  // faces): its underlay is the union of the two regions, no larger, in their mean colour
  // weighted by area, so a seam between them shows a colour between theirs, not the
  // background. No colour is used twice: no per-colour underlay.
  triangle_soup s;
  add_quad(s, {-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0});
  add_quad(s, {0, -1, 0}, {2, -1, 0}, {2, 1, 0}, {0, 1, 0});
  frame f = perspective_frame(std::move(s), {{200, 0, 0}, {0, 0, 200}},
                              {{0.5, 0, 6}, {0.5, 0, 0}, {0, 1, 0}}, 200, 150);
  run(f, {}, output_kind::svg);
  const vector_drawing d = visible_drawing(f);
  std::vector<const vector_path*> underlays;
  for (const vector_path& p : d.paths)
    if (p.kind == vector_path::kind_type::underlay) underlays.push_back(&p);
  const auto r = regions_of(d);
  ASSERT_EQ(r.size(), 2u);
  ASSERT_EQ(underlays.size(), 1u);
  const double a0 = std::abs(rings_area(r[0]->rings)), a1 = std::abs(rings_area(r[1]->rings));
  // Covering exactly the regions' pixel centres (its rings may overlap: nonzero fill).
  std::size_t covered = 0;
  for (int j = 0; j < d.height; ++j)
    for (int i = 0; i < d.width; ++i) {
      const double x = 100.0 * i + 50, y = 100.0 * j + 50;
      const bool in_region = winding(r[0]->rings, x, y) != 0 || winding(r[1]->rings, x, y) != 0;
      EXPECT_EQ(winding(underlays[0]->rings, x, y) != 0, in_region) << i << ", " << j;
      covered += in_region;
    }
  EXPECT_GT(covered, 1000u);
  auto mean = [&](int c0, int c1) {
    return static_cast<int>(std::lround((a0 * c0 + a1 * c1) / (a0 + a1)));
  };
  EXPECT_EQ(underlays[0]->color.r, mean(r[0]->color.r, r[1]->color.r));
  EXPECT_EQ(underlays[0]->color.b, mean(r[0]->color.b, r[1]->color.b));
  EXPECT_GT(underlays[0]->color.r, 0);
  EXPECT_GT(underlays[0]->color.b, 0);
  // Underlays come first: every region is drawn over them.
  EXPECT_EQ(d.paths.front().kind, vector_path::kind_type::underlay);
}

TEST(VisibleRegions, AFaceExactlyBehindAnotherOfTheSameOutlineIsHidden) {
  triangle_soup s;
  add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
  // Behind it, the same outline as seen from the eye (scaled about the eye at (0, 0, 5)).
  add_quad(s, {-2, -2, -5}, {2, -2, -5}, {2, 2, -5}, {-2, 2, -5});
  frame f = front_view_svg(std::move(s));
  const vector_drawing d = visible_drawing(f);  // regions_of points into it
  const auto r = regions_of(d);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0]->face, 0u);
}

TEST(VisibleRegions, TJunctionsLeaveNoCrackForTheFaceBehind) {
  triangle_soup s;
  // Front: one big quad on the left; two quads on the right meet its edge at a T (x = 0, y = 0.1).
  add_quad(s, {-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0});
  add_quad(s, {0, -1, 0}, {1, -1, 0}, {1, 0.1, 0}, {0, 0.1, 0});
  add_quad(s, {0, 0.1, 0}, {1, 0.1, 0}, {1, 1, 0}, {0, 1, 0});
  add_quad(s, {-0.5, -0.5, -1}, {0.5, -0.5, -1}, {0.5, 0.5, -1}, {-0.5, 0.5, -1});  // hidden behind
  frame f = perspective_frame(std::move(s), {{200, 0, 0}, {190, 0, 0}, {180, 0, 0}, {0, 0, 255}},
                              {{0.1, 0.05, 4}, {0, 0, 0}, {0, 1, 0}}, 400, 300);
  run(f, {}, output_kind::svg);
  const vector_drawing d = visible_drawing(f);
  for (const vector_path* p : regions_of(d))
    EXPECT_NE(p->face, 3u) << "the face behind shows through";
  EXPECT_EQ(regions_of(d).size(), 3u);
  EXPECT_EQ(sample_regions(d).max_overlap, 1);
}

TEST(VisibleRegions, OneRegionPerFaceWithItsHole) {
  // A small quad in front of a big one: the big face's region is one path with a hole.
  triangle_soup s;
  add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
  add_quad(s, {-0.2, -0.2, 1}, {0.2, -0.2, 1}, {0.2, 0.2, 1}, {-0.2, 0.2, 1});
  frame f = front_view_svg(std::move(s));
  const vector_drawing d = visible_drawing(f);  // regions_of points into it
  const auto r = regions_of(d);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0]->face, 0u);
  EXPECT_EQ(r[0]->rings.size(), 2u);  // outline and hole
  EXPECT_EQ(r[1]->rings.size(), 1u);
}

TEST(VisibleRegions, CoordinatesAreHundredthsOfAPixel) {
  scene::scene s;
  frame f = scene_frame("", s);
  run(f, s.effects, output_kind::svg);
  const std::string& svg = f.svg;
  // Every number in a path's d attribute has at most two decimals.
  for (std::size_t at = svg.find(" d=\""); at != std::string::npos;
       at = svg.find(" d=\"", at + 1)) {
    const std::size_t end = svg.find('"', at + 4);
    std::size_t decimals = 0;
    bool in_fraction = false;
    for (std::size_t k = at + 4; k < end; ++k) {
      const char c = svg[k];
      if (c == '.') {
        in_fraction = true;
        decimals = 0;
      } else if (c >= '0' && c <= '9') {
        if (in_fraction) {
          ASSERT_LE(++decimals, 2u) << svg.substr(at, 80);
        }
      } else {
        in_fraction = false;
      }
    }
  }
  EXPECT_EQ(svg.find("stroke=\"#"), std::string::npos);  // no seam stroke on regions
}

TEST(VisibleRegions, EveryFaceAtMostOnceAndGroupedPerMesh) {
  scene::scene s;
  frame f = scene_frame("perspective", s);
  run(f, s.effects, output_kind::svg);
  const vector_drawing d = visible_drawing(f);
  std::set<std::uint32_t> faces;
  std::uint32_t last_mesh = 0;
  for (const vector_path* p : regions_of(d)) {
    EXPECT_TRUE(faces.insert(p->face).second) << "face " << p->face << " twice";
    EXPECT_GE(p->mesh, last_mesh);
    last_mesh = p->mesh;
  }
  EXPECT_GT(last_mesh, 0u);
  EXPECT_EQ(std::count(f.svg.begin(), f.svg.end(), '\n') > 0, true);
  std::size_t groups = 0;
  for (std::size_t at = f.svg.find("<g id=\"mesh-"); at != std::string::npos;
       at = f.svg.find("<g id=\"mesh-", at + 1))
    ++groups;
  std::set<std::uint32_t> meshes;
  for (const vector_path* p : regions_of(d)) meshes.insert(p->mesh);
  EXPECT_EQ(groups, meshes.size());
}

TEST(VisibleRegions, MatchThePngAtPixelCentresOnEveryScene) {
  for (const std::string& name : scene_names()) {
    scene::scene s;
    frame f = scene_frame(name, s);
    f.curves.clear();  // regions only (the browser test checks curves)
    run(f, s.effects, output_kind::png);
    const image png = f.picture;
    const sampled got = sample_regions(visible_drawing(f));
    // Regions share boundaries up to Clipper's rounding of intersection points (< 1/100 px):
    // a pixel centre lying within that of two boundaries may be in both (0 to 2 per scene).
    EXPECT_LE(got.overlapping * 20000, static_cast<std::size_t>(s.width) * s.height) << label(name);
    EXPECT_GE(equal_fraction(got.picture, png), 0.995) << label(name);
  }
}

/// Colours by face id, distinct for the first hundreds of faces.
std::vector<rgb8> face_colours(std::uint32_t faces) {
  std::vector<rgb8> c;
  for (std::uint32_t k = 0; k < faces; ++k)
    c.push_back({static_cast<std::uint8_t>(k * 37 % 251), static_cast<std::uint8_t>(k * 91 % 241),
                 static_cast<std::uint8_t>(k * 53 % 239)});
  return c;
}

/// A perspective frame of `soup` seen from its box's centre + (0.9, 0.7, 1.1) x its diagonal
/// (the eye), towards the centre, 40 degrees, at width x height.
frame corner_frame(triangle_soup soup, std::vector<rgb8> colors, int width, int height) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& v : soup.vertices)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], v[i]);
      hi[i] = std::max(hi[i], v[i]);
    }
  const double diag = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const point3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const point3 eye{centre.x + 0.9 * diag, centre.y + 0.7 * diag, centre.z + 1.1 * diag};
  return perspective_frame(std::move(soup), std::move(colors), {eye, centre, {0, 1, 0}}, width,
                           height, 40, 0.3 * diag, 5 * diag);
}

TEST(VisibleRegions, OfARealMeshMatchThePngAndTheirUnderlayCoversExactlyThem) {
  // fandisk, split by its tree into ~2x as many fragments as faces (T-junctions everywhere),
  // each face its own colour: every pixel centre must show the face the painter's PNG shows
  // there, and the underlay (unions per 64-pixel square, one path) must cover exactly the
  // pixel centres the regions cover: no more (no outline grows), no less (no seam uncovered).
  const std::string path = exbsp_test::corpus_dir() + "fandisk.off";
  EXBSP_NEED_CORPUS(std::filesystem::exists(path), path);
  triangle_soup soup = read_mesh(path);
  const std::uint32_t faces = soup.face_count;
  frame f = corner_frame(std::move(soup), face_colours(faces), 400, 300);
  run(f, {}, output_kind::png);
  const image png = f.picture;
  const vector_drawing d = visible_drawing(f);
  const sampled got = sample_regions(d);
  EXPECT_GE(equal_fraction(got.picture, png), 0.995);
  EXPECT_LE(got.overlapping, 30u);
  // Winding numbers at pixel centres, added up ring by ring over each ring's bounding box.
  const std::size_t n = static_cast<std::size_t>(d.width) * d.height;
  std::vector<int> region_winding(n, 0), underlay_winding(n, 0);
  for (const vector_path& p : d.paths) {
    if (p.kind != vector_path::kind_type::underlay && p.kind != vector_path::kind_type::region)
      continue;
    auto& w = p.kind == vector_path::kind_type::underlay ? underlay_winding : region_winding;
    for (const auto& ring : p.rings) {
      long long x0 = ring[0].x, x1 = x0, y0 = ring[0].y, y1 = y0;
      for (const grid_point& q : ring) {
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
      }
      for (long long j = std::max(0LL, y0 / 100); j <= std::min<long long>(d.height - 1, y1 / 100);
           ++j)
        for (long long i = std::max(0LL, x0 / 100); i <= std::min<long long>(d.width - 1, x1 / 100);
             ++i)
          w[static_cast<std::size_t>(j * d.width + i)] += winding(
              {ring}, 100.0 * static_cast<double>(i) + 50, 100.0 * static_cast<double>(j) + 50);
    }
  }
  ASSERT_NE(std::count(underlay_winding.begin(), underlay_winding.end(), 0),
            static_cast<std::ptrdiff_t>(n));
  std::size_t covered = 0, differ = 0;
  for (std::size_t k = 0; k < n; ++k) {
    covered += region_winding[k] != 0;
    differ += (region_winding[k] != 0) != (underlay_winding[k] != 0);
  }
  EXPECT_GT(covered, 15000u);
  EXPECT_EQ(differ, 0u) << "of " << covered << " covered pixel centres";
}

TEST(VisibleRegions, PiecesSharingEdgesUniteByTheirBoundary) {
  using ClipperLib::Path;
  using ClipperLib::Paths;
  // Four unit squares of a 2 x 2 block, each as two triangles: one square ring of 4 corners.
  std::vector<Path> pieces;
  for (long long x = 0; x < 2; ++x)
    for (long long y = 0; y < 2; ++y) {
      pieces.push_back({{x, y}, {x + 1, y}, {x + 1, y + 1}});
      pieces.push_back({{x, y}, {x + 1, y + 1}, {x, y + 1}});
    }
  std::vector<const Path*> rings;
  for (const Path& p : pieces) rings.push_back(&p);
  Paths out;
  ASSERT_TRUE(cover::union_by_shared_edges(rings, out));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].size(), 4u);
  EXPECT_DOUBLE_EQ(ClipperLib::Area(out[0]), 4.0);
  // A ring of eight around a hole: an outline and a clockwise hole.
  pieces.clear();
  for (long long x = 0; x < 3; ++x)
    for (long long y = 0; y < 3; ++y)
      if (x != 1 || y != 1) pieces.push_back({{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}});
  rings.clear();
  for (const Path& p : pieces) rings.push_back(&p);
  ASSERT_TRUE(cover::union_by_shared_edges(rings, out));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(ClipperLib::Area(out[0]) + ClipperLib::Area(out[1]), 8.0);
  // Touching at a corner only, or along edges that do not match point for point: refused.
  // (Rings that share no edge are returned as they are: disjoint, they are their union.)
  const Path a{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, b{{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  EXPECT_FALSE(cover::union_by_shared_edges({&a, &b}, out));
  const Path left{{0, 0}, {1, 0}, {1, 1}, {1, 2}, {0, 2}}, right{{1, 0}, {2, 0}, {2, 2}, {1, 2}};
  EXPECT_FALSE(cover::union_by_shared_edges({&left, &right}, out));  // (1, 1) on one side only
}

TEST(VisibleRegions, NonConvexPiecesAndPiecesWithHolesUniteByTheirBoundaryToo) {
  using ClipperLib::Path;
  using ClipperLib::Paths;
  // A 4 x 4 square with a 2 x 2 hole (its ring counter-clockwise, the hole clockwise), the
  // hole filled by an L-shaped piece and the square that completes the L: one ring, 16.
  // (The hole's ring has the points where the L and the notch meet its sides, as mended
  // pieces do; without them those sides are T-junctions, and the union is refused.)
  const Path frame{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
      hole{{1, 1}, {1, 3}, {2, 3}, {3, 3}, {3, 2}, {3, 1}};
  const Path ell{{1, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}},
      notch{{2, 2}, {3, 2}, {3, 3}, {2, 3}};
  Paths out;
  const Path unmended_hole{{1, 1}, {1, 3}, {3, 3}, {3, 1}};
  EXPECT_FALSE(cover::union_by_shared_edges({&frame, &unmended_hole, &ell, &notch}, out));
  ASSERT_TRUE(cover::union_by_shared_edges({&frame, &hole, &ell, &notch}, out));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].size(), 4u);
  EXPECT_DOUBLE_EQ(ClipperLib::Area(out[0]), 16.0);
  // Without the notch: the square with a unit hole, clockwise.
  ASSERT_TRUE(cover::union_by_shared_edges({&frame, &hole, &ell}, out));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(ClipperLib::Area(out[0]) + ClipperLib::Area(out[1]), 15.0);
  const double hole_area = std::min(ClipperLib::Area(out[0]), ClipperLib::Area(out[1]));
  EXPECT_DOUBLE_EQ(hole_area, -1.0);
  // The union agrees with Clipper's, point for point as sets of vertices and in area.
  ClipperLib::Clipper clipper;
  clipper.AddPaths({frame, hole, ell}, ClipperLib::ptSubject, true);
  Paths expected;
  clipper.Execute(ClipperLib::ctUnion, expected, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  auto corners = [](const Paths& ps) {
    std::set<std::pair<long long, long long>> c;
    for (const Path& p : ps)
      for (const auto& q : p) c.insert({q.X, q.Y});
    return c;
  };
  EXPECT_EQ(corners(out), corners(expected));
  // One ring touching itself at a vertex (two squares meeting at a corner, one piece): refused,
  // so that Clipper decides.
  const Path bow{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}};
  EXPECT_FALSE(cover::union_by_shared_edges({&bow}, out));
}

// ---- back faces of outward-closed meshes (view/hidden_back_faces.h) -------------------------

/// The drawing of `f` (its PNG run) with back faces left out where allowed, the drawing with
/// none left out (every mesh marked as not whole), and the PNG.
struct drawn_twice {
  vector_drawing culled, full;
  image png;
};

drawn_twice draw_twice(frame& f) {
  run(f, {}, output_kind::png);
  drawn_twice out{visible_drawing(f), {}, f.picture};
  frame g = f;
  std::fill(g.meshes_whole.begin(), g.meshes_whole.end(), 0);
  out.full = visible_drawing(g);
  EXPECT_EQ(out.full.back_faces_left_out, 0u);
  return out;
}

TEST(BackFaces, OfAnOutwardClosedMeshAreLeftOutAndNoPixelCentreChanges) {
  // Oracle: the same drawing with nothing left out, and the painter's PNG. Faces facing away
  // from the eye by the test's own measure (double, far from zero) never have a region.
  const std::string path = exbsp_test::corpus_dir() + "fandisk.off";
  EXBSP_NEED_CORPUS(std::filesystem::exists(path), path);
  triangle_soup soup = read_mesh(path);
  const std::uint32_t faces = soup.face_count;
  frame f = corner_frame(std::move(soup), face_colours(faces), 400, 300);
  const point3 eye = f.view.cam.eye;
  const drawn_twice d = draw_twice(f);
  EXPECT_GT(d.culled.back_faces_left_out, 1000u);
  const sampled culled = sample_regions(d.culled), full = sample_regions(d.full);
  EXPECT_GE(equal_fraction(culled.picture, full.picture), 0.9999);
  EXPECT_GE(equal_fraction(culled.picture, d.png), 0.995);
  std::vector<int> away(faces, 1);  // 1: every triangle of the face clearly faces away
  for (const soup_triangle& t : f.soup.triangles) {
    const vec3d &a = f.soup.vertices[t.v[0]], &b = f.soup.vertices[t.v[1]],
                &c = f.soup.vertices[t.v[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    const double e[3] = {eye.x - a[0], eye.y - a[1], eye.z - a[2]};
    const double dot = n[0] * e[0] + n[1] * e[1] + n[2] * e[2];
    const double scale = std::hypot(n[0], n[1], n[2]) * std::hypot(e[0], e[1], e[2]);
    if (!(dot < -1e-9 * scale)) away[t.face] = 0;
  }
  std::size_t away_faces = 0;
  for (int a : away) away_faces += a;
  EXPECT_GT(away_faces, 1000u);
  for (const vector_path* r : regions_of(d.culled)) EXPECT_EQ(away[r->face], 0) << r->face;
}

TEST(BackFaces, OfAnInsideOutBoxAreItsVisibleFacesAndStay) {
  // Turned inward, the box's faces towards the eye face away from it: they are what the eye
  // sees, and the certificate refuses the box (negative volume). Leaving them out would show
  // the far faces instead.
  triangle_soup s;
  exbsp_test::add_box(s, {-1, -1, -1}, {1, 1, 1});
  for (soup_triangle& t : s.triangles) std::swap(t.v[1], t.v[2]);
  frame f = perspective_frame(std::move(s), face_colours(6), {{3, 2.5, 4}, {0, 0, 0}, {0, 1, 0}},
                              160, 120, 45, 0.5, 50);
  const drawn_twice d = draw_twice(f);
  EXPECT_EQ(d.culled.back_faces_left_out, 0u);
  EXPECT_GE(equal_fraction(sample_regions(d.culled).picture, d.png), 0.995);
  EXPECT_EQ(regions_of(d.culled).size(), 3u);
}

TEST(BackFaces, AreDrawnWhenTheEyeIsInsideOrTheNearPlaneCutsTheMesh) {
  // An outward box seen from inside: every face faces away and every face is seen. Then from
  // outside, with the near plane through the box: its far faces show through the cut.
  for (const bool inside : {true, false}) {
    triangle_soup s;
    exbsp_test::add_box(s, {-1, -1, -1}, {1, 1, 1});
    const camera cam = inside ? camera{{0.1, 0.2, 0.3}, {0.1, 0.2, -1}, {0, 1, 0}}
                              : camera{{0.2, 0.3, 5}, {0, 0, 0}, {0, 1, 0}};
    frame f = perspective_frame(std::move(s), face_colours(6), cam, 160, 120, inside ? 100 : 45,
                                inside ? 0.1 : 4.6, 50);
    const drawn_twice d = draw_twice(f);
    EXPECT_EQ(d.culled.back_faces_left_out, 0u) << inside;
    ASSERT_FALSE(f.meshes_whole.empty());
    EXPECT_EQ(f.meshes_whole[0], 0) << inside;
    const sampled got = sample_regions(d.culled);
    EXPECT_GE(equal_fraction(got.picture, d.png), 0.995) << inside;
    // The far face (z = -1, facing away from both eyes) covers pixel centres.
    const rgb8 far = face_colours(6)[0];
    std::size_t far_pixels = 0;
    for (int j = 0; j < got.picture.height(); ++j)
      for (int i = 0; i < got.picture.width(); ++i) far_pixels += got.picture.pixel(i, j) == far;
    EXPECT_GT(far_pixels, 100u) << inside;
  }
}

TEST(BackFaces, AreLeftOutOnlyForTheMeshesCertifiedClosed) {
  // Mesh 0: a closed box; mesh 1: a box without its +x side, seen into its open side, whose
  // inner faces (facing away) are visible.
  triangle_soup s;
  exbsp_test::add_box(s, {-3, -1, -1}, {-1, 1, 1});
  exbsp_test::add_box(s, {1, -1, -1}, {3, 1, 1});
  s.triangles.resize(s.triangles.size() - 2);  // mesh 1's +x quad (face 11) left out
  frame f = perspective_frame(std::move(s), face_colours(12), {{9, 1.5, 4}, {0, 0, 0}, {0, 1, 0}},
                              200, 120, 50, 0.5, 50);
  f.mesh_face_offsets = {0, 6, 12};
  const drawn_twice d = draw_twice(f);
  EXPECT_GT(d.culled.back_faces_left_out, 0u);
  EXPECT_GE(equal_fraction(sample_regions(d.culled).picture, d.png), 0.995);
  std::set<std::uint32_t> shown;
  for (const vector_path* r : regions_of(d.culled)) shown.insert(r->face);
  for (const std::uint32_t face : shown)
    if (face < 6) {
      EXPECT_TRUE(face == 1 || face == 3 || face == 5) << face;  // +z, +y, +x
    }
  EXPECT_TRUE(shown.count(6) || shown.count(8) || shown.count(10));  // an inner face of mesh 1
}

TEST(Grid, SnappingRoundsLikeLlroundEverywhereIncludingHalvesAndTheirNeighbours) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> wide(-3e6, 3e6), narrow(-2, 2);
  std::vector<double> values = {0.0,    -0.0,   0.005,   -0.005, 0.004999999999999999,    1e300,
                                -1e300, 0x1p61, -0x1p61, 0x1p62, 4503599627370495.5 / 100};
  for (int i = 0; i < 200000; ++i) values.push_back(i % 2 ? wide(rng) : narrow(rng));
  for (long long k = -3000; k <= 3000; ++k) {  // halves of the grid and their neighbours
    const double half = (static_cast<double>(k) + 0.5) / static_cast<double>(view::grid_per_pixel);
    values.push_back(half);
    values.push_back(std::nextafter(half, 1e9));
    values.push_back(std::nextafter(half, -1e9));
  }
  for (const double v : values) {
    const double s = v * static_cast<double>(view::grid_per_pixel);
    EXPECT_EQ(view::to_grid(v), std::llround(s)) << v;
  }
}

// ---- tile areas (view/visible_cover.h) ----------------------------------------------------

TEST(TileAreas, EachCellGetsTheAreaClipperFindsInsideItForEveryKindOfRing) {
  // Oracle: Clipper's intersection of the rings (nonzero) with each cell's square, its area,
  // signed as the rings turn; coordinates scaled by 2^20 for Clipper, whose cut points are
  // rounded to its integer grid (an error of about a unit times the cut's length).
  using ClipperLib::IntPoint;
  using ClipperLib::Path;
  using ClipperLib::Paths;
  std::mt19937_64 rng(11);
  const long long side = 400;
  const int cols = 5, rows = 4;
  const long long ox = -300, oy = 1200;
  std::uniform_int_distribution<long long> pick(-2, 12);  // multiples of side/2: on the lines
  std::uniform_int_distribution<long long> jitter(-700, 2700);
  const long long scale = 1LL << 20;
  auto scaled = [&](const Path& p) {
    Path q;
    for (const IntPoint& v : p) q.push_back({v.X * scale, v.Y * scale});
    return q;
  };
  auto check = [&](const Paths& rings, const char* what, double sign = 1) {
    std::vector<double> area, cover;
    cover::cell_areas(rings, ox, oy, side, cols, rows, area, cover);
    ASSERT_EQ(area.size(), static_cast<std::size_t>(cols * rows));
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        const long long x0 = ox + c * side, y0 = oy + r * side;
        ClipperLib::Clipper clipper;
        for (const Path& ring : rings) clipper.AddPath(scaled(ring), ClipperLib::ptSubject, true);
        clipper.AddPath(
            scaled({{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}),
            ClipperLib::ptClip, true);
        Paths in;
        clipper.Execute(ClipperLib::ctIntersection, in, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        double expected = 0;
        for (const Path& p : in) expected += ClipperLib::Area(p);
        expected *= sign / (static_cast<double>(scale) * static_cast<double>(scale));
        EXPECT_NEAR(area[static_cast<std::size_t>(r * cols + c)], expected, 1e-3)
            << what << " cell " << c << "," << r;
      }
  };
  for (int i = 0; i < 300; ++i) {
    // A convex polygon (counter-clockwise hull of random points, some on cell lines).
    std::vector<IntPoint> pts;
    for (int k = 0; k < 3 + i % 9; ++k) {
      const bool on_lines = k % 2 == 0;
      pts.push_back(on_lines ? IntPoint{ox + pick(rng) * side / 2, oy + pick(rng) * side / 2}
                             : IntPoint{ox + jitter(rng), oy + jitter(rng)});
    }
    std::sort(pts.begin(), pts.end(), [](const IntPoint& a, const IntPoint& b) {
      return a.X != b.X ? a.X < b.X : a.Y < b.Y;
    });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) continue;
    auto turn = [](const IntPoint& a, const IntPoint& b, const IntPoint& q) {
      return (b.X - a.X) * (q.Y - a.Y) - (b.Y - a.Y) * (q.X - a.X);
    };
    Path hull;
    for (int pass = 0; pass < 2; ++pass) {
      const std::size_t base = hull.size();
      for (std::size_t k = 0; k < pts.size(); ++k) {
        const IntPoint& q = pass == 0 ? pts[k] : pts[pts.size() - 1 - k];
        while (hull.size() >= base + 2 && turn(hull[hull.size() - 2], hull.back(), q) <= 0)
          hull.pop_back();
        hull.push_back(q);
      }
      hull.pop_back();
    }
    if (hull.size() < 3) continue;
    check({hull}, "convex");
    // The same with a clockwise hole (a smaller copy of it around its first vertex's centroid
    // side), and reversed (clockwise: negative areas).
    Path reversed(hull.rbegin(), hull.rend());
    check({reversed}, "clockwise", -1);
    long long cx = 0, cy = 0;
    for (const IntPoint& q : hull) {
      cx += q.X;
      cy += q.Y;
    }
    cx /= static_cast<long long>(hull.size());
    cy /= static_cast<long long>(hull.size());
    Path hole;
    for (auto it = hull.rbegin(); it != hull.rend(); ++it)
      hole.push_back({cx + (it->X - cx) / 2, cy + (it->Y - cy) / 2});
    check({hull, hole}, "with a hole");
  }
  // A star (not convex) with spikes across several cells, and a rectangle along cell lines.
  Path star;
  for (int k = 0; k < 14; ++k) {
    const double a = 2 * M_PI * k / 14, rad = k % 2 ? 500 : 1300;
    star.push_back(
        {ox + 1000 + std::llround(rad * std::cos(a)), oy + 800 + std::llround(rad * std::sin(a))});
  }
  check({star}, "star");
  check({{{ox + side, oy},
          {ox + 3 * side, oy},
          {ox + 3 * side, oy + 2 * side},
          {ox + side, oy + 2 * side}}},
        "rectangle on the lines");
  // Wholly outside the grid: nothing anywhere.
  check({{{ox - 900, oy - 900}, {ox - 100, oy - 900}, {ox - 100, oy - 100}}}, "outside");
}

// ---- strips (view/visible_strips.h) -------------------------------------------------------

TEST(Strips, CrossingPointsAreTheNearestGridPointAndTheSameFromBothEnds) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> coord(-200000, 200000);
  for (int i = 0; i < 20000; ++i) {
    const ClipperLib::IntPoint a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)};
    if (a.Y == b.Y) continue;
    const long long y = std::min(a.Y, b.Y) + coord(rng) % (std::abs(b.Y - a.Y));
    const long long x = cover::crossing_x(a, b, y);
    EXPECT_EQ(x, cover::crossing_x(b, a, y));
    // Exact oracle: |x - (a.X + (b.X - a.X)(y - a.Y)/(b.Y - a.Y))| <= 1/2, in integers
    // (|2 (x - a.X) d - 2 (b.X - a.X)(y - a.Y)| <= |d|, d = b.Y - a.Y; products below 2^62).
    const long long d = b.Y - a.Y;
    const long long lhs = std::abs(2 * (x - a.X) * d - 2 * (b.X - a.X) * (y - a.Y));
    EXPECT_LE(lhs, std::abs(d)) << a.X << "," << a.Y << " " << b.X << "," << b.Y << " y " << y;
  }
}

TEST(Strips, APolygonCutAtAStripLineComesBackWholeFromItsHalves) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<long long> coord(0, 4000);
  int crossing = 0;
  for (int i = 0; i < 3000; ++i) {
    ClipperLib::Path tri{
        {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
    if (ClipperLib::Area(tri) == 0) continue;
    if (ClipperLib::Area(tri) < 0) std::reverse(tri.begin(), tri.end());
    const long long y = 400 * (1 + static_cast<long long>(rng() % 9));
    ClipperLib::Path low, high;
    const bool has_low = cover::cut_to_band(tri, -(1LL << 60), y, low);
    const bool has_high = cover::cut_to_band(tri, y, 1LL << 60, high);
    for (const auto* half : {&low, &high})
      for (const ClipperLib::IntPoint& q : *half) {
        // Each half's points are the triangle's own or crossings on the strip line.
        const bool own = std::find(tri.begin(), tri.end(), q) != tri.end();
        EXPECT_TRUE(own || q.Y == y);
      }
    if (!has_low || !has_high) continue;
    ++crossing;
    // The halves meet along the line point for point: their shared edges cancel into one ring
    // (the triangle with its crossings, which lie within half a unit of its edges).
    ClipperLib::Paths whole;
    ASSERT_TRUE(cover::union_by_shared_edges({&low, &high}, whole));
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_LE(std::abs(ClipperLib::Area(whole[0]) - ClipperLib::Area(tri)),
              0.5 * 2 * 4000 + 1);  // two crossings, each moved under half a unit along the line
    EXPECT_EQ(ClipperLib::Area(low) + ClipperLib::Area(high), ClipperLib::Area(whole[0]));
  }
  EXPECT_GT(crossing, 500);
}

TEST(Strips, RowsAreIncreasingTileRowsHoldingEqualSharesOfTheCentres) {
  std::vector<long long> centres;
  for (long long k = 0; k < 1000; ++k) centres.push_back(k * k % 76800);  // skewed, 768 px
  const std::vector<int> rows = cover::strip_rows(centres, 76800, 4);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows.front(), 0);
  EXPECT_EQ(rows.back(), 192);
  for (std::size_t s = 0; s + 1 < rows.size(); ++s) {
    EXPECT_LT(rows[s], rows[s + 1]);
    const long long y0 = rows[s] * cover::tiled_coverage::tile_side;
    const long long y1 = rows[s + 1] * cover::tiled_coverage::tile_side;
    const auto in = std::count_if(centres.begin(), centres.end(),
                                  [&](long long c) { return c >= y0 && c < y1; });
    EXPECT_NEAR(static_cast<double>(in), 250.0, 30.0) << "strip " << s;
  }
  // Lines to avoid move a cut to the next row; a viewport of one tile row has one strip;
  // nothing at all, one strip.
  const std::vector<long long> avoid{rows[1] * cover::tiled_coverage::tile_side,
                                     rows[2] * cover::tiled_coverage::tile_side};
  const std::vector<int> moved = cover::strip_rows(centres, 76800, 4, avoid);
  ASSERT_EQ(moved.size(), 5u);
  EXPECT_EQ(moved[1], rows[1] + 1);
  EXPECT_EQ(moved[2], rows[2] + 1);
  EXPECT_EQ(moved[3], rows[3]);
  EXPECT_EQ(cover::strip_rows(centres, 300, 4), (std::vector<int>{0, 1}));
  EXPECT_EQ(cover::strip_rows({}, 76800, 4), (std::vector<int>{0, 192}));
}

/// A 200 x 200 frame of window-space polygons (back to front) and lines, drawn as visible
/// regions without edges.
frame window_frame(std::vector<screen_polygon> polygons, std::vector<screen_line> lines) {
  frame f;
  f.view.vp = {0, 0, 200, 200};
  f.polygons = std::move(polygons);
  f.lines = std::move(lines);
  f.vector.edges = vector_options::edges_kind::none;
  return f;
}

screen_polygon window_triangle(std::uint32_t face, rgb8 c, window_point a, window_point b,
                               window_point d) {
  screen_polygon p;
  p.face = face;
  p.fragment = face;
  p.color = c;
  p.v = {a, b, d};
  return p;
}

TEST(Strips, NoCrackAlongStripLinesAndCurvesCrossThemWhole) {
  // Back: a square over the whole viewport (faces 0, 1); front: a square (10, 10)-(190, 190)
  // (faces 2, 3) and, in front of it, many small triangles spread over the viewport so that
  // the strips fall between rows of them. Whatever the strip lines, the back square must show
  // only outside the front one, each front face's pieces must unite into one ring, and points
  // exactly on every tile row (every strip line is one) behind the front square are hidden.
  std::vector<screen_polygon> polys;
  polys.push_back(window_triangle(0, {0, 0, 255}, {-5, -5, 0.9}, {205, -5, 0.9}, {205, 205, 0.9}));
  polys.push_back(window_triangle(1, {0, 0, 250}, {-5, -5, 0.9}, {205, 205, 0.9}, {-5, 205, 0.9}));
  polys.push_back(window_triangle(2, {200, 0, 0}, {10, 10, 0.5}, {190, 10, 0.5}, {190, 190, 0.5}));
  polys.push_back(window_triangle(3, {190, 0, 0}, {10, 10, 0.5}, {190, 190, 0.5}, {10, 190, 0.5}));
  std::uint32_t face = 4;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 3; ++i) {
      const double x = 20 + 60 * i + 3.3 * j, y = 3 + 16.3 * j;
      polys.push_back(window_triangle(face++, {0, 200, 0}, {x, y, 0.1}, {x + 4.1, y + 0.7, 0.1},
                                      {x + 1.3, y + 5.9, 0.1}));
    }
  std::vector<screen_line> lines;
  auto point = [&](double x, double y, std::size_t slot) {
    screen_line l;
    l.a = l.b = {x, y, 0.7};
    l.point = true;
    l.slot = slot;
    l.color = {1, 2, 3};
    lines.push_back(l);
  };
  for (int y = 4; y < 200; y += 4) point(100.25, y, 0);  // behind everything: hidden
  for (int y = 4; y < 200; y += 4) point(197.5, y, 2);   // beside the front square: seen
  screen_line behind;  // behind the front square, across every strip: seen only outside it
  behind.a = {150.5, 1, 0.7};
  behind.b = {150.5, 199, 0.7};
  behind.slot = 2;
  behind.color = {4, 5, 6};
  lines.push_back(behind);
  screen_line front = behind;  // in front of everything: one polyline from end to end
  front.a = {120.5, 2, 0};
  front.b = {121.5, 198, 0};
  front.slot = polys.size();
  front.curve = 1;
  front.color = {7, 8, 9};
  lines.push_back(front);
  std::stable_sort(lines.begin(), lines.end(),
                   [](const screen_line& a, const screen_line& b) { return a.slot < b.slot; });
  frame f = window_frame(polys, lines);
  const vector_drawing d = visible_drawing(f);
  double back_area = 0;
  int front_faces = 0;
  for (const vector_path* r : regions_of(d)) {
    double area = 0;
    int outer = 0;
    for (const auto& ring : r->rings) {
      ClipperLib::Path p;
      for (const grid_point& q : ring) p.push_back({q.x, q.y});
      area += ClipperLib::Area(p);
      outer += ClipperLib::Area(p) > 0;
    }
    if (r->face <= 1) back_area += area;
    if (r->face == 2 || r->face == 3) {
      ++front_faces;
      // One outline (its halves in every strip reunited); the holes are the small triangles.
      EXPECT_EQ(outer, 1) << "face " << r->face;
    }
  }
  EXPECT_EQ(front_faces, 2);
  // The back square (210 px wide, over the viewport's edges) shows as the frame around the
  // front square, less the small triangles in front of it, never inside it.
  EXPECT_LE(back_area, (210.0 * 210 - 180.0 * 180) * 1e4 + 1);
  EXPECT_GT(back_area, (210.0 * 210 - 180.0 * 180) * 1e4 * 0.8);
  int points_seen = 0, behind_pieces = 0, front_pieces = 0;
  for (const vector_path& p : d.paths) {
    if (p.kind == vector_path::kind_type::point) {
      ++points_seen;
      EXPECT_EQ(p.rings[0][0].x, 19750) << "a point behind the front square is drawn";
    }
    if (p.kind == vector_path::kind_type::curve && p.color == rgb8{4, 5, 6})
      for (const auto& r : p.rings) {
        ++behind_pieces;
        for (const grid_point& q : r) EXPECT_TRUE(q.y <= 1000 || q.y >= 19000) << q.y;
      }
    if (p.kind == vector_path::kind_type::curve && p.color == rgb8{1, 2, 3}) ADD_FAILURE();
    if (p.kind == vector_path::kind_type::curve && p.face == 1) {
      front_pieces += static_cast<int>(p.rings.size());
      EXPECT_EQ(p.rings[0].front(), (grid_point{12050, 200}));
      EXPECT_EQ(p.rings[0].back(), (grid_point{12150, 19800}));
    }
  }
  EXPECT_EQ(points_seen, 49);
  EXPECT_EQ(behind_pieces, 2);
  EXPECT_EQ(front_pieces, 1);
}

// ---- edges ------------------------------------------------------------------------------

TEST(Edges, ACubeShowsNineVisibleEdgesAndThreeHidden) {
  // A unit cube seen from a generic corner direction: 9 visible edges (silhouette hexagon and
  // the three at the near corner), 3 hidden ones (at the far corner).
  triangle_soup s;
  const vec3d p[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int q[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                       {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (const auto& f4 : q) add_quad(s, p[f4[0]], p[f4[1]], p[f4[2]], p[f4[3]]);
  frame f = perspective_frame(std::move(s), std::vector<rgb8>(6, {180, 180, 180}),
                              {{4, 3.1, 2.3}, {0.5, 0.5, 0.5}, {0, 0, 1}}, 200, 150);
  f.vector.edges = vector_options::edges_kind::visible_hidden;
  run(f, {}, output_kind::svg);
  const vector_drawing d = visible_drawing(f);
  const drawing_counts c = count_paths(d);
  EXPECT_EQ(c.regions, 3u);
  EXPECT_EQ(c.visible_edges, 9u);
  EXPECT_EQ(c.hidden_edges, 3u);
  const std::string svg = svg_document(d);
  EXPECT_NE(svg.find("<g id=\"hidden-edges\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  // edges "visible": no hidden group.
  f.vector.edges = vector_options::edges_kind::visible;
  EXPECT_EQ(count_paths(visible_drawing(f)).hidden_edges, 0u);
}

TEST(Edges, CreaseAngleDecidesWhichEdgesAreDrawn) {
  // Two quads meeting at 20 degrees, seen from the front: a crease at 10, none at 30.
  triangle_soup s;
  const double t = std::tan(20 * M_PI / 180);
  add_quad(s, {-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0});
  add_quad(s, {0, -1, 0}, {1, -1, -t}, {1, 1, -t}, {0, 1, 0});
  frame f = perspective_frame(std::move(s), {{200, 0, 0}, {0, 0, 200}},
                              {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, 160, 120);
  f.vector.edges = vector_options::edges_kind::visible;
  run(f, {}, output_kind::svg);
  f.vector.crease_deg = 30;
  const std::size_t without = count_paths(visible_drawing(f)).visible_edges;
  f.vector.crease_deg = 10;
  EXPECT_EQ(count_paths(visible_drawing(f)).visible_edges, without + 1);
  f.vector.crease_deg = 0;
  EXPECT_THROW(visible_drawing(f), usage_error);
}

// ---- PDF --------------------------------------------------------------------------------

TEST(Pdf, IsAPdfWithOnePageOfTheViewportSize) {
  scene::scene s;
  frame f = scene_frame("", s);
  run(f, s.effects, output_kind::pdf);
  ASSERT_GT(f.pdf.size(), 100u);
  EXPECT_EQ(f.pdf.compare(0, 5, "%PDF-"), 0);
  EXPECT_NE(f.pdf.find("/MediaBox [ 0 0 " + std::to_string(s.width) + " " +
                       std::to_string(s.height) + " ]"),
            std::string::npos);
  f.vector.mode = vector_options::mode_kind::painter;
  run(f, s.effects, output_kind::pdf);
  EXPECT_EQ(f.pdf.compare(0, 5, "%PDF-"), 0);
}

TEST(Pdf, APlacedViewportGetsAPageOfTheImageSize) {
  scene::scene s;
  frame f = scene_frame("viewport", s);
  ASSERT_TRUE(f.view.needs_placement());
  run(f, s.effects, output_kind::pdf);
  EXPECT_NE(f.pdf.find("/MediaBox [ 0 0 " + std::to_string(f.view.image_width) + " " +
                       std::to_string(f.view.image_height) + " ]"),
            std::string::npos);
  run(f, s.effects, output_kind::svg);
  EXPECT_EQ(f.svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
                       std::to_string(f.view.image_width) + "\" height=\"" +
                       std::to_string(f.view.image_height) + "\""),
            f.svg.find("<svg"));
  EXPECT_NE(f.svg.find("<svg x=\"" + std::to_string(f.view.place_x) + "\""), std::string::npos);
  f.vector.mode = vector_options::mode_kind::painter;  // the painter's stack is placed the same way
  run(f, s.effects, output_kind::svg);
  EXPECT_NE(f.svg.find("<svg x=\"" + std::to_string(f.view.place_x) + "\""), std::string::npos);
  EXPECT_NE(f.svg.find("data-fragment"), std::string::npos);
  run(f, s.effects, output_kind::pdf);
  EXPECT_NE(f.pdf.find("/MediaBox [ 0 0 " + std::to_string(f.view.image_width) + " "),
            std::string::npos);
}

// ---- scene options and the command ------------------------------------------------------

TEST(Options, BadSvgOptionsNameTheirKey) {
  const std::string base =
      R"({"meshes": [], "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0]},
    "projection": {"type": "perspective", "fovy_deg": 40, "near": 1, "far": 100},
    "viewport": {"width": 64, "height": 48}, "svg": )";
  auto key_of = [&](const std::string& svg) {
    try {
      scene::parse_scene_text(base + svg + "}", "s.json");
    } catch (const scene_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(key_of(R"({"mode": "stack"})").find("/svg/mode"), std::string::npos);
  EXPECT_NE(key_of(R"({"edges": "all"})").find("/svg/edges"), std::string::npos);
  EXPECT_NE(key_of(R"({"crease_deg": 0})").find("/svg/crease_deg"), std::string::npos);
  EXPECT_NE(key_of(R"({"crease_deg": "30"})").find("/svg/crease_deg"), std::string::npos);
  EXPECT_NE(key_of(R"({"colour": 1})").find("/svg/colour"), std::string::npos);
  const scene::scene s = scene::parse_scene_text(
      base + R"({"mode": "painter", "edges": "visible+hidden", "crease_deg": 45})" + "}", "s.json");
  EXPECT_EQ(s.vector.mode, vector_options::mode_kind::painter);
  EXPECT_EQ(s.vector.edges, vector_options::edges_kind::visible_hidden);
  EXPECT_EQ(s.vector.crease_deg, 45);
}

TEST(Options, TheCommandWritesPdfAndSvgByExtension) {
  const std::string dir = temp_dir();
  std::ostringstream log;
  render_command({"", dir + "/cmd.pdf", false}, log);
  render_command({"", dir + "/cmd.svg", false}, log);
  std::ifstream pdf(dir + "/cmd.pdf", std::ios::binary), svg(dir + "/cmd.svg");
  std::string head(5, ' ');
  pdf.read(&head[0], 5);
  EXPECT_EQ(head, "%PDF-");
  std::stringstream text;
  text << svg.rdbuf();
  EXPECT_NE(text.str().find("<g id=\"mesh-0\">"), std::string::npos);
  EXPECT_EQ(text.str().find("data-fragment"), std::string::npos);  // visible regions, not the stack
  EXPECT_THROW(render_command({"", dir + "/cmd.eps", false}, log), usage_error);
}

// ---- browsers ---------------------------------------------------------------------------

std::string find_program(const char* env, std::initializer_list<const char*> candidates) {
  if (const char* e = std::getenv(env)) return e;
  for (const char* c : candidates)
    if (fs::exists(c)) return c;
  return "";
}

bool run_quiet(const std::string& command, const std::string& log) {
  return std::system((command + " >" + log + " 2>&1").c_str()) == 0;
}

/// Headless Chromium screenshot of an HTML page at width x height.
bool chromium_screenshot(const std::string& chromium, const std::string& html, int width,
                         int height, const std::string& png) {
  const std::string profile = html + ".profile";
  fs::remove_all(profile);
  fs::create_directories(profile);
  const std::string cmd =
      chromium +
      " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
      " --disable-background-networking --disable-component-update --disable-sync"
      " --hide-scrollbars --force-device-scale-factor=1 --force-color-profile=srgb"
      " --user-data-dir=" +
      profile + " --screenshot=" + png + " --window-size=" + std::to_string(width) + "," +
      std::to_string(height) + " file://" + html;
  fs::remove(png);
  const bool ok = run_quiet(cmd, html + ".log") && fs::exists(png);
  fs::remove_all(profile);
  return ok;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

const char* page_style =
    "<style>html,body{margin:0;padding:0;overflow:hidden}img,svg{display:block}</style>";

/// Pixel agreement of a rasterized drawing with a reference image.
struct agreement {
  std::size_t pixels = 0, equal = 0;       ///< pixels compared, equal ones
  std::size_t drawn = 0, drawn_equal = 0;  ///< of those, pixels not background in either image
  double all() const {
    return pixels ? static_cast<double>(equal) / static_cast<double>(pixels) : 0;
  }
  double of_drawn() const {
    return drawn ? static_cast<double>(drawn_equal) / static_cast<double>(drawn) : 1;
  }
};

/// True when `img` has colour c at (row, col) or one of its 8 neighbours.
bool near_colour(const image& img, int row, int col, rgb8 c) {
  for (int r = std::max(0, row - 1); r <= std::min(img.height() - 1, row + 1); ++r)
    for (int k = std::max(0, col - 1); k <= std::min(img.width() - 1, col + 1); ++k)
      if (img.at_row(r, k) == c) return true;
  return false;
}

/// Compares `shot` with `reference` pixel by pixel, leaving out the pixels where `skip` is set
/// (row-major, when given). A pixel of one of `curve_colours` in either image counts as equal
/// when the other image has that colour within one pixel (file comment).
agreement compare(const image& shot, const image& reference, rgb8 background,
                  const std::vector<rgb8>& curve_colours, const std::vector<bool>* skip = nullptr) {
  agreement a;
  if (shot.width() != reference.width() || shot.height() != reference.height()) return a;
  auto is_curve = [&](rgb8 c) {
    return std::find(curve_colours.begin(), curve_colours.end(), c) != curve_colours.end();
  };
  for (int r = 0; r < shot.height(); ++r)
    for (int k = 0; k < shot.width(); ++k) {
      if (skip && (*skip)[static_cast<std::size_t>(r) * shot.width() + k]) continue;
      const rgb8 x = shot.at_row(r, k), y = reference.at_row(r, k);
      const bool ok = x == y || (is_curve(x) && near_colour(reference, r, k, x)) ||
                      (is_curve(y) && near_colour(shot, r, k, y));
      ++a.pixels;
      a.equal += ok;
      if (x != background || y != background) {
        ++a.drawn;
        a.drawn_equal += ok;
      }
    }
  return a;
}

/// Pixels within one pixel of a curve: where `with` (a PNG with curves) differs from
/// `without` (the same without them), grown by one pixel. Row-major.
std::vector<bool> near_curves(const image& with, const image& without) {
  const int w = with.width(), h = with.height();
  std::vector<bool> mask(static_cast<std::size_t>(w) * h, false);
  for (int r = 0; r < h; ++r)
    for (int k = 0; k < w; ++k)
      if (with.at_row(r, k) != without.at_row(r, k))
        for (int rr = std::max(0, r - 1); rr <= std::min(h - 1, r + 1); ++rr)
          for (int kk = std::max(0, k - 1); kk <= std::min(w - 1, k + 1); ++kk)
            mask[static_cast<std::size_t>(rr) * w + kk] = true;
  return mask;
}

std::string percent(double v) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(3);
  o << 100 * v << "%";
  return o.str();
}

#if EXBSP_HAVE_OSMESA
/// Mesa's z-buffer image of a frame's triangles (world space) with exbsp's matrices, viewport
/// and placement, each triangle in its face's colour (lit by lighting.h's rule when the scene
/// asks for lighting: colours are not what this oracle checks), Mesa's tie rule mirrored
/// into exbsp's (osmesa_zbuffer.h).
image mesa_image(const frame& f, bool cull, bool lit) {
  const view_setup& v = f.view;
  const bool placed = v.needs_placement();
  osmesa::zbuffer_scene z;
  z.image_width = placed ? v.image_width : v.vp.width;
  z.image_height = placed ? v.image_height : v.vp.height;
  z.vp_x = v.vp.x + (placed ? v.place_x : 0);
  z.vp_y = v.vp.y + (placed ? v.place_y : 0);
  z.vp_width = v.vp.width;
  z.vp_height = v.vp.height;
  z.depth_near = v.vp.depth_near;
  z.depth_far = v.vp.depth_far;
  z.background = f.background;
  z.projection = v.projection.m;
  z.model_view = v.model_view.m;
  const lighting_settings& light = f.settings.lighting;
  // Each face's centroid (the mean of its triangles' centroids), where a headlight, a point
  // light and the highlights are evaluated (lighting.h).
  std::map<std::uint32_t, std::pair<point3, int>> centroid;
  for (const soup_triangle& t : f.soup.triangles) {
    auto& [sum, count] = centroid[t.face];
    for (int c = 0; c < 3; ++c) {
      const vec3d& p = f.soup.vertices[t.v[c]];
      sum = {sum.x + p[0] / 3, sum.y + p[1] / 3, sum.z + p[2] / 3};
    }
    ++count;
  }
  for (const soup_triangle& t : f.soup.triangles) {
    fragment_d tri{t.face, {}};
    for (int c = 0; c < 3; ++c) tri.v[c] = f.soup.vertices[t.v[c]];
    z.triangles.push_back(tri.v);
    const auto& [sum, count] = centroid[t.face];
    const point3 at{sum.x / count, sum.y / count, sum.z / count};
    z.colors.push_back(lit ? lit_color(f.color_of(t.face),
                                       shading_normal(tri, f.view, light.two_sided), at, f.view,
                                       light)
                           : f.color_of(t.face));
  }
  z.cull_back = cull;
  z.mirror_y = true;
  return osmesa::render_zbuffer(z);
}
#endif

TEST(Browser, SvgInChromiumAndPdfInPopplerMatchThePngAndMesasZBuffer) {
  const std::string chromium =
      find_program("EXBSP_CHROMIUM", {"/usr/bin/chromium", "/usr/bin/chromium-browser"});
  const std::string pdftoppm = find_program("EXBSP_PDFTOPPM", {"/usr/bin/pdftoppm"});
  const std::string pdftocairo = find_program("EXBSP_PDFTOCAIRO", {"/usr/bin/pdftocairo"});
  if (chromium.empty() || pdftoppm.empty() || pdftocairo.empty())
    GTEST_SKIP() << "SKIPPED: headless Chromium (" << (chromium.empty() ? "missing" : chromium)
                 << ") and pdftoppm (" << (pdftoppm.empty() ? "missing" : pdftoppm)
                 << ", pdftocairo"
                 << ") are needed to rasterize the SVG and PDF; run scripts/setup (apt-get install "
                    "chromium poppler-utils)";
#if !EXBSP_HAVE_OSMESA
  FAIL() << "OSMesa (GL/osmesa.h, GL/gl.h, libOSMesa) was not found when configuring: install "
            "Debian's "
            "libosmesa6-dev (scripts/setup) and reconfigure; the z-buffer comparison cannot run";
#else
  const std::string dir = temp_dir();
  for (const std::string& name : scene_names()) {
    const std::string base = dir + "/" + (name.empty() ? std::string("demo") : name);
    scene::scene s;
    frame f = scene_frame(name, s);
    const bool placed = f.view.needs_placement();
    const bool cull =
        std::find(s.effects.begin(), s.effects.end(), "backface_culling") != s.effects.end();
    std::vector<rgb8> curve_colours;
    for (const curve_spec& c : s.curves) curve_colours.push_back(c.color);
    run(f, s.effects, output_kind::png);
    if (placed) place_stage(f);
    const image png = f.picture;
    image mesa;
    try {
      mesa = mesa_image(
          f, cull, std::find(s.effects.begin(), s.effects.end(), "lighting") != s.effects.end());
    } catch (const std::exception& e) {
      FAIL() << label(name) << ": Mesa's z-buffer: " << e.what();
    }
    // Mesa draws no curves: the pixels next to the PNG's curves are left out (file comment).
    std::vector<bool> curve_pixels;
    if (!s.curves.empty()) {
      frame bare = scene_frame(name, s);
      bare.curves.clear();
      run(bare, s.effects, output_kind::png);
      if (placed) place_stage(bare);
      curve_pixels = near_curves(png, bare.picture);
    }
    const std::vector<bool>* skip = curve_pixels.empty() ? nullptr : &curve_pixels;
    run(f, s.effects, output_kind::svg);
    run(f, s.effects, output_kind::pdf);
    write_text(base + ".svg", f.svg);
    write_text(base + ".pdf", f.pdf);
    write_png(png, base + "_exbsp.png");
    write_png(mesa, base + "_mesa.png");
    const int w = png.width(), h = png.height();

    // Aliased: the SVG inlined with crispEdges; the PDF without anti-aliasing.
    const std::string inline_svg = f.svg.substr(f.svg.find("<svg"));
    write_text(base + "_crisp.html",
               std::string("<!DOCTYPE html><html><head>") + page_style +
                   "<style>svg *{shape-rendering:crispEdges}</style></head><body>" + inline_svg +
                   "</body></html>");
    ASSERT_TRUE(chromium_screenshot(chromium, base + "_crisp.html", w, h, base + "_crisp.png"))
        << label(name);
    // (pdftocairo, poppler's cairo back end, samples pixel centres without anti-aliasing;
    // pdftoppm's aliased mode paints every pixel a path touches, thin slivers included.)
    ASSERT_TRUE(run_quiet(
        pdftocairo + " -png -r 72 -singlefile -antialias none " + base + ".pdf " + base + "_pdf",
        base + "_pdf.log"))
        << label(name);
    const image svg_shot = read_png(base + "_crisp.png"), pdf_shot = read_png(base + "_pdf.png");
    const agreement svg_png = compare(svg_shot, png, s.background, curve_colours);
    const agreement pdf_png = compare(pdf_shot, png, s.background, curve_colours);
    const agreement svg_mesa = compare(svg_shot, mesa, s.background, {}, skip);
    const agreement pdf_mesa = compare(pdf_shot, mesa, s.background, {}, skip);
    const agreement png_mesa = compare(png, mesa, s.background, {}, skip);
    std::cout << "vector " << label(name) << (placed ? " (placed)" : "")
              << ": equal to the PNG: SVG " << percent(svg_png.all()) << ", PDF "
              << percent(pdf_png.all()) << "; to Mesa's z-buffer: SVG " << percent(svg_mesa.all())
              << " (drawn " << percent(svg_mesa.of_drawn()) << "), PDF " << percent(pdf_mesa.all())
              << " (drawn " << percent(pdf_mesa.of_drawn()) << "), PNG " << percent(png_mesa.all())
              << " (drawn " << percent(png_mesa.of_drawn()) << ")"
              << (skip ? "; pixels next to curves left out" : "") << "\n";
    EXPECT_GE(svg_png.all(), 0.995) << label(name) << ": Chromium, crispEdges, against the PNG";
    EXPECT_GE(pdf_png.all(), 0.995)
        << label(name) << ": pdftocairo, no anti-aliasing, against the PNG";
    EXPECT_GE(svg_mesa.all(), 0.995)
        << label(name) << ": Chromium, crispEdges, against Mesa's z-buffer";
    EXPECT_GE(pdf_mesa.all(), 0.995)
        << label(name) << ": pdftocairo, no anti-aliasing, against Mesa's z-buffer";
    // and not only thanks to the background (as test_oracle_gl requires of the PNG)
    EXPECT_GE(svg_mesa.of_drawn(), 0.995)
        << label(name) << ": Chromium, drawn pixels, against Mesa's z-buffer";
    EXPECT_GE(pdf_mesa.of_drawn(), 0.995)
        << label(name) << ": pdftocairo, drawn pixels, against Mesa's z-buffer";

    // Anti-aliased as shipped: no seam inside a flat face.
    write_text(base + ".html", std::string("<!DOCTYPE html><html><head>") + page_style +
                                   "</head><body><img src=\"" + base + ".svg\" width=\"" +
                                   std::to_string(w) + "\" height=\"" + std::to_string(h) +
                                   "\"></body></html>");
    ASSERT_TRUE(chromium_screenshot(chromium, base + ".html", w, h, base + "_aa.png"))
        << label(name);
    // Allowed: one interior pixel in 10,000, the anti-aliased tips of true slivers narrower than
    // a pixel that the PNG's centre sampling misses (a seam is a line: hundreds of pixels).
    std::size_t interior = 0;
    const std::size_t seams = interior_differences(png, read_png(base + "_aa.png"), &interior);
    EXPECT_GT(interior, 0u);
    EXPECT_LE(seams * 10000, interior) << label(name) << ": Chromium seams: " << seams;
    ASSERT_TRUE(run_quiet(pdftoppm + " -r 72 -png -singlefile " + base + ".pdf " + base + "_pdf_aa",
                          base + "_pdf.log"))
        << label(name);
    const std::size_t pdf_seams = interior_differences(png, read_png(base + "_pdf_aa.png"));
    EXPECT_LE(pdf_seams * 10000, interior) << label(name) << ": pdftoppm seams: " << pdf_seams;
  }
#endif
}

// ---- a PNG's edges (raster_edges_stage) ----------------------------------------------------

/// The cube [-1, 1]^3 (each face a quad of its own colour) seen from (0, 0, 5) through
/// gluPerspective(45, 4/3) at 400 x 300, rendered to PNG with `edges` drawn over it (with
/// `wireframe`, alone).
frame cube_png(vector_options::edges_kind edges, bool wireframe = false) {
  triangle_soup s;
  const double c[2] = {-1, 1};
  for (int axis = 0; axis < 3; ++axis)
    for (double side : c) {
      const int i = (axis + 1) % 3, j = (axis + 2) % 3;
      vec3d q[4];
      const double u[4] = {-1, 1, 1, -1}, v[4] = {-1, -1, 1, 1};
      for (int k = 0; k < 4; ++k) {
        q[k][axis] = side;
        q[k][i] = u[k];
        q[k][j] = side > 0 ? v[k] : -v[k];  // counter-clockwise seen from outside
      }
      add_quad(s, q[0], q[1], q[2], q[3]);
    }
  frame f = perspective_frame(
      std::move(s),
      {{200, 60, 60}, {60, 200, 60}, {60, 60, 200}, {200, 200, 60}, {60, 200, 200}, {200, 60, 200}},
      {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, 400, 300);
  f.raster_edges.edges = edges;
  f.wireframe = wireframe;
  run(f, {}, output_kind::png);
  if (edges != vector_options::edges_kind::none) raster_edges_stage(f);
  return f;
}

/// The oracle's image of world point p for cube_png's camera (a pinhole written out here, not
/// the pipeline's matrices): window coordinates, y up.
std::array<double, 2> cube_image(const vec3d& p) {
  const double t = std::tan(45.0 / 2 * M_PI / 180), depth = 5 - p[2];
  return {(p[0] / (depth * t * 4.0 / 3.0) + 1) / 2 * 400, (p[1] / (depth * t) + 1) / 2 * 300};
}

/// Of the pixels under the image of segment [a, b] (sampled each pixel, the ends' 3 px left
/// out), the fraction that `with` paints darker than `without` by more than 60 in the sum of
/// the channels (an edge stroke is black over a face).
double darkened_along(const image& without, const image& with, const vec3d& a, const vec3d& b) {
  const auto p = cube_image(a), q = cube_image(b);
  const double length = std::hypot(q[0] - p[0], q[1] - p[1]);
  int dark = 0, samples = 0;
  for (double s = 3; s <= length - 3; s += 1, ++samples) {
    const int i = static_cast<int>(p[0] + (q[0] - p[0]) * s / length);
    const int j = static_cast<int>(p[1] + (q[1] - p[1]) * s / length);
    const rgb8 x = without.pixel(i, j), y = with.pixel(i, j);
    dark += (x.r + x.g + x.b) - (y.r + y.g + y.b) > 60;
  }
  return samples ? static_cast<double>(dark) / samples : 0;
}

TEST(RasterEdges, VisibleEdgesAreSolidHiddenOnesDashedAndNothingElseChanges) {
  const frame plain = cube_png(vector_options::edges_kind::none);
  const frame visible = cube_png(vector_options::edges_kind::visible);
  const frame both = cube_png(vector_options::edges_kind::visible_hidden);
  // Visible from (0, 0, 5): the front face's outline. Hidden: the back square and the four
  // edges that recede to it, all inside the front face's image.
  const vec3d front[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const vec3d back[4] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}};
  for (int k = 0; k < 4; ++k) {
    const vec3d &a = front[k], &b = front[(k + 1) % 4];
    EXPECT_GE(darkened_along(plain.picture, visible.picture, a, b), 0.95) << "front edge " << k;
    EXPECT_GE(darkened_along(plain.picture, both.picture, a, b), 0.95) << "front edge " << k;
    const std::pair<vec3d, vec3d> hidden[2] = {{back[k], back[(k + 1) % 4]}, {back[k], front[k]}};
    for (const auto& [c, d] : hidden) {
      // Untouched without "hidden"; dashes (3 px on, 2 off) with it.
      EXPECT_EQ(darkened_along(plain.picture, visible.picture, c, d), 0.0) << "hidden " << k;
      const double dashed = darkened_along(plain.picture, both.picture, c, d);
      EXPECT_GT(dashed, 0.3) << "hidden " << k;
      EXPECT_LT(dashed, 0.9) << "hidden " << k << ": solid, not dashed";
    }
  }
  // Away from every edge's image (2 px), the picture is the plain raster's.
  std::vector<std::array<std::array<double, 2>, 2>> lines;
  for (int k = 0; k < 4; ++k) {
    lines.push_back({cube_image(front[k]), cube_image(front[(k + 1) % 4])});
    lines.push_back({cube_image(back[k]), cube_image(back[(k + 1) % 4])});
    lines.push_back({cube_image(front[k]), cube_image(back[k])});
  }
  const auto near_a_line = [&](double x, double y) {
    for (const auto& l : lines) {
      const double dx = l[1][0] - l[0][0], dy = l[1][1] - l[0][1];
      const double t =
          std::clamp(((x - l[0][0]) * dx + (y - l[0][1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      if (std::hypot(x - l[0][0] - t * dx, y - l[0][1] - t * dy) < 2) return true;
    }
    return false;
  };
  int changed_far = 0, changed = 0;
  for (int j = 0; j < 300; ++j)
    for (int i = 0; i < 400; ++i) {
      const bool differs = plain.picture.pixel(i, j) != both.picture.pixel(i, j);
      changed += differs;
      changed_far += differs && !near_a_line(i + 0.5, j + 0.5);
    }
  EXPECT_GT(changed, 1000);
  EXPECT_EQ(changed_far, 0);
}

TEST(RasterEdges, AWireframeDrawsEveryEdgeSolidOnTheBackgroundAlone) {
  const frame wire = cube_png(vector_options::edges_kind::visible_hidden, true);
  const image paper(400, 300, wire.background);
  const vec3d front[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const vec3d back[4] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_GE(darkened_along(paper, wire.picture, front[k], front[(k + 1) % 4]), 0.95) << k;
    EXPECT_GE(darkened_along(paper, wire.picture, back[k], back[(k + 1) % 4]), 0.95) << k;
    EXPECT_GE(darkened_along(paper, wire.picture, back[k], front[k]), 0.95) << k;
  }
  // No face is painted: every pixel is grey (an edge's anti-aliased black over white).
  for (int j = 0; j < 300; ++j)
    for (int i = 0; i < 400; ++i) {
      const rgb8 c = wire.picture.pixel(i, j);
      ASSERT_TRUE(c.r == c.g && c.g == c.b) << i << "," << j;
    }
}

TEST(RasterEdges, ASceneAsksWithRasterEdgesAndTheDefaultPictureIsUnchanged) {
  const fs::path dir = temp_path() / "raster_edges";
  fs::create_directories(dir);
  exbsp_test::write_file(dir / "t.off",
                         "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                         "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string scene = R"({"meshes": [{"file": "t.off"}],
    "camera": {"eye": [2, 1.5, 3], "look_at": [0.3, 0.3, 0.3], "up": [0, 1, 0]},
    "projection": {"type": "perspective", "fovy_deg": 40, "near": 0.5, "far": 20},
    "viewport": {"width": 160, "height": 120})";
  exbsp_test::write_file(dir / "plain.json", scene + "}");
  exbsp_test::write_file(dir / "edges.json",
                         scene + R"(, "raster": {"edges": "visible+hidden", "crease_deg": 20}})");
  const scene::scene plain_scene = scene::load_scene((dir / "plain.json").string());
  const scene::scene edges_scene = scene::load_scene((dir / "edges.json").string());
  EXPECT_EQ(plain_scene.raster_edges.edges, vector_options::edges_kind::none);
  EXPECT_EQ(edges_scene.raster_edges.edges, vector_options::edges_kind::visible_hidden);
  EXPECT_EQ(edges_scene.raster_edges.crease_deg, 20);
  EXPECT_EQ(edges_scene.vector.edges, vector_options::edges_kind::none);  // the SVG's own
  EXPECT_FALSE(edges_scene.wireframe);
  exbsp_test::write_file(dir / "wire.json", scene + R"(, "raster": {"wireframe": true}})");
  const scene::scene wire_scene = scene::load_scene((dir / "wire.json").string());
  EXPECT_TRUE(wire_scene.wireframe);
  EXPECT_EQ(wire_scene.raster_edges.edges, vector_options::edges_kind::visible_hidden);
}

}  // namespace
