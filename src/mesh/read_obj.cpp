// SPDX-License-Identifier: LGPL-3.0-or-later
// OBJ reader (Wavefront, polygonal subset).
//
//   v x y z [w] [r g b [a]]      a vertex; w and colour values are ignored (must be numbers)
//   vt u [v [w]]                 a texture coordinate (v defaults to 0; w is ignored); each
//                                value a finite number
//   f r1 r2 r3 ...               a face of >= 3 vertex references; each r is
//                                i, i/t, i/t/n or i//n. i = 1..(vertices so far) counts from
//                                the first vertex, i = -1..-(vertices so far) from the last
//                                one defined before this line; t likewise indexes the vt
//                                statements so far (out of range: an error); n is not used
//   vn vp g o s usemtl mtllib l p ...   attributes, groups, materials, lines and points:
//                                ignored (they define no face)
//
// Texture coordinates: when a face gives t for every corner, its triangles carry those (u, v)
// (triangle_soup::triangle_uvs); a file with such faces gives (0, 0) to the corners of faces
// without t; a file without them has no UVs.
//
// '#' starts a comment up to the end of the line; a line ending in '\' continues on the
// next one (errors then name its first line). A face may only use vertices defined above it.
// Free-form geometry (curv, surf, ...) and unknown statements are errors, so that no
// surface is dropped silently. The j-th f statement (0-based) gets face id j.
#include <algorithm>

#include "mesh/reader_util.h"

namespace exbsp::mesh_detail {
namespace {

constexpr std::string_view ignored_statements[] = {
    "vn", "vp",  "g",      "o",      "s",     "usemtl",   "mtllib",   "l",          "p",
    "mg", "lod", "maplib", "usemap", "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj"};

bool is_ignored(std::string_view keyword) {
  return std::find(std::begin(ignored_statements), std::end(ignored_statements), keyword) !=
         std::end(ignored_statements);
}

// Parses one face vertex reference ("i", "i/t", "i/t/n", "i//n") into its vertex number i;
// `texture` gets t, or 0 when the reference has none.
std::int64_t parse_vertex_reference(std::string_view ref, const std::string& file, std::size_t line,
                                    std::int64_t& texture) {
  std::string_view parts[3];
  std::size_t count = 0;
  std::size_t start = 0;
  for (;;) {
    const std::size_t slash = ref.find('/', start);
    if (count == 3)
      fail(file, line, "invalid face vertex reference " + quote(ref) + " (too many '/')");
    parts[count++] =
        ref.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  const auto bad = [&]() {
    fail(file, line,
         "invalid face vertex reference " + quote(ref) + " (expected i, i/t, i/t/n or i//n)");
  };
  std::int64_t v = 0;
  std::int64_t unused = 0;
  texture = 0;
  if (!parse_integer(parts[0], v)) bad();
  if (count == 2 && !parse_integer(parts[1], texture)) bad();
  if (count == 3 && ((!parts[1].empty() && !parse_integer(parts[1], texture)) ||
                     !parse_integer(parts[2], unused)))
    bad();
  if (count >= 2 && !parts[1].empty() && texture == 0)
    fail(file, line, "texture coordinate index 0 is invalid (OBJ indices start at 1)");
  return v;
}

}  // namespace

// Starts like read_off (soup, line reader, token buffer): the readers share line_reader and
// the number parsers (reader_util.h); their grammars differ from the next line on.
triangle_soup read_obj(std::string_view text, const std::string& file) {
  triangle_soup soup;
  soup.source = file;
  line_reader lines(text);
  std::vector<std::string_view> tokens;
  std::vector<std::uint32_t> polygon;
  std::vector<vec2d> texture_coordinates;  // the vt statements so far
  std::vector<vec2d> polygon_uvs;
  std::string joined;  // a logical line assembled from '\' continuations
  std::uint64_t faces = 0;
  bool any_statement = false;
  std::string_view physical;

  while (lines.next(physical)) {
    const std::size_t line = lines.line_number();
    std::string_view logical = strip_comment(physical);
    // Line continuation: a trailing '\' (after blanks are trimmed) joins the next line.
    const auto ends_with_backslash = [](std::string_view s) {
      while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
      return !s.empty() && s.back() == '\\';
    };
    if (ends_with_backslash(logical)) {
      joined.clear();
      std::string_view piece = logical;
      for (;;) {
        while (!piece.empty() && is_blank(piece.back())) piece.remove_suffix(1);
        const bool more = !piece.empty() && piece.back() == '\\';
        if (more) piece.remove_suffix(1);
        joined.append(piece.data(), piece.size());
        joined += ' ';
        if (!more) break;
        if (!lines.next(physical)) break;  // a '\' on the last line continues into nothing
        piece = strip_comment(physical);
      }
      logical = joined;
    }
    split_tokens(logical, tokens);
    if (tokens.empty()) continue;
    any_statement = true;
    const std::string_view keyword = tokens[0];

    if (keyword == "v") {
      const std::size_t values = tokens.size() - 1;
      if (values < 3)
        fail(file, line,
             "vertex has " + std::to_string(values) + " coordinates, expected 3 (x y z)");
      if (values > 7)
        fail(file, line,
             "vertex has " + std::to_string(values) + " values, expected x y z [w] [r g b [a]]");
      if (soup.vertices.size() >= max_element_count)
        fail(file, line, "too many vertices (at most " + std::to_string(max_element_count) + ")");
      const vec3d p = {parse_coordinate(tokens[1], 'x', file, line),
                       parse_coordinate(tokens[2], 'y', file, line),
                       parse_coordinate(tokens[3], 'z', file, line)};
      for (std::size_t i = 4; i < tokens.size(); ++i) {
        double extra = 0.0;
        if (parse_double(tokens[i], extra) != number_status::ok)
          fail(file, line, "vertex value " + quote(tokens[i]) + " is not a finite number");
      }
      soup.vertices.push_back(p);
    } else if (keyword == "vt") {
      const std::size_t values = tokens.size() - 1;
      if (values < 1 || values > 3)
        fail(file, line,
             "texture coordinate has " + std::to_string(values) + " values, expected u [v [w]]");
      if (texture_coordinates.size() >= max_element_count)
        fail(file, line,
             "too many texture coordinates (at most " + std::to_string(max_element_count) + ")");
      vec2d uv = {0.0, 0.0};
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        double value = 0.0;
        if (parse_double(tokens[i], value) != number_status::ok)
          fail(file, line,
               "texture coordinate value " + quote(tokens[i]) + " is not a finite number");
        if (i <= 2) uv[i - 1] = value;
      }
      texture_coordinates.push_back(uv);
    } else if (keyword == "f") {
      const std::size_t k = tokens.size() - 1;
      if (k < 3)
        fail(file, line,
             "face " + std::to_string(faces) + " has " + std::to_string(k) +
                 " vertices (at least 3 needed)");
      if (faces >= max_element_count)
        fail(file, line, "too many faces (at most " + std::to_string(max_element_count) + ")");
      const auto defined = static_cast<std::int64_t>(soup.vertices.size());
      const auto textures = static_cast<std::int64_t>(texture_coordinates.size());
      polygon.clear();
      polygon_uvs.clear();
      bool every_corner_textured = true;
      for (std::size_t c = 1; c <= k; ++c) {
        std::int64_t tref = 0;
        const std::int64_t ref = parse_vertex_reference(tokens[c], file, line, tref);
        if (tref == 0) {
          every_corner_textured = false;
        } else {
          const std::int64_t tindex = tref > 0 ? tref - 1 : textures + tref;
          if (tindex < 0 || tindex >= textures)
            fail(file, line,
                 "texture coordinate index " + std::to_string(tref) + " out of range (" +
                     std::to_string(textures) + " texture coordinates (vt) defined so far)");
          polygon_uvs.push_back(texture_coordinates[static_cast<std::size_t>(tindex)]);
        }
        if (ref == 0) fail(file, line, "vertex index 0 is invalid (OBJ indices start at 1)");
        // 1-based from the front, or negative: relative to the end of the list so far.
        const std::int64_t index = ref > 0 ? ref - 1 : defined + ref;
        if (index < 0 || index >= defined)
          fail(file, line,
               "vertex index " + std::to_string(ref) + " out of range (" + std::to_string(defined) +
                   " vertices defined so far)");
        polygon.push_back(static_cast<std::uint32_t>(index));
      }
      if (every_corner_textured)
        soup.add_polygon(polygon, polygon_uvs, static_cast<std::uint32_t>(faces));
      else
        soup.add_polygon(polygon, static_cast<std::uint32_t>(faces));
      ++faces;
    } else if (!is_ignored(keyword)) {
      fail(file, line, "unsupported OBJ statement " + quote(keyword));
    }
  }
  if (!any_statement)
    fail(file, lines.line_number(),
         "no OBJ statements (the file holds only blank lines and comments)");
  return soup;
}

}  // namespace exbsp::mesh_detail
