// SPDX-License-Identifier: LGPL-3.0-or-later
// The pieces every SVG document of exbsp starts from (the drawing of a view, a section's
// outline, a clip's picture, a drawing sheet): the XML declaration, the root element, colours
// and escaped text. Each writer keeps its own content and number format (pixels, grid units,
// millimetres); these are the parts that must not drift between them.
#pragma once
#include <cstdio>
#include <string>

namespace exbsp::svg {

inline constexpr const char* xml_declaration = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";

/// `<svg xmlns="http://www.w3.org/2000/svg"[ attributes] width="W`unit`" height="H`unit`"
/// viewBox="0 0 W H">` and a newline: W and H in user units, `unit` (e.g. "mm") on the size.
inline std::string open_root(const std::string& w, const std::string& h,
                             const std::string& attributes = "", const std::string& unit = "") {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\"" +
         (attributes.empty() ? std::string() : " " + attributes) + " width=\"" + w + unit +
         "\" height=\"" + h + unit + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
}

/// "#rrggbb".
inline std::string hex_color(unsigned r, unsigned g, unsigned b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r & 255u, g & 255u, b & 255u);
  return buf;
}

/// Text with &, <, > and " escaped for XML content and attribute values; control characters
/// other than tab and newline (not allowed in XML 1.0) become spaces.
inline std::string xml_escape(const std::string& t) {
  std::string o;
  for (char c : t) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' ? ' ' : c;
    }
  }
  return o;
}

}  // namespace exbsp::svg
