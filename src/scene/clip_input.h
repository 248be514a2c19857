// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp clip` (docs/contract.md "Command line"): the clipping toolbox from a JSON file.
//
// Input: {"region": R, "segments": [[p, q], ...], "polygons": [[p, ...], ...]} with R one of
//   {"rect": [xmin, ymin, xmax, ymax]}                2D window
//   {"box": [xmin, ymin, zmin, xmax, ymax, zmax]}     3D box
//   {"convex": [[x, y], ...]}                         convex polygon (either orientation)
//   {"convex": [[x, y, z], ...]}                      convex hull of a 3D point set
//   {"halfspaces": [[a, b, c], ...]}                  2D half-planes a x + b y + c >= 0
//   {"halfspaces": [[a, b, c, d], ...]}               3D half-spaces a x + b y + c z + d >= 0
//   {"frustum": [left, right, bottom, top, near, far]} glFrustum's view volume, eye coordinates
//                                                     (eye at the origin looking down -z)
// The region fixes the dimension; every point must have that many coordinates. "segments" and
// "polygons" are optional (absent = none).
// Algorithms: segments are clipped by Cohen–Sutherland (the default) or Liang–Barsky against a
// rect or box, by Cyrus–Beck against any region (the default for the others); polygons always
// by Sutherland–Hodgman, against any region (a rect or box as its half-spaces; convex regions
// through clip/convex_region.h). `--algorithm
// sutherland-hodgman` with segments in the input is an error (it clips polygons only).
// Output JSON: {"dimension", "algorithm": {"segments", "polygons"}, "segments": [[p, q] | null,
// ...] (one per input segment, null when nothing is left), "outcodes": [[c0, c1], ...]
// (Cohen–Sutherland: the endpoints' outcodes as clip/cohen_sutherland.h defines the bits),
// "t": [[t0, t1] | null, ...] (Liang–Barsky, Cyrus–Beck), "polygons": [[p, ...], ...] (the textbook
// Sutherland–Hodgman result per input polygon, [] when nothing is left; a concave input may
// contain the degenerate connecting edges of clip/sutherland_hodgman.h), "pieces": [[[p, ...],
// ...], ...] (the same result split into its connected pieces)}. Numbers are doubles that read
// back to the same value.
// SVG (2D only): the region (a rect, the convex polygon, or the half-planes' region within the
// drawing's bounds) filled pale blue, the input dashed grey, the result in red (segments, and
// the pieces filled), and for a polygon that fell apart the textbook polygon dotted dark grey
// (its connecting edges run along the boundary); y points up as in the input.
// Errors: a scene_error naming the input file and the JSON key (e.g. /segments/3/1), exit 2,
// and nothing written.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/clip/sutherland_hodgman.h>

namespace exbsp::scene {

/// Segment clippers.
enum class segment_clipper { cohen_sutherland, liang_barsky };

/// A validated `exbsp clip` input.
struct clip_input {
  std::string path;
  int dimension = 2;
  enum class region_kind { rect, box, convex, halfspaces, frustum } kind = region_kind::rect;
  clip::window2 window{};                   ///< rect
  clip::box3 box{};                         ///< box
  std::vector<clip::vec2d> convex_polygon;  ///< 2D convex region's vertices (for drawing)
  std::vector<clip::half_plane2> planes2;   ///< the 2D region as half-planes (every kind)
  std::vector<clip::half_space3> planes3;   ///< the 3D region as half-spaces (every kind)
  std::vector<clip::segment2> segments2;
  std::vector<clip::segment3> segments3;
  std::vector<std::vector<clip::vec2d>> polygons2;
  std::vector<std::vector<clip::vec3d>> polygons3;
};

/// Validates a parsed document (`path` names the file in messages). Throws scene_error naming
/// the key for every missing, wrongly typed, non-finite or impossible value (a non-convex
/// "convex" polygon, coplanar hull points, min > max, a point of the wrong dimension).
clip_input parse_clip_input(const nlohmann::json& doc, const std::string& path);

/// Reads and validates a file: input_error when it cannot be read, is not a regular file or
/// nests deeper than max_json_depth (mesh/json_limits.h), scene_error otherwise.
clip_input load_clip_input(const std::string& path);

/// Clips everything; `algorithm` is "cohen-sutherland", "liang-barsky", "sutherland-hodgman"
/// or empty (the defaults). With `log`, prints each segment's endpoint outcodes (rect or box
/// regions) and what happened to it. Returns the output JSON described above. Throws
/// usage_error for an unknown algorithm, scene_error naming /region when segments need a
/// rect or box, or /segments when sutherland-hodgman is asked to clip segments.
nlohmann::json run_clip(const clip_input& in, const std::string& algorithm, std::ostream* log);

/// The SVG drawing of an input and run_clip's result. Throws scene_error naming /region for
/// 3D input.
std::string clip_svg(const clip_input& in, const nlohmann::json& result);

/// `exbsp clip`: load, clip, write JSON or SVG (by the extension of output_path) atomically,
/// or JSON to `out` when output_path is empty. Log lines (verbose) go to `log`.
void clip_command(const std::string& input_path, const std::string& output_path,
                  const std::string& algorithm, bool verbose, std::ostream& out, std::ostream& log);

}  // namespace exbsp::scene
