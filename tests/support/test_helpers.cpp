// SPDX-License-Identifier: LGPL-3.0-or-later
// Small helpers of the test files; see test_helpers.h.
#include "support/test_helpers.h"

#include <stdlib.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <exbsp/view/projection.h>
#include "view/backface_culling.h"
#include "view/clip_stage.h"
#include "view/rasterizer.h"

namespace exbsp_test {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

std::filesystem::path make_temp_dir(const std::string& name) {
  std::string tmpl =
      (std::filesystem::temp_directory_path() / ("exbsp_" + name + "_XXXXXX")).string();
  if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed for " + tmpl);
  return tmpl;
}

bool fixed_rc_seed() {
  ::setenv("RC_PARAMS", "seed=20240611", 0);
  return true;
}

exbsp::triangle_soup soup_of(const std::vector<std::array<exbsp::vec3d, 3>>& tris) {
  exbsp::triangle_soup soup;
  for (const auto& t : tris) soup.add_triangle(t[0], t[1], t[2]);
  return soup;
}

std::set<std::tuple<int, int, int>> colours_of(const exbsp::view::image& img) {
  std::set<std::tuple<int, int, int>> c;
  for (int r = 0; r < img.height(); ++r)
    for (int k = 0; k < img.width(); ++k) {
      const exbsp::view::rgb8 p = img.at_row(r, k);
      c.insert({p.r, p.g, p.b});
    }
  return c;
}

std::uint32_t add_quad(exbsp::triangle_soup& s, const exbsp::vec3d& a, const exbsp::vec3d& b,
                       const exbsp::vec3d& c, const exbsp::vec3d& d) {
  const auto base = static_cast<std::uint32_t>(s.vertices.size());
  s.vertices.insert(s.vertices.end(), {a, b, c, d});
  const std::uint32_t face = s.face_count;
  s.add_polygon({base, base + 1, base + 2, base + 3}, face);
  return face;
}

void add_box(exbsp::triangle_soup& s, const exbsp::vec3d& lo, const exbsp::vec3d& hi) {
  const auto P = [&](int x, int y, int z) {
    return exbsp::vec3d{x ? hi[0] : lo[0], y ? hi[1] : lo[1], z ? hi[2] : lo[2]};
  };
  add_quad(s, P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0));  // z = lo, normal -z
  add_quad(s, P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1));  // z = hi, +z
  add_quad(s, P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1));  // y = lo, -y
  add_quad(s, P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0));  // y = hi, +y
  add_quad(s, P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0));  // x = lo, -x
  add_quad(s, P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1));  // x = hi, +x
}

exbsp::view::frame perspective_frame(exbsp::triangle_soup soup,
                                     std::vector<exbsp::view::rgb8> colors,
                                     const exbsp::view::camera& cam, int width, int height,
                                     double fovy, double near_dist, double far_dist) {
  namespace view = exbsp::view;
  view::frame f;
  f.soup = std::move(soup);
  f.face_colors = std::move(colors);
  f.background = {255, 255, 255};
  f.view.kind = view::projection_kind::perspective;
  f.view.cam = cam;
  f.view.model_view = view::look_at(cam);
  f.view.projection =
      view::perspective(fovy, static_cast<double>(width) / height, near_dist, far_dist);
  f.view.vp = {0, 0, width, height, 0, 1};
  return f;
}

exbsp::view::image zbuffer_render(const exbsp::view::frame& f, bool cull) {
  namespace view = exbsp::view;
  const int w = f.view.vp.width, h = f.view.vp.height;
  view::image img(w, h, f.background);
  std::vector<double> depth(static_cast<std::size_t>(w) * h, 2.0);  // window depth is in [0, 1]
  const view::mat4 pm = f.view.projection * f.view.model_view;
  std::vector<view::hpoint> in(3), out;
  for (const exbsp::soup_triangle& t : f.soup.triangles) {
    const exbsp::fragment_d tri{
        t.face, {f.soup.vertices[t.v[0]], f.soup.vertices[t.v[1]], f.soup.vertices[t.v[2]]}};
    if (cull && view::is_back_facing(tri, f.view)) continue;
    for (int k = 0; k < 3; ++k) in[k] = pm * view::to_point(tri.v[k]);
    view::clip_to_view_volume(in, out);
    std::vector<view::window_point> p;
    for (const view::hpoint& c : out)
      p.push_back(view::to_window(f.view.vp, c.x / c.w, c.y / c.w, c.z / c.w));
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      const view::window_point &a = p[0], &b = p[k], &c = p[k + 1];
      const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      view::for_each_covered_pixel({a.x, a.y}, {b.x, b.y}, {c.x, c.y}, w, h, [&](int i, int j) {
        // Window depth is affine in window x, y over a planar triangle: interpolate it.
        const double x = i + 0.5, y = j + 0.5;
        const double l1 = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
        const double l2 = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
        const double z = a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
        double& d = depth[static_cast<std::size_t>(j) * w + i];
        if (z < d) {
          d = z;
          img.set_pixel(i, j, f.color_of(t.face));
        }
      });
    }
  }
  return img;
}

double relative_difference(const exbsp::view::mat4& a, const exbsp::view::mat4& b) {
  double scale = 1;
  for (double x : b.m) scale = std::max(scale, std::fabs(x));
  return exbsp::view::max_abs_difference(a, b) / scale;
}

exbsp::input_error mesh_data_error(const std::string& data, exbsp::mesh_format format,
                                   const std::string& name) {
  try {
    exbsp::read_mesh_data(data, format, name);
  } catch (const exbsp::input_error& e) {
    return e;
  }
  ADD_FAILURE() << name << ": no input_error thrown";
  return exbsp::input_error(name, 0, "none");
}

std::vector<bad_input> bad_input_manifest() {
  const std::string path = std::string(EXBSP_SOURCE_DIR) + "/tests/data/bad/EXPECTED.tsv";
  std::vector<bad_input> rows;
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot open " << path;
  std::string row;
  while (std::getline(in, row)) {
    if (row.empty() || row[0] == '#') continue;
    const std::size_t tab1 = row.find('\t'), tab2 = row.find('\t', tab1 + 1);
    EXPECT_TRUE(tab1 != std::string::npos && tab2 != std::string::npos)
        << path << ": a row without two tabs: " << row;
    if (tab1 == std::string::npos || tab2 == std::string::npos) continue;
    rows.push_back({row.substr(0, tab1), std::stoul(row.substr(tab1 + 1, tab2 - tab1 - 1)),
                    row.substr(tab2 + 1)});
  }
  return rows;
}

std::string corpus_dir() { return std::string(EXBSP_SOURCE_DIR) + "/data/meshes/"; }

bool corpus_required() {
  const char* v = std::getenv("EXBSP_REQUIRE_CORPUS");
  return v && std::string(v) == "1";
}

int winding_number(const std::vector<std::vector<exbsp::view::grid_point>>& rings, double x,
                   double y) {
  int w = 0;
  for (const auto& r : rings)
    for (std::size_t k = 0; k < r.size(); ++k) {
      const exbsp::view::grid_point& a = r[k];
      const exbsp::view::grid_point& b = r[(k + 1) % r.size()];
      const double ay = static_cast<double>(a.y), by = static_cast<double>(b.y);
      if ((ay <= y) == (by <= y)) continue;
      const double t = (y - ay) / (by - ay);
      const double xi = static_cast<double>(a.x) + t * static_cast<double>(b.x - a.x);
      if (xi > x) w += by > ay ? 1 : -1;
    }
  return w;
}

}  // namespace exbsp_test
