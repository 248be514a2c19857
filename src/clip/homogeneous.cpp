// SPDX-License-Identifier: LGPL-3.0-or-later
// Homogeneous clipping (see homogeneous.h for the plane order and outcode bits).
// Plane j (0..5) is w + x, w - x, w + y, w - y, w + z, w - z >= 0: axis j / 2, and the
// coordinate enters with sign + for even j, - for odd j. `in`/`out` are the polygons before
// and after one plane; `f` holds the plane values of `in`'s vertices.
#include <exbsp/clip/homogeneous.h>

#include <cmath>
#include <string>
#include <utility>

#include "clip/clip_checks.h"

namespace exbsp::clip {
namespace {

double plane_value(const vec4d& p, std::size_t plane) {
  const std::size_t axis = plane / 2;
  return (plane % 2) ? p[3] - p[axis] : p[3] + p[axis];
}

unsigned outcode_and(const vec4d* points, std::size_t n) {
  if (n == 0) return 0;
  unsigned code = ~0u;
  for (std::size_t i = 0; i < n; ++i) code &= homogeneous_outcode(points[i]);
  return code;
}

unsigned outcode_or(const vec4d* points, std::size_t n) {
  unsigned code = 0;
  for (std::size_t i = 0; i < n; ++i) code |= homogeneous_outcode(points[i]);
  return code;
}

void validate_sizes(const homogeneous_polygon& poly, const char* function) {
  if (poly.attributes.size() != poly.positions.size() * poly.attribute_count)
    throw usage_error(std::string(function) + ": " + std::to_string(poly.attributes.size()) +
                      " attributes for " + std::to_string(poly.positions.size()) +
                      " vertices with " + std::to_string(poly.attribute_count) + " each");
}

void validate(const homogeneous_polygon& poly, const char* function) {
  validate_sizes(poly, function);
  for (const vec4d& p : poly.positions) detail::require_finite(p, function, "vertex");
  for (double a : poly.attributes)
    if (!std::isfinite(a)) throw usage_error(std::string(function) + ": NaN or infinite attribute");
}

/// Appends to `out` the crossing of edge (s, e) of `in` with `plane`, f[s] and f[e] having
/// strictly opposite signs; interpolated from the lexicographically smaller endpoint.
void push_crossing(const homogeneous_polygon& in, std::size_t s, std::size_t e, double fs,
                   double fe, std::size_t plane, homogeneous_polygon& out) {
  const bool swap = in.positions[e] < in.positions[s];
  const std::size_t lo = swap ? e : s, hi = swap ? s : e;
  const double f_lo = swap ? fe : fs, f_hi = swap ? fs : fe;
  const double t = f_lo / (f_lo - f_hi);  // in [0, 1]: |f_lo - f_hi| >= |f_lo|
  const vec4d& a = in.positions[lo];
  const vec4d& b = in.positions[hi];
  vec4d x;
  for (std::size_t k = 0; k < 4; ++k) x[k] = detail::lerp_within(a[k], b[k], t);
  const std::size_t axis = plane / 2;
  x[axis] = (plane % 2) ? x[3] : -x[3];  // exactly on the plane
  out.positions.push_back(x);
  const double* attr_a = in.attributes_of(lo);
  const double* attr_b = in.attributes_of(hi);
  for (std::size_t j = 0; j < in.attribute_count; ++j)
    out.attributes.push_back(detail::lerp_within(attr_a[j], attr_b[j], t));
}

void push_vertex(const homogeneous_polygon& in, std::size_t i, homogeneous_polygon& out) {
  out.positions.push_back(in.positions[i]);
  const double* attr = in.attributes_of(i);
  out.attributes.insert(out.attributes.end(), attr, attr + in.attribute_count);
}

homogeneous_polygon clip_validated(const homogeneous_polygon& polygon) {
  homogeneous_polygon empty;
  empty.attribute_count = polygon.attribute_count;
  const std::size_t n0 = polygon.size();
  if (n0 < 3) return empty;
  if (outcode_or(polygon.positions.data(), n0) == 0) return polygon;
  if (outcode_and(polygon.positions.data(), n0) != 0) return empty;

  homogeneous_polygon in = polygon, out = empty;
  std::vector<double> f;
  for (std::size_t plane = 0; plane < 6; ++plane) {
    const std::size_t n = in.size();
    f.resize(n);
    bool all_inside = true;
    for (std::size_t i = 0; i < n; ++i) {
      f[i] = plane_value(in.positions[i], plane);
      all_inside = all_inside && f[i] >= 0.0;
    }
    if (all_inside) continue;
    out.positions.clear();
    out.attributes.clear();
    std::size_t s = n - 1;
    for (std::size_t e = 0; e < n; s = e, ++e) {
      if ((f[s] > 0.0 && f[e] < 0.0) || (f[s] < 0.0 && f[e] > 0.0))
        push_crossing(in, s, e, f[s], f[e], plane, out);
      if (f[e] >= 0.0) push_vertex(in, e, out);
    }
    if (out.size() < 3) return empty;
    std::swap(in, out);
  }
  return in;
}

}  // namespace

unsigned homogeneous_outcode(const vec4d& p) {
  unsigned code = 0;
  for (std::size_t plane = 0; plane < 6; ++plane)
    if (plane_value(p, plane) < 0.0) code |= 1u << plane;
  return code;
}

bool homogeneous_trivially_accepted(const std::vector<vec4d>& points) {
  return !points.empty() && outcode_or(points.data(), points.size()) == 0;
}
bool homogeneous_trivially_rejected(const std::vector<vec4d>& points) {
  return outcode_and(points.data(), points.size()) != 0;
}
bool homogeneous_trivially_accepted(const std::array<vec4d, 3>& t) {
  return outcode_or(t.data(), 3) == 0;
}
bool homogeneous_trivially_rejected(const std::array<vec4d, 3>& t) {
  return outcode_and(t.data(), 3) != 0;
}

homogeneous_polygon homogeneous_clip(const homogeneous_polygon& polygon) {
  validate(polygon, "homogeneous_clip");
  return clip_validated(polygon);
}

homogeneous_polygon homogeneous_clip_triangle(const std::array<vec4d, 3>& p,
                                              const std::vector<double>& attributes) {
  if (attributes.size() % 3 != 0)
    throw usage_error("homogeneous_clip_triangle: " + std::to_string(attributes.size()) +
                      " attributes is not a multiple of 3 vertices");
  homogeneous_polygon tri;
  tri.attribute_count = attributes.size() / 3;
  tri.positions.assign(p.begin(), p.end());
  tri.attributes = attributes;
  validate(tri, "homogeneous_clip_triangle");
  return clip_validated(tri);
}

std::vector<homogeneous_polygon> fan_triangulate(const homogeneous_polygon& polygon) {
  validate_sizes(polygon, "fan_triangulate");
  std::vector<homogeneous_polygon> out;
  for (const auto& t : fan_triangle_indices(polygon.size())) {
    homogeneous_polygon tri;
    tri.attribute_count = polygon.attribute_count;
    for (std::size_t i : t) push_vertex(polygon, i, tri);
    out.push_back(std::move(tri));
  }
  return out;
}

vec3d perspective_divide(const vec4d& p) {
  if (!(p[3] > 0.0))
    throw usage_error("perspective_divide: w must be > 0 (got " + std::to_string(p[3]) + ")");
  return {p[0] / p[3], p[1] / p[3], p[2] / p[3]};
}

}  // namespace exbsp::clip
