// SPDX-License-Identifier: LGPL-3.0-or-later
// Liang–Barsky parametric line clipping against a 2D window or a 3D box.
//
// Notation: the segment is P(t) = p0 + t * d, d = p1 - p0, t in [0, 1]. Each boundary gives
// one inequality p_k * t <= q_k: for min[k], p = -d[k], q = p0[k] - min[k]; for max[k],
// p = d[k], q = max[k] - p0[k]. p < 0 raises the entry parameter t0, p > 0 lowers the
// exit parameter t1, p == 0 with q < 0 rejects (parallel and outside). The kept part is
// [t0, t1] when t0 <= t1.
//
// Floating point: t0 == 0 keeps p0 bit-for-bit and t1 == 1 keeps p1; an endpoint produced by
// a boundary has that coordinate set exactly to the boundary value, and every coordinate is
// clamped into the box (the exact point is inside, so clamping only reduces the error).
#pragma once
#include <optional>

#include <exbsp/clip/clip_types.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

namespace detail {

/// The parametric core of Liang–Barsky, shared by the box clippers below and the homogeneous
/// one (homogeneous_segment.h): the kept interval [t0, t1] of P(t), t in [0, 1], under
/// inequalities p t <= q, with the boundaries that set its ends (-1: the segment's own end).
struct parametric_interval {
  double t0 = 0, t1 = 1;
  int entry = -1, exit = -1;
  /// Adds p t <= q for `boundary`: p < 0 may raise t0 to q / p, p > 0 may lower t1 to it.
  /// Returns false when p == 0 and q < 0 (parallel to the boundary and outside it).
  bool add(double p, double q, int boundary) {
    if (p == 0.0) return q >= 0.0;
    const double r = q / p;
    if (p < 0.0) {
      if (r > t0) t0 = r, entry = boundary;
    } else if (r < t1) {
      t1 = r, exit = boundary;
    }
    return true;
  }
  /// True when nothing is kept.
  bool empty() const { return t0 > t1; }
};

}  // namespace detail

/// Result of Liang–Barsky: the parameter interval [t0, t1] of the kept part (0 <= t0 <= t1
/// <= 1) and the kept segment P(t0) -> P(t1).
template <std::size_t N>
struct liang_barsky_result {
  double t0;
  double t1;
  segment<N> clipped;
};
using liang_barsky_result2 = liang_barsky_result<2>;
using liang_barsky_result3 = liang_barsky_result<3>;

/// The part of s inside the closed window with its parameters, or nothing when s misses it.
/// A segment fully inside is returned bit-for-bit with t0 = 0, t1 = 1; a zero-length
/// segment is kept iff its point is inside. Throws usage_error on NaN/infinite coordinates
/// or min > max.
EXBSP_EXPORT std::optional<liang_barsky_result2> liang_barsky_clip(const segment2& s,
                                                                   const window2& window);
/// 3D version against the closed box; same guarantees and errors.
EXBSP_EXPORT std::optional<liang_barsky_result3> liang_barsky_clip(const segment3& s,
                                                                   const box3& box);

}  // namespace exbsp::clip
