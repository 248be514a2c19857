// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp render`: scene (or the built-in demo) -> one soup -> the stage list of
// view/effects.h -> atomic write by the output's format (output_formats.h: PNG, SVG, PDF); with an
// orbit, one build and one run of the per-view stages per frame (notation in render.h).
#include "scene/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string_view>

#include <exbsp/core/errors.h>
#include <exbsp/view/stages.h>
#include <exbsp/view/trackball.h>
#include "scene/demo_scene.h"
#include "scene/output_formats.h"
#include "view/effects.h"
#include "view/mesh_reject.h"
#include "view/placement.h"

namespace exbsp {

namespace {

std::string seconds_text(double s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", s);
  return buf;
}

view::vector3 to_vector(const vec3d& v) { return {v[0], v[1], v[2]}; }
vec3d to_array(const view::vector3& v) { return {v.x, v.y, v.z}; }

/// Runs the stages of `p`. A usage_error from a stage is something the scene asked for that
/// cannot be done (a lens too wide for the camera, a crease angle out of range): it becomes a
/// scene_error naming the scene file. Other errors (input, output, limits) pass unchanged.
void run_stages(const view::pipeline& p, view::frame& f, std::ostream* log,
                const std::string& scene_path) {
  try {
    p.run(f, log);
  } catch (const usage_error& e) {
    throw scene_error(scene_path, "", e.what());
  }
}

/// The write stage for `path`, by the format's writer.
view::stage write_stage(const std::string& path, const output_format_row& format) {
  return {"write", [path, &format](view::frame& fr) {
            format.write(fr, path);
            return path;
          }};
}

}  // namespace

std::string frame_path(const std::string& output, std::size_t k) {
  const std::size_t slash = output.find_last_of('/');
  const std::size_t dot = output.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  char num[32];
  std::snprintf(num, sizeof num, "_%04zu", k);
  return has_ext ? output.substr(0, dot) + num + output.substr(dot) : output + num;
}

std::vector<std::array<double, 2>> resample_path(const std::vector<std::array<double, 2>>& path,
                                                 std::size_t count) {
  if (path.empty()) throw usage_error("resample_path: the path is empty");
  if (count == 0) throw usage_error("resample_path: count must be >= 1");
  std::vector<double> along(path.size(), 0.0);  // arc length at each point
  for (std::size_t i = 1; i < path.size(); ++i)
    along[i] = along[i - 1] + std::hypot(path[i][0] - path[i - 1][0], path[i][1] - path[i - 1][1]);
  const double total = along.back();
  std::vector<std::array<double, 2>> out;
  out.reserve(count);
  std::size_t seg = 1;
  for (std::size_t k = 0; k < count; ++k) {
    if (k + 1 == count && count > 1) {
      out.push_back(path.back());
      continue;
    }
    if (!(total > 0) || k == 0) {
      out.push_back(path.front());
      continue;
    }
    const double s = total * static_cast<double>(k) / static_cast<double>(count - 1);
    while (seg + 1 < path.size() && along[seg] < s) ++seg;
    const double len = along[seg] - along[seg - 1];
    const double t = len > 0 ? (s - along[seg - 1]) / len : 0.0;
    out.push_back({path[seg - 1][0] + t * (path[seg][0] - path[seg - 1][0]),
                   path[seg - 1][1] + t * (path[seg][1] - path[seg - 1][1])});
  }
  return out;
}

std::vector<std::pair<view::camera, view::vector3>> orbit_cameras(
    const scene::scene& s, const std::vector<std::array<double, 2>>& path, std::size_t frames) {
  if (path.empty()) throw usage_error("orbit: the drag path is empty");
  const std::vector<std::array<double, 2>> points =
      frames == 0 ? path : resample_path(path, frames);
  if (s.form == scene::camera_form::phigs)
    throw usage_error(
        "orbit: a phigs camera is fixed (its projection is tied to its view reference frame); "
        "use eye/look_at/up, position/look/up, polar or pilot");
  const arcball ball(s.width, s.height, screen_y::down,
                     trackball_named(s.trackball).value_or(trackball_kind::arcball));
  const std::vector<quaternion> turns = ball.drag_path(points);
  const view::camera_basis b0 = view::look_at_basis(s.camera.eye, s.camera.look_at, s.camera.up);
  const view::vector3& d = s.projection.direction;
  const double du = view::dot(d, b0.u), dv = view::dot(d, b0.v), dw = view::dot(d, b0.w);
  std::vector<std::pair<view::camera, view::vector3>> out;
  out.reserve(turns.size());
  for (const quaternion& q : turns) {
    const orbit_view o = orbit_camera(
        {view::to_vec3d(s.camera.eye), view::to_vec3d(s.camera.look_at), to_array(s.camera.up)}, q);
    view::camera c{view::to_point(o.eye), view::to_point(o.look_at), to_vector(o.up)};
    const view::camera_basis b = view::look_at_basis(c.eye, c.look_at, c.up);
    out.push_back({c, du * b.u + dv * b.v + dw * b.w});
  }
  return out;
}

render_summary render_command(const render_request& request, std::ostream& log) {
  const std::string out =
      request.output_path.empty() ? std::string("exbsp.png") : request.output_path;
  const output_format_row& format = output_format_for(out);
  const view::output_kind kind = format.product;
  const bool orbit = !request.orbit_drag.empty();
  if (!orbit && request.frames != 0) throw usage_error("render: --frames needs --orbit-drag");
  if (orbit && out == "-")
    throw usage_error("render: an orbit writes several files; it cannot go to standard output");

  const auto t0 = std::chrono::steady_clock::now();
  scene::scene s = request.preloaded ? *request.preloaded
                   : request.scene_path.empty()
                       ? scene::demo_scene()
                       : scene::load_scene(request.scene_path, &log, request.strict);
  if (!request.trackball.empty()) {
    if (!trackball_named(request.trackball))
      throw usage_error("render: --trackball must be arcball or virtual, got " + request.trackball);
    s.trackball = request.trackball;
  }
  if (!request.edges.empty()) {
    const auto edges = view::edges_kind_named(request.edges);
    if (!edges)
      throw usage_error("render: --edges must be " + view::edges_kind_names() + ", got " +
                        request.edges);
    (kind == view::output_kind::png ? s.raster_edges : s.vector).edges = *edges;
  }
  if (request.wireframe) {
    if (kind != view::output_kind::png)
      throw usage_error("render: --wireframe applies to PNG output; " + out +
                        " is already a line drawing (--edges visible+hidden)");
    s.wireframe = true;
    if (request.edges.empty())
      s.raster_edges.edges = view::vector_options::edges_kind::visible_hidden;
    if (s.raster_edges.edges == view::vector_options::edges_kind::none)
      throw usage_error("render: --wireframe needs edges (--edges none was given)");
  }
  view::frame f = scene::make_frame(s);
  if (kind != view::output_kind::png) scene::use_texture_means(f);  // flat regions (scene.h)
  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  f.build.progress = request.progress;
  f.on_stage = request.on_stage;
  if (request.tree) f.tree = *request.tree;  // shared, not copied
  if (!request.kernel.empty()) f.build.kernel = parse_kernel(request.kernel);
  f.build.max_fragments = request.max_fragments;
  f.build.keep_input = false;  // a render never saves its tree: no copy of the soup
  render_summary summary;
  summary.triangles = f.soup.triangles.size();
  const auto note_build = [&] {
    if (!f.tree) return;
    summary.fragments = f.tree->stats().fragments;
    summary.build_seconds = f.tree->stats().build_seconds;
    summary.kernel = f.tree->stats().kernel;
  };
  const auto elapsed = [&t0] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };

  for (const std::string& name : view::effects_without_stage(s.effects, kind))
    log << "exbsp: warning: " << s.path << ": /effects/" << name
        << ": applies to PNG output only; ignored for " << out << "\n";
  const bool curves = !s.curves.empty();
  view::pipeline per_view = view::per_view_pipeline(s.effects, kind, curves);
  // A PNG's edges: drawn over the finished picture (its effects included), before placement.
  const bool raster_edges = kind == view::output_kind::png &&
                            s.raster_edges.edges != view::vector_options::edges_kind::none;
  if (raster_edges) per_view.add("edges", view::raster_edges_stage);
  std::ostream* stage_log = request.verbose ? &log : nullptr;

  if (request.verbose) {
    log << "scene: " << s.path << ": " << s.meshes.size() << " meshes, " << f.soup.triangles.size()
        << " triangles, " << s.curves.size() - s.line_count << " curves, " << s.line_count
        << " lines, " << view::to_string(s.projection.kind) << " " << s.width << "x" << s.height
        << "\n";
    log << "stage load: " << seconds_text(load_seconds)
        << " s (meshes read, transformed, appended into one soup)\n";
    std::string names = request.tree ? "adopt" : orbit ? "build" : "reject, build";
    for (const std::string& n : per_view.names()) names += ", " + n;
    if (f.view.needs_placement()) names += ", place";
    log << "stages: " << names << ", write\n";
  }

  if (!orbit) {
    view::pipeline p;
    if (request.tree) {  // a saved tree: drawn as it is (no mesh is dropped before a build)
      p.add("adopt", view::adopt_tree_stage);
      for (const view::stage& st : per_view.stages()) p.add(st.name, st.run);
    } else {
      p.add("reject", view::mesh_reject_stage);
      p.add("build", view::build_stage);
      for (const view::stage& st : per_view.stages()) p.add(st.name, st.run);
    }
    if (f.view.needs_placement()) p.add("place", view::place_stage);
    const view::stage w = write_stage(out, format);
    p.add(w.name, w.run);
    run_stages(p, f, stage_log, s.path);
    summary.non_finite = f.non_finite;
    if (request.verbose)
      for (std::size_t k : f.rejected_meshes)
        log << "reject: " << s.meshes[k].key << " (" << s.meshes[k].file
            << ") is outside the view volume (bounding box): not built, not drawn\n";
    note_build();
    summary.frames = 1;
    summary.outputs.push_back(out);
    summary.total_seconds = elapsed();
    return summary;
  }

  // Orbit: build once, then the per-view stages for every frame.
  const auto cameras = orbit_cameras(s, request.orbit_drag, request.frames);
  std::vector<view::view_setup> views;
  views.reserve(cameras.size());
  for (const auto& [cam, direction] : cameras) {
    scene::scene turned = s;
    turned.camera = cam;
    turned.projection.direction = direction;
    turned.view_matrix.reset();  // polar, pilot, look: the turned camera is a gluLookAt one
    turned.form = scene::camera_form::look_at;
    views.push_back(scene::make_view_setup(turned));
  }
  if (request.verbose)
    log << "orbit: " << views.size() << " frames along a drag of " << request.orbit_drag.size()
        << " points; one BSP build, one traversal per view\n";
  view::pipeline build;
  if (request.tree)
    build.add("adopt", view::adopt_tree_stage);
  else
    build.add("build", view::build_stage);
  run_stages(build, f, stage_log, s.path);
  note_build();
  // An error at frame k removes frames 0 .. k-1 of this run: no partial output.
  struct partial_frames {
    std::vector<std::string>* written;
    bool done = false;
    ~partial_frames() {
      if (!done)
        for (const std::string& path : *written) std::remove(path.c_str());
    }
  } cleanup{&summary.outputs};
  for (std::size_t k = 0; k < views.size(); ++k) {
    f.view = views[k];
    if (request.verbose) {
      const view::point3& e = f.view.cam.eye;
      char buf[160];
      std::snprintf(buf, sizeof buf, "frame %zu: eye %.6g,%.6g,%.6g", k, e.x, e.y, e.z);
      log << buf << "\n";
    }
    view::pipeline p = per_view;
    if (f.view.needs_placement()) p.add("place", view::place_stage);
    const view::stage w = write_stage(frame_path(out, k), format);
    p.add(w.name, w.run);
    run_stages(p, f, stage_log, s.path);
    summary.non_finite = std::max(summary.non_finite, f.non_finite);
    summary.outputs.push_back(frame_path(out, k));
  }
  cleanup.done = true;
  summary.frames = views.size();
  summary.total_seconds = elapsed();
  return summary;
}

}  // namespace exbsp
