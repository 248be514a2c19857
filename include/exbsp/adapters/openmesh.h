// SPDX-License-Identifier: LGPL-3.0-or-later
// OpenMesh adapters (component exbsp::openmesh): an OpenMesh TriMesh or PolyMesh (any traits)
// to a triangle_soup, and the BSP's fragments or a section back to an OpenMesh mesh.
//
// Notation (docs/contract.md "Input"): a face f with corners (v0, ..., v_{k-1}) = mesh.fv_range(f),
// k >= 3, becomes the fan (v0, v_i, v_{i+1}), i = 1..k-2, every triangle with face id
// f.idx(), so fragments and section triangles map straight back to the mesh's faces. No face
// is dropped: exactly degenerate triangles stay in the soup (the BSP skips and counts them in
// build_stats::degenerate_input). Coordinates are converted to double exactly (float points
// widen exactly); the doubles are the exact input.
//
// Back to OpenMesh: each triangle becomes one face carrying its face id in the face property
// named face_id_property (std::uint32_t). Corners with bitwise equal coordinates share one
// vertex where OpenMesh's halfedge structure allows it (it cannot hold the non-manifold edges
// or vertices that BSP fragments of intersecting parts can form); elsewhere a triangle gets
// three vertices of its own (triangle_list.h). So every triangle becomes a face, in order.
//
// Header-only: OpenMesh meshes are templates on their traits.
#pragma once
#include <OpenMesh/Core/Utils/Property.hh>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/adapters/triangle_list.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/soup.h>

namespace exbsp::openmesh {

/// Name of the face property holding exbsp face ids in meshes these adapters fill.
inline constexpr const char* face_id_property = "exbsp:face_id";

/// The soup of `mesh` (see the notation above): vertices by index (vertex i of the soup is
/// mesh vertex i, deleted ones included until garbage collection), faces in mesh.faces()
/// order (deleted faces skipped) with face id = face index, face_count = mesh.n_faces().
/// `source` names the mesh in messages. Throws input_error (source, line 0) for a non-finite
/// coordinate or a face with fewer than 3 vertices.
template <class Mesh>
triangle_soup soup_from_mesh(const Mesh& mesh, const std::string& source = "OpenMesh mesh") {
  triangle_soup soup;
  soup.source = source;
  soup.vertices.reserve(mesh.n_vertices());
  for (std::size_t i = 0; i < mesh.n_vertices(); ++i) {
    const auto& p = mesh.point(typename Mesh::VertexHandle(static_cast<int>(i)));
    const vec3d v{static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])};
    for (double x : v)
      if (!std::isfinite(x))
        throw input_error(source, 0,
                          "vertex " + std::to_string(i) + " has a non-finite coordinate");
    soup.vertices.push_back(v);
  }
  soup.face_count = static_cast<std::uint32_t>(mesh.n_faces());
  std::vector<std::uint32_t> corners;
  for (const auto f : mesh.faces()) {
    corners.clear();
    for (const auto v : mesh.fv_range(f)) corners.push_back(static_cast<std::uint32_t>(v.idx()));
    if (corners.size() < 3)
      throw input_error(source, 0,
                        "face " + std::to_string(f.idx()) + " has fewer than 3 vertices");
    soup.add_polygon(corners, static_cast<std::uint32_t>(f.idx()));
  }
  return soup;
}

/// The face property face_id_property of `mesh`, added when it does not exist yet.
template <class Mesh>
OpenMesh::FPropHandleT<std::uint32_t> face_id_handle(Mesh& mesh) {
  OpenMesh::FPropHandleT<std::uint32_t> h;
  if (!mesh.get_property_handle(h, face_id_property)) mesh.add_property(h, face_id_property);
  return h;
}

/// Appends `list` to `mesh` (see the notation above), each face with its face id in the
/// property face_id_property; corners are shared only with vertices this call made. Returns
/// the property.
template <class Mesh>
OpenMesh::FPropHandleT<std::uint32_t> append_triangles(Mesh& mesh, const triangle_list& list) {
  using vertex_handle = typename Mesh::VertexHandle;
  using scalar = typename Mesh::Point::value_type;
  const auto ids = face_id_handle(mesh);
  const auto make_vertex = [&](const vec3d& p) {
    return mesh.add_vertex(typename Mesh::Point(
        static_cast<scalar>(p[0]), static_cast<scalar>(p[1]), static_cast<scalar>(p[2])));
  };
  // OpenMesh's add_face refuses (with a message on omerr) a face at a vertex that is not on
  // the boundary or along a halfedge that already has a face: both are tested first.
  const auto add_face = [&](const std::array<vertex_handle, 3>& v, std::uint32_t id) {
    for (int k = 0; k < 3; ++k) {
      if (!mesh.is_boundary(v[k])) return false;
      const auto h = mesh.find_halfedge(v[k], v[(k + 1) % 3]);
      if (h.is_valid() && !mesh.is_boundary(h)) return false;
    }
    const auto face = mesh.add_face(v[0], v[1], v[2]);
    if (!face.is_valid()) return false;
    mesh.property(ids, face) = id;
    return true;
  };
  add_triangles_sharing_vertices<vertex_handle>(list, make_vertex, add_face);
  return ids;
}

/// Appends the fragments (e.g. bsp::fragments_double()) to `mesh` in the order of `order`
/// (e.g. bsp::order_from_eye; empty: storage order). Throws usage_error for an index out of
/// range.
template <class Mesh>
OpenMesh::FPropHandleT<std::uint32_t> append_fragments(
    Mesh& mesh, const std::vector<fragment_d>& fragments,
    const std::vector<std::uint32_t>& order = {}) {
  return append_triangles(mesh, fragment_triangles(fragments, order));
}

/// Appends a section's kept triangles, then its cap (face id section_result::cap_face); for a
/// closed input the result is a closed mesh.
template <class Mesh>
OpenMesh::FPropHandleT<std::uint32_t> append_section(Mesh& mesh, const section_result& r) {
  return append_triangles(mesh, section_triangles(r));
}

}  // namespace exbsp::openmesh
