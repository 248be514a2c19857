// SPDX-License-Identifier: LGPL-3.0-or-later
// What the views of one soup share and need not make again: its edge graph (feature_edges.h)
// and which of its meshes are outward closed (closed_shells.h). A CAD viewer draws the same
// soup from many views; each product is made again only when the soup (compared byte for byte
// with a kept copy) or the product's own parameter differs from the one it was made from.
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>
#include "geom/feature_edges.h"

namespace exbsp::geom {

/// The kept products of one soup. Thread-safe; the products are made independently (a thread
/// making the edge graph does not hold up one asking for the closed meshes).
class soup_cache {
 public:
  /// edge_graph_of(soup, crease_deg), kept.
  EXBSP_EXPORT std::shared_ptr<const edge_graph> edge_graph_for(const triangle_soup& soup,
                                                                double crease_deg);
  /// outward_closed_meshes(soup, mesh_face_offsets), kept.
  EXBSP_EXPORT std::shared_ptr<const std::vector<std::uint8_t>> outward_closed_for(
      const triangle_soup& soup, const std::vector<std::uint32_t>& mesh_face_offsets);

 private:
  /// The generation of `soup`: the kept copy's, or a new one (and a new copy) when it differs.
  std::uint64_t generation_of(const triangle_soup& soup);

  std::mutex soup_mutex_;
  std::vector<vec3d> vertices_;
  std::vector<soup_triangle> triangles_;
  std::uint64_t generation_ = 0;  ///< 0: no soup kept yet

  std::mutex graph_mutex_;
  std::uint64_t graph_generation_ = 0;
  std::shared_ptr<const edge_graph> graph_;

  std::mutex shells_mutex_;
  std::uint64_t shells_generation_ = 0;
  std::vector<std::uint32_t> shells_offsets_;
  std::shared_ptr<const std::vector<std::uint8_t>> shells_;
};

}  // namespace exbsp::geom
