// SPDX-License-Identifier: LGPL-3.0-or-later
// The built-in demo scene. World frame: z up; the parts sit side by side along x.
//
// Colours are per mesh and drawn unlit (docs/contract.md "Scenes"), so to make the solids readable
// the demo bakes a fixed shading into its meshes: each part is split into one mesh per
// distinct shade of its faces, shade = base colour * (0.5 + 0.5 |n . L|) for the world-space
// unit normal n and a fixed light direction L. All of them still go into the one BSP.
#include "scene/demo_scene.h"

#include <cmath>
#include <map>
#include <memory>
#include <tuple>

#include <exbsp/scene/procedural.h>
#include <exbsp/view/transforms.h>

namespace exbsp::scene {

namespace {
constexpr double pi = 3.14159265358979323846;

/// Adds `local` transformed by `transform` (rotations and translations only) as one mesh per
/// baked shade of `base`.
void add_shaded(scene& s, const std::string& name, const triangle_soup& local, view::rgb8 base,
                const view::mat4& transform) {
  const view::vector3 light = view::normalized({-0.35, -0.55, 0.75});
  std::map<std::tuple<int, int, int>, triangle_soup> parts;
  std::map<std::pair<std::tuple<int, int, int>, std::uint32_t>, std::uint32_t> face_ids;
  for (const soup_triangle& t : local.triangles) {
    const view::point3 a = view::to_point(local.vertices[t.v[0]]),
                       b = view::to_point(local.vertices[t.v[1]]),
                       c = view::to_point(local.vertices[t.v[2]]);
    const view::vector3 n_local = view::cross(b - a, c - a);
    if (!(view::length(n_local) > 0)) continue;
    const view::vector3 n = view::normalized(view::transform_vector(transform, n_local));
    const double k = 0.5 + 0.5 * std::fabs(view::dot(n, light));
    const std::tuple<int, int, int> key{static_cast<int>(std::lround(base.r * k)),
                                        static_cast<int>(std::lround(base.g * k)),
                                        static_cast<int>(std::lround(base.b * k))};
    triangle_soup& part = parts[key];
    const auto [it, inserted] = face_ids.try_emplace({key, t.face}, part.face_count);
    const auto v0 = static_cast<std::uint32_t>(part.vertices.size());
    for (int i = 0; i < 3; ++i) part.vertices.push_back(local.vertices[t.v[i]]);
    part.add_polygon({v0, v0 + 1, v0 + 2}, it->second);
  }
  for (auto& [key, part] : parts) {
    mesh_spec m;
    m.file = name;
    m.path = "(built-in) " + name;
    m.key = "/meshes/" + std::to_string(s.meshes.size());
    m.color = {static_cast<std::uint8_t>(std::get<0>(key)),
               static_cast<std::uint8_t>(std::get<1>(key)),
               static_cast<std::uint8_t>(std::get<2>(key))};
    m.transform = transform;
    part.source = name;
    m.soup = std::make_shared<const triangle_soup>(std::move(part));
    s.meshes.push_back(std::move(m));
  }
}

std::vector<std::array<double, 2>> hexagon(double r) {
  std::vector<std::array<double, 2>> h;
  for (int k = 0; k < 6; ++k) h.push_back({r * std::cos(k * pi / 3), r * std::sin(k * pi / 3)});
  return h;
}
}  // namespace

scene demo_scene() {
  using view::rotate;
  using view::translate;
  scene s;
  s.path = "(built-in demo)";
  // Intersecting parts: a cube pierced by a tilted slab.
  add_shaded(s, "cube", make_box({-1, -1, -1}, {1, 1, 1}), {220, 70, 60},
             translate({-4.6, 0.6, 1.0}) * rotate(25, {0, 0, 1}));
  add_shaded(s, "slab", make_box({-2.1, -0.3, -0.5}, {2.1, 0.3, 0.5}), {70, 130, 220},
             translate({-4.6, 0.6, 1.1}) * rotate(-40, {0, 0, 1}) * rotate(20, {1, 0, 0}) *
                 rotate(15, {0, 1, 0}));
  // Cyclic overlap: three planks, each over the next where they cross; one colour each.
  const triangle_soup planks = make_cyclic_planks(0.75, 2.1, 0.6, 0.25);
  const view::rgb8 plank_colors[3] = {{240, 190, 60}, {235, 125, 45}, {150, 95, 200}};
  for (std::uint32_t k = 0; k < 3; ++k) {
    triangle_soup one;
    one.vertices = planks.vertices;
    for (const soup_triangle& t : planks.triangles)
      if (t.face == k) one.add_polygon({t.v[0], t.v[1], t.v[2]}, 0);
    add_shaded(s, "plank " + std::to_string(k), one, plank_colors[k], translate({0.0, 0.2, 0.8}));
  }
  // A CAD-style part: a gear with a bore on a hexagonal shaft. Only rotations about z and
  // translations here: they keep the gear's coplanar faces exactly coplanar in double, so the
  // BSP needs no splits for them (a tilt would round each face onto its own plane).
  const view::mat4 gear_frame = translate({4.6, 0.4, 0.9});
  add_shaded(s, "gear", make_gear(12, 1.25, 1.6, 0.5, 0.4), {150, 160, 175},
             gear_frame * rotate(7, {0, 0, 1}));
  add_shaded(s, "shaft", make_prism(hexagon(0.36), -1.1, 1.2), {60, 170, 100}, gear_frame);
  s.camera = {{0.0, -8.5, 11.0}, {0.0, 0.6, 0.5}, {0, 0, 1}};
  s.projection.kind = view::projection_kind::perspective;
  s.projection.fovy_deg = 42;
  s.projection.near_dist = 1;
  s.projection.far_dist = 100;
  s.width = 800;
  s.height = 600;
  s.background = {242, 244, 248};
  return s;
}

}  // namespace exbsp::scene
