// SPDX-License-Identifier: LGPL-3.0-or-later
// Procedural meshes (notation in procedural.h). Polygons are listed counter-clockwise seen
// from outside, so n = (b - a) x (c - a) points outward.
#include <exbsp/scene/procedural.h>

#include <cmath>

#include <exbsp/core/errors.h>

namespace exbsp::scene {

namespace {
constexpr double pi = 3.14159265358979323846;

std::uint32_t add_vertex(triangle_soup& s, double x, double y, double z) {
  s.vertices.push_back({x, y, z});
  return static_cast<std::uint32_t>(s.vertices.size() - 1);
}

void add_face(triangle_soup& s, const std::vector<std::uint32_t>& poly) {
  s.add_polygon(poly, s.face_count);
}
}  // namespace

triangle_soup make_box(const vec3d& lo, const vec3d& hi) {
  if (!(lo[0] < hi[0] && lo[1] < hi[1] && lo[2] < hi[2]))
    throw usage_error("make_box: need lo < hi");
  triangle_soup s;
  s.source = "box";
  // Vertex k has x = hi if bit 0, y = hi if bit 1, z = hi if bit 2.
  for (int k = 0; k < 8; ++k)
    add_vertex(s, k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]);
  add_face(s, {0, 2, 3, 1});  // z = lo, normal -z
  add_face(s, {4, 5, 7, 6});  // z = hi, +z
  add_face(s, {0, 1, 5, 4});  // y = lo, -y
  add_face(s, {2, 6, 7, 3});  // y = hi, +y
  add_face(s, {0, 4, 6, 2});  // x = lo, -x
  add_face(s, {1, 3, 7, 5});  // x = hi, +x
  return s;
}

triangle_soup make_prism(const std::vector<std::array<double, 2>>& outline, double z0, double z1) {
  if (outline.size() < 3 || !(z0 < z1))
    throw usage_error("make_prism: need >= 3 outline points and z0 < z1");
  triangle_soup s;
  s.source = "prism";
  const auto n = static_cast<std::uint32_t>(outline.size());
  for (const auto& p : outline) add_vertex(s, p[0], p[1], z0);
  for (const auto& p : outline) add_vertex(s, p[0], p[1], z1);
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t k = 0; k < n; ++k) {
    bottom.push_back(n - 1 - k);
    top.push_back(n + k);
  }
  add_face(s, bottom);
  add_face(s, top);
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t k1 = (k + 1) % n;
    add_face(s, {k, k1, n + k1, n + k});
  }
  return s;
}

triangle_soup make_gear(int teeth, double root_radius, double tip_radius, double bore_radius,
                        double thickness) {
  if (teeth < 3 || !(0 < bore_radius && bore_radius < root_radius && root_radius < tip_radius) ||
      !(thickness > 0))
    throw usage_error("make_gear: bad dimensions");
  triangle_soup s;
  s.source = "gear";
  // Profile: per tooth period P, root (0), tip (0.2 P), tip (0.45 P), root (0.65 P).
  const double fractions[4] = {0.0, 0.2, 0.45, 0.65};
  const double radii[4] = {root_radius, tip_radius, tip_radius, root_radius};
  std::vector<double> angle, radius;
  const double period = 2 * pi / teeth;
  for (int t = 0; t < teeth; ++t)
    for (int k = 0; k < 4; ++k) {
      angle.push_back((t + fractions[k]) * period);
      radius.push_back(radii[k]);
    }
  const auto m = static_cast<std::uint32_t>(angle.size());
  const double z0 = -thickness / 2, z1 = thickness / 2;
  // Vertex blocks: outer bottom, outer top, bore bottom, bore top.
  for (double z : {z0, z1})
    for (std::uint32_t i = 0; i < m; ++i)
      add_vertex(s, radius[i] * std::cos(angle[i]), radius[i] * std::sin(angle[i]), z);
  for (double z : {z0, z1})
    for (std::uint32_t i = 0; i < m; ++i)
      add_vertex(s, bore_radius * std::cos(angle[i]), bore_radius * std::sin(angle[i]), z);
  auto ob = [&](std::uint32_t i) { return i % m; };
  auto ot = [&](std::uint32_t i) { return m + i % m; };
  auto bb = [&](std::uint32_t i) { return 2 * m + i % m; };
  auto bt = [&](std::uint32_t i) { return 3 * m + i % m; };
  for (std::uint32_t i = 0; i < m; ++i) {
    add_face(s, {bt(i), ot(i), ot(i + 1), bt(i + 1)});  // top ring, +z
    add_face(s, {bb(i), bb(i + 1), ob(i + 1), ob(i)});  // bottom ring, -z
    add_face(s, {ob(i), ob(i + 1), ot(i + 1), ot(i)});  // outer wall, outward
    add_face(s, {bb(i + 1), bb(i), bt(i), bt(i + 1)});  // bore wall, towards the axis
  }
  return s;
}

triangle_soup make_cyclic_planks(double offset, double half_length, double width, double slope) {
  triangle_soup s;
  s.source = "cyclic planks";
  for (int i = 0; i < 3; ++i) {
    const double a = i * (2 * pi / 3);
    const double ux = std::cos(a), uy = std::sin(a);    // along the plank
    const double nx = -uy, ny = ux;                     // across, u x n = +z
    const double cx = -offset * nx, cy = -offset * ny;  // foot of the centre line
    std::vector<std::uint32_t> quad;
    for (const auto& [t, w] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
      const double tt = t * half_length, ww = w * width / 2;
      quad.push_back(add_vertex(s, cx + tt * ux + ww * nx, cy + tt * uy + ww * ny, slope * tt));
    }
    add_face(s, quad);
  }
  return s;
}

}  // namespace exbsp::scene
