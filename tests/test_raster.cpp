// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of the fast painter's raster (view/rasterizer.h, view/paint.h): the span rasterizer
// must reproduce the pixel-by-pixel reference of the top-left rule bit for bit, and the
// front-to-back painter with its coverage mask must give the same image as the back-to-front
// reference painter.
//
// Notation: window coordinates, y up; pixel (i, j) has centre (i + 1/2, j + 1/2). A "case" is a
// triangle and a window size; its coverage is the list of (i, j) in visiting order.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/view/stages.h>
#include <exbsp/view/transforms.h>
#include "scene/demo_scene.h"
#include "scene/scene.h"
#include "view/clip_stage.h"
#include "view/effects.h"
#include "view/paint.h"
#include "view/rasterizer.h"

namespace {

using namespace exbsp::view;
using pixel_list = std::vector<std::pair<int, int>>;

pixel_list reference_pixels(point2 a, point2 b, point2 c, int w, int h) {
  pixel_list out;
  for_each_covered_pixel_reference(a, b, c, w, h, [&](int i, int j) { out.emplace_back(i, j); });
  return out;
}

pixel_list span_pixels(point2 a, point2 b, point2 c, int w, int h) {
  pixel_list out;
  for_each_covered_span(a, b, c, w, h, [&](int j, int lo, int hi) {
    EXPECT_LE(lo, hi);
    for (int i = lo; i <= hi; ++i) out.emplace_back(i, j);
  });
  return out;
}

std::string describe(point2 a, point2 b, point2 c, int w, int h) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g) (%.17g, %.17g) (%.17g, %.17g) in %dx%d", a.x, a.y,
                b.x, b.y, c.x, c.y, w, h);
  return buf;
}

/// Compares span and reference coverage of (a, b, c) and of its other windings and vertex
/// rotations; returns the number of pixels (for checks that the cases are not all empty).
std::size_t expect_same(point2 a, point2 b, point2 c, int w, int h) {
  const pixel_list ref = reference_pixels(a, b, c, w, h);
  EXPECT_EQ(span_pixels(a, b, c, w, h), ref) << describe(a, b, c, w, h);
  EXPECT_EQ(span_pixels(b, c, a, w, h), reference_pixels(b, c, a, w, h)) << describe(b, c, a, w, h);
  EXPECT_EQ(span_pixels(a, c, b, w, h), reference_pixels(a, c, b, w, h)) << describe(a, c, b, w, h);
  pixel_list via_cover;
  for_each_covered_pixel(a, b, c, w, h, [&](int i, int j) { via_cover.emplace_back(i, j); });
  EXPECT_EQ(via_cover, ref) << describe(a, b, c, w, h);
  return ref.size();
}

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------------------
// Degenerate triangles first

TEST(SpanRaster, ZeroAreaAndNonFiniteTrianglesCoverNothing) {
  for (const std::array<point2, 3>& t : std::vector<std::array<point2, 3>>{
           {{{1, 1}, {1, 1}, {1, 1}}},              // a point
           {{{0.5, 0.5}, {3.5, 3.5}, {7.5, 7.5}}},  // collinear through centres
           {{{0, 0.5}, {8, 0.5}, {4, 0.5}}},        // horizontal line on centres
           {{{nan, 1}, {3, 1}, {1, 4}}},
           {{{inf, 1}, {3, 1}, {1, 4}}},
           {{{1, -inf}, {3, 1}, {1, 4}}}}) {
    EXPECT_EQ(expect_same(t[0], t[1], t[2], 8, 8), 0u);
  }
}

TEST(SpanRaster, OutsideTheWindowAndOneByOneWindows) {
  EXPECT_EQ(expect_same({-5, -5}, {-1, -5}, {-3, -1}, 8, 8), 0u);
  EXPECT_EQ(expect_same({9, 9}, {20, 9}, {9, 20}, 8, 8), 0u);
  EXPECT_EQ(expect_same({-100, -100}, {100, -100}, {0, 100}, 1, 1), 1u);
  EXPECT_EQ(expect_same({0.5, 0.5}, {1, 0.5}, {0.5, 1}, 1, 1),
            0u);  // centre on a vertex and a bottom edge
  EXPECT_EQ(expect_same({0.5, 0.5}, {0.5, 0}, {1, 0.5}, 1, 1),
            1u);  // ... on a vertex, a top and a left edge
  EXPECT_EQ(expect_same({0, 0}, {1, 1}, {0, 1}, 1, 1), 0u);  // centre on the diagonal: a right edge
  EXPECT_EQ(expect_same({0, 0}, {1, 0}, {1, 1}, 1, 1), 1u);  // the other half: a left edge
}

TEST(SpanRaster, EdgesThroughPixelCentresFollowTheReference) {
  // Every vertex on a centre, an integer or a half-integer: many centres lie exactly on edges.
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> coord(-6, 40);
  std::size_t painted = 0;
  for (int n = 0; n < 20000; ++n) {
    auto p = [&] { return point2{coord(rng) * 0.5, coord(rng) * 0.5}; };
    painted += expect_same(p(), p(), p(), 17, 13);
    if (HasFailure()) return;
  }
  EXPECT_GT(painted, 100000u);
}

TEST(SpanRaster, SharedEdgesPartitionTheirPixels) {
  // Quads split along either diagonal, vertices on a 1/4 grid: each pixel of the quad painted
  // exactly once by the two span-rasterized halves, as by the reference.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(-4, 60);
  for (int n = 0; n < 3000; ++n) {
    point2 q[4];
    for (point2& v : q) v = {coord(rng) * 0.25, coord(rng) * 0.25};
    const int w = 15, h = 11;
    std::vector<int> count(w * h, 0), ref_count(w * h, 0);
    for (const std::array<int, 3>& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
      for (const auto& [i, j] : span_pixels(q[t[0]], q[t[1]], q[t[2]], w, h)) ++count[j * w + i];
      for (const auto& [i, j] : reference_pixels(q[t[0]], q[t[1]], q[t[2]], w, h))
        ++ref_count[j * w + i];
    }
    ASSERT_EQ(count, ref_count) << n;
  }
}

TEST(SpanRaster, RandomTrianglesOfEverySize) {
  std::mt19937_64 rng(1616);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t painted = 0;
  for (int n = 0; n < 20000; ++n) {
    const int w = 1 + static_cast<int>(unit(rng) * 64), h = 1 + static_cast<int>(unit(rng) * 48);
    // Scale from a tenth of a pixel to a million pixels, centred anywhere near the window.
    const double scale = std::pow(10.0, -1 + 7 * unit(rng));
    const point2 centre{(unit(rng) * 1.4 - 0.2) * w, (unit(rng) * 1.4 - 0.2) * h};
    auto p = [&] {
      return point2{centre.x + (unit(rng) - 0.5) * scale, centre.y + (unit(rng) - 0.5) * scale};
    };
    painted += expect_same(p(), p(), p(), w, h);
    if (HasFailure()) return;
  }
  EXPECT_GT(painted, 100000u);
}

TEST(SpanRaster, SliversAndNearlyCollinearTriangles) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t painted = 0;
  for (int n = 0; n < 20000; ++n) {
    const int w = 40, h = 30;
    const point2 a{unit(rng) * 60 - 10, unit(rng) * 50 - 10},
        b{unit(rng) * 60 - 10, unit(rng) * 50 - 10};
    const double t = unit(rng) * 1.2 - 0.1,
                 off = std::pow(10.0, -15 * unit(rng)) * (unit(rng) < 0.5 ? -1 : 1);
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (len == 0) continue;
    const point2 c{a.x + t * dx - off * dy / len, a.y + t * dy + off * dx / len};
    painted += expect_same(a, b, c, w, h);
    if (HasFailure()) return;
  }
  EXPECT_GT(painted, 1000u);
}

TEST(SpanRaster, VerticesOneUlpFromCentresAndEdgesNearlyThroughThem) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coord(0, 24), ulps(-3, 3);
  auto nudge = [&](double x) {
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) x = std::nextafter(x, k > 0 ? inf : -inf);
    return x;
  };
  for (int n = 0; n < 20000; ++n) {
    auto p = [&] { return point2{nudge(coord(rng) + 0.5), nudge(coord(rng) + 0.5)}; };
    expect_same(p(), p(), p(), 25, 25);
    if (HasFailure()) return;
  }
}

TEST(SpanRaster, HugeCoordinatesAndSteepEdges) {
  const double big[] = {1e6, 1e12, 1e15, 4e15, 1e18, 1e100, 1e300};
  std::size_t painted = 0;
  for (double m : big) {
    painted += expect_same({-m, -m}, {m, -1}, {3.5, m}, 32, 24);
    painted += expect_same({-m, 0.5}, {m, 0.5}, {0.5, m}, 32, 24);     // horizontal edge on centres
    painted += expect_same({0.5, -m}, {0.5, m}, {m, 3}, 32, 24);       // vertical edge on centres
    painted += expect_same({10.25, -m}, {10.75, m}, {-m, 3}, 32, 24);  // nearly vertical
    painted += expect_same({-m, 5.5}, {m, 5.5 + 1e-9}, {0, -m}, 32, 24);  // nearly horizontal
    painted += expect_same({1e-300, 0}, {m, 1e-300}, {0, m}, 32, 24);
  }
  EXPECT_GT(painted, 0u);
  // Edges with denormal or vanishing dy: their inverse slope overflows; the walk still settles.
  expect_same({0, 0.5}, {30, 0.5 + 4.9e-324}, {15, 20}, 32, 24);
  expect_same({0, 10.5}, {30, std::nextafter(10.5, inf)}, {15, -20}, 32, 24);
}

TEST(SpanRaster, LargeWindow) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-200, 1224), y(-200, 968);
  for (int n = 0; n < 60; ++n) {
    expect_same({x(rng), y(rng)}, {x(rng), y(rng)}, {x(rng), y(rng)}, 1024, 768);
    if (HasFailure()) return;
  }
}

TEST(SpanRaster, PolygonSpansAreTheFanTrianglesSpans) {
  const std::vector<point2> poly = {{0.5, 0.5}, {20.25, 1}, {25, 14.5}, {10, 20.5}, {-3, 9}};
  pixel_list fan, spans;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    for (const auto& p : reference_pixels(poly[0], poly[k], poly[k + 1], 24, 18)) fan.push_back(p);
  for_each_covered_span_polygon(poly, 24, 18, [&](int j, int lo, int hi) {
    for (int i = lo; i <= hi; ++i) spans.emplace_back(i, j);
  });
  EXPECT_EQ(spans, fan);
  EXPECT_GT(spans.size(), 200u);
}

// ---------------------------------------------------------------------------------------
// The front-to-back painter with its coverage mask against the back-to-front reference

/// Both walks of the painter on frame f at `scale`; expects the same bytes. Returns the image.
/// The front-to-back walk runs with 1, 2, 3 and 7 bands of rows and the default.
image expect_same_walks(frame& f, int scale, const std::string& what) {
  f.painter = paint_order::back_to_front;
  const image reference = paint_frame(f, scale);
  f.painter = paint_order::front_to_back;
  for (unsigned threads : {1u, 2u, 3u, 7u, 0u}) {
    f.raster_threads = threads;
    const image fast = paint_frame(f, scale);
    EXPECT_EQ(fast.data(), reference.data())
        << what << " at scale " << scale << ", " << threads << " bands";
  }
  return reference;
}

TEST(FrontToBack, EmptyFrameIsTheBackground) {
  frame f;
  f.view.vp = {0, 0, 7, 5, 0, 1};
  f.background = {1, 2, 3};
  const image img = expect_same_walks(f, 1, "empty");
  EXPECT_EQ(img.pixel(6, 4), (rgb8{1, 2, 3}));
}

TEST(FrontToBack, RandomOverlappingPolygonsGiveTheReferenceImage) {
  std::mt19937_64 rng(2016);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int n = 0; n < 60; ++n) {
    frame f;
    const int w = 20 + static_cast<int>(unit(rng) * 150),
              h = 10 + static_cast<int>(unit(rng) * 100);
    f.view.vp = {
        static_cast<int>(unit(rng) * 10) - 5, static_cast<int>(unit(rng) * 10) - 5, w, h, 0, 1};
    f.background = {9, 9, 9};
    const std::size_t count = 1 + static_cast<std::size_t>(unit(rng) * 400);
    for (std::size_t k = 0; k < count; ++k) {
      screen_polygon p;
      p.fragment = static_cast<std::uint32_t>(k);
      p.color = {static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                 static_cast<std::uint8_t>(byte(rng))};
      // Sizes from a fraction of a pixel to twice the viewport; vertices on a 1/2 grid half
      // the time, so that edges run through pixel centres and neighbours share them.
      const double size = std::pow(10.0, -0.5 + 2.5 * unit(rng)), grid = unit(rng) < 0.5 ? 2 : 0;
      const double cx = f.view.vp.x + (unit(rng) * 1.4 - 0.2) * w,
                   cy = f.view.vp.y + (unit(rng) * 1.4 - 0.2) * h;
      const int corners = unit(rng) < 0.7 ? 3 : 4;
      for (int c = 0; c < corners; ++c) {
        const double a = 2 * 3.141592653589793 * (c + 0.8 * unit(rng)) / corners;
        double x = cx + size * std::cos(a), y = cy + size * std::sin(a);
        if (grid > 0) x = std::round(x * grid) / grid, y = std::round(y * grid) / grid;
        p.v.push_back({x, y, unit(rng)});
      }
      f.polygons.push_back(p);
      if (unit(rng) < 0.3 && corners == 3) {  // a neighbour across the edge v1 v2
        screen_polygon q = p;
        q.color.r = static_cast<std::uint8_t>(q.color.r ^ 0x80);
        q.v[0] = {p.v[1].x + p.v[2].x - p.v[0].x, p.v[1].y + p.v[2].y - p.v[0].y, 0.5};
        std::swap(q.v[1], q.v[2]);
        f.polygons.push_back(q);
      }
    }
    for (int scale : {1, 2, 3}) expect_same_walks(f, scale, "random frame " + std::to_string(n));
    if (HasFailure()) return;
  }
}

TEST(FrontToBack, AFullyCoveringPolygonInFrontHidesEverythingBehind) {
  frame f;
  f.view.vp = {0, 0, 130, 70, 0, 1};
  for (int k = 0; k < 50; ++k) {
    screen_polygon p;
    p.color = {static_cast<std::uint8_t>(k), 0, 0};
    p.v = {{k + 0.25, 1.0, 0}, {k + 40.0, 3.0, 0}, {k + 20.0, 60.5, 0}};
    f.polygons.push_back(p);
  }
  screen_polygon cover;
  cover.color = {0, 200, 0};
  cover.v = {{-1, -1, 0}, {131, -1, 0}, {131, 71, 0}, {-1, 71, 0}};
  f.polygons.push_back(cover);
  const image img = expect_same_walks(f, 1, "covered");
  for (int j = 0; j < 70; ++j)
    for (int i = 0; i < 130; ++i) ASSERT_EQ(img.pixel(i, j), cover.color);
}

/// Every scene of scenes/ and the built-in demo through its whole PNG pipeline (effects and
/// curves included), once per walk: byte-identical pictures.
TEST(FrontToBack, EveryExampleSceneAndTheDemoGiveTheReferenceImage) {
  std::vector<std::string> paths{""};
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(EXBSP_SOURCE_DIR) + "/scenes"))
    if (e.path().extension() == ".json") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  ASSERT_GE(paths.size(), 10u);
  for (const std::string& path : paths) {
    const exbsp::scene::scene s =
        path.empty() ? exbsp::scene::demo_scene() : exbsp::scene::load_scene(path);
    exbsp::scene::scene_geometry g = exbsp::scene::load_geometry(s);
    frame f;
    f.view = exbsp::scene::make_view_setup(s);
    f.background = s.background;
    f.face_colors = std::move(g.face_colors);
    f.soup = std::move(g.soup);
    f.settings = s.effect_settings;
    f.curves = s.curves;
    build_stage(f);
    const pipeline per_view = per_view_pipeline(s.effects, output_kind::png, !s.curves.empty());
    f.painter = paint_order::back_to_front;
    per_view.run(f, nullptr);
    const image reference = f.picture;
    f.painter = paint_order::front_to_back;
    per_view.run(f, nullptr);
    const std::string name = path.empty() ? "demo" : path;
    EXPECT_EQ(f.picture.data(), reference.data()) << name;
    EXPECT_GT(f.polygons.size(), 0u) << name;
    // And the walks of the last view's polygons at 1x and 2x, whatever the scene's effects.
    for (int scale : {1, 2}) expect_same_walks(f, scale, name);
  }
}

// ---------------------------------------------------------------------------------------
// transform+clip: per-point transform and the clipper's trivial cases, same doubles

/// The stage as it was written first: every corner transformed, every fragment clipped.
std::vector<screen_polygon> reference_transform_clip(const frame& f, std::size_t& fully_clipped) {
  const mat4 pm = f.view.projection * f.view.model_view;
  std::vector<screen_polygon> polygons;
  fully_clipped = 0;
  std::vector<hpoint> in(3), out;
  for (std::uint32_t idx : f.order) {
    const exbsp::fragment_d& fr = f.fragments.at(idx);
    for (int k = 0; k < 3; ++k) in[k] = pm * to_point(fr.v[k]);
    clip_to_view_volume(in, out);
    bool ok = !out.empty();
    for (const hpoint& c : out) ok = ok && c.w > 0;
    if (!ok) {
      ++fully_clipped;
      continue;
    }
    screen_polygon poly;
    poly.fragment = idx;
    poly.face = fr.face;
    poly.color = f.fragment_colors.empty() ? f.color_of(fr.face) : f.fragment_colors.at(idx);
    for (const hpoint& c : out)
      poly.v.push_back(to_window(f.view.vp, c.x / c.w, c.y / c.w, c.z / c.w));
    polygons.push_back(poly);
  }
  return polygons;
}

void expect_bitwise_equal(const std::vector<screen_polygon>& a,
                          const std::vector<screen_polygon>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].fragment, b[i].fragment) << what;
    ASSERT_EQ(a[i].color, b[i].color) << what;
    ASSERT_EQ(a[i].v.size(), b[i].v.size()) << what << " polygon " << i;
    ASSERT_EQ(std::memcmp(a[i].v.data(), b[i].v.data(), a[i].v.size() * sizeof(window_point)), 0)
        << what << " polygon " << i;
  }
}

TEST(TransformClip, SharedPointsAndTrivialCasesGiveTheClippersDoubles) {
  // A scene whose near plane and sides cut through the mesh (inside.json), views from every
  // side, with and without the point index; polygons reused from the previous view.
  for (const char* name : {"inside", "perspective", "oblique", "orthographic"}) {
    const exbsp::scene::scene s =
        exbsp::scene::load_scene(std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json");
    exbsp::scene::scene_geometry g = exbsp::scene::load_geometry(s);
    frame f;
    f.view = exbsp::scene::make_view_setup(s);
    f.face_colors = std::move(g.face_colors);
    f.soup = std::move(g.soup);
    build_stage(f);
    ASSERT_EQ(f.fragment_points.size(), f.fragments.size());
    EXPECT_LT(f.points.size(), 3 * f.fragments.size()) << name;
    for (int view = 0; view < 6; ++view) {
      f.view.model_view = f.view.model_view * rotate(60.0 * view, {0.3, 0.2, 1});
      f.view.cam.eye = {f.view.cam.eye.y, -f.view.cam.eye.x, f.view.cam.eye.z};  // order only
      order_stage(f);
      std::size_t reference_clipped = 0;
      const std::vector<screen_polygon> reference = reference_transform_clip(f, reference_clipped);
      transform_clip_stage(f);
      expect_bitwise_equal(f.polygons, reference,
                           std::string(name) + " indexed, view " + std::to_string(view));
      EXPECT_EQ(f.fully_clipped, reference_clipped) << name;
      const auto index = std::move(f.fragment_points);
      f.fragment_points.clear();
      transform_clip_stage(f);
      expect_bitwise_equal(f.polygons, reference,
                           std::string(name) + " per corner, view " + std::to_string(view));
      f.fragment_points = index;
    }
  }
}

TEST(TransformClip, NonFiniteClipCoordinatesStillThrow) {
  frame f;
  f.view.vp = {0, 0, 10, 10, 0, 1};
  f.fragments = {{0, {exbsp::vec3d{0, 0, 0}, exbsp::vec3d{1, 0, 0}, exbsp::vec3d{0, 1, 0}}}};
  f.order = {0};
  f.view.projection(0, 0) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(transform_clip_stage(f), exbsp::usage_error);
}

}  // namespace
