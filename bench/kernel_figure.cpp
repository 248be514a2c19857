// SPDX-License-Identifier: LGPL-3.0-or-later
// What rounding does to a BSP order, as a picture: a mesh rendered (scene::mesh_scene's fitted,
// lit view) from the exact kernel's tree and from an inexact kernel's tree, side by side, and a
// third panel with every pixel where they differ in magenta over the dimmed exact picture.
//
// The inexact kernels round their split points; some come out non-finite (NaN or infinite,
// when a rounded orientation is 0 on both ends of an edge that the exact predicate says is
// cut), which the view pipeline refuses. Those fragments are left out of the inexact picture
// and counted: a viewer on that kernel would have to drop them too.
//
//   kernel_figure MESH OUT.png [--kernel double|epick] [--view iso|front|...] [--size WxH]
// prints one JSON line: mesh, kernel, fragments, non_finite_fragments, differing_pixels,
// covered_pixels.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/png_io.h>
#include "scene/mesh_scene.h"
#include "view/effects.h"

using namespace exbsp;

namespace {

struct rendered {
  view::image picture;
  std::size_t fragments = 0, non_finite = 0;
};

rendered render(const scene::scene& s, kernel_id kernel) {
  view::frame f = scene::make_frame(s);
  f.build.kernel = kernel;
  rendered r;
  view::pipeline p = view::standard_pipeline(s.effects, view::output_kind::png);
  p.insert_after("order", "drop non-finite", [&r](view::frame& fr) {
    std::vector<std::uint32_t> kept;
    for (std::uint32_t i : fr.order) {
      bool finite = true;
      for (const vec3d& v : fr.fragments[i].v)
        for (double x : v) finite = finite && std::isfinite(x);
      if (finite)
        kept.push_back(i);
      else
        ++r.non_finite;
    }
    fr.order = std::move(kept);
    return std::to_string(r.non_finite) + " non-finite fragments left out";
  });
  p.run(f, nullptr);
  r.fragments = f.fragments.size();
  r.picture = std::move(f.picture);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr
        << "usage: kernel_figure MESH OUT.png [--kernel double|epick] [--view V] [--size WxH]\n";
    return 2;
  }
  try {
    const std::string mesh = argv[1], out = argv[2];
    std::string kernel = "double";
    scene::mesh_view_options options;
    options.width = 480;
    options.height = 360;
    for (int k = 3; k + 1 < argc; k += 2) {
      const std::string key = argv[k], value = argv[k + 1];
      if (key == "--kernel")
        kernel = value;
      else if (key == "--view")
        options.view = value;
      else if (key == "--size" &&
               std::sscanf(value.c_str(), "%dx%d", &options.width, &options.height) == 2) {
      } else
        throw usage_error("unknown option " + key + " " + value);
    }
    auto soup = std::make_shared<const triangle_soup>(read_mesh(mesh));
    const scene::scene s = scene::mesh_scene(soup, mesh, options);
    const rendered exact = render(s, kernel_id::exact);
    const rendered rounded = render(s, parse_kernel(kernel));
    const int w = options.width, h = options.height;
    view::image panel(3 * w, h, s.background);
    std::size_t differing = 0, covered = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const view::rgb8 a = exact.picture.pixel(i, j), b = rounded.picture.pixel(i, j);
        const bool differ = a.r != b.r || a.g != b.g || a.b != b.b;
        const bool background =
            a.r == s.background.r && a.g == s.background.g && a.b == s.background.b;
        covered += !background;
        differing += differ;
        panel.set_pixel(i, j, a);
        panel.set_pixel(w + i, j, b);
        const auto dim = [](std::uint8_t c) {
          return static_cast<std::uint8_t>(160 + c * 95 / 255);
        };
        panel.set_pixel(
            2 * w + i, j,
            differ ? view::rgb8{230, 0, 200} : view::rgb8{dim(a.r), dim(a.g), dim(a.b)});
      }
    view::write_png(panel, out);
    std::printf(
        "{\"mesh\": \"%s\", \"kernel\": \"%s\", \"fragments\": %zu, \"non_finite_fragments\": %zu, "
        "\"differing_pixels\": %zu, \"covered_pixels\": %zu}\n",
        mesh.c_str(), kernel.c_str(), rounded.fragments, rounded.non_finite, differing, covered);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "kernel_figure: error: " << e.what() << "\n";
    return 2;
  }
}
