// SPDX-License-Identifier: LGPL-3.0-or-later
// JSON text for exbsp's coordinate outputs (`order`, `section`). docs/contract.md "Command line"
// fixes doubles as 17 significant digits ("%.17g"); nlohmann-json prints the shortest round-trip
// form instead, so these few pieces are written as text here, once, and the documents that
// use them (bsp/order_json.h, clip/section_output.cpp) share them.
#pragma once
#include <array>
#include <cstdio>
#include <string>

namespace exbsp::json_text {

/// `x` with 17 significant digits (finite values only; exbsp never writes others).
inline std::string number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// "[x, y, z]" with 17 significant digits.
inline void append_point(std::string& out, const std::array<double, 3>& p) {
  out += "[" + number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) + "]";
}

/// "[\"p/q\", \"p/q\", \"p/q\"]": exact coordinates as reduced rationals.
inline void append_exact_point(std::string& out, const std::array<std::string, 3>& p) {
  out += "[\"" + p[0] + "\", \"" + p[1] + "\", \"" + p[2] + "\"]";
}

}  // namespace exbsp::json_text
