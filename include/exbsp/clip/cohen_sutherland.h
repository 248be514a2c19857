// SPDX-License-Identifier: LGPL-3.0-or-later
// Cohen–Sutherland line clipping against a 2D window or a 3D box.
//
// Notation: an outcode has one bit per box boundary, two per axis k:
//   bit 2k   (value 1 << 2k)     : p[k] < min[k]  (outside below axis k)
//   bit 2k+1 (value 1 << (2k+1)) : p[k] > max[k]  (outside above axis k)
// so 2D outcodes have 4 bits (9 regions: left/right/bottom/top) and 3D outcodes 6 bits
// (27 regions). A point on the boundary (p[k] == min[k]) is inside: the box is closed.
// Trivial accept: both codes 0. Trivial reject: the codes share a bit (both endpoints
// strictly outside the same boundary). Otherwise an outside endpoint is moved to its
// intersection with one boundary it violates, and the test repeats.
//
// Floating point: an endpoint moved onto a boundary gets that coordinate set exactly to the
// boundary value; the other coordinates are interpolated from the original endpoints and
// kept within their range. If rounding later pushes an already-clipped coordinate a few
// ulps outside, it is snapped back to its boundary (the exact value is inside), so the loop
// always terminates and accepted endpoints are always inside the closed box exactly.
#pragma once
#include <optional>

#include <exbsp/clip/clip_types.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// Outcode bits (see the notation above). left/right/bottom/top name the 2D bits.
enum outcode_bit : unsigned {
  x_below = 1u,
  x_above = 2u,
  y_below = 4u,
  y_above = 8u,
  z_below = 16u,
  z_above = 32u,
  left = x_below,
  right = x_above,
  bottom = y_below,
  top = y_above
};

/// 4-bit outcode of p against the window. No checks: NaN compares as inside.
EXBSP_EXPORT unsigned outcode(const vec2d& p, const window2& window);
/// 6-bit outcode of p against the box (27 regions). No checks: NaN compares as inside.
EXBSP_EXPORT unsigned outcode(const vec3d& p, const box3& box);

/// True when both endpoints are inside (codes both 0): the segment is kept unchanged.
inline bool trivially_accepted(unsigned code0, unsigned code1) { return (code0 | code1) == 0; }
/// True when both endpoints are outside the same boundary: nothing of the segment is kept.
inline bool trivially_rejected(unsigned code0, unsigned code1) { return (code0 & code1) != 0; }

/// The part of segment s inside the closed window, with the direction of s, or nothing.
/// A segment fully inside is returned bit-for-bit; a zero-length segment is kept iff its
/// point is inside. Throws usage_error if a coordinate is NaN/infinite or min > max.
EXBSP_EXPORT std::optional<segment2> cohen_sutherland_clip(const segment2& s,
                                                           const window2& window);
/// 3D version against the closed box; same guarantees and errors.
EXBSP_EXPORT std::optional<segment3> cohen_sutherland_clip(const segment3& s, const box3& box);

}  // namespace exbsp::clip
