// SPDX-License-Identifier: LGPL-3.0-or-later
// Cyrus–Beck parametric clipping of a segment against any convex region given as half-planes
// (2D) or half-spaces (3D) (convex_region.h makes them from a convex polygon or polyhedron;
// sutherland_hodgman.h has the types): Liang–Barsky's parametric test (liang_barsky.h) with
// the region's own normals instead of the box's axes.
//
// Notation: P(t) = p0 + t * d, d = p1 - p0, t in [0, 1]; a half-plane f(x) = n·x + c >= 0
// (normal into the region). On the segment f(P(t)) = f(p0) + t (n·d) >= 0, i.e. p t <= q with
// p = -(n·d), q = f(p0): n·d > 0 (entering) raises t0 to -f(p0) / (n·d), n·d < 0 (leaving)
// lowers t1, n·d == 0 with f(p0) < 0 rejects (parallel and outside). The kept part is
// [t0, t1] when t0 <= t1.
//
// Floating point: t0 == 0 keeps p0 bit-for-bit and t1 == 1 keeps p1; other ends are
// p0 + t d, rounded once per coordinate (a point on a slanted boundary cannot be represented
// exactly in general, so it may evaluate a few ulps outside).
#pragma once
#include <optional>
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/clip/sutherland_hodgman.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// Result of Cyrus–Beck: the parameter interval [t0, t1] of the kept part, the kept segment
/// P(t0) -> P(t1), and the indices of the half-planes that set its ends (-1: the segment's own).
template <std::size_t N>
struct cyrus_beck_result {
  double t0;
  double t1;
  segment<N> clipped;
  int entry = -1, exit = -1;
};
using cyrus_beck_result2 = cyrus_beck_result<2>;
using cyrus_beck_result3 = cyrus_beck_result<3>;

/// The part of s inside every closed half-plane of `region`, or nothing when s misses it. An
/// empty region keeps all of s. Throws usage_error on NaN/infinite coordinates or
/// coefficients, or when n·d or f(p0) overflows.
EXBSP_EXPORT std::optional<cyrus_beck_result2> cyrus_beck_clip(
    const segment2& s, const std::vector<half_plane2>& region);
/// 3D version against half-spaces; same guarantees and errors.
EXBSP_EXPORT std::optional<cyrus_beck_result3> cyrus_beck_clip(
    const segment3& s, const std::vector<half_space3>& region);

}  // namespace exbsp::clip
