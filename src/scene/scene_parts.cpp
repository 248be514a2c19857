// SPDX-License-Identifier: LGPL-3.0-or-later
// Modelling hierarchy, camera forms, viewport/image, lines and trackball of a scene
// (notation in scene.h; docs/contract.md "Scenes").
#include "scene/scene_parts.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include <exbsp/view/trackball.h>
#include <exbsp/view/transforms.h>

namespace exbsp::scene::detail {

namespace {

view::point3 as_point(const view::vector3& v) { return {v.x, v.y, v.z}; }

/// Applies a "transforms" list to the top of `stack` (each entry post-multiplies).
void apply_transforms(const reader& r, const json& list, const std::string& key,
                      view::matrix_stack& stack) {
  if (!list.is_array())
    r.fail(key, std::string("must be an array of transforms (got ") + list.type_name() + ")");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string k = key + "/" + std::to_string(i);
    const json& t = r.object(list[i], k);
    const char* kinds[] = {"translate", "rotate", "scale", "matrix"};
    int found = -1, count = 0;
    for (int j = 0; j < 4; ++j)
      if (t.contains(kinds[j])) {
        found = j;
        ++count;
      }
    if (count != 1) r.fail(k, "must have exactly one of translate, rotate, scale, matrix");
    for (auto it = t.begin(); it != t.end(); ++it)
      if (it.key() != kinds[found] && !(found == 3 && it.key() == "order"))
        r.fail(k + "/" + it.key(), std::string("unknown key in a ") + kinds[found] + " transform");
    const std::string vk = k + "/" + kinds[found];
    const json& v = t.at(kinds[found]);
    switch (found) {
      case 0:
        stack.multiply(view::translate(r.triple(v, vk)));
        break;
      case 1: {
        if (!v.is_array() || v.size() != 4) r.fail(vk, "must be [degrees, ax, ay, az]");
        const double deg = r.number(v[0], vk + "/0");
        const view::vector3 axis{r.number(v[1], vk + "/1"), r.number(v[2], vk + "/2"),
                                 r.number(v[3], vk + "/3")};
        if (!(view::length(axis) > 0)) r.fail(vk, "the rotation axis must not be the zero vector");
        stack.multiply(view::rotate(deg, axis));
        break;
      }
      case 2: {
        const view::vector3 f = r.triple(v, vk);
        stack.multiply(view::scale(f.x, f.y, f.z));
        break;
      }
      default: {
        if (!v.is_array() || v.size() != 16) r.fail(vk, "must be an array of 16 numbers");
        std::array<double, 16> m{};
        for (int j = 0; j < 16; ++j) m[j] = r.number(v[j], vk + "/" + std::to_string(j));
        const json& order = r.require(t, k, "order");
        const std::string o = order.is_string() ? order.get<std::string>() : std::string();
        if (o != "row-major" && o != "column-major")
          r.fail(k + "/order",
                 "must be \"row-major\" or \"column-major\" (GL, glTF and three.js store matrices "
                 "column-major)");
        const view::mat4 rows = view::mat4::from_rows(m);
        stack.multiply(o == "row-major" ? rows : view::transpose(rows));
      }
    }
  }
}

/// A mesh's "texture" (scene.h texture_spec).
texture_spec parse_texture(const reader& r, const json& entry, const std::string& mesh_key,
                           const std::filesystem::path& base) {
  const std::string key = mesh_key + "/texture";
  const json& t = r.object(entry, key);
  r.warn_unknown(t, key, {"png", "filter", "wrap", "transforms"});
  texture_spec spec;
  const json& png = r.require(t, key, "png");
  if (!png.is_string() || png.get<std::string>().empty() ||
      png.get<std::string>().find('\0') != std::string::npos)
    r.fail(key + "/png", "must be a non-empty string (a PNG file path)");
  spec.png = png.get<std::string>();
  const std::filesystem::path fp(spec.png);
  spec.path = fp.is_absolute() ? fp.string() : (base / fp).string();
  const auto word = [&](const char* name, const char* a, const char* b) -> int {
    const json* v = r.optional(t, name);
    if (!v) return 0;
    const std::string w = v->is_string() ? v->get<std::string>() : std::string();
    if (w != a && w != b)
      r.fail(key + "/" + name, std::string("must be \"") + a + "\" or \"" + b + "\"");
    return w == a ? 0 : 1;
  };
  if (word("filter", "nearest", "linear") == 1) spec.filter = view::texture::filter_kind::linear;
  if (word("wrap", "repeat", "clamp") == 1) spec.wrap = view::texture::wrap_kind::clamp;
  if (const json* list = r.optional(t, "transforms")) {  // the GL_TEXTURE matrix stack's top
    view::matrix_stack stack;
    apply_transforms(r, *list, key + "/transforms", stack);
    const view::mat4& m = stack.top();
    if (m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1)
      r.fail(key + "/transforms",
             "must keep q = 1 (bottom row 0 0 0 1): projective texture matrices are not supported");
    spec.matrix = m;
  }
  return spec;
}

mesh_spec parse_mesh_entry(const reader& r, const json& entry, const std::string& key,
                           const std::filesystem::path& base, view::matrix_stack& stack) {
  const json& m = r.object(entry, key);
  r.warn_unknown(m, key, {"file", "color", "transform", "transforms", "texture"});
  mesh_spec spec;
  spec.key = key;
  const json& file = r.require(m, key, "file");
  if (!file.is_string() || file.get<std::string>().empty())
    r.fail(key + "/file", "must be a non-empty string (a mesh file path)");
  spec.file = file.get<std::string>();
  // A file name cannot hold a NUL ("\u0000" in JSON): the system would read the name up to it.
  if (spec.file.find('\0') != std::string::npos)
    r.fail(key + "/file", "contains a NUL character (\\u0000), which no file name can hold");
  const std::filesystem::path fp(spec.file);
  spec.path = fp.is_absolute() ? fp.string() : (base / fp).string();
  if (const json* c = r.optional(m, "color")) spec.color = r.color(*c, key + "/color");
  if (const json* tex = r.optional(m, "texture")) spec.texture = parse_texture(r, *tex, key, base);
  const json* t = r.optional(m, "transform");
  const json* ts = r.optional(m, "transforms");
  if (t && ts) r.fail(key + "/transforms", "give transform or transforms, not both");
  stack.push();
  if (t) stack.multiply(parse_row_major(r, *t, key + "/transform"));
  if (ts) apply_transforms(r, *ts, key + "/transforms", stack);
  spec.transform = stack.top();
  spec.transform_key = key + (ts ? "/transforms" : "/transform");
  stack.pop();
  return spec;
}

/// The meshes of one group object (or the document) at `key` ("" for the document).
void parse_group_meshes(const reader& r, const json& group, const std::string& key,
                        const std::filesystem::path& base, view::matrix_stack& stack, scene& s) {
  r.for_each_entry(group, key, "meshes", [&](const json& entry, const std::string& at) {
    s.meshes.push_back(parse_mesh_entry(r, entry, at, base, stack));
  });
}

const json* groups_of(const reader& r, const json& group, const std::string& key) {
  const json* g = r.optional(group, "groups");
  if (g && !g->is_array())
    r.fail(key + "/groups", std::string("must be an array of groups (got ") + g->type_name() + ")");
  return g;
}

const json& empty_groups() {
  static const json none = json::array();
  return none;
}

double angle(const reader& r, const json& obj, const std::string& key, const char* name) {
  return r.number(r.require(obj, key, name), key + "/" + name);
}

}  // namespace

view::mat4 parse_row_major(const reader& r, const json& v, const std::string& key) {
  if (!v.is_array() || v.size() != 16)
    r.fail(key, "must be an array of 16 numbers (row-major 4x4)");
  std::array<double, 16> rows{};
  for (int k = 0; k < 16; ++k) rows[k] = r.number(v[k], key + "/" + std::to_string(k));
  return view::mat4::from_rows(rows);
}

void parse_mesh_tree(const reader& r, const json& doc, const std::string& path, scene& s) {
  if (!r.optional(doc, "meshes") && !r.optional(doc, "groups")) r.fail("/meshes", "missing key");
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  view::matrix_stack stack;
  parse_group_meshes(r, doc, "", base, stack, s);
  // Depth-first over the groups with an explicit stack (no recursion): each level remembers
  // its group list and the next child to visit; entering a group pushes the matrix stack,
  // leaving it pops (glPushMatrix / glPopMatrix).
  struct level {
    const json* groups;
    std::string key;
    std::size_t next = 0;
  };
  std::vector<level> levels;
  if (const json* g = groups_of(r, doc, "")) levels.push_back({g, "/groups"});
  while (!levels.empty()) {
    level& top = levels.back();
    if (top.next == top.groups->size()) {
      levels.pop_back();
      if (!levels.empty()) stack.pop();
      continue;
    }
    const std::string key = top.key + "/" + std::to_string(top.next);
    const json& group = r.object((*top.groups)[top.next++], key);
    if (levels.size() > max_group_depth)
      r.fail(key, "groups nested deeper than " + std::to_string(max_group_depth) + " levels");
    r.warn_unknown(group, key, {"transforms", "meshes", "groups"});
    stack.push();
    if (const json* t = r.optional(group, "transforms"))
      apply_transforms(r, *t, key + "/transforms", stack);
    parse_group_meshes(r, group, key, base, stack, s);
    if (const json* g = groups_of(r, group, key))
      levels.push_back({g, key + "/groups"});
    else
      levels.push_back({&empty_groups(), key + "/groups"});
  }
}

bool is_ortho2d(const json& doc) {
  const auto p = doc.find("projection");
  if (p == doc.end() || !p->is_object()) return false;
  const auto t = p->find("type");
  return t != p->end() && t->is_string() && t->get<std::string>() == "ortho2d";
}

namespace {

/// The member object `name` of the camera, with its known keys.
const json& camera_member(const reader& r, const json& cam, const char* name,
                          std::initializer_list<const char*> known) {
  const std::string key = std::string("/camera/") + name;
  const json& m = r.object(cam.at(name), key);
  r.warn_unknown(m, key, known);
  return m;
}

void parse_phigs(const reader& r, const json& cam, scene& s) {
  const std::string key = "/camera/phigs";
  const json& p = camera_member(
      r, cam, "phigs", {"vrp", "vpn", "vup", "prp", "window", "front", "back", "projection"});
  view::phigs_view v;
  v.vrp = as_point(r.triple(r.require(p, key, "vrp"), key + "/vrp"));
  v.vpn = r.triple(r.require(p, key, "vpn"), key + "/vpn");
  v.vup = r.triple(r.require(p, key, "vup"), key + "/vup");
  v.prp = as_point(r.triple(r.require(p, key, "prp"), key + "/prp"));
  const json& w = r.require(p, key, "window");
  if (!w.is_array() || w.size() != 4) r.fail(key + "/window", "must be [umin, umax, vmin, vmax]");
  v.umin = r.number(w[0], key + "/window/0");
  v.umax = r.number(w[1], key + "/window/1");
  v.vmin = r.number(w[2], key + "/window/2");
  v.vmax = r.number(w[3], key + "/window/3");
  v.front = r.number(r.require(p, key, "front"), key + "/front");
  v.back = r.number(r.require(p, key, "back"), key + "/back");
  const json& proj = r.require(p, key, "projection");
  const std::string pt = proj.is_string() ? proj.get<std::string>() : std::string();
  if (pt != "perspective" && pt != "parallel")
    r.fail(key + "/projection", "must be \"perspective\" or \"parallel\"");
  v.perspective = pt == "perspective";
  if (!(view::length(v.vpn) > 0)) r.fail(key + "/vpn", "must not be the zero vector");
  if (!(view::length(v.vup) > 0)) r.fail(key + "/vup", "must not be the zero vector");
  view::phigs_matrices m;
  try {
    m = view::phigs_view_matrices(v);
  } catch (const usage_error& e) {
    const std::string what = e.what();
    const std::size_t colon = what.find(':');
    r.fail(key + "/" + what.substr(0, colon), what.substr(colon + 2));
  }
  s.phigs = m;
  s.phigs_parameters = v;
  s.view_matrix = m.model_view;
  s.camera = view::camera_of(m.model_view, v.perspective ? v.prp.z : 1.0);
  projection_spec& ps = s.projection;
  ps.kind = v.perspective ? view::projection_kind::frustum
            : m.oblique   ? view::projection_kind::oblique
                          : view::projection_kind::orthographic;
  ps.left = v.umin;
  ps.right = v.umax;
  ps.bottom = v.vmin;
  ps.top = v.vmax;
  ps.near_dist = v.perspective ? v.prp.z - v.front : -v.front;
  ps.far_dist = v.perspective ? v.prp.z - v.back : -v.back;
  ps.direction = m.direction;
}

}  // namespace

void parse_any_camera(const reader& r, const json& doc, scene& s) {
  const json* c = r.optional(doc, "camera");
  if (!c) {
    if (!is_ortho2d(doc)) r.fail("/camera", "missing key");
    s.camera = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}};  // gluOrtho2D's usual identity modelview
    return;
  }
  const json& cam = r.object(*c, "/camera");
  const char* forms[] = {"eye", "position", "polar", "pilot", "phigs"};
  int form = -1;
  for (int k = 0; k < 5; ++k)
    if (cam.contains(forms[k])) {
      if (form >= 0)
        r.fail(
            std::string("/camera/") + forms[k],
            std::string("one camera form only (") + forms[form] + " and " + forms[k] + " given)");
      form = k;
    }
  if (form < 0) form = 0;  // the gluLookAt form names what is missing
  switch (form) {
    case 0: {
      s.form = camera_form::look_at;
      r.warn_unknown(cam, "/camera", {"eye", "look_at", "up"});
      s.camera.eye = as_point(r.triple(r.require(cam, "/camera", "eye"), "/camera/eye"));
      s.camera.look_at =
          as_point(r.triple(r.require(cam, "/camera", "look_at"), "/camera/look_at"));
      s.camera.up = r.triple(r.require(cam, "/camera", "up"), "/camera/up");
      if (!(view::length(s.camera.look_at - s.camera.eye) > 0))
        r.fail("/camera/look_at", "must differ from /camera/eye");
      break;
    }
    case 1: {
      s.form = camera_form::look;
      r.warn_unknown(cam, "/camera", {"position", "look", "up"});
      s.camera.eye = as_point(r.triple(r.require(cam, "/camera", "position"), "/camera/position"));
      const view::vector3 look = r.triple(r.require(cam, "/camera", "look"), "/camera/look");
      s.camera.up = r.triple(r.require(cam, "/camera", "up"), "/camera/up");
      if (!(view::length(look) > 0)) r.fail("/camera/look", "must not be the zero vector");
      s.camera.look_at = s.camera.eye + look;
      if (!view::is_finite(s.camera.look_at)) r.fail("/camera/look", "position + look overflows");
      try {
        s.view_matrix = view::look_along(s.camera.eye, look, s.camera.up);
      } catch (const usage_error&) {
        if (!(view::length(s.camera.up) > 0)) r.fail("/camera/up", "must not be the zero vector");
        r.fail("/camera/up", "is parallel to the view direction (look)");
      }
      break;
    }
    case 2: {
      s.form = camera_form::polar;
      r.warn_unknown(cam, "/camera", {"polar"});
      const std::string key = "/camera/polar";
      const json& p = camera_member(
          r, cam, "polar", {"distance", "twist_deg", "elevation_deg", "azimuth_deg", "look_at"});
      const double distance = r.number(r.require(p, key, "distance"), key + "/distance");
      if (!(distance > 0))
        r.fail(key + "/distance", "must be > 0 (the eye's distance from look_at)");
      view::point3 centre{0, 0, 0};
      if (const json* l = r.optional(p, "look_at"))
        centre = as_point(r.triple(*l, key + "/look_at"));
      s.view_matrix = view::polar_view(distance, angle(r, p, key, "twist_deg"),
                                       angle(r, p, key, "elevation_deg"),
                                       angle(r, p, key, "azimuth_deg"), centre);
      s.camera = view::camera_of(*s.view_matrix, distance);
      break;
    }
    case 3: {
      s.form = camera_form::pilot;
      r.warn_unknown(cam, "/camera", {"pilot"});
      const std::string key = "/camera/pilot";
      const json& p =
          camera_member(r, cam, "pilot", {"position", "roll_deg", "pitch_deg", "heading_deg"});
      const view::point3 position =
          as_point(r.triple(r.require(p, key, "position"), key + "/position"));
      s.view_matrix =
          view::pilot_view(position, angle(r, p, key, "roll_deg"), angle(r, p, key, "pitch_deg"),
                           angle(r, p, key, "heading_deg"));
      s.camera = view::camera_of(*s.view_matrix, 1.0);
      break;
    }
    default:
      s.form = camera_form::phigs;
      r.warn_unknown(cam, "/camera", {"phigs"});
      parse_phigs(r, cam, s);
  }
  if (s.form == camera_form::look_at || s.form == camera_form::look) {
    if (!(view::length(s.camera.up) > 0)) r.fail("/camera/up", "must not be the zero vector");
    try {
      view::look_at_basis(s.camera.eye, s.camera.look_at, s.camera.up);
    } catch (const usage_error&) {
      r.fail("/camera/up", "is parallel to the view direction");
    }
  }
}

void parse_viewport_and_image(const reader& r, const json& doc, scene& s) {
  const json& vp = r.object(r.require(doc, "", "viewport"), "/viewport");
  r.warn_unknown(vp, "/viewport", {"width", "height", "x", "y", "depth_range"});
  auto side = [&](const json& obj, const std::string& key, const char* name) {
    const long long v = r.integer(r.require(obj, key, name), key + "/" + name);
    if (v < 1 || v > max_viewport_side)
      r.fail(key + "/" + name, "must be in 1.." + std::to_string(max_viewport_side) + " (got " +
                                   std::to_string(v) + ")");
    return static_cast<int>(v);
  };
  s.width = side(vp, "/viewport", "width");
  s.height = side(vp, "/viewport", "height");
  auto offset = [&](const char* name) {
    const json* v = r.optional(vp, name);
    if (!v) return 0LL;
    const long long o = r.integer(*v, std::string("/viewport/") + name);
    if (o < 0 || o > max_viewport_side)
      r.fail(std::string("/viewport/") + name,
             "must be in 0.." + std::to_string(max_viewport_side));
    return o;
  };
  s.viewport_x = static_cast<int>(offset("x"));
  s.viewport_y = static_cast<int>(offset("y"));
  if (const json* range = r.optional(vp, "depth_range")) {  // glDepthRange(near, far)
    if (!range->is_array() || range->size() != 2)
      r.fail("/viewport/depth_range", "must be [near, far], two numbers in [0, 1]");
    double d[2];
    for (int k = 0; k < 2; ++k) {
      const std::string key = "/viewport/depth_range/" + std::to_string(k);
      d[k] = r.number((*range)[k], key);
      if (!(d[k] >= 0 && d[k] <= 1))
        r.fail(key, "must be in [0, 1] (got " + number_text(d[k]) + ")");
    }
    // Fog reads the eye's depth back from the window's: an empty range would lose it.
    if (d[0] == d[1]) r.fail("/viewport/depth_range", "near and far must differ");
    s.depth_near = d[0];
    s.depth_far = d[1];
  }
  s.image_width = s.width;
  s.image_height = s.height;
  if (const json* img = r.optional(doc, "image")) {
    r.object(*img, "/image");
    r.warn_unknown(*img, "/image", {"width", "height"});
    s.image_width = side(*img, "/image", "width");
    s.image_height = side(*img, "/image", "height");
  }
  if (s.viewport_x + s.width > s.image_width)
    r.fail("/viewport/x", "the viewport (x + width = " + std::to_string(s.viewport_x + s.width) +
                              ") must fit in the image (width " + std::to_string(s.image_width) +
                              ")");
  if (s.viewport_y + s.height > s.image_height)
    r.fail("/viewport/y", "the viewport (y + height = " + std::to_string(s.viewport_y + s.height) +
                              ") must fit in the image (height " + std::to_string(s.image_height) +
                              ")");
  if (const json* a = r.optional(doc, "aspect")) {
    const std::string v = a->is_string() ? a->get<std::string>() : std::string();
    if (v == "fit")
      s.aspect = aspect_policy::fit;
    else if (v != "stretch")
      r.fail("/aspect", "must be \"stretch\" (OpenGL's default) or \"fit\" (letterbox)");
  }
}

void place_viewport(const scene& s, view::view_setup& v) {
  int w = s.width, h = s.height, dx = 0, dy = 0;
  const bool perspective = !s.phigs && s.projection.kind == view::projection_kind::perspective;
  // A perspective view's window has the viewport's aspect unless the projection gives one.
  const bool has_window = !perspective || s.projection.aspect > 0;
  if (s.aspect == aspect_policy::fit && has_window) {
    const double window_aspect = perspective ? s.projection.aspect
                                             : (s.projection.right - s.projection.left) /
                                                   (s.projection.top - s.projection.bottom);
    const double viewport_aspect = static_cast<double>(w) / h;
    if (window_aspect > viewport_aspect) {
      const int fitted = std::max(1, static_cast<int>(std::lround(w / window_aspect)));
      dy = (h - fitted) / 2;
      h = fitted;
    } else {
      const int fitted = std::max(1, static_cast<int>(std::lround(h * window_aspect)));
      dx = (w - fitted) / 2;
      w = fitted;
    }
  }
  v.vp = view::viewport{0, 0, w, h, s.depth_near, s.depth_far};
  v.image_width = s.image_width > 0 ? s.image_width : s.width;
  v.image_height = s.image_height > 0 ? s.image_height : s.height;
  v.place_x = s.viewport_x + dx;
  v.place_y = s.viewport_y + dy;
}

std::vector<vec3d> parse_points(const reader& r, const json& entry, const std::string& key,
                                const char* name, std::size_t min, std::size_t max,
                                const char* noun) {
  const json& pts = r.require(entry, key, name);
  const std::string at = key + "/" + name;
  const std::string nouns = std::string(noun) + "s";
  if (!pts.is_array() || pts.size() < min)
    r.fail(at, "must be an array of at least " + std::to_string(min) + " " +
                   (min == 1 ? noun : nouns) + " [x, y, z]");
  if (pts.size() > max)
    r.fail(at, "at most " + std::to_string(max) + " " + nouns + " (got " +
                   std::to_string(pts.size()) + ")");
  std::vector<vec3d> points;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const view::vector3 p = r.triple(pts[k], at + "/" + std::to_string(k));
    points.push_back({p.x, p.y, p.z});
  }
  return points;
}

void parse_lines(const reader& r, const json& doc, scene& s) {
  r.for_each_entry(doc, "", "lines", [&](const json& e, const std::string& key) {
    const json& entry = r.object(e, key);
    r.warn_unknown(entry, key, {"points", "color", "clipper"});
    view::curve_spec line;
    line.polyline = true;
    line.control_points = parse_points(r, entry, key, "points", 2, max_line_points, "point");
    if (const json* c = r.optional(entry, "color")) line.color = r.color(*c, key + "/color");
    if (const json* c = r.optional(entry, "clipper")) {
      const std::string v = c->is_string() ? c->get<std::string>() : std::string();
      if (v == "cohen-sutherland")
        line.clipper = view::segment_clipper::cohen_sutherland;
      else if (v != "liang-barsky")
        r.fail(key + "/clipper", "must be \"cohen-sutherland\" or \"liang-barsky\"");
    }
    s.curves.push_back(std::move(line));
    ++s.line_count;
  });
}

void parse_trackball(const reader& r, const json& doc, scene& s) {
  const json* t = r.optional(doc, "trackball");
  if (!t) return;
  const std::string v = t->is_string() ? t->get<std::string>() : std::string();
  if (!trackball_named(v))
    r.fail("/trackball",
           "must be \"arcball\" (Shoemake, the default) or \"virtual\" (the classic virtual "
           "trackball)");
  s.trackball = v;
}

}  // namespace exbsp::scene::detail
