// SPDX-License-Identifier: LGPL-3.0-or-later
// SVG and PDF writers of a drawing sheet (notation in sheet_writers.h).
#include "drawing/sheet_writers.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include <exbsp/core/errors.h>
#include "view/cairo_pdf_stream.h"
#include "core/svg_text.h"

namespace exbsp::drawing {

namespace {

/// A number with at most 4 decimals, trailing zeros dropped ("-0" printed as "0").
void put_number(std::string& out, double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  std::string t = buf;
  while (!t.empty() && t.back() == '0') t.pop_back();
  if (!t.empty() && t.back() == '.') t.pop_back();
  if (t == "-0") t = "0";
  out += t;
}

std::string number(double v) {
  std::string s;
  put_number(s, v);
  return s;
}

void put_path(std::string& out, const std::vector<point2>& pts, bool closed, double h) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    out += i == 0 ? 'M' : 'L';
    put_number(out, pts[i].x);
    out += ' ';
    put_number(out, h - pts[i].y);
  }
  if (closed) out += 'Z';
}

std::string hex(view::rgb8 c) { return svg::hex_color(c.r, c.g, c.b); }
using svg::xml_escape;

constexpr const char* font_family = "DejaVu Sans";

}  // namespace

std::string sheet_svg(const sheet& s) {
  const double h = s.height;
  std::string out;
  out.reserve(1 << 20);
  out += svg::xml_declaration;
  out += svg::open_root(number(s.width), number(s.height),
                        "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"", "mm");
  out += "<title>" + xml_escape(s.title) + "</title>\n";
  out += "<rect width=\"" + number(s.width) + "\" height=\"" + number(s.height) +
         "\" fill=\"#ffffff\"/>\n";
  for (const auto& [layer, layer_text] : layer_table) {
    const std::string name = layer_text;
    out += "<g inkscape:groupmode=\"layer\" inkscape:label=\"" + name + "\" id=\"layer-" + name +
           "\" fill=\"none\" stroke=\"#000000\">\n";
    for (const sheet_fill& f : s.fills) {
      if (f.layer != layer) continue;
      out += "<path fill=\"" + hex(f.color) + "\" stroke=\"none\" d=\"";
      for (const auto& r : f.rings) put_path(out, r, true, h);
      out += "\"/>\n";
    }
    for (const sheet_polyline& l : s.lines) {
      if (l.layer != layer || l.points.size() < 2) continue;
      out += "<path stroke-width=\"" + number(l.width) + "\"";
      const std::vector<double> dash = dash_pattern(l.style, l.width);
      if (dash.empty()) {
        out += " stroke-linecap=\"round\" stroke-linejoin=\"round\"";
      } else {
        out += " stroke-linecap=\"butt\" stroke-linejoin=\"miter\" stroke-dasharray=\"";
        for (std::size_t i = 0; i < dash.size(); ++i) {
          if (i) out += ' ';
          put_number(out, dash[i]);
        }
        out += "\"";
      }
      out += " d=\"";
      put_path(out, l.points, l.closed, h);
      out += "\"/>\n";
    }
    for (const sheet_text& t : s.texts) {
      if (t.layer != layer) continue;
      const char* anchor = t.anchor == sheet_text::anchor_kind::start    ? "start"
                           : t.anchor == sheet_text::anchor_kind::middle ? "middle"
                                                                         : "end";
      out += "<text x=\"" + number(t.at.x) + "\" y=\"" + number(h - t.at.y) + "\" font-family=\"" +
             font_family + ", Arial, sans-serif\" font-size=\"" +
             number(t.height / cap_height_per_em) + "\" text-anchor=\"" + anchor +
             "\" fill=\"#000000\" stroke=\"none\">" + xml_escape(t.text) + "</text>\n";
    }
    out += "</g>\n";
  }
  out += "</svg>\n";
  return out;
}

std::string sheet_pdf(const sheet& s, const std::string& date) {
  std::string bytes;
  const double pt = 72 / 25.4;
  const double h = s.height;
  {
    const auto surface = view::pdf_stream_surface(bytes, s.width * pt, s.height * pt);
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "exbsp");
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, s.title.c_str());
    const std::string stamp = date + "T00:00:00Z";
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, stamp.c_str());
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()),
                                                               cairo_destroy);
    cairo_t* cr = context.get();
    cairo_scale(cr, pt, pt);  // user space: mm, y down
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    const auto trace = [&](const std::vector<point2>& pts, bool closed) {
      for (std::size_t i = 0; i < pts.size(); ++i) {
        if (i == 0)
          cairo_move_to(cr, pts[i].x, h - pts[i].y);
        else
          cairo_line_to(cr, pts[i].x, h - pts[i].y);
      }
      if (closed) cairo_close_path(cr);
    };
    cairo_select_font_face(cr, font_family, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    for (const auto& row : layer_table) {
      const layer_id layer = row.value;
      for (const sheet_fill& f : s.fills) {
        if (f.layer != layer) continue;
        cairo_set_source_rgb(cr, f.color.r / 255.0, f.color.g / 255.0, f.color.b / 255.0);
        for (const auto& r : f.rings) trace(r, true);
        cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
        cairo_fill(cr);
      }
      cairo_set_source_rgb(cr, 0, 0, 0);
      for (const sheet_polyline& l : s.lines) {
        if (l.layer != layer || l.points.size() < 2) continue;
        trace(l.points, l.closed);
        const std::vector<double> dash = dash_pattern(l.style, l.width);
        cairo_set_line_width(cr, l.width);
        cairo_set_dash(cr, dash.empty() ? nullptr : dash.data(), static_cast<int>(dash.size()), 0);
        cairo_set_line_cap(cr, dash.empty() ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
        cairo_set_line_join(cr, dash.empty() ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_MITER);
        cairo_stroke(cr);
      }
      for (const sheet_text& t : s.texts) {
        if (t.layer != layer) continue;
        cairo_set_font_size(cr, t.height / cap_height_per_em);
        cairo_text_extents_t e;
        cairo_text_extents(cr, t.text.c_str(), &e);
        double x = t.at.x;
        if (t.anchor == sheet_text::anchor_kind::middle) x -= e.x_advance / 2;
        if (t.anchor == sheet_text::anchor_kind::end) x -= e.x_advance;
        cairo_move_to(cr, x, h - t.at.y);
        cairo_show_text(cr, t.text.c_str());
        cairo_new_path(cr);
      }
    }
    view::finish_pdf(context, surface.get());
  }
  return bytes;
}

}  // namespace exbsp::drawing
