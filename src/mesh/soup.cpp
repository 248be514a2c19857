// SPDX-License-Identifier: LGPL-3.0-or-later
#include <exbsp/mesh/soup.h>

#include <exbsp/core/errors.h>

namespace exbsp {

void triangle_soup::add_polygon(const std::vector<std::uint32_t>& indices, std::uint32_t face) {
  if (indices.size() < 3) throw usage_error("add_polygon: a face needs at least 3 vertices");
  for (std::uint32_t i : indices)
    if (i >= vertices.size()) throw usage_error("add_polygon: vertex index out of range");
  for (std::size_t i = 1; i + 1 < indices.size(); ++i)
    triangles.push_back({{indices[0], indices[i], indices[i + 1]}, face});
  if (face + 1 > face_count) face_count = face + 1;
  if (!triangle_uvs.empty()) triangle_uvs.resize(triangles.size(), {});
}

void triangle_soup::add_polygon(const std::vector<std::uint32_t>& indices,
                                const std::vector<vec2d>& uvs, std::uint32_t face) {
  if (uvs.size() != indices.size())
    throw usage_error("add_polygon: one texture coordinate per vertex is needed");
  const std::size_t first = triangles.size();
  add_polygon(indices, face);
  triangle_uvs.resize(first, {});
  for (std::size_t i = 1; i + 1 < indices.size(); ++i)
    triangle_uvs.push_back({uvs[0], uvs[i], uvs[i + 1]});
}

std::uint32_t triangle_soup::add_triangle(const vec3d& a, const vec3d& b, const vec3d& c) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.push_back(a);
  vertices.push_back(b);
  vertices.push_back(c);
  const std::uint32_t face = face_count;
  add_polygon({base, base + 1, base + 2}, face);
  return face;
}

void triangle_soup::append(const triangle_soup& other) {
  const auto vbase = static_cast<std::uint32_t>(vertices.size());
  const std::uint32_t fbase = face_count;
  const std::size_t tbase = triangles.size();
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const soup_triangle& t : other.triangles)
    triangles.push_back({{t.v[0] + vbase, t.v[1] + vbase, t.v[2] + vbase}, t.face + fbase});
  face_count = fbase + other.face_count;
  if (!triangle_uvs.empty() || other.has_uvs()) {
    triangle_uvs.resize(tbase, {});
    if (other.has_uvs())
      triangle_uvs.insert(triangle_uvs.end(), other.triangle_uvs.begin(), other.triangle_uvs.end());
    triangle_uvs.resize(triangles.size(), {});
  }
}

}  // namespace exbsp
