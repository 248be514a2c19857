// SPDX-License-Identifier: LGPL-3.0-or-later
// Benchmark inputs by spec; see generators.h.
#include "generators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <exbsp/mesh/mesh_io.h>

namespace exbsp::bench {

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
