// SPDX-License-Identifier: LGPL-3.0-or-later
// One welder for every module that needs a vertex's identity by position.
//
// Policy: two vertices are the same when their coordinates compare equal as doubles, so -0.0
// and +0.0 weld (they are the same point); coordinates are never rounded or snapped. NaN never
// reaches here (the readers refuse it).
#pragma once
#include <cstdint>
#include <vector>

#include <exbsp/mesh/soup.h>

namespace exbsp::geom {

/// The welded id of each point (0, 1, 2, ... in order of first appearance) and the count.
struct welded_ids {
  std::vector<std::uint32_t> id;
  std::uint32_t count = 0;
};

/// Welds `points` by exact position (policy above).
welded_ids weld(const std::vector<vec3d>& points);

}  // namespace exbsp::geom
