// SPDX-License-Identifier: LGPL-3.0-or-later
// The "edges" stage of a PNG (stages.h): the hidden-line drawing's edge paths over the
// painter's picture.
//
// The paths are the SVG's (edge_paths.h), on the drawing grid of 1/100 pixel; cairo strokes
// them anti-aliased on an RGB24 image surface that holds a copy of the picture (cairo draws
// lines; writing a coverage-based line rasterizer by hand would repeat it). Pixel (i, j) of
// the picture (window coordinates, j up) is surface pixel (i, height - 1 - j), so the grid
// point (X, Y) lands at (X / 100, height - Y / 100) as in the SVG.
#include <cairo.h>

#include <cstdint>
#include <memory>
#include <string>

#include <exbsp/core/errors.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/stages.h>
#include "view/cairo_paths.h"
#include "view/edge_paths.h"

namespace exbsp::view {

std::string raster_edges_stage(frame& f) {
  const vector_options& want = f.raster_edges;
  if (want.edges == vector_options::edges_kind::none) return "no edges asked for";
  if (!(want.crease_deg > 0 && want.crease_deg <= 180))
    throw usage_error("raster: crease_deg must be in (0, 180], got " +
                      std::to_string(want.crease_deg));
  const int w = f.picture.width(), h = f.picture.height();
  if (f.wireframe) f.picture = image(w, h, f.background);
  vector_drawing d;
  d.width = w;
  d.height = h;
  add_edge_paths(f, want, d);
  if (f.wireframe)
    for (vector_path& p : d.paths)
      if (p.kind == vector_path::kind_type::hidden_edge)
        p.kind = vector_path::kind_type::visible_edge;
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h), cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw usage_error(std::string("raster edges: cairo: ") +
                      cairo_status_to_string(cairo_surface_status(surface.get())));
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  cairo_surface_flush(surface.get());
  for (int row = 0; row < h; ++row) {
    auto* out = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(row) * stride);
    for (int col = 0; col < w; ++col) {
      const rgb8 c = f.picture.at_row(row, col);
      out[col] = (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
    }
  }
  cairo_surface_mark_dirty(surface.get());
  {
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()),
                                                               cairo_destroy);
    draw_paths_only(context.get(), d);
    if (cairo_status(context.get()) != CAIRO_STATUS_SUCCESS)
      throw usage_error(std::string("raster edges: cairo: ") +
                        cairo_status_to_string(cairo_status(context.get())));
  }
  cairo_surface_flush(surface.get());
  for (int row = 0; row < h; ++row) {
    const auto* in =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<std::size_t>(row) * stride);
    for (int col = 0; col < w; ++col)
      f.picture.set_at_row(
          row, col,
          {static_cast<std::uint8_t>(in[col] >> 16), static_cast<std::uint8_t>(in[col] >> 8),
           static_cast<std::uint8_t>(in[col])});
  }
  const drawing_counts c = count_paths(d);
  if (f.wireframe)
    return std::to_string(c.visible_edges) + " edge pieces, a wireframe of " + std::to_string(w) +
           "x" + std::to_string(h);
  return std::to_string(c.visible_edges) + " visible and " + std::to_string(c.hidden_edges) +
         " hidden edge pieces drawn over " + std::to_string(w) + "x" + std::to_string(h);
}

}  // namespace exbsp::view
