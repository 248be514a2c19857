// SPDX-License-Identifier: LGPL-3.0-or-later
// Curves in the frame: the scene's Bézier curves (input, world space) and the product of the
// "curves" stage, pieces of their flattened polylines in window coordinates, each tagged
// with its place in the painter's sequence (curves.h explains the depth rule).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <exbsp/mesh/soup.h>
#include <exbsp/view/image.h>
#include <exbsp/view/viewport.h>

namespace exbsp::view {

/// The segment clipper of a polyline (clip space, clip/homogeneous_segment.h).
enum class segment_clipper { liang_barsky, cohen_sutherland };

/// One entry of a scene's "curves": a Bézier curve of degree control_points.size() - 1; or of
/// its "lines": a polyline through control_points (polyline = true; no flattening), clipped by
/// `clipper`. Curves are clipped by Liang–Barsky.
struct curve_spec {
  std::vector<vec3d> control_points;  ///< >= 1 finite points, world space
  rgb8 color{0, 0, 0};
  bool polyline = false;
  segment_clipper clipper = segment_clipper::liang_barsky;
};

/// A clipped piece of a flattened curve in window coordinates (x right, y up, z depth).
struct screen_line {
  window_point a, b;
  rgb8 color;
  /// Painter's slot: drawn after f.polygons[slot - 1] and before f.polygons[slot]
  /// (0: before every polygon; polygons.size(): after all of them).
  std::size_t slot = 0;
  std::uint32_t curve = 0;  ///< index into frame::curves
  bool point = false;       ///< a degree-0 curve: a single point at a (== b)
};

}  // namespace exbsp::view
