// SPDX-License-Identifier: GPL-3.0-or-later
// DXF file of a drawing sheet (sheet.h), written by dxflib (Debian's libdxflib-dev). dxflib is
// licensed GPL-2.0-or-later, so this writer is part of the GPL component exbsp::gpl
// (libexbsp_gpl, docs/licence.md), not of the LGPL render library.
//
// Notation: AutoCAD 2000 DXF (AC1015), units millimetres ($INSUNITS 4, $MEASUREMENT 1), model
// space at 1 drawing unit = 1 mm of paper, y up, origin at the paper's lower-left corner.
// Layers: the sheet's layers but "fills" (DXF carries the line drawing; fills stay in SVG and
// PDF): hatching, hidden, visible, cutting-planes, frame, each with its linetype (CONTINUOUS;
// HIDDEN: dash 12 d, gap 3 d; DASHDOT: 24 d, 3 d, 0.5 d, 3 d; d the layer's line width) and line
// weight. Each polyline is one POLYLINE entity (a chain keeps its linetype pattern running), a
// two-point hatch line a LINE, a filled triangle (arrowheads) a SOLID, a text a TEXT.
#pragma once
#include <string>

#include <exbsp/core/export.h>
#include "drawing/sheet.h"

namespace exbsp::drawing {

/// The DXF document of `s`. Throws output_error when the temporary file dxflib writes cannot be
/// made or read back.
EXBSP_EXPORT std::string sheet_dxf(const sheet& s);

}  // namespace exbsp::drawing
