// Generated benchmark inputs (deterministic for a seed, the same on every machine).
//
// random soup (n, seed): n triangles at constant density: centres uniform in a cube of side
//   L = n^(1/3) (one triangle per unit volume), each vertex = centre + a random offset in
//   [-0.6, 0.6]^3. Triangles intersect their neighbours: about as many crossings per triangle
//   at every n, so growth in fragments comes from the splitting planes, not from denser input.
// sticks (k): the quadratic worst case of autopartitions. Layer A: k thin vertical sticks in
//   the planes y = i (i = 0..k-1), x in [-1, k], z in [0, h]; layer B, above it: k sticks in
//   the planes x = j + 1/2, y in [-1, k], z in [1, 1 + h]. Every plane of one layer crosses
//   every stick of the other and no input plane separates the layers, so every BSP whose
//   planes are input planes has Omega(k^2) fragments. Each stick is one rectangle = 2
//   triangles: n = 4k.
#pragma once
#include <cstdint>
#include <string>

#include "mesh/soup.h"

namespace exbsp::bench {

/// splitmix64 stream: portable, unlike std:: distributions.
class split_mix {
public:
  explicit split_mix(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  /// Uniform double in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
  std::uint64_t state_;
};

/// n random triangles at constant density (see the top of this file).
triangle_soup make_random_soup(std::size_t n, std::uint64_t seed);

/// The two-layer grid of k + k sticks (see the top of this file); 4k triangles.
triangle_soup make_sticks(std::size_t k);

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
