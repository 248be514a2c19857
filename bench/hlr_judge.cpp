// SPDX-License-Identifier: LGPL-3.0-or-later
// hlr_judge: exbsp's hidden-line drawing of a mesh in one PARALLEL view, and optionally a peer's
// (Open CASCADE's HLR through FreeCAD: bench/hlr_peers.py), judged by the same independent
// ray-cast oracle (tests/support/hidden_line_oracle.h). Issue 23, "peers table".
//
// The frame is the one the hidden-line suite builds for its parallel views (tests/support/
// hidden_line_views.h make_view:
// the camera looks at the bounding box's centre from 4 radii away along the view direction,
// an orthographic window of 1.3 radii around it, viewport WIDTH x HEIGHT, edges
// "visible+hidden", crease 30 degrees), through the scene parser (parse_scene_text +
// make_frame), so it is exactly the frame of exbsp's own tests.
//
// exbsp is timed in one process, the pipeline run once:
//   edges     add_edge_paths on the frame: feature edges + exact visibility + edge paths
//             (src/view/edge_paths.h), the hidden-line drawing itself (best of --repeats);
//   drawing   visible_drawing: visible regions (Clipper) + the edges (best of --repeats);
//   pipeline  the whole SVG pipeline once: build (BSP) + order + transform+clip + svg.
// The judged drawing is visible_drawing(f), as the tests judge it.
//
// The peer: a JSON file {"visible": [[x0, y0, x1, y1, ...], ...], "hidden": [...]} of
// polylines (two points or more: a flat list of grid coordinates) in the view's drawing grid
// (1/100 pixel, y up, origin at the viewport's lower-left: vector_drawing.h). Points are
// rounded to the nearest grid point, as exbsp's are (to_grid); the polylines of each kind are then
// chained where exactly two ends meet (as edge_paths.h chains exbsp's), so that the oracle's run
// check (which skips run ends) sees the same kind of runs on both sides. They become one
// visible_edge and one hidden_edge path of mesh 0.
//
// The mapping (--mapping-out FILE, or with --mapping-only on stdout): for a parallel view the
// map from world to grid is affine, grid = G (x, y, z, 1); its 2 x 4 matrix is measured on the
// oracle's own projection (hidden_line_oracle::grid_of) and checked against the camera basis:
// grid = scale * ((p - origin) . right, (p - origin) . up), where origin is the world point
// (on the plane through the look-at point) that lands on the grid's (0, 0).
//
// Output: one JSON object on stdout: mesh, view, direction, up, width, height, triangles,
// feature_edges, feature_kinds, exbsp {seconds, seconds_drawing, seconds_pipeline, stages,
// agreement, run_agreement, samples, wrong, run_points, run_wrong, ...}, peer {...} (the first
// --peer) and peers [...] (every --peer, in order). Never a timed test.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/standard_pipeline.h>
#include <exbsp/view/vector_drawing.h>
#include "scene/scene.h"
#include "support/hidden_line_oracle.h"
#include "view/edge_paths.h"
#include "view/svg_writer.h"
#include "support/hidden_line_views.h"

namespace {

using namespace exbsp;
using namespace exbsp::view;
using json = nlohmann::json;
using clock_type = std::chrono::steady_clock;

using exbsp_test::view_spec;

/// The suite's view name in the command line's spelling: "Front" -> "front",
/// "IsometricBackLeft" -> "isometric-back-left".
std::string cli_name(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (std::isupper(static_cast<unsigned char>(c))) {
      if (i > 0) out += '-';
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else {
      out += c;
    }
  }
  return out;
}

std::vector<double> parse_numbers(const std::string& s) {
  std::vector<double> out;
  std::string item;
  std::istringstream in(s);
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

/// A view by name, or "dx,dy,dz" (view-up +y, or +z when the direction is vertical).
view_spec view_of(const std::string& text, const std::string& up_text) {
  view_spec v;
  bool found = false;
  for (const view_spec& n : exbsp_test::standard_views())
    if (cli_name(n.name) == text) {
      v = n;
      found = true;
    }
  if (!found) {
    const std::vector<double> d = parse_numbers(text);
    if (d.size() != 3) throw std::runtime_error("view: a name or dx,dy,dz: " + text);
    v.name = text;
    v.direction = {d[0], d[1], d[2]};
    const double h = std::hypot(d[0], d[2]);
    v.up = h < 1e-9 * std::abs(d[1]) ? vec3d{0, 0, d[1] > 0 ? 1.0 : -1.0} : vec3d{0, 1, 0};
  }
  if (!up_text.empty()) {
    const std::vector<double> u = parse_numbers(up_text);
    if (u.size() != 3) throw std::runtime_error("--up: ux,uy,uz");
    v.up = {u[0], u[1], u[2]};
  }
  return v;
}

json vec_json(const vector3& a) { return json::array({a.x, a.y, a.z}); }
json vec_json(const vec3d& a) { return json::array({a[0], a[1], a[2]}); }

/// The world-to-grid map of a parallel frame (see the header comment).
json mapping_of(const frame& f, const exbsp_test::hidden_line_oracle& oracle) {
  const camera_basis b = look_at_basis(f.view.cam.eye, f.view.cam.look_at, f.view.cam.up);
  std::array<double, 2> g0{}, gx{}, gy{}, gz{};
  // Measured on the look-at point and unit steps from it (affine: exact up to rounding).
  const vec3d c{f.view.cam.look_at.x, f.view.cam.look_at.y, f.view.cam.look_at.z};
  if (!oracle.grid_of(c, g0) || !oracle.grid_of({c[0] + 1, c[1], c[2]}, gx) ||
      !oracle.grid_of({c[0], c[1] + 1, c[2]}, gy) || !oracle.grid_of({c[0], c[1], c[2] + 1}, gz))
    throw std::runtime_error("the look-at point does not project");
  json G = json::array();
  for (int k = 0; k < 2; ++k) {
    const double ax = gx[k] - g0[k], ay = gy[k] - g0[k], az = gz[k] - g0[k];
    G.push_back({ax, ay, az, g0[k] - ax * c[0] - ay * c[1] - az * c[2]});
  }
  // scale: grid units per world unit along `right` (the window keeps the aspect ratio).
  const double scale = (gx[0] - g0[0]) * b.u.x + (gy[0] - g0[0]) * b.u.y + (gz[0] - g0[0]) * b.u.z;
  // origin: the point of the plane through the look-at point that lands on grid (0, 0).
  const double s0 = -g0[0] / scale, t0 = -g0[1] / scale;
  const vec3d origin{c[0] + s0 * b.u.x + t0 * b.v.x, c[1] + s0 * b.u.y + t0 * b.v.y,
                     c[2] + s0 * b.u.z + t0 * b.v.z};
  const std::array<double, 2> size = oracle.grid_size();
  return {{"grid_from_world", G},
          {"right", vec_json(b.u)},
          {"up", vec_json(b.v)},
          {"toward_viewer", vec_json(b.w)},
          {"direction", vec_json(f.view.direction)},
          {"origin", vec_json(origin)},
          {"scale", scale},
          {"look_at", vec_json(c)},
          {"grid_width", size[0]},
          {"grid_height", size[1]},
          {"note",
           "grid = grid_from_world * (x, y, z, 1) = scale * ((p - origin) . right, (p - origin) . "
           "up); 1 grid unit = 1/100 pixel, y up, origin at the viewport's lower-left"}};
}

/// Polylines of the peer file's `key` as grid polylines, chained where exactly two ends meet.
std::vector<std::vector<grid_point>> peer_polylines(const json& j, const char* key,
                                                    std::size_t& pieces_in) {
  std::vector<std::vector<grid_point>> lines;
  if (!j.contains(key)) return lines;
  for (const json& item : j.at(key)) {
    std::vector<grid_point> line;
    if (item.size() < 4 || item.size() % 2 != 0)
      throw std::runtime_error(std::string("peer: a polyline of ") + key +
                               " needs an even number (>= 4) of coordinates");
    for (std::size_t k = 0; k < item.size(); k += 2) {
      const grid_point p{std::llround(item[k].get<double>()),
                         std::llround(item[k + 1].get<double>())};
      if (line.empty() || !(line.back() == p)) line.push_back(p);
    }
    ++pieces_in;
    if (line.size() >= 2) lines.push_back(std::move(line));
  }
  // Chain: join two polylines at an end point shared by exactly two ends.
  auto key_of = [](const grid_point& p) { return std::make_pair(p.x, p.y); };
  bool merged = true;
  while (merged) {
    merged = false;
    std::map<std::pair<long long, long long>, std::vector<std::pair<std::size_t, bool>>> ends;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (lines[i].front() == lines[i].back()) continue;  // closed: leave alone
      ends[key_of(lines[i].front())].push_back({i, false});
      ends[key_of(lines[i].back())].push_back({i, true});
    }
    std::vector<bool> gone(lines.size(), false), touched(lines.size(), false);
    for (const auto& [pt, list] : ends) {
      if (list.size() != 2) continue;
      auto [i, i_back] = list[0];
      auto [k, k_back] = list[1];
      if (i == k || gone[i] || gone[k] || touched[i] || touched[k]) continue;
      std::vector<grid_point> a = lines[i], b = lines[k];
      if (!i_back) std::reverse(a.begin(), a.end());  // a ends at pt
      if (k_back) std::reverse(b.begin(), b.end());   // b starts at pt
      a.insert(a.end(), b.begin() + 1, b.end());
      lines[i] = std::move(a);
      gone[k] = true;
      touched[i] = true;
      merged = true;
    }
    std::vector<std::vector<grid_point>> kept;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (!gone[i]) kept.push_back(std::move(lines[i]));
    lines = std::move(kept);
  }
  return lines;
}

json report_json(const exbsp_test::hidden_line_report& r, bool with_summary) {
  json j = {{"agreement", r.agreement()},
            {"run_agreement", r.run_agreement()},
            {"samples", r.checked()},
            {"wrong", r.wrong()},
            {"visible_ok", r.visible_ok},
            {"hidden_ok", r.hidden_ok},
            {"visible_dashed", r.visible_dashed},
            {"visible_missing", r.visible_missing},
            {"hidden_solid", r.hidden_solid},
            {"hidden_missing", r.hidden_missing},
            {"skipped_ambiguous", r.skipped_ambiguous},
            {"skipped_outside", r.skipped_outside},
            {"run_points", r.run_ok + r.run_wrong()},
            {"run_wrong", r.run_wrong()},
            {"solid_over_hidden", r.solid_over_hidden},
            {"dashed_under_visible", r.dashed_under_visible},
            {"spurious", r.spurious},
            {"exact", r.exact}};
  if (with_summary) j["summary"] = r.summary();
  return j;
}

json drawing_counts_json(const vector_drawing& d) {
  std::size_t vis_lines = 0, hid_lines = 0, vis_pieces = 0, hid_pieces = 0;
  for (const vector_path& p : d.paths) {
    if (p.kind == vector_path::kind_type::visible_edge) {
      vis_lines += p.rings.size();
      for (const auto& r : p.rings) vis_pieces += r.size() - 1;
    } else if (p.kind == vector_path::kind_type::hidden_edge) {
      hid_lines += p.rings.size();
      for (const auto& r : p.rings) hid_pieces += r.size() - 1;
    }
  }
  return {{"visible_polylines", vis_lines},
          {"visible_pieces", vis_pieces},
          {"hidden_polylines", hid_lines},
          {"hidden_pieces", hid_pieces}};
}

template <class F>
double best_seconds(int repeats, F&& f) {
  double best = 1e300;
  for (int k = 0; k < std::max(1, repeats); ++k) {
    const auto t0 = clock_type::now();
    f();
    best = std::min(best, std::chrono::duration<double>(clock_type::now() - t0).count());
  }
  return best;
}

/// "stage NAME: SECONDS s (NOTE)" lines of pipeline::run's log.
json stage_times(const std::string& log) {
  json out = json::object();
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("stage ", 0) != 0) continue;
    const std::size_t colon = line.find(": ");
    if (colon == std::string::npos) continue;
    const std::string name = line.substr(6, colon - 6);
    try {
      out[name] = std::stod(line.substr(colon + 2));
    } catch (const std::exception&) {
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "hlr_judge: exbsp's hidden-line drawing (and a peer's) judged by the ray-cast oracle");
  std::string mesh_path, view_text = "front", up_text, size_text = "400x300", mapping_out, svg_out,
                         arithmetic = "automatic";
  std::vector<std::string> peer_paths, peer_svg_outs;
  int repeats = 3;
  double crease = 30;
  bool mapping_only = false, summary = false;
  app.add_option("mesh", mesh_path, "mesh file (OFF, PLY, STL, OBJ)")->required();
  app.add_option("--view", view_text,
                 "front, back, top, bottom, left, right, isometric, isometric-back-left, or "
                 "dx,dy,dz (direction into the scene)")
      ->capture_default_str();
  app.add_option("--up", up_text, "view-up ux,uy,uz (default: the named view's, or +y)");
  app.add_option("--size", size_text, "viewport WIDTHxHEIGHT in pixels")->capture_default_str();
  app.add_option("--peer", peer_paths,
                 "JSON {\"visible\": [[x0,y0,x1,y1,...],...], \"hidden\": [...]} in grid units "
                 "(repeatable: each is judged; the first is \"peer\", all are in \"peers\")");
  app.add_option("--mapping-out", mapping_out, "write the world-to-grid mapping (JSON) here");
  app.add_flag("--mapping-only", mapping_only,
               "print the mapping and the view and stop (no pipeline, no judging)");
  app.add_option("--repeats", repeats, "timing: best of this many edge/drawing runs")
      ->capture_default_str();
  app.add_option("--crease", crease, "crease angle, degrees (the contract: 30)")
      ->capture_default_str();
  app.add_option("--oracle", arithmetic, "oracle arithmetic: automatic, exact, filtered")
      ->capture_default_str();
  app.add_option("--svg-out", svg_out, "write exbsp's SVG here");
  app.add_option("--peer-svg-out", peer_svg_outs,
                 "write the peers' drawings as SVG here (one per --peer, in order)");
  app.add_flag("--summary", summary, "include the oracle's summary paragraphs");
  CLI11_PARSE(app, argc, argv);

  try {
    int width = 0, height = 0;
    if (std::sscanf(size_text.c_str(), "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0)
      throw std::runtime_error("--size WIDTHxHEIGHT");
    const view_spec v = view_of(view_text, up_text);
    const triangle_soup soup = read_mesh(mesh_path);
    frame f = exbsp_test::make_view(soup, {0, soup.face_count}, v, true, width, height, crease);

    exbsp_test::hidden_line_options opt;
    if (arithmetic == "exact")
      opt.arithmetic = exbsp_test::oracle_arithmetic::exact;
    else if (arithmetic == "filtered")
      opt.arithmetic = exbsp_test::oracle_arithmetic::filtered;
    else if (arithmetic != "automatic")
      throw std::runtime_error("--oracle automatic|exact|filtered");

    json out = {{"mesh", std::filesystem::path(mesh_path).filename().string()},
                {"view", v.name},
                {"direction", vec_json(v.direction)},
                {"up", vec_json(v.up)},
                {"width", width},
                {"height", height},
                {"crease_deg", crease}};

    const auto o0 = clock_type::now();
    const exbsp_test::hidden_line_oracle oracle(f, opt);
    const double oracle_seconds = std::chrono::duration<double>(clock_type::now() - o0).count();
    out["triangles"] = oracle.triangle_count();
    out["feature_edges"] = oracle.edges().size();
    json kinds = json::object();
    for (const exbsp_test::oracle_edge& e : oracle.edges())
      kinds[exbsp_test::to_string(e.kind)] = kinds.value(exbsp_test::to_string(e.kind), 0) + 1;
    out["feature_kinds"] = kinds;
    const json mapping = mapping_of(f, oracle);
    if (!mapping_out.empty()) {
      std::ofstream m(mapping_out);
      m << std::setprecision(17) << mapping.dump(2) << "\n";
      if (!m) throw std::runtime_error("cannot write " + mapping_out);
    }
    if (mapping_only) {
      out["mapping"] = mapping;
      std::cout << std::setprecision(17) << out.dump() << "\n";
      return 0;
    }

    // exbsp: the whole SVG pipeline once (per-stage times from its log), then the edge paths
    // and the drawing alone, best of `repeats`.
    std::ostringstream log;
    const auto p0 = clock_type::now();
    standard_pipeline({}, output_kind::svg).run(f, &log);
    const double pipeline_seconds = std::chrono::duration<double>(clock_type::now() - p0).count();
    const double edges_seconds = best_seconds(repeats, [&] {
      vector_drawing e;
      add_edge_paths(f, f.vector, e);
    });
    vector_drawing d;
    const double drawing_seconds = best_seconds(repeats, [&] { d = visible_drawing(f); });
    if (!svg_out.empty()) {
      std::ofstream s(svg_out);
      s << f.svg;
    }
    const auto j0 = clock_type::now();
    const exbsp_test::hidden_line_report r = exbsp_test::check_hidden_lines(oracle, d);
    const double judge_seconds = std::chrono::duration<double>(clock_type::now() - j0).count();
    json ex = report_json(r, summary);
    ex["seconds"] = edges_seconds;
    ex["seconds_drawing"] = drawing_seconds;
    ex["seconds_pipeline"] = pipeline_seconds;
    ex["stages"] = stage_times(log.str());
    ex["drawing"] = drawing_counts_json(d);
    out["edges_in_view"] = r.edges_in_view;
    out["exbsp"] = ex;

    json peers = json::array();
    for (std::size_t peer_index = 0; peer_index < peer_paths.size(); ++peer_index) {
      const std::string& peer_path = peer_paths[peer_index];
      std::ifstream in(peer_path);
      if (!in) throw std::runtime_error("cannot read " + peer_path);
      const json pj = json::parse(in);
      vector_drawing pd;
      pd.width = d.width;
      pd.height = d.height;
      pd.background = d.background;
      std::size_t vis_in = 0, hid_in = 0;
      vector_path hidden;
      hidden.kind = vector_path::kind_type::hidden_edge;
      hidden.color = rgb8{0, 0, 0};
      hidden.rings = peer_polylines(pj, "hidden", hid_in);
      vector_path visible;
      visible.kind = vector_path::kind_type::visible_edge;
      visible.color = rgb8{0, 0, 0};
      visible.rings = peer_polylines(pj, "visible", vis_in);
      pd.paths.push_back(std::move(hidden));  // hidden first, as visible_drawing orders them
      pd.paths.push_back(std::move(visible));
      if (peer_index < peer_svg_outs.size()) {
        std::ofstream s(peer_svg_outs[peer_index]);
        s << svg_document(pd);
      }
      const exbsp_test::hidden_line_report pr = exbsp_test::check_hidden_lines(oracle, pd);
      json pjr = report_json(pr, summary);
      pjr["drawing"] = drawing_counts_json(pd);
      pjr["polylines_in"] = {{"visible", vis_in}, {"hidden", hid_in}};
      for (const char* k : {"name", "seconds", "note"})
        if (pj.contains(k)) pjr[k] = pj[k];
      peers.push_back(pjr);
    }
    if (!peers.empty()) {
      out["peer"] = peers[0];
      out["peers"] = peers;
    }
    out["oracle_seconds"] = oracle_seconds;
    out["judge_seconds"] = judge_seconds;
    std::cout << std::setprecision(17) << out.dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "hlr_judge: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
