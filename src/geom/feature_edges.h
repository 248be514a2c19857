// SPDX-License-Identifier: LGPL-3.0-or-later
// Feature edges of a triangle soup for one viewer (docs/contract.md section 6): the edges a
// line drawing shows, used by the hidden-line drawing and by sections.
//
// Notation: vertices are welded by exact position (weld.h); an edge is a pair of welded
// vertices used by one or more triangles. The viewer is a homogeneous point E (homogeneous_det.h):
// the eye (w = 1) of a perspective view, or the direction towards the viewer (w = 0) of a
// parallel one. Triangle t = (a, b, c) with normal n = (b - a) x (c - a) FACES the viewer when E
// lies strictly on n's side of its plane: orientation(a, b, c, E) > 0 (for w = 0: n . E > 0),
// decided exactly. An edge is a feature edge when it is
//   - a boundary edge (one triangle),
//   - non-manifold (three or more triangles),
//   - a crease: its two faces' normals make an angle over crease_deg (in double: a user's
//     threshold, not a predicate), or
//   - a silhouette: one of its two triangles faces the viewer and the other does not.
// Two triangles of one source face (a fan diagonal) never make a feature edge; degenerate
// triangles (no plane) are left out.
#pragma once
#include <cstdint>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>
#include "geom/homogeneous_det.h"

namespace exbsp::geom {

/// Why an edge is drawn.
enum class feature_kind : std::uint8_t { boundary, non_manifold, crease, silhouette };

struct feature_edge {
  std::uint32_t a = 0, b = 0;       ///< soup vertex indices (as the first triangle has them)
  std::uint32_t tris[2] = {0, 0};   ///< its first two triangles (tris[1] == tris[0]: boundary)
  std::uint32_t faces[2] = {0, 0};  ///< their source face ids
  feature_kind kind = feature_kind::boundary;
};

/// The feature edges of a soup for one viewer, and what an occlusion test needs per triangle.
struct view_features {
  std::vector<feature_edge> edges;  ///< in order of their welded vertex pairs
  /// Per triangle: 1 facing the viewer, -1 facing away, 0 seen edge-on or degenerate.
  std::vector<std::int8_t> facing;
  /// Per triangle: bit k set when its side (v[k], v[k+1 mod 3]) is a feature edge.
  std::vector<std::uint8_t> feature_sides;
};

/// Exact facing of triangle (a, b, c) for viewer E (notation): 1, -1 or 0.
EXBSP_EXPORT int facing(const vec3d& a, const vec3d& b, const vec3d& c, const hpoint& viewer);

/// facing(), the same result, cheaper: the determinant in double with a bound on its rounding,
/// and facing() only when the bound does not decide the sign. Call it with the rounding mode to
/// nearest (outside a rounding_guard).
EXBSP_EXPORT int facing_filtered(const vec3d& a, const vec3d& b, const vec3d& c,
                                 const hpoint& viewer);

/// What of the feature edges does not depend on the viewer: the soup's edges with the
/// triangles around each, and whether each is drawn in every view (boundary, non-manifold,
/// crease) or only where it is a silhouette. Made once per soup and crease angle
/// (edge_graph_of), read for each viewer by find_feature_edges.
struct edge_graph {
  /// A triangle side: triangle `tri`'s side (v[side], v[side + 1 mod 3]).
  struct half {
    std::uint32_t tri, side;
  };
  /// An edge that may be drawn: its halves are halves[first, end).
  struct edge {
    std::uint32_t first = 0, end = 0;
    std::uint32_t a = 0, b = 0;      ///< soup vertex indices (as the first triangle has them)
    std::uint32_t tris[2] = {0, 0};  ///< its first two triangles of distinct faces
    feature_kind kind = feature_kind::boundary;  ///< silhouette: drawn only as one
  };
  double crease_deg = 0;
  std::vector<std::uint8_t> degenerate;  ///< per triangle: no plane (never facing, no sides)
  std::vector<half> halves;
  std::vector<edge> edges;  ///< in order of their welded vertex pairs (fan diagonals left out)
};

/// The edge graph of `soup`. Precondition: 0 < crease_deg <= 180.
EXBSP_EXPORT edge_graph edge_graph_of(const triangle_soup& soup, double crease_deg);

/// The feature edges of `soup` for `viewer`, from its edge graph.
EXBSP_EXPORT view_features find_feature_edges(const edge_graph& graph, const triangle_soup& soup,
                                              const hpoint& viewer);

/// The feature edges of `soup` for `viewer`. Precondition: 0 < crease_deg <= 180.
EXBSP_EXPORT view_features find_feature_edges(const triangle_soup& soup, const hpoint& viewer,
                                              double crease_deg);

}  // namespace exbsp::geom
