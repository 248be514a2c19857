// Homogeneous (4D) clipping of a line segment against the OpenGL view volume, before the
// perspective divide, for the view module's hpoint: the clippers of clip/homogeneous_segment.h
// (one implementation for curves and lines; notation and floating-point rules there).
#pragma once
#include "clip/homogeneous_segment.h"
#include "view/matrix.h"
#include "view/screen_line.h"

namespace exbsp::view {

/// Clips segment (a, b) (clip coordinates) to -w <= x, y, z <= w with `clipper`. Returns false
/// when nothing is left; otherwise sets out_a = P(t0), out_b = P(t1) and, when t0_out / t1_out
/// are not null, the parameters. A zero-length segment (a == b) is kept iff a is inside.
/// Non-finite input returns false (nothing to draw); never throws.
bool clip_segment_to_view_volume(const hpoint& a, const hpoint& b, hpoint& out_a, hpoint& out_b,
                                 double* t0_out = nullptr, double* t1_out = nullptr,
                                 segment_clipper clipper = segment_clipper::liang_barsky);

}  // namespace exbsp::view
