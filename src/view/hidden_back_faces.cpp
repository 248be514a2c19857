// SPDX-License-Identifier: LGPL-3.0-or-later
// Back faces of outward-closed meshes (notation in hidden_back_faces.h).
#include "view/hidden_back_faces.h"

#include <algorithm>

#include "geom/feature_edges.h"
#include "view/edge_visibility.h"
#include "view/workers.h"

namespace exbsp::view {

bool may_leave_out_back_faces(const frame& f) {
  return f.visibility == visibility_order::bsp &&
         std::any_of(f.meshes_whole.begin(), f.meshes_whole.end(),
                     [](std::uint8_t whole) { return whole != 0; });
}

std::vector<std::uint8_t> hidden_back_faces(const frame& f,
                                            const std::vector<std::uint8_t>& outward_closed,
                                            unsigned workers) {
  if (!may_leave_out_back_faces(f)) return {};
  std::vector<std::uint8_t> candidate(outward_closed.size(), 0);  // per mesh
  bool any = false;
  for (std::size_t m = 0; m < candidate.size() && m < f.meshes_whole.size(); ++m) {
    candidate[m] = outward_closed[m] && f.meshes_whole[m];
    any = any || candidate[m];
  }
  if (!any) return {};
  const triangle_soup& s = f.soup;
  const std::size_t n = s.triangles.size();
  // Per triangle of a candidate mesh: 1 when it faces away from the viewer (exact).
  std::vector<std::uint8_t> away(n, 0);
  const geom::hpoint viewer = viewer_of(f);
  constexpr std::size_t block = 4096;
  parallel_for((n + block - 1) / block, workers, [&](std::size_t b, unsigned) {
    for (std::size_t t = b * block; t < std::min(n, (b + 1) * block); ++t) {
      const soup_triangle& tri = s.triangles[t];
      const std::uint32_t mesh = f.mesh_of(tri.face);
      if (mesh >= candidate.size() || !candidate[mesh]) continue;
      away[t] = geom::facing_filtered(s.vertices[tri.v[0]], s.vertices[tri.v[1]],
                                      s.vertices[tri.v[2]], viewer) < 0;
    }
  });
  std::uint32_t faces = 0;
  for (const soup_triangle& tri : s.triangles) faces = std::max(faces, tri.face + 1);
  // Per face: 0 no triangle yet, 1 all facing away so far, 2 some triangle does not.
  std::vector<std::uint8_t> state(faces, 0);
  for (std::size_t t = 0; t < n; ++t) {
    std::uint8_t& st = state[s.triangles[t].face];
    st = away[t] && st != 2 ? 1 : 2;
  }
  for (std::uint8_t& st : state) st = st == 1;
  return state;
}

}  // namespace exbsp::view
