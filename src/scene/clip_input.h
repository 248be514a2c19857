// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp clip` (docs/contract.md "Command line"): the clipping toolbox from a JSON file.
//
// Input: {"region": R, "segments": [[p, q], ...], "polygons": [[p, ...], ...],
//         "polygons_with_holes": [{"outer": [p, ...], "holes": [[p, ...], ...]}, ...]}
// with R one of
//   {"rect": [xmin, ymin, xmax, ymax]}                2D window
//   {"box": [xmin, ymin, zmin, xmax, ymax, zmax]}     3D box
//   {"convex": [[x, y], ...]}                         convex polygon (either orientation)
//   {"convex": [[x, y, z], ...]}                      convex hull of a 3D point set
//   {"halfspaces": [[a, b, c], ...]}                  2D half-planes a x + b y + c >= 0
//   {"halfspaces": [[a, b, c, d], ...]}               3D half-spaces a x + b y + c z + d >= 0
//   {"frustum": [left, right, bottom, top, near, far]} glFrustum's view volume, eye coordinates
//                                                     (eye at the origin looking down -z)
//   {"polygon": {"outer": [[x, y], ...], "holes": [[[x, y], ...], ...]}}
//                                                     2D polygon with holes, may be concave
//                                                     ("holes" optional; rings in either
//                                                     orientation, simple, >= 3 distinct points,
//                                                     holes inside the outer ring; notation in
//                                                     clip/polygon_boolean.h)
//   {"clip_space": true}                              OpenGL's clip space before the divide:
//                                                     points [x, y, z, w], -w <= x, y, z <= w
// The region fixes the dimension (2, 3, or 4 for clip_space); every point must have that many
// coordinates. "segments", "polygons" and "polygons_with_holes" are optional (absent = none);
// "polygons_with_holes" only with a polygon region, where "polygons" must be simple rings too.
// Algorithms: segments are clipped by Cohen–Sutherland (the default) or Liang–Barsky against a
// rect or box, by Cyrus–Beck against any convex region (the default for the others); polygons
// by Sutherland–Hodgman, against any convex region (a rect or box as its half-spaces; convex
// regions through clip/convex_region.h). `--algorithm sutherland-hodgman` with segments in the
// input is an error (it clips polygons only). A polygon region takes weiler-atherton only (its
// default; refused for every other region): CGAL's exact regularized Boolean intersection
// stands in for Weiler–Atherton (clip/polygon_boolean.h), segments keep their exact parts in
// the closed region. clip_space clips in homogeneous coordinates (clip/homogeneous.h,
// clip/homogeneous_segment.h): segments by Cohen–Sutherland (the default) or Liang–Barsky,
// polygons by Sutherland–Hodgman; the planes imply w >= 0, so whatever lies behind the eye
// (w < 0) is cut off before the divide and a segment from in front of the eye to behind it
// keeps its front part only, never the "external" segment through infinity.
// Output JSON: {"dimension", "algorithm": {"segments", "polygons"}, "segments": [[p, q] | null,
// ...] (one per input segment, null when nothing is left), "outcodes": [[c0, c1], ...]
// (Cohen–Sutherland: the endpoints' outcodes as clip/cohen_sutherland.h, or clip/homogeneous.h
// for clip_space, defines the bits), "t": [[t0, t1] | null, ...] (Liang–Barsky, Cyrus–Beck),
// "polygons": [[p, ...], ...] (the textbook Sutherland–Hodgman result per input polygon, []
// when nothing is left; a concave input may contain the degenerate connecting edges of
// clip/sutherland_hodgman.h), "pieces": [[[p, ...], ...], ...] (the same result split into its
// connected pieces; not for clip_space)}. clip_space adds "ndc": {"segments", "polygons"}: the
// same points divided by w (normalised device coordinates), a point with w = 0 (only the 4D
// origin survives with it) as null. A polygon region writes instead "segments": [[[p, q], ...],
// ...] (per input segment its parts, [] for none; a touching point as [p, p]), "polygons" and
// "polygons_with_holes": per input polygon the resulting [{"outer": [p, ...], "holes": [[p,
// ...], ...]}, ...] (outer counter-clockwise, holes clockwise, [] for nothing). Numbers are
// doubles that read back to the same value (exact results rounded once to the nearest).
// SVG (2D only): the region (a rect, the convex polygon, the polygon with its holes drawn with
// fill-rule evenodd, or the half-planes' region within the drawing's bounds) filled pale blue,
// the input dashed grey, the result in red (segments, and the pieces or polygons with holes
// filled), and for a polygon that fell apart the textbook polygon dotted dark grey (its
// connecting edges run along the boundary); y points up as in the input.
// Errors: a scene_error naming the input file and the JSON key (e.g. /segments/3/1,
// /region/polygon/holes/1), exit 2, and nothing written.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/clip/polygon_boolean.h>
#include <exbsp/clip/sutherland_hodgman.h>

namespace exbsp::scene {

/// Segment clippers.
enum class segment_clipper { cohen_sutherland, liang_barsky };

/// A validated `exbsp clip` input.
struct clip_input {
  std::string path;
  int dimension = 2;
  enum class region_kind {
    rect,
    box,
    convex,
    halfspaces,
    frustum,
    polygon,
    clip_space
  } kind = region_kind::rect;
  clip::window2 window{};                       ///< rect
  clip::box3 box{};                             ///< box
  std::vector<clip::vec2d> convex_polygon;      ///< 2D convex region's vertices (for drawing)
  std::vector<clip::half_plane2> planes2;       ///< the 2D region as half-planes (every kind)
  std::vector<clip::half_space3> planes3;       ///< the 3D region as half-spaces (every kind)
  std::optional<clip::polygon_region> polygon;  ///< polygon (prepared once)
  std::vector<clip::segment2> segments2;
  std::vector<clip::segment3> segments3;
  std::vector<std::vector<clip::vec2d>> polygons2;
  std::vector<std::vector<clip::vec3d>> polygons3;
  std::vector<clip::polygon_with_holes2> holed_polygons2;  ///< "polygons_with_holes"
  std::vector<clip::segment<4>> segments4;                 ///< clip_space
  std::vector<std::vector<clip::vec4d>> polygons4;         ///< clip_space
};

/// Validates a parsed document (`path` names the file in messages). Throws scene_error naming
/// the key for every missing, wrongly typed, non-finite or impossible value (a non-convex
/// "convex" polygon, coplanar hull points, min > max, a point of the wrong dimension, a ring
/// that is not simple or a hole outside its outer ring).
clip_input parse_clip_input(const nlohmann::json& doc, const std::string& path);

/// Reads and validates a file: input_error when it cannot be read, is not a regular file or
/// nests deeper than max_json_depth (mesh/json_limits.h), scene_error otherwise.
clip_input load_clip_input(const std::string& path);

/// Clips everything; `algorithm` is "cohen-sutherland", "liang-barsky", "cyrus-beck",
/// "sutherland-hodgman", "weiler-atherton" or empty (the defaults). With `log`, prints each
/// segment's endpoint outcodes (rect, box or clip_space regions) and what happened to it.
/// Returns the output JSON described above. Throws usage_error for an unknown algorithm,
/// scene_error naming /region when the algorithm does not clip against that region (segments
/// need a rect or box for the box clippers, weiler-atherton a polygon region, a polygon
/// region weiler-atherton), or /segments when sutherland-hodgman is asked to clip segments.
nlohmann::json run_clip(const clip_input& in, const std::string& algorithm, std::ostream* log);

/// The SVG drawing of an input and run_clip's result. Throws scene_error naming /region for
/// 3D input.
std::string clip_svg(const clip_input& in, const nlohmann::json& result);

/// `exbsp clip`: load, clip, write JSON or SVG (by the extension of output_path) atomically,
/// or JSON to `out` when output_path is empty. Log lines (verbose) go to `log`.
void clip_command(const std::string& input_path, const std::string& output_path,
                  const std::string& algorithm, bool verbose, std::ostream& out, std::ostream& log);

}  // namespace exbsp::scene
