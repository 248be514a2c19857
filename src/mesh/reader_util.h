// SPDX-License-Identifier: LGPL-3.0-or-later
// Internal helpers shared by the mesh readers (read_off.cpp, read_obj.cpp, read_ply.cpp,
// read_stl.cpp). Not part of the public API: include mesh/mesh_io.h instead.
//
// Notation: a file is held in memory as one `std::string_view text` (a leading UTF-8 byte
// order mark already removed). Lines end with "\n", "\r\n" or a lone "\r" (old Mac
// files) and are numbered from 1; the "line" of an end-of-file error is the file's last
// line. A token is a maximal run of non-blank bytes (blank = space, \t, \r, \f, \v).
// Every reader function throws exbsp::input_error(file, line, what) and nothing else that
// is caused by the file's contents (std::bad_alloc can still escape on a real memory shortage).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <exbsp/mesh/soup.h>

namespace exbsp::mesh_detail {

/// The largest vertex or face count a soup can index (indices are std::uint32_t).
constexpr std::uint64_t max_element_count = 0xFFFFFFFFull;

/// Throws input_error(file, line, what). Line 0 means "no line" (binary data, whole file).
[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& what);

/// Throws input_error(file, line, "WHAT COUNT exceeds the supported maximum ...") when the
/// element count of a header (OFF, PLY) is above max_element_count.
void check_element_count(std::uint64_t count, const std::string& what, const std::string& file,
                         std::size_t line);

/// `token` for an error message: in single quotes, at most 40 bytes, non-printable bytes
/// written as \xNN, so binary garbage cannot corrupt a terminal.
std::string quote(std::string_view token);

/// `text` without a leading UTF-8 byte order mark (EF BB BF), if it has one.
std::string_view skip_utf8_bom(std::string_view text);

/// Whether text[i] ends a line: '\n', or '\r' not followed by '\n' (the '\r' of "\r\n"
/// is a blank; its '\n' ends the line).
inline bool ends_line(std::string_view text, std::size_t i) {
  return text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'));
}

/// Splits text into lines. A line excludes its terminator ("\n", "\r\n" or "\r").
class line_reader {
 public:
  /// Starts at byte `start` of `text`; line numbers continue from `first_line - 1`.
  explicit line_reader(std::string_view text, std::size_t start = 0, std::size_t first_line = 1)
      : text_(text), pos_(start), line_(first_line - 1) {}
  /// Stores the next line in `line` and returns true, or returns false at end of text.
  bool next(std::string_view& line);
  /// Number of the line last returned by next(); after next() returned false, the number
  /// of the file's last line (0 only for empty text).
  std::size_t line_number() const { return line_; }
  /// Byte offset just after the terminator of the line last returned.
  std::size_t offset() const { return pos_; }

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t line_;
};

/// Whether `c` separates tokens (space, \t, \r, \f, \v; \n never occurs inside a line).
inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// Whether `s` equals `lowercase_word` ignoring ASCII case (`lowercase_word` is lower case).
bool equals_ignoring_case(std::string_view s, std::string_view lowercase_word);

/// `line` up to (not including) the first `marker` character.
std::string_view strip_comment(std::string_view line, char marker = '#');

/// Replaces `out` by the tokens of `line`.
void split_tokens(std::string_view line, std::vector<std::string_view>& out);

/// Result of parsing one number token.
enum class number_status {
  ok,          ///< parsed; the value is stored
  syntax,      ///< not a number in the accepted notation
  not_finite,  ///< "nan", "inf", "infinity" (any case, optional sign)
  overflow     ///< finite notation whose value is beyond the largest double (e.g. 1e999)
};

/// Parses a decimal floating-point token into the IEEE double nearest to its value
/// (std::from_chars, round to nearest even). Accepts an optional sign ('+' or '-'), digits
/// with an optional '.', and an optional exponent: 1, -0, .5, 5., 1e-3, 1E+5. Values too
/// small for a double round to the nearest denormal or to a zero of the right sign.
/// Hexadecimal notation is rejected.
number_status parse_double(std::string_view token, double& value);

/// Parses an optionally signed decimal integer token that fits in std::int64_t.
bool parse_integer(std::string_view token, std::int64_t& value);

/// Parses a coordinate token; throws input_error (file, line) naming `axis` ("x", "y", "z")
/// unless it is a finite number.
double parse_coordinate(std::string_view token, char axis, const std::string& file,
                        std::size_t line);

/// How many elements to reserve for `declared` items when each needs at least
/// `min_bytes_each` of the `bytes_left` bytes: min(declared, bytes_left / min_bytes_each + 1).
/// Keeps huge declared counts from allocating before their data has been seen.
std::size_t bounded_reserve(std::uint64_t declared, std::size_t bytes_left,
                            std::size_t min_bytes_each);

/// Merges vertices with exactly equal coordinates (== on doubles, so -0 and +0 merge; the
/// first occurrence is stored). Used by the STL reader, whose facets carry coordinates.
/// The rule is geom::weld's (geom/weld.h), but this one stays: mesh lies under geom, and it
/// welds while the file is read, one vertex at a time, with the vertex limit checked on the
/// way and the line of the vertex that exceeds it in the message.
class vertex_welder {
 public:
  explicit vertex_welder(triangle_soup& soup) : soup_(soup) {}
  /// Index of the vertex equal to `p`, appending it if new. Throws input_error(file, line)
  /// when the soup would exceed max_element_count vertices.
  std::uint32_t index_of(const vec3d& p, const std::string& file, std::size_t line);

 private:
  struct hash {
    std::size_t operator()(const vec3d& p) const;
  };
  triangle_soup& soup_;
  std::unordered_map<vec3d, std::uint32_t, hash> index_;
};

/// The format readers. `text` is the whole file (nonempty); `file` names it in messages.
/// Each fills and returns a soup (source = file) or throws input_error.
triangle_soup read_off(std::string_view text, const std::string& file);
triangle_soup read_obj(std::string_view text, const std::string& file);
triangle_soup read_ply(std::string_view text, const std::string& file);
triangle_soup read_stl(std::string_view text, const std::string& file);

}  // namespace exbsp::mesh_detail
