// SPDX-License-Identifier: LGPL-3.0-or-later
// Output formats of `exbsp section` (section.h): JSON like `exbsp order`'s fragments, OFF of
// kept ∪ cap, and an SVG of the outline in the cut plane. The JSON is text built with
// core/json_text.h, so that doubles print with 17 significant digits exactly as `order` does.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>

#include <exbsp/clip/section.h>
#include "core/json_text.h"
#include "core/svg_text.h"

namespace exbsp {

namespace {

using json_text::number;

/// A pixel coordinate rounded to 1/100, without trailing zeros.
std::string px(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  std::string t = buf;
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  return t == "-0" ? "0" : t;
}

void append_point(std::string& out, const section_point& p) { json_text::append_point(out, p.v); }

void append_exact(std::string& out, const section_point& p) {
  json_text::append_exact_point(out, p.exact);
}

/// "v": [...], "exact": [...] of a list of point indices.
void append_points(std::string& out, const section_result& r, const std::uint32_t* idx,
                   std::size_t n) {
  out += "\"v\": [";
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ", ";
    append_point(out, r.points[idx[i]]);
  }
  out += "], \"exact\": [";
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ", ";
    append_exact(out, r.points[idx[i]]);
  }
  out += "]";
}

double dot(const vec3d& a, const vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

std::string section_json(const section_result& r) {
  std::string out = "{\"plane\": [" + number(r.plane[0]) + ", " + number(r.plane[1]) + ", " +
                    number(r.plane[2]) + ", " + number(r.plane[3]) +
                    "],\n \"closed\": " + (r.closed ? "true" : "false") + ",\n \"kept\": [";
  for (std::size_t i = 0; i < r.kept.size(); ++i) {
    out += i ? ",\n  {\"face\": " : "\n  {\"face\": ";
    out += std::to_string(r.kept[i].face) + ", ";
    append_points(out, r, r.kept[i].p.data(), 3);
    out += "}";
  }
  out += "\n ],\n \"outline\": [";
  for (std::size_t i = 0; i < r.outline.size(); ++i) {
    out += i ? ",\n  {\"closed\": " : "\n  {\"closed\": ";
    out += r.outline[i].closed ? "true, " : "false, ";
    append_points(out, r, r.outline[i].p.data(), r.outline[i].p.size());
    out += "}";
  }
  out += "\n ],\n \"cap\": [";
  for (std::size_t i = 0; i < r.cap.size(); ++i) {
    out += i ? ",\n  {" : "\n  {";
    append_points(out, r, r.cap[i].p.data(), 3);
    out += "}";
  }
  out += "\n ],\n \"stats\": {";
  const char* separator = "";
  for_each_section_stat(r, [&](const char* name, auto value) {
    out += separator + std::string("\"") + name + "\": ";
    if constexpr (std::is_floating_point_v<decltype(value)>)
      out += number(value);
    else
      out += std::to_string(value);
    separator = ", ";
  });
  out += "}}\n";
  return out;
}

std::string section_off(const section_result& r) {
  // Only the points of kept and cap triangles (outline points are among them).
  std::vector<std::uint32_t> index(r.points.size(), UINT32_MAX);
  std::vector<std::uint32_t> order;
  for (const auto* list : {&r.kept, &r.cap})
    for (const section_triangle& t : *list)
      for (std::uint32_t p : t.p)
        if (index[p] == UINT32_MAX) {
          index[p] = static_cast<std::uint32_t>(order.size());
          order.push_back(p);
        }
  std::string out = "OFF\n" + std::to_string(order.size()) + " " +
                    std::to_string(r.kept.size() + r.cap.size()) + " 0\n";
  for (std::uint32_t p : order) {
    const vec3d& v = r.points[p].v;
    out += number(v[0]) + " " + number(v[1]) + " " + number(v[2]) + "\n";
  }
  for (const auto* list : {&r.kept, &r.cap})
    for (const section_triangle& t : *list)
      out += "3 " + std::to_string(index[t.p[0]]) + " " + std::to_string(index[t.p[1]]) + " " +
             std::to_string(index[t.p[2]]) + "\n";
  return out;
}

std::array<vec3d, 2> section_svg_basis(const section_plane& plane) {
  const double len = std::sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
  const vec3d n{plane[0] / len, plane[1] / len, plane[2] / len};
  int m = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(n[k]) < std::fabs(n[m])) m = k;
  vec3d u{0, 0, 0};
  u[m] = 1;
  const double along = n[m];
  for (int k = 0; k < 3; ++k) u[k] -= along * n[k];
  const double ul = std::sqrt(dot(u, u));
  for (double& x : u) x /= ul;
  const vec3d v{n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
  return {u, v};
}

std::string section_svg(const section_result& r, const std::array<unsigned char, 3>& cap_color) {
  const auto basis = section_svg_basis(r.plane);
  std::vector<std::array<double, 2>> uv(r.points.size());
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const section_chain& c : r.outline)
    for (std::uint32_t p : c.p) {
      uv[p] = {dot(basis[0], r.points[p].v), dot(basis[1], r.points[p].v)};
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], uv[p][k]);
        hi[k] = std::max(hi[k], uv[p][k]);
      }
    }
  const double side = 800, margin = 20;
  double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(extent > 0)) extent = 1;
  if (!(lo[0] <= hi[0])) lo[0] = hi[0] = lo[1] = hi[1] = 0;
  const double scale = side / extent;
  const double width = (hi[0] - lo[0]) * scale + 2 * margin,
               height = (hi[1] - lo[1]) * scale + 2 * margin;
  auto x = [&](std::uint32_t p) { return px((uv[p][0] - lo[0]) * scale + margin); };
  auto y = [&](std::uint32_t p) { return px((hi[1] - uv[p][1]) * scale + margin); };
  const std::string colour = svg::hex_color(cap_color[0], cap_color[1], cap_color[2]);

  const std::string w = px(std::ceil(width)), h = px(std::ceil(height));
  std::string out = svg::open_root(w, h);
  out += "<!-- exbsp section by the plane " + number(r.plane[0]) + "*x + " + number(r.plane[1]) +
         "*y + " + number(r.plane[2]) + "*z + " + number(r.plane[3]) +
         " = 0, seen from the kept side; u = (" + number(basis[0][0]) + ", " + number(basis[0][1]) +
         ", " + number(basis[0][2]) + ") to the right, v = (" + number(basis[1][0]) + ", " +
         number(basis[1][1]) + ", " + number(basis[1][2]) + ") upwards; scale " + number(scale) +
         " px per unit -->\n";
  std::string loops, lines;
  for (const section_chain& c : r.outline) {
    std::string& d = c.closed ? loops : lines;
    for (std::size_t i = 0; i < c.p.size(); ++i)
      d += (i ? " L" : (d.empty() ? "M" : " M")) + x(c.p[i]) + "," + y(c.p[i]);
    if (c.closed) d += " Z";
  }
  if (!loops.empty())
    out += "<path id=\"cap\" d=\"" + loops + "\" fill=\"" + colour +
           "\" fill-rule=\"nonzero\" stroke=\"#000000\" stroke-width=\"1\" "
           "stroke-linejoin=\"round\"/>\n";
  if (!lines.empty())
    out += "<path id=\"open\" d=\"" + lines +
           "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  out += "</svg>\n";
  return out;
}

}  // namespace exbsp
