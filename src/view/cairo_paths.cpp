// SPDX-License-Identifier: LGPL-3.0-or-later
// Vector paths on a cairo context (notation in cairo_paths.h).
#include "view/cairo_paths.h"

#include "view/svg_writer.h"

namespace exbsp::view {

namespace {

void set_color(cairo_t* cr, rgb8 c) {
  cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

}  // namespace

void draw_paths_only(cairo_t* cr, const vector_drawing& d) {
  const double h = d.height;
  const double unit = 1.0 / static_cast<double>(grid_per_pixel);
  auto move_line = [&](const std::vector<grid_point>& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const double x = ring[k].x * unit, y = h - ring[k].y * unit;
      if (k == 0)
        cairo_move_to(cr, x, y);
      else
        cairo_line_to(cr, x, y);
    }
  };
  for (const vector_path& p : d.paths) {
    set_color(cr, p.color);
    switch (p.kind) {
      case vector_path::kind_type::underlay:
      case vector_path::kind_type::region:
        for (const auto& ring : p.rings) {
          move_line(ring);
          cairo_close_path(cr);
        }
        cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
        cairo_fill(cr);
        break;
      case vector_path::kind_type::visible_edge:
      case vector_path::kind_type::hidden_edge:
      case vector_path::kind_type::curve: {
        for (const auto& ring : p.rings) move_line(ring);
        const bool hidden = p.kind == vector_path::kind_type::hidden_edge;
        const bool edge = p.kind != vector_path::kind_type::curve;
        cairo_set_line_width(cr, hidden ? hidden_edge_width : edge ? visible_edge_width : 1.0);
        cairo_set_dash(cr, hidden ? hidden_edge_dash : nullptr, hidden ? 2 : 0, 0);
        cairo_set_line_cap(cr, edge && !hidden ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
        cairo_set_line_join(cr, edge && !hidden ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_MITER);
        cairo_stroke(cr);
        break;
      }
      case vector_path::kind_type::point:
        cairo_rectangle(cr, p.rings[0][0].x * unit - 0.5, h - p.rings[0][0].y * unit - 0.5, 1, 1);
        cairo_fill(cr);
        break;
    }
  }
}

void draw_vector_paths(cairo_t* cr, const vector_drawing& d) {
  set_color(cr, d.background);
  cairo_rectangle(cr, 0, 0, d.width, d.height);
  cairo_fill(cr);
  draw_paths_only(cr, d);
}

}  // namespace exbsp::view
