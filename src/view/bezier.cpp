// SPDX-License-Identifier: LGPL-3.0-or-later
// Bézier curves: de Casteljau evaluation and subdivision, Bernstein weights, derivative,
// adaptive flattening. Notation as in bezier.h: degree n, control points P_0 .. P_n,
// parameter t in [0, 1], de Casteljau rounds P_i^(k+1) = (1-t) P_i^(k) + t P_{i+1}^(k).
//
// Linear interpolation is always written (1-t) a + t b (not a + t (b - a)): it returns a
// exactly at t = 0 and b exactly at t = 1, which makes B(0) = P_0 and B(1) = P_n exact.
// Bernstein weights are products of doubles kept as mantissa * 2^exponent (frexp), so the
// binomial C(n,i) (which overflows a double for n > 1029) and t^i (which underflows early)
// never leave the representable range before the final ldexp.
#include <exbsp/view/bezier.h>

#include <cmath>
#include <string>

#include <exbsp/core/errors.h>

namespace exbsp {
namespace {

void check_parameter(double t, const char* where) {
  if (!(t >= 0.0 && t <= 1.0))  // also false for NaN
    throw usage_error(std::string(where) + ": parameter t must be in [0, 1], got " +
                      std::to_string(t));
}

bool is_finite(const vec3d& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

vec3d lerp(const vec3d& a, const vec3d& b, double t) {
  const double s = 1.0 - t;
  return {s * a[0] + t * b[0], s * a[1] + t * b[1], s * a[2] + t * b[2]};
}

/// n (b - a).
vec3d scaled_difference(const vec3d& a, const vec3d& b, double n) {
  return {n * (b[0] - a[0]), n * (b[1] - a[1]), n * (b[2] - a[2])};
}

/// In-place de Casteljau: on return q[0] = B(t) of the control points q (non-empty).
vec3d de_casteljau(std::vector<vec3d> q, double t) {
  for (std::size_t k = q.size() - 1; k > 0; --k)
    for (std::size_t i = 0; i < k; ++i) q[i] = lerp(q[i], q[i + 1], t);
  return q[0];
}

/// A non-negative number mantissa * 2^exponent, mantissa in [0.5, 1) or 0.
struct scaled {
  double mantissa;
  long exponent;
};

scaled make_scaled(double x) {
  int e = 0;
  const double m = std::frexp(x, &e);
  return {m, e};
}

scaled multiply(const scaled& a, double x) {
  scaled r = make_scaled(a.mantissa * x);
  r.exponent += a.exponent;
  return r;
}

scaled divide(const scaled& a, double x) {
  scaled r = make_scaled(a.mantissa / x);
  r.exponent += a.exponent;
  return r;
}

/// powers[k] = x^k for k = 0..n, x in (0, 1).
std::vector<scaled> scaled_powers(double x, std::size_t n) {
  std::vector<scaled> powers(n + 1);
  powers[0] = make_scaled(1.0);
  for (std::size_t k = 1; k <= n; ++k) powers[k] = multiply(powers[k - 1], x);
  return powers;
}

/// Distance from p to the segment [a, b] (to a when a == b).
double distance_to_segment(const vec2d& p, const vec2d& a, const vec2d& b) {
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double dx = p[0] - a[0], dy = p[1] - a[1];
  const double length2 = ux * ux + uy * uy;
  double s = 0.0;
  if (length2 > 0.0) {
    s = (dx * ux + dy * uy) / length2;
    s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
  }
  return std::hypot(dx - s * ux, dy - s * uy);
}

}  // namespace

std::vector<double> bernstein_weights(std::size_t n, double t) {
  check_parameter(t, "bernstein_weights");
  std::vector<double> weights(n + 1, 0.0);
  if (t == 0.0) {
    weights[0] = 1.0;
    return weights;
  }
  if (t == 1.0) {
    weights[n] = 1.0;
    return weights;
  }
  // b_i = C(n,i) t^i (1-t)^(n-i) with C(n,i+1) = C(n,i) (n-i) / (i+1); each factor scaled.
  const std::vector<scaled> t_powers = scaled_powers(t, n);
  const std::vector<scaled> s_powers = scaled_powers(1.0 - t, n);
  scaled binomial = make_scaled(1.0);
  for (std::size_t i = 0; i <= n; ++i) {
    if (i > 0) {
      binomial = multiply(binomial, static_cast<double>(n - i + 1));
      binomial = divide(binomial, static_cast<double>(i));
    }
    const scaled& tp = t_powers[i];
    const scaled& sp = s_powers[n - i];
    const double mantissa = binomial.mantissa * tp.mantissa * sp.mantissa;  // in [1/8, 1)
    const long exponent = binomial.exponent + tp.exponent + sp.exponent;
    // ldexp takes an int; anything below -1100 is 0 and nothing here exceeds 1.
    weights[i] = exponent < -1100 ? 0.0 : std::ldexp(mantissa, static_cast<int>(exponent));
  }
  return weights;
}

bezier_curve::bezier_curve(std::vector<vec3d> control_points)
    : control_points_(std::move(control_points)) {
  if (control_points_.empty())
    throw usage_error("bezier_curve: at least one control point is required");
  for (std::size_t i = 0; i < control_points_.size(); ++i)
    if (!is_finite(control_points_[i]))
      throw usage_error("bezier_curve: control point " + std::to_string(i) +
                        " has a non-finite coordinate");
}

bezier_curve::bezier_curve(std::vector<vec3d> control_points, unchecked)
    : control_points_(std::move(control_points)) {}

vec3d bezier_curve::evaluate(double t) const {
  check_parameter(t, "bezier_curve::evaluate");
  return de_casteljau(control_points_, t);
}

vec3d bezier_curve::evaluate_bernstein(double t) const {
  check_parameter(t, "bezier_curve::evaluate_bernstein");
  if (t == 0.0) return control_points_.front();
  if (t == 1.0) return control_points_.back();
  const std::vector<double> w = bernstein_weights(degree(), t);
  vec3d sum{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < w.size(); ++i)
    for (int c = 0; c < 3; ++c) sum[c] += w[i] * control_points_[i][c];
  return sum;
}

bezier_curve bezier_curve::derivative() const {
  const std::size_t n = degree();
  if (n == 0) return bezier_curve({vec3d{0.0, 0.0, 0.0}}, unchecked{});
  std::vector<vec3d> d(n);
  for (std::size_t i = 0; i < n; ++i)
    d[i] = scaled_difference(control_points_[i], control_points_[i + 1], static_cast<double>(n));
  for (const vec3d& p : d)
    if (!is_finite(p))
      throw usage_error("bezier_curve::derivative: a control point difference overflows");
  return bezier_curve(std::move(d), unchecked{});
}

vec3d bezier_curve::derivative_at(double t) const {
  check_parameter(t, "bezier_curve::derivative_at");
  const std::size_t n = degree();
  if (n == 0) return {0.0, 0.0, 0.0};
  std::vector<vec3d> d(n);
  for (std::size_t i = 0; i < n; ++i)
    d[i] = scaled_difference(control_points_[i], control_points_[i + 1], static_cast<double>(n));
  return de_casteljau(std::move(d), t);
}

vec3d bezier_curve::start_tangent() const { return derivative_at(0.0); }

vec3d bezier_curve::end_tangent() const { return derivative_at(1.0); }

std::pair<bezier_curve, bezier_curve> bezier_curve::split(double t) const {
  check_parameter(t, "bezier_curve::split");
  const std::size_t n = degree();
  std::vector<vec3d> q = control_points_;
  std::vector<vec3d> first(n + 1), second(n + 1);
  first[0] = q[0];
  second[n] = q[n];
  // After round k, q[i] = P_i^(k) for i = 0..n-k: first[k] = P_0^(k), second[n-k] = P_{n-k}^(k).
  for (std::size_t k = 1; k <= n; ++k) {
    for (std::size_t i = 0; i + k <= n; ++i) q[i] = lerp(q[i], q[i + 1], t);
    first[k] = q[0];
    second[n - k] = q[n - k];
  }
  return {bezier_curve(std::move(first), unchecked{}),
          bezier_curve(std::move(second), unchecked{})};
}

flattened_curve flatten(const bezier_curve& curve, const projection_2d& project, double tolerance,
                        const flatten_options& options) {
  if (!project) throw usage_error("flatten: the projection is empty");
  if (!(std::isfinite(tolerance) && tolerance > 0.0))
    throw usage_error("flatten: tolerance must be finite and > 0, got " +
                      std::to_string(tolerance));
  if (options.max_depth < 0 || options.max_depth > 60)
    throw usage_error("flatten: max_depth must be in [0, 60], got " +
                      std::to_string(options.max_depth));

  flattened_curve out;
  out.points.push_back(curve.evaluate(0.0));
  out.parameters.push_back(0.0);
  if (curve.degree() == 0) return out;

  struct piece {
    bezier_curve curve;
    double t0, t1;
    int depth;
  };
  std::vector<piece> stack;
  stack.push_back({curve, 0.0, 1.0, 0});
  std::vector<vec2d> projected;
  while (!stack.empty()) {
    piece p = std::move(stack.back());
    stack.pop_back();

    const std::vector<vec3d>& cp = p.curve.control_points();
    projected.resize(cp.size());
    std::size_t non_finite = 0;
    for (std::size_t i = 0; i < cp.size(); ++i) {
      projected[i] = project(cp[i]);
      if (!(std::isfinite(projected[i][0]) && std::isfinite(projected[i][1]))) ++non_finite;
    }
    bool flat = false;
    if (non_finite == 0) {
      flat = true;
      for (std::size_t i = 1; i + 1 < cp.size() && flat; ++i)
        flat = distance_to_segment(projected[i], projected.front(), projected.back()) <= tolerance;
    }
    const bool give_up = p.depth >= options.max_depth || non_finite == cp.size();
    if (flat || give_up) {
      if (!flat) ++out.forced_chords;
      out.points.push_back(curve.evaluate(p.t1));
      out.parameters.push_back(p.t1);
      continue;
    }
    // Halve; the midpoint parameter is a dyadic rational, exact in double for depth <= 60.
    const double tm = 0.5 * (p.t0 + p.t1);
    auto halves = p.curve.split(0.5);
    stack.push_back({std::move(halves.second), tm, p.t1, p.depth + 1});  // later
    stack.push_back({std::move(halves.first), p.t0, tm, p.depth + 1});   // next
  }
  return out;
}

}  // namespace exbsp
