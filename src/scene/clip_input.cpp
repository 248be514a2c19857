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
#include <exbsp/clip/homogeneous.h>
#include <exbsp/clip/homogeneous_segment.h>
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

/// A ring of a polygon with holes (clip/polygon_boolean.h): simple, >= 3 distinct points.
std::vector<clip::vec2d> ring(const reader& r, const json& v, const std::string& key) {
  std::vector<clip::vec2d> pts = points<2>(r, v, key);
  const std::string problem = clip::ring_problem(pts);
  if (!problem.empty()) r.fail(key, "the ring " + problem);
  return pts;
}

/// {"outer": ring, "holes": [ring, ...]} ("holes" optional), each hole inside the outer ring.
clip::polygon_with_holes2 polygon_with_holes(const reader& r, const json& v,
                                             const std::string& key) {
  r.object(v, key);
  for (auto it = v.begin(); it != v.end(); ++it)
    if (it.key() != "outer" && it.key() != "holes")
      r.fail(key + "/" + it.key(), "unknown key (expected outer, holes)");
  clip::polygon_with_holes2 p;
  p.outer = ring(r, r.require(v, key, "outer"), key + "/outer");
  if (const json* holes = r.optional(v, "holes")) {
    array_of(r, *holes, key + "/holes", "rings");
    for (std::size_t i = 0; i < holes->size(); ++i) {
      const std::string at = key + "/holes/" + std::to_string(i);
      p.holes.push_back(ring(r, (*holes)[i], at));
      if (!clip::ring_inside(p.holes.back(), p.outer))
        r.fail(at, "the hole is not inside the outer ring " + key + "/outer");
    }
  }
  return p;
}

/// The region's JSON key.
const char* region_name(clip_input::region_kind kind) {
  static const char* const names[] = {"rect",    "box",     "convex",    "halfspaces",
                                      "frustum", "polygon", "clip_space"};
  return names[static_cast<int>(kind)];
}

/// The segment clippers that take a (convex) region of this kind.
const char* segment_clippers(clip_input::region_kind kind) {
  return kind == clip_input::region_kind::clip_space
             ? "cohen-sutherland or liang-barsky"
             : "cohen-sutherland, liang-barsky or cyrus-beck";
}

void parse_region(const reader& r, const json& doc, clip_input& in) {
  const json& region = r.object(r.require(doc, "", "region"), "/region");
  if (region.size() != 1)
    r.fail("/region",
           "must have exactly one of rect, box, convex, halfspaces, frustum, polygon, clip_space");
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
    } else if (name == "polygon") {  // concave, with holes: weiler-atherton
      in.kind = kind::polygon;
      in.dimension = 2;
      in.polygon.emplace(polygon_with_holes(r, v, key));
    } else if (name == "clip_space") {  // OpenGL's -w <= x, y, z <= w, before the divide
      if (!v.is_boolean() || !v.get<bool>())
        r.fail(key, "must be true (OpenGL's clip space: points [x, y, z, w], -w <= x, y, z <= w)");
      in.kind = kind::clip_space;
      in.dimension = 4;
    } else {
      r.fail(key,
             "unknown region (expected rect, box, convex, halfspaces, frustum, polygon or "
             "clip_space)");
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

/// "0101 (left|bottom)": the outcode's bits, highest first, and their names (dimension 4:
/// clip space, the six bits of clip/homogeneous.h).
std::string outcode_text(unsigned code, std::size_t dimension) {
  static const char* names[] = {"x<min", "x>max", "y<min", "y>max", "z<min", "z>max"};
  static const char* names2[] = {"left", "right", "bottom", "top"};
  static const char* names4[] = {"x<-w", "x>w", "y<-w", "y>w", "z<-w", "z>w"};
  const char* const* bit_names = dimension == 2 ? names2 : dimension == 3 ? names : names4;
  const std::size_t bits = dimension == 2 ? 4 : 6;
  std::string s;
  for (std::size_t b = bits; b-- > 0;) s += (code >> b) & 1u ? '1' : '0';
  std::string list;
  for (std::size_t b = 0; b < bits; ++b)
    if ((code >> b) & 1u) list += (list.empty() ? "" : "|") + std::string(bit_names[b]);
  return s + " (" + (list.empty() ? "inside" : list) + ")";
}

/// Segments by a box clipper: `outcode(p)` codes an end, `clip_one(s, t)` returns the kept
/// part (or nothing) and sets t = {t0, t1} for Liang–Barsky. Writes "segments" and
/// "outcodes" (Cohen–Sutherland) or "t" (Liang–Barsky).
template <std::size_t N, class Outcode, class Clip>
void clip_segments(const std::vector<clip::segment<N>>& segments, segment_clipper algorithm,
                   Outcode&& outcode, Clip&& clip_one, json& result, std::ostream* log) {
  json out = json::array(), codes = json::array(), ts = json::array();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const clip::segment<N>& s = segments[i];
    const unsigned c0 = outcode(s.p0), c1 = outcode(s.p1);
    std::array<double, 2> t{};
    const std::optional<clip::segment<N>> kept = clip_one(s, t);
    if (algorithm == segment_clipper::cohen_sutherland)
      codes.push_back({c0, c1});
    else
      ts.push_back(kept ? json{t[0], t[1]} : json());
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

/// Segments against a rect or box by Cohen–Sutherland or Liang–Barsky.
template <std::size_t N>
void clip_segments_box(const std::vector<clip::segment<N>>& segments, const clip::box<N>& region,
                       segment_clipper algorithm, json& result, std::ostream* log) {
  clip_segments<N>(
      segments, algorithm, [&](const std::array<double, N>& p) { return clip::outcode(p, region); },
      [&](const clip::segment<N>& s, std::array<double, 2>& t) -> std::optional<clip::segment<N>> {
        if (algorithm == segment_clipper::cohen_sutherland)
          return clip::cohen_sutherland_clip(s, region);
        const auto lb = clip::liang_barsky_clip(s, region);
        if (!lb) return std::nullopt;
        t = {lb->t0, lb->t1};
        return lb->clipped;
      },
      result, log);
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

/// A clip-space point after the perspective divide (NDC), null unless w > 0 (the clipped
/// output has w >= 0; w = 0 only at the 4D origin).
json ndc_json(const json& p) {
  const clip::vec4d q{p[0].get<double>(), p[1].get<double>(), p[2].get<double>(),
                      p[3].get<double>()};
  return q[3] > 0 ? to_json(clip::perspective_divide(q)) : json();
}

json ndc_points(const json& points) {
  json out = json::array();
  for (const json& p : points) out.push_back(ndc_json(p));
  return out;
}

/// clip_space: segments by the homogeneous Cohen–Sutherland or Liang–Barsky, polygons by the
/// homogeneous Sutherland–Hodgman, each result also divided by w ("ndc").
json clip_in_clip_space(const clip_input& in, const std::string& algorithm, std::ostream* log) {
  if (algorithm == "cyrus-beck")
    throw scene_error(in.path, "/region",
                      "cyrus-beck clips against rect, box, convex, halfspaces and frustum "
                      "regions; clip_space segments are clipped by cohen-sutherland (the default) "
                      "or liang-barsky in homogeneous coordinates");
  const segment_clipper sc = algorithm == "liang-barsky" ? segment_clipper::liang_barsky
                                                         : segment_clipper::cohen_sutherland;
  json result;
  result["dimension"] = 4;
  result["algorithm"] = {
      {"segments", sc == segment_clipper::liang_barsky ? "liang-barsky" : "cohen-sutherland"},
      {"polygons", "sutherland-hodgman"}};
  clip_segments<4>(
      in.segments4, sc, [](const clip::vec4d& p) { return clip::homogeneous_outcode(p); },
      [&](const clip::segment<4>& s, std::array<double, 2>& t) -> std::optional<clip::segment<4>> {
        clip::segment<4> kept{};
        const bool ok =
            sc == segment_clipper::liang_barsky
                ? clip::homogeneous_liang_barsky(s.p0, s.p1, kept.p0, kept.p1, &t[0], &t[1])
                : clip::homogeneous_cohen_sutherland(s.p0, s.p1, kept.p0, kept.p1);
        if (!ok) return std::nullopt;
        return kept;
      },
      result, log);
  json polygons = json::array();
  for (std::size_t i = 0; i < in.polygons4.size(); ++i) {
    clip::homogeneous_polygon poly;
    poly.positions = in.polygons4[i];
    const clip::homogeneous_polygon kept = clip::homogeneous_clip(poly);
    polygons.push_back(polygon_json(kept.positions));
    if (log)
      *log << "polygon " << i << ": " << poly.size() << " vertices -> " << kept.size()
           << " vertices\n";
  }
  result["polygons"] = polygons;
  json ndc_segments = json::array(), ndc_polygons = json::array();
  for (const json& s : result["segments"]) ndc_segments.push_back(s.is_null() ? s : ndc_points(s));
  for (const json& p : polygons) ndc_polygons.push_back(ndc_points(p));
  result["ndc"] = {{"segments", ndc_segments}, {"polygons", ndc_polygons}};
  return result;
}

json polygons_with_holes_json(const std::vector<clip::polygon_with_holes2>& polygons) {
  json out = json::array();
  for (const auto& p : polygons) {
    json holes = json::array();
    for (const auto& h : p.holes) holes.push_back(polygon_json(h));
    out.push_back({{"outer", polygon_json(p.outer)}, {"holes", holes}});
  }
  return out;
}

/// A polygon region: CGAL's exact Boolean intersection (standing in for Weiler–Atherton,
/// clip/polygon_boolean.h) for polygons, the exact parts in the closed region for segments.
json clip_against_polygon(const clip_input& in, const std::string& algorithm, std::ostream* log) {
  if (!algorithm.empty() && algorithm != "weiler-atherton")
    throw scene_error(in.path, "/region",
                      "a polygon region (concave, with holes) is clipped by weiler-atherton only "
                      "(CGAL's exact Boolean operations); " +
                          algorithm +
                          " needs a convex region (rect, box, convex, halfspaces, frustum) or "
                          "clip_space");
  const clip::polygon_region& region = *in.polygon;
  json result;
  result["dimension"] = 2;
  result["algorithm"] = {{"segments", "weiler-atherton"}, {"polygons", "weiler-atherton"}};
  json segments = json::array();
  for (std::size_t i = 0; i < in.segments2.size(); ++i) {
    json parts = json::array();
    for (const clip::segment2& s : region.clip_segment(in.segments2[i]))
      parts.push_back({to_json(s.p0), to_json(s.p1)});
    if (log)
      *log << "segment " << i << ": " << parts.size() << (parts.size() == 1 ? " part" : " parts")
           << " in the region\n";
    segments.push_back(std::move(parts));
  }
  result["segments"] = segments;
  auto clip_all = [&](const std::vector<clip::polygon_with_holes2>& polygons, const char* what) {
    json out = json::array();
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      const auto kept = region.intersect(polygons[i]);
      if (log)
        *log << what << " " << i << ": " << polygons[i].outer.size() << " vertices, "
             << polygons[i].holes.size() << " holes -> " << kept.size()
             << (kept.size() == 1 ? " polygon\n" : " polygons\n");
      out.push_back(polygons_with_holes_json(kept));
    }
    return out;
  };
  std::vector<clip::polygon_with_holes2> simple;
  for (const auto& p : in.polygons2) simple.push_back({p, {}});
  result["polygons"] = clip_all(simple, "polygon");
  result["polygons_with_holes"] = clip_all(in.holed_polygons2, "polygon with holes");
  return result;
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
    if (it.key() != "region" && it.key() != "segments" && it.key() != "polygons" &&
        it.key() != "polygons_with_holes")
      r.fail("/" + it.key(),
             "unknown key (expected region, segments, polygons, polygons_with_holes)");
  clip_input in;
  in.path = path;
  parse_region(r, doc, in);
  if (in.dimension == 2)
    parse_items<2>(r, doc, in.segments2, in.polygons2);
  else if (in.dimension == 3)
    parse_items<3>(r, doc, in.segments3, in.polygons3);
  else
    parse_items<4>(r, doc, in.segments4, in.polygons4);
  const bool polygon_region = in.kind == clip_input::region_kind::polygon;
  if (polygon_region)  // the Boolean operations need simple polygons
    for (std::size_t i = 0; i < in.polygons2.size(); ++i) {
      const std::string problem = clip::ring_problem(in.polygons2[i]);
      if (!problem.empty()) r.fail("/polygons/" + std::to_string(i), "the polygon " + problem);
    }
  if (const json* holed = r.optional(doc, "polygons_with_holes")) {
    if (!polygon_region)
      r.fail("/polygons_with_holes",
             "polygons with holes are clipped against a polygon region only (weiler-atherton); "
             "the " +
                 std::string(region_name(in.kind)) +
                 " region clips simple polygons (\"polygons\")");
    array_of(r, *holed, "/polygons_with_holes", "polygons with holes");
    for (std::size_t i = 0; i < holed->size(); ++i)
      in.holed_polygons2.push_back(
          polygon_with_holes(r, (*holed)[i], "/polygons_with_holes/" + std::to_string(i)));
  }
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
      algorithm != "cyrus-beck" && algorithm != "sutherland-hodgman" &&
      algorithm != "weiler-atherton")
    throw usage_error("clip: unknown --algorithm " + algorithm +
                      " (expected cohen-sutherland, liang-barsky, cyrus-beck, sutherland-hodgman "
                      "or weiler-atherton)");
  if (in.kind == clip_input::region_kind::polygon) return clip_against_polygon(in, algorithm, log);
  if (algorithm == "weiler-atherton")
    throw scene_error(in.path, "/region",
                      std::string("weiler-atherton clips against a polygon region ({\"polygon\": "
                                  "{\"outer\": ..., \"holes\": ...}}) only; against a ") +
                          region_name(in.kind) +
                          " region clip polygons with sutherland-hodgman and segments with " +
                          segment_clippers(in.kind));
  const bool has_segments = !in.segments2.empty() || !in.segments3.empty() || !in.segments4.empty();
  const bool box_region =
      in.kind == clip_input::region_kind::rect || in.kind == clip_input::region_kind::box;
  if (has_segments && algorithm == "sutherland-hodgman")
    throw scene_error(in.path, "/segments",
                      std::string("Sutherland–Hodgman clips polygons; clip segments with ") +
                          segment_clippers(in.kind));
  if (in.kind == clip_input::region_kind::clip_space) return clip_in_clip_space(in, algorithm, log);
  // Segments: Cohen–Sutherland (default) or Liang–Barsky against a rect or box, Cyrus–Beck
  // against any convex region (the default for convex and halfspaces regions).
  const bool cyrus_beck = algorithm == "cyrus-beck" || (algorithm.empty() && !box_region);
  if (has_segments && !box_region && !cyrus_beck)
    throw scene_error(in.path, "/region",
                      algorithm + " clips segments against a rect or box; use cyrus-beck for a " +
                          region_name(in.kind) + " region");
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
      clip_segments_box<2>(in.segments2, in.window, sc, result, log);
    clip_polygons(in.polygons2, in.planes2, result, log);
  } else {
    if (has_segments && cyrus_beck)
      clip_segments_cyrus_beck<3>(in.segments3, in.planes3, result, log);
    else if (has_segments)
      clip_segments_box<3>(in.segments3, in.box, sc, result, log);
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
  for (const auto& poly : in.holed_polygons2)
    for (const auto& p : poly.outer) grow(p);
  // A polygon region: its regularized rings (outer counter-clockwise, holes clockwise).
  const std::vector<clip::polygon_with_holes2> polygon_region =
      in.polygon ? in.polygon->polygons() : std::vector<clip::polygon_with_holes2>{};
  for (const auto& poly : polygon_region)
    for (const auto& p : poly.outer) grow(p);
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
  // A polygon with holes ({"outer", "holes"}) as one path of closed rings, for evenodd filling.
  auto holed_path = [&](const json& p) {
    std::string d = path(p.at("outer"), true);
    for (const json& h : p.at("holes")) d += " " + path(h, true);
    return d;
  };
  std::ostringstream svg;
  svg << svg::open_root(fixed(width), fixed(height));
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  json region_pts = json::array();
  for (const auto& p : region) region_pts.push_back({p[0], p[1]});
  std::string region_d = region_pts.empty() ? std::string() : path(region_pts, true);
  for (const json& p : polygons_with_holes_json(polygon_region))
    region_d += (region_d.empty() ? "" : " ") + holed_path(p);
  if (!region_d.empty())
    svg << "<path id=\"region\" d=\"" << region_d
        << "\" fill=\"#dce8f5\" fill-rule=\"evenodd\" stroke=\"#4a6fa5\" stroke-width=\"1.5\"/>\n";
  svg << "<g id=\"input\" fill=\"none\" stroke=\"#888\" stroke-width=\"1\" stroke-dasharray=\"4 "
         "3\">\n";
  for (const auto& s : in.segments2)
    svg << "<path d=\"M" << xy(s.p0[0], s.p0[1]) << " L" << xy(s.p1[0], s.p1[1]) << "\"/>\n";
  for (const auto& poly : in.polygons2)
    svg << "<path d=\"" << path(polygon_json(poly), true) << "\"/>\n";
  for (const json& p : polygons_with_holes_json(in.holed_polygons2))
    svg << "<path d=\"" << holed_path(p) << "\"/>\n";
  svg << "</g>\n<g id=\"result\" stroke=\"#c0392b\" stroke-width=\"2\">\n";
  const char* fill = "\" fill=\"#e74c3c\" fill-opacity=\"0.45\"";
  if (in.polygon) {  // per input polygon, polygons with holes; per segment, its parts
    for (const char* key : {"polygons", "polygons_with_holes"})
      for (const json& kept : result.at(key))
        for (const json& p : kept)
          svg << "<path d=\"" << holed_path(p) << fill << " fill-rule=\"evenodd\"/>\n";
    for (const json& parts : result.at("segments"))
      for (const json& s : parts) svg << "<path d=\"" << path(s, false) << "\" fill=\"none\"/>\n";
    svg << "</g>\n</svg>\n";
    return svg.str();
  }
  for (const auto& pieces : result.at("pieces"))
    for (const auto& piece : pieces) svg << "<path d=\"" << path(piece, true) << fill << "/>\n";
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
