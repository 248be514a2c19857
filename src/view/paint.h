// SPDX-License-Identifier: LGPL-3.0-or-later
// The painter: polygons back to front (top-left rule, rasterizer.h) with curve lines
// (line_raster.h) in their painter's slots (curves.h), each sample through the frame's
// sample_shader when a screen effect installed one (sample_shader.h: fog, per pixel),
// at 1x or N x N resolution (antialias.h). No depth buffer.
//
// Two walks give the same image. The reference (back_to_front) paints every polygon of
// f.polygons in order, each overwriting what is behind it. The fast one (front_to_back) walks
// the list in reverse (docs/contract.md "The BSP": front-to-back is the exact reverse) with a
// coverage mask of one bit per pixel: a pixel takes the colour of the first polygon that
// covers it, which is the last one the reference paints there, and a polygon whose screen box
// is already entirely covered is skipped without rasterizing it. Visibility still comes from
// the BSP order alone (no depth values). Lines are painted in slots between polygons; a frame
// with lines is always painted back to front.
//
// Notation: scale s >= 1; the painted image is (s width) x (s height); a window point (x, y)
// maps to (s (x - vp.x), s (y - vp.y)) in it, and its pixel (i, j) has its centre at window
// point (vp.x + (i + 1/2) / s, vp.y + (j + 1/2) / s). Lines are s pixels wide, so they stay one
// output pixel wide after a box downsample by s.
#pragma once
#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// The walk paint_frame uses for frame f: f.painter (front_to_back by default), except that a
/// frame with lines is painted back_to_front.
paint_order effective_paint_order(const frame& f);

/// Paints the background (the sample shader's, when there is one), then for every slot k the lines
/// of slot k and polygon k of f.polygons: the image of the back-to-front walk, whichever walk
/// (effective_paint_order) computes it. Throws usage_error unless 1 <= scale and the scaled
/// image fits (image.h).
image paint_frame(const frame& f, int scale);

/// Box filter: each output pixel is the rounded mean of an n x n block of `hi`, whose sides
/// must be multiples of n. Throws usage_error otherwise.
image box_downsample(const image& hi, int n);

}  // namespace exbsp::view
