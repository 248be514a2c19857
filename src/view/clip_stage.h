// SPDX-License-Identifier: LGPL-3.0-or-later
// The clipping stage of the viewing pipeline: the one boundary between the view module and
// exbsp_clip's homogeneous clippers (polygons: clip/homogeneous.h; segments of curves and
// lines: clip/homogeneous_segment.h), for the view's hpoint. Switching clippers changes only
// clip_stage.cpp.
//
// Notation: clip coordinates (x, y, z, w); the view volume is -w <= x, y, z <= w (OpenGL).
// Clipping happens BEFORE the perspective divide, so points behind the eye never wrap around.
#pragma once
#include <cstddef>
#include <vector>

#include <exbsp/view/matrix.h>
#include <exbsp/view/screen_line.h>

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

/// Clips segment (a, b) (clip coordinates) to -w <= x, y, z <= w with `clipper`. Returns false
/// when nothing is left; otherwise sets out_a = P(t0), out_b = P(t1) and, when t0_out / t1_out
/// are not null, the parameters. A zero-length segment (a == b) is kept iff a is inside.
/// Non-finite input returns false (nothing to draw); never throws.
bool clip_segment_to_view_volume(const hpoint& a, const hpoint& b, hpoint& out_a, hpoint& out_b,
                                 double* t0_out = nullptr, double* t1_out = nullptr,
                                 segment_clipper clipper = segment_clipper::liang_barsky);

}  // namespace exbsp::view
