// SPDX-License-Identifier: LGPL-3.0-or-later
// Scene parsing and validation (notation in scene.h). Every check names its key as a JSON
// pointer; parse_scene validates the whole document before any mesh file is read.
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <sstream>

#include <exbsp/clip/section.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/projection.h>
#include "mesh/json_limits.h"
#include "scene/scene_parts.h"
#include "view/effects.h"
#include "scene/effect_parameters.h"
#include "scene/json_reader.h"

namespace exbsp::scene {

using nlohmann::json;

namespace {

/// "projection": {"type": "matrix", "matrix": [16 numbers, row-major]}: glLoadMatrix of an
/// eye-to-clip matrix P. Its centre of projection is C = P^-1 (0, 0, 1, 0), the eye-space point
/// (or direction, w = 0) that P sends to infinity along the depth axis: a point makes a
/// perspective view ordered from that point, a direction a parallel view along it. Window and
/// near and far distances come from the corners of the near face and the centres of the near
/// and far faces of the clip volume, mapped back by P^-1 (depths along eye -z, as glFrustum's
/// and glOrtho's).
void parse_projection_matrix(const reader& r, const json& m, scene& s) {
  const view::mat4 p = detail::parse_row_major(r, m, "/projection/matrix");
  const auto back = [&](double x, double y, double z, double w) {
    const std::optional<view::hpoint> e = view::solve(p, {x, y, z, w});
    if (!e)
      r.fail("/projection/matrix",
             "is singular (or not finite): no view volume maps onto the clip volume");
    return *e;
  };
  const view::hpoint c = back(0, 0, 1, 0);
  const double size = std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)});
  const bool perspective = std::abs(c.w) > 1e-9 * size;
  projection_spec& ps = s.projection;
  ps.kind = perspective ? view::projection_kind::frustum : view::projection_kind::orthographic;
  const auto eye_point = [&](const view::hpoint& h, const std::string& what) {
    if (!(std::abs(h.w) > 0))
      r.fail("/projection/matrix", "maps the " + what + " of the clip volume to infinity");
    return view::point3{h.x / h.w, h.y / h.w, h.z / h.w};
  };
  const view::point3 lo = eye_point(back(-1, -1, -1, 1), "near lower-left corner");
  const view::point3 hi = eye_point(back(1, 1, -1, 1), "near upper-right corner");
  const view::point3 near_centre = eye_point(back(0, 0, -1, 1), "near face's centre");
  const view::point3 far_centre = eye_point(back(0, 0, 1, 1), "far face's centre");
  ps.left = lo.x;
  ps.right = hi.x;
  ps.bottom = lo.y;
  ps.top = hi.y;
  if (perspective) {  // depths along eye -z from the centre of projection, as glFrustum's
    const double centre_z = c.z / c.w;
    ps.near_dist = centre_z - near_centre.z;
    ps.far_dist = centre_z - far_centre.z;
    if (!(ps.near_dist > 0) || !(ps.far_dist > ps.near_dist))
      r.fail("/projection/matrix",
             "puts the near face of the view volume behind its centre of projection or "
             "beyond the far face");
  } else {
    ps.near_dist = -near_centre.z;
    ps.far_dist = -far_centre.z;
  }
  if (!(ps.right > ps.left) || !(ps.top > ps.bottom))
    r.fail("/projection/matrix",
           "mirrors the window (its near face runs right to left or top to bottom)");
  s.projection_matrix = p;
}

void parse_projection(const reader& r, const json& doc, scene& s) {
  const json& p = r.object(r.require(doc, "", "projection"), "/projection");
  const json& type = r.require(p, "/projection", "type");
  if (!type.is_string()) r.fail("/projection/type", "must be a string");
  const std::string t = type.get<std::string>();
  projection_spec& ps = s.projection;
  auto num = [&](const char* name) {
    return r.number(r.require(p, "/projection", name), std::string("/projection/") + name);
  };
  if (t == "perspective") {
    ps.kind = view::projection_kind::perspective;
    r.warn_unknown(p, "/projection", {"type", "fovy_deg", "fovx_deg", "aspect", "near", "far"});
    const bool height = p.contains("fovy_deg"), width = p.contains("fovx_deg");
    if (height == width)
      r.fail(height ? "/projection/fovx_deg" : "/projection/fovy_deg",
             height ? "give the height angle fovy_deg or the width angle fovx_deg, not both"
                    : "missing key (or fovx_deg, the width angle)");
    const char* angle = height ? "fovy_deg" : "fovx_deg";
    (height ? ps.fovy_deg : ps.fovx_deg) = num(angle);
    const double a = height ? ps.fovy_deg : ps.fovx_deg;
    if (!(a > 0 && a < 180))
      r.fail(std::string("/projection/") + angle,
             "must be in (0, 180) degrees (got " + number_text(a) + ")");
    if (const json* v = r.optional(p, "aspect")) ps.aspect = r.positive(*v, "/projection/aspect");
  } else if (t == "frustum" || t == "orthographic" || t == "oblique") {
    ps.kind = t == "frustum"        ? view::projection_kind::frustum
              : t == "orthographic" ? view::projection_kind::orthographic
                                    : view::projection_kind::oblique;
    if (ps.kind == view::projection_kind::oblique)
      r.warn_unknown(p, "/projection",
                     {"type", "left", "right", "bottom", "top", "near", "far", "direction"});
    else
      r.warn_unknown(p, "/projection", {"type", "left", "right", "bottom", "top", "near", "far"});
  } else if (t == "ortho2d") {
    ps.kind = view::projection_kind::orthographic;
    ps.ortho2d = true;
    r.warn_unknown(p, "/projection", {"type", "left", "right", "bottom", "top"});
  } else if (t == "matrix") {
    r.warn_unknown(p, "/projection", {"type", "matrix"});
    parse_projection_matrix(r, r.require(p, "/projection", "matrix"), s);
    return;
  } else {
    r.fail("/projection/type",
           "unknown projection type \"" + t +
               "\" (expected perspective, frustum, orthographic, oblique, ortho2d or matrix)");
  }
  if (t == "frustum" || t == "orthographic" || t == "oblique" || t == "ortho2d") {
    ps.left = num("left");
    ps.right = num("right");
    ps.bottom = num("bottom");
    ps.top = num("top");
    if (!(ps.right > ps.left)) r.fail("/projection/right", "must be greater than /projection/left");
    if (!(ps.top > ps.bottom)) r.fail("/projection/top", "must be greater than /projection/bottom");
  }
  if (ps.ortho2d) {
    ps.near_dist = -1;
    ps.far_dist = 1;
    return;
  }
  ps.near_dist = num("near");
  ps.far_dist = num("far");
  if (ps.kind == view::projection_kind::orthographic) {  // glOrtho: any distinct near and far
    if (ps.near_dist == ps.far_dist)
      r.fail("/projection/far", "must differ from /projection/near (glOrtho)");
  } else if (!(ps.near_dist > 0))
    r.fail("/projection/near", "must be a positive distance in front of the eye (got " +
                                   number_text(ps.near_dist) + ")");
  if (ps.kind != view::projection_kind::orthographic && !(ps.far_dist > ps.near_dist))
    r.fail("/projection/far", "must be greater than /projection/near (near " +
                                  number_text(ps.near_dist) + ", far " + number_text(ps.far_dist) +
                                  ")");
  if (ps.kind == view::projection_kind::oblique) {
    ps.direction = r.triple(r.require(p, "/projection", "direction"), "/projection/direction");
    if (!(view::length(ps.direction) > 0))
      r.fail("/projection/direction", "must not be the zero vector");
    const view::vector3 g = s.camera.look_at - s.camera.eye;
    const double cos_angle =
        view::dot(ps.direction, g) / (view::length(ps.direction) * view::length(g));
    if (!(cos_angle > 1e-6))
      r.fail("/projection/direction",
             "must point into the scene (positive component along look_at - eye)");
  }
}

void parse_effects(const reader& r, const json& doc, scene& s) {
  const json* e = r.optional(doc, "effects");
  if (!e) return;
  r.object(*e, "/effects");
  std::string known;
  for (const view::effect_description& d : view::effect_catalog())
    known += (known.empty() ? "" : ", ") + d.name;
  const bool parallel = s.projection.kind != view::projection_kind::perspective &&
                        s.projection.kind != view::projection_kind::frustum;
  const view::effect_scene facts{
      parallel, s.projection.near_dist, s.projection.far_dist, s.background, s.width,
      s.height, max_viewport_side};
  for (auto it = e->begin(); it != e->end(); ++it) {
    const std::string key = "/effects/" + it.key();
    const view::effect_description* d = view::find_effect(it.key());
    if (!d) r.fail(key, "unknown effect (known: " + known + ")");
    const json& v = it.value();
    bool enabled;
    if (v.is_boolean()) {
      enabled = v.get<bool>();
    } else if (v.is_object()) {
      enabled = true;
    } else {
      r.fail(key, "must be true, false or an object of parameters");
    }
    if (!enabled) continue;
    if (!d->available) r.fail(key, "effect not supported yet");
    const json params = v.is_object() ? v : json::object();
    const effect_parameters_reader read = effect_parameters(d->name);
    if (!read) r.fail(key, "effect has no parameter reader");  // tests/test_effects.cpp
    read(r, params, key, facts, s.effect_settings);
    s.effects.push_back(d->name);
  }
  const auto has = [&](const char* name) {
    return std::find(s.effects.begin(), s.effects.end(), name) != s.effects.end();
  };
  if (has("exposure") && has("depth_of_field"))
    r.fail("/effects/exposure",
           "cannot be combined with depth_of_field (each averages views of its own)");
}

void parse_curves(const reader& r, const json& doc, scene& s) {
  r.for_each_entry(doc, "", "curves", [&](const json& e, const std::string& key) {
    const json& entry = r.object(e, key);
    r.warn_unknown(entry, key, {"bezier", "color", "control_polygon"});
    view::curve_spec curve;
    curve.control_points =
        detail::parse_points(r, entry, key, "bezier", 1, max_curve_control_points, "control point");
    if (const json* col = r.optional(entry, "color")) curve.color = r.color(*col, key + "/color");
    // "control_polygon": true or {"color"}: the polyline through the control points too, drawn
    // like "lines" (the curve lies in its convex hull).
    if (const json* polygon = r.optional(entry, "control_polygon")) {
      const std::string at = key + "/control_polygon";
      view::curve_spec hull{
          curve.control_points, {150, 150, 150}, true, view::segment_clipper::liang_barsky};
      if (polygon->is_object()) {
        r.warn_unknown(*polygon, at, {"color"});
        if (const json* col = r.optional(*polygon, "color"))
          hull.color = r.color(*col, at + "/color");
      } else if (!polygon->is_boolean()) {
        r.fail(at, "must be true, false or {\"color\": [r, g, b]}");
      }
      if ((!polygon->is_boolean() || polygon->get<bool>()) && curve.control_points.size() >= 2) {
        s.curves.push_back(std::move(hull));
        ++s.line_count;
      }
    }
    s.curves.push_back(std::move(curve));
  });
}

/// "svg": {"mode", "edges", "crease_deg"} (docs/contract.md "Pixels"; also used for PDF output)
/// into `out`; with `name` "raster" ({"edges", "crease_deg"}, the PNG's edges) there is no mode.
void parse_vector(const reader& r, const json& doc, const char* name, view::vector_options& out) {
  const json* v = r.optional(doc, name);
  if (!v) return;
  const std::string key = std::string("/") + name;
  const bool svg = key == "/svg";
  r.object(*v, key);
  if (svg)
    r.reject_unknown(*v, key, name, {"mode", "edges", "crease_deg"});
  else
    r.reject_unknown(*v, key, name, {"edges", "crease_deg", "wireframe"});
  auto text = [&](const char* member) -> std::string {
    const json& t = (*v)[member];
    if (!t.is_string())
      r.fail(key + "/" + member, std::string("must be a string (got ") + t.type_name() + ")");
    return t.get<std::string>();
  };
  if (svg && r.optional(*v, "mode")) {
    const std::string m = text("mode");
    if (m == "visible")
      out.mode = view::vector_options::mode_kind::visible;
    else if (m == "painter")
      out.mode = view::vector_options::mode_kind::painter;
    else
      r.fail(key + "/mode", "unknown mode \"" + m + "\" (expected visible or painter)");
  }
  if (r.optional(*v, "edges")) {
    const std::string e = text("edges");
    if (const auto kind = view::edges_kind_named(e))
      out.edges = *kind;
    else
      r.fail(key + "/edges",
             "unknown edges \"" + e + "\" (expected " + view::edges_kind_names() + ")");
  }
  if (const json* c = r.optional(*v, "crease_deg")) {
    const double d = r.number(*c, key + "/crease_deg");
    if (!(d > 0 && d <= 180))
      r.fail(key + "/crease_deg", "must be in (0, 180] (got " + number_text(d) + ")");
    out.crease_deg = d;
  }
}

/// "clip_planes" and "caps" (notation in scene.h).
void parse_clip_planes(const reader& r, const json& doc, scene& s) {
  if (const json* c = r.optional(doc, "clip_planes")) {
    if (!c->is_array())
      r.fail("/clip_planes",
             std::string("must be an array of [A, B, C, D] (got ") + c->type_name() + ")");
    if (c->size() > max_clip_planes)
      r.fail("/clip_planes", "at most " + std::to_string(max_clip_planes) + " planes (got " +
                                 std::to_string(c->size()) + ")");
    for (std::size_t i = 0; i < c->size(); ++i) {
      const std::string key = "/clip_planes/" + std::to_string(i);
      const json& p = (*c)[i];
      if (!p.is_array() || p.size() != 4)
        r.fail(key, "must be an array of 4 numbers [A, B, C, D] (A*x+B*y+C*z+D >= 0 is kept)");
      std::array<double, 4> plane{};
      for (int k = 0; k < 4; ++k) plane[k] = r.number(p[k], key + "/" + std::to_string(k));
      if (plane[0] == 0 && plane[1] == 0 && plane[2] == 0)
        r.fail(key, "the normal (A, B, C) must not be zero");
      s.clip_planes.push_back(plane);
    }
  }
  if (const json* caps = r.optional(doc, "caps")) {
    r.object(*caps, "/caps");
    r.warn_unknown(*caps, "/caps", {"color"});
    s.caps = true;
    if (const json* col = r.optional(*caps, "color")) s.cap_color = r.color(*col, "/caps/color");
    if (s.clip_planes.empty()) r.warn("/caps", "has no effect without /clip_planes");
  }
}

/// "drawing": {"title", "number", "date", "views", "projection", "sheet", "scale", "units",
/// "sections", "lines_only", "line_widths", "crease_deg"} (the options of `exbsp drawing`,
/// drawing/drawing.h), each checked by the drawing library's own parser.
void parse_drawing(const reader& r, const json& doc, scene& s) {
  const json* d = r.optional(doc, "drawing");
  if (!d) return;
  r.object(*d, "/drawing");
  r.reject_unknown(*d, "/drawing", "drawing",
                   {"title", "number", "date", "views", "projection", "sheet", "scale", "units",
                    "up", "sections", "lines_only", "line_widths", "crease_deg"});
  drawing::drawing_options& o = s.drawing;
  // The library's parsers name their argument first ("KEY: ..."): name the JSON key instead.
  const auto checked = [&](const std::string& key, auto&& parse) {
    try {
      return parse(std::string("\x01"));
    } catch (const usage_error& e) {
      std::string what = e.what();
      if (what.rfind("\x01: ", 0) == 0) what = what.substr(3);
      r.fail(key, what);
    }
  };
  const auto text = [&](const json& v, const std::string& key) {
    if (!v.is_string()) r.fail(key, std::string("must be a string (got ") + v.type_name() + ")");
    return v.get<std::string>();
  };
  const auto texts = [&](const json& v, const std::string& key) {
    std::vector<std::string> out;
    if (v.is_string()) return std::vector<std::string>{v.get<std::string>()};
    if (!v.is_array())
      r.fail(key, std::string("must be an array of strings (got ") + v.type_name() + ")");
    for (std::size_t k = 0; k < v.size(); ++k)
      out.push_back(text(v[k], key + "/" + std::to_string(k)));
    return out;
  };
  for (auto it = d->begin(); it != d->end(); ++it) {
    const std::string name = it.key(), key = "/drawing/" + name;
    const json& v = it.value();
    if (v.is_null()) continue;
    s.drawing_keys.push_back(name);
    if (name == "title") {
      o.title = text(v, key);
    } else if (name == "number") {
      o.number = text(v, key);
    } else if (name == "date") {
      o.date = text(v, key);
    } else if (name == "views") {
      std::string joined;
      for (const std::string& t : texts(v, key)) joined += (joined.empty() ? "" : ",") + t;
      o.views = checked(key, [&](const std::string& k) { return drawing::parse_views(joined, k); });
    } else if (name == "projection") {
      o.projection = checked(
          key, [&](const std::string& k) { return drawing::parse_projection(text(v, key), k); });
    } else if (name == "sheet") {
      o.sheet =
          checked(key, [&](const std::string& k) { return drawing::parse_paper(text(v, key), k); });
    } else if (name == "scale") {
      const std::string t = text(v, key);
      if (t == "auto")
        o.scale.reset();
      else
        o.scale = checked(key, [&](const std::string& k) { return drawing::parse_scale(t, k); });
    } else if (name == "units") {
      o.units = text(v, key);
      checked(key, [&](const std::string& k) { return drawing::unit_mm(o.units, k); });
    } else if (name == "up") {
      o.up = text(v, key);
      if (o.up != "z" && o.up != "y") r.fail(key, "expected \"z\" or \"y\", got \"" + o.up + "\"");
    } else if (name == "sections") {
      const auto list = texts(v, key);
      o.sections.clear();
      for (std::size_t k = 0; k < list.size(); ++k)
        o.sections.push_back(checked(key + "/" + std::to_string(k), [&](const std::string& kk) {
          return drawing::parse_section(list[k], kk);
        }));
    } else if (name == "lines_only") {
      if (!v.is_boolean())
        r.fail(key, std::string("must be true or false (got ") + v.type_name() + ")");
      o.lines_only = v.get<bool>();
    } else if (name == "line_widths") {
      if (!v.is_array() || v.size() != 2) r.fail(key, "must be [visible, hidden] in mm");
      o.visible_width = r.number(v[0], key + "/0");
      o.hidden_width = r.number(v[1], key + "/1");
      if (!(o.visible_width > 0 && o.visible_width <= 5 && o.hidden_width > 0 &&
            o.hidden_width <= 5))
        r.fail(key, "each width must be in (0, 5] mm");
    } else if (name == "crease_deg") {
      o.crease_deg = r.number(v, key);
      if (!(o.crease_deg > 0 && o.crease_deg <= 180)) r.fail(key, "must be in (0, 180]");
    }
  }
}

}  // namespace

void detail::parse_camera_and_projection(const reader& r, const json& doc, scene& s) {
  detail::parse_any_camera(r, doc, s);
  if (s.form != camera_form::phigs)
    parse_projection(r, doc, s);
  else if (r.optional(doc, "projection"))
    r.fail("/projection",
           "a phigs camera defines its own projection (window, front, back, projection): remove "
           "this key");
}

scene parse_scene(const json& doc, const std::string& path, std::ostream* warnings, bool strict) {
  const reader r(path, warnings, strict);
  if (!doc.is_object())
    r.fail("", std::string("the scene must be a JSON object (got ") + doc.type_name() + ")");
  r.warn_unknown(doc, "",
                 {"meshes", "groups", "curves", "lines", "camera", "projection", "viewport",
                  "image", "aspect", "background", "effects", "trackball", "svg", "raster",
                  "clip_planes", "caps", "drawing", "teaching"});
  scene s;
  s.path = path;
  detail::parse_mesh_tree(r, doc, path, s);
  parse_curves(r, doc, s);
  detail::parse_lines(r, doc, s);
  detail::parse_camera_and_projection(r, doc, s);
  detail::parse_viewport_and_image(r, doc, s);
  detail::parse_trackball(r, doc, s);
  if (const json* b = r.optional(doc, "background")) s.background = r.color(*b, "/background");
  parse_effects(r, doc, s);
  parse_vector(r, doc, "svg", s.vector);
  parse_vector(r, doc, "raster", s.raster_edges);
  if (const json* raster = r.optional(doc, "raster"))
    if (const json* w = r.optional(*raster, "wireframe")) {
      if (!w->is_boolean())
        r.fail("/raster/wireframe",
               std::string("must be true or false (got ") + w->type_name() + ")");
      s.wireframe = w->get<bool>();
      if (s.wireframe && !r.optional(*raster, "edges"))
        s.raster_edges.edges = view::vector_options::edges_kind::visible_hidden;
      if (s.wireframe && s.raster_edges.edges == view::vector_options::edges_kind::none)
        r.fail("/raster/wireframe", "a wireframe needs edges (\"edges\" is \"none\")");
    }
  parse_clip_planes(r, doc, s);
  parse_drawing(r, doc, s);
  detail::parse_teaching(r, doc, s);
  make_view_setup(s);  // reject cameras and projections whose matrices overflow, before any work
  return s;
}

json parse_scene_json(const std::string& text, const std::string& path) {
  check_json_nesting(text, path);  // before nlohmann builds (and later copies) the document
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // syntax errors, and numbers too large for a double
    throw scene_error(path, "", std::string("invalid JSON: ") + e.what());
  }
}

scene parse_scene_text(const std::string& text, const std::string& path, std::ostream* warnings,
                       bool strict) {
  return parse_scene(parse_scene_json(text, path), path, warnings, strict);
}

scene load_scene(const std::string& path, std::ostream* warnings, bool strict) {
  return parse_scene_text(read_input_file(path), path, warnings, strict);
}

perspective_lens lens_of(const projection_spec& p, int viewport_width, int viewport_height) {
  perspective_lens lens;
  lens.aspect = p.aspect > 0 ? p.aspect : static_cast<double>(viewport_width) / viewport_height;
  lens.fovy_deg = p.fovx_deg > 0
                      ? 2 * std::atan(std::tan(p.fovx_deg * M_PI / 360) / lens.aspect) * 180 / M_PI
                      : p.fovy_deg;
  return lens;
}

view::view_setup make_view_setup(const scene& s) {
  view::view_setup v;
  const projection_spec& p = s.projection;
  v.kind = p.kind;
  v.cam = s.camera;
  detail::place_viewport(s, v);
  try {
    v.model_view = s.view_matrix ? *s.view_matrix : view::look_at(s.camera);
  } catch (const usage_error& e) {
    throw scene_error(s.path, "/camera/up", e.what());
  }
  try {
    if (s.phigs) {
      v.projection = s.phigs->projection;
      v.direction = s.phigs->direction;
    } else if (s.projection_matrix) {
      // The centre of projection (parse_projection_matrix) in world coordinates: the eye of a
      // perspective view, the direction of a parallel one (into the scene: deeper along it).
      v.projection = *s.projection_matrix;
      const std::optional<view::hpoint> c = view::solve(v.projection, {0, 0, 1, 0});
      const std::optional<view::hpoint> world = c ? view::solve(v.model_view, *c) : std::nullopt;
      if (!world) throw usage_error("the viewing transformation is singular");
      if (p.kind == view::projection_kind::frustum)
        v.cam.eye = {world->x / world->w, world->y / world->w, world->z / world->w};
      else
        v.direction = view::normalized({world->x, world->y, world->z});
    } else
      switch (p.kind) {
        case view::projection_kind::perspective: {
          const perspective_lens lens = lens_of(p, v.vp.width, v.vp.height);
          v.projection = view::perspective(lens.fovy_deg, lens.aspect, p.near_dist, p.far_dist);
        } break;
        case view::projection_kind::frustum:
          v.projection = view::frustum(p.left, p.right, p.bottom, p.top, p.near_dist, p.far_dist);
          break;
        case view::projection_kind::orthographic:
          v.projection = view::ortho(p.left, p.right, p.bottom, p.top, p.near_dist, p.far_dist);
          v.direction = view::gaze_direction(s.camera);
          break;
        case view::projection_kind::oblique: {
          const view::vector3 d = view::normalized(p.direction);
          const view::vector3 dop_eye = view::transform_vector(v.model_view, d);
          const double pivot = -view::length(s.camera.look_at - s.camera.eye);
          v.projection = view::oblique(p.left, p.right, p.bottom, p.top, p.near_dist, p.far_dist,
                                       dop_eye, pivot);
          v.direction = d;
          break;
        }
      }
  } catch (const usage_error& e) {
    throw scene_error(s.path, "/projection", e.what());
  }
  const auto finite = [](const view::mat4& m) {
    for (double x : m.m)
      if (!std::isfinite(x)) return false;
    return true;
  };
  if (!finite(v.model_view))
    throw scene_error(s.path, "/camera/eye",
                      "the viewing transformation overflows (coordinates too large)");
  if (!finite(v.projection))
    throw scene_error(s.path, "/projection",
                      "the projection matrix overflows (near, far or window too extreme)");
  return v;
}

namespace {

/// The texture of mesh `m` (its "texture" given), whose geometry `part` has been read; the
/// texture matrix ("transforms") applied to part's texture coordinates.
std::shared_ptr<const view::texture> load_texture(const scene& s, const mesh_spec& m,
                                                  triangle_soup& part) {
  const texture_spec& t = *m.texture;
  const std::string key = m.key + "/texture";
  if (!part.has_uvs() && !part.triangles.empty())
    throw scene_error(s.path, key,
                      "the mesh " + m.path +
                          " has no texture coordinates (OBJ: vt and f v/vt; PLY: vertex "
                          "properties u, v or s, t)");
  if (!s.clip_planes.empty())
    throw scene_error(s.path, key,
                      "a textured mesh cannot be cut by clip_planes (the cut pieces carry no "
                      "texture coordinates)");
  if (t.matrix)
    for (std::array<vec2d, 3>& corners : part.triangle_uvs)
      for (vec2d& uv : corners) {
        const view::hpoint q = *t.matrix * view::point3{uv[0], uv[1], 0};
        if (!std::isfinite(q.x) || !std::isfinite(q.y))
          throw scene_error(s.path, key + "/transforms",
                            "sends a texture coordinate of " + m.path + " to infinity");
        uv = {q.x, q.y};
      }
  std::error_code ec;
  if (!std::filesystem::exists(t.path, ec))
    throw scene_error(s.path, key + "/png", "texture file not found: " + t.path);
  try {
    return std::make_shared<const view::texture>(view::read_png(t.path), t.filter, t.wrap);
  } catch (const input_error& e) {
    throw scene_error(s.path, key + "/png", std::string("unreadable texture: ") + e.what());
  }
}

}  // namespace

scene_geometry load_geometry(const scene& s) {
  scene_geometry g;
  g.face_offsets.push_back(0);
  const view::view_setup view_matrices = make_view_setup(s);
  const double max_clip = std::numeric_limits<double>::max() / 16;
  for (const mesh_spec& m : s.meshes) {
    triangle_soup part;
    if (m.soup) {
      part = *m.soup;
    } else {
      std::error_code ec;
      if (!std::filesystem::exists(m.path, ec))
        throw scene_error(s.path, m.key + "/file", "mesh file not found: " + m.path);
      part = read_mesh(m.path);
    }
    const bool identity = m.transform.m == view::mat4::identity().m;
    // Where a vertex that is too large comes from: the transform, or the mesh file itself.
    std::string culprit = identity
                              ? m.key + "/file"
                              : (m.transform_key.empty() ? m.key + "/transform" : m.transform_key);
    const auto move_vertices = [&](const view::mat4& t, const std::string& key) {
      for (std::size_t k = 0; k < part.vertices.size(); ++k) {
        const view::hpoint h = t * view::to_point(part.vertices[k]);
        const vec3d p = h.w == 1 ? vec3d{h.x, h.y, h.z} : vec3d{h.x / h.w, h.y / h.w, h.z / h.w};
        if (!(h.w != 0) || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
          throw scene_error(s.path, key,
                            "sends vertex " + std::to_string(k) + " of " + m.path + " to infinity");
        part.vertices[k] = p;
      }
    };
    if (!identity) move_vertices(m.transform, culprit);
    if (s.teaching.space_matrix) {
      // "teaching" "view_volume" "space": the scene after the observed camera's normalisation
      // up to that step; a projective step keeps the side of its plane that holds the scene,
      // cut exactly, so that no triangle wraps through infinity.
      if (s.teaching.space_keep) {
        const std::array<double, 4>& k = *s.teaching.space_keep;
        part = clip_soup(part, {k});
      }
      culprit = "/teaching/view_volume/space";
      move_vertices(*s.teaching.space_matrix, culprit);
    }
    for (std::size_t k = 0; k < part.vertices.size(); ++k) {
      const vec3d p = part.vertices[k];
      // Finite in the world but too large once viewed (e.g. scaled by 1e308): say so here,
      // naming the key, rather than as a NaN deep inside the clipper, which forms sums such
      // as w + z and interpolates between vertices (hence the headroom of 16).
      const view::hpoint clip =
          view_matrices.projection * (view_matrices.model_view * view::to_point(p));
      if (!(std::fabs(clip.x) <= max_clip && std::fabs(clip.y) <= max_clip &&
            std::fabs(clip.z) <= max_clip && std::fabs(clip.w) <= max_clip)) {
        // A vertex of ordinary size sent beyond the doubles by the view: the camera (an eye or
        // distance too far) or the projection is to blame, not the mesh.
        if (std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])}) <= 1e150)
          throw scene_error(s.path, "/camera",
                            "the view sends vertex " + std::to_string(k) + " of " + m.path +
                                " beyond " + number_text(max_clip) +
                                " in clip coordinates (the largest double / 16): the eye, its "
                                "distance or the projection's bounds are too large");
        throw scene_error(s.path, culprit,
                          "vertex " + std::to_string(k) + " of " + m.path +
                              " is too large to view: its clip coordinates exceed " +
                              number_text(max_clip) +
                              " (the largest double / 16; scale the mesh down)");
      }
    }
    const std::uint32_t first_face = g.soup.face_count, own_faces = part.face_count;
    std::shared_ptr<const view::texture> tex = m.texture ? load_texture(s, m, part) : nullptr;
    if (!s.clip_planes.empty())
      part = s.caps ? clip_soup_with_caps(part, s.clip_planes) : clip_soup(part, s.clip_planes);
    g.soup.append(part);
    g.face_colors.resize(g.soup.face_count, tex ? tex->mean : m.color);
    g.textures.push_back(std::move(tex));
    for (std::uint32_t f = first_face + own_faces; f < g.soup.face_count; ++f)
      g.face_colors[f] = s.cap_color;
    g.face_offsets.push_back(g.soup.face_count);
  }
  return g;
}

view::frame make_frame(const scene& s) {
  scene_geometry geometry = load_geometry(s);
  view::frame f;
  f.view = make_view_setup(s);
  f.background = s.background;
  f.face_colors = std::move(geometry.face_colors);
  f.soup = std::move(geometry.soup);
  f.settings = s.effect_settings;
  f.curves = s.curves;
  f.mesh_face_offsets = std::move(geometry.face_offsets);
  // Textured meshes: white faces, so that the raster's texel times the (lit) face colour is the
  // texel itself when unlit (GL_MODULATE).
  for (std::size_t k = 0; k < geometry.textures.size(); ++k)
    if (geometry.textures[k])
      for (std::uint32_t face = f.mesh_face_offsets[k]; face < f.mesh_face_offsets[k + 1]; ++face)
        f.face_colors[face] = view::rgb8{255, 255, 255};
  if (std::any_of(geometry.textures.begin(), geometry.textures.end(),
                  [](const auto& t) { return t != nullptr; }))
    f.mesh_textures = std::move(geometry.textures);
  f.vector = s.vector;
  f.raster_edges = s.raster_edges;
  f.wireframe = s.wireframe;
  f.visibility = s.teaching.painter;
  f.near_plane = s.teaching.near_plane;
  return f;
}

void use_texture_means(view::frame& f) {
  for (std::size_t k = 0; k < f.mesh_textures.size() && k + 1 < f.mesh_face_offsets.size(); ++k)
    if (f.mesh_textures[k])
      for (std::uint32_t face = f.mesh_face_offsets[k]; face < f.mesh_face_offsets[k + 1]; ++face)
        if (face < f.face_colors.size()) f.face_colors[face] = f.mesh_textures[k]->mean;
  f.mesh_textures.clear();
}

std::size_t mesh_of_face(const scene_geometry& g, std::uint32_t face) {
  const auto it = std::upper_bound(g.face_offsets.begin(), g.face_offsets.end(), face);
  if (it == g.face_offsets.begin() || it == g.face_offsets.end())
    return g.face_offsets.empty() ? 0 : g.face_offsets.size() - 1;
  return static_cast<std::size_t>(it - g.face_offsets.begin()) - 1;
}

}  // namespace exbsp::scene
