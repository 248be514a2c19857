// SPDX-License-Identifier: LGPL-3.0-or-later
// Small value types shared by the floating-point clippers of src/clip/.
//
// Notation: points are std::array<double, N> (vec2d, vec3d, vec4d = homogeneous x, y, z, w);
// an axis-aligned box (a 2D window or a 3D box) is the closed set min <= p <= max,
// component-wise. A polygon is a vector of its vertices in order (closed implicitly:
// the last vertex connects to the first). A fan triangulation of a polygon v0..v(k-1)
// is (v0, v[i], v[i+1]) for i = 1..k-2, as in docs/contract.md "Input".
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include <exbsp/core/vec.h>

namespace exbsp::clip {

// The one vocabulary (<exbsp/core/vec.h>); vec4d is a homogeneous clip-space point (x, y, z, w).
using exbsp::vec2d;
using exbsp::vec3d;
using exbsp::vec4d;

// box and segment below are two templates of the same form (two arrays, aliases for 2 and 3
// dimensions): plain aggregates users build with braces.
/// Closed axis-aligned box in N dimensions: min[k] <= p[k] <= max[k] for every axis k.
template <std::size_t N>
struct box {
  std::array<double, N> min;
  std::array<double, N> max;
};
using box2 = box<2>;
using box3 = box<3>;
/// A 2D clip window [xmin, xmax] x [ymin, ymax].
using window2 = box2;

/// Builds the window [xmin, xmax] x [ymin, ymax]. No checks (the clippers check).
inline window2 make_window(double xmin, double xmax, double ymin, double ymax) {
  return window2{{xmin, ymin}, {xmax, ymax}};
}

/// Directed segment from p0 to p1 in N dimensions.
template <std::size_t N>
struct segment {
  std::array<double, N> p0;
  std::array<double, N> p1;
};
using segment2 = segment<2>;
using segment3 = segment<3>;

/// Index triples (0, i, i+1), i = 1..k-2, of the fan triangulation of a k-gon.
/// Returns nothing for k < 3.
inline std::vector<std::array<std::size_t, 3>> fan_triangle_indices(std::size_t vertex_count) {
  std::vector<std::array<std::size_t, 3>> out;
  if (vertex_count < 3) return out;
  out.reserve(vertex_count - 2);
  for (std::size_t i = 1; i + 1 < vertex_count; ++i) out.push_back({0, i, i + 1});
  return out;
}

/// Fan triangulation (v0, v[i], v[i+1]) of a polygon; the triangles keep the polygon's
/// orientation. Returns nothing for fewer than 3 vertices. Never throws (except bad_alloc).
template <class Point>
std::vector<std::array<Point, 3>> fan_triangulate(const std::vector<Point>& polygon) {
  std::vector<std::array<Point, 3>> out;
  for (const auto& t : fan_triangle_indices(polygon.size()))
    out.push_back({polygon[t[0]], polygon[t[1]], polygon[t[2]]});
  return out;
}

}  // namespace exbsp::clip
