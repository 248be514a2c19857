// SPDX-License-Identifier: LGPL-3.0-or-later
// Flat Lambert shading (notation in lighting.h).
#include "view/lighting.h"

#include "view/smooth_shading.h"

#include <algorithm>
#include <cmath>

namespace exbsp::view {

namespace {
std::uint8_t scale_channel(std::uint8_t c, double k) {
  return static_cast<std::uint8_t>(std::lround(std::min(255.0, std::max(0.0, c * k))));
}
}  // namespace

rgb8 lambert_color(rgb8 base, const vector3& unit_normal, const lighting_settings& s) {
  const vector3 l = normalized(s.direction);
  const double k = s.ambient + s.intensity * std::max(0.0, dot(unit_normal, l));
  return {scale_channel(base.r, k), scale_channel(base.g, k), scale_channel(base.b, k)};
}

rgb8 lit_color(rgb8 base, const vector3& n, const point3& centroid, const view_setup& view,
               const lighting_settings& s) {
  if (!s.headlight && s.specular == 0 && s.lights.empty()) return lambert_color(base, n, s);
  const vector3 to_eye = view.is_parallel() ? -view.direction : view.cam.eye - centroid;
  const vector3 v = length(to_eye) > 0 ? normalized(to_eye) : vector3{0, 0, 0};
  double diffuse = s.ambient, highlight = 0;
  const auto add = [&](const vector3& l, double intensity) {
    const double nl = dot(n, l);
    if (!(nl > 0)) return;
    diffuse += intensity * nl;
    if (s.specular > 0) {
      const vector3 h = l + v;
      if (length(h) > 0)
        highlight +=
            intensity * s.specular * std::pow(std::max(0.0, dot(n, normalized(h))), s.shininess);
    }
  };
  add(s.headlight ? v : normalized(s.direction), s.intensity);
  for (const light_source& light : s.lights) {
    vector3 l = v;
    if (light.kind == light_source::kind_type::directional) l = normalized(light.where);
    if (light.kind == light_source::kind_type::point) {
      const vector3 d = point3{light.where.x, light.where.y, light.where.z} - centroid;
      if (!(length(d) > 0)) continue;  // a point light at the face's centroid: no direction
      l = normalized(d);
    }
    add(l, light.intensity);
  }
  const auto channel = [&](std::uint8_t c) {
    return static_cast<std::uint8_t>(
        std::lround(std::min(255.0, std::max(0.0, c * diffuse + 255 * highlight))));
  };
  return {channel(base.r), channel(base.g), channel(base.b)};
}

vector3 shading_normal(const fragment_d& fr, const view_setup& view, bool two_sided) {
  const point3 a = to_point(fr.v[0]), b = to_point(fr.v[1]), c = to_point(fr.v[2]);
  const vector3 n = cross(b - a, c - a);
  const double len = length(n);
  if (!(len > 0) || !std::isfinite(len)) return {0, 0, 0};
  vector3 unit = (1.0 / len) * n;
  if (two_sided) {
    const vector3 v = view.is_parallel() ? -view.direction : view.cam.eye - a;
    if (dot(unit, v) < 0) unit = -unit;
  }
  return unit;
}

std::string lighting_stage(frame& f) {
  const lighting_settings& s = f.settings.lighting;
  normalized(s.direction);  // throws usage_error for a zero or non-finite direction
  for (const light_source& light : s.lights)
    if (light.kind == light_source::kind_type::directional) normalized(light.where);
  // A headlight, a point light and the highlights depend on where the face is: its centroid
  // (the mean of its triangles' centroids in the input), so that every piece of a face gets
  // the face's colour and the picture does not show where the tree split it.
  std::vector<point3> face_centroid;  // sums of the triangles' centroids, then their means
  std::vector<std::uint32_t> triangles_of_face;
  if (s.headlight || s.specular > 0 || !s.lights.empty()) {
    for (const soup_triangle& t : f.soup.triangles) {
      if (t.face >= face_centroid.size()) {
        face_centroid.resize(t.face + 1);
        triangles_of_face.resize(t.face + 1);
      }
      point3& c = face_centroid[t.face];
      for (int corner = 0; corner < 3; ++corner) {
        const vec3d& p = f.soup.vertices[t.v[corner]];
        c = {c.x + p[0] / 3, c.y + p[1] / 3, c.z + p[2] / 3};
      }
      ++triangles_of_face[t.face];
    }
    for (std::size_t face = 0; face < face_centroid.size(); ++face)
      if (triangles_of_face[face] > 0) {
        const double k = 1.0 / triangles_of_face[face];
        const point3& c = face_centroid[face];
        face_centroid[face] = {c.x * k, c.y * k, c.z * k};
      }
  }
  f.fragment_colors.assign(f.fragments.size(), rgb8{});
  for (std::uint32_t idx : f.order) {
    const fragment_d& fr = f.fragments.at(idx);
    const point3 centroid = fr.face < face_centroid.size() && triangles_of_face[fr.face] > 0
                                ? face_centroid[fr.face]
                                : point3{(fr.v[0][0] + fr.v[1][0] + fr.v[2][0]) / 3,
                                         (fr.v[0][1] + fr.v[1][1] + fr.v[2][1]) / 3,
                                         (fr.v[0][2] + fr.v[1][2] + fr.v[2][2]) / 3};
    f.fragment_colors[idx] = lit_color(f.color_of(fr.face), shading_normal(fr, f.view, s.two_sided),
                                       centroid, f.view, s);
  }
  if (s.smooth) smooth_corner_colors(f);
  return std::to_string(f.order.size()) + " fragments lit, " + (s.smooth ? "smooth, " : "") +
         (s.two_sided ? "two-sided" : "one-sided") +
         (s.lights.empty() ? "" : ", " + std::to_string(1 + s.lights.size()) + " lights") +
         (s.headlight ? ", headlight" : "") + (s.specular > 0 ? ", specular" : "");
}

}  // namespace exbsp::view
