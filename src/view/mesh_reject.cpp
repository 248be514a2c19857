// SPDX-License-Identifier: LGPL-3.0-or-later
// Bounding-box trivial reject of whole meshes (notation in mesh_reject.h).
#include "view/mesh_reject.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <exbsp/clip/bbox.h>
#include <exbsp/clip/homogeneous.h>

namespace exbsp::view {

std::string mesh_reject_stage(frame& f) {
  f.rejected_meshes.clear();
  const std::vector<std::uint32_t>& off = f.mesh_face_offsets;
  if (off.size() < 2) return "no mesh ranges";
  const mat4 pm = f.view.projection * f.view.model_view;
  const std::size_t meshes = off.size() - 1;
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<clip::box3> boxes(meshes, clip::box3{{inf, inf, inf}, {-inf, -inf, -inf}});
  auto mesh_of = [&](std::uint32_t face) {
    return static_cast<std::size_t>(std::upper_bound(off.begin(), off.end(), face) - off.begin()) -
           1;
  };
  for (const soup_triangle& t : f.soup.triangles) {
    const std::size_t k = mesh_of(t.face);
    if (k >= meshes) continue;
    for (std::uint32_t vi : t.v)
      for (int a = 0; a < 3; ++a) {
        const double x = f.soup.vertices[vi][a];
        boxes[k].min[a] = std::min(boxes[k].min[a], x);
        boxes[k].max[a] = std::max(boxes[k].max[a], x);
      }
  }
  std::vector<bool> reject(meshes, false);
  for (std::size_t k = 0; k < meshes; ++k) {
    if (!(boxes[k].min[0] <= boxes[k].max[0])) continue;  // no triangles
    std::vector<clip::vec4d> corners;
    for (const clip::vec3d& c : clip::box_corners(boxes[k])) {
      const hpoint h = pm * point3{c[0], c[1], c[2]};
      corners.push_back({h.x, h.y, h.z, h.w});
    }
    reject[k] = clip::homogeneous_trivially_rejected(corners);
    if (reject[k]) f.rejected_meshes.push_back(k);
  }
  if (f.rejected_meshes.empty())
    return "0 of " + std::to_string(meshes) + " meshes outside the view volume";
  const std::size_t before = f.soup.triangles.size();
  const auto rejected = [&](const soup_triangle& t) {
    const std::size_t k = mesh_of(t.face);
    return k < meshes && reject[k];
  };
  if (f.soup.has_uvs()) {  // the texture coordinates stay with their triangles
    std::size_t kept = 0;
    for (std::size_t t = 0; t < before; ++t)
      if (!rejected(f.soup.triangles[t])) f.soup.triangle_uvs[kept++] = f.soup.triangle_uvs[t];
    f.soup.triangle_uvs.resize(kept);
  }
  f.soup.triangles.erase(std::remove_if(f.soup.triangles.begin(), f.soup.triangles.end(), rejected),
                         f.soup.triangles.end());
  std::string list;
  for (std::size_t k : f.rejected_meshes) list += (list.empty() ? "" : ", ") + std::to_string(k);
  return std::to_string(f.rejected_meshes.size()) + " of " + std::to_string(meshes) +
         " meshes outside the view volume, rejected by their bounding boxes before the BSP build "
         "(mesh " +
         list + "; " + std::to_string(before - f.soup.triangles.size()) + " triangles)";
}

}  // namespace exbsp::view
