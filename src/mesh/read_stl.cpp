// SPDX-License-Identifier: LGPL-3.0-or-later
// STL reader (stereolithography, ascii and binary).
//
// binary:  80-byte header (ignored, may start with "solid"), uint32 N, then N records of
//          50 bytes: float32 normal[3] (ignored), float32 vertex[3][3], uint16 attribute
//          (ignored); all little endian. The file size must be exactly 84 + 50 N.
// ascii:   solid [name]
//            facet normal ni nj nk          (normal ignored; nan allowed there)
//              outer loop
//                vertex x y z               (3 per facet; more are fan-triangulated)
//              endloop
//            endfacet
//          endsolid [name]                  several solids may follow one another
//          Keywords are matched ignoring case; the rest of a solid/endsolid line is a name.
//
// Detection: binary when the size is 84 + 50 N for the N stored at byte 80; otherwise
// ascii when the file starts with "solid" (after an optional UTF-8 byte order mark) and
// holds no NUL byte; otherwise an error. Ascii lines end with \n, \r\n or \r.
// Facet j (0-based, in file order) is face j. Vertices with exactly equal coordinates are
// merged into one soup vertex (the first occurrence is kept), like other STL loaders do;
// merging changes no coordinate, so the geometry is exactly the file's.
#include <cmath>
#include <cstring>

#include "mesh/reader_util.h"

namespace exbsp::mesh_detail {
namespace {

constexpr std::size_t stl_header_size = 84;
constexpr std::size_t stl_record_size = 50;

std::uint32_t little_endian_u32(std::string_view text, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k)
    v = (v << 8) | static_cast<unsigned char>(text[at + static_cast<std::size_t>(k)]);
  return v;
}

float little_endian_float(std::string_view text, std::size_t at) {
  const std::uint32_t bits = little_endian_u32(text, at);
  float f = 0.0f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

bool starts_with_solid(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size() && (is_blank(text[i]) || ends_line(text, i))) ++i;
  const std::string_view word = text.substr(i, 5);
  if (!equals_ignoring_case(word, "solid")) return false;
  return i + 5 == text.size() || is_blank(text[i + 5]) || ends_line(text, i + 5);
}

triangle_soup read_binary_stl(std::string_view text, const std::string& file, std::uint32_t count) {
  triangle_soup soup;
  soup.source = file;
  soup.triangles.reserve(count);  // the file size was checked: count records are present
  vertex_welder weld(soup);
  std::vector<std::uint32_t> polygon(3);
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::size_t record = stl_header_size + std::size_t{t} * stl_record_size;
    for (std::size_t v = 0; v < 3; ++v) {
      vec3d p;
      for (std::size_t a = 0; a < 3; ++a) {
        p[a] = static_cast<double>(little_endian_float(text, record + 12 + 12 * v + 4 * a));
        if (!std::isfinite(p[a]))
          fail(file, 0,
               "triangle #" + std::to_string(t) + " (byte offset " + std::to_string(record) +
                   "): coordinate is not finite (NaN/Inf are not allowed)");
      }
      polygon[v] = weld.index_of(p, file, 0);
    }
    soup.add_polygon(polygon, t);
  }
  return soup;
}

// Tokens of an ascii STL with the line of each.
class token_reader {
 public:
  explicit token_reader(std::string_view text) : text_(text) {}
  // Stores the next token in `token`; false at end of text.
  bool next(std::string_view& token) {
    while (pos_ < text_.size() && (is_blank(text_[pos_]) || ends_line(text_, pos_))) {
      if (ends_line(text_, pos_)) ++line_;
      ++pos_;
    }
    if (pos_ == text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_]) && !ends_line(text_, pos_)) ++pos_;
    token = text_.substr(start, pos_ - start);
    return true;
  }
  // Skips the rest of the current line (a solid's name).
  void skip_line() {
    while (pos_ < text_.size() && !ends_line(text_, pos_)) ++pos_;
  }
  // Line of the last token.
  std::size_t line() const { return line_; }
  // The file's last line, for end-of-file messages.
  std::size_t last_line() const {
    return !text_.empty() && ends_line(text_, text_.size() - 1) ? line_count() : line_count() + 1;
  }

 private:
  std::size_t line_count() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < text_.size(); ++i) n += ends_line(text_, i);
    return n;
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

triangle_soup read_ascii_stl(std::string_view text, const std::string& file) {
  triangle_soup soup;
  soup.source = file;
  vertex_welder weld(soup);
  token_reader in(text);
  std::string_view token;
  const auto next_or_fail = [&](const char* expected) {
    if (!in.next(token))
      fail(file, in.last_line(), std::string("unexpected end of file: expected ") + expected);
  };
  const auto expect = [&](const char* word) {
    next_or_fail((std::string("'") + word + "'").c_str());
    if (!equals_ignoring_case(token, word))
      fail(file, in.line(), std::string("expected '") + word + "', found " + quote(token));
  };

  std::uint64_t facets = 0;
  std::vector<std::uint32_t> polygon;
  bool first_solid = true;
  while (in.next(token)) {
    if (!equals_ignoring_case(token, "solid"))
      fail(file, in.line(),
           std::string(first_solid ? "expected 'solid'" : "expected 'solid' or the end of file") +
               ", found " + quote(token));
    first_solid = false;
    in.skip_line();
    for (;;) {
      next_or_fail("'facet' or 'endsolid'");
      if (equals_ignoring_case(token, "endsolid")) {
        in.skip_line();
        break;
      }
      if (!equals_ignoring_case(token, "facet"))
        fail(file, in.line(), "expected 'facet' or 'endsolid', found " + quote(token));
      expect("normal");
      for (int a = 0; a < 3; ++a) {
        next_or_fail("a normal component");
        double ignored = 0.0;
        if (parse_double(token, ignored) == number_status::syntax)
          fail(file, in.line(), "normal component " + quote(token) + " is not a number");
      }
      expect("outer");
      expect("loop");
      polygon.clear();
      for (;;) {
        next_or_fail("'vertex' or 'endloop'");
        if (equals_ignoring_case(token, "endloop")) break;
        if (!equals_ignoring_case(token, "vertex"))
          fail(file, in.line(), "expected 'vertex' or 'endloop', found " + quote(token));
        vec3d p;
        for (std::size_t a = 0; a < 3; ++a) {
          next_or_fail("a vertex coordinate");
          p[a] = parse_coordinate(token, static_cast<char>('x' + a), file, in.line());
        }
        polygon.push_back(weld.index_of(p, file, in.line()));
      }
      if (polygon.size() < 3)
        fail(file, in.line(),
             "facet " + std::to_string(facets) + " has " + std::to_string(polygon.size()) +
                 " vertices (at least 3 needed)");
      expect("endfacet");
      if (facets >= max_element_count)
        fail(file, in.line(),
             "too many facets (at most " + std::to_string(max_element_count) + ")");
      soup.add_polygon(polygon, static_cast<std::uint32_t>(facets));
      ++facets;
    }
  }
  return soup;
}

}  // namespace

triangle_soup read_stl(std::string_view text, const std::string& file) {
  if (text.size() >= stl_header_size) {
    const std::uint32_t count = little_endian_u32(text, 80);
    const std::uint64_t expected = stl_header_size + std::uint64_t{count} * stl_record_size;
    if (text.size() == expected) return read_binary_stl(text, file, count);
    if (starts_with_solid(skip_utf8_bom(text)) && text.find('\0') == std::string_view::npos)
      return read_ascii_stl(skip_utf8_bom(text), file);
    fail(file, 0,
         "binary STL declares " + std::to_string(count) + " triangles (" +
             std::to_string(expected) + " bytes) but the file has " + std::to_string(text.size()) +
             " bytes");
  }
  text = skip_utf8_bom(text);
  if (!starts_with_solid(text) || text.find('\0') != std::string_view::npos)
    fail(file, 0,
         "not an STL file: too short for binary STL (" + std::to_string(text.size()) +
             " bytes, at least 84 needed) and not ascii STL (no 'solid' at the start)");
  return read_ascii_stl(text, file);
}

}  // namespace exbsp::mesh_detail
