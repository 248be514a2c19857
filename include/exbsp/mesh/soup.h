// SPDX-License-Identifier: LGPL-3.0-or-later
// Triangle soup: the exact input of every exbsp computation (docs/contract.md "Input").
// Vertices are the IEEE doubles read from the file; polygons are fan-triangulated from
// their first vertex and every triangle keeps the 0-based index of its source face.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include <exbsp/core/export.h>
#include <exbsp/core/vec.h>

namespace exbsp {

/// One input triangle: three vertex indices into triangle_soup::vertices and its face id.
struct soup_triangle {
  std::array<std::uint32_t, 3> v;
  std::uint32_t face;
};

/// A triangle soup as loaded: no face dropped, degenerate triangles still present
/// (the BSP build skips and counts them).
struct EXBSP_EXPORT triangle_soup {
  std::vector<vec3d> vertices;
  std::vector<soup_triangle> triangles;  ///< file order, fans in order
  std::uint32_t face_count = 0;          ///< number of faces in the source (polygons)
  std::string source;                    ///< file name, for messages

  /// Append polygon `indices` (k >= 3) as a fan (v0, v[i], v[i+1]) with the given face id.
  /// Precondition: indices are valid (< vertices.size()); throws usage_error otherwise.
  void add_polygon(const std::vector<std::uint32_t>& indices, std::uint32_t face);

  /// Append a triangle given by its corner coordinates as a new face (convenience for tests).
  std::uint32_t add_triangle(const vec3d& a, const vec3d& b, const vec3d& c);

  /// Append all of `other`, shifting its face ids by face_count.
  void append(const triangle_soup& other);
};

}  // namespace exbsp
