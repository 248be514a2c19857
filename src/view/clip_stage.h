// The clipping stage of the viewing pipeline: one function boundary between the pipeline and
// the clipping algorithm (clip_stage.cpp calls exbsp_clip's homogeneous clipper; switching
// clippers changes only that file).
//
// Notation: clip coordinates (x, y, z, w); the view volume is -w <= x, y, z <= w (OpenGL).
// Clipping happens BEFORE the perspective divide, so points behind the eye never wrap around.
#pragma once
#include <cstddef>
#include <vector>

#include "view/matrix.h"

namespace exbsp::view {

/// Clips the convex polygon `in` (clip coordinates, either winding) to the view volume
/// -w <= x, y, z <= w and writes the result to `out` (cleared first; empty when the polygon
/// is entirely outside or degenerates to fewer than 3 vertices). Vertex order is kept.
/// Two polygons sharing an edge get bit-identical new vertices on that edge, so no cracks open.
/// Throws usage_error for a NaN or infinite coordinate.
void clip_to_view_volume(const std::vector<hpoint>& in, std::vector<hpoint>& out);

/// 6-bit outcode of a finite clip-space point against the view volume: 0 inside (boundary
/// included). A polygon whose vertices all have outcode 0 is returned unchanged by
/// clip_to_view_volume; one whose vertices share a set bit is returned empty.
unsigned view_volume_outcode(const hpoint& p);

}  // namespace exbsp::view
