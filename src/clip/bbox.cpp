// SPDX-License-Identifier: LGPL-3.0-or-later
// Bounding boxes (see bbox.h). `b` is the box being grown, one point after the other.
#include <exbsp/clip/bbox.h>

#include <cstddef>

#include "clip/clip_checks.h"

namespace exbsp::clip {
namespace {

template <std::size_t N, class Points>
box<N> bounding_box_n(const Points& points) {
  if (points.begin() == points.end()) throw usage_error("bounding_box: no points");
  box<N> b{*points.begin(), *points.begin()};
  for (const auto& p : points) {
    detail::require_finite(p, "bounding_box", "point");
    for (std::size_t k = 0; k < N; ++k) {
      if (p[k] < b.min[k]) b.min[k] = p[k];
      if (p[k] > b.max[k]) b.max[k] = p[k];
    }
  }
  return b;
}

template <std::size_t N>
bool overlap_n(const box<N>& a, const box<N>& b) {
  for (std::size_t k = 0; k < N; ++k)
    if (!(a.min[k] <= b.max[k] && b.min[k] <= a.max[k])) return false;
  return true;
}

}  // namespace

box2 bounding_box(const std::vector<vec2d>& points) { return bounding_box_n<2>(points); }
box3 bounding_box(const std::vector<vec3d>& points) { return bounding_box_n<3>(points); }
box2 bounding_box(const std::array<vec2d, 3>& triangle) { return bounding_box_n<2>(triangle); }
box3 bounding_box(const std::array<vec3d, 3>& triangle) { return bounding_box_n<3>(triangle); }

bool boxes_overlap(const box2& a, const box2& b) { return overlap_n(a, b); }
bool boxes_overlap(const box3& a, const box3& b) { return overlap_n(a, b); }

bool triangle_outside_window(const std::array<vec2d, 3>& triangle, const window2& window) {
  return !boxes_overlap(bounding_box(triangle), window);
}

std::array<vec3d, 8> box_corners(const box3& box) {
  std::array<vec3d, 8> out;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k) out[i][k] = (i >> k) & 1u ? box.max[k] : box.min[k];
  return out;
}

}  // namespace exbsp::clip
