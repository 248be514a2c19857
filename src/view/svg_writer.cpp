// SPDX-License-Identifier: LGPL-3.0-or-later
// SVG writer (notation in svg_writer.h). Coordinates are printed with std::to_chars, the
// shortest text that reads back as the same double.
#include "view/svg_writer.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <utility>

#include "core/atomic_file.h"
#include "core/svg_text.h"
#include "view/workers.h"

namespace exbsp::view {

namespace {

void append_number(std::string& out, double v) {
  if (v == 0) v = 0;  // no "-0"
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

std::string hex_color(rgb8 c) { return svg::hex_color(c.r, c.g, c.b); }

/// A grid value as pixels: v / 100 with at most two decimals ("12", "12.5", "-0.25").
void append_grid(std::string& out, long long v) {
  char buf[32];
  char* end = buf;
  if (v < 0) {
    *end++ = '-';
    v = -v;
  }
  end = std::to_chars(end, buf + sizeof buf, v / grid_per_pixel).ptr;
  const long long frac = v % grid_per_pixel;
  if (frac != 0) {
    *end++ = '.';
    *end++ = static_cast<char>('0' + frac / 10);
    if (frac % 10 != 0) *end++ = static_cast<char>('0' + frac % 10);
  }
  out.append(buf, end);
}

/// The group (<g>) a path of a drawing is drawn in: its id and attributes.
std::pair<std::string, std::string> group_of(const vector_path& p, const char* dash) {
  switch (p.kind) {
    case vector_path::kind_type::underlay:
      return {"underlay", ""};
    case vector_path::kind_type::region:
      return {"mesh-" + std::to_string(p.mesh), ""};
    case vector_path::kind_type::hidden_edge:
    case vector_path::kind_type::visible_edge: {
      const bool hidden = p.kind == vector_path::kind_type::hidden_edge;
      char width[32];
      std::snprintf(width, sizeof width, "%g", hidden ? hidden_edge_width : visible_edge_width);
      return {
          hidden ? "hidden-edges" : "visible-edges",
          std::string(" fill=\"none\" stroke-width=\"") + width + "\"" +
              (hidden ? std::string(" stroke-dasharray=\"") + dash + "\" stroke-linecap=\"butt\""
                      : std::string(" stroke-linecap=\"round\" stroke-linejoin=\"round\""))};
    }
    case vector_path::kind_type::curve:
    case vector_path::kind_type::point:
      return {"curves", " fill=\"none\" stroke-width=\"1\" stroke-linecap=\"butt\""};
  }
  return {"", ""};
}

/// The element of path p (without its group).
void append_path(std::string& out, const vector_path& p, long long y_top) {
  const std::string color = hex_color(p.color);
  auto point = [&](const grid_point& q) {
    append_grid(out, q.x);
    out += ' ';
    append_grid(out, y_top - q.y);
  };
  auto rings = [&](bool closed) {
    bool first = true;
    for (const std::vector<grid_point>& ring : p.rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        out += k == 0 ? (first ? "M" : " M") : " L";
        point(ring[k]);
      }
      if (closed) out += " Z";
      first = false;
    }
  };
  auto path = [&](const std::string& attributes, bool closed) {
    out += "<path " + attributes + " d=\"";
    rings(closed);
    out += "\"/>\n";
  };
  switch (p.kind) {
    case vector_path::kind_type::underlay:
      path("fill=\"" + color + "\"", true);
      break;
    case vector_path::kind_type::region:
      path("data-face=\"" + std::to_string(p.face) + "\" fill=\"" + color + "\"", true);
      break;
    case vector_path::kind_type::hidden_edge:
    case vector_path::kind_type::visible_edge:
      path("data-mesh=\"" + std::to_string(p.mesh) + "\" stroke=\"" + color + "\"", false);
      break;
    case vector_path::kind_type::curve:
      path("data-curve=\"" + std::to_string(p.face) + "\" stroke=\"" + color + "\"", false);
      break;
    case vector_path::kind_type::point:
      out += "<rect data-curve=\"" + std::to_string(p.face) + "\" x=\"";
      append_grid(out, p.rings[0][0].x - grid_per_pixel / 2);
      out += "\" y=\"";
      append_grid(out, y_top - p.rings[0][0].y - grid_per_pixel / 2);
      out += "\" width=\"1\" height=\"1\" fill=\"" + color + "\"/>\n";
      break;
  }
}

}  // namespace

std::string svg_document(const vector_drawing& d) {
  std::string out;
  const std::string w = std::to_string(d.width), h = std::to_string(d.height);
  const long long y_top = static_cast<long long>(d.height) * grid_per_pixel;
  out += svg::xml_declaration;
  out += svg::open_root(w, h, "version=\"1.1\"");
  out += "<rect x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"" +
         hex_color(d.background) + "\"/>\n";
  char dash[64];
  std::snprintf(dash, sizeof dash, "%g %g", hidden_edge_dash[0], hidden_edge_dash[1]);
  // A path's group depends on the path alone, so blocks of paths are written on the workers,
  // each opening a group where its path's differs from the one before, and joined in order.
  const std::vector<vector_path>& paths = d.paths;
  constexpr std::size_t block = 2048;
  std::vector<std::string> parts((paths.size() + block - 1) / block);
  parallel_for(parts.size(), hardware_workers(), [&](std::size_t b, unsigned) {
    std::string& part = parts[b];
    std::string previous = b == 0 ? std::string() : group_of(paths[b * block - 1], dash).first;
    for (std::size_t i = b * block; i < std::min(paths.size(), (b + 1) * block); ++i) {
      auto [id, attributes] = group_of(paths[i], dash);
      if (id != previous) {
        if (!previous.empty()) part += "</g>\n";
        part += "<g id=\"" + id + "\"" + attributes + ">\n";
        previous = std::move(id);
      }
      append_path(part, paths[i], y_top);
    }
  });
  std::size_t size = out.size() + 16;
  for (const std::string& part : parts) size += part.size();
  out.reserve(size);
  for (const std::string& part : parts) out += part;
  if (!paths.empty()) out += "</g>\n";
  out += "</svg>\n";
  return d.placed() ? place_svg(out, d.height, d.placement) : out;
}

std::string place_svg(const std::string& document, int height, const drawing_placement& placement) {
  std::string inner = document;
  if (inner.compare(0, 5, "<?xml") == 0) inner.erase(0, inner.find('\n') + 1);
  const std::string x = std::to_string(placement.x),
                    y = std::to_string(placement.image_height - placement.y - height);
  inner.replace(inner.find("<svg "), 5, "<svg x=\"" + x + "\" y=\"" + y + "\" ");
  const std::string iw = std::to_string(placement.image_width),
                    ih = std::to_string(placement.image_height);
  return svg::xml_declaration + svg::open_root(iw, ih, "version=\"1.1\"") +
         "<rect x=\"0\" y=\"0\" width=\"" + iw + "\" height=\"" + ih + "\" fill=\"" +
         hex_color(placement.background) + "\"/>\n" + inner + "</svg>\n";
}

std::string svg_document(const viewport& vp, rgb8 background,
                         const std::vector<screen_polygon>& polygons) {
  return svg_document(vp, background, polygons, {}, nullptr);
}

std::string svg_document(const viewport& vp, rgb8 background,
                         const std::vector<screen_polygon>& polygons,
                         const std::vector<screen_line>& lines, const sample_shader* shader) {
  std::string out;
  out.reserve(256 + polygons.size() * 120 + lines.size() * 40);
  const std::string w = std::to_string(vp.width), h = std::to_string(vp.height);
  out += svg::xml_declaration;
  out += svg::open_root(w, h, "version=\"1.1\"");
  out += "<rect x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"" +
         hex_color(shader ? shader->background : background) + "\"/>\n";
  if (svg_seam_stroke > 0) {
    out += "<g stroke-width=\"";
    append_number(out, svg_seam_stroke);
    out += "\" stroke-linejoin=\"round\">\n";
  }
  const double y_top = static_cast<double>(vp.y) + vp.height;
  auto point = [&](double x, double y) {
    append_number(out, x - vp.x);
    out += ' ';
    append_number(out, y_top - y);
  };
  std::size_t next_line = 0;
  // Curve pieces of slot k: maximal runs of one curve joined end to end become one polyline.
  auto write_lines = [&](std::size_t slot) {
    while (next_line < lines.size() && lines[next_line].slot <= slot) {
      const screen_line& first = lines[next_line];
      rgb8 c = first.color;
      if (shader) {
        const double mx = 0.5 * (first.a.x + first.b.x), my = 0.5 * (first.a.y + first.b.y),
                     mz = 0.5 * (first.a.z + first.b.z);
        c = shader->shade(c, mx, my, mz);
      }
      const std::string color = hex_color(c);
      if (first.point) {
        out += "<rect data-curve=\"" + std::to_string(first.curve) + "\" x=\"";
        append_number(out, first.a.x - vp.x - 0.5);
        out += "\" y=\"";
        append_number(out, y_top - first.a.y - 0.5);
        out += "\" width=\"1\" height=\"1\" stroke=\"none\" fill=\"" + color + "\"/>\n";
        ++next_line;
        continue;
      }
      out += "<path data-curve=\"" + std::to_string(first.curve) + "\" fill=\"none\" stroke=\"" +
             color + "\" stroke-width=\"1\" stroke-linecap=\"butt\" d=\"M";
      point(first.a.x, first.a.y);
      out += " L";
      point(first.b.x, first.b.y);
      ++next_line;
      while (!shader && next_line < lines.size()) {
        const screen_line& l = lines[next_line];
        const screen_line& prev = lines[next_line - 1];
        if (l.point || l.slot != prev.slot || l.curve != prev.curve || l.a.x != prev.b.x ||
            l.a.y != prev.b.y)
          break;
        out += " L";
        point(l.b.x, l.b.y);
        ++next_line;
      }
      out += "\"/>\n";
    }
  };
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    write_lines(k);
    const screen_polygon& p = polygons[k];
    if (p.v.size() < 3) continue;
    rgb8 fill = p.color;
    if (shader) {
      double cx = 0, cy = 0, cz = 0;
      for (const window_point& v : p.v) {
        cx += v.x;
        cy += v.y;
        cz += v.z;
      }
      const double n = static_cast<double>(p.v.size());
      fill = shader->shade(fill, cx / n, cy / n, cz / n);
    }
    const std::string color = hex_color(fill);
    out += "<path data-face=\"" + std::to_string(p.face) + "\" data-fragment=\"" +
           std::to_string(p.fragment) + "\" fill=\"" + color + "\" stroke=\"" + color + "\" d=\"";
    for (std::size_t k2 = 0; k2 < p.v.size(); ++k2) {
      out += k2 == 0 ? "M" : " L";
      point(p.v[k2].x, p.v[k2].y);
    }
    out += " Z\"/>\n";
  }
  write_lines(polygons.size());
  if (svg_seam_stroke > 0) out += "</g>\n";
  out += "</svg>\n";
  return out;
}

void write_svg(const std::string& path, const viewport& vp, rgb8 background,
               const std::vector<screen_polygon>& polygons) {
  write_file_atomically(path, svg_document(vp, background, polygons));
}

}  // namespace exbsp::view
