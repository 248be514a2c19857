// SPDX-License-Identifier: LGPL-3.0-or-later
// CGAL adapters: any CGAL FaceGraph (Surface_mesh, Polyhedron_3, OpenMesh through CGAL's
// graph traits, ...) to a triangle_soup, and triangles (BSP fragments, a section) back into
// a FaceGraph. Header-only; the consumer brings CGAL (and its flags) for its own mesh.
//
// Notation (docs/contract.md "Input"): the faces are taken in faces(g) order; the face at position
// f (0-based) with corners (v0, ..., v_{k-1}) = vertices_around_face(halfedge(face, g), g)
// becomes the fan (v0, v_i, v_{i+1}), i = 1..k-2, every triangle with face id f (for a
// Surface_mesh without removed faces, f = the face's idx()). No face is dropped: exactly
// degenerate triangles stay (the BSP skips and counts them). Soup vertex i is the vertex whose
// CGAL::get_initialized_vertex_index_map value is i. Coordinates go through CGAL::to_double:
// exact for double-based kernels (Epick, Simple_cartesian<double>) and for Epeck points made
// from doubles; other values are rounded by CGAL.
//
// Back to a FaceGraph: each triangle becomes one face, its face id written to a writable
// property map the caller gives (e.g. a Surface_mesh property map). Corners with bitwise equal
// coordinates share a vertex where CGAL::Euler::can_add_face allows it (a FaceGraph cannot
// hold the non-manifold edges or vertices that fragments of intersecting parts can form);
// elsewhere a triangle gets three vertices of its own (triangle_list.h). So every triangle
// becomes a face, in order.
#pragma once
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/adapters/triangle_list.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/soup.h>

namespace exbsp::cgal {

/// The soup of the FaceGraph `g` (see the notation above); face_count = num_faces(g).
/// `source` names the mesh in messages. Throws input_error (source, line 0) for a non-finite
/// coordinate or a face with fewer than 3 vertices.
template <class FaceGraph>
triangle_soup soup_from_face_graph(const FaceGraph& g,
                                   const std::string& source = "CGAL face graph") {
  triangle_soup soup;
  soup.source = source;
  const auto index = CGAL::get_initialized_vertex_index_map(g);
  const auto points = get(CGAL::vertex_point, g);
  for (const auto v : vertices(g)) {
    const std::size_t i = static_cast<std::size_t>(get(index, v));
    if (i >= soup.vertices.size()) soup.vertices.resize(i + 1, vec3d{0, 0, 0});
    const auto& p = get(points, v);
    soup.vertices[i] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for (double x : soup.vertices[i])
      if (!std::isfinite(x))
        throw input_error(source, 0,
                          "vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  std::uint32_t face = 0;
  std::vector<std::uint32_t> corners;
  for (const auto f : faces(g)) {
    corners.clear();
    for (const auto v : vertices_around_face(halfedge(f, g), g))
      corners.push_back(static_cast<std::uint32_t>(get(index, v)));
    if (corners.size() < 3)
      throw input_error(source, 0, "face " + std::to_string(face) + " has fewer than 3 vertices");
    soup.add_polygon(corners, face++);
  }
  soup.face_count = face;
  return soup;
}

/// Appends `list` to `g` (see the notation above), writing each new face's id to `face_ids`
/// (a writable property map from face_descriptor to an integer type, e.g. a Surface_mesh
/// property map). Corners are shared only with vertices this call made.
template <class FaceGraph, class FaceIdMap>
void append_triangles(FaceGraph& g, const triangle_list& list, FaceIdMap face_ids) {
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  auto points = get(CGAL::vertex_point, g);
  using point = typename boost::property_traits<decltype(points)>::value_type;
  const auto make_vertex = [&](const vec3d& p) {
    const vertex_descriptor v = add_vertex(g);
    put(points, v, point(p[0], p[1], p[2]));
    return v;
  };
  const auto add_face = [&](const std::array<vertex_descriptor, 3>& v, std::uint32_t id) {
    if (!CGAL::Euler::can_add_face(v, g)) return false;
    const auto face = CGAL::Euler::add_face(v, g);
    if (face == boost::graph_traits<FaceGraph>::null_face()) return false;
    put(face_ids, face, id);
    return true;
  };
  add_triangles_sharing_vertices<vertex_descriptor>(list, make_vertex, add_face);
}

/// Appends the fragments (e.g. bsp::fragments_double()) to `g` in the order of `order`
/// (e.g. bsp::order_from_eye; empty: storage order). Throws usage_error for an index out of
/// range.
template <class FaceGraph, class FaceIdMap>
void append_fragments(FaceGraph& g, const std::vector<fragment_d>& fragments, FaceIdMap face_ids,
                      const std::vector<std::uint32_t>& order = {}) {
  append_triangles(g, fragment_triangles(fragments, order), face_ids);
}

/// Appends a section's kept triangles, then its cap (face id section_result::cap_face); for a
/// closed input the result is closed.
template <class FaceGraph, class FaceIdMap>
void append_section(FaceGraph& g, const section_result& r, FaceIdMap face_ids) {
  append_triangles(g, section_triangles(r), face_ids);
}

}  // namespace exbsp::cgal
