// SPDX-License-Identifier: LGPL-3.0-or-later
// Deterministic generated inputs shared by the tests and the benchmarks: the same soup on
// every machine for a given size and seed (splitmix64, not std:: distributions), and the one
// OFF writer of the tests (coordinates with 17 significant digits: reading the file back
// gives the same doubles).
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
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include <exbsp/mesh/soup.h>

namespace exbsp_test {

/// splitmix64 stream: portable, unlike std:: distributions.
class split_mix {
 public:
  explicit split_mix(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  /// Uniform double in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform double in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// An integer in [0, n) (0 when n is 0); modulo bias is irrelevant here.
  std::size_t below(std::size_t n) { return n ? static_cast<std::size_t>(next() % n) : 0; }

 private:
  std::uint64_t state_;
};

/// n random triangles at constant density (see the top of this file).
exbsp::triangle_soup make_random_soup(std::size_t n, std::uint64_t seed);

/// The two-layer grid of k + k sticks (see the top of this file); 4k triangles.
exbsp::triangle_soup make_sticks(std::size_t k);

/// The soup as an OFF file: its vertices with %.17g and one face per triangle.
std::string off_text(const exbsp::triangle_soup& soup);

}  // namespace exbsp_test
