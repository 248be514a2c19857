// SPDX-License-Identifier: LGPL-3.0-or-later
// Convex regions as half-spaces (notation in convex_region.h). The convexity test comes from
// CGAL (is_convex_2 with exact predicates) rather than hand code; the 3D convex hull is in
// convex_hull.cpp (the GPL component: CGAL's convex_hull_3 is GPL-3.0-or-later).
#include <exbsp/clip/convex_region.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "clip/clip_checks.h"

namespace exbsp::clip {

namespace {
using kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
}

std::vector<half_plane2> convex_polygon_half_planes(const std::vector<vec2d>& polygon) {
  const char* function = "convex_polygon_half_planes";
  for (const vec2d& p : polygon) detail::require_finite(p, function, "polygon vertex");
  // Drop repeated consecutive vertices (cyclically): they give no edge.
  std::vector<kernel::Point_2> pts;
  for (const vec2d& p : polygon) {
    const kernel::Point_2 q(p[0], p[1]);
    if (pts.empty() || pts.back() != q) pts.push_back(q);
  }
  while (pts.size() > 1 && pts.back() == pts.front()) pts.pop_back();
  if (pts.size() < 3)
    throw usage_error(std::string(function) +
                      ": a convex polygon needs at least 3 distinct vertices");
  const CGAL::Orientation o = CGAL::orientation_2(pts.begin(), pts.end(), kernel());
  if (o == CGAL::COLLINEAR)
    throw usage_error(std::string(function) + ": the polygon has zero area");
  if (!CGAL::is_convex_2(pts.begin(), pts.end(), kernel()))
    throw usage_error(std::string(function) + ": the polygon is not convex");
  // is_convex_2 accepts polygons that wind around more than once; the turning total rules them out.
  double turning = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& a = pts[i];
    const auto& b = pts[(i + 1) % pts.size()];
    const auto& c = pts[(i + 2) % pts.size()];
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = c.x() - b.x(), vy = c.y() - b.y();
    turning += std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  }
  if (std::fabs(turning) > 2 * M_PI + 1e-6)
    throw usage_error(std::string(function) + ": the polygon winds more than once");
  const double sign = o == CGAL::COUNTERCLOCKWISE ? 1.0 : -1.0;
  std::vector<half_plane2> out;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    const auto& q = pts[(i + 1) % pts.size()];
    // f(x) = (q - p) x (x - p) = -(qy - py) x + (qx - px) y + (qy - py) px - (qx - px) py.
    const double a = -(q.y() - p.y()), b = q.x() - p.x();
    out.push_back({sign * a, sign * b, sign * (-(a * p.x() + b * p.y()))});
  }
  return out;
}

std::vector<half_space3> convex_polyhedron_half_spaces(
    const std::vector<std::vector<vec3d>>& faces) {
  const char* function = "convex_polyhedron_half_spaces";
  vec3d centroid{0, 0, 0};
  std::size_t count = 0;
  double size = 0;
  for (const auto& face : faces) {
    if (face.size() < 3)
      throw usage_error(std::string(function) + ": a face needs at least 3 vertices");
    for (const vec3d& p : face) {
      detail::require_finite(p, function, "face vertex");
      for (int k = 0; k < 3; ++k) {
        centroid[k] += p[k];
        size = std::max(size, std::fabs(p[k]));
      }
      ++count;
    }
  }
  if (faces.size() < 4)
    throw usage_error(std::string(function) + ": a polyhedron needs at least 4 faces");
  for (double& c : centroid) c /= static_cast<double>(count);
  std::vector<half_space3> out;
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const auto& face = faces[fi];
    vec3d n{0, 0, 0};
    for (std::size_t i = 0, j = face.size() - 1; i < face.size(); j = i++) {
      const vec3d& a = face[j];
      const vec3d& b = face[i];
      n[0] += (a[1] - b[1]) * (a[2] + b[2]);
      n[1] += (a[2] - b[2]) * (a[0] + b[0]);
      n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    if (n == vec3d{0, 0, 0})
      throw usage_error(std::string(function) + ": face " + std::to_string(fi) + " has zero area");
    half_space3 h{n, -(n[0] * face[0][0] + n[1] * face[0][1] + n[2] * face[0][2])};
    if (h.value(centroid) < 0) h = {{-n[0], -n[1], -n[2]}, -h.d};
    out.push_back(h);
  }
  for (std::size_t fi = 0; fi < out.size(); ++fi) {
    const double scale = std::sqrt(out[fi].n[0] * out[fi].n[0] + out[fi].n[1] * out[fi].n[1] +
                                   out[fi].n[2] * out[fi].n[2]);
    for (const auto& face : faces)
      for (const vec3d& p : face)
        if (out[fi].value(p) < -1e-9 * scale * std::max(size, 1.0))
          throw usage_error(std::string(function) +
                            ": the polyhedron is not convex (a vertex lies outside face " +
                            std::to_string(fi) + ")");
  }
  return out;
}

}  // namespace exbsp::clip
