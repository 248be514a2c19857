// SPDX-License-Identifier: LGPL-3.0-or-later
// The back faces the vector drawing may leave out: those of outward-closed meshes
// (geom/closed_shells.h), which no viewer outside the mesh sees, in a view that draws the mesh
// whole (no fragment of it cut at the near plane: frame::meshes_whole). Leaving them out
// changes no visible region in exact arithmetic; it spares the coverage walk the polygons it
// would find hidden, most of them only after clipping near silhouettes.
//
// Notation: the viewer E is the eye (w = 1) or the direction towards the viewer (w = 0), as
// for the edges (edge_visibility.h); a face is left out when every triangle of it faces away
// from E, decided exactly (geom::facing's determinant, the same as the silhouettes').
#pragma once
#include <cstdint>
#include <vector>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// True when the frame may leave out back faces at all: the tree's order (not a teaching
/// view's depth sort) and some mesh drawn whole.
bool may_leave_out_back_faces(const frame& f);

/// Per face id of f.soup: 1 when the face belongs to a mesh that is outward closed
/// (`outward_closed`, per mesh as frame::mesh_of numbers them) and whole in this view, and all
/// its triangles face away from the viewer. Empty when no face qualifies. The facing tests run
/// on up to `workers` threads.
std::vector<std::uint8_t> hidden_back_faces(const frame& f,
                                            const std::vector<std::uint8_t>& outward_closed,
                                            unsigned workers);

/// True when polygon p's face is one of `hidden` (hidden_back_faces; empty: none).
inline bool left_out(const std::vector<std::uint8_t>& hidden, const screen_polygon& p) {
  return p.face < hidden.size() && hidden[p.face] != 0;
}

}  // namespace exbsp::view
