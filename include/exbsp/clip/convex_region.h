// SPDX-License-Identifier: LGPL-3.0-or-later
// Convex regions as half-spaces, for Sutherland–Hodgman (sutherland_hodgman.h).
//
// Notation: a 2D half-plane is {a*x + b*y + c >= 0} and a 3D half-space {n·p + d >= 0}, the
// normal pointing INTO the region; the region is the intersection of the closed half-spaces.
// A convex polygon (either orientation) gives one half-plane per edge of nonzero length: for
// a counter-clockwise edge p -> q, f(x) = (q - p) x (x - p) (the 2D cross product), negated for
// a clockwise polygon. A convex polyhedron given as a point set gives one half-space per face
// of its convex hull (CGAL::convex_hull_3, convex_hull.h in the GPL component exbsp::gpl;
// coplanar hull triangles give repeated planes); given
// as faces, one per face, its normal by Newell's formula oriented towards the centroid of all
// vertices. Convexity and orientation are decided with exact predicates (CGAL Epick) on the
// double input; the coefficients are rounded doubles (a point exactly on a face may evaluate a
// few ulps negative).
#pragma once
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/clip/sutherland_hodgman.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// The half-planes of a convex polygon (the region it bounds, boundary included). Collinear
/// and repeated vertices are allowed. Throws usage_error for NaN/infinite input, fewer than 3
/// vertices, zero area, or a polygon that is not convex (a reflex vertex or a self-crossing).
EXBSP_EXPORT std::vector<half_plane2> convex_polygon_half_planes(const std::vector<vec2d>& polygon);

/// The half-spaces of a convex polyhedron given by its faces (each a planar polygon of at least
/// 3 vertices, any orientation). Throws usage_error for NaN/infinite input, a degenerate face,
/// or a polyhedron that is not convex (a vertex strictly outside some face's half-space, by
/// more than a relative 1e-9 of the coordinates' size).
EXBSP_EXPORT std::vector<half_space3> convex_polyhedron_half_spaces(
    const std::vector<std::vector<vec3d>>& faces);

}  // namespace exbsp::clip
