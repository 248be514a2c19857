// Homogeneous (4D) clipping of a line segment against the OpenGL view volume, before the
// perspective divide: parametric Liang–Barsky in clip coordinates.
//
// Notation: clip-space points a, b = (x, y, z, w); the segment is P(t) = a + t (b - a),
// t in [0, 1]. The view volume is the intersection of the six closed half-spaces
//   d_k(P) >= 0,   d_k in {w + x, w - x, w + y, w - y, w + z, w - z}   (k = 0..5),
// each d_k linear, so d_k(P(t)) = (1 - t) d_k(a) + t d_k(b). For each plane with
// d_k(a) < 0 <= d_k(b) the segment enters at t = d_k(a) / (d_k(a) - d_k(b)) (raising t0);
// with d_k(b) < 0 <= d_k(a) it leaves there (lowering t1); both negative rejects it. The kept
// part is [t0, t1] when t0 <= t1. Together the planes imply w >= 0, so a segment running
// behind the eye is cut before the divide and never wraps around through infinity.
//
// Floating point: t0 == 0 keeps a bit-for-bit and t1 == 1 keeps b; an end point produced by a
// plane is then put exactly on it (x = -w for w + x = 0, and so on).
#pragma once
#include "view/matrix.h"

namespace exbsp::view {

/// Clips segment (a, b) (clip coordinates) to -w <= x, y, z <= w. Returns false when nothing
/// is left; otherwise sets out_a = P(t0), out_b = P(t1) and, when t0_out / t1_out are not
/// null, the parameters. A zero-length segment (a == b) is kept iff a is inside.
/// Non-finite input returns false (nothing to draw); never throws.
bool clip_segment_to_view_volume(const hpoint& a, const hpoint& b, hpoint& out_a, hpoint& out_b,
                                 double* t0_out = nullptr, double* t1_out = nullptr);

}  // namespace exbsp::view
