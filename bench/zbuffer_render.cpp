// SPDX-License-Identifier: LGPL-3.0-or-later
// zbuffer_render: Mesa's off-screen z-buffer (OSMesa, tests/support/osmesa_zbuffer.h) image of
// flat-coloured triangles under a given 4x4 matrix: the reference images of bench/vector_peers.py,
// which compares exbsp's, matplotlib's and three.js's vector drawings with them.
//
//   zbuffer_render JOBS.json
// JOBS.json: {"jobs": [{"out": "PATH.png", "width": W, "height": H, "background": [r, g, b],
//   "clip_from_world": [16 numbers, row-major: world -> clip coordinates],
//   "nearer": "smaller" | "greater" (window depth of nearer points; default "smaller", OpenGL),
//   "triangles": [[x0, y0, z0, x1, y1, z1, x2, y2, z2], ...], "colors": [[r, g, b], ...]}]}
// The viewport is the whole image (glViewport(0, 0, W, H)); the matrix must keep the scene
// inside -w <= x, y, z <= w where it should be drawn (OpenGL clipping). Mesa's tie rule is
// mirrored into exbsp's (osmesa_zbuffer.h). Exit status 2 with a message on bad input or when
// OSMesa is missing or fails.
#include <nlohmann/json.hpp>

#include <exception>
#include <fstream>
#include <iostream>
#include <string>

#include <exbsp/view/png_io.h>
#include "support/osmesa_zbuffer.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: zbuffer_render JOBS.json\n";
    return 2;
  }
#if !EXBSP_HAVE_OSMESA
  std::cerr << "zbuffer_render: built without OSMesa (apt-get install libosmesa6-dev, then "
               "reconfigure)\n";
  return 2;
#else
  using nlohmann::json;
  try {
    std::ifstream in(argv[1]);
    if (!in) throw std::runtime_error(std::string("cannot read ") + argv[1]);
    const json doc = json::parse(in);
    for (const json& job : doc.at("jobs")) {
      exbsp::osmesa::zbuffer_scene z;
      z.image_width = z.vp_width = job.at("width").get<int>();
      z.image_height = z.vp_height = job.at("height").get<int>();
      const auto bg = job.at("background").get<std::array<int, 3> >();
      z.background = {static_cast<std::uint8_t>(bg[0]), static_cast<std::uint8_t>(bg[1]),
                      static_cast<std::uint8_t>(bg[2])};
      z.projection = job.at("clip_from_world").get<std::array<double, 16> >();
      z.nearer_is_smaller = job.value("nearer", std::string("smaller")) == "smaller";
      z.mirror_y = true;
      const json& tris = job.at("triangles");
      const json& cols = job.at("colors");
      if (tris.size() != cols.size())
        throw std::runtime_error("\"triangles\" and \"colors\" differ in length");
      for (std::size_t k = 0; k < tris.size(); ++k) {
        const auto t = tris[k].get<std::array<double, 9> >();
        z.triangles.push_back({{{t[0], t[1], t[2]}, {t[3], t[4], t[5]}, {t[6], t[7], t[8]}}});
        const auto c = cols[k].get<std::array<int, 3> >();
        z.colors.push_back({static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
                            static_cast<std::uint8_t>(c[2])});
      }
      exbsp::view::write_png(exbsp::osmesa::render_zbuffer(z), job.at("out").get<std::string>());
    }
  } catch (const std::exception& e) {
    std::cerr << "zbuffer_render: " << argv[1] << ": " << e.what() << "\n";
    return 2;
  }
  return 0;
#endif
}
