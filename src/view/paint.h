// The painter: polygons back to front (top-left rule, rasterizer.h) with curve lines
// (line_raster.h) in their painter's slots (curves.h), optionally fogged per pixel (fog.h),
// at 1x or N x N resolution (antialias.h). No depth buffer.
//
// Notation: scale s >= 1; the painted image is (s width) x (s height); a window point (x, y)
// maps to (s (x - vp.x), s (y - vp.y)) in it, and its pixel (i, j) has its centre at window
// point (vp.x + (i + 1/2) / s, vp.y + (j + 1/2) / s). Lines are s pixels wide, so they stay one
// output pixel wide after a box downsample by s.
#pragma once
#include "view/pipeline.h"

namespace exbsp::view {

/// Paints the background (the fog colour when fog is on), then for every slot k the lines of
/// slot k and polygon k of f.polygons. Throws usage_error unless 1 <= scale and the scaled
/// image fits (image.h).
image paint_frame(const frame& f, int scale);

/// Box filter: each output pixel is the rounded mean of an n x n block of `hi`, whose sides
/// must be multiples of n. Throws usage_error otherwise.
image box_downsample(const image& hi, int n);

}  // namespace exbsp::view
