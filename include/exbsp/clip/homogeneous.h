// SPDX-License-Identifier: LGPL-3.0-or-later
// Homogeneous (4D) clipping in OpenGL clip space, before the perspective divide.
//
// Notation: a clip-space point is (x, y, z, w); the view volume is -w <= x, y, z <= w, i.e.
// the six closed half-spaces, in this order and with these outcode bits:
//   w + x >= 0 (bit 1), w - x >= 0 (bit 2), w + y >= 0 (bit 4), w - y >= 0 (bit 8),
//   w + z >= 0 (bit 16, near), w - z >= 0 (bit 32, far).
// Together they imply w >= |x|, |y|, |z| >= 0: points with w < 0 (behind the eye) are
// outside, so a clipped polygon never wraps around through infinity after the divide; w = 0
// survives only at the 4D origin. Each vertex carries `attribute_count` doubles (colour,
// depth, texture coordinates, ...) that are interpolated linearly in clip space, like the
// position (perspective-correct, as OpenGL does before the divide).
//
// Floating point: an edge crossing a plane is always interpolated from its lexicographically
// smaller endpoint (comparing x, y, z, w), so two triangles sharing an edge get bit-identical
// vertices on it whatever their winding. The crossing point is then put exactly on its
// plane (x = -w for w + x = 0, and so on), and every interpolated value stays within the
// range of the edge's two endpoints.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include <exbsp/clip/clip_types.h>
#include <exbsp/core/export.h>

namespace exbsp::clip {

/// A convex polygon in clip space with per-vertex attributes stored vertex-major:
/// attributes[i * attribute_count + j] is attribute j of vertex i.
struct homogeneous_polygon {
  std::size_t attribute_count = 0;
  std::vector<vec4d> positions;
  std::vector<double> attributes;

  std::size_t size() const { return positions.size(); }
  bool empty() const { return positions.empty(); }
  /// Pointer to the attribute_count attributes of vertex i (i < size()).
  const double* attributes_of(std::size_t i) const {
    return attributes.data() + i * attribute_count;
  }
};

/// 6-bit outcode of p against the six clip planes (bits as in the notation above).
/// A point with w < 0 always has at least one bit set. No checks.
EXBSP_EXPORT unsigned homogeneous_outcode(const vec4d& p);

/// True when every point is inside the view volume (all outcodes 0); false for no points.
EXBSP_EXPORT bool homogeneous_trivially_accepted(const std::vector<vec4d>& points);
/// True when all points are outside one common clip plane (the AND of their outcodes is not
/// 0): nothing of their convex hull is visible. Use it on the eight clip-space corners of
/// an object's bounding box to reject the object before any per-triangle work.
/// False for no points.
EXBSP_EXPORT bool homogeneous_trivially_rejected(const std::vector<vec4d>& points);
/// Triangle versions of the two tests above.
EXBSP_EXPORT bool homogeneous_trivially_accepted(const std::array<vec4d, 3>& triangle);
EXBSP_EXPORT bool homogeneous_trivially_rejected(const std::array<vec4d, 3>& triangle);

/// Clips a convex polygon against the view volume. Trivially accepted input is returned
/// unchanged (bit-for-bit); trivially rejected input, input with fewer than 3 vertices and
/// results with fewer than 3 vertices are returned empty (attribute_count kept). Throws usage_error
/// when attributes.size() != positions.size() * attribute_count or a coordinate/attribute is NaN or
/// infinite.
EXBSP_EXPORT homogeneous_polygon homogeneous_clip(const homogeneous_polygon& polygon);

/// Clips triangle (p[0], p[1], p[2]) with attributes.size() / 3 attributes per vertex
/// (vertex-major, may be empty) and returns the visible convex polygon, in the triangle's
/// order. Throws usage_error when attributes.size() is not a multiple of 3 or a value is
/// NaN or infinite.
homogeneous_polygon homogeneous_clip_triangle(const std::array<vec4d, 3>& p,
                                              const std::vector<double>& attributes = {});

/// Fan triangulation (v0, v[i], v[i+1]) of a clipped polygon, each triangle a 3-vertex
/// homogeneous_polygon with the same attribute_count. Nothing for fewer than 3 vertices.
/// Throws usage_error when attributes.size() != positions.size() * attribute_count.
EXBSP_EXPORT std::vector<homogeneous_polygon> fan_triangulate(const homogeneous_polygon& polygon);

/// Perspective divide (x/w, y/w, z/w) to normalised device coordinates.
/// Throws usage_error unless w > 0 (clipped output has w >= 0; w == 0 only at the origin).
EXBSP_EXPORT vec3d perspective_divide(const vec4d& p);

}  // namespace exbsp::clip
