// SPDX-License-Identifier: LGPL-3.0-or-later
// Sutherland–Hodgman polygon clipping against a convex region given as half-spaces.
//
// Notation: a 2D half-plane is {a*x + b*y + c >= 0}; a 3D half-space is {n·p + d >= 0};
// f(p) is that left-hand side. The region is the intersection of the (closed) half-spaces.
// The polygon is clipped against one half-space after the other; for each edge s -> e
// (from the last vertex to the first included) the clipper emits: e when f(e) >= 0, and
// before it the crossing point when f(s) and f(e) have strictly opposite signs. A vertex
// with f = 0 is kept as it is (no crossing point is computed next to it).
//
// Floating point: a crossing point is computed from the edge's endpoints in lexicographic
// order (so an edge shared by two polygons gives the same point whichever way it is
// walked), each coordinate kept within the range of the two endpoints. For an axis-aligned
// half-space (exactly one nonzero normal component n_k) the point's coordinate k is set to
// -d / n_k, so a box or window boundary is hit exactly.
//
// The result is exact for convex input polygons (the clipped part, in the input's order and
// orientation); a concave input can produce degenerate connecting edges along a boundary.
//
// Concave input (the textbook's known defect): when a concave polygon leaves and re-enters a
// half-space, the single output polygon walks along the boundary line between the pieces, so
// the result is one polygon whose "connecting edges" run twice over the same stretch of the
// line (zero area, but drawn as a spurious edge and wrong for anything that needs a simple
// polygon). sutherland_hodgman_pieces() keeps the textbook's crossing points and vertex order
// but splits the result into its pieces: per half-space, the output is cut into chains (maximal
// runs of vertices with f >= 0, from an entry point on the line to an exit point), the chain
// ends are sorted along the boundary line in the direction t = n_h x N (N: the input's normal
// by Newell's formula; t runs along the line with the kept side on the left when seen from N,
// the direction in which a piece's boundary follows the line), and the k-th exit is joined to
// the k-th entry. For a simple input this gives exactly the connected pieces of the clipped
// region, each a simple polygon with the input's orientation; a chain that touches the line
// without area (all its points on the line) is dropped. A self-intersecting input is handled
// the same way, but then the pieces are only as meaningful as the input.
#pragma once
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// Closed half-plane a*x + b*y + c >= 0.
struct half_plane2 {
  double a, b, c;
  double value(const vec2d& p) const { return a * p[0] + b * p[1] + c; }
};

/// Closed half-space n·p + d >= 0.
struct half_space3 {
  vec3d n;
  double d;
  double value(const vec3d& p) const { return n[0] * p[0] + n[1] * p[1] + n[2] * p[2] + d; }
};

/// The part of `polygon` inside every half-plane of `region` (their intersection, which is
/// convex), in the input's vertex order. An empty region list returns the polygon unchanged;
/// a result with fewer than 3 vertices (nothing, a point or a segment) is returned empty, as
/// is an input with fewer than 3 vertices. Throws usage_error on NaN/infinite input.
EXBSP_EXPORT std::vector<vec2d> sutherland_hodgman_clip(const std::vector<vec2d>& polygon,
                                                        const std::vector<half_plane2>& region);
/// 3D version: a planar polygon clipped by half-spaces; same guarantees and errors.
EXBSP_EXPORT std::vector<vec3d> sutherland_hodgman_clip(const std::vector<vec3d>& polygon,
                                                        const std::vector<half_space3>& region);

/// sutherland_hodgman_clip split into pieces (see the file comment): each piece is a polygon
/// of at least 3 vertices; a convex input gives at most one piece, equal to
/// sutherland_hodgman_clip's result. Throws usage_error on NaN/infinite input.
EXBSP_EXPORT std::vector<std::vector<vec2d>> sutherland_hodgman_pieces(
    const std::vector<vec2d>& polygon, const std::vector<half_plane2>& region);
/// 3D version for a planar polygon; same guarantees and errors.
EXBSP_EXPORT std::vector<std::vector<vec3d>> sutherland_hodgman_pieces(
    const std::vector<vec3d>& polygon, const std::vector<half_space3>& region);

/// The four half-planes of the closed window: x >= xmin, x <= xmax, y >= ymin, y <= ymax
/// (in that order). Throws usage_error on NaN/infinite bounds or min > max.
EXBSP_EXPORT std::vector<half_plane2> window_half_planes(const window2& window);
/// The six half-spaces of the closed box: x >= min, x <= max, then y, then z.
/// Throws usage_error on NaN/infinite bounds or min > max.
EXBSP_EXPORT std::vector<half_space3> box_half_spaces(const box3& box);
/// The six half-spaces of a glFrustum view volume in eye coordinates (eye at the origin,
/// looking down -z): left, right, bottom, top, near (z <= -near), far (z >= -far).
/// Throws usage_error unless left < right, bottom < top, 0 < near < far, all finite.
EXBSP_EXPORT std::vector<half_space3> frustum_half_spaces(double left, double right, double bottom,
                                                          double top, double near, double far);
/// The six half-spaces of a glOrtho view volume in eye coordinates: the box
/// [left, right] x [bottom, top] x [-far, -near]. Throws usage_error unless left < right,
/// bottom < top, near < far, all finite.
EXBSP_EXPORT std::vector<half_space3> orthographic_half_spaces(double left, double right,
                                                               double bottom, double top,
                                                               double near, double far);

}  // namespace exbsp::clip
