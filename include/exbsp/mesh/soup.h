// SPDX-License-Identifier: LGPL-3.0-or-later
// Triangle soup: the exact input of every exbsp computation (docs/contract.md "Input").
// Vertices are the IEEE doubles read from the file; polygons are fan-triangulated from
// their first vertex and every triangle keeps the 0-based index of its source face.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
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
  /// Texture coordinates (u, v) at the three corners of each triangle (OBJ vt, PLY s/t or u/v;
  /// docs/contract.md "Input"): empty when the source has none, else one entry per triangle,
  /// in the order of `triangles`. Fans copy their polygon's corner UVs; a file that gives UVs
  /// to some faces only has (0, 0) at the others' corners.
  std::vector<std::array<vec2d, 3>> triangle_uvs;

  /// True when the soup carries texture coordinates (triangle_uvs has one entry per triangle).
  bool has_uvs() const { return !triangle_uvs.empty() && triangle_uvs.size() == triangles.size(); }

  /// Append polygon `indices` (k >= 3) as a fan (v0, v[i], v[i+1]) with the given face id.
  /// Precondition: indices are valid (< vertices.size()); throws usage_error otherwise.
  void add_polygon(const std::vector<std::uint32_t>& indices, std::uint32_t face);

  /// add_polygon with the texture coordinates of its corners (uvs.size() == indices.size()):
  /// the fan's triangles get the UVs of their corners; earlier triangles without UVs get
  /// (0, 0). Throws usage_error on a size mismatch (and as add_polygon).
  void add_polygon(const std::vector<std::uint32_t>& indices, const std::vector<vec2d>& uvs,
                   std::uint32_t face);

  /// Append a triangle given by its corner coordinates as a new face (convenience for tests).
  std::uint32_t add_triangle(const vec3d& a, const vec3d& b, const vec3d& c);

  /// Append all of `other`, shifting its face ids by face_count. UVs: when either soup has
  /// them, the result has them ((0, 0) at the corners of the side that has none).
  void append(const triangle_soup& other);
};

/// Meshes appended into one soup (triangle_soup::append), mesh k's face ids starting at
/// first_face[k] (view::frame::mesh_face_offsets): the mesh of face id `face`. Mesh 0 when
/// first_face is empty; a face before first_face[0] is in mesh 0, one past the last entry
/// gets first_face.size() - 1, which is no mesh of mesh_count's.
inline std::uint32_t mesh_of_face(const std::vector<std::uint32_t>& first_face,
                                  std::uint32_t face) {
  if (first_face.empty()) return 0;
  const auto it = std::upper_bound(first_face.begin(), first_face.end(), face);
  return static_cast<std::uint32_t>(std::max<std::ptrdiff_t>(0, it - first_face.begin() - 1));
}

/// The number of meshes `first_face` describes (mesh_of_face): one when it has fewer than two
/// entries.
inline std::size_t mesh_count(const std::vector<std::uint32_t>& first_face) {
  return first_face.size() < 2 ? 1 : first_face.size() - 1;
}

}  // namespace exbsp
