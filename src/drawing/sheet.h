// SPDX-License-Identifier: LGPL-3.0-or-later
// A drawing sheet (`exbsp drawing`, docs/contract.md "Command line"): what is on the paper, in
// millimetres, before any file format. The SVG and PDF writers (sheet_writers.h) and the DXF
// writer (sheet_dxf.h) print this one model, so the three files hold the same drawing.
//
// Notation: sheet coordinates (x, y) in millimetres, origin at the lower-left corner of the
// paper, y up (as DXF and as the paper is held). The SVG writer flips y (y_svg = height - y).
//
// Layers, in drawing order (each writer's groups / DXF layers carry these names):
//   fills           visible regions of faces (shaded views; absent with --lines-only)
//   hatching        section hatching: thin lines at 45 degrees (ISO 128-50)
//   hidden          hidden edges: dashed (ISO 128 type 02: dash 12 d, gap 3 d, d the width)
//   visible         visible edges: continuous (type 01)
//   cutting-planes  cutting-plane lines: long-dash dotted (type 04: dash 24 d, gap 3 d,
//                   dot 0.5 d, gap 3 d), thick at the ends, arrows and letters
//   frame           border, title block (ISO 7200), projection symbol (ISO 5456-2), view labels
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/view/image.h>

#include "core/named_table.h"

namespace exbsp::drawing {

/// A point on the sheet (mm, y up).
struct point2 {
  double x = 0, y = 0;
};

/// The layers, in drawing order (notation above).
enum class layer_id { fills, hatching, hidden, visible, cutting_planes, frame };
/// The layers in drawing order with their names (SVG group ids, DXF layer names).
constexpr enum_name<layer_id> layer_table[] = {{layer_id::fills, "fills"},
                                               {layer_id::hatching, "hatching"},
                                               {layer_id::hidden, "hidden"},
                                               {layer_id::visible, "visible"},
                                               {layer_id::cutting_planes, "cutting-planes"},
                                               {layer_id::frame, "frame"}};
inline const char* layer_name(layer_id l) { return name_of(l, layer_table); }

/// ISO 128-20 line types.
enum class line_style {
  continuous,  ///< type 01
  dashed,      ///< type 02: dash 12 d, gap 3 d
  chain        ///< type 04: long dash 24 d, gap 3 d, dot 0.5 d, gap 3 d
};

/// The dash pattern of `style` for line width d (mm): lengths of dash, gap, dash, gap...
/// (empty: continuous).
inline std::vector<double> dash_pattern(line_style style, double d) {
  switch (style) {
    case line_style::continuous:
      return {};
    case line_style::dashed:
      return {12 * d, 3 * d};
    case line_style::chain:
      return {24 * d, 3 * d, 0.5 * d, 3 * d};
  }
  return {};
}

/// One stroked polyline: a chain of edges is one polyline, so its dash pattern runs on.
struct sheet_polyline {
  layer_id layer = layer_id::visible;
  line_style style = line_style::continuous;
  double width = 0.5;  ///< mm
  bool closed = false;
  std::vector<point2> points;
};

/// A filled area: rings filled by the nonzero rule, no stroke.
struct sheet_fill {
  layer_id layer = layer_id::fills;
  view::rgb8 color{0, 0, 0};
  std::vector<std::vector<point2>> rings;
};

/// One line of text (ISO 3098 lettering: an upright sans-serif).
struct sheet_text {
  enum class anchor_kind { start, middle, end };
  layer_id layer = layer_id::frame;
  point2 at;          ///< baseline point, at the anchor
  double height = 5;  ///< capital height, mm
  anchor_kind anchor = anchor_kind::start;
  std::string text;  ///< UTF-8
};

/// Where one view is on the sheet (for tests, logs and the Python module).
struct sheet_view {
  std::string name;              ///< "front", "top", ..., "iso", "section A"
  point2 lower_left;             ///< of its box (mm)
  double width = 0, height = 0;  ///< its box (mm)
  /// Sheet mm of a model point p: lower_left + mm_per_model * (p . right - left, p . up - bottom).
  std::array<double, 3> right{}, up{}, towards_eye{};
  double left = 0,
         bottom = 0;  ///< model coordinates of the box's lower-left corner (p . right, p . up)
  double mm_per_model = 1;  ///< model units to paper millimetres (units times scale)
  std::size_t visible_chains = 0, hidden_chains = 0;
};

/// A whole sheet.
struct sheet {
  double width = 420, height = 297;  ///< paper size, mm
  std::string title;                 ///< the document title (SVG <title>, PDF metadata)
  std::vector<sheet_fill> fills;
  std::vector<sheet_polyline> lines;
  std::vector<sheet_text> texts;
  std::vector<sheet_view> views;
  /// The hatched regions of the sections, one entry per section view: closed rings in sheet mm
  /// (even-odd: holes are rings inside rings), the exact cut's outline loops rounded once.
  std::vector<std::vector<std::vector<point2>>> hatch_regions;
};

}  // namespace exbsp::drawing
