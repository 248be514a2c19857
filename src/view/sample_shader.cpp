// SPDX-License-Identifier: LGPL-3.0-or-later
// The depth plane of a window-space polygon (notation in sample_shader.h).
#include <exbsp/view/sample_shader.h>

#include <cmath>

namespace exbsp::view {

depth_plane polygon_depth_plane(const std::vector<window_point>& v) {
  depth_plane p;
  if (v.empty()) return p;
  double best = 0;
  std::size_t kb = 0;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const double det =
        (v[k].x - v[0].x) * (v[k + 1].y - v[0].y) - (v[k + 1].x - v[0].x) * (v[k].y - v[0].y);
    if (std::fabs(det) > std::fabs(best)) {
      best = det;
      kb = k;
    }
  }
  if (!(std::fabs(best) > 1e-9)) {  // edge-on: the mean depth
    for (const window_point& w : v) p.z0 += w.z;
    p.z0 /= static_cast<double>(v.size());
    return p;
  }
  const window_point &a = v[0], &b = v[kb], &c = v[kb + 1];
  // Solve zx (bx-ax) + zy (by-ay) = bz-az and zx (cx-ax) + zy (cy-ay) = cz-az (Cramer).
  p.zx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / best;
  p.zy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / best;
  p.z0 = a.z - p.zx * a.x - p.zy * a.y;
  return p;
}

}  // namespace exbsp::view
