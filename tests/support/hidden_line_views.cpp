// SPDX-License-Identifier: LGPL-3.0-or-later
#include "support/hidden_line_views.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "scene/scene.h"

namespace exbsp_test {

using exbsp::vec3d;

const std::vector<view_spec>& standard_views() {
  static const std::vector<view_spec> v = {
      {"Front", {0, 0, -1}, {0, 1, 0}},
      {"Back", {0, 0, 1}, {0, 1, 0}},
      {"Top", {0, -1, 0}, {0, 0, -1}},
      {"Bottom", {0, 1, 0}, {0, 0, 1}},
      {"Left", {1, 0, 0}, {0, 1, 0}},
      {"Right", {-1, 0, 0}, {0, 1, 0}},
      {"Isometric", {-1, -1, -1}, {0, 1, 0}},        // from the (+, +, +) corner
      {"IsometricBackLeft", {1, -1, 1}, {0, 1, 0}},  // from the (-, +, -) corner
  };
  return v;
}

const std::vector<view_spec>& general_views() {
  static const std::vector<view_spec> v = {
      {"GeneralA", {-0.37, -0.52, -0.77}, {0, 1, 0}},
      {"GeneralB", {0.61, 0.29, -0.74}, {0, 1, 0}},
  };
  return v;
}

exbsp::view::frame make_view(const exbsp::triangle_soup& soup,
                             const std::vector<std::uint32_t>& offsets, const view_spec& v,
                             bool parallel, int width, int height, double crease_deg) {
  vec3d lo = soup.vertices.at(0), hi = lo;
  for (const vec3d& p : soup.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  auto norm = [](const vec3d& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); };
  const vec3d c{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const double r = norm({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / 2;
  const double dn = norm(v.direction);
  const double dist = 4 * r;
  const vec3d eye{c[0] - dist * v.direction[0] / dn, c[1] - dist * v.direction[1] / dn,
                  c[2] - dist * v.direction[2] / dn};
  const double aspect = static_cast<double>(width) / height;
  std::ostringstream j;
  j << std::setprecision(17) << R"({"meshes": [], "camera": {"eye": [)" << eye[0] << ", " << eye[1]
    << ", " << eye[2] << "], \"look_at\": [" << c[0] << ", " << c[1] << ", " << c[2]
    << "], \"up\": [" << v.up[0] << ", " << v.up[1] << ", " << v.up[2] << "]}, \"projection\": ";
  if (parallel)
    j << R"({"type": "orthographic", "left": )" << -1.3 * r * aspect
      << ", \"right\": " << 1.3 * r * aspect << ", \"bottom\": " << -1.3 * r
      << ", \"top\": " << 1.3 * r << ", \"near\": " << dist - 2 * r << ", \"far\": " << dist + 2 * r
      << "}";
  else
    j << R"({"type": "perspective", "fovy_deg": )" << 2 * std::atan(1.3 / 4) * 180 / M_PI
      << ", \"near\": " << dist - 2 * r << ", \"far\": " << dist + 2 * r << "}";
  j << R"(, "viewport": {"width": )" << width << ", \"height\": " << height
    << R"(}, "svg": {"edges": "visible+hidden", "crease_deg": )" << crease_deg << "}}";
  const exbsp::scene::scene sc = exbsp::scene::parse_scene_text(j.str(), "hidden_lines.json");
  exbsp::view::frame f = exbsp::scene::make_frame(sc);
  f.soup = soup;
  f.face_colors.assign(soup.face_count, exbsp::view::rgb8{200, 200, 200});
  f.mesh_face_offsets = offsets;
  return f;
}

}  // namespace exbsp_test
