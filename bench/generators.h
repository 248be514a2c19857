// SPDX-License-Identifier: LGPL-3.0-or-later
// Benchmark inputs: a mesh file or a generated soup (random soup, sticks: their definitions are
// at the top of tests/support/inputs.h, shared with the tests), named by a spec string.
#pragma once
#include <cstdint>
#include <string>

#include <exbsp/mesh/soup.h>
#include "support/inputs.h"

namespace exbsp::bench {

using exbsp_test::make_random_soup;
using exbsp_test::make_sticks;
using exbsp_test::split_mix;

/// An input described by a spec: "mesh:PATH", "soup:N[:SEED]" or "sticks:K".
struct input_spec {
  std::string kind;  ///< "mesh", "soup", "sticks"
  std::string name;  ///< mesh file stem, "soup-N", "sticks-K"
  std::string path;  ///< mesh only
  std::size_t size = 0;
  std::uint64_t seed = 0;
};
/// Parses a spec; throws std::invalid_argument for a malformed one.
input_spec parse_input_spec(const std::string& spec);
/// Loads (read_mesh) or generates the soup of an input.
triangle_soup load_input(const input_spec& in);

/// Axis-aligned bounding box of the soup's vertices used by triangles.
struct bounds {
  vec3d lo{}, hi{};
  vec3d centre() const { return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}; }
  double diagonal() const;
};
bounds soup_bounds(const triangle_soup& soup);

}  // namespace exbsp::bench
