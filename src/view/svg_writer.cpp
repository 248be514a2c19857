// SVG writer (notation in svg_writer.h). Coordinates are printed with std::to_chars, the
// shortest text that reads back as the same double.
#include "view/svg_writer.h"

#include <charconv>
#include <cstdio>

#include "view/atomic_file.h"

namespace exbsp::view {

namespace {

void append_number(std::string& out, double v) {
  if (v == 0) v = 0;  // no "-0"
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

std::string hex_color(rgb8 c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

}  // namespace

std::string svg_document(const viewport& vp, rgb8 background, const std::vector<screen_polygon>& polygons) {
  std::string out;
  out.reserve(256 + polygons.size() * 120);
  const std::string w = std::to_string(vp.width), h = std::to_string(vp.height);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + w + "\" height=\"" + h +
         "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"" + hex_color(background) + "\"/>\n";
  if (svg_seam_stroke > 0) {
    out += "<g stroke-width=\"";
    append_number(out, svg_seam_stroke);
    out += "\" stroke-linejoin=\"round\">\n";
  }
  const double y_top = static_cast<double>(vp.y) + vp.height;
  for (const screen_polygon& p : polygons) {
    if (p.v.size() < 3) continue;
    const std::string color = hex_color(p.color);
    out += "<path data-face=\"" + std::to_string(p.face) + "\" data-fragment=\"" + std::to_string(p.fragment) +
           "\" fill=\"" + color + "\" stroke=\"" + color + "\" d=\"";
    for (std::size_t k = 0; k < p.v.size(); ++k) {
      out += k == 0 ? "M" : " L";
      append_number(out, p.v[k].x - vp.x);
      out += ' ';
      append_number(out, y_top - p.v[k].y);
    }
    out += " Z\"/>\n";
  }
  if (svg_seam_stroke > 0) out += "</g>\n";
  out += "</svg>\n";
  return out;
}

void write_svg(const std::string& path, const viewport& vp, rgb8 background,
               const std::vector<screen_polygon>& polygons) {
  write_file_atomically(path, svg_document(vp, background, polygons));
}

}  // namespace exbsp::view
