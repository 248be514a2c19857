// SPDX-License-Identifier: LGPL-3.0-or-later
// A vector drawing's paths (vector_drawing.h) drawn on a cairo context: the one drawing of
// them that the PDF writer (vector_pdf.h) and the raster's edges (raster_edges.h) share.
//
// Notation: cairo's user space has its origin at the drawing's top-left corner with y down,
// one unit per pixel, so a grid point (X, Y) is drawn at (X / 100, height - Y / 100), the
// SVG's coordinates. Regions are filled with the nonzero (winding) rule; edges and curves are
// stroked as in svg_writer.h (visible edges solid with round caps and joins, hidden edges
// dashed with butt caps, curves 1 px with butt caps); points are 1 px squares.
#pragma once
#include <cairo.h>

#include <exbsp/view/vector_drawing.h>

namespace exbsp::view {

/// Fills the drawing's background over its width x height, then draws its paths in order.
void draw_vector_paths(cairo_t* cr, const vector_drawing& d);

/// Draws only the drawing's paths, in order, over what `cr` holds already.
void draw_paths_only(cairo_t* cr, const vector_drawing& d);

}  // namespace exbsp::view
