// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp order` output (order_json.h), built as text through core/json_text.h (17 digits).
#include "bsp/order_json.h"

#include "core/json_text.h"

namespace exbsp {

std::size_t order_json(const bsp& tree, const std::vector<std::uint32_t>& order, const vec3d& where,
                       bool use_eye, const output_sink& sink) {
  const bool exact = is_exact(tree.kernel());
  constexpr std::size_t piece = std::size_t{1} << 20;
  std::string out;
  out.reserve(piece + 4096);
  out += use_eye ? "{\"eye\": " : "{\"direction\": ";
  json_text::append_point(out, where);
  out += ",\n \"kernel\": \"" + to_string(tree.kernel()) + "\", \"heuristic\": \"" +
         tree.stats().heuristic + "\",\n \"fragments\": [";
  std::size_t written = 0, non_finite = 0;
  for (std::size_t n = 0; n < order.size(); ++n) {
    const fragment_d f = tree.fragment(order[n]);
    // An inexact kernel's rounded split point can be NaN or infinite, which JSON cannot hold:
    // such a fragment is left out and counted.
    if (!f.finite()) {
      ++non_finite;
      continue;
    }
    out += written++ ? ",\n  {\"face\": " : "\n  {\"face\": ";
    out += std::to_string(f.face) + ", \"v\": [";
    for (int i = 0; i < 3; ++i) {
      if (i) out += ", ";
      json_text::append_point(out, f.v[i]);
    }
    out += "]";
    if (exact) {
      const exact_triangle e = tree.fragment_exact(order[n]);
      out += ", \"exact\": [";
      for (int i = 0; i < 3; ++i) {
        if (i) out += ", ";
        json_text::append_exact_point(out, e[i]);
      }
      out += "]";
    }
    out += "}";
    if (out.size() >= piece) {
      sink(out);
      out.clear();
    }
  }
  out += "\n ],\n \"non_finite_fragments\": " + std::to_string(non_finite) + "}\n";
  sink(out);
  return non_finite;
}

}  // namespace exbsp
