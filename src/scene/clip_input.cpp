// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp clip`: JSON input -> the clippers of src/clip -> JSON or SVG (notation in clip_input.h).
#include "scene/clip_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <exbsp/clip/cohen_sutherland.h>
#include <exbsp/clip/convex_hull.h>
#include <exbsp/clip/convex_region.h>
#include <exbsp/clip/cyrus_beck.h>
#include <exbsp/clip/liang_barsky.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include "core/file_name.h"
#include "mesh/json_limits.h"
#include "core/atomic_file.h"
#include "scene/json_reader.h"
#include "core/svg_text.h"

namespace exbsp::scene {

using nlohmann::json;

namespace {

/// The largest coordinate or coefficient `exbsp clip` accepts (notation in point()).
constexpr double max_clip_magnitude = 1e100;

const json& array_of(const reader& r, const json& v, const std::string& key, const char* what) {
  if (!v.is_array())
    r.fail(key, std::string("must be an array of ") + what + " (got " + v.type_name() + ")");
  return v;
}

template <std::size_t N>
std::array<double, N> point(const reader& r, const json& v, const std::string& key) {
  if (!v.is_array() || v.size() != N)
    r.fail(key, "must be a point of " + std::to_string(N) + " numbers (the region is " +
                    std::to_string(N) + "D)");
  std::array<double, N> p{};
  for (std::size_t k = 0; k < N; ++k) {
    const std::string at = key + "/" + std::to_string(k);
    p[k] = r.number(v[k], at);
    // The clippers' intermediate values (differences, products of a difference and a
    // coordinate, plane values) must stay finite: beyond this they overflow to infinity and the
    // answer would hold NaN ("null") or lose vertices.
    if (!(std::fabs(p[k]) <= max_clip_magnitude))
      r.fail(at, "must be at most 1e100 in magnitude (got " + number_text(p[k]) +
                     "): the clippers' intermediate values would overflow");
  }
  return p;
}

template <std::size_t N>
std::vector<std::array<double, N>> points(const reader& r, const json& v, const std::string& key) {
  array_of(r, v, key, "points");
  std::vector<std::array<double, N>> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(point<N>(r, v[i], key + "/" + std::to_string(i)));
  return out;
}

void parse_region(const reader& r, const json& doc, clip_input& in) {
  const json& region = r.object(r.require(doc, "", "region"), "/region");
  if (region.size() != 1)
    r.fail("/region", "must have exactly one of rect, box, convex, halfspaces, frustum");
  const std::string name = region.begin().key();
  const std::string key = "/region/" + name;
  const json& v = region.begin().value();
  using kind = clip_input::region_kind;
  try {
    if (name == "rect") {
      if (!v.is_array() || v.size() != 4) r.fail(key, "must be [xmin, ymin, xmax, ymax]");
      const auto b = point<4>(r, v, key);
      if (!(b[0] <= b[2])) r.fail(key + "/2", "xmax must be >= xmin");
      if (!(b[1] <= b[3])) r.fail(key + "/3", "ymax must be >= ymin");
      in.kind = kind::rect;
      in.dimension = 2;
      in.window = clip::make_window(b[0], b[2], b[1], b[3]);
      in.planes2 = clip::window_half_planes(in.window);
    } else if (name == "box") {
      if (!v.is_array() || v.size() != 6)
        r.fail(key, "must be [xmin, ymin, zmin, xmax, ymax, zmax]");
      const auto b = point<6>(r, v, key);
      for (int k = 0; k < 3; ++k)
        if (!(b[k] <= b[k + 3])) r.fail(key + "/" + std::to_string(k + 3), "max must be >= min");
      in.kind = kind::box;
      in.dimension = 3;
      in.box = clip::box3{{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
      in.planes3 = clip::box_half_spaces(in.box);
    } else if (name == "frustum") {  // glFrustum's view volume in eye coordinates
      if (!v.is_array() || v.size() != 6)
        r.fail(key, "must be [left, right, bottom, top, near, far] (glFrustum, eye coordinates)");
      const auto f = point<6>(r, v, key);
      if (!(f[0] < f[1])) r.fail(key + "/1", "right must be > left");
      if (!(f[2] < f[3])) r.fail(key + "/3", "top must be > bottom");
      if (!(f[4] > 0)) r.fail(key + "/4", "near must be > 0");
      if (!(f[5] > f[4])) r.fail(key + "/5", "far must be > near");
      in.kind = kind::frustum;
      in.dimension = 3;
      in.planes3 = clip::frustum_half_spaces(f[0], f[1], f[2], f[3], f[4], f[5]);
    } else if (name == "convex") {
      array_of(r, v, key, "points");
      if (v.empty() || !v[0].is_array() || (v[0].size() != 2 && v[0].size() != 3))
        r.fail(
            key,
            "must be a list of 2D points [x, y] (a convex polygon) or 3D points (a convex hull)");
      in.kind = kind::convex;
      in.dimension = static_cast<int>(v[0].size());
      if (in.dimension == 2) {
        in.convex_polygon = points<2>(r, v, key);
        in.planes2 = clip::convex_polygon_half_planes(in.convex_polygon);
      } else {
        in.planes3 = clip::convex_hull_half_spaces(points<3>(r, v, key));
      }
    } else if (name == "halfspaces") {
      array_of(r, v, key, "half-spaces");
      if (v.empty()) r.fail(key, "must list at least one half-space");
      if (!v[0].is_array() || (v[0].size() != 3 && v[0].size() != 4))
        r.fail(key + "/0", "must be [a, b, c] (2D: a x + b y + c >= 0) or [a, b, c, d] (3D)");
      in.kind = kind::halfspaces;
      in.dimension = v[0].size() == 3 ? 2 : 3;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string k = key + "/" + std::to_string(i);
        if (in.dimension == 2) {
          if (!v[i].is_array() || v[i].size() != 3)
            r.fail(k, "must be [a, b, c] like /region/halfspaces/0");
          const auto h = point<3>(r, v[i], k);
          if (h[0] == 0 && h[1] == 0) r.fail(k, "the normal (a, b) must not be zero");
          in.planes2.push_back({h[0], h[1], h[2]});
        } else {
          if (!v[i].is_array() || v[i].size() != 4)
            r.fail(k, "must be [a, b, c, d] like /region/halfspaces/0");
          const auto h = point<4>(r, v[i], k);
          if (h[0] == 0 && h[1] == 0 && h[2] == 0)
            r.fail(k, "the normal (a, b, c) must not be zero");
          in.planes3.push_back({{h[0], h[1], h[2]}, h[3]});
        }
      }
    } else {
      r.fail(key, "unknown region (expected rect, box, convex, halfspaces or frustum)");
    }
  } catch (const usage_error& e) {  // the convex-region helpers' checks
    r.fail(key, e.what());
  }
}

template <std::size_t N>
void parse_items(const reader& r, const json& doc, std::vector<clip::segment<N>>& segments,
                 std::vector<std::vector<std::array<double, N>>>& polygons) {
  if (const json* s = r.optional(doc, "segments")) {
    array_of(r, *s, "/segments", "segments [p, q]");
    for (std::size_t i = 0; i < s->size(); ++i) {
      const std::string key = "/segments/" + std::to_string(i);
      if (!(*s)[i].is_array() || (*s)[i].size() != 2)
        r.fail(key, "must be a segment [p, q] of two points");
      segments.push_back(
          {point<N>(r, (*s)[i][0], key + "/0"), point<N>(r, (*s)[i][1], key + "/1")});
    }
  }
  if (const json* p = r.optional(doc, "polygons")) {
    array_of(r, *p, "/polygons", "polygons");
    for (std::size_t i = 0; i < p->size(); ++i) {
      const std::string key = "/polygons/" + std::to_string(i);
      polygons.push_back(points<N>(r, (*p)[i], key));
      if (polygons.back().size() < 3) r.fail(key, "a polygon needs at least 3 vertices");
    }
  }
}

template <std::size_t N>
json to_json(const std::array<double, N>& p) {
  json a = json::array();
  for (double v : p) a.push_back(v);
  return a;
}

template <class P>
json polygon_json(const std::vector<P>& poly) {
  json a = json::array();
  for (const P& p : poly) a.push_back(to_json(p));
  return a;
}

/// "0101 (left|bottom)": the outcode's bits, highest first, and their names.
std::string outcode_text(unsigned code, int dimension) {
  static const char* names[] = {"x<min", "x>max", "y<min", "y>max", "z<min", "z>max"};
  static const char* names2[] = {"left", "right", "bottom", "top"};
  const int bits = 2 * dimension;
  std::string s;
  for (int b = bits - 1; b >= 0; --b) s += (code >> b) & 1u ? '1' : '0';
  std::string list;
  for (int b = 0; b < bits; ++b)
    if ((code >> b) & 1u)
      list += (list.empty() ? "" : "|") + std::string(dimension == 2 ? names2[b] : names[b]);
  return s + " (" + (list.empty() ? "inside" : list) + ")";
}

template <std::size_t N, class Region>
void clip_segments(const std::vector<clip::segment<N>>& segments, const Region& region,
                   segment_clipper algorithm, json& result, std::ostream* log) {
  json out = json::array(), codes = json::array(), ts = json::array();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const clip::segment<N>& s = segments[i];
    const unsigned c0 = clip::outcode(s.p0, region), c1 = clip::outcode(s.p1, region);
    std::optional<clip::segment<N>> kept;
    if (algorithm == segment_clipper::cohen_sutherland) {
      kept = clip::cohen_sutherland_clip(s, region);
      codes.push_back({c0, c1});
    } else {
      const auto lb = clip::liang_barsky_clip(s, region);
      if (lb) kept = lb->clipped;
      ts.push_back(lb ? json{lb->t0, lb->t1} : json());
    }
    out.push_back(kept ? json{to_json(kept->p0), to_json(kept->p1)} : json());
    if (log) {
      const char* what = clip::trivially_accepted(c0, c1)   ? "trivially accepted"
                         : clip::trivially_rejected(c0, c1) ? "trivially rejected"
                         : kept                             ? "clipped"
                                                            : "rejected after clipping";
      *log << "segment " << i << ": p0 outcode " << outcode_text(c0, N) << ", p1 outcode "
           << outcode_text(c1, N) << ": " << what << "\n";
    }
  }
  result["segments"] = out;
  if (algorithm == segment_clipper::cohen_sutherland)
    result["outcodes"] = codes;
  else
    result["t"] = ts;
}

/// Segments against any convex region's half-planes or half-spaces by Cyrus–Beck: the kept
/// parts and their parameter intervals ("t"), like Liang–Barsky's.
template <std::size_t N, class H>
void clip_segments_cyrus_beck(const std::vector<clip::segment<N>>& segments,
                              const std::vector<H>& planes, json& result, std::ostream* log) {
  json out = json::array(), ts = json::array();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto cb = clip::cyrus_beck_clip(segments[i], planes);
    out.push_back(cb ? json{to_json(cb->clipped.p0), to_json(cb->clipped.p1)} : json());
    ts.push_back(cb ? json{cb->t0, cb->t1} : json());
    if (log) {
      *log << "segment " << i << ": ";
      if (!cb)
        *log << "rejected";
      else if (cb->entry < 0 && cb->exit < 0)
        *log << "inside";
      else
        *log << "kept t in [" << cb->t0 << ", " << cb->t1 << "], entering by half-plane "
             << cb->entry << ", leaving by " << cb->exit << " (-1: its own end)";
      *log << "\n";
    }
  }
  result["segments"] = out;
  result["t"] = ts;
}

template <class P, class H>
void clip_polygons(const std::vector<std::vector<P>>& polygons, const std::vector<H>& planes,
                   json& result, std::ostream* log) {
  json out = json::array(), pieces = json::array();
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    out.push_back(polygon_json(clip::sutherland_hodgman_clip(polygons[i], planes)));
    json list = json::array();
    const auto parts = clip::sutherland_hodgman_pieces(polygons[i], planes);
    for (const auto& p : parts) list.push_back(polygon_json(p));
    if (log)
      *log << "polygon " << i << ": " << polygons[i].size() << " vertices -> " << out.back().size()
           << " vertices, " << parts.size() << (parts.size() == 1 ? " piece" : " pieces") << "\n";
    pieces.push_back(std::move(list));
  }
  result["polygons"] = out;
  result["pieces"] = pieces;
}

std::string fixed(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

}  // namespace

clip_input parse_clip_input(const json& doc, const std::string& path) {
  const reader r(path, nullptr);
  if (!doc.is_object())
    r.fail("", std::string("the input must be a JSON object (got ") + doc.type_name() + ")");
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "region" && it.key() != "segments" && it.key() != "polygons")
      r.fail("/" + it.key(), "unknown key (expected region, segments, polygons)");
  clip_input in;
  in.path = path;
  parse_region(r, doc, in);
  if (in.dimension == 2)
    parse_items<2>(r, doc, in.segments2, in.polygons2);
  else
    parse_items<3>(r, doc, in.segments3, in.polygons3);
  return in;
}

clip_input load_clip_input(const std::string& path) {
  const std::string text = read_input_file(path);  // a regular file: no FIFO hang, no /dev/zero
  check_json_nesting(text, path);                  // before nlohmann builds and copies it
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw scene_error(path, "", std::string("invalid JSON: ") + e.what());
  }
  return parse_clip_input(doc, path);
}

json run_clip(const clip_input& in, const std::string& algorithm, std::ostream* log) {
  if (!algorithm.empty() && algorithm != "cohen-sutherland" && algorithm != "liang-barsky" &&
      algorithm != "cyrus-beck" && algorithm != "sutherland-hodgman")
    throw usage_error("clip: unknown --algorithm " + algorithm +
                      " (expected cohen-sutherland, liang-barsky, cyrus-beck or "
                      "sutherland-hodgman)");
  const bool has_segments = !in.segments2.empty() || !in.segments3.empty();
  const bool box_region =
      in.kind == clip_input::region_kind::rect || in.kind == clip_input::region_kind::box;
  if (has_segments && algorithm == "sutherland-hodgman")
    throw scene_error(in.path, "/segments",
                      "Sutherland–Hodgman clips polygons; clip segments with cohen-sutherland, "
                      "liang-barsky or cyrus-beck");
  // Segments: Cohen–Sutherland (default) or Liang–Barsky against a rect or box, Cyrus–Beck
  // against any convex region (the default for convex and halfspaces regions).
  const bool cyrus_beck = algorithm == "cyrus-beck" || (algorithm.empty() && !box_region);
  if (has_segments && !box_region && !cyrus_beck)
    throw scene_error(in.path, "/region",
                      algorithm + " clips segments against a rect or box; use cyrus-beck for a " +
                          (in.kind == clip_input::region_kind::convex    ? "convex"
                           : in.kind == clip_input::region_kind::frustum ? "frustum"
                                                                         : "halfspaces") +
                          " region");
  const segment_clipper sc = algorithm == "liang-barsky" ? segment_clipper::liang_barsky
                                                         : segment_clipper::cohen_sutherland;
  json result;
  result["dimension"] = in.dimension;
  result["algorithm"] = {{"segments", cyrus_beck                            ? "cyrus-beck"
                                      : sc == segment_clipper::liang_barsky ? "liang-barsky"
                                                                            : "cohen-sutherland"},
                         {"polygons", "sutherland-hodgman"}};
  if (in.dimension == 2) {
    if (has_segments && cyrus_beck)
      clip_segments_cyrus_beck<2>(in.segments2, in.planes2, result, log);
    else if (has_segments)
      clip_segments<2>(in.segments2, in.window, sc, result, log);
    clip_polygons(in.polygons2, in.planes2, result, log);
  } else {
    if (has_segments && cyrus_beck)
      clip_segments_cyrus_beck<3>(in.segments3, in.planes3, result, log);
    else if (has_segments)
      clip_segments<3>(in.segments3, in.box, sc, result, log);
    clip_polygons(in.polygons3, in.planes3, result, log);
  }
  if (!has_segments) result["segments"] = json::array();
  return result;
}

std::string clip_svg(const clip_input& in, const json& result) {
  if (in.dimension != 2)
    throw scene_error(in.path, "/region",
                      "SVG output draws 2D input only (use -o OUT.json for 3D)");
  // Bounds: every input point, and the region when it is bounded.
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  auto grow = [&](const clip::vec2d& p) {
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  };
  for (const auto& s : in.segments2) {
    grow(s.p0);
    grow(s.p1);
  }
  for (const auto& poly : in.polygons2)
    for (const auto& p : poly) grow(p);
  std::vector<clip::vec2d> region;
  if (in.kind == clip_input::region_kind::rect) {
    region = {in.window.min,
              {in.window.max[0], in.window.min[1]},
              in.window.max,
              {in.window.min[0], in.window.max[1]}};
  } else if (in.kind == clip_input::region_kind::convex) {
    region = in.convex_polygon;
  }
  for (const auto& p : region) grow(p);
  if (!(lo[0] <= hi[0])) lo[0] = lo[1] = -1, hi[0] = hi[1] = 1;
  double span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-300});
  for (int k = 0; k < 2; ++k) {
    lo[k] -= 0.05 * span;
    hi[k] += 0.05 * span;
  }
  if (in.kind == clip_input::region_kind::halfspaces)  // the half-planes' region within the bounds
    region = clip::sutherland_hodgman_clip(
        std::vector<clip::vec2d>{{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}},
        in.planes2);
  span = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const double scale = 512.0 / span;
  const double width = (hi[0] - lo[0]) * scale, height = (hi[1] - lo[1]) * scale;
  auto xy = [&](double x, double y) {
    return fixed((x - lo[0]) * scale) + "," + fixed((hi[1] - y) * scale);
  };
  auto path = [&](const json& pts, bool closed) {
    std::string d;
    for (std::size_t i = 0; i < pts.size(); ++i)
      d += (i ? " L" : "M") + xy(pts[i][0].get<double>(), pts[i][1].get<double>());
    return d + (closed ? " Z" : "");
  };
  std::ostringstream svg;
  svg << svg::open_root(fixed(width), fixed(height));
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  json region_pts = json::array();
  for (const auto& p : region) region_pts.push_back({p[0], p[1]});
  if (!region_pts.empty())
    svg << "<path id=\"region\" d=\"" << path(region_pts, true)
        << "\" fill=\"#dce8f5\" stroke=\"#4a6fa5\" stroke-width=\"1.5\"/>\n";
  svg << "<g id=\"input\" fill=\"none\" stroke=\"#888\" stroke-width=\"1\" stroke-dasharray=\"4 "
         "3\">\n";
  for (const auto& s : in.segments2)
    svg << "<path d=\"M" << xy(s.p0[0], s.p0[1]) << " L" << xy(s.p1[0], s.p1[1]) << "\"/>\n";
  for (const auto& poly : in.polygons2)
    svg << "<path d=\"" << path(polygon_json(poly), true) << "\"/>\n";
  svg << "</g>\n<g id=\"result\" stroke=\"#c0392b\" stroke-width=\"2\">\n";
  for (const auto& pieces : result.at("pieces"))
    for (const auto& piece : pieces)
      svg << "<path d=\"" << path(piece, true) << "\" fill=\"#e74c3c\" fill-opacity=\"0.45\"/>\n";
  for (const auto& s : result.at("segments"))
    if (!s.is_null()) svg << "<path d=\"" << path(s, false) << "\" fill=\"none\"/>\n";
  svg << "</g>\n";
  // The textbook Sutherland–Hodgman polygon where it differs from its pieces: its degenerate
  // connecting edges show as dark dotted lines along the region's boundary.
  const json& textbook = result.at("polygons");
  svg << "<g id=\"textbook\" fill=\"none\" stroke=\"#222\" stroke-width=\"1\" stroke-dasharray=\"1 "
         "3\">\n";
  for (std::size_t i = 0; i < textbook.size(); ++i)
    if (result.at("pieces")[i].size() > 1)
      svg << "<path d=\"" << path(textbook[i], true) << "\"/>\n";
  svg << "</g>\n</svg>\n";
  return svg.str();
}

void clip_command(const std::string& input_path, const std::string& output_path,
                  const std::string& algorithm, bool verbose, std::ostream& out,
                  std::ostream& log) {
  const bool svg = has_extension(output_path, ".svg");
  if (!output_path.empty() && !svg && !has_extension(output_path, ".json"))
    throw usage_error("clip: the output file must end in .json or .svg: " + output_path);
  const clip_input in = load_clip_input(input_path);
  const json result = run_clip(in, algorithm, verbose ? &log : nullptr);
  std::string text;
  if (svg) {
    text = clip_svg(in, result);
  } else {  // one top-level key per line, each value compact
    for (auto it = result.begin(); it != result.end(); ++it)
      text += (text.empty() ? "{\n \"" : ",\n \"") + it.key() + "\": " + it.value().dump();
    text += "\n}\n";
  }
  if (output_path.empty())
    out << text;
  else
    write_file_atomically(output_path, text);
}

}  // namespace exbsp::scene
