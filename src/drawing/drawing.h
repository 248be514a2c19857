// SPDX-License-Identifier: LGPL-3.0-or-later
// Multi-view drawing sheets of a part (`exbsp drawing`, docs/contract.md "Command line").
//
// Notation: model axes as CAD uses them, z up: the front view looks at the part from -y (the
// viewer stands at -y, up +z, right +x), top from +z (up +y), left from -x (the view of the
// left side: up +z, right -y), right from +x, bottom from -z (up -y), rear from +y; iso looks
// from (1, -1, 1) (up: +z made perpendicular). With up = "y" these axes (x, y, z) are the
// model's (x, -z, y): the front view looks from +z with +y up, as `exbsp render --view front`. Each
// view is an orthographic projection of the exact BSP (built once per solid), with the contract's
// exact hidden lines, mapped to the sheet by the scale: mm_per_model = unit (mm per model unit) *
// scale.
//
// Layout (ISO 5456-2): the views sit in the cells of a grid around the front view. First-angle:
// top below, bottom above, left view on the right, right view on the left, rear right of the
// left view. Third-angle: top above, bottom below, left view on the left, right view on the
// right, rear right of the right view. A column's views share their x range and a row's their
// height range (each principal view's box is the projection of the part's bounding box), so the
// views line up exactly. The iso view and the section views take free cells (upper right
// first). Columns are as wide as their widest view, rows as high as their highest; a gap of
// view_gap mm (at least) separates them, and the block is centred in the drawing area above the
// title block.
//
// Scale (ISO 5455): 1:1; reductions 1:2, 1:5, 1:10 and on by powers of ten; enlargements 2:1,
// 5:1, 10:1 and on. "auto" takes the largest of them at which the views fit.
//
// Sections (ISO 128-40/-50): section X=a,b,c,d cuts the part by a*x + b*y + c*z + d = 0 and
// keeps the side where it is >= 0 (as `exbsp section`); the view "SECTION X-X" looks at the
// cut face along +n (n = (a, b, c)), with the exact cap hatched at 45 degrees; its hidden edges
// are left out (ISO 128-40). The cutting-plane line is drawn on the first principal view that
// sees the plane edge-on, with arrows in the viewing direction and the letter at each end.
//
// Lines (ISO 128-20, -24): visible edges continuous, hidden dashed, hatching and the
// cutting-plane chain line thin; widths from drawing_options (default 0.5 and 0.25 mm). The
// iso view shows no hidden edges (as drawings do).
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>
#include "drawing/sheet.h"

namespace exbsp::drawing {

/// ISO 5456-2 projection methods.
enum class projection_method { first_angle, third_angle };

/// A drawing scale num:den (1:2 is {1, 2}; 2:1 is {2, 1}).
struct drawing_scale {
  long long num = 1, den = 1;
  double factor() const { return static_cast<double>(num) / static_cast<double>(den); }
  std::string text() const { return std::to_string(num) + ":" + std::to_string(den); }
};

/// A paper size in mm, landscape.
struct paper {
  std::string name;  ///< "A3", or "WxH" as given
  double width = 420, height = 297;
};

/// A section of the drawing: its letter and plane.
struct section_spec {
  std::string letter;             ///< "A".."Z" (one or two capitals)
  std::array<double, 4> plane{};  ///< a, b, c, d
};

/// A section's cut solid and cap, made by the caller (exbsp::gpl's section_with_cap: the cap
/// is the GPL part of the library).
struct section_cut {
  section_spec spec;
  triangle_soup solid;         ///< kept triangles and the cap, closed where the part is
  std::uint32_t cap_face = 0;  ///< face id of the cap triangles in `solid`
  /// The cap's outline loops (exact points rounded once), each closed (last != first).
  std::vector<std::vector<std::array<double, 3>>> loops;
};

/// What `exbsp drawing` may choose (flags of the command; scenes' "drawing" key).
struct drawing_options {
  std::vector<std::string> views{"front", "top", "left", "iso"};
  projection_method projection = projection_method::first_angle;
  paper sheet{"A3", 420, 297};
  std::optional<drawing_scale> scale;  ///< empty: auto
  std::string units = "mm";            ///< model units: mm, cm, m, in
  /// The model's up axis: "z" (CAD, the contract's default) or "y" (most OBJ/OFF/PLY files, and
  /// `exbsp render`): with "y" the front view looks from +z, the top view from +y.
  std::string up = "z";
  std::vector<section_spec> sections;
  bool lines_only = false;
  std::string title, number, date;  ///< title block fields (date: YYYY-MM-DD)
  double visible_width = 0.5,
         hidden_width = 0.25;       ///< mm (ISO 128 pairs: 0.7/0.35, 0.5/0.25, 0.35/0.18)
  double crease_deg = 30;           ///< feature edges: dihedral angle over this
  view::rgb8 color{176, 190, 214};  ///< the part's colour in shaded views (lit per view)
  build_options build;              ///< the BSP builds (kernel, fragment limit, progress)
};

/// The view names: front, top, left, right, bottom, rear, iso.
EXBSP_EXPORT const std::vector<std::string>& view_names();

/// A4 .. A0 (landscape) or "WxH" in mm (each in 10..10000). Throws usage_error naming `key`.
EXBSP_EXPORT paper parse_paper(const std::string& text, const std::string& key = "--sheet");
/// "1:N", "N:1" with N a positive integer (any, not only ISO 5455's). Throws usage_error.
EXBSP_EXPORT drawing_scale parse_scale(const std::string& text, const std::string& key = "--scale");
/// Millimetres per model unit: mm 1, cm 10, m 1000, in 25.4. Throws usage_error naming `key`.
EXBSP_EXPORT double unit_mm(const std::string& units, const std::string& key = "--units");
/// "first-angle" / "third-angle". Throws usage_error.
EXBSP_EXPORT projection_method parse_projection(const std::string& text,
                                                const std::string& key = "--projection");
/// "X=a,b,c,d" (X one or two capital letters, a..d finite doubles, (a, b, c) not zero).
/// Throws usage_error naming `key`.
EXBSP_EXPORT section_spec parse_section(const std::string& text,
                                        const std::string& key = "--section");
/// "front,top,left,iso": each a view_names() entry, no repeats. Throws usage_error.
EXBSP_EXPORT std::vector<std::string> parse_views(const std::string& text,
                                                  const std::string& key = "--views");

/// ISO 5455 scales from the smallest reduction to the largest enlargement that make sense for
/// a part of `extent` model units (every 1, 2, 5 step from 1:10^k to 10^k:1).
EXBSP_EXPORT std::vector<drawing_scale> standard_scales();

/// Today's date (UTC, YYYY-MM-DD), or that of SOURCE_DATE_EPOCH (seconds since 1970) when it is
/// set: the reproducible-builds convention, for sheets that must be byte-identical.
EXBSP_EXPORT std::string today_date();

/// Progress of make_sheet: a line per step (may be empty).
using sheet_progress = std::function<void(const std::string&)>;

/// The sheet of `part` (named `name` in the title block when options.title is empty) with
/// options' views and the sections in `cuts` (same order as options.sections). Throws
/// usage_error when the views do not fit the sheet at the asked scale (naming the largest that
/// fits) or an option is out of range, input_error naming `name` when the part has no triangle.
EXBSP_EXPORT sheet make_sheet(const triangle_soup& part, const std::string& name,
                              const std::vector<section_cut>& cuts, const drawing_options& options,
                              const sheet_progress& progress = {});

/// make_sheet of the part a built tree holds (tree.input(); e.g. a saved tree, bsp::load): the
/// part's views use `tree` as it is, without a build (sections still cut and build their own).
EXBSP_EXPORT sheet make_sheet(bsp tree, const std::string& name,
                              const std::vector<section_cut>& cuts, const drawing_options& options,
                              const sheet_progress& progress = {});

}  // namespace exbsp::drawing
