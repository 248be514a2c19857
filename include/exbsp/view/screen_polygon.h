// SPDX-License-Identifier: LGPL-3.0-or-later
// The product of the transform+clip stage: one clipped fragment in window coordinates.
#pragma once
#include <cstdint>
#include <vector>

#include <exbsp/view/image.h>
#include <exbsp/view/viewport.h>

namespace exbsp::view {

/// A fragment after modelview, projection, clipping, divide and viewport: a convex polygon
/// in window coordinates (x right, y up, z depth in [0, 1]), with its source and colour.
struct screen_polygon {
  std::uint32_t fragment = 0;  ///< index into bsp::fragments_double()
  std::uint32_t face = 0;      ///< face id in the scene's appended soup
  rgb8 color;
  std::vector<window_point> v;  ///< >= 3 vertices, the fragment's winding
};

}  // namespace exbsp::view
