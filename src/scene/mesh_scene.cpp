// SPDX-License-Identifier: LGPL-3.0-or-later
// A scene for one bare mesh with a fitted view (notation in mesh_scene.h). The scene is
// written as a JSON document and validated by parse_scene, so a fitted scene obeys exactly
// the rules of a scene file; the already-read soup is then attached (the file is not read
// twice).
#include "scene/mesh_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include <exbsp/core/errors.h>
#include <exbsp/view/matrix.h>

namespace exbsp::scene {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double fovy_deg = 30;
/// The bounding sphere fills 1 / margin of the smaller field of view: a little air around the mesh.
constexpr double margin = 1.08;

struct named_view {
  const char* name;
  view::vector3 towards_eye;  ///< from the centre towards the eye (any length)
  view::vector3 up;
};

constexpr named_view views[] = {
    {"iso", {1, 1, 1}, {0, 1, 0}},     {"front", {0, 0, 1}, {0, 1, 0}},
    {"back", {0, 0, -1}, {0, 1, 0}},   {"left", {-1, 0, 0}, {0, 1, 0}},
    {"right", {1, 0, 0}, {0, 1, 0}},   {"top", {0, 1, 0}, {0, 0, -1}},
    {"bottom", {0, -1, 0}, {0, 0, 1}},
};

/// A JSON triple of the scene document.
std::array<double, 3> triple(const view::vector3& v) { return {v.x, v.y, v.z}; }

}  // namespace

const std::vector<std::string>& mesh_view_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const named_view& v : views) n.emplace_back(v.name);
    return n;
  }();
  return names;
}

scene mesh_scene(std::shared_ptr<const triangle_soup> soup, const std::string& name,
                 const mesh_view_options& options) {
  const named_view* chosen = nullptr;
  for (const named_view& v : views)
    if (options.view == v.name) chosen = &v;
  if (!chosen)
    throw usage_error("--view: unknown view '" + options.view +
                      "' (expected iso, front, back, left, right, top or bottom)");
  if (options.width < 1 || options.width > 16384 || options.height < 1 || options.height > 16384)
    throw usage_error("--size: width and height must be in 1..16384");
  if (!soup || soup->triangles.empty())
    throw input_error(name, 0, "the mesh has no triangle to render");

  // Bounding box of the vertices the triangles use (a stray unused vertex does not move the view).
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const soup_triangle& t : soup->triangles)
    for (std::uint32_t i : t.v)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], soup->vertices[i][k]);
        hi[k] = std::max(hi[k], soup->vertices[i][k]);
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

  const double aspect = static_cast<double>(options.width) / options.height;
  const double half_fovy = fovy_deg * pi / 360;
  const double half_fov = std::min(half_fovy, std::atan(std::tan(half_fovy) * aspect));
  const double distance = margin * radius / std::sin(half_fov);
  const view::vector3 w = view::normalized(chosen->towards_eye);
  std::array<double, 3> eye{};
  for (int k = 0; k < 3; ++k) eye[k] = centre[k] + distance * triple(w)[k];
  const double near_dist = distance - 1.01 * radius, far_dist = distance + 1.01 * radius;
  const bool finite =
      std::isfinite(distance) && std::isfinite(far_dist) && near_dist > 0 &&
      std::all_of(eye.begin(), eye.end(), [](double x) { return std::isfinite(x); });
  if (!finite)
    throw input_error(name, 0, "the mesh's coordinates are too large to fit a view in double");

  // Light over the viewer's left shoulder: towards the eye, up and to the left.
  const view::vector3 right = view::normalized(view::cross(chosen->up, w));
  const view::vector3 light = w + 0.6 * chosen->up - 0.4 * right;

  const nlohmann::json doc = {
      {"meshes", {{{"file", name}, {"color", {176, 190, 214}}}}},
      {"camera", {{"eye", eye}, {"look_at", centre}, {"up", triple(chosen->up)}}},
      {"projection",
       {{"type", "perspective"}, {"fovy_deg", fovy_deg}, {"near", near_dist}, {"far", far_dist}}},
      {"viewport", {{"width", options.width}, {"height", options.height}}},
      {"background", {250, 250, 252}},
      {"effects",
       {{"lighting", {{"direction", triple(light)}, {"ambient", 0.3}, {"intensity", 0.7}}}}},
      {"svg", {{"edges", options.edges}}},
  };
  scene s = parse_scene(doc, name, nullptr, true);
  s.meshes.at(0).soup = std::move(soup);
  return s;
}

}  // namespace exbsp::scene
