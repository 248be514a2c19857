// SPDX-License-Identifier: LGPL-3.0-or-later
// The option values of a drawing: ISO 216 paper sizes, ISO 5455 scales, units, projection
// methods, views and section planes (drawing.h).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <exbsp/core/errors.h>
#include "drawing/drawing.h"

namespace exbsp::drawing {

namespace {

/// A whole decimal number in 1..limit, or 0 when `text` is not one.
long long positive_integer(const std::string& text, long long limit) {
  if (text.empty() || text.size() > 12) return 0;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return 0;
  const long long v = std::stoll(text);
  return v >= 1 && v <= limit ? v : 0;
}

/// A finite double spelled as the whole of `text`, or nothing.
std::optional<double> finite_number(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(sep, start);
    parts.push_back(text.substr(start, at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

}  // namespace

const std::vector<std::string>& view_names() {
  static const std::vector<std::string> names{"front",  "top",  "left", "right",
                                              "bottom", "rear", "iso"};
  return names;
}

paper parse_paper(const std::string& text, const std::string& key) {
  // ISO 216, landscape.
  static const paper sizes[] = {
      {"A0", 1189, 841}, {"A1", 841, 594}, {"A2", 594, 420}, {"A3", 420, 297}, {"A4", 297, 210}};
  for (const paper& p : sizes)
    if (text == p.name ||
        (text.size() == 2 && std::toupper(static_cast<unsigned char>(text[0])) == 'A' &&
         text[1] == p.name[1]))
      return p;
  const std::size_t x = text.find('x');
  if (x != std::string::npos) {
    const auto w = finite_number(text.substr(0, x)), h = finite_number(text.substr(x + 1));
    if (w && h && *w >= 10 && *w <= 10000 && *h >= 10 && *h <= 10000) return {text, *w, *h};
  }
  throw usage_error(key +
                    ": expected A4, A3, A2, A1, A0 or WxH in millimetres (each 10..10000), "
                    "got '" +
                    text + "'");
}

drawing_scale parse_scale(const std::string& text, const std::string& key) {
  const std::size_t colon = text.find(':');
  if (colon != std::string::npos) {
    const long long a = positive_integer(text.substr(0, colon), 1000000);
    const long long b = positive_integer(text.substr(colon + 1), 1000000);
    if (a && b && (a == 1 || b == 1)) return {a, b};
  }
  throw usage_error(key + ": expected auto, 1:N or N:1 (N a whole number 1..1000000), got '" +
                    text + "'");
}

double unit_mm(const std::string& units, const std::string& key) {
  if (units == "mm") return 1;
  if (units == "cm") return 10;
  if (units == "m") return 1000;
  if (units == "in") return 25.4;
  throw usage_error(key + ": expected mm, cm, m or in, got '" + units + "'");
}

projection_method parse_projection(const std::string& text, const std::string& key) {
  if (text == "first-angle") return projection_method::first_angle;
  if (text == "third-angle") return projection_method::third_angle;
  throw usage_error(key + ": expected first-angle or third-angle, got '" + text + "'");
}

section_spec parse_section(const std::string& text, const std::string& key) {
  const std::string expected =
      key +
      ": expected X=a,b,c,d (X one or two capital letters; the plane a*x+b*y+c*z+d = 0, "
      "the side >= 0 kept), got '" +
      text + "'";
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq > 2) throw usage_error(expected);
  section_spec s;
  s.letter = text.substr(0, eq);
  for (char c : s.letter)
    if (c < 'A' || c > 'Z') throw usage_error(expected);
  const std::vector<std::string> parts = split(text.substr(eq + 1), ',');
  if (parts.size() != 4) throw usage_error(expected);
  for (int k = 0; k < 4; ++k) {
    const auto v = finite_number(parts[static_cast<std::size_t>(k)]);
    if (!v) throw usage_error(expected);
    s.plane[static_cast<std::size_t>(k)] = *v;
  }
  if (s.plane[0] == 0 && s.plane[1] == 0 && s.plane[2] == 0)
    throw usage_error(key + ": the plane's normal (a, b, c) is zero in '" + text + "'");
  const double n = std::hypot(s.plane[0], s.plane[1], s.plane[2]);
  if (!std::isfinite(n) || !(n > 1e-150))
    throw usage_error(key + ": the plane's normal (a, b, c) is too large or too small in '" + text +
                      "'");
  return s;
}

std::vector<std::string> parse_views(const std::string& text, const std::string& key) {
  std::vector<std::string> views;
  for (const std::string& v : split(text, ',')) {
    if (std::find(view_names().begin(), view_names().end(), v) == view_names().end())
      throw usage_error(key + ": unknown view '" + v +
                        "' (expected front, top, left, right, bottom, rear or iso)");
    if (std::find(views.begin(), views.end(), v) != views.end())
      throw usage_error(key + ": view '" + v + "' is listed twice");
    views.push_back(v);
  }
  return views;
}

std::vector<drawing_scale> standard_scales() {
  std::vector<drawing_scale> s;
  // Reductions 1:10^6 .. 1:2, full size, enlargements 2:1 .. 10^6:1 in the 1-2-5 series.
  const long long steps[] = {1, 2, 5};
  std::vector<long long> series;
  for (long long p = 1; p <= 1000000; p *= 10)
    for (long long m : steps)
      if (m * p <= 1000000) series.push_back(m * p);
  for (auto it = series.rbegin(); it != series.rend(); ++it)
    if (*it > 1) s.push_back({1, *it});
  s.push_back({1, 1});
  for (long long v : series)
    if (v > 1) s.push_back({v, 1});
  return s;
}

}  // namespace exbsp::drawing
