// SPDX-License-Identifier: GPL-3.0-or-later
// Concave clipping: polygons with holes (and segments) against a polygon region with holes,
// exactly. In the GPL component exbsp::gpl (libexbsp_gpl; find_package(exbsp COMPONENTS gpl),
// target exbsp::gpl): CGAL's 2D regularized Boolean set operations are GPL-3.0-or-later
// (docs/licence.md).
//
// The course material names Weiler–Atherton for concave-against-concave clipping; CGAL's
// Boolean set operations (Polygon_set_2 on the exact kernel Epeck, an arrangement sweep) stand
// in for a hand-written Weiler–Atherton: same result (the regularized intersection), exact for
// every degeneracy Weiler–Atherton's entry/exit lists are known to mishandle (shared edges,
// vertices on edges, touching rings).
//
// Notation: a ring is a polygon's closed boundary, its vertices in order (closed implicitly; a
// repeated last vertex equal to the first, and consecutive repeats, are ignored). A valid ring
// has at least 3 distinct points and is simple (no two edges meet except consecutive ones at
// their common vertex; collinear consecutive edges are allowed); either orientation. A polygon
// with holes is the closed region of its outer ring minus the open regions of its holes; every
// hole must lie inside the outer ring's closed region (holes may touch the outer ring or each
// other, and may overlap: the region is then the outer ring minus their union).
// Results are regularized (the closure of the interior: parts of zero area, such as a shared
// edge, disappear), with the outer rings counter-clockwise and the holes clockwise; where two
// parts of a result meet at a single point, CGAL may give them as one outer ring that passes
// through that point twice (a "relatively simple" polygon, still a closed curve). Every
// coordinate is computed exactly (rationals) and rounded once to the nearest double at output.
// Output order (deterministic): each ring starts at its lexicographically smallest vertex
// (x, then y), holes sorted by their first vertex, polygons by their outer ring's first vertex.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// A 2D polygon with holes (notation above).
struct polygon_with_holes2 {
  std::vector<vec2d> outer;
  std::vector<std::vector<vec2d>> holes;
};

/// Why `ring` is not a valid ring ("has a NaN or infinite coordinate", "has fewer than 3
/// distinct points", "is not simple: ..."), or the empty string when it is valid. Exact.
EXBSP_EXPORT std::string ring_problem(const std::vector<vec2d>& ring);

/// True when the closed region of `inner` lies in the closed region of `outer` (up to zero
/// area: `inner` may touch `outer`'s boundary from inside). Exact. Throws usage_error when
/// either ring is not valid (ring_problem).
EXBSP_EXPORT bool ring_inside(const std::vector<vec2d>& inner, const std::vector<vec2d>& outer);

/// A polygon region with holes, prepared once for many clips. Copies share the prepared
/// region (immutable, safe to use from several threads).
class EXBSP_EXPORT polygon_region {
 public:
  /// Throws usage_error naming the ring ("outer ring", "hole 2") when a ring is not valid or a
  /// hole is not inside the outer ring.
  explicit polygon_region(const polygon_with_holes2& region);

  /// The regularized intersection subject ∩ region: polygons with holes (notation above),
  /// none when nothing of positive area is left. Throws usage_error like the constructor when
  /// `subject` is not a valid polygon with holes.
  std::vector<polygon_with_holes2> intersect(const polygon_with_holes2& subject) const;

  /// The parts of segment s in the closed region, in order from s.p0 to s.p1: maximal
  /// sub-segments (a part along the boundary counts as inside) and, where s only touches the
  /// region at a point, that point as a segment of zero length. A zero-length s is kept iff
  /// its point is in the region. Endpoints rounded once to the nearest double; an end of s
  /// that is kept is returned bit for bit. Throws usage_error on NaN/infinite input.
  std::vector<segment2> clip_segment(const segment2& s) const;

  /// True when p lies in the closed region. Exact. Throws usage_error on NaN/infinite input.
  bool contains(const vec2d& p) const;

  /// The region itself, regularized and normalised (outer rings CCW, holes CW, rounded).
  std::vector<polygon_with_holes2> polygons() const;

 private:
  struct impl;
  std::shared_ptr<const impl> impl_;
};

}  // namespace exbsp::clip
