// SPDX-License-Identifier: LGPL-3.0-or-later
// The "antialias" effect: N x N supersampling with a box filter. Its stage replaces "raster".
//
// Notation: N = settings.samples. The frame is painted at N times the viewport's resolution
// (paint.h: window point (x, y) -> (N x, N y), the same top-left rule, lines N pixels wide),
// and each output pixel is the rounded mean of its N x N sub-pixels, whose centres are the
// window points (i + (k + 1/2)/N, j + (l + 1/2)/N), k, l = 0..N-1. Two polygons sharing an edge
// are rasterized with the top-left rule at the high resolution, where it still covers each
// sub-pixel exactly once, so no seam can appear: a pixel whose sub-pixels are all covered by
// polygons of one colour has exactly that colour.
#pragma once
#include <string>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// "antialias": f.picture = box_downsample(paint_frame(f, N), N), N = f.settings.antialias.samples.
/// Throws usage_error when N is outside 1..8 or the supersampled image is too large.
std::string antialias_stage(frame& f);

}  // namespace exbsp::view
