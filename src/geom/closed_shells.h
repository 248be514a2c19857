// SPDX-License-Identifier: LGPL-3.0-or-later
// Meshes whose back faces no viewer outside them can see: the certificate that lets the vector
// drawing leave those faces out (docs/contract.md section 6, "visible regions").
//
// Notation: a mesh's triangles, vertices welded by exact position (weld.h), make a 2-chain;
// its winding number w(x) counts, for a point x off the surface, the oriented triangles around
// x. A triangle FACES AWAY from a viewer E when E lies strictly behind its plane (facing < 0 in
// feature_edges.h). Take a point p of such a triangle seen from E: the open segment (parallel
// view: the open ray) from p to E crosses no face. Crossing p towards E's side raises w by one,
// so w just beyond p is w(E) - 1. Hence when w >= 0 everywhere and w(E) = 0, no point of a
// back-facing triangle is ever seen. This file certifies w >= 0: the mesh is OUTWARD CLOSED when
//   - no triangle is degenerate (three welded vertices not exactly collinear),
//   - every directed edge (a, b) is used once and (b, a) once (closed, edges manifold,
//     consistently oriented),
//   - no two triangles meet except in their shared vertices and edges (exact tests), and
//   - every edge-connected component has a positive signed volume (exact sign).
// Each component is then an embedded closed surface (pinched at vertices at most) whose
// complement has two parts, w = 1 inside and 0 outside; their sum is never negative. A viewer
// outside every component (w(E) = 0: the caller checks that, e.g. no part of the mesh was cut
// at the near plane) sees none of the mesh's back faces. Nested shells (a hollow part, whose
// inner shell is inward) are refused although w >= 0 there too: the certificate is
// sufficient, not necessary.
#pragma once
#include <cstdint>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>

namespace exbsp::geom {

/// Why a mesh is or is not outward closed (notation), in the order the tests run.
enum class shell_verdict : std::uint8_t {
  outward_closed,       ///< the certificate holds
  empty,                ///< no triangle
  degenerate_triangle,  ///< a triangle with no plane (or a corner not finite)
  not_closed,           ///< some directed edge is not matched by exactly one reverse edge
  self_intersecting,    ///< two triangles meet beyond their shared vertices and edges
  not_outward           ///< a component's signed volume is zero or negative
};

/// The verdict for the triangles `triangles` (indices into soup.triangles) as one mesh.
EXBSP_EXPORT shell_verdict shell_verdict_of(const triangle_soup& soup,
                                            const std::vector<std::uint32_t>& triangles);

/// Per mesh k < mesh_count(mesh_face_offsets) of `soup` (its triangles: those whose face id
/// mesh_of_face assigns to k, as frame::mesh_of does): 1 when it is outward closed, 0 otherwise.
EXBSP_EXPORT std::vector<std::uint8_t> outward_closed_meshes(
    const triangle_soup& soup, const std::vector<std::uint32_t>& mesh_face_offsets);

}  // namespace exbsp::geom
