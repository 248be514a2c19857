// SPDX-License-Identifier: LGPL-3.0-or-later
// Multi-view drawing sheets (notation in drawing.h). Each view runs the viewing pipeline's
// per-view stages (order, [lighting], transform+clip) on an orthographic view of a BSP built
// once per solid, then the vector drawing's edges (and regions, unless --lines-only); the
// drawing grid (1/100 pixel, vector_drawing.h) at px_per_mm pixels per paper millimetre is
// mapped to the sheet.
#include "drawing/drawing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <map>

#include <exbsp/core/errors.h>
#include <exbsp/core/version.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
#include "drawing/hatch.h"
#include "view/edge_paths.h"
#include "view/lighting.h"

namespace exbsp::drawing {

namespace {

using view::vector3;

/// Pixels of the drawing grid per paper millimetre: one grid unit is 2 micrometres.
constexpr double px_per_mm = 5;
/// Air around each view's box, paper mm (edges on the bounding box stay inside the viewport).
constexpr double view_pad = 2;
/// At least this much paper between two views, mm (room for a section's label).
constexpr double view_gap = 14;
/// ISO 5457 borders: 20 mm filing margin on the left, 10 mm elsewhere; frame line 0.7 mm.
constexpr double margin_left = 20, margin = 10, frame_width = 0.7;
/// The title block (ISO 7200): at most 180 mm wide, at the lower right corner of the frame.
constexpr double title_width = 180, title_height = 32;
/// Lettering (ISO 3098): capital heights in mm.
constexpr double label_text = 2.5, value_text = 3.5, big_text = 5;
/// Thin lines of the frame and title block.
constexpr double thin = 0.25;

struct view_spec {
  const char* name;
  vector3 towards_eye, up;
  int first_col, first_row, third_col, third_row;  // grid cell (rows grow downwards)
};

// The principal views and their cells (notation in drawing.h).
constexpr view_spec principal[] = {
    {"front", {0, -1, 0}, {0, 0, 1}, 0, 0, 0, 0},    {"top", {0, 0, 1}, {0, 1, 0}, 0, 1, 0, -1},
    {"left", {-1, 0, 0}, {0, 0, 1}, 1, 0, -1, 0},    {"right", {1, 0, 0}, {0, 0, 1}, -1, 0, 1, 0},
    {"bottom", {0, 0, -1}, {0, -1, 0}, 0, -1, 0, 1}, {"rear", {0, 1, 0}, {0, 0, 1}, 2, 0, 2, 0},
};

/// The cells tried, in order, for the iso view and the sections.
constexpr int free_cells[][2] = {{1, -1}, {1, 1},   {-1, -1}, {-1, 1}, {2, -1}, {2, 1},
                                 {0, -1}, {0, 1},   {-1, 0},  {1, 0},  {2, 0},  {3, 0},
                                 {3, -1}, {3, 1},   {-1, 2},  {0, 2},  {1, 2},  {2, 2},
                                 {3, 2},  {-1, -2}, {0, -2},  {1, -2}, {2, -2}, {3, -2}};

/// One view to draw.
struct planned_view {
  std::string name;
  vector3 towards_eye, up;
  bool principal = false, hidden_edges = false;
  int section = -1;  // index into cuts
  int col = 0, row = 0;
  view::camera_basis basis;
  // Model extent in the view's (right, up) coordinates.
  double lo_r = 0, hi_r = 0, lo_u = 0, hi_u = 0;
  // Box in pixels at the chosen scale, and its lower-left corner in model (right, up).
  int width_px = 0, height_px = 0;
  double left = 0, bottom = 0;
  point2 lower_left;  // on the sheet
};

vector3 unit_vector(const vector3& v) { return view::normalized(v); }

double dot3(const vector3& a, const vec3d& p) { return a.x * p[0] + a.y * p[1] + a.z * p[2]; }

/// The vertices the triangles use.
template <class F>
void for_used_vertices(const triangle_soup& s, F&& f) {
  std::vector<char> used(s.vertices.size(), 0);
  for (const soup_triangle& t : s.triangles)
    for (std::uint32_t i : t.v) used[i] = 1;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) f(s.vertices[i]);
}

/// The axis-aligned bounding box of the vertices a soup's triangles use.
struct bounds {
  vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  bool finite = true;  ///< no coordinate is NaN or infinite
  bool empty() const { return !(lo[0] <= hi[0]); }
  /// Its centre, and (radius) the radius of its bounding sphere (halves first: no overflow).
  vector3 centre(double& radius) const {
    radius = std::max(
        std::hypot(hi[0] / 2 - lo[0] / 2, hi[1] / 2 - lo[1] / 2, hi[2] / 2 - lo[2] / 2), 1e-300);
    return {lo[0] / 2 + hi[0] / 2, lo[1] / 2 + hi[1] / 2, lo[2] / 2 + hi[2] / 2};
  }
};

bounds bounds_of(const triangle_soup& s) {
  bounds b;
  for_used_vertices(s, [&](const vec3d& p) {
    for (std::size_t a = 0; a < 3; ++a) {
      b.finite = b.finite && std::isfinite(p[a]);
      b.lo[a] = std::min(b.lo[a], p[a]);
      b.hi[a] = std::max(b.hi[a], p[a]);
    }
  });
  return b;
}

/// Extent in the view's basis of the points `each` visits (each(f) calls f(p) per point).
template <class ForEach>
void measure(planned_view& v, ForEach&& each) {
  v.lo_r = v.lo_u = std::numeric_limits<double>::infinity();
  v.hi_r = v.hi_u = -std::numeric_limits<double>::infinity();
  each([&](const vec3d& p) {
    const double r = dot3(v.basis.u, p), u = dot3(v.basis.v, p);
    v.lo_r = std::min(v.lo_r, r);
    v.hi_r = std::max(v.hi_r, r);
    v.lo_u = std::min(v.lo_u, u);
    v.hi_u = std::max(v.hi_u, u);
  });
}

/// The view's box in pixels at k pixels per model unit.
void size_box(planned_view& v, double k) {
  const double pad_px = view_pad * px_per_mm;
  v.width_px = static_cast<int>(std::ceil((v.hi_r - v.lo_r) * k + 2 * pad_px));
  v.height_px = static_cast<int>(std::ceil((v.hi_u - v.lo_u) * k + 2 * pad_px));
  v.left = (v.lo_r + v.hi_r) / 2 - v.width_px / (2 * k);
  v.bottom = (v.lo_u + v.hi_u) / 2 - v.height_px / (2 * k);
}

struct grid_layout {
  std::map<int, double> col_width, row_height;  // mm
  double width = 0, height = 0;                 // mm, gaps included
};

grid_layout lay_out(const std::vector<planned_view>& views) {
  grid_layout g;
  for (const planned_view& v : views) {
    g.col_width[v.col] = std::max(g.col_width[v.col], v.width_px / px_per_mm);
    g.row_height[v.row] = std::max(g.row_height[v.row], v.height_px / px_per_mm);
  }
  for (const auto& c : g.col_width) g.width += c.second;
  for (const auto& r : g.row_height) g.height += r.second;
  g.width += view_gap * static_cast<double>(g.col_width.size() - 1);
  g.height += view_gap * static_cast<double>(g.row_height.size() - 1);
  return g;
}

point2 to_sheet(const planned_view& v, const view::grid_point& q) {
  const double unit_mm = 1.0 / (static_cast<double>(view::grid_per_pixel) * px_per_mm);
  return {v.lower_left.x + static_cast<double>(q.x) * unit_mm,
          v.lower_left.y + static_cast<double>(q.y) * unit_mm};
}

/// Sheet point of model point p in view v at mm_per_model.
point2 model_to_sheet(const planned_view& v, double mm_per_model, const vec3d& p) {
  return {v.lower_left.x + (dot3(v.basis.u, p) - v.left) * mm_per_model,
          v.lower_left.y + (dot3(v.basis.v, p) - v.bottom) * mm_per_model};
}

class sheet_builder {
 public:
  explicit sheet_builder(sheet& s) : s_(s) {}

  void line(layer_id layer, line_style style, double width, std::vector<point2> pts,
            bool closed = false) {
    s_.lines.push_back({layer, style, width, closed, std::move(pts)});
  }
  void rect(layer_id layer, double width, double x0, double y0, double x1, double y1) {
    line(layer, line_style::continuous, width, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, true);
  }
  void text(layer_id layer, point2 at, double h, std::string t,
            sheet_text::anchor_kind a = sheet_text::anchor_kind::start) {
    s_.texts.push_back({layer, at, h, a, std::move(t)});
  }
  void fill(layer_id layer, view::rgb8 c, std::vector<std::vector<point2>> rings) {
    s_.fills.push_back({layer, c, std::move(rings)});
  }

  /// A filled arrowhead at `tip` pointing along unit (dx, dy), length len (ISO 129: 15 degrees).
  void arrowhead(layer_id layer, point2 tip, double dx, double dy, double len) {
    const double half = len * std::tan(7.5 * 3.14159265358979323846 / 180);
    const point2 base{tip.x - dx * len, tip.y - dy * len};
    fill(layer, {0, 0, 0},
         {{tip,
           {base.x - dy * half, base.y + dx * half},
           {base.x + dy * half, base.y - dx * half}}});
  }

  /// The ISO 5456-2 symbol centred at (cx, cy) with size h (the cone's small diameter), first-
  /// or third-angle: a truncated cone whose small end faces left, and its view from the left
  /// (on the right of the cone in first angle, on its left in third angle).
  void projection_symbol(double cx, double cy, double h, projection_method m) {
    // Proportions of ISO 5456-2: small diameter h, large 2h, cone length 2h, gap h between.
    const double r1 = h / 2, r2 = h;
    const double cone = 2 * h, gap = h * 0.8;
    const double total = cone + gap + 2 * r2;
    const double x_left = cx - total / 2;
    const bool first = m == projection_method::first_angle;
    const double cone_x0 = first ? x_left : x_left + 2 * r2 + gap;
    const double circle_cx = first ? x_left + cone + gap + r2 : x_left + r2;
    line(layer_id::frame, line_style::continuous, thin,
         {{cone_x0, cy - r1},
          {cone_x0 + cone, cy - r2},
          {cone_x0 + cone, cy + r2},
          {cone_x0, cy + r1}},
         true);
    for (double r : {r1, r2}) {
      std::vector<point2> c;
      for (int k = 0; k < 72; ++k) {
        const double a = k * 2 * 3.14159265358979323846 / 72;
        c.push_back({circle_cx + r * std::cos(a), cy + r * std::sin(a)});
      }
      line(layer_id::frame, line_style::continuous, thin, std::move(c), true);
    }
    // Centre lines (thin), a little beyond the outlines.
    const double over = 0.15 * h;
    line(layer_id::frame, line_style::continuous, 0.13,
         {{x_left - over, cy}, {x_left + total + over, cy}});
    line(layer_id::frame, line_style::continuous, 0.13,
         {{circle_cx, cy - r2 - over}, {circle_cx, cy + r2 + over}});
  }

  /// One title block field: a label at the top left of its cell, the value below it.
  void field(double x, double y, double w, double h, const std::string& label,
             const std::string& value, double value_h = value_text) {
    rect(layer_id::frame, thin, x, y, x + w, y + h);
    text(layer_id::frame, {x + 1.5, y + h - 1.5 - label_text}, label_text, label);
    if (!value.empty()) text(layer_id::frame, {x + 1.5, y + 2}, value_h, value);
  }

 private:
  sheet& s_;
};

/// The drawing of one view: the pipeline on frame f (whose BSP is built).
view::vector_drawing draw_view(view::frame& f, const planned_view& v, double k, double radius,
                               const vector3& centre_v, const drawing_options& o) {
  const view::point3 centre{centre_v.x, centre_v.y, centre_v.z};
  const double distance = 2 * radius;
  view::view_setup& vs = f.view;
  vs.kind = view::projection_kind::orthographic;
  vs.cam = {centre + distance * v.towards_eye, centre, v.up};
  vs.model_view = view::look_at(vs.cam);
  // Eye coordinates x_e = u . (p - eye) = u . p - u . centre.
  const double cu = dot3(v.basis.u, {centre.x, centre.y, centre.z});
  const double cv = dot3(v.basis.v, {centre.x, centre.y, centre.z});
  const double l = v.left - cu, b = v.bottom - cv;
  vs.projection = view::ortho(l, l + v.width_px / k, b, b + v.height_px / k,
                              distance - 1.01 * radius, distance + 1.01 * radius);
  vs.vp = {0, 0, v.width_px, v.height_px, 0, 1};
  vs.direction = -1.0 * v.towards_eye;
  vs.image_width = vs.image_height = 0;
  f.vector.mode = view::vector_options::mode_kind::visible;
  f.vector.crease_deg = o.crease_deg;
  f.vector.edges = v.hidden_edges ? view::vector_options::edges_kind::visible_hidden
                                  : view::vector_options::edges_kind::visible;
  view::order_stage(f);
  if (!o.lines_only) {
    // Light over the viewer's left shoulder, as `exbsp render MESH`.
    f.settings.lighting.direction = v.towards_eye + 0.6 * v.basis.v - 0.4 * v.basis.u;
    f.settings.lighting.ambient = 0.3;
    f.settings.lighting.intensity = 0.7;
    view::lighting_stage(f);
  }
  view::transform_clip_stage(f);
  if (!o.lines_only) return view::visible_drawing(f);
  view::vector_drawing d;
  d.width = v.width_px;
  d.height = v.height_px;
  view::add_edge_paths(f, f.vector, d);
  return d;
}

/// The frame of a solid: its soup, one colour (the cap face another), the BSP built.
view::frame solid_frame(const triangle_soup& solid, const drawing_options& o,
                        std::optional<std::uint32_t> cap_face) {
  view::frame f;
  f.soup = solid;
  f.face_colors.assign(solid.face_count, o.color);
  if (cap_face && *cap_face < f.face_colors.size()) f.face_colors[*cap_face] = {236, 236, 236};
  f.build = o.build;
  f.background = {255, 255, 255};
  view::build_stage(f);
  return f;
}

}  // namespace

std::string today_date() {
  // SOURCE_DATE_EPOCH (reproducible builds' convention) fixes the date for identical output.
  std::time_t t = std::time(nullptr);
  if (const char* e = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long v = std::strtoll(e, &end, 10);
    if (end && *end == 0 && v >= 0) t = static_cast<std::time_t>(v);
  }
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[16];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
  return buf;
}

namespace {

sheet make_sheet_of(const triangle_soup& part, std::optional<bsp> part_tree,
                    const std::string& name, const std::vector<section_cut>& cuts,
                    const drawing_options& o, const sheet_progress& progress) {
  const auto say = [&](const std::string& m) {
    if (progress) progress(m);
  };
  if (o.views.empty() && o.sections.empty())
    throw usage_error("--views: at least one view (or a --section) is needed");
  if (cuts.size() != o.sections.size())
    throw usage_error("make_sheet: one cut per section is needed");
  if (!(o.visible_width > 0 && o.visible_width <= 5 && o.hidden_width > 0 && o.hidden_width <= 5))
    throw usage_error("--line-widths: each width must be in (0, 5] mm");
  const bounds part_box = bounds_of(part);
  if (part_box.empty()) throw input_error(name, 0, "the mesh has no triangle to draw");
  for (std::size_t a = 0; a < 3; ++a)
    if (!part_box.finite ||
        !(std::fabs(part_box.lo[a]) <= 1e150 && std::fabs(part_box.hi[a]) <= 1e150))
      throw input_error(name, 0, "coordinates too large to draw (over 1e150 in magnitude)");
  const double unit = unit_mm(o.units);
  if (o.up != "z" && o.up != "y") throw usage_error("--up: expected z or y, got '" + o.up + "'");
  // The views are defined on z-up axes; a y-up model's axes are (x, y, z) = (x, z_cad, -y_cad).
  const auto to_model = [&](const vector3& cad) {
    return o.up == "z" ? cad : vector3{cad.x, cad.z, -cad.y};
  };

  // The views, their bases and extents.
  std::vector<planned_view> views;
  for (const std::string& n : o.views) {
    planned_view v;
    v.name = n;
    if (n == "iso") {
      v.towards_eye = to_model(unit_vector({1, -1, 1}));
      v.up = to_model({0, 0, 1});
    } else {
      const view_spec* spec = nullptr;
      for (const view_spec& p : principal)
        if (n == p.name) spec = &p;
      if (!spec) throw usage_error("--views: unknown view '" + n + "'");
      v.towards_eye = to_model(spec->towards_eye);
      v.up = to_model(spec->up);
      v.principal = v.hidden_edges = true;
      const bool first = o.projection == projection_method::first_angle;
      v.col = first ? spec->first_col : spec->third_col;
      v.row = first ? spec->first_row : spec->third_row;
    }
    v.basis = view::look_direction_basis(-1.0 * v.towards_eye, v.up);
    views.push_back(v);
  }
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const auto& pl = cuts[i].spec.plane;
    const vector3 n = unit_vector({pl[0], pl[1], pl[2]});
    planned_view v;
    v.name = "section " + cuts[i].spec.letter;
    v.section = static_cast<int>(i);
    v.towards_eye = -1.0 * n;  // the viewer on the removed side looks at the cut face
    // Up: the drawing's up axis, or (a cut across it, seen from below or above) as the bottom
    // and top views have it.
    const vector3 z = to_model({0, 0, 1});
    const double nz = dot(n, z);
    v.up = std::fabs(nz) < 0.99 ? z : to_model({0, nz > 0 ? -1.0 : 1.0, 0});
    v.basis = view::look_direction_basis(n, v.up);
    views.push_back(v);
  }
  // Free cells for the iso view and the sections.
  {
    std::vector<std::pair<int, int>> taken;
    for (const planned_view& v : views)
      if (v.principal) taken.emplace_back(v.col, v.row);
    for (planned_view& v : views) {
      if (v.principal) continue;
      for (const auto& c : free_cells)
        if (std::find(taken.begin(), taken.end(), std::make_pair(c[0], c[1])) == taken.end()) {
          v.col = c[0];
          v.row = c[1];
          taken.emplace_back(c[0], c[1]);
          break;
        }
    }
  }
  // Extents: principal views use the part's bounding box (so that views line up), the others
  // their own solid's vertices.
  for (planned_view& v : views) {
    if (v.principal) {  // the 8 corners of the bounding box
      measure(v, [&](const auto& visit) {
        for (int c = 0; c < 8; ++c)
          visit(vec3d{c & 1 ? part_box.hi[0] : part_box.lo[0],
                      c & 2 ? part_box.hi[1] : part_box.lo[1],
                      c & 4 ? part_box.hi[2] : part_box.lo[2]});
      });
    } else {
      const triangle_soup& solid =
          v.section >= 0 ? cuts[static_cast<std::size_t>(v.section)].solid : part;
      measure(v, [&](const auto& visit) { for_used_vertices(solid, visit); });
    }
  }

  // The drawing area: inside the frame, above the title block.
  sheet s;
  s.width = o.sheet.width;
  s.height = o.sheet.height;
  s.title = o.title.empty() ? name : o.title;
  const double inner_w = s.width - margin_left - margin, inner_h = s.height - 2 * margin;
  const double tb_w = std::min(title_width, inner_w);
  if (inner_w < 40 || inner_h < title_height + 20)
    throw usage_error("--sheet: " + o.sheet.name + " is too small for a frame and a title block");
  const double area_x = margin_left + 4, area_y = margin + title_height + 4;
  const double area_w = inner_w - 8;
  // Room above the block for the top row's section labels.
  const double area_h = inner_h - title_height - 8 - (cuts.empty() ? 0 : 9);

  // Scale: the asked one, or the largest standard one at which the views fit.
  const auto fits = [&](double factor, grid_layout* out) {
    const double k = unit * factor * px_per_mm;
    std::vector<planned_view> trial = views;
    for (planned_view& v : trial) {
      const double w = (v.hi_r - v.lo_r) * k, h = (v.hi_u - v.lo_u) * k;
      if (!(w < 1e6 && h < 1e6)) return false;  // over 200 m of paper
      size_box(v, k);
    }
    const grid_layout g = lay_out(trial);
    if (out) *out = g;
    return g.width <= area_w && g.height <= area_h;
  };
  drawing_scale scale{1, 1};
  if (o.scale) {
    scale = *o.scale;
    if (!fits(scale.factor(), nullptr)) {
      std::string best;
      for (const drawing_scale& c : standard_scales())
        if (fits(c.factor(), nullptr)) best = c.text();
      throw usage_error(
          "--scale: at " + scale.text() + " the views do not fit the " + o.sheet.name + " sheet" +
          (best.empty() ? std::string() : "; the largest standard scale that fits is " + best));
    }
  } else {
    bool found = false;
    for (const drawing_scale& c : standard_scales())
      if (fits(c.factor(), nullptr)) {
        scale = c;
        found = true;
      }
    if (!found)
      throw usage_error("--scale auto: the views do not fit the " + o.sheet.name +
                        " sheet at any scale from 1:1000000 to 1000000:1");
  }
  const double mm_per_model = unit * scale.factor();
  const double k = mm_per_model * px_per_mm;
  for (planned_view& v : views) size_box(v, k);
  const grid_layout g = lay_out(views);
  // Cell origins: the block centred in the drawing area; views centred in their cells.
  {
    std::map<int, double> col_x, row_top;
    double x = area_x + (area_w - g.width) / 2;
    for (const auto& c : g.col_width) {
      col_x[c.first] = x;
      x += c.second + view_gap;
    }
    double y = area_y + area_h - (area_h - g.height) / 2;
    for (const auto& r : g.row_height) {
      row_top[r.first] = y;
      y -= r.second + view_gap;
    }
    for (planned_view& v : views) {
      const double w = v.width_px / px_per_mm, h = v.height_px / px_per_mm;
      v.lower_left = {col_x[v.col] + (g.col_width.at(v.col) - w) / 2,
                      row_top[v.row] - g.row_height.at(v.row) + (g.row_height.at(v.row) - h) / 2};
    }
  }
  say("scale " + scale.text() + ", " + std::to_string(views.size()) + " views on " + o.sheet.name);

  sheet_builder out(s);
  const double vis_w = o.visible_width, hid_w = o.hidden_width;
  // The solids: the part (built once for all its views), then each section's cut solid.

  std::optional<view::frame> part_frame;
  for (planned_view& v : views) {
    const triangle_soup& solid =
        v.section >= 0 ? cuts[static_cast<std::size_t>(v.section)].solid : part;
    std::optional<view::frame> section_frame;
    view::frame* f = nullptr;
    if (v.section >= 0) {
      say("building the BSP of section " + cuts[static_cast<std::size_t>(v.section)].spec.letter);
      section_frame.emplace(
          solid_frame(solid, o, cuts[static_cast<std::size_t>(v.section)].cap_face));
      f = &*section_frame;
    } else {
      if (!part_frame && part_tree) {  // a saved tree: its views need no build
        part_frame.emplace();
        part_frame->soup = part;
        part_frame->face_colors.assign(part.face_count, o.color);
        part_frame->tree.emplace(std::move(*part_tree));
        part_tree.reset();
        view::adopt_tree_stage(*part_frame);
      }
      if (!part_frame) {
        say("building the BSP of " + name);
        part_frame.emplace(solid_frame(part, o, std::nullopt));
      }
      f = &*part_frame;
    }
    double radius = 0;
    const vector3 centre = (v.section >= 0 ? bounds_of(solid) : part_box).centre(radius);
    say("view " + v.name);
    const view::vector_drawing d = draw_view(*f, v, k, radius, centre, o);
    sheet_view sv;
    sv.name = v.name;
    sv.lower_left = v.lower_left;
    sv.width = v.width_px / px_per_mm;
    sv.height = v.height_px / px_per_mm;
    sv.right = {v.basis.u.x, v.basis.u.y, v.basis.u.z};
    sv.up = {v.basis.v.x, v.basis.v.y, v.basis.v.z};
    sv.towards_eye = {v.basis.w.x, v.basis.w.y, v.basis.w.z};
    sv.left = v.left;
    sv.bottom = v.bottom;
    sv.mm_per_model = mm_per_model;
    for (const view::vector_path& p : d.paths) {
      std::vector<std::vector<point2>> rings;
      for (const auto& r : p.rings) {
        std::vector<point2> pts;
        pts.reserve(r.size());
        for (const view::grid_point& q : r) pts.push_back(to_sheet(v, q));
        rings.push_back(std::move(pts));
      }
      switch (p.kind) {
        case view::vector_path::kind_type::underlay:
        case view::vector_path::kind_type::region:
          out.fill(layer_id::fills, p.color, std::move(rings));
          break;
        case view::vector_path::kind_type::visible_edge:
          for (auto& r : rings)
            out.line(layer_id::visible, line_style::continuous, vis_w, std::move(r));
          sv.visible_chains += p.rings.size();
          break;
        case view::vector_path::kind_type::hidden_edge:
          for (auto& r : rings) out.line(layer_id::hidden, line_style::dashed, hid_w, std::move(r));
          sv.hidden_chains += p.rings.size();
          break;
        default:
          break;
      }
    }
    if (v.section >= 0) {
      const section_cut& cut = cuts[static_cast<std::size_t>(v.section)];
      std::vector<std::vector<point2>> region;
      for (const auto& loop : cut.loops) {
        std::vector<point2> r;
        for (const auto& p : loop) r.push_back(model_to_sheet(v, mm_per_model, p));
        region.push_back(std::move(r));
      }
      // Spacing (ISO 128-50: suited to the size of the area): the largest of 3, 2, 1.5, 1 mm
      // that draws at least 8 lines across the region's smaller extent.
      double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
      for (const auto& r : region)
        for (const point2& p : r) {
          lo_x = std::min(lo_x, p.x);
          hi_x = std::max(hi_x, p.x);
          lo_y = std::min(lo_y, p.y);
          hi_y = std::max(hi_y, p.y);
        }
      const double extent = std::min(hi_x - lo_x, hi_y - lo_y);
      double spacing = 1;
      for (double c : {3.0, 2.0, 1.5})
        if (extent >= 8 * c) {
          spacing = c;
          break;
        }
      for (const hatch_segment& h : hatch_lines(region, spacing))
        out.line(layer_id::hatching, line_style::continuous, hid_w, {h.a, h.b});
      s.hatch_regions.push_back(std::move(region));
      // ISO 128-40: the section's identification above its view.
      const std::string label = "SECTION " + cut.spec.letter + "\u2013" + cut.spec.letter;
      out.text(layer_id::frame, {v.lower_left.x + sv.width / 2, v.lower_left.y + sv.height + 3},
               big_text, label, sheet_text::anchor_kind::middle);
    }
    s.views.push_back(sv);
  }

  // Cutting-plane lines (ISO 128-40) on the first principal view that sees each plane edge-on.
  for (const section_cut& cut : cuts) {
    const vector3 n{cut.spec.plane[0], cut.spec.plane[1], cut.spec.plane[2]};
    const planned_view* parent = nullptr;
    for (const planned_view& v : views)
      if (v.principal && dot(n, v.basis.w) == 0) {
        parent = &v;
        break;
      }
    if (!parent) {
      say("section " + cut.spec.letter +
          ": no principal view sees the plane edge-on; its cutting-plane line is not drawn");
      continue;
    }
    const planned_view& v = *parent;
    // In the view's model coordinates (r, u): nr * r + nu * u + d = 0.
    const double nr = dot(n, v.basis.u), nu = dot(n, v.basis.v), d0 = cut.spec.plane[3];
    const double len = std::hypot(nr, nu);
    const double ar = nr / len, au = nu / len;  // unit normal in the view: the viewing direction
    // A point on the line and its direction.
    const double r0 = -d0 * nr / (len * len), u0 = -d0 * nu / (len * len);
    const double tr = -au, tu = ar;
    // The line across the view's box, 6 mm beyond it at each end.
    const double w_model = v.width_px / k, h_model = v.height_px / k;
    double t_lo = -INFINITY, t_hi = INFINITY;
    const auto clip = [&](double p0, double dp, double lo, double hi) {
      if (dp == 0) {
        if (p0 < lo || p0 > hi) t_lo = INFINITY;
        return;
      }
      double a = (lo - p0) / dp, b = (hi - p0) / dp;
      if (a > b) std::swap(a, b);
      t_lo = std::max(t_lo, a);
      t_hi = std::min(t_hi, b);
    };
    clip(r0, tr, v.left, v.left + w_model);
    clip(u0, tu, v.bottom, v.bottom + h_model);
    if (!(t_lo < t_hi)) {
      say("section " + cut.spec.letter + ": the plane misses the " + v.name + " view");
      continue;
    }
    const auto at = [&](double t) {
      return point2{v.lower_left.x + (r0 + t * tr - v.left) * mm_per_model,
                    v.lower_left.y + (u0 + t * tu - v.bottom) * mm_per_model};
    };
    const double extra = 6 / mm_per_model;
    const point2 a = at(t_lo - extra), b = at(t_hi + extra);
    const double dx = (b.x - a.x), dy = (b.y - a.y), l = std::hypot(dx, dy);
    const double ex = dx / l, ey = dy / l;
    out.line(layer_id::cutting_planes, line_style::chain, hid_w, {a, b});
    // Thick ends (8 mm), arrows in the viewing direction, letters.
    const double thick = std::min(8.0, l / 4);
    const point2 a2{a.x + ex * thick, a.y + ey * thick}, b2{b.x - ex * thick, b.y - ey * thick};
    out.line(layer_id::cutting_planes, line_style::continuous, vis_w, {a, a2});
    out.line(layer_id::cutting_planes, line_style::continuous, vis_w, {b2, b});
    const double arrow = 8, head = 3.5;
    for (const point2& e : {a, b}) {
      const point2 tip{e.x + ar * arrow, e.y + au * arrow};
      out.line(layer_id::cutting_planes, line_style::continuous, hid_w, {e, tip});
      out.arrowhead(layer_id::cutting_planes, tip, ar, au, head);
      out.text(layer_id::cutting_planes, {tip.x + ar * 2.5 - 1.8, tip.y + au * 2.5 - 2.5}, big_text,
               cut.spec.letter);
    }
  }

  // Frame (ISO 5457) and title block (ISO 7200).
  out.rect(layer_id::frame, frame_width, margin_left, margin, s.width - margin, s.height - margin);
  const double tx = s.width - margin - tb_w, ty = margin;
  const double row1 = 12, row2 = 10, row3 = title_height - row1 - row2;
  const double wide = tb_w * 110 / 180, narrow = tb_w - wide;
  out.field(tx, ty, wide, row1, "Title", s.title, big_text);
  out.field(tx + wide, ty, narrow, row1, "Drawing number", o.number, big_text);
  const double c1 = tb_w * 30 / 180, c2 = tb_w * 25 / 180, c3 = tb_w * 45 / 180,
               c4 = tb_w * 45 / 180, c5 = tb_w - c1 - c2 - c3 - c4;
  double x = tx;
  out.field(x, ty + row1, c1, row2, "Scale", scale.text());
  x += c1;
  out.field(x, ty + row1, c2, row2, "Units", o.units);
  x += c2;
  out.field(x, ty + row1, c3, row2, "Projection", "");
  out.projection_symbol(x + 8.5, ty + row1 + 3.6, 2.4, o.projection);
  out.text(layer_id::frame, {x + 17, ty + row1 + 2.4}, label_text,
           o.projection == projection_method::first_angle ? "first angle" : "third angle");
  x += c3;
  out.field(x, ty + row1, c4, row2, "Date of issue", o.date.empty() ? today_date() : o.date);
  x += c4;
  out.field(x, ty + row1, c5, row2, "Sheet", o.sheet.name);
  out.field(tx, ty + row1 + row2, wide, row3, "Part", name);
  out.field(tx + wide, ty + row1 + row2, narrow, row3, "Drawn by",
            std::string("exbsp ") + version_string);
  return s;
}

}  // namespace

sheet make_sheet(const triangle_soup& part, const std::string& name,
                 const std::vector<section_cut>& cuts, const drawing_options& options,
                 const sheet_progress& progress) {
  return make_sheet_of(part, std::nullopt, name, cuts, options, progress);
}

sheet make_sheet(bsp tree, const std::string& name, const std::vector<section_cut>& cuts,
                 const drawing_options& options, const sheet_progress& progress) {
  const triangle_soup part = tree.input();
  return make_sheet_of(part, std::move(tree), name, cuts, options, progress);
}

}  // namespace exbsp::drawing
