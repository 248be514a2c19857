// SPDX-License-Identifier: LGPL-3.0-or-later
// Shared helpers of the mesh readers: lines, tokens, exact number parsing, messages.
// Numbers: a decimal token means the IEEE double nearest to its value; std::from_chars
// (correctly rounded) does the conversion, this file only adds the sign handling, the
// rejection of nan/inf and the overflow/underflow decision.
#include "mesh/reader_util.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

#include <exbsp/core/errors.h>

namespace exbsp::mesh_detail {

void fail(const std::string& file, std::size_t line, const std::string& what) {
  throw input_error(file, line, what);
}

void check_element_count(std::uint64_t count, const std::string& what, const std::string& file,
                         std::size_t line) {
  if (count > max_element_count)
    fail(file, line,
         what + " " + std::to_string(count) + " exceeds the supported maximum " +
             std::to_string(max_element_count));
}

std::string quote(std::string_view token) {
  constexpr std::size_t max_shown = 40;
  static const char hex[] = "0123456789abcdef";
  std::string out = "'";
  const std::size_t shown = std::min(token.size(), max_shown);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > max_shown) out += "...";
  out += "'";
  return out;
}

std::string_view skip_utf8_bom(std::string_view text) {
  return text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text;
}

bool line_reader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const std::size_t end = std::min(text_.find_first_of("\r\n", pos_), text_.size());
  std::size_t after = end;
  if (end < text_.size())
    after =
        text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n' ? end + 2 : end + 1;
  line = text_.substr(pos_, end - pos_);
  pos_ = after;
  ++line_;
  return true;
}

std::string_view strip_comment(std::string_view line, char marker) {
  const std::size_t at = line.find(marker);
  return at == std::string_view::npos ? line : line.substr(0, at);
}

void split_tokens(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && is_blank(line[i])) ++i;
    if (i == n) break;
    const std::size_t start = i;
    while (i < n && !is_blank(line[i])) ++i;
    out.push_back(line.substr(start, i - start));
  }
}

namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

bool equals_ignoring_case(std::string_view s, std::string_view lowercase_word) {
  if (s.size() != lowercase_word.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (lower(s[i]) != lowercase_word[i]) return false;
  return true;
}

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Whether an unsigned decimal literal accepted by from_chars whose value is out of the
// double range is too large (true) rather than too small (false). The value is
// 0.d1d2... * 10^E with d1 != 0; overflow needs E >= 309 and underflow E <= -323,
// so the sign of E decides.
bool magnitude_exceeds_one(std::string_view body) {
  std::size_t i = 0;
  const std::size_t n = body.size();
  long long e = 0;
  bool nonzero_seen = false;
  for (; i < n && is_digit(body[i]); ++i) {
    if (body[i] != '0') nonzero_seen = true;
    if (nonzero_seen) ++e;  // digits of the integer part from the first nonzero one
  }
  if (i < n && body[i] == '.') {
    ++i;
    for (; i < n && is_digit(body[i]); ++i) {
      if (nonzero_seen) continue;
      if (body[i] != '0')
        nonzero_seen = true;
      else
        --e;  // leading zeros of the fraction
    }
  }
  if (i < n && (body[i] == 'e' || body[i] == 'E')) {
    ++i;
    bool negative = false;
    if (i < n && (body[i] == '+' || body[i] == '-')) negative = body[i++] == '-';
    long long exponent = 0;
    for (; i < n && is_digit(body[i]); ++i)
      exponent = std::min(exponent * 10 + (body[i] - '0'), 1000000000000LL);
    e += negative ? -exponent : exponent;
  }
  return e > 0;
}

}  // namespace

number_status parse_double(std::string_view token, double& value) {
  if (token.empty()) return number_status::syntax;
  bool negative = false;
  std::string_view body = token;
  if (body[0] == '+' || body[0] == '-') {
    negative = body[0] == '-';
    body.remove_prefix(1);
  }
  if (body.empty()) return number_status::syntax;
  if (!is_digit(body[0]) && body[0] != '.') {
    // std::from_chars would accept these words; they never denote a finite coordinate.
    if (equals_ignoring_case(body, "inf") || equals_ignoring_case(body, "infinity") ||
        equals_ignoring_case(body, "nan") ||
        (body.size() > 4 && equals_ignoring_case(body.substr(0, 4), "nan(") && body.back() == ')'))
      return number_status::not_finite;
    return number_status::syntax;
  }
  double magnitude = 0.0;
  const char* first = body.data();
  const char* last = body.data() + body.size();
  const std::from_chars_result r =
      std::from_chars(first, last, magnitude, std::chars_format::general);
  if (r.ec == std::errc::invalid_argument || r.ptr != last) return number_status::syntax;
  if (r.ec == std::errc::result_out_of_range) {
    if (magnitude_exceeds_one(body)) return number_status::overflow;
    magnitude = 0.0;  // below half the smallest denormal: the nearest double is zero
  } else if (r.ec != std::errc()) {
    return number_status::syntax;
  }
  value = negative ? -magnitude : magnitude;
  return number_status::ok;
}

bool parse_integer(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token[0] == '+') {
    token.remove_prefix(1);
    if (token.empty() || token[0] == '-') return false;
  }
  if (token.empty()) return false;
  std::int64_t v = 0;
  const std::from_chars_result r = std::from_chars(token.data(), token.data() + token.size(), v);
  if (r.ec != std::errc() || r.ptr != token.data() + token.size()) return false;
  value = v;
  return true;
}

double parse_coordinate(std::string_view token, char axis, const std::string& file,
                        std::size_t line) {
  double v = 0.0;
  const number_status status = parse_double(token, v);
  if (status == number_status::ok) return v;
  const std::string name = std::string(1, axis) + " coordinate " + quote(token);
  if (status == number_status::not_finite)
    fail(file, line, name + " is not finite (NaN/Inf are not allowed)");
  if (status == number_status::overflow) fail(file, line, name + " overflows double (not finite)");
  fail(file, line, name + " is not a number");
}

std::size_t bounded_reserve(std::uint64_t declared, std::size_t bytes_left,
                            std::size_t min_bytes_each) {
  const std::uint64_t cap = bytes_left / std::max<std::size_t>(min_bytes_each, 1) + 1;
  return static_cast<std::size_t>(std::min(declared, cap));
}

std::size_t vertex_welder::hash::operator()(const vec3d& p) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (double c : p) {
    const double normalized = c == 0.0 ? 0.0 : c;  // -0 == +0, so they must hash alike
    std::uint64_t bits = 0;
    std::memcpy(&bits, &normalized, sizeof bits);
    h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  }
  return static_cast<std::size_t>(h);
}

std::uint32_t vertex_welder::index_of(const vec3d& p, const std::string& file, std::size_t line) {
  const auto found = index_.find(p);
  if (found != index_.end()) return found->second;
  if (soup_.vertices.size() >= max_element_count)
    fail(file, line, "too many vertices (at most " + std::to_string(max_element_count) + ")");
  const auto index = static_cast<std::uint32_t>(soup_.vertices.size());
  soup_.vertices.push_back(p);
  index_.emplace(p, index);
  return index;
}

}  // namespace exbsp::mesh_detail
