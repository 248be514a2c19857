// SPDX-License-Identifier: LGPL-3.0-or-later
// Axis-aligned bounding boxes for trivial rejection before per-triangle clipping work.
//
// Notation: boxes are closed (min <= p <= max on every axis, clip_types.h); two boxes
// overlap when they share at least one point, so boxes that only touch do overlap and a
// triangle touching the window's border is not rejected. For clip space (4D, before the
// divide) use homogeneous_trivially_rejected on the transformed box_corners instead.
#pragma once
#include <array>
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// Smallest box containing the points. Throws usage_error for no points or NaN/infinite ones.
EXBSP_EXPORT box2 bounding_box(const std::vector<vec2d>& points);
/// Smallest box containing the points. Throws usage_error for no points or NaN/infinite ones.
EXBSP_EXPORT box3 bounding_box(const std::vector<vec3d>& points);
/// Smallest box containing the triangle. Throws usage_error for NaN/infinite coordinates.
EXBSP_EXPORT box2 bounding_box(const std::array<vec2d, 3>& triangle);
/// Smallest box containing the triangle. Throws usage_error for NaN/infinite coordinates.
EXBSP_EXPORT box3 bounding_box(const std::array<vec3d, 3>& triangle);

/// True when the closed boxes share a point. No checks (NaN bounds never overlap).
EXBSP_EXPORT bool boxes_overlap(const box2& a, const box2& b);
/// True when the closed boxes share a point. No checks (NaN bounds never overlap).
EXBSP_EXPORT bool boxes_overlap(const box3& a, const box3& b);

/// True when the triangle's bounding box misses the closed window, so no clipping is needed
/// to discard it. False does not mean the triangle meets the window. Throws like bounding_box.
EXBSP_EXPORT bool triangle_outside_window(const std::array<vec2d, 3>& triangle,
                                          const window2& window);

/// The eight corners of the box, corner i taking max on axis k when bit k of i is set.
EXBSP_EXPORT std::array<vec3d, 8> box_corners(const box3& box);

}  // namespace exbsp::clip
