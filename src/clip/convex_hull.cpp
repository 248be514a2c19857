// SPDX-License-Identifier: GPL-3.0-or-later
// The half-spaces of the convex hull of a 3D point set (notation in convex_region.h), by
// CGAL's convex_hull_3 into a Surface_mesh. Both CGAL packages are GPL-3.0-or-later, so this
// file is the GPL component exbsp::gpl (libexbsp_gpl; docs/licence.md).
#include <exbsp/clip/convex_hull.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <string>

#include <exbsp/core/errors.h>
#include "clip/clip_checks.h"

namespace exbsp::clip {

namespace {
using kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
}

std::vector<half_space3> convex_hull_half_spaces(const std::vector<vec3d>& points) {
  const char* function = "convex_hull_half_spaces";
  std::vector<kernel::Point_3> pts;
  for (const vec3d& p : points) {
    detail::require_finite(p, function, "point");
    pts.emplace_back(p[0], p[1], p[2]);
  }
  if (pts.size() < 4)
    throw usage_error(std::string(function) + ": a polyhedron needs at least 4 points");
  // The hull is 3D iff some four points are not coplanar.
  bool solid = false;
  {
    std::size_t i = 1;
    while (i < pts.size() && pts[i] == pts[0]) ++i;
    std::size_t j = i + 1;
    while (j < pts.size() && CGAL::collinear(pts[0], pts[i], pts[j])) ++j;
    for (std::size_t k = j + 1; k < pts.size() && !solid; ++k)
      solid = CGAL::orientation(pts[0], pts[i], pts[j], pts[k]) != CGAL::COPLANAR;
  }
  if (!solid)
    throw usage_error(std::string(function) + ": the points do not span a solid (all coplanar)");
  CGAL::Surface_mesh<kernel::Point_3> hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  std::vector<half_space3> out;
  for (const auto f : hull.faces()) {
    std::vector<kernel::Point_3> v;
    for (const auto vd : CGAL::vertices_around_face(hull.halfedge(f), hull))
      v.push_back(hull.point(vd));
    // Faces are counter-clockwise seen from outside: (b - a) x (c - a) points out.
    const kernel::Vector_3 n = -CGAL::cross_product(v[1] - v[0], v[2] - v[0]);
    out.push_back(
        {{n.x(), n.y(), n.z()}, -(n.x() * v[0].x() + n.y() * v[0].y() + n.z() * v[0].z())});
  }
  return out;
}

}  // namespace exbsp::clip
