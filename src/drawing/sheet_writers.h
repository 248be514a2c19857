// SPDX-License-Identifier: LGPL-3.0-or-later
// SVG and PDF files of a drawing sheet (sheet.h).
//
// SVG: width and height in mm, viewBox "0 0 W H" (one user unit = 1 mm), y flipped
// (y_svg = H - y). One <g inkscape:groupmode="layer" inkscape:label="NAME" id="layer-NAME">
// per layer of sheet.h in drawing order, with the layer's paths: fills as filled paths
// (nonzero), each polyline as one <path> (so a dash pattern runs on along the whole chain)
// with its width, stroke-dasharray for dashed and chain lines (ISO 128-20 lengths), butt caps
// on patterned lines and round caps and joins on continuous ones; texts in an upright sans
// serif whose capital height is the text's height. Coordinates have at most 4 decimals (0.1
// micrometre).
//
// PDF (cairo): the page is the paper at its true size (points = mm * 72 / 25.4), the same
// drawing in the same order; cairo has no layers, so the PDF has none. Its creation date is the
// sheet's date (so that equal sheets give equal bytes).
#pragma once
#include <string>

#include <exbsp/core/export.h>
#include "drawing/sheet.h"

namespace exbsp::drawing {

/// The SVG document of `s`.
EXBSP_EXPORT std::string sheet_svg(const sheet& s);

/// The PDF document of `s`, created at `date` (YYYY-MM-DD). Throws usage_error when cairo fails.
EXBSP_EXPORT std::string sheet_pdf(const sheet& s, const std::string& date);

/// Capital height / font size of the lettering's font (DejaVu Sans).
constexpr double cap_height_per_em = 0.729;

}  // namespace exbsp::drawing
