// Tests of the fast painter's raster (view/rasterizer.h): the span rasterizer must reproduce
// the pixel-by-pixel reference of the top-left rule bit for bit.
//
// Notation: window coordinates, y up; pixel (i, j) has centre (i + 1/2, j + 1/2). A "case" is a
// triangle and a window size; its coverage is the list of (i, j) in visiting order.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "view/rasterizer.h"

namespace {

using namespace exbsp::view;
using pixel_list = std::vector<std::pair<int, int>>;

pixel_list reference_pixels(vec2 a, vec2 b, vec2 c, int w, int h) {
  pixel_list out;
  for_each_covered_pixel_reference(a, b, c, w, h, [&](int i, int j) { out.emplace_back(i, j); });
  return out;
}

pixel_list span_pixels(vec2 a, vec2 b, vec2 c, int w, int h) {
  pixel_list out;
  for_each_covered_span(a, b, c, w, h, [&](int j, int lo, int hi) {
    EXPECT_LE(lo, hi);
    for (int i = lo; i <= hi; ++i) out.emplace_back(i, j);
  });
  return out;
}

std::string describe(vec2 a, vec2 b, vec2 c, int w, int h) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g) (%.17g, %.17g) (%.17g, %.17g) in %dx%d", a.x, a.y, b.x, b.y, c.x,
                c.y, w, h);
  return buf;
}

/// Compares span and reference coverage of (a, b, c) and of its other windings and vertex
/// rotations; returns the number of pixels (for checks that the cases are not all empty).
std::size_t expect_same(vec2 a, vec2 b, vec2 c, int w, int h) {
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
  for (const std::array<vec2, 3>& t : std::vector<std::array<vec2, 3>>{
           {{{1, 1}, {1, 1}, {1, 1}}},            // a point
           {{{0.5, 0.5}, {3.5, 3.5}, {7.5, 7.5}}},  // collinear through centres
           {{{0, 0.5}, {8, 0.5}, {4, 0.5}}},       // horizontal line on centres
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
  EXPECT_EQ(expect_same({0.5, 0.5}, {1, 0.5}, {0.5, 1}, 1, 1), 0u);  // centre on a vertex and a bottom edge
  EXPECT_EQ(expect_same({0.5, 0.5}, {0.5, 0}, {1, 0.5}, 1, 1), 1u);  // ... on a vertex, a top and a left edge
  EXPECT_EQ(expect_same({0, 0}, {1, 1}, {0, 1}, 1, 1), 0u);          // centre on the diagonal: a right edge
  EXPECT_EQ(expect_same({0, 0}, {1, 0}, {1, 1}, 1, 1), 1u);          // the other half: a left edge
}

TEST(SpanRaster, EdgesThroughPixelCentresFollowTheReference) {
  // Every vertex on a centre, an integer or a half-integer: many centres lie exactly on edges.
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> coord(-6, 40);
  std::size_t painted = 0;
  for (int n = 0; n < 20000; ++n) {
    auto p = [&] { return vec2{coord(rng) * 0.5, coord(rng) * 0.5}; };
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
    vec2 q[4];
    for (vec2& v : q) v = {coord(rng) * 0.25, coord(rng) * 0.25};
    const int w = 15, h = 11;
    std::vector<int> count(w * h, 0), ref_count(w * h, 0);
    for (const std::array<int, 3>& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
      for (const auto& [i, j] : span_pixels(q[t[0]], q[t[1]], q[t[2]], w, h)) ++count[j * w + i];
      for (const auto& [i, j] : reference_pixels(q[t[0]], q[t[1]], q[t[2]], w, h)) ++ref_count[j * w + i];
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
    const vec2 centre{(unit(rng) * 1.4 - 0.2) * w, (unit(rng) * 1.4 - 0.2) * h};
    auto p = [&] { return vec2{centre.x + (unit(rng) - 0.5) * scale, centre.y + (unit(rng) - 0.5) * scale}; };
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
    const vec2 a{unit(rng) * 60 - 10, unit(rng) * 50 - 10}, b{unit(rng) * 60 - 10, unit(rng) * 50 - 10};
    const double t = unit(rng) * 1.2 - 0.1, off = std::pow(10.0, -15 * unit(rng)) * (unit(rng) < 0.5 ? -1 : 1);
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (len == 0) continue;
    const vec2 c{a.x + t * dx - off * dy / len, a.y + t * dy + off * dx / len};
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
    auto p = [&] { return vec2{nudge(coord(rng) + 0.5), nudge(coord(rng) + 0.5)}; };
    expect_same(p(), p(), p(), 25, 25);
    if (HasFailure()) return;
  }
}

TEST(SpanRaster, HugeCoordinatesAndSteepEdges) {
  const double big[] = {1e6, 1e12, 1e15, 4e15, 1e18, 1e100, 1e300};
  std::size_t painted = 0;
  for (double m : big) {
    painted += expect_same({-m, -m}, {m, -1}, {3.5, m}, 32, 24);
    painted += expect_same({-m, 0.5}, {m, 0.5}, {0.5, m}, 32, 24);      // horizontal edge on centres
    painted += expect_same({0.5, -m}, {0.5, m}, {m, 3}, 32, 24);        // vertical edge on centres
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
  const std::vector<vec2> poly = {{0.5, 0.5}, {20.25, 1}, {25, 14.5}, {10, 20.5}, {-3, 9}};
  pixel_list fan, spans;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    for (const auto& p : reference_pixels(poly[0], poly[k], poly[k + 1], 24, 18)) fan.push_back(p);
  for_each_covered_span_polygon(poly, 24, 18, [&](int j, int lo, int hi) {
    for (int i = lo; i <= hi; ++i) spans.emplace_back(i, j);
  });
  EXPECT_EQ(spans, fan);
  EXPECT_GT(spans.size(), 200u);
}

}  // namespace
