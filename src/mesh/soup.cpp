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
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const soup_triangle& t : other.triangles)
    triangles.push_back({{t.v[0] + vbase, t.v[1] + vbase, t.v[2] + vbase}, t.face + fbase});
  face_count = fbase + other.face_count;
}

}  // namespace exbsp
