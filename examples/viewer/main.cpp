// SPDX-License-Identifier: LGPL-3.0-or-later
// A viewer-style consumer of the installed exbsp package: reads a mesh with OpenMesh (as a CAD
// viewer already holds it), converts it with the OpenMesh adapter, builds the exact BSP and
// renders a PNG from the view fitted to the mesh (exbsp::view::render_soup,
// <exbsp/view/render.h>), and writes the fragments in back-to-front order back to an OpenMesh mesh
// (face ids in a face property).
//
//   exbsp_viewer MESH OUT.png [FRAGMENTS.off]
// Exit status: 0 on success, 2 for bad input or output (message on stderr).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <exbsp/adapters/openmesh.h>
#include <exbsp/exbsp.h>

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
    const exbsp::triangle_soup soup = exbsp::openmesh::soup_from_mesh(mesh, argv[1]);
    // The view `exbsp render MESH` fits to the mesh, lit from over the viewer's shoulder.
    exbsp::view::render_options options;
    options.width = 320;
    options.height = 240;
    const exbsp::view::render_result r = exbsp::view::render_soup(soup, options);
    exbsp::view::write_png(r.picture, argv[2]);

    const exbsp::build_stats& s = r.tree.stats();
    std::printf(
        "exbsp %s: %s: %zu faces, %zu triangles (%zu degenerate), %zu fragments, %zu splits, "
        "%zu nodes, depth %zu, kernel %s\n",
        exbsp::version_string, argv[1], std::size_t(mesh.n_faces()), s.input_triangles,
        s.degenerate_input, s.fragments, s.splits, s.nodes, s.depth, s.kernel.c_str());
    std::size_t painted = 0;
    for (int j = 0; j < r.picture.height(); ++j)
      for (int i = 0; i < r.picture.width(); ++i)
        painted += r.picture.pixel(i, j) != options.background;
    std::printf("%s: %dx%d, %zu pixels painted\n", argv[2], r.picture.width(), r.picture.height(),
                painted);

    if (argc > 3) {  // the back-to-front fragments as an OpenMesh mesh
      tri_mesh out;
      exbsp::openmesh::append_fragments(out, r.tree.fragments_double(), r.order);
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
