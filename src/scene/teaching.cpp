// SPDX-License-Identifier: LGPL-3.0-or-later
// "teaching": the views the course notes draw to teach, as scene options (notation in scene.h).
// None is a default: a scene without "teaching" gets exactly the BSP's picture.
//
// View volume: the observed camera ("camera" and "projection" of "view_volume", read by the
// scene's own camera and projection parsers with the scene's viewport, so every camera form
// and projection type works; their errors name /teaching/view_volume/...) gives the matrices
// Mv and P. Its view volume is the clip cube -1 <= x, y, z <= 1 mapped back to the world by
// (P Mv)^-1: the near rectangle is z = -1, the far rectangle z = +1. Its centre of projection
// is (P Mv)^-1 (0, 0, 1, 0): a point for a perspective view (edges to the near corners are
// drawn: the tip of the pyramid), a direction at infinity for a parallel one. Its reference
// frame is the origin and the axes of its eye coordinates, Mv^-1 (0, 0, 0, 1) and
// Mv^-1 e_x, e_y, e_z (normalised): for a gluLookAt-type camera the eye and its x, y, z axes
// (u, v, n; n points back, away from the scene), for a PHIGS camera the VRP with u, v, n.
// Axis length: "axis_length", or a quarter of the distance between the centres of the near and
// far rectangles. All of it becomes "lines" (curve_spec polylines, Liang–Barsky), drawn by the
// curves stage in the scene camera's BSP order like any other line, in PNG, SVG and PDF.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/view/projection.h>
#include "scene/json_reader.h"
#include "scene/scene_parts.h"

namespace exbsp::scene::detail {

namespace {

constexpr const char* view_volume_key = "/teaching/view_volume";

/// `text` with every " /camera" and " /projection" (keys the shared parsers name in their
/// messages) prefixed with /teaching/view_volume.
std::string prefixed_keys(std::string text) {
  for (const char* k : {" /camera", " /projection", " /viewport"}) {
    const std::string from = k, to = std::string(" ") + view_volume_key + (k + 1);
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  }
  return text;
}

/// The observed camera's view setup: "camera" and "projection" of `vv` parsed as a scene's,
/// with the scene's viewport; errors and warnings name /teaching/view_volume/...
view::view_setup observed_view(const reader& r, const json& vv, const scene& s) {
  json sub = json::object();
  sub["camera"] = r.require(vv, view_volume_key, "camera");
  if (const json* p = r.optional(vv, "projection")) sub["projection"] = *p;
  sub["viewport"] = {{"width", s.width}, {"height", s.height}};
  std::ostringstream warnings;
  const reader sub_reader(r.file(), r.warnings() ? &warnings : nullptr, r.strict());
  scene observed;
  observed.path = s.path;
  view::view_setup v;
  try {
    parse_camera_and_projection(sub_reader, sub, observed);
    parse_viewport_and_image(sub_reader, sub, observed);
    v = make_view_setup(observed);
  } catch (const scene_error& e) {
    const std::string lead = e.file() + ": " + (e.key().empty() ? "" : e.key() + ": ");
    std::string what = e.what();
    if (what.rfind(lead, 0) == 0) what = what.substr(lead.size());
    throw scene_error(e.file(), view_volume_key + e.key(), prefixed_keys(what));
  }
  // Warnings ("exbsp: warning: FILE: KEY: what") again, with the key prefixed.
  const std::string lead = "exbsp: warning: " + r.file() + ": ";
  std::istringstream lines(warnings.str());
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(lead, 0) != 0) continue;
    line = line.substr(lead.size());
    const std::size_t colon = line.find(": ");
    if (colon == std::string::npos) continue;
    r.warn(view_volume_key + line.substr(0, colon), prefixed_keys(line.substr(colon + 2)));
  }
  return v;
}

/// A world point from homogeneous h (w != 0).
vec3d euclidean(const view::hpoint& h) { return {h.x / h.w, h.y / h.w, h.z / h.w}; }

/// The lines of the observed view volume and its reference frame (notation at the top).
void add_view_volume(const reader& r, const json& doc, scene& s) {
  const json& vv = r.object(*r.optional(doc, "view_volume"), view_volume_key);
  const std::string at = view_volume_key;
  r.reject_unknown(vv, at, "view_volume", {"camera", "projection", "color", "axes", "axis_length"});
  view::rgb8 color{60, 60, 60};
  if (const json* c = r.optional(vv, "color")) color = r.color(*c, at + "/color");
  bool axes = true;
  if (const json* a = r.optional(vv, "axes")) {
    if (!a->is_boolean())
      r.fail(at + "/axes", std::string("must be true or false (got ") + a->type_name() + ")");
    axes = a->get<bool>();
  }
  double axis_length = 0;
  if (const json* l = r.optional(vv, "axis_length"))
    axis_length = r.positive(*l, at + "/axis_length");
  const view::view_setup v = observed_view(r, vv, s);

  const view::mat4 pm = v.projection * v.model_view;
  const auto back = [&](double x, double y, double z, double w) {
    const std::optional<view::hpoint> h = view::solve(pm, {x, y, z, w});
    if (!h) r.fail(at, "the observed camera's matrices are singular: no view volume to draw");
    return *h;
  };
  const auto corner = [&](double x, double y, double z) {
    const view::hpoint h = back(x, y, z, 1);
    if (!(h.w != 0)) r.fail(at, "a corner of the observed view volume lies at infinity");
    const vec3d p = euclidean(h);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      r.fail(at, "a corner of the observed view volume overflows");
    return p;
  };
  const double xs[4] = {-1, 1, 1, -1}, ys[4] = {-1, -1, 1, 1};
  vec3d near_face[4], far_face[4];
  for (int k = 0; k < 4; ++k) {
    near_face[k] = corner(xs[k], ys[k], -1);
    far_face[k] = corner(xs[k], ys[k], 1);
  }
  const auto add = [&](std::vector<vec3d> points, view::rgb8 c) {
    s.curves.push_back({std::move(points), c, true, view::segment_clipper::liang_barsky});
    ++s.line_count;
    ++s.teaching.view_volume_lines;
  };
  add({near_face[0], near_face[1], near_face[2], near_face[3], near_face[0]}, color);
  add({far_face[0], far_face[1], far_face[2], far_face[3], far_face[0]}, color);
  for (int k = 0; k < 4; ++k) add({near_face[k], far_face[k]}, color);
  // The centre of projection: a point (perspective) closes the pyramid.
  const view::hpoint cop = back(0, 0, 1, 0);
  const double size = std::max({std::abs(cop.x), std::abs(cop.y), std::abs(cop.z)});
  if (std::abs(cop.w) > 1e-9 * size) {
    const vec3d c = euclidean(cop);
    for (int k = 0; k < 4; ++k) add({c, near_face[k]}, color);
  }
  if (!axes) return;
  const std::optional<view::hpoint> origin_h = view::solve(v.model_view, {0, 0, 0, 1});
  if (!origin_h || !(origin_h->w != 0))
    r.fail(at + "/camera", "the observed camera's viewing matrix is singular");
  const vec3d origin = euclidean(*origin_h);
  if (axis_length == 0) {
    const auto centre = [](const vec3d* face) {
      vec3d c{0, 0, 0};
      for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 3; ++i) c[i] += face[k][i] / 4;
      return c;
    };
    const vec3d n = centre(near_face), f = centre(far_face);
    axis_length = 0.25 * std::sqrt((f[0] - n[0]) * (f[0] - n[0]) + (f[1] - n[1]) * (f[1] - n[1]) +
                                   (f[2] - n[2]) * (f[2] - n[2]));
  }
  const view::rgb8 axis_colors[3] = {{220, 40, 40}, {30, 150, 30}, {40, 80, 230}};
  for (int i = 0; i < 3; ++i) {
    const std::optional<view::hpoint> d =
        view::solve(v.model_view, {i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0, 0});
    const double len = d ? std::sqrt(d->x * d->x + d->y * d->y + d->z * d->z) : 0;
    if (!(len > 0)) r.fail(at + "/camera", "the observed camera's viewing matrix is singular");
    const double t = axis_length / len;
    add({origin, {origin[0] + t * d->x, origin[1] + t * d->y, origin[2] + t * d->z}},
        axis_colors[i]);
  }
}

/// The string member `name` of `t` (at /teaching/NAME), one of `allowed`.
std::string choice(const reader& r, const json& t, const char* name,
                   std::initializer_list<const char*> allowed) {
  const std::string key = std::string("/teaching/") + name;
  const json& v = t[name];
  if (!v.is_string()) r.fail(key, std::string("must be a string (got ") + v.type_name() + ")");
  const std::string value = v.get<std::string>();
  std::string list;
  for (const char* a : allowed) {
    if (value == a) return value;
    list += (list.empty() ? "" : ", ") + std::string(a);
  }
  r.fail(key, "unknown value \"" + value + "\" (expected " + list + ")");
}

}  // namespace

void parse_teaching(const reader& r, const json& doc, scene& s) {
  const json* t = r.optional(doc, "teaching");
  if (!t) return;
  r.object(*t, "/teaching");
  r.reject_unknown(*t, "/teaching", "teaching",
                   {"painter", "depth_key", "near_plane", "view_volume"});
  teaching_spec& spec = s.teaching;
  if (r.optional(*t, "painter") && choice(r, *t, "painter", {"bsp", "depth_sort"}) == "depth_sort")
    spec.painter = view::visibility_order::depth_sort_farthest;
  if (r.optional(*t, "depth_key")) {
    if (spec.painter == view::visibility_order::bsp)
      r.fail("/teaching/depth_key", "applies to \"painter\": \"depth_sort\" only");
    if (choice(r, *t, "depth_key", {"farthest", "centroid"}) == "centroid")
      spec.painter = view::visibility_order::depth_sort_centroid;
  }
  if (r.optional(*t, "near_plane")) {
    const std::string rule = choice(r, *t, "near_plane", {"clip", "drop", "drop_mesh"});
    spec.near_plane = rule == "drop"        ? view::near_plane_rule::drop_polygon
                      : rule == "drop_mesh" ? view::near_plane_rule::drop_mesh
                                            : view::near_plane_rule::clip;
  }
  if (spec.painter != view::visibility_order::bsp) {
    // The depth rule of curves and lines places them in the tree's cells; smooth shading reads
    // the tree's fragment sources. A depth sort builds no tree.
    const char* needs_tree =
        !s.curves.empty()               ? "curves and lines (their depth rule uses the "
                                          "BSP's cells)"
        : r.optional(*t, "view_volume") ? "a view_volume (its lines are placed in the BSP's cells)"
        : s.effect_settings.lighting.smooth &&
                std::find(s.effects.begin(), s.effects.end(), "lighting") != s.effects.end()
            ? "smooth lighting (it reads the BSP's fragment sources)"
            : nullptr;
    if (needs_tree)
      r.fail("/teaching/painter", std::string("a depth sort builds no BSP, so it cannot draw ") +
                                      needs_tree + ": remove them or the depth sort");
  }
  if (r.optional(*t, "view_volume")) add_view_volume(r, *t, s);
}

}  // namespace exbsp::scene::detail
