// SPDX-License-Identifier: LGPL-3.0-or-later
// Backface culling: N = (b - a) x (c - a), V towards the viewer, cull when N . V <= 0
// (notation in backface_culling.h).
#include "view/backface_culling.h"

namespace exbsp::view {

bool is_back_facing(const fragment_d& fr, const view_setup& view) {
  const point3 a = to_point(fr.v[0]), b = to_point(fr.v[1]), c = to_point(fr.v[2]);
  const vector3 n = cross(b - a, c - a);
  const vector3 v = view.is_parallel() ? -view.direction : view.cam.eye - a;
  return !(dot(n, v) > 0);
}

std::string backface_culling_stage(frame& f) {
  std::size_t kept = 0;
  for (std::uint32_t idx : f.order)
    if (!is_back_facing(f.fragments.at(idx), f.view)) f.order[kept++] = idx;
  f.culled = f.order.size() - kept;
  f.order.resize(kept);
  return std::to_string(f.culled) + " culled, " + std::to_string(kept) + " kept";
}

}  // namespace exbsp::view
