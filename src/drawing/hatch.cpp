// SPDX-License-Identifier: LGPL-3.0-or-later
// Section hatching (notation in hatch.h). Written here rather than with Clipper's line
// clipping because the lines are known in closed form: a sweep over each line's crossings is
// a few lines and keeps every segment's endpoints on the rings' edges in double precision
// (Clipper would round them to its integer grid).
#include "drawing/hatch.h"

#include <algorithm>
#include <cmath>

namespace exbsp::drawing {

namespace {

constexpr double inv_sqrt2 = 0.70710678118654752440;

double across(const point2& p) { return (p.y - p.x) * inv_sqrt2; }
double along(const point2& p) { return (p.x + p.y) * inv_sqrt2; }

/// The point at (along t, across u).
point2 at(double t, double u) { return {(t - u) * inv_sqrt2, (t + u) * inv_sqrt2}; }

double signed_area(const std::vector<point2>& r) {
  double a = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const point2& p = r[i];
    const point2& q = r[(i + 1) % n];
    a += p.x * q.y - q.x * p.y;
  }
  return a / 2;
}

/// Crossing parity of the horizontal ray from p to +x with ring r (half-open rule).
bool inside_ring(const point2& p, const std::vector<point2>& r) {
  bool in = false;
  for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    const point2& a = r[i];
    const point2& b = r[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

}  // namespace

std::vector<hatch_segment> hatch_lines(const std::vector<std::vector<point2>>& rings,
                                       double spacing) {
  std::vector<hatch_segment> out;
  if (!(spacing > 0)) return out;
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& r : rings)
    for (const point2& p : r) {
      lo = std::min(lo, across(p));
      hi = std::max(hi, across(p));
    }
  if (!(lo <= hi)) return out;
  std::vector<double> ts;
  for (double k = std::ceil(lo / spacing); k * spacing <= hi; k += 1) {
    const double u = k * spacing;
    ts.clear();
    for (const auto& r : rings)
      for (std::size_t i = 0, n = r.size(); i < n; ++i) {
        const point2& p = r[i];
        const point2& q = r[(i + 1) % n];
        const double up = across(p), uq = across(q);
        if ((up > u) == (uq > u)) continue;  // both above, or both on/below
        const double s = (u - up) / (uq - up);
        ts.push_back(along(p) + s * (along(q) - along(p)));
      }
    std::sort(ts.begin(), ts.end());
    for (std::size_t i = 0; i + 1 < ts.size(); i += 2)
      if (ts[i + 1] > ts[i]) out.push_back({at(ts[i], u), at(ts[i + 1], u)});
  }
  return out;
}

double even_odd_area(const std::vector<std::vector<point2>>& rings) {
  double total = 0;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (rings[i].size() < 3) continue;
    int depth = 0;  // how many other rings hold this one (a vertex of it stands for it)
    for (std::size_t j = 0; j < rings.size(); ++j)
      if (j != i && rings[j].size() >= 3 && inside_ring(rings[i][0], rings[j])) ++depth;
    const double a = std::fabs(signed_area(rings[i]));
    total += depth % 2 == 0 ? a : -a;
  }
  return total;
}

}  // namespace exbsp::drawing
