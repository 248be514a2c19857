// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of include/exbsp/view/bezier.h: Bernstein weights, de Casteljau evaluation, convex hull,
// end-point interpolation, subdivision, derivative, adaptive flattening, precondition errors.
// Notation: degree n, control points P_0 .. P_n, B(t) the curve, t in [0, 1].
// Random coordinates are integers / 1000 in [-1000, 1000]; error bounds are relative to the
// largest control point coordinate ("scale").
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/view/bezier.h>
#include "support/test_helpers.h"

namespace {

using exbsp::bezier_curve;
using exbsp::vec2d;
using exbsp::vec3d;

using exbsp_test::cross;
using exbsp_test::dist;
using exbsp_test::dot;
using exbsp_test::sub;

[[maybe_unused]] const bool fixed_seed = exbsp_test::fixed_rc_seed();

bool finite(const vec3d& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

double scale_of(const std::vector<vec3d>& pts) {
  double m = 1.0;
  for (const vec3d& p : pts)
    for (double c : p) m = std::max(m, std::fabs(c));
  return m;
}

// --- generators (called inside properties) ---
double random_coordinate(int range = 1000) {
  return *rc::gen::inRange(-range * 1000, range * 1000 + 1) / 1000.0;
}
vec3d random_point() { return {random_coordinate(), random_coordinate(), random_coordinate()}; }
std::vector<vec3d> random_control_points(std::size_t min_degree, std::size_t max_degree) {
  const auto n = *rc::gen::inRange<std::size_t>(min_degree, max_degree + 1);
  std::vector<vec3d> pts;
  for (std::size_t i = 0; i <= n; ++i) pts.push_back(random_point());
  return pts;
}
/// t in [0, 1] with 0 and 1 themselves likely.
double random_parameter() {
  return *rc::gen::oneOf(
      rc::gen::just(0.0), rc::gen::just(1.0),
      rc::gen::map(rc::gen::inRange(0, (1 << 30) + 1), [](int k) { return k / double(1 << 30); }));
}

// --- Bernstein weights ---

RC_GTEST_PROP(BezierBernstein, WeightsAreNonNegativeAndSumToOne, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 400);
  const double t = random_parameter();
  const std::vector<double> w = exbsp::bernstein_weights(n, t);
  RC_ASSERT(w.size() == n + 1);
  double sum = 0.0;
  for (double x : w) {
    RC_ASSERT(std::isfinite(x));
    RC_ASSERT(x >= 0.0);
    sum += x;
  }
  RC_ASSERT(std::fabs(sum - 1.0) <= 1e-12);
}

TEST(BezierBernstein, WeightsMatchBinomialFormulaForSmallDegree) {
  const int binomial[] = {1, 5, 10, 10, 5, 1};
  for (double t : {0.1, 0.25, 0.5, 0.7, 0.999}) {
    const std::vector<double> w = exbsp::bernstein_weights(5, t);
    for (int i = 0; i <= 5; ++i) {
      const double expected = binomial[i] * std::pow(t, i) * std::pow(1.0 - t, 5 - i);
      EXPECT_NEAR(w[i], expected, 1e-15) << "i=" << i << " t=" << t;
    }
  }
}

TEST(BezierBernstein, WeightsAreExactUnitVectorsAtEnds) {
  const std::vector<double> w0 = exbsp::bernstein_weights(7, 0.0);
  const std::vector<double> w1 = exbsp::bernstein_weights(7, 1.0);
  for (int i = 0; i <= 7; ++i) {
    EXPECT_EQ(w0[i], i == 0 ? 1.0 : 0.0);
    EXPECT_EQ(w1[i], i == 7 ? 1.0 : 0.0);
  }
}

TEST(BezierBernstein, HugeDegreeWeightsStayFiniteWhereBinomialOverflows) {
  // C(5000, 2500) ~ 1e1503 overflows a double; the weights must not.
  for (double t : {1e-9, 0.3, 0.5, 0.999999}) {
    const std::vector<double> w = exbsp::bernstein_weights(5000, t);
    double sum = 0.0;
    for (double x : w) {
      ASSERT_TRUE(std::isfinite(x));
      ASSERT_GE(x, 0.0);
      sum += x;
    }
    EXPECT_NEAR(sum, 1.0, 1e-11) << "t=" << t;
  }
}

TEST(BezierBernstein, ParameterOutsideUnitIntervalThrowsUsageError) {
  EXPECT_THROW(exbsp::bernstein_weights(3, -0.1), exbsp::usage_error);
  EXPECT_THROW(exbsp::bernstein_weights(3, 1.5), exbsp::usage_error);
  EXPECT_THROW(exbsp::bernstein_weights(3, std::nan("")), exbsp::usage_error);
}

// --- convex hull, end points, de Casteljau vs Bernstein ---

RC_GTEST_PROP(BezierConvexHull, CurvePointIsConvexCombinationWithBernsteinWeights, ()) {
  const bezier_curve c(random_control_points(0, 40));
  const double t = random_parameter();
  const std::vector<double> w = exbsp::bernstein_weights(c.degree(), t);
  double sum = 0.0;
  vec3d combination{0, 0, 0};
  for (std::size_t i = 0; i < w.size(); ++i) {
    RC_ASSERT(w[i] >= 0.0);
    sum += w[i];
    for (int k = 0; k < 3; ++k) combination[k] += w[i] * c.control_points()[i][k];
  }
  RC_ASSERT(std::fabs(sum - 1.0) <= 1e-12);
  RC_ASSERT(dist(c.evaluate(t), combination) <= 1e-12 * scale_of(c.control_points()));
}

RC_GTEST_PROP(BezierConvexHull, CurvePointIsInsideEverySupportingPlaneOfControlPoints, ()) {
  // Brute force for n = 3, 4: every plane through three control points with all the other
  // control points on one side supports the hull; the curve point must be on that side too.
  const bezier_curve c(random_control_points(3, 4));
  const std::vector<vec3d>& p = c.control_points();
  const double scale = scale_of(p);
  const vec3d point = c.evaluate(random_parameter());
  std::size_t planes = 0;
  for (std::size_t a = 0; a < p.size(); ++a)
    for (std::size_t b = a + 1; b < p.size(); ++b)
      for (std::size_t d = b + 1; d < p.size(); ++d) {
        const vec3d normal = cross(sub(p[b], p[a]), sub(p[d], p[a]));
        const double normal_length = std::sqrt(dot(normal, normal));
        if (normal_length <= 1e-9 * scale * scale) continue;  // (nearly) collinear triple
        const double slack = 1e-12 * normal_length * scale;
        bool all_below = true, all_above = true;
        for (const vec3d& q : p) {
          const double side = dot(normal, sub(q, p[a]));
          all_below = all_below && side <= slack;
          all_above = all_above && side >= -slack;
        }
        const double side = dot(normal, sub(point, p[a]));
        if (all_below) {
          ++planes;
          RC_ASSERT(side <= 8 * slack);
        }
        if (all_above) {
          ++planes;
          RC_ASSERT(side >= -8 * slack);
        }
      }
  RC_TAG(planes >= 4 ? "hull with >= 4 faces" : "degenerate hull");
}

RC_GTEST_PROP(BezierEndPoints, CurveInterpolatesFirstAndLastControlPointExactly, ()) {
  const bezier_curve c(random_control_points(0, 60));
  const vec3d first = c.control_points().front(), last = c.control_points().back();
  RC_ASSERT(c.evaluate(0.0) == first);
  RC_ASSERT(c.evaluate(1.0) == last);
  RC_ASSERT(c.evaluate_bernstein(0.0) == first);
  RC_ASSERT(c.evaluate_bernstein(1.0) == last);
}

RC_GTEST_PROP(BezierEvaluation, DeCasteljauAgreesWithBernsteinFormUpToDegree30, ()) {
  const bezier_curve c(random_control_points(0, 30));
  const double t = random_parameter();
  const vec3d a = c.evaluate(t), b = c.evaluate_bernstein(t);
  RC_ASSERT(dist(a, b) <= 1e-12 * scale_of(c.control_points()));
}

TEST(BezierEvaluation, Degree300BothFormsFiniteAndAgree) {
  std::vector<vec3d> pts;
  for (int i = 0; i <= 300; ++i)
    pts.push_back({std::cos(0.37 * i) * 1000.0, std::sin(0.11 * i) * 500.0, (i % 7) - 3.0});
  const bezier_curve c(pts);
  for (int k = 0; k <= 64; ++k) {
    const double t = k / 64.0;
    const vec3d a = c.evaluate(t), b = c.evaluate_bernstein(t);
    ASSERT_TRUE(finite(a)) << "t=" << t;
    ASSERT_TRUE(finite(b)) << "t=" << t;
    EXPECT_LE(dist(a, b), 1e-10 * 1000.0) << "t=" << t;
  }
}

TEST(BezierEvaluation, Degree3000BernsteinFormFinite) {
  std::vector<vec3d> pts;
  for (int i = 0; i <= 3000; ++i) pts.push_back({double(i % 11), double(i % 5), 1.0});
  const bezier_curve c(pts);
  for (double t : {0.0, 1e-6, 0.25, 0.5, 0.75, 1.0}) {
    const vec3d b = c.evaluate_bernstein(t);
    ASSERT_TRUE(finite(b));
    EXPECT_NEAR(b[2], 1.0, 1e-11);  // weights sum to 1
  }
}

TEST(BezierEvaluation, StraightLineControlPolygonGivesLinearCurve) {
  // Evenly spaced collinear control points: B(t) = P_0 + t (P_n - P_0) (linear precision).
  std::vector<vec3d> pts;
  for (int i = 0; i <= 6; ++i) pts.push_back({double(i), 2.0 * i, -3.0 * i});
  const bezier_curve c(pts);
  for (int k = 0; k <= 10; ++k) {
    const double t = k / 10.0;
    const vec3d p = c.evaluate(t);
    EXPECT_NEAR(p[0], 6.0 * t, 1e-14);
    EXPECT_NEAR(p[1], 12.0 * t, 1e-14);
    EXPECT_NEAR(p[2], -18.0 * t, 1e-14);
  }
}

// --- subdivision ---

RC_GTEST_PROP(BezierSplit, HalvesReproduceTheCurve, ()) {
  const bezier_curve c(random_control_points(0, 20));
  const double t = random_parameter();
  const auto halves = c.split(t);
  RC_ASSERT(halves.first.degree() == c.degree());
  RC_ASSERT(halves.second.degree() == c.degree());
  RC_ASSERT(halves.first.control_points().back() == halves.second.control_points().front());
  RC_ASSERT(halves.first.control_points().front() == c.control_points().front());
  RC_ASSERT(halves.second.control_points().back() == c.control_points().back());
  const double tolerance = 1e-12 * scale_of(c.control_points());
  for (int k = 0; k <= 16; ++k) {
    const double s = k / 16.0;
    RC_ASSERT(dist(halves.first.evaluate(s), c.evaluate(t * s)) <= tolerance);
    RC_ASSERT(dist(halves.second.evaluate(s), c.evaluate(t + (1.0 - t) * s)) <= tolerance);
  }
}

TEST(BezierSplit, SplitAtEndsGivesDegenerateHalfAndTheCurveItself) {
  const bezier_curve c({{0, 0, 0}, {1, 2, 0}, {3, -1, 2}, {4, 0, 1}});
  const auto at0 = c.split(0.0);
  for (const vec3d& p : at0.first.control_points()) EXPECT_EQ(p, c.control_points().front());
  EXPECT_EQ(at0.second.control_points(), c.control_points());
  const auto at1 = c.split(1.0);
  EXPECT_EQ(at1.first.control_points(), c.control_points());
  for (const vec3d& p : at1.second.control_points()) EXPECT_EQ(p, c.control_points().back());
}

TEST(BezierSplit, ParameterOutsideUnitIntervalThrowsUsageError) {
  const bezier_curve c({{0, 0, 0}, {1, 1, 1}});
  EXPECT_THROW(c.split(-1e-300), exbsp::usage_error);
  EXPECT_THROW(c.split(1.0000001), exbsp::usage_error);
  EXPECT_THROW(c.split(std::numeric_limits<double>::infinity()), exbsp::usage_error);
}

// --- derivative ---

RC_GTEST_PROP(BezierDerivative, MatchesCentralFiniteDifferences, ()) {
  const bezier_curve c(random_control_points(0, 8));
  const double n = double(c.degree());
  const double scale = scale_of(c.control_points());
  const double t = *rc::gen::inRange(1, 1000) / 1000.0;  // interior, so t +- h stays in [0, 1]
  const double h = 1e-4;
  const vec3d plus = c.evaluate(t + h), minus = c.evaluate(t - h);
  const vec3d difference{(plus[0] - minus[0]) / (2 * h), (plus[1] - minus[1]) / (2 * h),
                         (plus[2] - minus[2]) / (2 * h)};
  // Truncation h^2/6 |B'''| with |B'''| <= n^3 * 8 * scale; rounding ~ n eps scale / h.
  const double tolerance = h * h / 6.0 * n * n * n * 8.0 * scale + 1e-10 * scale;
  RC_ASSERT(dist(c.derivative_at(t), difference) <= tolerance);
  RC_ASSERT(dist(c.derivative().evaluate(t), c.derivative_at(t)) <= 1e-12 * (n + 1) * scale);
}

RC_GTEST_PROP(BezierDerivative, EndTangentsAreDegreeTimesFirstAndLastLeg, ()) {
  const bezier_curve c(random_control_points(1, 30));
  const std::vector<vec3d>& p = c.control_points();
  const double n = double(c.degree());
  const std::size_t last = p.size() - 1;
  const vec3d start{n * (p[1][0] - p[0][0]), n * (p[1][1] - p[0][1]), n * (p[1][2] - p[0][2])};
  const vec3d end{n * (p[last][0] - p[last - 1][0]), n * (p[last][1] - p[last - 1][1]),
                  n * (p[last][2] - p[last - 1][2])};
  RC_ASSERT(c.start_tangent() == start);
  RC_ASSERT(c.end_tangent() == end);
  RC_ASSERT(c.derivative_at(0.0) == start);
  RC_ASSERT(c.derivative_at(1.0) == end);
  const bezier_curve d = c.derivative();
  RC_ASSERT(d.degree() == c.degree() - 1);
  RC_ASSERT(d.evaluate(0.0) == start);
  RC_ASSERT(d.evaluate(1.0) == end);
}

TEST(BezierDerivative, DegreeZeroCurveHasZeroDerivative) {
  const bezier_curve c({{1, 2, 3}});
  EXPECT_EQ(c.derivative().degree(), 0u);
  EXPECT_EQ(c.derivative().control_points().front(), (vec3d{0, 0, 0}));
  EXPECT_EQ(c.derivative_at(0.5), (vec3d{0, 0, 0}));
  EXPECT_EQ(c.start_tangent(), (vec3d{0, 0, 0}));
  EXPECT_EQ(c.end_tangent(), (vec3d{0, 0, 0}));
}

TEST(BezierDerivative, OverflowingDifferenceThrowsUsageError) {
  const double big = std::numeric_limits<double>::max();
  const bezier_curve c({{-big, 0, 0}, {big, 0, 0}});
  EXPECT_THROW(c.derivative(), exbsp::usage_error);
  EXPECT_FALSE(finite(c.derivative_at(0.5)));  // documented: may be infinite, no throw
}

// --- preconditions and the degree-0 curve ---

TEST(BezierPreconditions, NoControlPointsThrowsUsageError) {
  EXPECT_THROW(bezier_curve(std::vector<vec3d>{}), exbsp::usage_error);
}

TEST(BezierPreconditions, NonFiniteCoordinateThrowsUsageError) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(bezier_curve({{0, 0, 0}, {std::nan(""), 0, 0}}), exbsp::usage_error);
  EXPECT_THROW(bezier_curve({{0, inf, 0}}), exbsp::usage_error);
  EXPECT_THROW(bezier_curve({{0, 0, 0}, {1, 1, 1}, {0, 0, -inf}}), exbsp::usage_error);
}

TEST(BezierPreconditions, EvaluationOutsideUnitIntervalThrowsUsageError) {
  const bezier_curve c({{0, 0, 0}, {1, 1, 1}});
  EXPECT_THROW(c.evaluate(-0.5), exbsp::usage_error);
  EXPECT_THROW(c.evaluate(std::nan("")), exbsp::usage_error);
  EXPECT_THROW(c.evaluate_bernstein(2.0), exbsp::usage_error);
  EXPECT_THROW(c.derivative_at(-1.0), exbsp::usage_error);
}

TEST(BezierPreconditions, DegreeZeroCurveIsAPoint) {
  const vec3d p{4, -5, 6};
  const bezier_curve c({p});
  EXPECT_EQ(c.degree(), 0u);
  for (double t : {0.0, 0.3, 1.0}) {
    EXPECT_EQ(c.evaluate(t), p);
    EXPECT_EQ(c.evaluate_bernstein(t), p);
  }
  const auto halves = c.split(0.4);
  EXPECT_EQ(halves.first.control_points(), std::vector<vec3d>{p});
  EXPECT_EQ(halves.second.control_points(), std::vector<vec3d>{p});
  const auto flat = exbsp::flatten(
      c,
      [](const vec3d& q) {
        return vec2d{q[0], q[1]};
      },
      0.5);
  ASSERT_EQ(flat.points.size(), 1u);
  EXPECT_EQ(flat.points[0], p);
  EXPECT_EQ(flat.parameters, std::vector<double>{0.0});
}

// --- flattening ---

double distance_to_segment_2d(const vec2d& p, const vec2d& a, const vec2d& b) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], dx = p[0] - a[0], dy = p[1] - a[1];
  const double l2 = ux * ux + uy * uy;
  double s = l2 > 0 ? (dx * ux + dy * uy) / l2 : 0.0;
  s = std::min(1.0, std::max(0.0, s));
  return std::hypot(dx - s * ux, dy - s * uy);
}

/// Checks the structure of a flattening and that 4000 curve points, each against the chord of
/// its parameter interval (stronger than against the whole polyline), are within tolerance.
void check_flattening(const bezier_curve& c, const exbsp::projection_2d& project, double tolerance,
                      double projected_scale) {
  const exbsp::flattened_curve f = exbsp::flatten(c, project, tolerance);
  RC_ASSERT(f.forced_chords == 0u);
  RC_ASSERT(f.points.size() == f.parameters.size());
  RC_ASSERT(f.points.size() >= 2u);
  RC_ASSERT(f.parameters.front() == 0.0);
  RC_ASSERT(f.parameters.back() == 1.0);
  RC_ASSERT(f.points.front() == c.control_points().front());
  RC_ASSERT(f.points.back() == c.control_points().back());
  for (std::size_t k = 1; k < f.parameters.size(); ++k)
    RC_ASSERT(f.parameters[k] > f.parameters[k - 1]);
  for (std::size_t k = 0; k < f.points.size(); ++k)
    RC_ASSERT(f.points[k] == c.evaluate(f.parameters[k]));
  std::vector<vec2d> projected;
  for (const vec3d& p : f.points) projected.push_back(project(p));
  const int samples = 4000;
  double worst = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double t = double(i) / samples;
    const auto it = std::upper_bound(f.parameters.begin(), f.parameters.end(), t);
    std::size_t k = std::size_t(it - f.parameters.begin());
    k = std::min(std::max<std::size_t>(k, 1), f.parameters.size() - 1);
    const double d = distance_to_segment_2d(project(c.evaluate(t)), projected[k - 1], projected[k]);
    worst = std::max(worst, d);
    RC_ASSERT(d <= tolerance + 1e-9 * projected_scale);
  }
  RC_TAG(worst > 0.5 * tolerance ? "tight" : "loose");
}

RC_GTEST_PROP(BezierFlatten, PolylineWithinToleranceUnderAffineProjection, ()) {
  const bezier_curve c(random_control_points(1, 7));
  double m[6];
  for (double& x : m) x = *rc::gen::inRange(-2000, 2001) / 1000.0;
  const exbsp::projection_2d project = [m](const vec3d& p) {
    return vec2d{m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + 320.0,
                 m[3] * p[0] + m[4] * p[1] + m[5] * p[2] + 240.0};
  };
  const double tolerance = *rc::gen::inRange(5, 501) / 100.0;  // 0.05 .. 5 px
  check_flattening(c, project, tolerance, 6.0 * scale_of(c.control_points()));
}

RC_GTEST_PROP(BezierFlatten, PolylineWithinToleranceUnderPerspectiveProjectionInFront, ()) {
  // Eye at the origin looking down -z; all control points at z in [-100, -1] (w = -z > 0).
  const auto n = *rc::gen::inRange<std::size_t>(1, 7);
  std::vector<vec3d> pts;
  for (std::size_t i = 0; i <= n; ++i)
    pts.push_back({random_coordinate(100), random_coordinate(100),
                   -*rc::gen::inRange(1000, 100001) / 1000.0});
  const bezier_curve c(pts);
  const exbsp::projection_2d project = [](const vec3d& p) {
    return vec2d{320.0 + 500.0 * p[0] / -p[2], 240.0 - 500.0 * p[1] / -p[2]};
  };
  const double tolerance = *rc::gen::inRange(5, 501) / 100.0;
  check_flattening(c, project, tolerance, 5e4);
}

TEST(BezierFlatten, LineIsOneChord) {
  const bezier_curve c({{0, 0, 0}, {10, 5, 3}});
  const auto f = exbsp::flatten(
      c,
      [](const vec3d& p) {
        return vec2d{p[0], p[1]};
      },
      0.1);
  EXPECT_EQ(f.parameters, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(f.forced_chords, 0u);
}

TEST(BezierFlatten, TerminatesOnCoincidentControlPoints) {
  const bezier_curve c(std::vector<vec3d>(12, vec3d{1, 1, 1}));
  const auto f = exbsp::flatten(
      c,
      [](const vec3d& p) {
        return vec2d{p[0], p[1]};
      },
      1e-300);
  EXPECT_EQ(f.parameters, (std::vector<double>{0.0, 1.0}));
}

TEST(BezierFlatten, CurveAlongTheViewDirectionIsOneChord) {
  const bezier_curve c({{0, 0, 0}, {0, 0, 5}, {0, 0, -3}, {0, 0, 9}});
  const auto f = exbsp::flatten(
      c,
      [](const vec3d& p) {
        return vec2d{p[0], p[1]};
      },
      0.25);
  EXPECT_EQ(f.points.size(), 2u);
}

TEST(BezierFlatten, TerminatesWhenProjectionReturnsNaN) {
  const bezier_curve c({{0, 0, 0}, {1, 3, 0}, {2, -3, 0}, {3, 0, 0}});
  const double nan = std::nan("");
  const auto all_nan = exbsp::flatten(
      c,
      [nan](const vec3d&) {
        return vec2d{nan, nan};
      },
      0.5);
  EXPECT_EQ(all_nan.points.size(), 2u);
  EXPECT_EQ(all_nan.forced_chords, 1u);
  // NaN only at x > 2.9: the bad part is isolated by subdivision, up to max_depth.
  exbsp::flatten_options options;
  options.max_depth = 10;
  const auto some_nan = exbsp::flatten(
      c,
      [nan](const vec3d& p) {
        return p[0] > 2.9 ? vec2d{nan, nan} : vec2d{p[0], p[1]};
      },
      0.5, options);
  EXPECT_GT(some_nan.forced_chords, 0u);
  EXPECT_LE(some_nan.points.size(), (1u << 10) + 1u);
  EXPECT_EQ(some_nan.parameters.back(), 1.0);
}

TEST(BezierFlatten, MaxDepthBoundsWorkOnHugeCurveAtTinyTolerance) {
  const bezier_curve c({{0, 0, 0}, {1e12, 1e12, 0}, {-1e12, 1e12, 0}, {1, 0, 0}});
  exbsp::flatten_options options;
  options.max_depth = 8;
  const auto f = exbsp::flatten(
      c,
      [](const vec3d& p) {
        return vec2d{p[0], p[1]};
      },
      1e-6, options);
  EXPECT_EQ(f.points.size(), 257u);
  EXPECT_EQ(f.forced_chords, 256u);
}

TEST(BezierFlatten, InvalidArgumentsThrowUsageError) {
  const bezier_curve c({{0, 0, 0}, {1, 1, 1}});
  const exbsp::projection_2d xy = [](const vec3d& p) { return vec2d{p[0], p[1]}; };
  EXPECT_THROW(exbsp::flatten(c, exbsp::projection_2d{}, 1.0), exbsp::usage_error);
  EXPECT_THROW(exbsp::flatten(c, xy, 0.0), exbsp::usage_error);
  EXPECT_THROW(exbsp::flatten(c, xy, -1.0), exbsp::usage_error);
  EXPECT_THROW(exbsp::flatten(c, xy, std::nan("")), exbsp::usage_error);
  EXPECT_THROW(exbsp::flatten(c, xy, std::numeric_limits<double>::infinity()), exbsp::usage_error);
  exbsp::flatten_options bad;
  bad.max_depth = -1;
  EXPECT_THROW(exbsp::flatten(c, xy, 1.0, bad), exbsp::usage_error);
  bad.max_depth = 61;
  EXPECT_THROW(exbsp::flatten(c, xy, 1.0, bad), exbsp::usage_error);
}

}  // namespace
