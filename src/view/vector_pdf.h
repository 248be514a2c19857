// SPDX-License-Identifier: LGPL-3.0-or-later
// PDF output of a vector drawing (vector_drawing.h) through cairo's PDF surface: the same
// paths, colours, groups' drawing order and stroke styles as the SVG writer.
//
// Notation: one PDF point per pixel (the page is width x height pt); cairo's user space has
// its origin at the top-left corner with y down, so a grid point (X, Y) is drawn at
// (X / 100, height - Y / 100), the SVG's coordinates. Regions are filled with the nonzero
// (winding) rule; edges and curves are stroked as in svg_writer.h. A placed drawing
// (vector_drawing::placed) is drawn on a page of the image's size, filled with the image's
// background, translated to (x, image_height - y - height) and clipped to its viewport.
#pragma once
#include <string>

#include <exbsp/view/vector_drawing.h>

namespace exbsp::view {

/// The PDF document of `d` (bytes). Throws usage_error when cairo reports an error.
std::string pdf_document(const vector_drawing& d);

}  // namespace exbsp::view
