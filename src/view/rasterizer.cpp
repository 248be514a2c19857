// SPDX-License-Identifier: LGPL-3.0-or-later
// Painting with the top-left-rule rasterizer (notation in rasterizer.h).
#include "view/rasterizer.h"

namespace exbsp::view {

void fill_triangle(image& img, const point2& a, const point2& b, const point2& c, rgb8 color) {
  for_each_covered_pixel(a, b, c, img.width(), img.height(),
                         [&](int i, int j) { img.set_pixel(i, j, color); });
}

void fill_convex_polygon(image& img, const std::vector<point2>& poly, rgb8 color) {
  for_each_covered_pixel_polygon(poly, img.width(), img.height(),
                                 [&](int i, int j) { img.set_pixel(i, j, color); });
}

}  // namespace exbsp::view
