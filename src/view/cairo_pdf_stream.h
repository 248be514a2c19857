// SPDX-License-Identifier: LGPL-3.0-or-later
// Private: the cairo PDF surface both PDF writers draw on (vector_pdf.cpp, the drawing sheets'
// sheet_writers.cpp): a stream surface that appends the document to a string, and the end of a
// document, where cairo's deferred errors surface.
#pragma once
#include <cairo-pdf.h>
#include <cairo.h>

#include <memory>
#include <string>

#include <exbsp/core/errors.h>

namespace exbsp::view {

/// A PDF surface of width x height points whose bytes are appended to `out`.
inline std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> pdf_stream_surface(
    std::string& out, double width, double height) {
  const auto append = [](void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  };
  return {cairo_pdf_surface_create_for_stream(append, &out, width, height), cairo_surface_destroy};
}

/// Ends the page and the document: shows the page, destroys the context, finishes the surface.
/// Throws usage_error with cairo's message when drawing or finishing failed.
inline void finish_pdf(std::unique_ptr<cairo_t, decltype(&cairo_destroy)>& context,
                       cairo_surface_t* surface) {
  cairo_show_page(context.get());
  const cairo_status_t status = cairo_status(context.get());
  if (status != CAIRO_STATUS_SUCCESS)
    throw usage_error(std::string("PDF output: cairo: ") + cairo_status_to_string(status));
  context.reset();
  cairo_surface_finish(surface);
  const cairo_status_t finished = cairo_surface_status(surface);
  if (finished != CAIRO_STATUS_SUCCESS)
    throw usage_error(std::string("PDF output: cairo: ") + cairo_status_to_string(finished));
}

}  // namespace exbsp::view
