// SPDX-License-Identifier: LGPL-3.0-or-later
// A viewer-style consumer of the installed exbsp package: reads a mesh with OpenMesh (as a CAD
// viewer already holds it), converts it with the OpenMesh adapter, builds the exact BSP, renders
// a PNG from a view fitted to the mesh with exbsp's viewing pipeline, and writes the fragments
// in back-to-front order back to an OpenMesh mesh (face ids in a face property).
//
//   exbsp_viewer MESH OUT.png [FRAGMENTS.off]
// Exit status: 0 on success, 2 for bad input or output (message on stderr).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <exbsp/adapters/openmesh.h>
#include <exbsp/exbsp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

struct double_traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<double_traits>;
using tri_mesh = OpenMesh::TriMesh_ArrayKernelT<double_traits>;

// A perspective view of the soup's bounding box from the (+x, -y, +z) octant.
exbsp::view::view_setup fitted_view(const exbsp::triangle_soup& soup, int width, int height) {
  exbsp::vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& v : soup.vertices)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], v[a]);
      hi[a] = std::max(hi[a], v[a]);
    }
  const exbsp::view::point3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const double radius = std::max(1e-9, std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2);
  const double distance = radius / std::sin(std::acos(-1.0) / 9) * 1.05;  // fits a 40 degree fovy
  const exbsp::view::vector3 towards_eye = exbsp::view::normalized({0.6, -0.8, 0.5});
  exbsp::view::view_setup view;
  view.cam = {centre + distance * towards_eye, centre, {0, 0, 1}};
  view.model_view = exbsp::view::look_at(view.cam);
  view.projection =
      exbsp::view::perspective(40, double(width) / height, distance - radius, distance + radius);
  view.vp = {0, 0, width, height};
  return view;
}

// A colour per face: light blue, shaded by the angle between the face's normal (its first
// triangle's) and the direction to the eye (a headlight), both sides lit alike.
std::vector<exbsp::view::rgb8> headlight_colors(const exbsp::triangle_soup& soup,
                                                const exbsp::view::camera& cam) {
  const exbsp::view::vector3 light = exbsp::view::normalized(cam.eye - cam.look_at);
  std::vector<exbsp::view::rgb8> colors(soup.face_count, {200, 200, 200});
  std::vector<bool> done(soup.face_count, false);
  for (const exbsp::soup_triangle& t : soup.triangles) {
    if (done[t.face]) continue;
    const auto a = exbsp::view::to_point(soup.vertices[t.v[0]]);
    const auto n = exbsp::view::cross(exbsp::view::to_point(soup.vertices[t.v[1]]) - a,
                                      exbsp::view::to_point(soup.vertices[t.v[2]]) - a);
    const double len = exbsp::view::length(n);
    if (!(len > 0)) continue;  // degenerate: try the face's next triangle
    const double shade = 0.25 + 0.75 * std::abs(exbsp::view::dot(n, light)) / len;
    colors[t.face] = {static_cast<std::uint8_t>(120 * shade),
                      static_cast<std::uint8_t>(170 * shade),
                      static_cast<std::uint8_t>(250 * shade)};
    done[t.face] = true;
  }
  return colors;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: exbsp_viewer MESH OUT.png [FRAGMENTS.off]\n");
    return 2;
  }
  exbsp::install_gmp_memory_functions();
  try {
    poly_mesh mesh;
    if (!OpenMesh::IO::read_mesh(mesh, argv[1]))
      throw exbsp::input_error(argv[1], 0, "OpenMesh cannot read it");
    exbsp::view::frame f;
    f.soup = exbsp::openmesh::soup_from_mesh(mesh, argv[1]);
    f.view = fitted_view(f.soup, 320, 240);
    f.face_colors = headlight_colors(f.soup, f.view.cam);
    const auto stages = exbsp::view::standard_pipeline({}, exbsp::view::output_kind::png);
    stages.run(f, nullptr);
    exbsp::view::write_png(f.picture, argv[2]);

    const exbsp::build_stats& s = f.tree->stats();
    std::printf(
        "exbsp %s: %s: %zu faces, %zu triangles (%zu degenerate), %zu fragments, %zu splits, "
        "%zu nodes, depth %zu, kernel %s\n",
        exbsp::version_string, argv[1], std::size_t(mesh.n_faces()), s.input_triangles,
        s.degenerate_input, s.fragments, s.splits, s.nodes, s.depth, s.kernel.c_str());
    std::size_t painted = 0;
    for (int j = 0; j < f.picture.height(); ++j)
      for (int i = 0; i < f.picture.width(); ++i) painted += f.picture.pixel(i, j) != f.background;
    std::printf("%s: %dx%d, %zu pixels painted\n", argv[2], f.picture.width(), f.picture.height(),
                painted);

    if (argc > 3) {  // the back-to-front fragments as an OpenMesh mesh
      tri_mesh out;
      exbsp::openmesh::append_fragments(out, f.fragments, f.order);
      if (!OpenMesh::IO::write_mesh(out, argv[3]))
        throw exbsp::output_error(argv[3], "OpenMesh cannot write it");
      std::printf("%s: %zu faces, %zu vertices\n", argv[3], std::size_t(out.n_faces()),
                  std::size_t(out.n_vertices()));
    }
    return painted > 0 && s.fragments > 0 ? 0 : 1;
  } catch (const exbsp::error& e) {
    std::fprintf(stderr, "exbsp_viewer: error: %s\n", e.what());
    return 2;
  }
}
