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
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/view/phigs.h>
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

/// The observed camera: its view setup and, for a PHIGS camera, its parameters.
struct observed_camera {
  view::view_setup v;
  std::optional<view::phigs_view> phigs;
};

/// The observed camera's view setup: "camera" and "projection" of `vv` parsed as a scene's,
/// with the scene's viewport; errors and warnings name /teaching/view_volume/...
observed_camera observed_view(const reader& r, const json& vv, const scene& s) {
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
  return {v, observed.phigs_parameters};
}

/// A world point from homogeneous h (w != 0).
vec3d euclidean(const view::hpoint& h) { return {h.x / h.w, h.y / h.w, h.z / h.w}; }

/// The space a "view_volume" "space" names: the partial product of the observed PHIGS
/// camera's normalisation, and the half-space kept before a projective one.
struct drawing_space {
  std::string name = "world";
  view::mat4 m = view::mat4::identity();
  std::optional<std::array<double, 4>> keep;  ///< world plane: keep A x + B y + C z + D >= 0

  bool is_world() const { return name == "world"; }
  bool projective() const { return keep.has_value(); }

  double side(const vec3d& p) const {
    const std::array<double, 4>& k = *keep;
    return k[0] * p[0] + k[1] * p[1] + k[2] * p[2] + k[3];
  }

  /// `p` in this space; fails naming `key` when the map sends it to infinity or beyond the
  /// doubles.
  vec3d map(const reader& r, const std::string& key, const vec3d& p) const {
    const view::hpoint h = m * view::point3{p[0], p[1], p[2]};
    const vec3d q = euclidean(h);
    if (!(h.w > 0) || !std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      r.fail(key, "the " + name + " space sends a point of the scene to infinity");
    return q;
  }

  /// A polyline in this space: cut to the kept half-space first when the map is projective
  /// (a line through the plane of the centre of projection would wrap through infinity).
  std::vector<std::vector<vec3d>> map_polyline(const reader& r, const std::string& key,
                                               const std::vector<vec3d>& points) const {
    std::vector<std::vector<vec3d>> runs(1);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!projective() || side(points[i]) >= 0) {
        runs.back().push_back(points[i]);
      } else if (!runs.back().empty()) {
        runs.emplace_back();
      }
      if (!projective() || i + 1 == points.size()) continue;
      const double a = side(points[i]), b = side(points[i + 1]);
      if ((a >= 0) == (b >= 0)) continue;
      // The crossing, in double: the lines are drawn, not built into the tree.
      const double t = a / (a - b);
      vec3d x;
      for (int c = 0; c < 3; ++c) x[c] = points[i][c] + t * (points[i + 1][c] - points[i][c]);
      runs.back().push_back(x);
      if (a >= 0) runs.emplace_back();
    }
    std::vector<std::vector<vec3d>> out;
    for (std::vector<vec3d>& run : runs) {
      if (run.empty() || (run.size() == 1 && points.size() > 1)) continue;
      for (vec3d& p : run) p = map(r, key, p);
      out.push_back(std::move(run));
    }
    return out;
  }
};

/// The space named by `vv`'s "space" (default world).
drawing_space space_of(const reader& r, const json& vv, const observed_camera& observed) {
  const std::string key = std::string(view_volume_key) + "/space";
  drawing_space d;
  const json* sp = r.optional(vv, "space");
  if (!sp) return d;
  if (!sp->is_string()) r.fail(key, std::string("must be a string (got ") + sp->type_name() + ")");
  d.name = sp->get<std::string>();
  const char* names[] = {"world", "vrc", "sheared", "opening_45", "normalised"};
  if (std::find(std::begin(names), std::end(names), d.name) == std::end(names))
    r.fail(key, "unknown space \"" + d.name +
                    "\" (expected world, vrc, sheared, opening_45, normalised)");
  if (d.is_world()) return d;
  if (!observed.phigs)
    r.fail(key,
           "the normalisation steps are those of the PHIGS view reference model: give the "
           "observed camera as {\"phigs\": {...}}");
  const view::phigs_view& p = *observed.phigs;
  if (d.name == "opening_45" && !p.perspective)
    r.fail(key,
           "a parallel view has no 45 degree opening (spaces: world, vrc, sheared, "
           "normalised)");
  std::vector<view::phigs_step> steps;
  try {
    steps = view::phigs_normalisation(p);
  } catch (const usage_error& e) {
    r.fail(std::string(view_volume_key) + "/camera/phigs", e.what());
  }
  for (const view::phigs_step& step : steps) {
    d.m = step.m * d.m;
    if (step.space == d.name) break;
  }
  if (d.name == "normalised" && p.perspective) {
    // Keep n <= (pn + F) / 2 in VRC: n(x) = (x - VRP) . n_hat.
    const view::camera_basis b = view::look_direction_basis(-p.vpn, p.vup);
    const double h = (p.prp.z + p.front) / 2;
    const double offset = b.w.x * p.vrp.x + b.w.y * p.vrp.y + b.w.z * p.vrp.z + h;
    d.keep = std::array<double, 4>{-b.w.x, -b.w.y, -b.w.z, offset};
  }
  return d;
}

/// Moves the scene's curves and lines into `d` (before the view volume's own lines are added).
void map_curves(const reader& r, const drawing_space& d, scene& s) {
  const std::string key = std::string(view_volume_key) + "/space";
  std::vector<view::curve_spec> curves, lines;
  const std::size_t first_line = s.curves.size() - s.line_count;
  for (std::size_t i = 0; i < s.curves.size(); ++i) {
    view::curve_spec& c = s.curves[i];
    std::vector<view::curve_spec>& out = i < first_line ? curves : lines;
    if (!c.polyline && c.control_points.size() > 2 && d.projective())
      r.fail(key,
             "the perspective normalised space is a projective map: it turns a Bezier curve "
             "into a rational one, which exbsp does not draw (draw the curves in an affine "
             "space: vrc, sheared or opening_45)");
    if (c.polyline || d.projective()) {  // a segment or a point is a polyline too
      for (std::vector<vec3d>& run : d.map_polyline(r, key, c.control_points))
        out.push_back({std::move(run), c.color, c.polyline, c.clipper});
    } else {  // affine: Bezier curves are affinely invariant, map the control points
      for (vec3d& p : c.control_points) p = d.map(r, key, p);
      out.push_back(std::move(c));
    }
  }
  s.line_count = lines.size();
  s.curves = std::move(curves);
  s.curves.insert(s.curves.end(), lines.begin(), lines.end());
}

/// The lines of the observed view volume and its reference frame (notation at the top).
void add_view_volume(const reader& r, const json& doc, scene& s) {
  const json& vv = r.object(*r.optional(doc, "view_volume"), view_volume_key);
  const std::string at = view_volume_key;
  r.reject_unknown(vv, at, "view_volume",
                   {"camera", "projection", "color", "axes", "axis_length", "space"});
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
  const observed_camera observed = observed_view(r, vv, s);
  const view::view_setup& v = observed.v;
  const drawing_space space = space_of(r, vv, observed);
  if (!space.is_world()) {
    if (space.projective())
      for (const mesh_spec& m : s.meshes)
        if (m.texture)
          r.fail(at + "/space",
                 "the perspective normalised space is a projective map, under which a texture's "
                 "coordinates no longer interpolate linearly: remove the texture of " +
                     m.key);
    map_curves(r, space, s);
    s.teaching.space = space.name;
    s.teaching.space_matrix = space.m;
    s.teaching.space_keep = space.keep;
  }

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
  const auto add = [&](const std::vector<vec3d>& points, view::rgb8 c) {
    for (std::vector<vec3d>& run : space.map_polyline(r, at + "/space", points)) {
      s.curves.push_back({std::move(run), c, true, view::segment_clipper::liang_barsky});
      ++s.line_count;
      ++s.teaching.view_volume_lines;
    }
  };
  add({near_face[0], near_face[1], near_face[2], near_face[3], near_face[0]}, color);
  add({far_face[0], far_face[1], far_face[2], far_face[3], far_face[0]}, color);
  for (int k = 0; k < 4; ++k) add({near_face[k], far_face[k]}, color);
  // The centre of projection: a point (perspective) closes the pyramid.
  const view::hpoint cop = back(0, 0, 1, 0);
  const double size = std::max({std::abs(cop.x), std::abs(cop.y), std::abs(cop.z)});
  if (std::abs(cop.w) > 1e-9 * size && !space.projective()) {  // the map sends it to infinity
    const vec3d c = euclidean(cop);
    for (int k = 0; k < 4; ++k) add({c, near_face[k]}, color);
  }
  if (!axes) return;
  // A PHIGS camera's frame is VRC: origin VRP, axes u, v, n (its perspective model_view puts
  // the eye coordinates' origin at PRP instead).
  const std::optional<view::hpoint> origin_h =
      observed.phigs
          ? view::hpoint{observed.phigs->vrp.x, observed.phigs->vrp.y, observed.phigs->vrp.z, 1}
          : view::solve(v.model_view, {0, 0, 0, 1});
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
  if (!space.is_world()) {
    // The world's frame too, in the same hues but muted: the notes' pictures show both frames
    // keeping their relative position through every step.
    const view::rgb8 world_colors[3] = {{200, 140, 140}, {130, 185, 130}, {140, 155, 215}};
    for (int i = 0; i < 3; ++i)
      add({{0, 0, 0},
           {i == 0 ? axis_length : 0, i == 1 ? axis_length : 0, i == 2 ? axis_length : 0}},
          world_colors[i]);
  }
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
