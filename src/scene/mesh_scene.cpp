// SPDX-License-Identifier: LGPL-3.0-or-later
// A scene for one bare mesh with a fitted view (view::fit_view, <exbsp/view/render.h>). The scene
// is written as a JSON document and validated by parse_scene, so a fitted scene obeys exactly the
// rules of a scene file; the already-read soup is then attached (the file is not read twice).
#include "scene/mesh_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include <exbsp/core/errors.h>
#include <exbsp/view/matrix.h>
#include "view/fitted_view.h"

namespace exbsp::scene {

namespace {

/// A JSON triple of the scene document.
std::array<double, 3> triple(const view::vector3& v) { return {v.x, v.y, v.z}; }
std::array<double, 3> triple(const view::point3& p) { return {p.x, p.y, p.z}; }

}  // namespace

const std::vector<std::string>& mesh_view_names() { return view::fitted_view_names(); }

scene mesh_scene(std::shared_ptr<const triangle_soup> soup, const std::string& name,
                 const mesh_view_options& options) {
  if (!soup) throw input_error(name, 0, "the mesh has no triangle to render");
  // Checks the view's name, the size and that there is a triangle (messages naming the options).
  const view::fitted_view v = view::fit_view_of(*soup, options.width, options.height, options.view,
                                                name, "--view", "--size");
  const nlohmann::json doc = {
      {"meshes", {{{"file", name}, {"color", {176, 190, 214}}}}},
      {"camera",
       {{"eye", triple(v.cam.eye)}, {"look_at", triple(v.cam.look_at)}, {"up", triple(v.cam.up)}}},
      {"projection",
       {{"type", "perspective"},
        {"fovy_deg", v.fovy_deg},
        {"near", v.near_dist},
        {"far", v.far_dist}}},
      {"viewport", {{"width", options.width}, {"height", options.height}}},
      {"background", {250, 250, 252}},
      {"effects",
       {{"lighting", {{"direction", triple(v.light)}, {"ambient", 0.3}, {"intensity", 0.7}}}}},
      {"svg", {{"edges", options.edges}}},
  };
  scene s = parse_scene(doc, name, nullptr, true);
  s.meshes.at(0).soup = std::move(soup);
  return s;
}

}  // namespace exbsp::scene
