// SPDX-License-Identifier: LGPL-3.0-or-later
// The depth-sort painter of the course notes (a teaching view, never the default): sort the
// polygons back to front by one depth each and paint them in that order. It is wrong wherever
// polygons overlap cyclically (each in front of the next) or pass through each other, which
// is what the BSP's order (stages.h, "order") gets right; scenes ask for it with
// "teaching": {"painter": "depth_sort"} (docs/contract.md "Scenes").
//
// Notation: the depth of a world point p is its distance in front of the viewer along the
// view: -z of Mv p (eye coordinates) for a perspective view, p . d for a parallel view with
// direction of projection d (into the scene). A triangle's sort key is the depth of its
// farthest corner (visibility_order::depth_sort_farthest, the classic first step of the
// depth-sort algorithm) or the mean depth of its corners (depth_sort_centroid). The painter
// draws the largest key first; equal keys keep the soup's order (a stable sort), so the
// result is deterministic. The sorted polygons are the input triangles as they are: no BSP is
// built and nothing is split.
#pragma once
#include <cstdint>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/mesh/soup.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/view_setup.h>

namespace exbsp::view {

/// The soup's triangles as fragments (face ids kept), in soup order, unsplit.
std::vector<fragment_d> soup_fragments(const triangle_soup& soup);

/// The depth of world point p for `view` (notation above).
double view_depth(const view_setup& view, const vec3d& p);

/// Indices of `fragments` in painting order for `key` (farthest first, ties in index order).
/// Fragments with a NaN or infinite corner go last (transform+clip leaves them out).
/// Throws usage_error when `key` is visibility_order::bsp.
std::vector<std::uint32_t> depth_sorted_order(const std::vector<fragment_d>& fragments,
                                              const view_setup& view, visibility_order key);

}  // namespace exbsp::view
