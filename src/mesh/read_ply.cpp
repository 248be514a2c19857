// SPDX-License-Identifier: LGPL-3.0-or-later
// PLY reader (Stanford polygon format: ascii, binary_little_endian, binary_big_endian).
//
//   ply
//   format ascii|binary_little_endian|binary_big_endian 1.0
//   comment ... / obj_info ...                      ignored
//   element NAME COUNT                              COUNT instances, in file order
//   property TYPE NAME                              a scalar
//   property list COUNT_TYPE VALUE_TYPE NAME        a count, then that many values
//   end_header
//   body: for each element, COUNT instances of its properties in order
//
// TYPE: char/int8 uchar/uint8 short/int16 ushort/uint16 int/int32 uint/uint32
// float/float32 double/float64. Used: element "vertex" (scalar x, y, z of any type; an
// ascii token means the double nearest to its text, a binary float is widened exactly) and
// element "face" (list vertex_indices or vertex_index of an integer type); texture coordinates
// from the first scalar vertex pair present of (u, v), (s, t), (texture_u, texture_v),
// (texture_s, texture_t), finite, carried to the triangles' corners (triangle_soup::
// triangle_uvs; no pair: no UVs). Other properties
// and elements are checked for size/syntax and skipped; "tristrips" is rejected rather than
// dropped. ascii: one instance per line, blank lines skipped. Binary: no byte may be left
// over except trailing whitespace. Header and ascii errors name the line; binary errors
// have line 0 and give the element instance and its byte offset. Faces may come before
// vertices: indices are range-checked once all elements are read.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_set>

#include "mesh/reader_util.h"

namespace exbsp::mesh_detail {
namespace {

enum class ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
enum class ply_encoding { ascii, binary_little_endian, binary_big_endian };
enum class ply_role { skip, x, y, z, u, v, face_indices };

struct ply_type_name {
  std::string_view name;
  ply_type type;
};
constexpr ply_type_name ply_type_names[] = {
    {"char", ply_type::int8},      {"int8", ply_type::int8},       {"uchar", ply_type::uint8},
    {"uint8", ply_type::uint8},    {"short", ply_type::int16},     {"int16", ply_type::int16},
    {"ushort", ply_type::uint16},  {"uint16", ply_type::uint16},   {"int", ply_type::int32},
    {"int32", ply_type::int32},    {"uint", ply_type::uint32},     {"uint32", ply_type::uint32},
    {"float", ply_type::float32},  {"float32", ply_type::float32}, {"double", ply_type::float64},
    {"float64", ply_type::float64}};

std::size_t size_of(ply_type t) {
  switch (t) {
    case ply_type::int8:
    case ply_type::uint8:
      return 1;
    case ply_type::int16:
    case ply_type::uint16:
      return 2;
    case ply_type::int32:
    case ply_type::uint32:
    case ply_type::float32:
      return 4;
    case ply_type::float64:
      return 8;
  }
  return 8;
}

bool is_integral(ply_type t) { return t != ply_type::float32 && t != ply_type::float64; }

std::string_view name_of(ply_type t) {
  for (const ply_type_name& n : ply_type_names)
    if (n.type == t) return n.name;
  return "?";
}

// Inclusive value range of an integer type.
void range_of(ply_type t, std::int64_t& lo, std::int64_t& hi) {
  const int bits = static_cast<int>(size_of(t) * 8);
  const bool is_signed = t == ply_type::int8 || t == ply_type::int16 || t == ply_type::int32;
  lo = is_signed ? -(std::int64_t{1} << (bits - 1)) : 0;
  hi = is_signed ? (std::int64_t{1} << (bits - 1)) - 1 : (std::int64_t{1} << bits) - 1;
}

struct ply_property {
  std::string name;
  bool is_list = false;
  ply_type count_type = ply_type::uint8;
  ply_type value_type = ply_type::float32;
  ply_role role = ply_role::skip;
  std::size_t line = 0;
};

struct ply_element {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;
  std::vector<ply_property> properties;
};

struct ply_header {
  ply_encoding encoding = ply_encoding::ascii;
  bool has_uvs = false;  // the vertex element has a texture coordinate pair
  std::vector<ply_element> elements;
  std::size_t body_offset = 0;  // first byte after the end_header line
  std::size_t end_line = 0;     // line number of end_header
};

// The faces as read, validated against the vertex count at the end.
struct pending_faces {
  std::vector<std::int64_t> indices;
  std::vector<std::size_t> start;    // face f is indices[start[f] .. start[f+1])
  std::vector<std::uint64_t> where;  // ascii: line; binary: byte offset of the instance
};

ply_type parse_type(std::string_view token, const std::string& file, std::size_t line) {
  for (const ply_type_name& n : ply_type_names)
    if (n.name == token) return n.type;
  fail(file, line,
       "unknown property type " + quote(token) +
           " (expected char, uchar, short, ushort, int, uint, float, double or their "
           "int8..float64 aliases)");
}

// Assigns roles to the vertex and face properties and checks what the reader relies on.
void check_elements(ply_header& header, const std::string& file) {
  header.has_uvs = false;
  const ply_element* vertex = nullptr;
  const ply_element* face = nullptr;
  for (ply_element& e : header.elements) {
    if (e.count > 0 && e.properties.empty())
      fail(file, e.line, "element " + quote(e.name) + " has no properties");
    if (e.name == "tristrips" && e.count > 0)
      fail(file, e.line, "element 'tristrips' (triangle strips) is not supported");
    if (e.name == "vertex") {
      if (vertex) fail(file, e.line, "second 'vertex' element");
      vertex = &e;
      check_element_count(e.count, "vertex count", file, e.line);
      const char* axes[] = {"x", "y", "z"};
      const ply_role roles[] = {ply_role::x, ply_role::y, ply_role::z};
      for (int a = 0; a < 3; ++a) {
        auto p = std::find_if(e.properties.begin(), e.properties.end(),
                              [&](const ply_property& q) { return q.name == axes[a]; });
        if (p == e.properties.end())
          fail(file, e.line, std::string("element 'vertex' has no '") + axes[a] + "' property");
        if (p->is_list)
          fail(file, p->line,
               std::string("vertex property '") + axes[a] + "' must be a scalar, not a list");
        p->role = roles[a];
      }
      const auto scalar = [&](std::string_view name) -> ply_property* {
        for (ply_property& q : e.properties)
          if (q.name == name && !q.is_list) return &q;
        return nullptr;
      };
      constexpr std::string_view pairs[][2] = {
          {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
      for (const auto& pair : pairs) {
        ply_property* pu = scalar(pair[0]);
        ply_property* pv = scalar(pair[1]);
        if (!pu || !pv) continue;
        pu->role = ply_role::u;
        pv->role = ply_role::v;
        header.has_uvs = true;
        break;
      }
    } else if (e.name == "face") {
      if (face) fail(file, e.line, "second 'face' element");
      face = &e;
      check_element_count(e.count, "face count", file, e.line);
      auto p = std::find_if(e.properties.begin(), e.properties.end(),
                            [](const ply_property& q) { return q.name == "vertex_indices"; });
      if (p == e.properties.end())
        p = std::find_if(e.properties.begin(), e.properties.end(),
                         [](const ply_property& q) { return q.name == "vertex_index"; });
      if (p == e.properties.end())
        fail(file, e.line,
             "element 'face' has no list property 'vertex_indices' (or 'vertex_index')");
      if (!p->is_list) fail(file, p->line, "face property " + quote(p->name) + " must be a list");
      if (!is_integral(p->value_type))
        fail(file, p->line,
             "face indices must have an integer type, not " + std::string(name_of(p->value_type)));
      p->role = ply_role::face_indices;
    }
  }
}

ply_header parse_header(std::string_view text, const std::string& file) {
  ply_header header;
  line_reader lines(text);
  std::string_view line;
  std::vector<std::string_view> tokens;
  lines.next(line);
  split_tokens(line, tokens);
  if (tokens.size() != 1 || tokens[0] != "ply")
    fail(file, 1, "not a PLY file: the first line must be 'ply', found " + quote(line));
  bool have_format = false;
  // Duplicate checks by hash set: the header is read in time linear in its length, however
  // many elements or properties it declares.
  std::unordered_set<std::string> element_names, property_names;  // the latter: current element's
  for (;;) {
    if (!lines.next(line))
      fail(file, lines.line_number(), "unexpected end of file in the PLY header (no 'end_header')");
    const std::size_t n = lines.line_number();
    split_tokens(line, tokens);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (tokens.size() != 1) fail(file, n, "unexpected values after 'end_header'");
      if (!have_format) fail(file, n, "missing 'format' line in the PLY header");
      header.body_offset = lines.offset();
      header.end_line = n;
      break;
    }
    if (keyword == "format") {
      if (have_format) fail(file, n, "second 'format' line");
      if (tokens.size() != 3)
        fail(file, n, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (tokens[1] == "ascii")
        header.encoding = ply_encoding::ascii;
      else if (tokens[1] == "binary_little_endian")
        header.encoding = ply_encoding::binary_little_endian;
      else if (tokens[1] == "binary_big_endian")
        header.encoding = ply_encoding::binary_big_endian;
      else
        fail(file, n,
             "unknown PLY format " + quote(tokens[1]) +
                 " (expected ascii, binary_little_endian or binary_big_endian)");
      if (tokens[2] != "1.0")
        fail(file, n, "unsupported PLY format version " + quote(tokens[2]) + " (expected 1.0)");
      have_format = true;
    } else if (keyword == "element") {
      if (!have_format) fail(file, n, "'element' before the 'format' line");
      if (tokens.size() != 3) fail(file, n, "expected 'element NAME COUNT'");
      std::int64_t count = 0;
      if (!parse_integer(tokens[2], count) || count < 0)
        fail(file, n, "element count " + quote(tokens[2]) + " is not a non-negative integer");
      if (!element_names.insert(std::string(tokens[1])).second)
        fail(file, n, "second element named " + quote(tokens[1]));
      // A fresh set, not clear(): clear() costs the bucket count, which stays as large as the
      // biggest element's, and that would make many small elements after a big one quadratic.
      std::unordered_set<std::string>().swap(property_names);
      ply_element e;
      e.name = std::string(tokens[1]);
      e.count = static_cast<std::uint64_t>(count);
      e.line = n;
      header.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail(file, n, "'property' before any 'element'");
      ply_property p;
      p.line = n;
      if (tokens.size() >= 2 && tokens[1] == "list") {
        if (tokens.size() != 5)
          fail(file, n, "expected 'property list COUNT_TYPE VALUE_TYPE NAME'");
        p.is_list = true;
        p.count_type = parse_type(tokens[2], file, n);
        if (!is_integral(p.count_type))
          fail(file, n, "list count type must be an integer type, not " + quote(tokens[2]));
        p.value_type = parse_type(tokens[3], file, n);
        p.name = std::string(tokens[4]);
      } else {
        if (tokens.size() != 3) fail(file, n, "expected 'property TYPE NAME'");
        p.value_type = parse_type(tokens[1], file, n);
        p.name = std::string(tokens[2]);
      }
      ply_element& e = header.elements.back();
      if (!property_names.insert(p.name).second)
        fail(file, n, "second property named " + quote(p.name) + " in element " + quote(e.name));
      e.properties.push_back(std::move(p));
    } else {
      fail(file, n, "unknown PLY header keyword " + quote(keyword));
    }
  }
  check_elements(header, file);
  return header;
}

// ---- ascii body ----

// What an ascii value is, for messages: "<kind> '<property>'" ("property 'x'", ...).
struct value_name {
  const char* kind;
  const std::string& property;
  std::string text() const { return std::string(kind) + " " + quote(property); }
};

std::int64_t ascii_integer(std::string_view token, ply_type type, const value_name& what,
                           const std::string& file, std::size_t line) {
  std::int64_t v = 0;
  if (!parse_integer(token, v))
    fail(file, line, what.text() + " value " + quote(token) + " is not an integer");
  std::int64_t lo = 0, hi = 0;
  range_of(type, lo, hi);
  if (v < lo || v > hi)
    fail(file, line,
         what.text() + " value " + std::to_string(v) + " does not fit its type " +
             std::string(name_of(type)));
  return v;
}

// Checks a value of a skipped property.
void ascii_skip_value(std::string_view token, ply_type type, const value_name& what,
                      const std::string& file, std::size_t line) {
  if (is_integral(type)) {
    ascii_integer(token, type, what, file, line);
    return;
  }
  double v = 0.0;
  if (parse_double(token, v) == number_status::syntax)
    fail(file, line, what.text() + " value " + quote(token) + " is not a number");
}

void read_ascii_body(const ply_header& header, std::string_view text, const std::string& file,
                     triangle_soup& soup, std::vector<vec2d>& uvs, pending_faces& faces) {
  line_reader lines(text, header.body_offset, header.end_line + 1);
  std::vector<std::string_view> tokens;
  std::string_view line_text;
  for (const ply_element& e : header.elements) {
    const bool is_vertex = e.name == "vertex";
    const bool is_face = e.name == "face";
    const std::size_t bytes_left = text.size() - lines.offset();
    if (is_vertex) soup.vertices.reserve(bounded_reserve(e.count, bytes_left, 6));
    if (is_face) faces.where.reserve(bounded_reserve(e.count, bytes_left, 8));
    for (std::uint64_t i = 0; i < e.count; ++i) {
      bool found = false;
      while (lines.next(line_text)) {
        split_tokens(line_text, tokens);
        if (!tokens.empty()) {
          found = true;
          break;
        }
      }
      if (!found)
        fail(file, lines.line_number(),
             "unexpected end of file: read " + std::to_string(i) + " of " +
                 std::to_string(e.count) + " instances of element " + quote(e.name));
      const std::size_t n = lines.line_number();
      const auto too_few = [&]() {
        fail(file, n,
             "too few values for element " + quote(e.name) + " (" + std::to_string(tokens.size()) +
                 " on the line)");
      };
      std::size_t t = 0;
      vec3d p = {0.0, 0.0, 0.0};
      vec2d uv = {0.0, 0.0};
      for (const ply_property& prop : e.properties) {
        const value_name what{"property", prop.name};
        if (!prop.is_list) {
          if (t >= tokens.size()) too_few();
          const std::string_view token = tokens[t++];
          if (prop.role == ply_role::skip) {
            ascii_skip_value(token, prop.value_type, what, file, n);
            continue;
          }
          if (prop.role == ply_role::u || prop.role == ply_role::v) {
            double value = 0.0;
            if (is_integral(prop.value_type))
              value = static_cast<double>(ascii_integer(token, prop.value_type, what, file, n));
            else if (parse_double(token, value) != number_status::ok)
              fail(file, n,
                   "texture coordinate " + quote(prop.name) + " value " + quote(token) +
                       " is not a finite number");
            uv[prop.role == ply_role::u ? 0 : 1] = value;
            continue;
          }
          const int axis = prop.role == ply_role::x ? 0 : prop.role == ply_role::y ? 1 : 2;
          p[axis] = is_integral(prop.value_type)
                        ? static_cast<double>(ascii_integer(token, prop.value_type, what, file, n))
                        : parse_coordinate(token, static_cast<char>('x' + axis), file, n);
          continue;
        }
        if (t >= tokens.size()) too_few();
        const std::int64_t count = ascii_integer(tokens[t++], prop.count_type,
                                                 value_name{"list count of", prop.name}, file, n);
        if (count < 0) fail(file, n, "list count of " + quote(prop.name) + " is negative");
        if (static_cast<std::uint64_t>(count) > tokens.size() - t) too_few();
        if (prop.role == ply_role::face_indices) {
          if (count < 3)
            fail(file, n,
                 "face " + std::to_string(i) + " has " + std::to_string(count) +
                     " vertices (at least 3 needed)");
          faces.start.push_back(faces.indices.size());
          faces.where.push_back(n);
          for (std::int64_t c = 0; c < count; ++c)
            faces.indices.push_back(ascii_integer(tokens[t++], prop.value_type, what, file, n));
        } else {
          for (std::int64_t c = 0; c < count; ++c)
            ascii_skip_value(tokens[t++], prop.value_type, what, file, n);
        }
      }
      if (t != tokens.size())
        fail(file, n,
             "too many values for element " + quote(e.name) + " (" + std::to_string(tokens.size()) +
                 " on the line, " + std::to_string(t) + " expected)");
      if (is_vertex) {
        soup.vertices.push_back(p);
        if (header.has_uvs) uvs.push_back(uv);
      }
    }
  }
  while (lines.next(line_text)) {
    split_tokens(line_text, tokens);
    if (!tokens.empty())
      fail(file, lines.line_number(),
           "unexpected data after the last element: " + quote(tokens[0]));
  }
}

// ---- binary body ----

class byte_reader {
 public:
  byte_reader(std::string_view text, std::size_t offset, bool big_endian)
      : text_(text), pos_(offset), big_endian_(big_endian) {}
  std::size_t offset() const { return pos_; }
  std::size_t left() const { return text_.size() - pos_; }
  void skip(std::size_t n) { pos_ += n; }
  // Raw bits of a value of `size` bytes in file byte order. Precondition: left() >= size.
  std::uint64_t bits(std::size_t size) {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const std::size_t at = big_endian_ ? pos_ + k : pos_ + size - 1 - k;
      v = (v << 8) | static_cast<unsigned char>(text_[at]);
    }
    pos_ += size;
    return v;
  }
  // A value of integer type `t`. Precondition: left() >= size_of(t).
  std::int64_t integer(ply_type t) {
    const std::uint64_t b = bits(size_of(t));
    switch (t) {
      case ply_type::int8:
        return static_cast<std::int8_t>(static_cast<std::uint8_t>(b));
      case ply_type::int16:
        return static_cast<std::int16_t>(static_cast<std::uint16_t>(b));
      case ply_type::int32:
        return static_cast<std::int32_t>(static_cast<std::uint32_t>(b));
      default:
        return static_cast<std::int64_t>(b);
    }
  }
  // A value of any type `t`, widened exactly to double. Precondition: left() >= size_of(t).
  double real(ply_type t) {
    if (t == ply_type::float32) {
      const auto b = static_cast<std::uint32_t>(bits(4));
      float f = 0.0f;
      std::memcpy(&f, &b, sizeof f);
      return static_cast<double>(f);
    }
    if (t == ply_type::float64) {
      const std::uint64_t b = bits(8);
      double d = 0.0;
      std::memcpy(&d, &b, sizeof d);
      return d;
    }
    return static_cast<double>(integer(t));
  }

 private:
  std::string_view text_;
  std::size_t pos_;
  bool big_endian_;
};

void read_binary_body(const ply_header& header, std::string_view text, const std::string& file,
                      triangle_soup& soup, std::vector<vec2d>& uvs, pending_faces& faces) {
  byte_reader in(text, header.body_offset, header.encoding == ply_encoding::binary_big_endian);
  for (const ply_element& e : header.elements) {
    if (e.count == 0) continue;
    std::size_t min_size = 0;  // bytes of an instance whose lists are all empty
    bool fixed_size = true;
    for (const ply_property& p : e.properties) {
      min_size += size_of(p.is_list ? p.count_type : p.value_type);
      if (p.is_list) fixed_size = false;
    }
    if (e.count > in.left() / min_size)
      fail(file, 0,
           "unexpected end of file: element " + quote(e.name) + " declares " +
               std::to_string(e.count) + " instances of at least " + std::to_string(min_size) +
               " bytes, but only " + std::to_string(in.left()) + " bytes remain (byte offset " +
               std::to_string(in.offset()) + ")");
    const bool is_vertex = e.name == "vertex";
    const bool is_face = e.name == "face";
    if (!is_vertex && !is_face && fixed_size) {
      in.skip(static_cast<std::size_t>(e.count) * min_size);
      continue;
    }
    if (is_vertex)
      soup.vertices.reserve(static_cast<std::size_t>(e.count));  // bounded by the check above
    if (is_face) {
      faces.where.reserve(static_cast<std::size_t>(e.count));
      faces.start.reserve(static_cast<std::size_t>(e.count));
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const std::size_t instance_offset = in.offset();
      const auto where = [&]() {  // built only for a message
        return "element " + quote(e.name) + " #" + std::to_string(i) + " (byte offset " +
               std::to_string(instance_offset) + ")";
      };
      const auto need = [&](std::uint64_t bytes) {
        if (bytes > in.left()) fail(file, 0, "unexpected end of file in " + where());
      };
      vec3d p = {0.0, 0.0, 0.0};
      vec2d uv = {0.0, 0.0};
      for (const ply_property& prop : e.properties) {
        if (!prop.is_list) {
          const std::size_t size = size_of(prop.value_type);
          need(size);
          if (prop.role == ply_role::skip) {
            in.skip(size);
            continue;
          }
          if (prop.role == ply_role::u || prop.role == ply_role::v) {
            const double value = in.real(prop.value_type);
            if (!std::isfinite(value))
              fail(file, 0,
                   where() + ": texture coordinate " + quote(prop.name) +
                       " is not finite (NaN/Inf are not allowed)");
            uv[prop.role == ply_role::u ? 0 : 1] = value;
            continue;
          }
          const int axis = prop.role == ply_role::x ? 0 : prop.role == ply_role::y ? 1 : 2;
          p[axis] = in.real(prop.value_type);
          if (!std::isfinite(p[axis]))
            fail(file, 0,
                 where() + ": " + std::string(1, static_cast<char>('x' + axis)) +
                     " coordinate is not finite (NaN/Inf are not allowed)");
          continue;
        }
        need(size_of(prop.count_type));
        const std::int64_t count = in.integer(prop.count_type);
        if (count < 0)
          fail(file, 0, where() + ": list " + quote(prop.name) + " has a negative count");
        const std::size_t value_size = size_of(prop.value_type);
        need(static_cast<std::uint64_t>(count) * value_size);
        if (prop.role != ply_role::face_indices) {
          in.skip(static_cast<std::size_t>(count) * value_size);
          continue;
        }
        if (count < 3)
          fail(file, 0,
               where() + ": face has " + std::to_string(count) + " vertices (at least 3 needed)");
        faces.start.push_back(faces.indices.size());
        faces.where.push_back(instance_offset);
        for (std::int64_t c = 0; c < count; ++c)
          faces.indices.push_back(in.integer(prop.value_type));
      }
      if (is_vertex) {
        soup.vertices.push_back(p);
        if (header.has_uvs) uvs.push_back(uv);
      }
    }
  }
  for (std::size_t k = in.offset(); k < text.size(); ++k)
    if (!is_blank(text[k]) && text[k] != '\n')
      fail(file, 0,
           std::to_string(text.size() - in.offset()) +
               " bytes of unexpected data after the last element (byte offset " +
               std::to_string(in.offset()) + ")");
}

}  // namespace

triangle_soup read_ply(std::string_view text, const std::string& file) {
  ply_header header = parse_header(text, file);
  triangle_soup soup;
  soup.source = file;
  pending_faces faces;
  std::vector<vec2d> uvs;  // per vertex, when header.has_uvs
  const bool ascii = header.encoding == ply_encoding::ascii;
  if (ascii)
    read_ascii_body(header, text, file, soup, uvs, faces);
  else
    read_binary_body(header, text, file, soup, uvs, faces);

  const std::size_t nv = soup.vertices.size();
  std::vector<std::uint32_t> polygon;
  std::vector<vec2d> polygon_uvs;
  const std::size_t nf = faces.start.size();
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t begin = faces.start[f];
    const std::size_t end = f + 1 < nf ? faces.start[f + 1] : faces.indices.size();
    polygon.clear();
    for (std::size_t c = begin; c < end; ++c) {
      const std::int64_t index = faces.indices[c];
      if (index < 0 || static_cast<std::uint64_t>(index) >= nv) {
        const std::string what = "vertex index " + std::to_string(index) + " out of range (" +
                                 std::to_string(nv) + " vertices)";
        if (ascii) fail(file, static_cast<std::size_t>(faces.where[f]), what);
        fail(file, 0,
             "element 'face' #" + std::to_string(f) + " (byte offset " +
                 std::to_string(faces.where[f]) + "): " + what);
      }
      polygon.push_back(static_cast<std::uint32_t>(index));
    }
    if (header.has_uvs) {
      polygon_uvs.clear();
      for (std::uint32_t v : polygon) polygon_uvs.push_back(uvs[v]);
      soup.add_polygon(polygon, polygon_uvs, static_cast<std::uint32_t>(f));
    } else {
      soup.add_polygon(polygon, static_cast<std::uint32_t>(f));
    }
  }
  return soup;
}

}  // namespace exbsp::mesh_detail
