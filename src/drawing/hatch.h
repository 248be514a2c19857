// SPDX-License-Identifier: LGPL-3.0-or-later
// Section hatching (ISO 128-50): parallel thin lines at 45 degrees over a region given by
// closed rings under the even-odd rule (holes and islands are rings inside rings).
//
// Notation: the lines are u = const in the rotated frame u = (y - x) / sqrt 2 (lines rising at
// 45 degrees to the right), at u = phase + k * spacing. Each line meets the rings' edges at
// points t = (x + y) / sqrt 2 along it; an edge counts when its endpoints lie on opposite
// sides of the line, the upper one included (half-open, so a vertex on a line is met once or
// not at all); sorted crossings pair up into the segments inside the region.
#pragma once
#include <vector>

#include "drawing/sheet.h"

namespace exbsp::drawing {

/// One hatch segment.
struct hatch_segment {
  point2 a, b;
};

/// The hatch segments of the region `rings` (even-odd) with line spacing `spacing` (> 0), the
/// lines placed at u = k * spacing (so hatching of different regions lines up).
std::vector<hatch_segment> hatch_lines(const std::vector<std::vector<point2>>& rings,
                                       double spacing);

/// Area of the region `rings` under the even-odd rule when no two rings cross: the sum of the
/// rings' signed areas, each counted with the sign of its nesting depth parity.
double even_odd_area(const std::vector<std::vector<point2>>& rings);

}  // namespace exbsp::drawing
