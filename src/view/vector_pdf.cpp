// SPDX-License-Identifier: LGPL-3.0-or-later
// cairo PDF writer (notation in vector_pdf.h).
#include "view/vector_pdf.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <memory>

#include <exbsp/core/errors.h>
#include "view/cairo_paths.h"
#include "view/cairo_pdf_stream.h"
#include "view/svg_writer.h"

namespace exbsp::view {

std::string pdf_document(const vector_drawing& d) {
  std::string bytes;
  const bool placed = d.placed();
  const drawing_placement& place = d.placement;
  {
    const auto surface = pdf_stream_surface(bytes, placed ? place.image_width : d.width,
                                            placed ? place.image_height : d.height);
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "exbsp");
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()),
                                                               cairo_destroy);
    cairo_t* cr = context.get();
    if (placed) {  // the image's background, then the drawing translated and clipped to its
                   // viewport
      cairo_set_source_rgb(cr, place.background.r / 255.0, place.background.g / 255.0,
                           place.background.b / 255.0);
      cairo_paint(cr);
      cairo_translate(cr, place.x, place.image_height - place.y - d.height);
      cairo_rectangle(cr, 0, 0, d.width, d.height);
      cairo_clip(cr);
    }
    draw_vector_paths(cr, d);
    view::finish_pdf(context, surface.get());
  }
  return bytes;
}

}  // namespace exbsp::view
