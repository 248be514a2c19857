// SPDX-License-Identifier: LGPL-3.0-or-later
#include "support/observable.h"

#include <cstdio>

namespace exbsp_test {

std::string observable(const exbsp::bsp& t, const std::vector<exbsp::vec3d>& eyes) {
  const auto& s = t.stats();
  std::string out = std::to_string(s.input_triangles) + " " + std::to_string(s.degenerate_input) +
                    " " + std::to_string(s.fragments) + " " + std::to_string(s.splits) + " " +
                    std::to_string(s.nodes) + " " + std::to_string(s.depth) + " " + s.heuristic +
                    "\n";
  char buf[64];
  for (std::size_t i = 0; i < t.fragment_count(); ++i) {
    const auto d = t.fragment(i);
    out += std::to_string(d.face);
    if (exbsp::is_exact(t.kernel()))
      for (const auto& p : t.fragment_exact(i))
        for (const auto& x : p) out += " " + x;
    for (const auto& p : d.v)
      for (double x : p) {
        std::snprintf(buf, sizeof buf, " %.17g", x);
        out += buf;
      }
    for (const auto& a : t.ancestors(i))
      out += " " + std::to_string(a.plane_face) + (a.side > 0 ? "+" : "-");
    out += "\n";
  }
  for (const exbsp::vec3d& e : eyes) {
    out += "eye:";
    for (const auto i : t.order_from_eye(e)) out += std::to_string(i) + ",";
    out += "\n";
    if (e == exbsp::vec3d{0, 0, 0}) continue;
    out += "direction:";
    for (const auto i : t.order_for_direction(e)) out += std::to_string(i) + ",";
    out += "\n";
  }
  return out;
}

std::vector<exbsp::vec3d> eyes_for(const exbsp::triangle_soup& soup) {
  std::vector<exbsp::vec3d> eyes{{0.3, -7, 11}, {-5, 2, -3}, {1, 1, 1}};
  for (std::size_t i = 0; i < soup.vertices.size() && i < 9; i += 4)
    eyes.push_back(soup.vertices[i]);
  return eyes;
}

}  // namespace exbsp_test
