// SPDX-License-Identifier: LGPL-3.0-or-later
// Walking a built BSP tree (exbsp::bsp::traverse_from_eye / traverse_for_direction): its nodes
// (plane, coplanar fragments, children) and its cells, in the painter's order, so that other
// primitives (curves, lines, points) can be split and ordered against the node planes exactly.
//
// Notation (docs/contract.md "The BSP"): node N has the plane of the input triangle (a, b, c) =
// N.plane; h_N(p) = orientation(a, b, c, p), positive on the side n = (b - a) x (c - a)
// points to. Each side of N holds a subtree or nothing; an empty side is a CELL: the convex
// region (open or closed at its walls) cut out by the half-spaces on the path from the root,
// which no fragment enters. Every point of space lies in exactly one cell or on a node plane
// of its path. For an eye e, s = sign h_N(e) (a direction of projection d: s = sign n . (-d));
// the NEAR side of N is the positive one when s >= 0, the negative one when s < 0.
// Back to front, N is visited as: enter(N), the far side (subtree or cell), fragments(N),
// the near side. The fragments() calls give exactly bsp::order_from_eye / order_for_direction.
// Front to back is the exact reverse: the fragments() and cell() calls come in reverse order
// (take a node's fragments last to first then); enter(N) still comes before N's sides.
#pragma once
#include <array>
#include <cstdint>

#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>

namespace exbsp {

/// A node of a built tree as the traversal shows it.
struct bsp_node {
  std::uint32_t index = 0;       ///< node id: 0 is the root, a child comes after its parent
  std::uint32_t plane_face = 0;  ///< the input triangle (index in soup.triangles) whose plane it is
  std::array<vec3d, 3> plane{};  ///< that triangle's vertices (the exact input doubles): (a, b, c)
  /// Its coplanar fragments: bsp::fragment(first_fragment + k), k < fragment_count, back to front.
  std::uint32_t first_fragment = 0, fragment_count = 0;
  std::int32_t negative = -1, positive = -1;  ///< child node ids; -1: an empty cell on that side
  std::int32_t parent = -1;                   ///< -1 for the root
  int side_in_parent = 0;  ///< the side (+1 / -1) of the parent it lies on; root: 0
};

/// Exact sign (+1, 0, -1) of h_N(p) = orientation(N.plane, p) for any finite double point p,
/// whatever the tree's kernel (CGAL's filtered exact predicate on double input).
EXBSP_EXPORT int side_of_plane(const bsp_node& n, const vec3d& p);

/// h_N(p) = ((b - a) x (c - a)) . (p - a) in double: for interpolating where a segment meets
/// the plane. Its sign may differ from side_of_plane's near the plane; decide with the latter.
EXBSP_EXPORT double plane_value(const bsp_node& n, const vec3d& p);

/// The callbacks of a traversal (order above); each default does nothing.
class EXBSP_EXPORT bsp_visitor {
 public:
  virtual ~bsp_visitor() = default;
  /// Node n is reached, before its sides and fragments; eye_side = s (+1, 0 or -1).
  virtual void enter(const bsp_node& n, int eye_side) { (void)n, (void)eye_side; }
  /// n's coplanar fragments, at their place in the order.
  virtual void fragments(const bsp_node& n) { (void)n; }
  /// The empty side `side` (+1 / -1) of n: a cell, at its place in the order.
  virtual void cell(const bsp_node& n, int side) { (void)n, (void)side; }
};

}  // namespace exbsp
