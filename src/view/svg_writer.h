// SPDX-License-Identifier: LGPL-3.0-or-later
// SVG output: the visible-region drawing (vector_drawing.h, the default) and the painter's
// stack ("svg": {"mode": "painter"}), a vector drawing that looks like the PNG.
//
// Notation (both): the SVG user space is the window with y flipped: (x_svg, y_svg) = (x - vp.x,
// vp.y + height - y), viewBox "0 0 width height", so window pixel (i, j) is the unit square
// at SVG (i, height - 1 - j) — the same place as in the PNG.
//
// Visible regions: <g id="underlay"> (one path per colour shared by several regions,
// vector_drawing.h), then one <g id="mesh-N"> per mesh holding one <path data-face="F"> per
// visible region (its rings in one path, nonzero fill, no stroke), then <g id="hidden-edges">
// (dashed) and <g id="visible-edges"> with one path per mesh (data-mesh="N"), then
// <g id="curves">. Coordinates are grid values / 100 (at most two decimals).
//
// The painter's stack: polygons are written in the order
// given (back to front), one closed <path> each, filled with the polygon's colour and stroked
// in the same colour with width svg_seam_stroke (round joins): anti-aliasing SVG renderers
// otherwise let the background shine through the shared edges of adjacent polygons
// ("conflation" seams). Each path carries data-face and data-fragment attributes (face id,
// fragment index).
// Curves (curves.h) are written in their painter's slots between the polygons: each run of
// pieces of one curve in one slot is one <path data-curve="K"> polyline, no fill, stroked in
// the curve's colour with width 1 (the PNG's 1-pixel lines), butt caps; a degree-0 curve is a
// 1 x 1 square. With a sample shader (sample_shader.h: fog) each polygon is filled with its
// colour shaded at its window centroid (flat: SVG has no per-pixel shading), each curve piece
// at its midpoint (one path per piece), and the background rectangle takes the shader's
// background.
//
// Placement (a viewport inside a larger "image", docs/contract.md "Scenes"): both documents are
// nested, unchanged, as an inner <svg x=".." y=".." width height> (which clips to the
// viewport, as the PNG's copy does) in an outer <svg> of the image's size whose background
// rectangle has the scene's background colour; y = image_height - place_y - height (SVG's y
// points down). The PNG's "place" stage (placement.h) puts the raster picture in the same place.
#pragma once
#include <string>
#include <vector>

#include <exbsp/view/sample_shader.h>
#include <exbsp/view/screen_line.h>
#include <exbsp/view/screen_polygon.h>
#include <exbsp/view/vector_drawing.h>

namespace exbsp::view {

/// Width in pixels of the same-colour stroke that closes anti-aliasing seams (0: no stroke).
constexpr double svg_seam_stroke = 0.5;

/// The SVG document: a background rectangle, then one path per polygon in order.
std::string svg_document(const viewport& vp, rgb8 background,
                         const std::vector<screen_polygon>& polygons);

/// The SVG document with curve pieces in their slots (lines sorted by slot) and, when `shader`
/// is not null, flat shading as described above.
std::string svg_document(const viewport& vp, rgb8 background,
                         const std::vector<screen_polygon>& polygons,
                         const std::vector<screen_line>& lines, const sample_shader* shader);

/// The SVG document of a visible-region drawing (notation above), placed in its image when
/// d.placed().
std::string svg_document(const vector_drawing& d);

/// `document` (an SVG document of a viewport `height` pixels high) nested in the image of
/// `placement` (notation above). Precondition: the viewport lies inside the image.
std::string place_svg(const std::string& document, int height, const drawing_placement& placement);

/// Stroke widths and dash pattern of edges (pixels), shared by the SVG and PDF writers.
constexpr double visible_edge_width = 1.0;
constexpr double hidden_edge_width = 0.6;
constexpr double hidden_edge_dash[2] = {3.0, 2.0};

/// svg_document written atomically to `path`. Throws output_error naming `path` on failure.
void write_svg(const std::string& path, const viewport& vp, rgb8 background,
               const std::vector<screen_polygon>& polygons);

}  // namespace exbsp::view
