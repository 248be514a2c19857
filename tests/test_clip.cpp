// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of src/clip/: each clipper against its definition on fixed and random input.
//
// Random coordinates come from gen_coord(): a mix of uniform doubles on a fine grid, values
// on a quarter grid and the window's own boundary values, so that endpoints exactly on the
// boundary, axis-parallel segments and zero-length segments all occur. `scale` is the
// largest magnitude involved; tolerances are relative to it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <exbsp/clip/bbox.h>
#include <exbsp/clip/cohen_sutherland.h>
#include <exbsp/clip/cyrus_beck.h>
#include <exbsp/clip/homogeneous.h>
#include <exbsp/clip/liang_barsky.h>
#include <exbsp/clip/sutherland_hodgman.h>
#include <exbsp/core/errors.h>
#include "support/exact_triangle_clip.h"

namespace {

using namespace exbsp::clip;
using namespace exbsp_test::oracle;

// ---------------------------------------------------------------------------------------
// Generators and small geometry helpers

/// Uniform integer in [lo, hi) whatever RapidCheck's current size (gen::inRange alone
/// draws from a range that grows with the size); shrinks towards lo.
template <class T>
T uniform_int(T lo, T hi) {
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange<T>(lo, hi));
}

/// Uniform double on a grid of 2^40 steps in [lo, hi].
double gen_double(double lo, double hi) {
  const auto k = uniform_int<std::int64_t>(0, (std::int64_t{1} << 40) + 1);
  return std::min(hi, lo + (hi - lo) * (static_cast<double>(k) * 0x1p-40));
}

/// A coordinate in [lo, hi]: uniform, on the quarter grid, or one of `specials`.
double gen_coord(double lo, double hi, const std::vector<double>& specials = {}) {
  const int kind = uniform_int(0, 10);
  if (kind < 2 && !specials.empty()) return *rc::gen::elementOf(specials);
  if (kind < 4) return std::clamp(std::round(gen_double(lo, hi) * 4.0) / 4.0, lo, hi);
  return gen_double(lo, hi);
}

/// Random closed box with quarter-grid bounds (width 0 possible).
template <std::size_t N>
box<N> gen_box() {
  box<N> b;
  for (std::size_t k = 0; k < N; ++k) {
    b.min[k] = uniform_int(-16, 17) / 4.0;
    b.max[k] = b.min[k] + uniform_int(0, 25) / 4.0;
  }
  return b;
}

template <std::size_t N>
std::array<double, N> gen_point(const box<N>& b, double margin) {
  std::array<double, N> p;
  for (std::size_t k = 0; k < N; ++k)
    p[k] = gen_coord(b.min[k] - margin, b.max[k] + margin, {b.min[k], b.max[k]});
  return p;
}

template <std::size_t N>
std::array<double, N> gen_point_inside(const box<N>& b) {
  std::array<double, N> p;
  for (std::size_t k = 0; k < N; ++k) p[k] = gen_coord(b.min[k], b.max[k], {b.min[k], b.max[k]});
  return p;
}

template <std::size_t N>
bool inside(const std::array<double, N>& p, const box<N>& b) {
  for (std::size_t k = 0; k < N; ++k)
    if (!(b.min[k] <= p[k] && p[k] <= b.max[k])) return false;
  return true;
}

template <std::size_t N>
bool same_bits(const std::array<double, N>& a, const std::array<double, N>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * N) == 0;
}

template <std::size_t N>
bool same_bits(const segment<N>& a, const segment<N>& b) {
  return same_bits(a.p0, b.p0) && same_bits(a.p1, b.p1);
}

template <std::size_t N>
double max_abs(const std::array<double, N>& p) {
  double m = 0;
  for (double v : p) m = std::max(m, std::abs(v));
  return m;
}

template <std::size_t N>
double scale_of(const segment<N>& s, const box<N>& b) {
  return std::max({1.0, max_abs(s.p0), max_abs(s.p1), max_abs(b.min), max_abs(b.max)});
}

template <std::size_t N>
double distance(const std::array<double, N>& a, const std::array<double, N>& b) {
  double d = 0;
  for (std::size_t k = 0; k < N; ++k) d += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(d);
}

/// Distance of q from the line through s, and q's parameter along s (0 at p0, 1 at p1).
/// For a zero-length s: the distance to its point, parameter 0.
template <std::size_t N>
std::pair<double, double> line_distance_and_parameter(const segment<N>& s,
                                                      const std::array<double, N>& q) {
  double dd = 0, dq = 0;
  for (std::size_t k = 0; k < N; ++k) {
    dd += (s.p1[k] - s.p0[k]) * (s.p1[k] - s.p0[k]);
    dq += (s.p1[k] - s.p0[k]) * (q[k] - s.p0[k]);
  }
  if (dd == 0) return {distance(s.p0, q), 0.0};
  const double t = dq / dd;
  std::array<double, N> foot;
  for (std::size_t k = 0; k < N; ++k) foot[k] = s.p0[k] + t * (s.p1[k] - s.p0[k]);
  return {distance(foot, q), t};
}

/// Checks a clipped segment: endpoints inside the closed box exactly, on s (distance and
/// parameter within tol relative to the scale), in s's direction.
template <std::size_t N>
void check_clipped_segment(const segment<N>& s, const box<N>& b, const segment<N>& c) {
  const double scale = scale_of(s, b);
  const double length = distance(s.p0, s.p1);
  RC_ASSERT(inside(c.p0, b));
  RC_ASSERT(inside(c.p1, b));
  for (const auto& q : {c.p0, c.p1}) {
    const auto [dist, t] = line_distance_and_parameter(s, q);
    RC_ASSERT(dist <= 1e-12 * scale);
    if (length > 0) {
      RC_ASSERT(t >= -1e-12 * scale / length);
      RC_ASSERT(t <= 1 + 1e-12 * scale / length);
    }
  }
  double along = 0;
  for (std::size_t k = 0; k < N; ++k) along += (c.p1[k] - c.p0[k]) * (s.p1[k] - s.p0[k]);
  RC_ASSERT(along >= -1e-12 * scale * scale);
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Cohen–Sutherland outcodes

TEST(CohenSutherlandOutcode, TwoDBitsNameTheViolatedBoundaries) {
  const window2 w = make_window(-1, 2, -3, 4);
  EXPECT_EQ(outcode(vec2d{0, 0}, w), 0u);
  EXPECT_EQ(outcode(vec2d{-2, 0}, w), unsigned{left});
  EXPECT_EQ(outcode(vec2d{3, 0}, w), unsigned{right});
  EXPECT_EQ(outcode(vec2d{0, -4}, w), unsigned{bottom});
  EXPECT_EQ(outcode(vec2d{0, 5}, w), unsigned{top});
  EXPECT_EQ(outcode(vec2d{-2, 5}, w), unsigned{left | top});
  EXPECT_EQ(outcode(vec2d{3, -4}, w), unsigned{right | bottom});
}

TEST(CohenSutherlandOutcode, PointsOnTheBoundaryAreInside) {
  const window2 w = make_window(-1, 2, -3, 4);
  for (const vec2d& p :
       {vec2d{-1, 0}, vec2d{2, 0}, vec2d{0, -3}, vec2d{0, 4}, vec2d{-1, -3}, vec2d{2, 4}})
    EXPECT_EQ(outcode(p, w), 0u);
}

TEST(CohenSutherlandOutcode, ThreeDOutcodesSeparateTwentySevenRegions) {
  const box3 b{{0, 0, 0}, {1, 1, 1}};
  std::vector<unsigned> codes;
  for (double x : {-1.0, 0.5, 2.0})
    for (double y : {-1.0, 0.5, 2.0})
      for (double z : {-1.0, 0.5, 2.0}) codes.push_back(outcode(vec3d{x, y, z}, b));
  std::sort(codes.begin(), codes.end());
  EXPECT_EQ(std::unique(codes.begin(), codes.end()) - codes.begin(), 27);
  EXPECT_EQ(outcode(vec3d{0.5, 0.5, -1}, b), unsigned{z_below});
  EXPECT_EQ(outcode(vec3d{0.5, 0.5, 2}, b), unsigned{z_above});
}

RC_GTEST_PROP(CohenSutherlandOutcode, MatchesTheDefinitionOnRandomPoints, ()) {
  const box3 b = gen_box<3>();
  const vec3d p = gen_point(b, 3.0);
  unsigned expected = 0;
  for (unsigned k = 0; k < 3; ++k) {
    if (p[k] < b.min[k]) expected |= 1u << (2 * k);
    if (p[k] > b.max[k]) expected |= 1u << (2 * k + 1);
  }
  RC_ASSERT(outcode(p, b) == expected);
  const window2 w{{b.min[0], b.min[1]}, {b.max[0], b.max[1]}};
  RC_ASSERT(outcode(vec2d{p[0], p[1]}, w) == (expected & 15u));
}

TEST(CohenSutherlandOutcode, TrivialAcceptAndRejectTests) {
  EXPECT_TRUE(trivially_accepted(0, 0));
  EXPECT_FALSE(trivially_accepted(0, left));
  EXPECT_TRUE(trivially_rejected(left | top, left));
  EXPECT_FALSE(trivially_rejected(left, right));
  EXPECT_FALSE(trivially_rejected(0, left));
}

// ---------------------------------------------------------------------------------------
// Line clipping: Cohen–Sutherland and Liang–Barsky

namespace {

/// Runs both clippers on s and checks them against each other and the definition.
template <std::size_t N>
void check_line_clippers(const segment<N>& s, const box<N>& b) {
  const auto cs = cohen_sutherland_clip(s, b);
  const auto lb = liang_barsky_clip(s, b);
  const double scale = scale_of(s, b);
  if (cs) check_clipped_segment(s, b, *cs);
  if (lb) {
    check_clipped_segment(s, b, lb->clipped);
    RC_ASSERT(0.0 <= lb->t0);
    RC_ASSERT(lb->t0 <= lb->t1);
    RC_ASSERT(lb->t1 <= 1.0);
  }
  if (cs && lb) {
    RC_ASSERT(distance(cs->p0, lb->clipped.p0) <= 1e-9 * scale);
    RC_ASSERT(distance(cs->p1, lb->clipped.p1) <= 1e-9 * scale);
  } else if (cs) {  // only a rounding-size grazing piece may be in doubt
    RC_ASSERT(distance(cs->p0, cs->p1) <= 1e-9 * scale);
  } else if (lb) {
    RC_ASSERT(distance(lb->clipped.p0, lb->clipped.p1) <= 1e-9 * scale);
  }
  RC_CLASSIFY(!cs && !lb, "rejected");
  RC_CLASSIFY(cs && lb && same_bits(*cs, s), "unchanged");
}

}  // namespace

RC_GTEST_PROP(LineClipping, CohenSutherlandAgreesWithLiangBarsky2D, ()) {
  const box2 b = gen_box<2>();
  const segment2 s{gen_point(b, 2.0), gen_point(b, 2.0)};
  check_line_clippers(s, b);
}

RC_GTEST_PROP(LineClipping, CohenSutherlandAgreesWithLiangBarsky3D, ()) {
  const box3 b = gen_box<3>();
  const segment3 s{gen_point(b, 1.5), gen_point(b, 1.5)};
  check_line_clippers(s, b);
}

RC_GTEST_PROP(LineClipping, LongSegmentsThroughTheWindowAgree, ()) {
  // Far endpoints on opposite sides of a point of the window: clipped at both ends.
  const box2 b = gen_box<2>();
  const vec2d c = gen_point_inside(b), p0 = gen_point(b, 1e3);
  const double stretch = gen_double(0.5, 2);
  const segment2 s{p0, {c[0] + stretch * (c[0] - p0[0]), c[1] + stretch * (c[1] - p0[1])}};
  check_line_clippers(s, b);
  RC_CLASSIFY(outcode(s.p0, b) != 0 && outcode(s.p1, b) != 0, "both ends outside");
}

RC_GTEST_PROP(LineClipping, SegmentsFullyInsideAreUnchangedBitForBit, ()) {
  const box3 b = gen_box<3>();
  const segment3 s{gen_point_inside(b), gen_point_inside(b)};
  const auto cs = cohen_sutherland_clip(s, b);
  const auto lb = liang_barsky_clip(s, b);
  RC_ASSERT(cs.has_value());
  RC_ASSERT(lb.has_value());
  RC_ASSERT(same_bits(*cs, s));
  RC_ASSERT(same_bits(lb->clipped, s));
  RC_ASSERT(lb->t0 == 0.0);
  RC_ASSERT(lb->t1 == 1.0);
  const segment2 s2{{s.p0[0], s.p0[1]}, {s.p1[0], s.p1[1]}};
  const window2 w{{b.min[0], b.min[1]}, {b.max[0], b.max[1]}};
  RC_ASSERT(same_bits(*cohen_sutherland_clip(s2, w), s2));
  RC_ASSERT(same_bits(liang_barsky_clip(s2, w)->clipped, s2));
}

RC_GTEST_PROP(LineClipping, SegmentsBeyondOneBoundaryAreRejected, ()) {
  const box2 b = gen_box<2>();
  const unsigned axis = uniform_int(0u, 2u);
  const bool above = *rc::gen::arbitrary<bool>();
  segment2 s{gen_point(b, 4.0), gen_point(b, 4.0)};
  for (vec2d* p : {&s.p0, &s.p1})
    (*p)[axis] = above ? b.max[axis] + gen_double(1e-9, 4.0) : b.min[axis] - gen_double(1e-9, 4.0);
  RC_ASSERT(trivially_rejected(outcode(s.p0, b), outcode(s.p1, b)));
  RC_ASSERT(!cohen_sutherland_clip(s, b));
  RC_ASSERT(!liang_barsky_clip(s, b));
}

RC_GTEST_PROP(LineClipping, SegmentsPassingOutsideACornerAreRejected, ()) {
  // Both endpoints in the half-plane x + y > xmax + ymax: the segment misses the window even
  // though its outcodes (left/top, bottom/right, ...) need not share a bit.
  const box2 b = gen_box<2>();
  const double corner = b.max[0] + b.max[1];
  auto gen_beyond = [&] {
    const double x = gen_double(b.min[0] - 8, b.max[0] + 8);
    return vec2d{x, corner - x + gen_double(1e-6, 4.0)};
  };
  const segment2 s{gen_beyond(), gen_beyond()};
  RC_ASSERT(!cohen_sutherland_clip(s, b));
  RC_ASSERT(!liang_barsky_clip(s, b));
}

TEST(LineClipping, DiagonalPastTheCornerIsRejectedAfterOneClip) {
  const window2 w = make_window(0, 1, 0, 1);
  const segment2 s{{-1, 0.9}, {0.2, 2.1}};  // left, then top: not a trivial reject
  EXPECT_FALSE(trivially_rejected(outcode(s.p0, w), outcode(s.p1, w)));
  EXPECT_FALSE(cohen_sutherland_clip(s, w));
  EXPECT_FALSE(liang_barsky_clip(s, w));
}

TEST(LineClipping, EndpointsExactlyOnTheBoundaryAreKept) {
  const window2 w = make_window(-1.5, 2.25, -0.75, 3);
  for (const segment2& s : {segment2{{-1.5, 0.1}, {2.25, 1.7}}, segment2{{0.3, -0.75}, {1.1, 3}},
                            segment2{{-1.5, -0.75}, {2.25, 3}}, segment2{{-1.5, -0.5}, {-1.5, 2.5}},
                            segment2{{-1.5, 3}, {2.25, 3}}}) {
    const auto cs = cohen_sutherland_clip(s, w);
    const auto lb = liang_barsky_clip(s, w);
    ASSERT_TRUE(cs);
    ASSERT_TRUE(lb);
    EXPECT_TRUE(same_bits(*cs, s));
    EXPECT_TRUE(same_bits(lb->clipped, s));
  }
}

TEST(LineClipping, ClippedEndpointsLieExactlyOnTheWindowBoundary) {
  const window2 w = make_window(-1.5, 2.25, -0.75, 3);
  const segment2 s{{-4.0, 0.3}, {5.0, 1.9}};
  const auto cs = cohen_sutherland_clip(s, w);
  const auto lb = liang_barsky_clip(s, w);
  ASSERT_TRUE(cs);
  ASSERT_TRUE(lb);
  EXPECT_EQ(cs->p0[0], -1.5);
  EXPECT_EQ(cs->p1[0], 2.25);
  EXPECT_EQ(lb->clipped.p0[0], -1.5);
  EXPECT_EQ(lb->clipped.p1[0], 2.25);
  EXPECT_DOUBLE_EQ(lb->t0, 2.5 / 9.0);
  EXPECT_DOUBLE_EQ(lb->t1, 6.25 / 9.0);
}

TEST(LineClipping, SegmentThroughTheCornerGivesTheCornerPoint) {
  const window2 w = make_window(-1.5, 2.25, -0.75, 3);
  const segment2 s{{-2.5, 0.25}, {-0.5, -1.75}};  // passes exactly through (-1.5, -0.75)
  const auto cs = cohen_sutherland_clip(s, w);
  const auto lb = liang_barsky_clip(s, w);
  ASSERT_TRUE(cs);
  ASSERT_TRUE(lb);
  for (const vec2d& p : {cs->p0, cs->p1, lb->clipped.p0, lb->clipped.p1}) {
    EXPECT_EQ(p[0], -1.5);
    EXPECT_EQ(p[1], -0.75);
  }
}

TEST(LineClipping, ThreeDSegmentClippedOnAllThreeAxes) {
  const box3 b{{0, 0, 0}, {1, 2, 4}};
  const segment3 s{{-1, -2, -4}, {2, 4, 8}};  // the box's diagonal, extended
  const auto cs = cohen_sutherland_clip(s, b);
  const auto lb = liang_barsky_clip(s, b);
  ASSERT_TRUE(cs);
  ASSERT_TRUE(lb);
  EXPECT_TRUE(same_bits(*cs, segment3{{0, 0, 0}, {1, 2, 4}}));
  EXPECT_TRUE(same_bits(lb->clipped, segment3{{0, 0, 0}, {1, 2, 4}}));
  EXPECT_EQ(lb->t0, 1.0 / 3.0);
  EXPECT_EQ(lb->t1, 2.0 / 3.0);
}

RC_GTEST_PROP(LineClipping, ZeroLengthSegmentIsKeptIffItsPointIsInside, ()) {
  const box3 b = gen_box<3>();
  const vec3d p = gen_point(b, 2.0);
  const segment3 s{p, p};
  const auto cs = cohen_sutherland_clip(s, b);
  const auto lb = liang_barsky_clip(s, b);
  RC_ASSERT(cs.has_value() == inside(p, b));
  RC_ASSERT(lb.has_value() == inside(p, b));
  if (cs) RC_ASSERT(same_bits(*cs, s));
  if (lb) RC_ASSERT(same_bits(lb->clipped, s));
}

TEST(LineClipping, ZeroWidthWindowKeepsTheCrossingPoint) {
  const window2 w = make_window(1, 1, 0, 2);
  const segment2 s{{0, 0}, {2, 2}};
  const auto cs = cohen_sutherland_clip(s, w);
  const auto lb = liang_barsky_clip(s, w);
  ASSERT_TRUE(cs);
  ASSERT_TRUE(lb);
  EXPECT_TRUE(same_bits(*cs, segment2{{1, 1}, {1, 1}}));
  EXPECT_TRUE(same_bits(lb->clipped, segment2{{1, 1}, {1, 1}}));
}

TEST(LineClipping, BadInputThrowsUsageError) {
  const double nan = std::nan("");
  const window2 w = make_window(0, 1, 0, 1);
  EXPECT_THROW(cohen_sutherland_clip(segment2{{nan, 0}, {1, 1}}, w), exbsp::usage_error);
  EXPECT_THROW(liang_barsky_clip(segment2{{0, 0}, {HUGE_VAL, 1}}, w), exbsp::usage_error);
  EXPECT_THROW(cohen_sutherland_clip(segment2{{0, 0}, {1, 1}}, make_window(1, 0, 0, 1)),
               exbsp::usage_error);
  EXPECT_THROW(liang_barsky_clip(segment3{{0, 0, 0}, {1, 1, 1}}, box3{{0, 0, 1}, {1, 1, 0}}),
               exbsp::usage_error);
}

// ---------------------------------------------------------------------------------------
// Sutherland–Hodgman

namespace {

double cross2(const vec2d& o, const vec2d& a, const vec2d& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double signed_area(const std::vector<vec2d>& poly) {
  double twice = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const vec2d& p = poly[i];
    const vec2d& q = poly[(i + 1) % poly.size()];
    twice += p[0] * q[1] - p[1] * q[0];
  }
  return twice / 2;
}

/// Vector area (half the sum of the cross products of a fan) of a 3D polygon.
vec3d vector_area(const std::vector<vec3d>& poly) {
  vec3d sum{0, 0, 0};
  for (const auto& t : fan_triangulate(poly)) {
    const vec3d u{t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
    const vec3d v{t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
    sum[0] += (u[1] * v[2] - u[2] * v[1]) / 2;
    sum[1] += (u[2] * v[0] - u[0] * v[2]) / 2;
    sum[2] += (u[0] * v[1] - u[1] * v[0]) / 2;
  }
  return sum;
}

/// Counter-clockwise convex hull (Andrew's monotone chain), collinear points dropped.
std::vector<vec2d> convex_hull(std::vector<vec2d> pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<vec2d> hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::vector<vec2d> gen_convex_polygon(double range) {
  const int n = uniform_int(3, 12);
  std::vector<vec2d> pts;
  for (int i = 0; i < n; ++i) pts.push_back({gen_coord(-range, range), gen_coord(-range, range)});
  return convex_hull(pts);
}

/// Random half-plane whose line passes within `range` of the origin (mostly containing it).
half_plane2 gen_half_plane(double range) {
  const double angle = gen_double(0, 6.283185307179586);
  return {std::cos(angle), std::sin(angle), gen_double(-range / 4, range)};
}

double line_distance(const half_plane2& h, const vec2d& p) {
  return std::abs(h.value(p)) / std::hypot(h.a, h.b);
}

/// Half-plane on the left of the directed edge p -> q (inside of a CCW polygon).
half_plane2 left_of(const vec2d& p, const vec2d& q) {
  const double a = -(q[1] - p[1]), b = q[0] - p[0];
  return {a, b, -(a * p[0] + b * p[1])};
}

bool inside_convex(const std::vector<vec2d>& ccw, const vec2d& p) {
  if (ccw.size() < 3) return false;
  for (std::size_t i = 0; i < ccw.size(); ++i)
    if (cross2(ccw[i], ccw[(i + 1) % ccw.size()], p) < 0) return false;
  return true;
}

double polygon_scale(const std::vector<vec2d>& poly) {
  double s = 1;
  for (const auto& p : poly) s = std::max(s, max_abs(p));
  return s;
}

}  // namespace

TEST(SutherlandHodgman, SquareClippedByATriangle) {
  const std::vector<vec2d> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  // Triangle (0,0), (3,0), (0,3): x >= 0, y >= 0, x + y <= 3.
  const std::vector<half_plane2> triangle{left_of({0, 0}, {3, 0}), left_of({3, 0}, {0, 3}),
                                          left_of({0, 3}, {0, 0})};
  const auto out = sutherland_hodgman_clip(square, triangle);
  const std::vector<vec2d> expected{{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 2}};
  EXPECT_EQ(out, expected);
  EXPECT_EQ(signed_area(out), 3.5);
  const auto fan = fan_triangulate(out);
  ASSERT_EQ(fan.size(), 3u);
  EXPECT_EQ(fan[1], (std::array<vec2d, 3>{vec2d{0, 0}, vec2d{2, 1}, vec2d{1, 2}}));
}

TEST(SutherlandHodgman, SquareClippedByATriangleInsideItGivesTheTriangle) {
  const std::vector<vec2d> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const vec2d a{1, 1}, b{3, 1}, c{2, 3};
  const auto out = sutherland_hodgman_clip(square, {left_of(a, b), left_of(b, c), left_of(c, a)});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_NEAR(signed_area(out), 2.0, 1e-14);
  for (const vec2d& v : {a, b, c}) {
    double nearest = 1e300;
    for (const vec2d& p : out) nearest = std::min(nearest, distance(p, v));
    EXPECT_LT(nearest, 1e-14);
  }
}

TEST(SutherlandHodgman, WindowBoundariesAreHitExactly) {
  const window2 w = make_window(-0.3, 0.7, -0.1, 0.9);
  const std::vector<vec2d> tri{{-1.3, -0.77}, {2.1, 0.2}, {0.1, 1.61}};
  const auto out = sutherland_hodgman_clip(tri, window_half_planes(w));
  ASSERT_GE(out.size(), 3u);
  int on_boundary = 0;
  for (const vec2d& p : out) {
    EXPECT_TRUE(inside(p, w));
    on_boundary += p[0] == w.min[0] || p[0] == w.max[0] || p[1] == w.min[1] || p[1] == w.max[1];
  }
  EXPECT_EQ(on_boundary, static_cast<int>(out.size()));
}

/// A random convex polygon (at least 3 vertices) and a region of 1 to `max_planes` random
/// half-planes.
std::pair<std::vector<vec2d>, std::vector<half_plane2>> gen_polygon_and_region(int max_planes) {
  std::vector<vec2d> poly = gen_convex_polygon(10);
  RC_PRE(poly.size() >= 3);
  std::vector<half_plane2> region;
  const int m = uniform_int(1, max_planes);
  for (int i = 0; i < m; ++i) region.push_back(gen_half_plane(6));
  return {std::move(poly), std::move(region)};
}

RC_GTEST_PROP(SutherlandHodgman, ResultIsInsideEveryHalfPlaneAndNotLarger, ()) {
  const auto [poly, region] = gen_polygon_and_region(7);
  const auto out = sutherland_hodgman_clip(poly, region);
  const double scale = polygon_scale(poly);
  for (const vec2d& p : out)
    for (const auto& h : region) RC_ASSERT(h.value(p) >= -1e-12 * scale);
  RC_ASSERT(out.empty() || out.size() >= 3);
  RC_ASSERT(signed_area(out) <= signed_area(poly) + 1e-12 * scale * scale);
  RC_ASSERT(signed_area(out) >= -1e-12 * scale * scale);  // orientation kept
  RC_CLASSIFY(out.empty(), "empty");
}

RC_GTEST_PROP(SutherlandHodgman, ConvexPolygonInsideTheWindowIsUnchanged, ()) {
  const window2 w = gen_box<2>();
  std::vector<vec2d> pts;
  for (int i = 0; i < 8; ++i) pts.push_back(gen_point_inside(w));
  const auto poly = convex_hull(pts);
  RC_PRE(poly.size() >= 3);
  RC_ASSERT(sutherland_hodgman_clip(poly, window_half_planes(w)) == poly);
}

RC_GTEST_PROP(SutherlandHodgman, RandomConvexPolygonsMatchPointSampling, ()) {
  const auto [poly, region] = gen_polygon_and_region(6);
  const auto out = sutherland_hodgman_clip(poly, region);
  const double tol = 1e-9 * polygon_scale(poly);
  std::vector<half_plane2> lines = region;
  for (std::size_t i = 0; i < poly.size(); ++i)
    lines.push_back(left_of(poly[i], poly[(i + 1) % poly.size()]));
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const vec2d p{gen_double(-11, 11), gen_double(-11, 11)};
    bool near_a_line = false;
    for (const auto& h : lines) near_a_line = near_a_line || line_distance(h, p) < tol;
    if (near_a_line) continue;
    bool expected = inside_convex(poly, p);
    for (const auto& h : region) expected = expected && h.value(p) >= 0;
    RC_ASSERT(inside_convex(out, p) == expected);
    ++checked;
  }
  RC_ASSERT(checked > 100);
}

TEST(SutherlandHodgman, EdgeCasesOfTheInput) {
  const std::vector<vec2d> tri{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(sutherland_hodgman_clip(tri, {}), tri);
  EXPECT_TRUE(sutherland_hodgman_clip(std::vector<vec2d>{{0, 0}, {1, 0}}, {}).empty());
  EXPECT_TRUE(sutherland_hodgman_clip(tri, {{1, 0, -5}}).empty());  // x >= 5
  // A half-plane that only touches a vertex keeps nothing of positive area.
  EXPECT_TRUE(sutherland_hodgman_clip(tri, {{-1, 0, 0}}).empty());  // x <= 0: one edge
  // Vertices exactly on the line are kept as they are, with no duplicate crossing points.
  const auto half = sutherland_hodgman_clip(tri, {{-1, 1, 0}});  // y >= x
  EXPECT_EQ(half, (std::vector<vec2d>{{0, 0}, {0.5, 0.5}, {0, 1}}));
  EXPECT_THROW(sutherland_hodgman_clip(std::vector<vec2d>{{0, 0}, {1, std::nan("")}, {0, 1}}, {}),
               exbsp::usage_error);
  EXPECT_THROW(sutherland_hodgman_clip(tri, {{1, 0, HUGE_VAL}}), exbsp::usage_error);
  EXPECT_THROW(window_half_planes(make_window(1, 0, 0, 1)), exbsp::usage_error);
}

TEST(SutherlandHodgman, FanTriangulationCoversThePolygon) {
  const std::vector<vec2d> hexagon{{2, 0}, {1, 2}, {-1, 2}, {-2, 0}, {-1, -2}, {1, -2}};
  const auto fan = fan_triangulate(hexagon);
  ASSERT_EQ(fan.size(), 4u);
  double area = 0;
  for (std::size_t i = 0; i < fan.size(); ++i) {
    EXPECT_EQ(fan[i][0], hexagon[0]);
    EXPECT_EQ(fan[i][1], hexagon[i + 1]);
    EXPECT_EQ(fan[i][2], hexagon[i + 2]);
    area += signed_area({fan[i][0], fan[i][1], fan[i][2]});
  }
  EXPECT_EQ(area, signed_area(hexagon));
  EXPECT_TRUE(fan_triangulate(std::vector<vec2d>{{0, 0}, {1, 1}}).empty());
}

RC_GTEST_PROP(SutherlandHodgman, ThreeDTriangleClippedByABoxStaysInItsPlane, ()) {
  const box3 b = gen_box<3>();
  std::vector<vec3d> tri;
  for (int i = 0; i < 3; ++i) tri.push_back(gen_point(b, 3.0));
  const auto out = sutherland_hodgman_clip(tri, box_half_spaces(b));
  double scale = 1;
  for (const auto& p : tri) scale = std::max(scale, max_abs(p));
  const vec3d n = vector_area(tri);
  const double n_len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (const vec3d& p : out) {
    for (std::size_t k = 0; k < 3; ++k) {
      RC_ASSERT(p[k] >= b.min[k] - 1e-12 * scale);
      RC_ASSERT(p[k] <= b.max[k] + 1e-12 * scale);
    }
    if (n_len > 1e-6 * scale * scale) {
      const double off =
          (n[0] * (p[0] - tri[0][0]) + n[1] * (p[1] - tri[0][1]) + n[2] * (p[2] - tri[0][2])) /
          n_len;
      RC_ASSERT(std::abs(off) <= 1e-9 * scale);
    }
  }
  const vec3d a = vector_area(out);
  RC_ASSERT(a[0] * n[0] + a[1] * n[1] + a[2] * n[2] <=
            n_len * n_len + 1e-12 * scale * scale * (n_len + 1));
}

TEST(SutherlandHodgman, FrustumHalfSpacesFollowGlFrustum) {
  const double l = -1, r = 2, bo = -0.5, t = 1.5, n = 1, f = 10;
  const auto planes = frustum_half_spaces(l, r, bo, t, n, f);
  ASSERT_EQ(planes.size(), 6u);
  // The near rectangle's corners lie on the side planes and the near plane.
  for (const vec3d& c : {vec3d{l, bo, -n}, vec3d{r, bo, -n}, vec3d{r, t, -n}, vec3d{l, t, -n}}) {
    int on = 0;
    for (const auto& h : planes) {
      EXPECT_GE(h.value(c), 0);
      on += h.value(c) == 0;
    }
    EXPECT_EQ(on, 3);
  }
  for (const auto& h : planes) EXPECT_GT(h.value({0.1, 0.2, -5}), 0);
  bool behind_rejected = false;
  for (const auto& h : planes) behind_rejected = behind_rejected || h.value({0, 0, 1}) < 0;
  EXPECT_TRUE(behind_rejected);
  EXPECT_THROW(frustum_half_spaces(l, r, bo, t, 0, f), exbsp::usage_error);
  EXPECT_THROW(frustum_half_spaces(r, l, bo, t, n, f), exbsp::usage_error);
  const auto ortho = orthographic_half_spaces(l, r, bo, t, n, f);
  for (const auto& h : ortho) EXPECT_GE(h.value({l, t, -f}), 0);
  EXPECT_THROW(orthographic_half_spaces(l, r, bo, t, f, n), exbsp::usage_error);
}

// ---------------------------------------------------------------------------------------
// Cyrus–Beck

namespace {

/// The exact kept interval [t0, t1] of P(t) = p0 + t (p1 - p0) in every half-plane of the
/// region, with the input's doubles as exact rationals (GMP): the oracle. Empty: t0 > t1.
template <std::size_t N, class H>
std::pair<mpq_class, mpq_class> exact_interval(const segment<N>& s, const std::vector<H>& region) {
  mpq_class t0 = 0, t1 = 1;
  for (const H& h : region) {
    std::array<double, N> n;
    double c;
    if constexpr (N == 2) {
      n = {h.a, h.b};
      c = h.c;
    } else {
      n = h.n;
      c = h.d;
    }
    mpq_class nd = 0, f0 = c;
    for (std::size_t k = 0; k < N; ++k) {
      nd += mpq_class(n[k]) * (mpq_class(s.p1[k]) - mpq_class(s.p0[k]));
      f0 += mpq_class(n[k]) * mpq_class(s.p0[k]);
    }
    if (nd == 0) {
      if (f0 < 0) return {1, 0};
    } else if (nd > 0) {
      t0 = std::max(t0, mpq_class(-f0 / nd));
    } else {
      t1 = std::min(t1, mpq_class(-f0 / nd));
    }
  }
  return {t0, t1};
}

/// Cyrus–Beck against the oracle: the same verdict where the exact interval is clear of the
/// rounding (empty by a margin, or longer than a margin), its ends within 1e-12 of the exact
/// parameters and its points within 1e-12 of the exact points (relative to the coordinates).
template <std::size_t N, class H>
void check_cyrus_beck(const segment<N>& s, const std::vector<H>& region) {
  const auto [e0, e1] = exact_interval(s, region);
  const auto got = cyrus_beck_clip(s, region);
  const double length = mpq_class(e1 - e0).get_d();
  if (std::abs(length) < 1e-9) {
    RC_CLASSIFY(true, "grazing (not judged)");
    return;
  }
  if (length < 0) {
    RC_ASSERT(!got);
    RC_CLASSIFY(true, "rejected");
    return;
  }
  RC_ASSERT(got.has_value());
  RC_ASSERT(std::abs(got->t0 - e0.get_d()) <= 1e-12);
  RC_ASSERT(std::abs(got->t1 - e1.get_d()) <= 1e-12);
  double scale = 1;
  for (std::size_t k = 0; k < N; ++k)
    scale = std::max({scale, std::abs(s.p0[k]), std::abs(s.p1[k])});
  for (std::size_t k = 0; k < N; ++k) {
    const mpq_class d = mpq_class(s.p1[k]) - mpq_class(s.p0[k]);
    RC_ASSERT(std::abs(got->clipped.p0[k] - mpq_class(mpq_class(s.p0[k]) + e0 * d).get_d()) <=
              1e-12 * scale);
    RC_ASSERT(std::abs(got->clipped.p1[k] - mpq_class(mpq_class(s.p0[k]) + e1 * d).get_d()) <=
              1e-12 * scale);
  }
  if (e0 == 0) RC_ASSERT(got->clipped.p0 == s.p0);  // an own end is kept bit for bit
  if (e1 == 1) RC_ASSERT(got->clipped.p1 == s.p1);
  RC_CLASSIFY(e0 == 0 && e1 == 1, "inside");
  RC_CLASSIFY(e0 > 0 || e1 < 1, "clipped");
}

}  // namespace

RC_GTEST_PROP(CyrusBeck, SegmentsAgainstConvexPolygonsMatchTheExactInterval, ()) {
  std::vector<half_plane2> region;
  const int m = uniform_int(1, 8);
  for (int i = 0; i < m; ++i) region.push_back(gen_half_plane(6));
  const segment2 s{{gen_coord(-10, 10), gen_coord(-10, 10)},
                   {gen_coord(-10, 10), gen_coord(-10, 10)}};
  check_cyrus_beck(s, region);
}

RC_GTEST_PROP(CyrusBeck, SegmentsAgainstAFrustumMatchTheExactInterval, ()) {
  const auto region = frustum_half_spaces(-1, 2, -0.5, 1.5, 1, 10);
  const segment3 s{{gen_coord(-6, 6), gen_coord(-6, 6), gen_coord(-12, 2)},
                   {gen_coord(-6, 6), gen_coord(-6, 6), gen_coord(-12, 2)}};
  check_cyrus_beck(s, region);
}

RC_GTEST_PROP(CyrusBeck, AgainstARectItKeepsWhatLiangBarskyKeeps, ()) {
  const window2 w = gen_box<2>();
  const segment2 s{{gen_coord(-4, 4), gen_coord(-4, 4)}, {gen_coord(-4, 4), gen_coord(-4, 4)}};
  const std::vector<half_plane2> sides = window_half_planes(w);
  const auto lb = liang_barsky_clip(s, w);
  const auto cb = cyrus_beck_clip(s, sides);
  RC_ASSERT(lb.has_value() == cb.has_value());
  if (!lb) return;
  RC_ASSERT(std::abs(lb->t0 - cb->t0) <= 1e-15 && std::abs(lb->t1 - cb->t1) <= 1e-15);
  for (int k = 0; k < 2; ++k) {
    RC_ASSERT(std::abs(lb->clipped.p0[k] - cb->clipped.p0[k]) <= 1e-14 * (1 + std::abs(s.p0[k])));
    RC_ASSERT(std::abs(lb->clipped.p1[k] - cb->clipped.p1[k]) <= 1e-14 * (1 + std::abs(s.p1[k])));
  }
}

TEST(CyrusBeck, EdgeCasesAndBadInput) {
  const std::vector<half_plane2> right_of_y{{1, 0, 0}};  // x >= 0
  const auto whole = cyrus_beck_clip(segment2{{1, 1}, {2, 2}}, right_of_y);
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->entry, -1);
  EXPECT_EQ(whole->exit, -1);
  EXPECT_FALSE(cyrus_beck_clip(segment2{{-1, 0}, {-1, 5}}, right_of_y));       // parallel, outside
  const auto on_line = cyrus_beck_clip(segment2{{0, 0}, {0, 5}}, right_of_y);  // on the boundary
  ASSERT_TRUE(on_line);
  EXPECT_EQ(on_line->clipped.p1, (vec2d{0, 5}));
  const auto cut = cyrus_beck_clip(segment2{{-2, 1}, {2, 1}}, right_of_y);
  ASSERT_TRUE(cut);
  EXPECT_EQ(cut->t0, 0.5);
  EXPECT_EQ(cut->clipped.p0, (vec2d{0, 1}));
  EXPECT_EQ(cut->entry, 0);
  EXPECT_TRUE(cyrus_beck_clip(segment2{{3, 3}, {3, 3}}, right_of_y));  // a point inside
  EXPECT_TRUE(cyrus_beck_clip(segment2{{-3, 3}, {5, 3}}, {}));         // no half-plane: all
  EXPECT_THROW(cyrus_beck_clip(segment2{{NAN, 0}, {1, 1}}, right_of_y), exbsp::usage_error);
  EXPECT_THROW(cyrus_beck_clip(segment2{{0, 0}, {1, 1}}, {{INFINITY, 0, 0}}), exbsp::usage_error);
  EXPECT_THROW(cyrus_beck_clip(segment2{{-1e308, 0}, {1e308, 0}}, {{1e10, 0, 0}}),
               exbsp::usage_error);  // n . d overflows
}

// ---------------------------------------------------------------------------------------
// Bounding boxes

TEST(BoundingBox, OverlapIsClosedAndRejectsDisjointTriangles) {
  const std::array<vec2d, 3> tri{vec2d{2, 0}, vec2d{3, 1}, vec2d{2.5, 3}};
  const box2 bb = bounding_box(tri);
  EXPECT_EQ(bb.min, (vec2d{2, 0}));
  EXPECT_EQ(bb.max, (vec2d{3, 3}));
  EXPECT_FALSE(triangle_outside_window(tri, make_window(0, 2, 0, 2)));  // touches x = 2
  EXPECT_TRUE(triangle_outside_window(tri, make_window(0, 1.999, 0, 2)));
  EXPECT_TRUE(boxes_overlap(box3{{0, 0, 0}, {1, 1, 1}}, box3{{1, 1, 1}, {2, 2, 2}}));
  EXPECT_FALSE(boxes_overlap(box3{{0, 0, 0}, {1, 1, 1}}, box3{{0, 0, 1.5}, {2, 2, 2}}));
  EXPECT_THROW(bounding_box(std::vector<vec3d>{}), exbsp::usage_error);
  EXPECT_THROW(bounding_box(std::vector<vec2d>{{0, std::nan("")}}), exbsp::usage_error);
  const auto corners = box_corners(box3{{0, 1, 2}, {3, 4, 5}});
  EXPECT_EQ(corners[0], (vec3d{0, 1, 2}));
  EXPECT_EQ(corners[5], (vec3d{3, 1, 5}));
  EXPECT_EQ(corners[7], (vec3d{3, 4, 5}));
}

RC_GTEST_PROP(BoundingBox, BoxesOverlapIffSomePointIsInBoth, ()) {
  const box2 a = gen_box<2>(), b = gen_box<2>();
  bool expected = true;
  for (std::size_t k = 0; k < 2; ++k)
    expected = expected && std::max(a.min[k], b.min[k]) <= std::min(a.max[k], b.max[k]);
  RC_ASSERT(boxes_overlap(a, b) == expected);
  RC_ASSERT(boxes_overlap(b, a) == expected);
}

// ---------------------------------------------------------------------------------------
// Homogeneous (4D) clipping

namespace {

using mat4 = std::array<std::array<double, 4>, 4>;

/// glFrustum(l, r, b, t, n, f).
mat4 frustum_matrix(double l, double r, double b, double t, double n, double f) {
  return {{{2 * n / (r - l), 0, (r + l) / (r - l), 0},
           {0, 2 * n / (t - b), (t + b) / (t - b), 0},
           {0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)},
           {0, 0, -1, 0}}};
}

vec4d transform(const mat4& m, const vec3d& p) {
  vec4d out;
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
  return out;
}

struct frustum_params {
  double l, r, b, t, n, f;
};

frustum_params gen_frustum() {
  frustum_params p;
  p.l = gen_double(-2, -0.1);
  p.r = gen_double(0.1, 2);
  p.b = gen_double(-2, -0.1);
  p.t = gen_double(0.1, 2);
  p.n = gen_double(0.5, 2);
  p.f = p.n + gen_double(1, 20);
  return p;
}

vec3d gen_eye_point() { return {gen_double(-6, 6), gen_double(-6, 6), gen_double(-14, 4)}; }

/// Largest distance from a point of `a` to its nearest point of `b`, both ways.
double hausdorff(const std::vector<vec3d>& a, const std::vector<vec3d>& b) {
  auto one_way = [](const std::vector<vec3d>& x, const std::vector<vec3d>& y) {
    double worst = 0;
    for (const vec3d& p : x) {
      double nearest = 1e300;
      for (const vec3d& q : y) nearest = std::min(nearest, distance(p, q));
      worst = std::max(worst, nearest);
    }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

std::vector<vec3d> to_ndc(const std::vector<vec4d>& points) {
  std::vector<vec3d> out;
  for (const vec4d& p : points) out.push_back(perspective_divide(p));
  return out;
}

/// Clips an eye-space triangle with the homogeneous clipper and, as the oracle, in eye
/// space by the frustum's half-spaces; checks that both give the same polygon in NDC.
void check_against_eye_space(const std::array<vec3d, 3>& eye, const frustum_params& fp) {
  const mat4 m = frustum_matrix(fp.l, fp.r, fp.b, fp.t, fp.n, fp.f);
  const auto clipped =
      homogeneous_clip_triangle({transform(m, eye[0]), transform(m, eye[1]), transform(m, eye[2])});
  const auto oracle =
      sutherland_hodgman_clip(std::vector<vec3d>(eye.begin(), eye.end()),
                              frustum_half_spaces(fp.l, fp.r, fp.b, fp.t, fp.n, fp.f));
  std::vector<vec4d> oracle_clip;
  for (const vec3d& p : oracle) oracle_clip.push_back(transform(m, p));
  for (const vec4d& p : clipped.positions) RC_ASSERT(p[3] > 0.0);
  const auto a = to_ndc(clipped.positions);
  const auto b = to_ndc(oracle_clip);
  for (const vec3d& p : a)
    for (double v : p) RC_ASSERT(std::abs(v) <= 1 + 1e-12);
  if (a.empty() != b.empty()) {
    // Only a sliver within rounding of the volume's boundary may be in doubt.
    const vec3d area = vector_area(a.empty() ? b : a);
    RC_ASSERT(std::abs(area[0]) + std::abs(area[1]) + std::abs(area[2]) <= 1e-9);
  } else {
    RC_ASSERT(hausdorff(a, b) <= 1e-9);
  }
}

}  // namespace

TEST(HomogeneousOutcode, BitsFollowThePlaneOrder) {
  EXPECT_EQ(homogeneous_outcode({0, 0, 0, 1}), 0u);
  EXPECT_EQ(homogeneous_outcode({-2, 0, 0, 1}), 1u);
  EXPECT_EQ(homogeneous_outcode({2, 0, 0, 1}), 2u);
  EXPECT_EQ(homogeneous_outcode({0, -2, 0, 1}), 4u);
  EXPECT_EQ(homogeneous_outcode({0, 2, 0, 1}), 8u);
  EXPECT_EQ(homogeneous_outcode({0, 0, -2, 1}), 16u);
  EXPECT_EQ(homogeneous_outcode({0, 0, 2, 1}), 32u);
  EXPECT_EQ(homogeneous_outcode({1, -1, 1, 1}), 0u);  // on the boundary: inside
  EXPECT_EQ(homogeneous_outcode({0, 0, 0, -1}), 63u);
}

RC_GTEST_PROP(HomogeneousOutcode, PointsBehindTheEyeAreAlwaysOutside, ()) {
  const vec4d p{gen_double(-3, 3), gen_double(-3, 3), gen_double(-3, 3), -gen_double(1e-9, 3)};
  const unsigned code = homogeneous_outcode(p);
  RC_ASSERT(code != 0u);
  RC_ASSERT((code & 3u) != 0u);  // it violates an x plane (and a y and a z plane)
  RC_ASSERT((code & 12u) != 0u);
  RC_ASSERT((code & 48u) != 0u);
}

RC_GTEST_PROP(HomogeneousClip, TriviallyAcceptedTriangleIsUnchanged, ()) {
  std::array<vec4d, 3> tri;
  std::vector<double> attributes;
  for (auto& p : tri) {
    const double w = gen_double(0.25, 3);
    p = {gen_coord(-w, w, {-w, w}), gen_coord(-w, w, {-w, w}), gen_coord(-w, w, {-w, w}), w};
    attributes.push_back(gen_double(0, 1));
    attributes.push_back(gen_double(0, 1));
  }
  RC_ASSERT(homogeneous_trivially_accepted(tri));
  const auto out = homogeneous_clip_triangle(tri, attributes);
  RC_ASSERT(out.attribute_count == 2u);
  RC_ASSERT(out.positions == std::vector<vec4d>(tri.begin(), tri.end()));
  RC_ASSERT(out.attributes == attributes);
}

RC_GTEST_PROP(HomogeneousClip, TriangleWithAllWNegativeIsRejected, ()) {
  std::array<vec4d, 3> tri;
  for (auto& p : tri)
    p = {gen_double(-3, 3), gen_double(-3, 3), gen_double(-3, 3), -gen_double(1e-6, 3)};
  RC_CLASSIFY(homogeneous_trivially_rejected(tri), "trivially rejected");
  const auto out = homogeneous_clip_triangle(tri, {1, 2, 3});
  RC_ASSERT(out.empty());
  RC_ASSERT(out.attributes.empty());
}

TEST(HomogeneousClip, TriangleBehindTheEyeThatWouldWrapAroundGivesNothing) {
  // Behind the eye (w < 0) but x/w, y/w, z/w inside [-1, 1]: drawn without clipping, it
  // would appear mirrored in the middle of the screen.
  const std::array<vec4d, 3> tri{vec4d{0.5, 0.5, 0.5, -1}, vec4d{-0.5, 0.2, 0.1, -1},
                                 vec4d{0.3, -0.9, -1.5, -2}};
  for (const vec4d& p : tri)
    for (std::size_t k = 0; k < 3; ++k) EXPECT_LE(std::abs(p[k] / p[3]), 1.0);
  EXPECT_TRUE(homogeneous_clip_triangle(tri).empty());
  // Mixed signs: the outcodes (42, 21, 38) share no bit, still nothing is visible.
  const std::array<vec4d, 3> mixed{vec4d{3, 3, 3, -1}, vec4d{-3, -3, -3, -1}, vec4d{3, -3, 3, -1}};
  EXPECT_FALSE(homogeneous_trivially_rejected(mixed));
  EXPECT_TRUE(homogeneous_clip_triangle(mixed).empty());
}

TEST(HomogeneousClip, TriangleCrossingWZeroKeepsOnlyTheVisiblePart) {
  const frustum_params fp{-1, 1, -1, 1, 1, 10};
  const mat4 m = frustum_matrix(fp.l, fp.r, fp.b, fp.t, fp.n, fp.f);
  // Two vertices in front of the eye, one behind it (w < 0 after the projection).
  const std::array<vec3d, 3> eye{vec3d{-0.5, -0.5, -5}, vec3d{0.5, -0.5, -5}, vec3d{0, 0.5, 5}};
  const std::array<vec4d, 3> clip{transform(m, eye[0]), transform(m, eye[1]), transform(m, eye[2])};
  ASSERT_LT(clip[2][3], 0.0);
  EXPECT_FALSE(homogeneous_trivially_rejected(clip));
  const auto out = homogeneous_clip_triangle(clip);
  ASSERT_GE(out.size(), 3u);
  for (const vec4d& p : out.positions) {
    EXPECT_GT(p[3], 0.0);
    // Visible points have eye z <= -near = -1, so eye y = -0.5 + (z + 5) / 10 <= -0.1.
    EXPECT_LT(p[1] / p[3], 0.0);
  }
  EXPECT_NO_THROW(check_against_eye_space(eye, fp));
}

RC_GTEST_PROP(HomogeneousClip, MatchesEyeSpaceClippingByTheFrustum, ()) {
  const frustum_params fp = gen_frustum();
  const std::array<vec3d, 3> eye{gen_eye_point(), gen_eye_point(), gen_eye_point()};
  RC_CLASSIFY(eye[0][2] > 0 || eye[1][2] > 0 || eye[2][2] > 0, "a vertex behind the eye");
  check_against_eye_space(eye, fp);
}

RC_GTEST_PROP(HomogeneousClip, ResultIsInsideTheViewVolume, ()) {
  std::array<vec4d, 3> tri;
  for (auto& p : tri)
    p = {gen_double(-4, 4), gen_double(-4, 4), gen_double(-4, 4), gen_double(-2, 4)};
  const auto out = homogeneous_clip_triangle(tri);
  RC_ASSERT(out.empty() || out.size() >= 3);
  for (const vec4d& p : out.positions) {
    RC_ASSERT(p[3] >= 0.0);
    for (std::size_t k = 0; k < 3; ++k) RC_ASSERT(std::abs(p[k]) <= p[3] + 1e-12);
  }
  RC_ASSERT(fan_triangulate(out).size() == (out.empty() ? 0 : out.size() - 2));
}

RC_GTEST_PROP(HomogeneousClip, AttributesAreInterpolatedWithThePosition, ()) {
  // Attributes = eye-space position; the projection of a clipped vertex's attributes must be
  // the clipped vertex itself (linear interpolation in clip space is perspective-correct).
  const frustum_params fp = gen_frustum();
  const mat4 m = frustum_matrix(fp.l, fp.r, fp.b, fp.t, fp.n, fp.f);
  const std::array<vec3d, 3> eye{gen_eye_point(), gen_eye_point(), gen_eye_point()};
  std::vector<double> attributes;
  for (const vec3d& p : eye) attributes.insert(attributes.end(), p.begin(), p.end());
  const auto out = homogeneous_clip_triangle(
      {transform(m, eye[0]), transform(m, eye[1]), transform(m, eye[2])}, attributes);
  RC_ASSERT(out.attribute_count == 3u);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double* a = out.attributes_of(i);
    const vec4d expected = transform(m, {a[0], a[1], a[2]});
    for (std::size_t k = 0; k < 4; ++k)
      RC_ASSERT(std::abs(expected[k] - out.positions[i][k]) <=
                1e-11 * (1 + std::abs(expected[k])) * 100);
  }
}

namespace {

/// Vertices of a clipped polygon whose attribute 0 is exactly 0, i.e. those on the edge
/// between the two input vertices with attribute 0, as (x, y, z, w, attribute 1) tuples.
std::vector<std::array<double, 5>> vertices_on_shared_edge(const homogeneous_polygon& poly) {
  std::vector<std::array<double, 5>> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const double* a = poly.attributes_of(i);
    if (a[0] != 0.0) continue;
    const vec4d& p = poly.positions[i];
    out.push_back({p[0], p[1], p[2], p[3], a[1]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool same_bits(const std::vector<std::array<double, 5>>& a,
               const std::vector<std::array<double, 5>>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

}  // namespace

RC_GTEST_PROP(HomogeneousClip, TrianglesSharingAnEdgeGetBitIdenticalVerticesOnIt, ()) {
  // (P, Q, R) and (Q, P, S) share the edge PQ, walked in opposite directions. Attribute 0
  // is 0 at P and Q and 1 at R and S, so it stays exactly 0 on PQ and only there;
  // attribute 1 is a colour that must be interpolated identically too.
  auto gen_vertex = [] {
    return vec4d{gen_double(-3, 3), gen_double(-3, 3), gen_double(-3, 3), gen_double(-1, 3)};
  };
  const vec4d p = gen_vertex(), q = gen_vertex(), r = gen_vertex(), s = gen_vertex();
  const double cp = gen_double(0, 1), cq = gen_double(0, 1), cr = gen_double(0, 1),
               cs = gen_double(0, 1);
  const auto first = homogeneous_clip_triangle({p, q, r}, {0, cp, 0, cq, 1, cr});
  const auto second = homogeneous_clip_triangle({q, p, s}, {0, cq, 0, cp, 1, cs});
  const auto on_first = vertices_on_shared_edge(first);
  const auto on_second = vertices_on_shared_edge(second);
  RC_CLASSIFY(!on_first.empty(), "shared edge partly visible");
  RC_CLASSIFY(!on_first.empty() && !homogeneous_trivially_accepted(std::vector<vec4d>{p, q}),
              "shared edge clipped");
  // A triangle whose clipped part is a sliver may lose it entirely while its neighbour
  // keeps the shared edge as a boundary: compare only when both keep something.
  if (!first.empty() && !second.empty()) RC_ASSERT(same_bits(on_first, on_second));
}

TEST(HomogeneousClip, SharedEdgeCrossingSeveralPlanesGivesIdenticalVertices) {
  const vec4d p{-3.1, 0.3, 0.2, 1.1}, q{2.7, -0.4, 0.9, 0.7};  // crosses x = -w and x = w
  const vec4d r{0.1, 2.9, -0.3, 1.3}, s{0.2, -2.6, 0.4, 0.9};
  const auto first = homogeneous_clip_triangle({p, q, r}, {0, 0.25, 0, 0.75, 1, 0.5});
  const auto second = homogeneous_clip_triangle({q, p, s}, {0, 0.75, 0, 0.25, 1, 0.125});
  const auto on_first = vertices_on_shared_edge(first);
  ASSERT_EQ(on_first.size(), 2u);
  EXPECT_TRUE(same_bits(on_first, vertices_on_shared_edge(second)));
  for (const auto& v : on_first) EXPECT_EQ(std::abs(v[0]), v[3]);  // exactly on x = ±w
}

TEST(HomogeneousClip, BoundingBoxCornersRejectObjectsBeforeTriangleWork) {
  const mat4 m = frustum_matrix(-1, 1, -1, 1, 1, 10);
  auto clip_corners = [&](const box3& b) {
    std::vector<vec4d> out;
    for (const vec3d& c : box_corners(b)) out.push_back(transform(m, c));
    return out;
  };
  EXPECT_TRUE(homogeneous_trivially_rejected(clip_corners({{-1, -1, 2}, {1, 1, 4}})));  // behind
  EXPECT_TRUE(
      homogeneous_trivially_rejected(clip_corners({{-1, -1, -30}, {1, 1, -20}})));  // beyond far
  EXPECT_TRUE(homogeneous_trivially_rejected(clip_corners({{20, -1, -6}, {30, 1, -4}})));  // right
  EXPECT_FALSE(
      homogeneous_trivially_rejected(clip_corners({{-1, -1, -6}, {1, 1, 2}})));  // straddles
  EXPECT_TRUE(homogeneous_trivially_accepted(clip_corners({{-0.5, -0.5, -6}, {0.5, 0.5, -4}})));
  EXPECT_FALSE(homogeneous_trivially_rejected(std::vector<vec4d>{}));
  EXPECT_FALSE(homogeneous_trivially_accepted(std::vector<vec4d>{}));
}

TEST(HomogeneousClip, PolygonClipAndFanKeepAttributes) {
  homogeneous_polygon quad;
  quad.attribute_count = 1;
  quad.positions = {{-2, -0.5, 0, 1}, {0.5, -0.5, 0, 1}, {0.5, 0.5, 0, 1}, {-2, 0.5, 0, 1}};
  quad.attributes = {0, 1, 2, 3};
  const auto out = homogeneous_clip(quad);
  // x >= -1 cuts edges 0 -> 1 and 2 -> 3; each crossing is interpolated from the
  // lexicographically smaller endpoint (vertex 0, then vertex 3) with t = 1 / 2.5.
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out.positions[0], (vec4d{-1, -0.5, 0, 1}));
  EXPECT_EQ(out.positions[1], quad.positions[1]);
  EXPECT_EQ(out.positions[2], quad.positions[2]);
  EXPECT_EQ(out.positions[3], (vec4d{-1, 0.5, 0, 1}));
  EXPECT_EQ(out.attributes, (std::vector<double>{0.4, 1, 2, 3 - 0.4}));
  const auto fan = fan_triangulate(out);
  ASSERT_EQ(fan.size(), 2u);
  EXPECT_EQ(fan[1].positions[1], out.positions[2]);
  EXPECT_EQ(fan[1].attributes[2], out.attributes[3]);
}

TEST(HomogeneousClip, BadInputThrowsUsageError) {
  const std::array<vec4d, 3> tri{vec4d{0, 0, 0, 1}, vec4d{1, 0, 0, 1}, vec4d{0, 1, 0, 1}};
  EXPECT_THROW(homogeneous_clip_triangle(tri, {1, 2}), exbsp::usage_error);
  EXPECT_THROW(homogeneous_clip_triangle(tri, {1, 2, std::nan("")}), exbsp::usage_error);
  EXPECT_THROW(homogeneous_clip_triangle({vec4d{0, 0, HUGE_VAL, 1}, tri[1], tri[2]}),
               exbsp::usage_error);
  homogeneous_polygon bad;
  bad.attribute_count = 2;
  bad.positions = {tri.begin(), tri.end()};
  bad.attributes = {1, 2, 3};
  EXPECT_THROW(homogeneous_clip(bad), exbsp::usage_error);
  EXPECT_THROW(fan_triangulate(bad), exbsp::usage_error);
  EXPECT_THROW(perspective_divide({1, 1, 1, 0}), exbsp::usage_error);
  EXPECT_THROW(perspective_divide({1, 1, 1, -1}), exbsp::usage_error);
  EXPECT_EQ(perspective_divide({1, 2, 4, 2}), (vec3d{0.5, 1, 2}));
}

// ---------------------------------------------------------------------------------------
// Exact triangle/plane clipping (Epeck and Simple_cartesian<Gmpq>)
//
// Tiling is checked with vector areas: pieces of a planar triangle that keep its
// orientation have cross products (v1 - v0) x (v2 - v0) that sum exactly to the parent's.

namespace {

template <class K>
typename K::Point_3 exact_point(const std::array<double, 3>& p) {
  return typename K::Point_3(p[0], p[1], p[2]);
}

/// A coordinate from a small integer grid (vertices on the plane, coplanar and parallel
/// cases are frequent) or a fine double grid.
std::array<double, 3> gen_exact_coords(bool small) {
  std::array<double, 3> p;
  for (double& v : p) v = small ? uniform_int(-3, 4) : gen_double(-4, 4);
  return p;
}

template <class K>
typename K::Vector_3 cross_of(const exact_triangle<K>& t) {
  return CGAL::cross_product(t.v[1] - t.v[0], t.v[2] - t.v[0]);
}

template <class K>
bool same_triangles(const std::vector<exact_triangle<K>>& a,
                    const std::vector<exact_triangle<K>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j)
      if (a[i].v[j] != b[i].v[j]) return false;
  return true;
}

template <class K>
CGAL::Orientation side(const exact_plane<K>& h, const typename K::Point_3& p) {
  return CGAL::orientation(h.a, h.b, h.c, p);
}

template <class K>
void check_split(const exact_triangle<K>& t, const exact_plane<K>& plane) {
  using Vector = typename K::Vector_3;
  const triangle_plane_side kind = classify_triangle(t, plane);
  const exact_split<K> split = split_triangle(t, plane);
  const Vector n = cross_of(t);

  // Tiling: the vector areas of all pieces sum exactly to the parent's.
  Vector sum = CGAL::NULL_VECTOR;
  for (const auto* list : {&split.positive, &split.negative})
    for (const auto& piece : *list) sum = sum + cross_of(piece);
  RC_ASSERT(sum == n);

  // Sides: kept vertices on the closed positive side, the others on the closed negative.
  for (const auto& piece : split.positive)
    for (const auto& v : piece.v) RC_ASSERT(side(plane, v) != CGAL::NEGATIVE);
  for (const auto& piece : split.negative)
    for (const auto& v : piece.v) RC_ASSERT(side(plane, v) != CGAL::POSITIVE);

  // Orientation: every piece's cross product is a positive multiple of the parent's.
  int zeros = 0;
  for (const auto& v : t.v) zeros += side(plane, v) == CGAL::COPLANAR;
  for (const auto* list : {&split.positive, &split.negative})
    for (const auto& piece : *list) {
      const Vector c = cross_of(piece);
      RC_ASSERT(CGAL::cross_product(c, n) == CGAL::NULL_VECTOR);
      if (n != CGAL::NULL_VECTOR) RC_ASSERT(c * n > 0);
      // New vertices lie on the plane.
      for (const auto& v : piece.v)
        if (v != t.v[0] && v != t.v[1] && v != t.v[2]) RC_ASSERT(side(plane, v) == CGAL::COPLANAR);
    }

  // Piece counts of the section 3 convention.
  const std::vector<exact_triangle<K>> whole{t};
  switch (kind) {
    case triangle_plane_side::coplanar:
    case triangle_plane_side::positive:
      RC_ASSERT(same_triangles(split.positive, whole));
      RC_ASSERT(split.negative.empty());
      break;
    case triangle_plane_side::negative:
      RC_ASSERT(same_triangles(split.negative, whole));
      RC_ASSERT(split.positive.empty());
      break;
    case triangle_plane_side::straddling:
      RC_ASSERT(zeros <= 1);
      if (zeros == 1) {
        RC_ASSERT(split.positive.size() == 1u && split.negative.size() == 1u);
      } else {
        RC_ASSERT(split.positive.size() + split.negative.size() == 3u);
        RC_ASSERT(split.positive.size() >= 1u && split.negative.size() >= 1u);
      }
      break;
  }
  RC_CLASSIFY(kind == triangle_plane_side::straddling && zeros == 0, "split in three");
  RC_CLASSIFY(kind == triangle_plane_side::straddling && zeros == 1, "split at a vertex");
  RC_CLASSIFY(kind != triangle_plane_side::straddling && zeros > 0, "touching");

  // Clipping keeps the positive side; the flipped plane swaps the sides (the same pieces).
  RC_ASSERT(same_triangles(clip_triangle(t, plane), split.positive));
  if (kind != triangle_plane_side::coplanar) {
    const exact_split<K> flipped = split_triangle(t, exact_plane<K>{plane.a, plane.c, plane.b});
    RC_ASSERT(same_triangles(flipped.positive, split.negative));
    RC_ASSERT(same_triangles(flipped.negative, split.positive));
  }
}

template <class K>
void check_random_split() {
  const bool small = *rc::gen::arbitrary<bool>();
  const exact_plane<K> plane{exact_point<K>(gen_exact_coords(small)),
                             exact_point<K>(gen_exact_coords(small)),
                             exact_point<K>(gen_exact_coords(small))};
  RC_PRE(!CGAL::collinear(plane.a, plane.b, plane.c));
  exact_triangle<K> t{{exact_point<K>(gen_exact_coords(small)),
                       exact_point<K>(gen_exact_coords(small)),
                       exact_point<K>(gen_exact_coords(small))}};
  // Sometimes put a vertex exactly on the plane (a point of the plane's own triangle).
  if (uniform_int(0, 4) == 0) t.v[uniform_int(0, 3)] = plane.b;
  check_split(t, plane);
}

/// Inward oriented planes of the faces of box b (positive side = inside).
template <class K>
std::vector<exact_plane<K>> exact_box_planes(const box3& b) {
  std::vector<exact_plane<K>> out;
  for (std::size_t k = 0; k < 3; ++k) {
    std::array<double, 3> e1{0, 0, 0}, e2{0, 0, 0};
    e1[(k + 1) % 3] = 1;
    e2[(k + 2) % 3] = 1;  // e1 x e2 = e_k
    for (int upper = 0; upper < 2; ++upper) {
      std::array<double, 3> a{0, 0, 0};
      a[k] = upper ? b.max[k] : b.min[k];
      std::array<double, 3> p1 = a, p2 = a;
      for (std::size_t j = 0; j < 3; ++j) {
        p1[j] += upper ? e2[j] : e1[j];
        p2[j] += upper ? e1[j] : e2[j];
      }
      out.push_back({exact_point<K>(a), exact_point<K>(p1), exact_point<K>(p2)});
    }
  }
  return out;
}

template <class K>
void check_box_clip() {
  box3 b = gen_box<3>();
  for (std::size_t k = 0; k < 3; ++k) b.max[k] += 0.25;  // keep every face a plane
  std::array<vec3d, 3> tri;
  for (auto& p : tri) p = gen_point(b, 3.0);
  const exact_triangle<K> t{
      {exact_point<K>(tri[0]), exact_point<K>(tri[1]), exact_point<K>(tri[2])}};
  const auto planes = exact_box_planes<K>(b);
  const auto kept = clip_triangle(t, planes);

  // Tiling by replaying the clip one plane at a time and collecting what each plane cuts off.
  typename K::Vector_3 cut_off = CGAL::NULL_VECTOR;
  std::vector<exact_triangle<K>> pieces{t};
  for (const auto& plane : planes) {
    std::vector<exact_triangle<K>> next;
    for (const auto& piece : pieces) {
      const auto split = split_triangle(piece, plane);
      next.insert(next.end(), split.positive.begin(), split.positive.end());
      for (const auto& gone : split.negative) cut_off = cut_off + cross_of(gone);
    }
    pieces = next;
  }
  RC_ASSERT(same_triangles(kept, pieces));
  typename K::Vector_3 kept_sum = CGAL::NULL_VECTOR;
  for (const auto& piece : kept) {
    kept_sum = kept_sum + cross_of(piece);
    for (const auto& v : piece.v)
      for (const auto& plane : planes) RC_ASSERT(side(plane, v) != CGAL::NEGATIVE);
  }
  RC_ASSERT(kept_sum + cut_off == cross_of(t));

  // The double Sutherland–Hodgman clip of the same triangle has the same vector area.
  const vec3d area = vector_area(
      sutherland_hodgman_clip(std::vector<vec3d>(tri.begin(), tri.end()), box_half_spaces(b)));
  for (int k = 0; k < 3; ++k)
    RC_ASSERT(std::abs(CGAL::to_double(kept_sum[k]) / 2 - area[static_cast<std::size_t>(k)]) <=
              1e-9 * 100);
  RC_CLASSIFY(kept.empty(), "nothing kept");
}

}  // namespace

RC_GTEST_PROP(ExactTriangleClip, EpeckPiecesTileTheTriangleOnTheirSides, ()) {
  check_random_split<epeck>();
}
RC_GTEST_PROP(ExactTriangleClip, GmpqPiecesTileTheTriangleOnTheirSides, ()) {
  check_random_split<gmpq_kernel>();
}
RC_GTEST_PROP(ExactTriangleClip, EpeckClipByABoxTilesAndMatchesSutherlandHodgman, ()) {
  check_box_clip<epeck>();
}
RC_GTEST_PROP(ExactTriangleClip, GmpqClipByABoxTilesAndMatchesSutherlandHodgman, ()) {
  check_box_clip<gmpq_kernel>();
}

RC_GTEST_PROP(ExactTriangleClip, PositiveSideIsWhereTheNormalPoints, ()) {
  using K = gmpq_kernel;
  const exact_plane<K> h{exact_point<K>(gen_exact_coords(true)),
                         exact_point<K>(gen_exact_coords(true)),
                         exact_point<K>(gen_exact_coords(true))};
  const K::Point_3 p = exact_point<K>(gen_exact_coords(false));
  const K::Vector_3 u = h.b - h.a, v = h.c - h.a, d = p - h.a;
  const K::FT along = (u.y() * v.z() - u.z() * v.y()) * d.x() +
                      (u.z() * v.x() - u.x() * v.z()) * d.y() +
                      (u.x() * v.y() - u.y() * v.x()) * d.z();
  RC_ASSERT(static_cast<int>(side(h, p)) == CGAL::sign(along));
}

namespace {

template <class K>
exact_triangle<K> tri3(const std::array<double, 3>& a, const std::array<double, 3>& b,
                       const std::array<double, 3>& c) {
  return {{exact_point<K>(a), exact_point<K>(b), exact_point<K>(c)}};
}

template <class K>
void check_section3_convention() {
  const exact_plane<K> z0{exact_point<K>({0, 0, 0}), exact_point<K>({1, 0, 0}),
                          exact_point<K>({0, 1, 0})};
  // No vertex on the plane: c = (0,0,1) alone on the positive side, a = (2,0,-1), b = (0,2,-1).
  for (int rotation = 0; rotation < 3; ++rotation) {
    std::array<std::array<double, 3>, 3> v{{{0, 0, 1}, {2, 0, -1}, {0, 2, -1}}};
    std::rotate(v.begin(), v.begin() + rotation, v.end());
    const auto split = split_triangle(tri3<K>(v[0], v[1], v[2]), z0);
    EXPECT_TRUE(same_triangles(split.negative, {tri3<K>({2, 0, -1}, {0, 2, -1}, {1, 0, 0}),
                                                tri3<K>({0, 2, -1}, {0, 1, 0}, {1, 0, 0})}));
    EXPECT_TRUE(same_triangles(split.positive, {tri3<K>({1, 0, 0}, {0, 1, 0}, {0, 0, 1})}));
  }
  // One vertex on the plane: z = (0,0,0), a = (1,0,1), b = (0,1,-1), X = (1/2, 1/2, 0).
  for (int rotation = 0; rotation < 3; ++rotation) {
    std::array<std::array<double, 3>, 3> v{{{0, 0, 0}, {1, 0, 1}, {0, 1, -1}}};
    std::rotate(v.begin(), v.begin() + rotation, v.end());
    const auto split = split_triangle(tri3<K>(v[0], v[1], v[2]), z0);
    EXPECT_TRUE(same_triangles(split.positive, {tri3<K>({0, 0, 0}, {1, 0, 1}, {0.5, 0.5, 0})}));
    EXPECT_TRUE(same_triangles(split.negative, {tri3<K>({0, 0, 0}, {0.5, 0.5, 0}, {0, 1, -1})}));
  }
  // The other orientation of the same triangle: mirrored pieces, the same convention.
  const auto reversed = split_triangle(tri3<K>({0, 0, 0}, {0, 1, -1}, {1, 0, 1}), z0);
  EXPECT_TRUE(same_triangles(reversed.negative, {tri3<K>({0, 0, 0}, {0, 1, -1}, {0.5, 0.5, 0})}));
  EXPECT_TRUE(same_triangles(reversed.positive, {tri3<K>({0, 0, 0}, {0.5, 0.5, 0}, {1, 0, 1})}));
  // Touching cases go whole to one side; coplanar is kept by clipping.
  const auto edge_on = tri3<K>({0, 0, 0}, {1, 0, 0}, {0, 0, -1});
  EXPECT_EQ(classify_triangle(edge_on, z0), triangle_plane_side::negative);
  EXPECT_TRUE(clip_triangle(edge_on, z0).empty());
  const auto in_plane = tri3<K>({0, 0, 0}, {0, 3, 0}, {2, 0, 0});
  EXPECT_EQ(classify_triangle(in_plane, z0), triangle_plane_side::coplanar);
  EXPECT_TRUE(same_triangles(clip_triangle(in_plane, z0), {in_plane}));
  // Errors.
  const exact_plane<K> line{exact_point<K>({0, 0, 0}), exact_point<K>({1, 1, 1}),
                            exact_point<K>({2, 2, 2})};
  EXPECT_THROW(split_triangle(in_plane, line), exbsp::usage_error);
  EXPECT_THROW(clip_triangle(in_plane, std::vector<exact_plane<K>>{z0, line}), exbsp::usage_error);
  EXPECT_THROW(plane_segment_intersection(z0, exact_point<K>({0, 0, 1}), exact_point<K>({0, 0, 0})),
               exbsp::usage_error);
  EXPECT_EQ(plane_segment_intersection(z0, exact_point<K>({0, 0, 3}), exact_point<K>({3, 0, -1})),
            exact_point<K>({2.25, 0, 0}));
  EXPECT_TRUE(same_triangles(clip_triangle(in_plane, std::vector<exact_plane<K>>{}), {in_plane}));
}

}  // namespace

TEST(ExactTriangleClip, EpeckFollowsTheSection3PieceConvention) {
  check_section3_convention<epeck>();
}
TEST(ExactTriangleClip, GmpqFollowsTheSection3PieceConvention) {
  check_section3_convention<gmpq_kernel>();
}
