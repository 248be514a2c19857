// Generated benchmark inputs; notation at the top of generators.h.
#include "generators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mesh/mesh_io.h"

namespace exbsp::bench {

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

input_spec parse_input_spec(const std::string& spec) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw std::invalid_argument("input spec without kind: " + spec);
  input_spec in;
  in.kind = spec.substr(0, colon);
  const std::string rest = spec.substr(colon + 1);
  if (in.kind == "mesh") {
    in.path = rest;
    const auto slash = rest.find_last_of('/');
    std::string stem = slash == std::string::npos ? rest : rest.substr(slash + 1);
    const auto dot = stem.find_last_of('.');
    in.name = dot == std::string::npos ? stem : stem.substr(0, dot);
  } else if (in.kind == "soup" || in.kind == "sticks") {
    const auto colon2 = rest.find(':');
    in.size = std::stoull(rest.substr(0, colon2));
    if (colon2 != std::string::npos) in.seed = std::stoull(rest.substr(colon2 + 1));
    in.name = in.kind + "-" + std::to_string(in.size);
  } else {
    throw std::invalid_argument("unknown input kind '" + in.kind + "' in " + spec);
  }
  return in;
}

triangle_soup load_input(const input_spec& in) {
  if (in.kind == "mesh") return read_mesh(in.path);
  if (in.kind == "soup") return make_random_soup(in.size, in.seed);
  return make_sticks(in.size);
}

double bounds::diagonal() const {
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

bounds soup_bounds(const triangle_soup& soup) {
  bounds b;
  const double inf = std::numeric_limits<double>::infinity();
  b.lo = {inf, inf, inf};
  b.hi = {-inf, -inf, -inf};
  for (const soup_triangle& t : soup.triangles)
    for (std::uint32_t v : t.v)
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], soup.vertices[v][k]);
        b.hi[k] = std::max(b.hi[k], soup.vertices[v][k]);
      }
  if (soup.triangles.empty()) b.lo = b.hi = {0, 0, 0};
  return b;
}

}  // namespace exbsp::bench
