// SPDX-License-Identifier: LGPL-3.0-or-later
// The common half of the mesh adapters (openmesh.h, cgal_face_graph.h): triangles with face
// ids taken from BSP fragments or a section, and their insertion into a halfedge mesh with
// vertices shared where the mesh allows it. Header-only.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/clip/section.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/soup.h>

namespace exbsp {

/// Triangles (three corners each) and their face ids, in order.
struct triangle_list {
  std::vector<std::array<vec3d, 3>> corners;
  std::vector<std::uint32_t> faces;
};

/// The fragments (e.g. bsp::fragments_double()) in the order of `order` (fragment indices,
/// e.g. bsp::order_from_eye), or in storage order when `order` is empty. Throws usage_error
/// for an index out of range.
inline triangle_list fragment_triangles(const std::vector<fragment_d>& fragments,
                                        const std::vector<std::uint32_t>& order = {}) {
  triangle_list out;
  const std::size_t n = order.empty() ? fragments.size() : order.size();
  out.corners.reserve(n);
  out.faces.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order.empty() ? k : order[k];
    if (i >= fragments.size()) throw usage_error("fragment_triangles: fragment index out of range");
    out.corners.push_back(fragments[i].v);
    out.faces.push_back(fragments[i].face);
  }
  return out;
}

/// A section's kept triangles, then its cap (face id section_result::cap_face); for a closed
/// input, kept and cap together are closed (clip/section.h).
inline triangle_list section_triangles(const section_result& r) {
  triangle_list out;
  for (const auto* list : {&r.kept, &r.cap})
    for (const section_triangle& t : *list) {
      out.corners.push_back({r.points.at(t.p[0]).v, r.points.at(t.p[1]).v, r.points.at(t.p[2]).v});
      out.faces.push_back(t.face);
    }
  return out;
}

/// Adds every triangle of `list` to a halfedge mesh through two callbacks:
/// make_vertex(vec3d) -> Vertex makes a vertex; add_face(std::array<Vertex, 3>, face id) -> bool
/// adds a face unless the mesh cannot hold it there (then returns false and changes nothing).
/// Corners with bitwise equal coordinates share one vertex made by this call; a triangle the
/// mesh refuses with shared vertices, or whose corners coincide, gets three vertices of its
/// own (add_face must accept those). So every triangle becomes a face, in order.
template <class Vertex, class MakeVertex, class AddFace>
void add_triangles_sharing_vertices(const triangle_list& list, MakeVertex&& make_vertex,
                                    AddFace&& add_face) {
  if (list.faces.size() != list.corners.size())
    throw usage_error("add_triangles_sharing_vertices: one face id per triangle expected");
  std::map<vec3d, Vertex> shared;
  const auto vertex_at = [&](const vec3d& p) {
    auto it = shared.find(p);
    if (it == shared.end()) it = shared.emplace(p, make_vertex(p)).first;
    return it->second;
  };
  for (std::size_t i = 0; i < list.corners.size(); ++i) {
    const auto& t = list.corners[i];
    const bool distinct = t[0] != t[1] && t[1] != t[2] && t[2] != t[0];
    if (distinct &&
        add_face(std::array<Vertex, 3>{vertex_at(t[0]), vertex_at(t[1]), vertex_at(t[2])},
                 list.faces[i]))
      continue;
    if (!add_face(std::array<Vertex, 3>{make_vertex(t[0]), make_vertex(t[1]), make_vertex(t[2])},
                  list.faces[i]))
      throw usage_error("add_triangles_sharing_vertices: the mesh refused an isolated triangle");
  }
}

}  // namespace exbsp
