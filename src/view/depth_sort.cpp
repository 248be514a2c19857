// SPDX-License-Identifier: LGPL-3.0-or-later
// The depth-sort painter's order (notation in depth_sort.h).
#include "view/depth_sort.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include <exbsp/core/errors.h>

namespace exbsp::view {

std::vector<fragment_d> soup_fragments(const triangle_soup& soup) {
  std::vector<fragment_d> out;
  out.reserve(soup.triangles.size());
  for (const soup_triangle& t : soup.triangles)
    out.push_back({t.face, {soup.vertices[t.v[0]], soup.vertices[t.v[1]], soup.vertices[t.v[2]]}});
  return out;
}

double view_depth(const view_setup& view, const vec3d& p) {
  if (view.is_parallel()) {
    const vector3& d = view.direction;
    return p[0] * d.x + p[1] * d.y + p[2] * d.z;
  }
  return -(view.model_view * to_point(p)).z;
}

std::vector<std::uint32_t> depth_sorted_order(const std::vector<fragment_d>& fragments,
                                              const view_setup& view, visibility_order key) {
  if (key == visibility_order::bsp)
    throw usage_error("depth_sorted_order: the bsp order is the tree's, not a depth sort");
  std::vector<std::pair<double, std::uint32_t>> keyed;  // (sort key, fragment index)
  std::vector<std::uint32_t> last;                      // non-finite corners
  keyed.reserve(fragments.size());
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    const fragment_d& fr = fragments[i];
    const auto index = static_cast<std::uint32_t>(i);
    if (!fr.finite()) {
      last.push_back(index);
      continue;
    }
    const double d0 = view_depth(view, fr.v[0]), d1 = view_depth(view, fr.v[1]),
                 d2 = view_depth(view, fr.v[2]);
    const double k =
        key == visibility_order::depth_sort_farthest ? std::max({d0, d1, d2}) : (d0 + d1 + d2) / 3;
    keyed.push_back({k, index});
  }
  // Farthest first; a stable sort on the key alone keeps equal keys in index order.
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::uint32_t> order;
  order.reserve(fragments.size());
  for (const auto& [k, index] : keyed) order.push_back(index);
  order.insert(order.end(), last.begin(), last.end());
  return order;
}

}  // namespace exbsp::view
