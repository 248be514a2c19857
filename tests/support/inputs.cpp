// SPDX-License-Identifier: LGPL-3.0-or-later
// Deterministic generated inputs; notation at the top of inputs.h.
#include "support/inputs.h"

#include <array>
#include <cstdio>

namespace exbsp_test {

using exbsp::triangle_soup;
using exbsp::vec3d;

std::uint64_t split_mix::next() {
  std::uint64_t x = (state_ += 0x9e3779b97f4a7c15ULL);
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

triangle_soup make_random_soup(std::size_t n, std::uint64_t seed) {
  triangle_soup soup;
  soup.source = "soup-" + std::to_string(n);
  split_mix rng(seed * 0x100000001b3ULL + n);
  const double side = std::cbrt(static_cast<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const vec3d c{side * rng.uniform(), side * rng.uniform(), side * rng.uniform()};
    std::array<vec3d, 3> v;
    for (auto& p : v)
      for (int k = 0; k < 3; ++k) p[k] = c[k] + 1.2 * (rng.uniform() - 0.5);
    soup.add_triangle(v[0], v[1], v[2]);
  }
  return soup;
}

triangle_soup make_sticks(std::size_t k) {
  triangle_soup soup;
  soup.source = "sticks-" + std::to_string(k);
  const double h = 0.25, lo = -1, hi = static_cast<double>(k);
  const auto stick = [&soup](const vec3d& a, const vec3d& b, const vec3d& c, const vec3d& d) {
    soup.add_triangle(a, b, c);
    soup.add_triangle(a, c, d);
  };
  for (std::size_t i = 0; i < k; ++i) {  // layer A: planes y = i
    const double y = static_cast<double>(i);
    stick({lo, y, 0}, {hi, y, 0}, {hi, y, h}, {lo, y, h});
  }
  for (std::size_t j = 0; j < k; ++j) {  // layer B: planes x = j + 1/2
    const double x = static_cast<double>(j) + 0.5;
    stick({x, lo, 1}, {x, hi, 1}, {x, hi, 1 + h}, {x, lo, 1 + h});
  }
  return soup;
}

std::string off_text(const triangle_soup& soup) {
  std::string out = "OFF\n" + std::to_string(soup.vertices.size()) + " " +
                    std::to_string(soup.triangles.size()) + " 0\n";
  char buffer[128];
  for (const vec3d& p : soup.vertices) {
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    out += buffer;
  }
  for (const exbsp::soup_triangle& t : soup.triangles) {
    std::snprintf(buffer, sizeof buffer, "3 %u %u %u\n", static_cast<unsigned>(t.v[0]),
                  static_cast<unsigned>(t.v[1]), static_cast<unsigned>(t.v[2]));
    out += buffer;
  }
  return out;
}

}  // namespace exbsp_test
