// SPDX-License-Identifier: LGPL-3.0-or-later
#include "geom/weld.h"

#include <functional>
#include <unordered_map>

namespace exbsp::geom {

namespace {
struct position_hash {
  std::size_t operator()(const vec3d& v) const {
    std::size_t h = 0;
    for (double c : v) h = h * 1000003u ^ std::hash<double>()(c == 0 ? 0.0 : c);  // -0 == +0
    return h;
  }
};
}  // namespace

welded_ids weld(const std::vector<vec3d>& points) {
  std::unordered_map<vec3d, std::uint32_t, position_hash> first;  // operator== welds -0, +0
  first.reserve(points.size());
  welded_ids w;
  w.id.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    w.id[i] = first.emplace(points[i], static_cast<std::uint32_t>(first.size())).first->second;
  w.count = static_cast<std::uint32_t>(first.size());
  return w;
}

}  // namespace exbsp::geom
