// SPDX-License-Identifier: LGPL-3.0-or-later
// Per-sample colour changes of screen-space effects (fog), kept out of the painters.
//
// A screen effect's stage (fog.h) installs a sample_shader in the frame; the painters
// (paint.h) and the vector writers (svg_writer.h, vector_drawing.h) know no effect: each
// sample they colour is painted shade(colour, x, y, z) at its window point (viewport.h:
// x, y in pixels, z the depth in [depth_near, depth_far]), and what nothing covers takes the
// shader's background. Samples: a pixel centre of a polygon (its depth from the polygon's
// depth plane below) or a line's sample point (PNG); a path's mean window point (SVG, PDF).
//
// Depth plane: over a planar polygon the window depth z is an affine function of (x, y) (a
// projective map sends planes to planes), so a polygon's depth at a pixel centre comes from
// its plane z = zx x + zy y + z0 through its window vertices: per-pixel depth without a
// depth buffer.
#pragma once
#include <functional>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/view/image.h>
#include <exbsp/view/viewport.h>

namespace exbsp::view {

/// The colour change of a screen effect (notation above).
struct sample_shader {
  std::function<rgb8(rgb8 color, double x, double y, double z)> shade;
  rgb8 background{255, 255, 255};  ///< the colour of samples no primitive covers
};

/// The depth plane z = zx x + zy y + z0 of a window-space polygon; for a polygon seen
/// edge-on (no stable plane) zx = zy = 0 and z0 is the mean depth.
struct depth_plane {
  double zx = 0, zy = 0, z0 = 0;
  double at(double x, double y) const { return zx * x + zy * y + z0; }
};
/// The plane through the polygon's widest fan triangle.
EXBSP_EXPORT depth_plane polygon_depth_plane(const std::vector<window_point>& v);

}  // namespace exbsp::view
