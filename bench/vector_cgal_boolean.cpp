// SPDX-License-Identifier: GPL-3.0-or-later
// vector_cgal_boolean: the visible-region loop of src/view/vector_drawing.cpp with CGAL's
// Boolean_set_operations_2 (Polygon_set_2 on Epeck, exact) instead of Clipper, on the first N
// front-to-back polygons of a mesh at 800x600 (the camera of bench_vector), to compare the two
// candidates (bench/vector_output.md). Per polygon P: visible = P \ covered; covered |= P.
//   vector_cgal_boolean MESH N          (built with -DEXBSP_BENCH_CGAL_BOOLEAN=ON)
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include "bench_view.h"
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/camera.h>
#include "view/effects.h"
#include <exbsp/view/pipeline.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
using K = CGAL::Epeck;
using Pgn = CGAL::Polygon_2<K>;
using PS = CGAL::Polygon_set_2<K>;
using namespace exbsp;
int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: vector_cgal_boolean MESH N\n");
    return 2;
  }
  const std::size_t limit = static_cast<std::size_t>(std::atol(argv[2]));
  view::frame f;
  f.soup = read_mesh(argv[1]);
  f.face_colors.assign(f.soup.face_count, {200, 200, 210});
  bench::set_bench_view(f, 800, 600);
  view::build_stage(f);
  view::order_stage(f);
  view::transform_clip_stage(f);
  PS covered;
  std::size_t done = 0, visible = 0;
  auto t0 = std::chrono::steady_clock::now();
  std::clock_t c0 = std::clock();
  for (std::size_t k = f.polygons.size(); k-- > 0 && done < limit; ++done) {
    Pgn p;
    for (auto& w : f.polygons[k].v) p.push_back(K::Point_2(w.x, w.y));
    if (!p.is_simple() || p.area() == 0) continue;
    if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
    PS vis(p);
    vis.difference(covered);
    if (!vis.is_empty()) ++visible;
    covered.join(p);
  }
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  printf(
      "CGAL Polygon_set_2<Epeck>: %zu of %zu polygons, %zu visible, wall %.2f s, cpu %.2f s, %.2f "
      "ms/polygon\n",
      done, f.polygons.size(), visible, wall, cpu, 1000 * cpu / done);
}
