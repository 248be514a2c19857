// SPDX-License-Identifier: LGPL-3.0-or-later
// OFF reader (Geomview Object File Format, ASCII).
//
//   [ST][C][N]OFF [nv nf [ne]]     header keyword; the counts may follow on the same line
//   nv nf [ne]                     vertex, face and (ignored) edge counts
//   x y z [extra...]               nv vertex lines; extra columns (normal, colour, texture
//                                  coordinates) only when the keyword has an ST/C/N prefix
//   k i0 i1 ... i(k-1) [colour]    nf face lines: k >= 3 vertex indices (0-based), then at
//                                  most 4 colour values (index, RGB or RGBA), ignored
//
// '#' starts a comment up to the end of the line; blank lines are skipped. One vertex or
// face per line. 4OFF, nOFF and "OFF BINARY" are rejected. Vertex i gets index i; face j
// (0-based) is fan-triangulated into the soup with face id j.
#include <algorithm>

#include "mesh/reader_util.h"

namespace exbsp::mesh_detail {
namespace {

constexpr std::size_t max_face_colour_values = 4;

// Parses the header keyword; returns whether per-vertex extra columns are allowed.
bool parse_off_keyword(std::string_view keyword, const std::string& file, std::size_t line) {
  const auto bad = [&]() {
    fail(file, line,
         "expected an OFF header ('OFF', 'COFF', 'NOFF', 'STOFF', ...), found " + quote(keyword));
  };
  constexpr std::string_view suffix = "OFF";
  if (keyword.size() < suffix.size() || keyword.substr(keyword.size() - suffix.size()) != suffix)
    bad();
  std::string_view prefix = keyword.substr(0, keyword.size() - suffix.size());
  const bool has_extra = !prefix.empty();
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  if (!prefix.empty() && prefix[0] == 'C') prefix.remove_prefix(1);
  if (!prefix.empty() && prefix[0] == 'N') prefix.remove_prefix(1);
  if (!prefix.empty() && (prefix[0] == '4' || prefix[0] == 'n'))
    fail(file, line, "OFF variant " + quote(keyword) + " (vertices not in 3D) is not supported");
  if (!prefix.empty()) bad();
  return has_extra;
}

std::uint64_t parse_count(std::string_view token, const char* what, const std::string& file,
                          std::size_t line) {
  std::int64_t v = 0;
  if (!parse_integer(token, v))
    fail(file, line, std::string(what) + " " + quote(token) + " is not an integer");
  if (v < 0) fail(file, line, std::string(what) + " " + std::to_string(v) + " is negative");
  const auto count = static_cast<std::uint64_t>(v);
  check_element_count(count, what, file, line);
  return count;
}

}  // namespace

triangle_soup read_off(std::string_view text, const std::string& file) {
  triangle_soup soup;
  soup.source = file;
  line_reader lines(text);
  std::vector<std::string_view> tokens;
  // Advances to the next line with tokens; false at end of file.
  const auto next_content_line = [&]() {
    std::string_view line;
    while (lines.next(line)) {
      split_tokens(strip_comment(line), tokens);
      if (!tokens.empty()) return true;
    }
    return false;
  };

  if (!next_content_line())
    fail(file, lines.line_number(), "no OFF header (the file holds only blank lines and comments)");
  const bool extra_vertex_columns = parse_off_keyword(tokens[0], file, lines.line_number());
  if (tokens.size() >= 2 && tokens[1] == "BINARY")
    fail(file, lines.line_number(), "binary OFF is not supported");
  tokens.erase(tokens.begin());
  if (tokens.empty() && !next_content_line())
    fail(file, lines.line_number(), "unexpected end of file: missing the counts line 'nv nf ne'");
  if (tokens.size() < 2 || tokens.size() > 3)
    fail(file, lines.line_number(),
         "expected the counts 'nv nf ne' (vertices, faces, edges), found " +
             std::to_string(tokens.size()) + " values");
  const std::uint64_t nv = parse_count(tokens[0], "vertex count", file, lines.line_number());
  const std::uint64_t nf = parse_count(tokens[1], "face count", file, lines.line_number());
  if (tokens.size() == 3) parse_count(tokens[2], "edge count", file, lines.line_number());

  // Each vertex line needs at least 6 bytes ("0 0 0\n"), each face line 8 ("3 0 1 2\n").
  const std::size_t bytes_left = text.size() - lines.offset();
  soup.vertices.reserve(bounded_reserve(nv, bytes_left, 6));
  soup.triangles.reserve(bounded_reserve(nf, bytes_left, 8));

  // Advances to record i of n ("vertices" or "faces"); returns its line number.
  const auto next_record = [&](std::uint64_t i, std::uint64_t n, const char* what) {
    if (!next_content_line())
      fail(file, lines.line_number(),
           "unexpected end of file: read " + std::to_string(i) + " of " + std::to_string(n) + " " +
               what);
    return lines.line_number();
  };

  for (std::uint64_t i = 0; i < nv; ++i) {
    const std::size_t line = next_record(i, nv, "vertices");
    if (tokens.size() < 3)
      fail(file, line,
           "vertex " + std::to_string(i) + " has " + std::to_string(tokens.size()) +
               " coordinates, expected 3 (x y z)");
    if (tokens.size() > 3 && !extra_vertex_columns)
      fail(file, line,
           "vertex " + std::to_string(i) + " has " + std::to_string(tokens.size()) +
               " values, expected 3 (extra columns need a COFF/NOFF/STOFF header)");
    soup.vertices.push_back({parse_coordinate(tokens[0], 'x', file, line),
                             parse_coordinate(tokens[1], 'y', file, line),
                             parse_coordinate(tokens[2], 'z', file, line)});
  }

  std::vector<std::uint32_t> polygon;
  for (std::uint64_t f = 0; f < nf; ++f) {
    const std::size_t line = next_record(f, nf, "faces");
    std::int64_t k = 0;
    if (!parse_integer(tokens[0], k))
      fail(file, line, "face vertex count " + quote(tokens[0]) + " is not an integer");
    if (k < 3)
      fail(file, line,
           "face " + std::to_string(f) + " has " + std::to_string(k) +
               " vertices (at least 3 needed)");
    const std::size_t listed = tokens.size() - 1;
    if (static_cast<std::uint64_t>(k) > listed)
      fail(file, line,
           "face " + std::to_string(f) + " declares " + std::to_string(k) +
               " vertices but lists only " + std::to_string(listed) + " indices");
    const std::size_t nk = static_cast<std::size_t>(k);
    if (listed - nk > max_face_colour_values)
      fail(file, line,
           "face " + std::to_string(f) + " has " + std::to_string(listed - nk) +
               " values after its " + std::to_string(nk) +
               " indices (at most 4 colour values allowed)");
    for (std::size_t c = 1 + nk; c < tokens.size(); ++c) {
      double colour = 0.0;
      if (parse_double(tokens[c], colour) != number_status::ok)
        fail(file, line, "face colour value " + quote(tokens[c]) + " is not a number");
    }
    polygon.clear();
    for (std::size_t c = 1; c <= nk; ++c) {
      std::int64_t index = 0;
      if (!parse_integer(tokens[c], index))
        fail(file, line, "vertex index " + quote(tokens[c]) + " is not an integer");
      if (index < 0 || static_cast<std::uint64_t>(index) >= nv)
        fail(file, line,
             "vertex index " + std::to_string(index) + " out of range (" + std::to_string(nv) +
                 " vertices)");
      polygon.push_back(static_cast<std::uint32_t>(index));
    }
    soup.add_polygon(polygon, static_cast<std::uint32_t>(f));
  }

  if (next_content_line())
    fail(file, lines.line_number(),
         "unexpected data after the last face (declared face count: " + std::to_string(nf) +
             "): " + quote(tokens[0]));
  soup.face_count = static_cast<std::uint32_t>(nf);
  return soup;
}

}  // namespace exbsp::mesh_detail
