// SPDX-License-Identifier: LGPL-3.0-or-later
// libFuzzer target: the number parsing every mesh reader relies on (mesh/reader_util.h),
// checked against an independent oracle. docs/contract.md "Input": "a coordinate in a file means
// the IEEE double nearest to its decimal text". One input = one token.
//
// parse_double(token):
//   - a token of the documented notation [+-] digits [. digits] [(e|E) [+-] digits] (at
//     least one mantissa digit, either side of the '.') is ok or overflow, never syntax;
//     ok gives exactly the bits of glibc's strtod (correctly rounded, so also the sign of a
//     zero and every denormal), overflow happens exactly when strtod overflows;
//   - inf, infinity, nan, nan(...) with an optional sign, any case: not_finite;
//   - everything else (hex, blanks, NUL, empty, ...): syntax.
// parse_integer(token): [+|-] digits that fit std::int64_t, the value of strtoll; else false.
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "mesh/reader_util.h"

namespace {

using exbsp::fuzz::require;
using exbsp::mesh_detail::number_status;

bool digit(char c) { return c >= '0' && c <= '9'; }

// The notation parse_double documents (reader_util.h), written out independently.
bool is_decimal_notation(std::string_view s) {
  std::size_t i = 0;
  const std::size_t n = s.size();
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa_digits = 0;
  while (i < n && digit(s[i])) ++i, ++mantissa_digits;
  if (i < n && s[i] == '.') {
    ++i;
    while (i < n && digit(s[i])) ++i, ++mantissa_digits;
  }
  if (mantissa_digits == 0) return false;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    while (i < n && digit(s[i])) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == n;
}

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equals_lower(std::string_view s, std::string_view word) {
  if (s.size() != word.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (lower(s[i]) != word[i]) return false;
  return true;
}

bool is_non_finite_word(std::string_view s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  if (equals_lower(s, "inf") || equals_lower(s, "infinity") || equals_lower(s, "nan")) return true;
  return s.size() > 4 && equals_lower(s.substr(0, 4), "nan(") && s.back() == ')';
}

bool is_integer_notation(std::string_view s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  if (s.empty()) return false;
  for (char c : s)
    if (!digit(c)) return false;
  return true;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void check_double(std::string_view token) {
  double value = 12345.0;
  const number_status status = exbsp::mesh_detail::parse_double(token, value);
  if (is_decimal_notation(token)) {
    require(status == number_status::ok || status == number_status::overflow,
            "a decimal in the documented notation is accepted (ok or overflow)");
    const std::string text(token);
    errno = 0;
    char* end = nullptr;
    const double expected = std::strtod(text.c_str(), &end);
    require(end == text.c_str() + text.size(), "strtod reads the whole decimal");
    const bool overflows = std::isinf(expected);
    require(overflows == (status == number_status::overflow),
            "overflow exactly when strtod overflows");
    if (status == number_status::ok) {
      if (!same_bits(value, expected)) {
        std::fprintf(stderr, "exbsp fuzz: parse_double %.17g (%a), strtod %.17g (%a)\n", value,
                     value, expected, expected);
        require(false,
                "parse_double gives the double nearest to the decimal (bit-identical to strtod)");
      }
    }
  } else if (is_non_finite_word(token)) {
    require(status == number_status::not_finite, "inf/nan words are not_finite");
  } else {
    require(status == number_status::syntax, "anything else is a syntax error");
  }
}

void check_integer(std::string_view token) {
  std::int64_t value = 777;
  const bool ok = exbsp::mesh_detail::parse_integer(token, value);
  if (!is_integer_notation(token)) {
    require(!ok, "parse_integer rejects what is not [+|-]digits");
    return;
  }
  const std::string text(token);
  errno = 0;
  char* end = nullptr;
  const long long expected = std::strtoll(text.c_str(), &end, 10);
  const bool fits = errno != ERANGE;
  require(ok == fits, "parse_integer accepts exactly the integers that fit int64");
  if (ok) require(value == expected, "parse_integer gives the value of strtoll");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view token(reinterpret_cast<const char*>(data), size);
  exbsp::fuzz::run_guarded([&] {
    check_double(token);
    check_integer(token);
  });
  return 0;
}
