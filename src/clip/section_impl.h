// SPDX-License-Identifier: LGPL-3.0-or-later
// Private: what the section algorithm (section.cpp, in the LGPL core) shares with the cap
// builder (section_cap.cpp, in the GPL component exbsp::gpl, because it uses CGAL's GPL
// constrained Delaunay triangulation; docs/licence.md). Notation as in section.h and
// section.cpp. Not installed.
//
// The core runs the whole section and calls the cap builder, when it is given one, on the
// outline of a closed input; the builder may add points (Steiner points, lifted to the plane)
// and reports the outline edges it subdivided, which the core then refines in the kept
// triangles and the outline. section_detail::section and ::clip_soup are exported from the
// shared core library on purpose (EXBSP_EXPORT) so that the shared GPL library can call them;
// their signatures use CGAL types, so both libraries must come from the same build.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include <exbsp/clip/section.h>
#include <exbsp/core/export.h>
#include "geom/cut_plane.h"

namespace exbsp::section_detail {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using point3 = K::Point_3;
using point2 = K::Point_2;
constexpr std::uint32_t no_point = std::numeric_limits<std::uint32_t>::max();

struct tri {
  std::array<std::uint32_t, 3> v;
  std::uint32_t face;
};

/// Points (with the input double where a point is an input vertex) and triangles.
struct exact_mesh {
  std::vector<point3> pts;
  std::vector<vec3d> input;  ///< the input double, NaN for constructed points
  std::vector<tri> tris;
  std::uint32_t add(const point3& p, const vec3d& d) {
    pts.push_back(p);
    input.push_back(d);
    return static_cast<std::uint32_t>(pts.size() - 1);
  }
};

inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(a) << 32) | b;
}

/// The plane with exact coefficients and its dominant axis.
struct cut_plane {
  section_plane d;
  K::Plane_3 p;
  int axis;  ///< index of the largest |n_k|
  explicit cut_plane(const section_plane& c) : d(c), p(c[0], c[1], c[2], c[3]) {
    axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(c[k]) > std::fabs(c[axis])) axis = k;
  }
  int side(const point3& q) const {
    return geom::cut_plane_traits<K>().oriented_side_3_object()(p, q);
  }
  point2 project(const point3& q) const { return {q[(axis + 1) % 3], q[(axis + 2) % 3]}; }
  /// The point of the plane above the 2D point (inverse of project).
  point3 lift(const point2& q) const {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const K::FT n[3] = {p.a(), p.b(), p.c()};
    K::FT c[3];
    c[i] = q.x();
    c[j] = q.y();
    c[axis] = -(p.d() + n[i] * c[i] + n[j] * c[j]) / n[axis];
    return {c[0], c[1], c[2]};
  }
};

struct directed_edge {
  std::uint32_t from, to;
};

/// Interior points of the outline edges the triangulation subdivided: key (lo, hi) -> the
/// points strictly between, ordered from lo to hi.
using subdivision = std::unordered_map<std::uint64_t, std::vector<std::uint32_t>>;

/// Builds the cap of a closed input from its outline (see section_cap.cpp): triangles with
/// face id `cap_face`; new points are appended to m, subdivided outline edges reported in
/// `split`, cap_steiner_points and split_constraints counted in `stats`.
using cap_builder = std::vector<tri> (*)(exact_mesh& m, const cut_plane& plane,
                                         const std::vector<directed_edge>& outline,
                                         std::uint32_t cap_face, section_stats& stats,
                                         subdivision& split);

/// exbsp::section with an optional cap builder (nullptr: no cap).
EXBSP_EXPORT section_result section(const triangle_soup& soup, const section_plane& plane,
                                    const section_options& options, cap_builder build_cap);

/// exbsp::clip_soup with an optional cap builder (nullptr: no caps, face_count unchanged).
EXBSP_EXPORT triangle_soup clip_soup(const triangle_soup& soup,
                                     const std::vector<section_plane>& planes,
                                     cap_builder build_cap);

}  // namespace exbsp::section_detail
