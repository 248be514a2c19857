// SPDX-License-Identifier: LGPL-3.0-or-later
// Homogeneous (4D) clipping of a line segment against the OpenGL view volume, before the
// perspective divide: Liang–Barsky and Cohen–Sutherland in clip coordinates.
//
// Notation: clip-space points a, b = (x, y, z, w); the segment is P(t) = a + t (b - a),
// t in [0, 1]. The view volume is the intersection of the six closed half-spaces
//   d_k(P) >= 0,   d_k in {w + x, w - x, w + y, w - y, w + z, w - z}   (k = 0..5),
// (outcode bit k = 1 << k, as homogeneous.h), each d_k linear, so d_k(P(t)) = (1 - t) d_k(a)
// + t d_k(b). Together the planes imply w >= 0, so a segment running behind the eye is cut
// before the divide and never wraps around through infinity.
// Liang–Barsky: for each plane with d_k(a) < 0 <= d_k(b) the segment enters at
// t = d_k(a) / (d_k(a) - d_k(b)) (raising t0); with d_k(b) < 0 <= d_k(a) it leaves there
// (lowering t1); both negative rejects it. The kept part is [t0, t1] when t0 <= t1. This is
// liang_barsky.h's parametric_interval with p = d_k(a) - d_k(b), q = d_k(a): one core for the
// 2D/3D box clippers and this one.
// Cohen–Sutherland: outcodes of both ends; both 0 accepts, a common bit rejects; otherwise the
// end that is outside (a first) moves to the lowest plane k its code violates, at the same t
// as above (always computed on the original segment, so t only grows for a and shrinks for
// b), and the test repeats (at most 12 moves; the planes are convex, so the result is the
// Liang–Barsky one up to rounding).
//
// Floating point (both): t0 == 0 keeps a bit-for-bit and t1 == 1 keeps b; an end point
// produced by a plane is then put exactly on it (x = -w for w + x = 0, and so on).
#pragma once
#include <exbsp/clip/clip_types.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// Liang–Barsky: clips segment (a, b) (clip coordinates) to -w <= x, y, z <= w. Returns false
/// when nothing is left; otherwise sets out_a = P(t0), out_b = P(t1) and, when t0_out / t1_out
/// are not null, the parameters. A zero-length segment (a == b) is kept iff a is inside.
/// Non-finite input returns false (nothing to draw); never throws.
EXBSP_EXPORT bool homogeneous_liang_barsky(const vec4d& a, const vec4d& b, vec4d& out_a,
                                           vec4d& out_b, double* t0_out = nullptr,
                                           double* t1_out = nullptr);

/// Cohen–Sutherland with the same contract as homogeneous_liang_barsky.
EXBSP_EXPORT bool homogeneous_cohen_sutherland(const vec4d& a, const vec4d& b, vec4d& out_a,
                                               vec4d& out_b, double* t0_out = nullptr,
                                               double* t1_out = nullptr);

}  // namespace exbsp::clip
