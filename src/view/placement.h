// SPDX-License-Identifier: LGPL-3.0-or-later
// The "place" stage: the viewport's picture inside a larger image (glViewport x, y inside the
// window; docs/contract.md "Scenes" "image", and the letterbox bars of aspect "fit").
//
// Notation: window coordinates as viewport.h (y up, origin at the image's lower-left corner);
// the viewport's picture has its lower-left corner at (place_x, place_y) of the image
// (view_setup). PNG: the image is the background colour with the picture copied in; image row
// r = image_height - 1 - j. SVG and PDF are placed the same way by their own stages (the
// drawing's placement, vector_drawing.h; svg_writer.h, vector_pdf.h), so this stage leaves
// f.svg and f.pdf alone.
#pragma once
#include <string>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// Composes f.picture (PNG) into the image of f.view.
/// Precondition: the viewport lies inside the image. Returns a note for the verbose log.
std::string place_stage(frame& f);

}  // namespace exbsp::view
