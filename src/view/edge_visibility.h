// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact edge visibility for the hidden-line drawing (docs/contract.md section 6).
//
// Notation: a feature edge (geom/feature_edges.h) from A to B is p(t) = A + t (B - A), 0 <= t
// <= 1. E is the viewer as a homogeneous point: the eye (perspective views) or the direction
// towards the viewer, -view.direction (parallel views). D is the 4 x 4 determinant of
// geom/homogeneous_det.h, and m = facing(T) = +-1 for an occluding triangle T = (a, b, c)
// (triangles seen edge-on hide nothing). p is hidden by T exactly when
//   g(p)   = m D(a, b, c, p) > 0          p lies beyond T's plane, seen from E, and
//   h_uv(p) = m D(E, u, v, p) >= 0         for the sides uv = ab, bc, ca of T: the segment (or
//                                          ray) from p to E meets the closed triangle;
// with "> 0" instead of ">= 0" for a side that is a feature edge (touching a feature edge hides
// nothing). Each function is affine in t, so T hides an interval of t whose ends are where one
// of them vanishes: t = f(A) / (f(A) - f(B)), compared exactly (geom::crossing). Only whether an
// interval has positive length matters to a drawing; so each interval is taken closed, and a
// strict constraint matters only where its function is identically 0 on the edge (the edge
// lies in T's plane, or in the plane through E and a feature side of T): then T hides nothing.
// The hidden part of an edge is the union of these intervals, merged exactly; the rest is
// visible.
//
// Candidates: only triangles whose window-space bounding box meets the edge's window image (a
// grid of square cells over the viewport) are tested; the box test is conservative (a margin
// far above the rounding of the projection), the exact test decides.
#pragma once
#include <cstdint>
#include <vector>

#include "geom/feature_edges.h"

namespace exbsp::view {

struct frame;

/// A run of a feature edge: parameters t0 < t1 on the edge, visible or hidden.
struct edge_run {
  std::uint32_t edge = 0;  ///< index into view_features::edges
  double t0 = 0, t1 = 1;
  bool visible = true;
};

/// The viewer of a frame's view as a homogeneous point (notation).
geom::hpoint viewer_of(const frame& f);

/// The feature edges of a frame's soup for its view and, for each edge whose image meets the
/// view volume, its runs in order along the edge, alternating visible and hidden, covering
/// [0, 1] (runs of zero length left out). Precondition: 0 < crease_deg <= 180.
struct edge_visibility {
  geom::view_features features;
  std::vector<edge_run> runs;
};
edge_visibility visible_runs(const frame& f, double crease_deg);

}  // namespace exbsp::view
