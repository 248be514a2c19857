// SPDX-License-Identifier: LGPL-3.0-or-later
#include "geom/soup_cache.h"

#include <cstring>

#include "geom/closed_shells.h"

namespace exbsp::geom {

// The byte comparison below needs types without padding.
static_assert(sizeof(vec3d) == 3 * sizeof(double));
static_assert(sizeof(soup_triangle) == 4 * sizeof(std::uint32_t));

std::uint64_t soup_cache::generation_of(const triangle_soup& soup) {
  const std::lock_guard<std::mutex> lock(soup_mutex_);
  // Byte for byte: a vertex's -0.0 and 0.0 differ here (new products, the same results).
  const bool same =
      generation_ != 0 && vertices_.size() == soup.vertices.size() &&
      triangles_.size() == soup.triangles.size() &&
      (vertices_.empty() || std::memcmp(vertices_.data(), soup.vertices.data(),
                                        vertices_.size() * sizeof(vec3d)) == 0) &&
      (triangles_.empty() || std::memcmp(triangles_.data(), soup.triangles.data(),
                                         triangles_.size() * sizeof(soup_triangle)) == 0);
  if (!same) {
    vertices_ = soup.vertices;
    triangles_ = soup.triangles;
    ++generation_;
  }
  return generation_;
}

std::shared_ptr<const edge_graph> soup_cache::edge_graph_for(const triangle_soup& soup,
                                                             double crease_deg) {
  const std::uint64_t generation = generation_of(soup);
  const std::lock_guard<std::mutex> lock(graph_mutex_);
  if (!graph_ || graph_generation_ != generation || graph_->crease_deg != crease_deg) {
    graph_ = std::make_shared<const edge_graph>(edge_graph_of(soup, crease_deg));
    graph_generation_ = generation;
  }
  return graph_;
}

std::shared_ptr<const std::vector<std::uint8_t>> soup_cache::outward_closed_for(
    const triangle_soup& soup, const std::vector<std::uint32_t>& mesh_face_offsets) {
  const std::uint64_t generation = generation_of(soup);
  const std::lock_guard<std::mutex> lock(shells_mutex_);
  if (!shells_ || shells_generation_ != generation || shells_offsets_ != mesh_face_offsets) {
    shells_ = std::make_shared<const std::vector<std::uint8_t>>(
        outward_closed_meshes(soup, mesh_face_offsets));
    shells_generation_ = generation;
    shells_offsets_ = mesh_face_offsets;
  }
  return shells_;
}

}  // namespace exbsp::geom
