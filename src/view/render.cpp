// SPDX-License-Identifier: LGPL-3.0-or-later
// One-call rendering and the fitted view (notation in <exbsp/view/render.h>).
#include <exbsp/view/render.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <exbsp/core/errors.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
#include <exbsp/view/standard_pipeline.h>
#include "core/name_list.h"
#include "view/fitted_view.h"

namespace exbsp::view {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double fovy_deg = 30;
/// The bounding sphere fills 1 / margin of the smaller field of view: a little air around it.
constexpr double margin = 1.08;

struct named_view {
  const char* name;
  vector3 towards_eye;  ///< from the centre towards the eye (any length)
  vector3 up;
};

constexpr named_view views[] = {
    {"iso", {1, 1, 1}, {0, 1, 0}},     {"front", {0, 0, 1}, {0, 1, 0}},
    {"back", {0, 0, -1}, {0, 1, 0}},   {"left", {-1, 0, 0}, {0, 1, 0}},
    {"right", {1, 0, 0}, {0, 1, 0}},   {"top", {0, 1, 0}, {0, 0, -1}},
    {"bottom", {0, -1, 0}, {0, 0, 1}},
};

}  // namespace

const std::vector<std::string>& fitted_view_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const named_view& v : views) n.emplace_back(v.name);
    return n;
  }();
  return names;
}

fitted_view fit_view_of(const triangle_soup& soup, int width, int height, const std::string& name,
                        const std::string& file, const std::string& view_what,
                        const std::string& size_what) {
  const named_view* chosen = nullptr;
  for (const named_view& v : views)
    if (name == v.name) chosen = &v;
  if (!chosen)
    throw usage_error(view_what + ": unknown view '" + name + "' (expected " +
                      name_list(fitted_view_names(), "or") + ")");
  if (width < 1 || width > 16384 || height < 1 || height > 16384)
    throw usage_error(size_what + ": width and height must be in 1..16384");
  if (soup.triangles.empty()) throw input_error(file, 0, "the mesh has no triangle to render");

  // Bounding box of the vertices the triangles use (a stray unused vertex does not move the view).
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const soup_triangle& t : soup.triangles)
    for (std::uint32_t i : t.v)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], soup.vertices[i][k]);
        hi[k] = std::max(hi[k], soup.vertices[i][k]);
      }
  // Halves first, so that a box spanning -DBL_MAX..DBL_MAX does not overflow here.
  std::array<double, 3> centre{}, half{};
  for (int k = 0; k < 3; ++k) {
    centre[k] = lo[k] / 2 + hi[k] / 2;
    half[k] = hi[k] / 2 - lo[k] / 2;
  }
  double radius = std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
  const double magnitude =
      std::max({std::fabs(centre[0]), std::fabs(centre[1]), std::fabs(centre[2])});
  // A mesh that is a single point (all triangles degenerate there) still gets a view of a small
  // region around it, scaled to its coordinates so that eye - centre is not lost to rounding.
  if (!(radius > magnitude * 1e-12)) radius = std::max(magnitude * 1e-6, 1.0);

  const double aspect = static_cast<double>(width) / height;
  const double half_fovy = fovy_deg * pi / 360;
  const double half_fov = std::min(half_fovy, std::atan(std::tan(half_fovy) * aspect));
  const double distance = margin * radius / std::sin(half_fov);
  const vector3 w = normalized(chosen->towards_eye);
  const std::array<double, 3> wk{w.x, w.y, w.z};
  std::array<double, 3> eye{};
  for (int k = 0; k < 3; ++k) eye[k] = centre[k] + distance * wk[k];
  const double near_dist = distance - 1.01 * radius, far_dist = distance + 1.01 * radius;
  const bool finite =
      std::isfinite(distance) && std::isfinite(far_dist) && near_dist > 0 &&
      std::all_of(eye.begin(), eye.end(), [](double x) { return std::isfinite(x); });
  if (!finite)
    throw input_error(file, 0, "the mesh's coordinates are too large to fit a view in double");

  fitted_view out;
  out.cam = {{eye[0], eye[1], eye[2]}, {centre[0], centre[1], centre[2]}, chosen->up};
  out.fovy_deg = fovy_deg;
  out.near_dist = near_dist;
  out.far_dist = far_dist;
  // Light over the viewer's left shoulder: towards the eye, up and to the left.
  const vector3 right = normalized(cross(chosen->up, w));
  out.light = w + 0.6 * chosen->up - 0.4 * right;
  return out;
}

fitted_view fit_view(const triangle_soup& soup, int width, int height, const std::string& name) {
  return fit_view_of(soup, width, height, name, soup.source);
}

fitted_view view_of_tree(const bsp& tree, const camera& cam, double fovy_deg) {
  if (!(fovy_deg > 0 && fovy_deg < 180))
    throw usage_error("view_of_tree: fovy_deg must be in (0, 180)");
  const camera_basis basis = look_at_basis(cam.eye, cam.look_at, cam.up);  // checks the camera
  if (tree.fragment_count() == 0) throw usage_error("view_of_tree: the tree is empty");
  point3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const fragment_d& f : tree.fragments_double())
    for (const vec3d& p : f.v) {
      lo = {std::min(lo.x, p[0]), std::min(lo.y, p[1]), std::min(lo.z, p[2])};
      hi = {std::max(hi.x, p[0]), std::max(hi.y, p[1]), std::max(hi.z, p[2])};
    }
  const point3 centre{lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2};
  const double radius =
      length(vector3{hi.x / 2 - lo.x / 2, hi.y / 2 - lo.y / 2, hi.z / 2 - lo.z / 2});
  const double distance = length(cam.eye - centre);
  fitted_view out;
  out.cam = cam;
  out.fovy_deg = fovy_deg;
  out.far_dist = distance + 1.01 * radius;
  out.near_dist = std::max(distance - 1.01 * radius, 1e-4 * out.far_dist);
  if (!(out.far_dist > out.near_dist && std::isfinite(out.far_dist)))
    throw usage_error("view_of_tree: the eye is too far from the tree to fit near and far");
  // Light over the viewer's left shoulder: towards the eye (w), up (v) and to the left (-u).
  out.light = basis.w + 0.6 * basis.v - 0.4 * basis.u;
  return out;
}

view_setup to_view_setup(const fitted_view& v, int width, int height) {
  view_setup s;
  s.kind = projection_kind::perspective;
  s.cam = v.cam;
  s.model_view = look_at(v.cam);
  s.vp = {0, 0, width, height};
  s.projection =
      perspective(v.fovy_deg, static_cast<double>(width) / height, v.near_dist, v.far_dist);
  return s;
}

std::vector<rgb8> headlight_colors(const triangle_soup& soup, const camera& cam, rgb8 base) {
  const vector3 light = normalized(cam.eye - cam.look_at);
  const auto scaled = [&base](double shade) {
    const auto channel = [shade](std::uint8_t c) {
      return static_cast<std::uint8_t>(std::lround(std::min(255.0, c * shade)));
    };
    return rgb8{channel(base.r), channel(base.g), channel(base.b)};
  };
  std::vector<rgb8> colors(soup.face_count, scaled(0.25));
  std::vector<bool> done(soup.face_count, false);
  for (const soup_triangle& t : soup.triangles) {
    if (t.face >= soup.face_count || done[t.face]) continue;
    const point3 a = to_point(soup.vertices[t.v[0]]);
    const vector3 n =
        cross(to_point(soup.vertices[t.v[1]]) - a, to_point(soup.vertices[t.v[2]]) - a);
    const double len = length(n);
    if (!(len > 0)) continue;
    colors[t.face] = scaled(0.25 + 0.75 * std::abs(dot(n, light)) / len);
    done[t.face] = true;
  }
  return colors;
}

namespace {

/// A frame holding `tree` (shared) for `view`, its fragments converted, painted in `style`.
frame tree_frame(const bsp& tree, const fitted_view& view, int width, int height,
                 const render_style& style) {
  if (width < 1 || width > 16384 || height < 1 || height > 16384)
    throw usage_error("render_tree: width and height must be in 1..16384");
  frame f;
  f.tree = tree;
  f.view = to_view_setup(view, width, height);
  f.background = style.background;
  f.settings.lighting.direction = view.light;
  f.settings.lighting.ambient = 0.3;
  f.settings.lighting.intensity = 0.7;
  adopt_tree_stage(f);
  // One colour for every face: the default, not a table by face id (ids may be sparse and
  // large: a caller's face_ids).
  f.default_color = style.color;
  return f;
}

/// "none", "visible" or "visible+hidden" (vector_options' names).
vector_options::edges_kind edges_named(const std::string& name) {
  if (const auto kind = edges_kind_named(name)) return *kind;
  throw usage_error("render: edges must be " + edges_kind_names() + ", got '" + name + "'");
}

/// The painted frame of render_tree: its picture (with `edges` drawn over it) and its
/// back-to-front order.
frame painted(const bsp& tree, const fitted_view& view, int width, int height,
              const render_style& style,
              vector_options::edges_kind edges = vector_options::edges_kind::none) {
  frame f = tree_frame(tree, view, width, height, style);
  pipeline p = per_view_pipeline({"lighting"}, output_kind::png);
  if (edges != vector_options::edges_kind::none) {
    f.soup = tree.input();  // the feature edges are the input mesh's (as in render_tree_svg)
    f.raster_edges.edges = edges;
    p.add("edges", raster_edges_stage);
  }
  p.run(f, nullptr);
  return f;
}

}  // namespace

image render_tree(const bsp& tree, const fitted_view& view, int width, int height,
                  const render_style& style, const std::string& edges) {
  return std::move(painted(tree, view, width, height, style, edges_named(edges)).picture);
}

std::string render_tree_svg(const bsp& tree, const fitted_view& view, int width, int height,
                            const render_style& style, const std::string& edges) {
  frame f = tree_frame(tree, view, width, height, style);
  f.vector = vector_options::for_mesh();
  f.vector.edges = edges_named(edges);
  // Feature edges are the input mesh's (boundary, crease, silhouette): they need the soup the
  // tree was built from (a tree built with build_options::keep_input = false has none).
  if (f.vector.edges != vector_options::edges_kind::none) f.soup = tree.input();
  per_view_pipeline({"lighting"}, output_kind::svg).run(f, nullptr);
  return std::move(f.svg);
}

render_result render_soup(const triangle_soup& soup, const render_options& options) {
  const fitted_view fitted = fit_view(soup, options.width, options.height, options.view);
  bsp tree = bsp::build(soup, options.build);
  // One traversal: the picture and the order come from the same painted frame.
  frame f =
      painted(tree, fitted, options.width, options.height, {options.color, options.background});
  return {std::move(f.picture), std::move(tree), std::move(f.order), fitted};
}

}  // namespace exbsp::view
