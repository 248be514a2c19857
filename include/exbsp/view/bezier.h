// SPDX-License-Identifier: LGPL-3.0-or-later
// Bézier curves of any degree in 3D (double), for the "curves" of a scene (docs/contract.md
// "Scenes").
//
// Notation: a curve of degree n has the n + 1 control points P_0 .. P_n and is
//   B(t) = sum_{i=0..n} b_{i,n}(t) P_i,   b_{i,n}(t) = C(n,i) t^i (1-t)^(n-i),   t in [0, 1].
// The b_{i,n} are the Bernstein polynomials: non-negative on [0, 1] and summing to 1, so B(t)
// lies in the convex hull of the control points, B(0) = P_0 and B(1) = P_n.
// De Casteljau's algorithm evaluates B(t) by n rounds of linear interpolation
//   P_i^(k+1) = (1-t) P_i^(k) + t P_{i+1}^(k),   B(t) = P_0^(n);
// the triangle of intermediate points also gives the two halves of the curve split at t.
// The derivative B'(t) is the Bézier curve of degree n-1 with control points n (P_{i+1} - P_i).
//
// Every operation here is iterative (no recursion) and works for any degree (n = 300 and far
// beyond: the Bernstein weights are computed without forming C(n,i), so nothing overflows).
// Precondition failures throw exbsp::usage_error (include/exbsp/core/errors.h); nothing aborts.
#pragma once
#include <array>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>
#include <exbsp/core/export.h>
#include <exbsp/core/vec.h>

namespace exbsp {

// vec2d (e.g. a point in pixels) and vec3d: <exbsp/core/vec.h>.

/// The n + 1 Bernstein weights b_{0,n}(t) .. b_{n,n}(t): each >= 0, summing to 1 (up to
/// rounding). Computed as scaled products (a separate binary exponent is carried), so neither
/// C(n,i) nor t^i overflow or underflow prematurely; tiny weights may round to 0. Relative
/// error about 3 n ulp (binomial and power recurrences).
/// Exact at the ends: t = 0 gives (1, 0, .., 0), t = 1 gives (0, .., 0, 1).
/// Throws usage_error unless t is finite and in [0, 1].
EXBSP_EXPORT std::vector<double> bernstein_weights(std::size_t n, double t);

/// A Bézier curve of degree n >= 0 given by n + 1 finite control points.
/// A degree-0 curve (one control point) is valid: it is that point for every t.
class EXBSP_EXPORT bezier_curve {
 public:
  /// Throws usage_error when `control_points` is empty or a coordinate is NaN or infinite.
  explicit bezier_curve(std::vector<vec3d> control_points);

  /// n = number of control points - 1.
  std::size_t degree() const { return control_points_.size() - 1; }
  /// P_0 .. P_n.
  const std::vector<vec3d>& control_points() const { return control_points_; }

  /// B(t) by de Casteljau's algorithm: O(n^2) operations, numerically stable.
  /// B(0) == P_0 and B(1) == P_n exactly. Throws usage_error unless t is finite and in [0, 1].
  vec3d evaluate(double t) const;
  /// B(t) as sum b_{i,n}(t) P_i with bernstein_weights(n, t): O(n) operations, for comparison.
  /// Throws usage_error unless t is finite and in [0, 1].
  vec3d evaluate_bernstein(double t) const;

  /// The derivative curve B' (degree n - 1, control points n (P_{i+1} - P_i)).
  /// For a degree-0 curve: the degree-0 curve at the origin (B' = 0).
  /// Throws usage_error if a difference overflows to infinity (coordinates near DBL_MAX).
  bezier_curve derivative() const;
  /// B'(t) (the unnormalised tangent vector), by de Casteljau on n (P_{i+1} - P_i).
  /// Zero for a degree-0 curve. May be infinite when coordinates are near DBL_MAX.
  /// Throws usage_error unless t is finite and in [0, 1].
  vec3d derivative_at(double t) const;
  /// B'(0) = n (P_1 - P_0), exactly as derivative_at(0); zero for degree 0. It may be zero
  /// (P_1 == P_0) although the curve has a direction there (a higher derivative gives it).
  vec3d start_tangent() const;
  /// B'(1) = n (P_n - P_{n-1}), exactly as derivative_at(1); zero for degree 0.
  vec3d end_tangent() const;

  /// Splits at t with de Casteljau's triangle into `first` on [0, t] and `second` on [t, 1],
  /// each reparametrised to [0, 1]: first(s) = B(t s), second(s) = B(t + (1 - t) s).
  /// Both have degree n; first's last control point equals second's first one.
  /// t = 0 or t = 1 is allowed (one half is then a degenerate curve at an end point).
  /// Throws usage_error unless t is finite and in [0, 1].
  std::pair<bezier_curve, bezier_curve> split(double t) const;

 private:
  struct unchecked {};
  bezier_curve(std::vector<vec3d> control_points, unchecked);
  std::vector<vec3d> control_points_;
};

/// Maps a 3D point to the 2D plane in which the flattening tolerance is measured (e.g. pixels).
using projection_2d = std::function<vec2d(const vec3d&)>;

/// Limits of flatten().
struct flatten_options {
  /// A piece of the curve that is still not flat after this many halvings is emitted as one
  /// chord anyway (so degenerate input terminates): at most 2^max_depth chords. Must be in
  /// [0, 60].
  int max_depth = 16;
};

/// A polyline approximating a curve: points[k] = B(parameters[k]), parameters increasing from
/// 0 to 1 (one point only for a degree-0 curve).
struct flattened_curve {
  std::vector<vec3d> points;
  std::vector<double> parameters;
  /// Chords emitted because max_depth was reached (or the projection returned non-finite
  /// values) rather than because they were within tolerance. 0 means the guarantee holds.
  std::size_t forced_chords = 0;
};

/// Adaptive flattening of `curve` to a polyline that, after `project`, is within
/// `tolerance` of the projected curve. The curve is halved (de Casteljau at t = 1/2, with an
/// explicit stack) until a piece is flat: every projected control point of the piece lies
/// within `tolerance` of the projected chord (segment from its first to its last control
/// point). Points are evaluated on the original curve, so B(0) and B(1) are exact.
///
/// The guarantee (every projected curve point within `tolerance` of the projected polyline)
/// holds when the projected piece lies in the convex hull of its projected control points:
/// for affine projections, and for perspective projections (x/w, y/w) when w > 0 at every
/// control point (the projected curve is then a rational Bézier curve with positive weights).
/// For other projections the test is a good heuristic. If `project` returns a non-finite value
/// the piece is subdivided further (to isolate the bad part), then emitted; a piece whose
/// projected control points are all non-finite is emitted as one chord at once.
///
/// Throws usage_error when `project` is empty, `tolerance` is not finite and > 0, or
/// options.max_depth is out of range. Exceptions thrown by `project` propagate.
flattened_curve flatten(const bezier_curve& curve, const projection_2d& project, double tolerance,
                        const flatten_options& options = {});

}  // namespace exbsp
