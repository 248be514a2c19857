// SPDX-License-Identifier: LGPL-3.0-or-later
// Line rasterization for curves: a DDA with an explicit pixel rule (docs/contract.md "Pixels"
// pixels: pixel (i, j) covers [i, i+1] x [j, j+1], centre (i+1/2, j+1/2), y up).
//
// Notation: segment from s = (x0, y0) to e = (x1, y1), dx = x1 - x0, dy = y1 - y0; width W
// (pixels, W = 1 for ordinary images, W = N at N x N supersampling so that the line stays one
// output pixel wide).
// Rule ("column-centre rule"):
//   - x-major segments (|dx| >= |dy|, dx != 0) step over the pixel columns i whose centre
//     c = i + 1/2 lies in [x0, x1) (or (x1, x0] when dx < 0): the start is included, the end
//     excluded, so consecutive segments of a polyline never paint a column twice or skip one
//     (OpenGL's "last pixel not drawn" convention). At c the segment's height is
//     y(c) = y0 + (c - x0) dy / dx, and the pixels painted are the W rows j whose centres lie
//     in (y(c) - W/2, y(c) + W/2]; for W = 1 that is the one pixel j = floor(y(c)) whose span
//     contains y(c).
//   - y-major segments swap the roles of x and y.
//   - a zero-length segment paints nothing; a lone point (a degree-0 curve) paints the W x W
//     pixels whose centres lie in (p - W/2, p + W/2] on both axes (W = 1: the pixel containing p).
// Each covered pixel is reported with t in [0, 1], the parameter of the sample point along
// the segment, so attributes (depth) can be interpolated linearly in window space.
// Pixels outside [0, width) x [0, height) are skipped; non-finite input paints nothing.
#pragma once
#include <algorithm>
#include <cmath>

namespace exbsp::view {

namespace detail {
/// Index range of the W pixels whose centres lie in (v - W/2, v + W/2], clamped to [0, n-1].
inline bool band(double v, int w, int n, int& lo, int& hi) {
  const double a = std::floor(v - 0.5 * w - 0.5) + 1, b = std::floor(v + 0.5 * w - 0.5);
  if (!(b >= 0) || !(a <= n - 1)) return false;
  lo = a < 0 ? 0 : static_cast<int>(a);
  hi = b > n - 1 ? n - 1 : static_cast<int>(b);
  return lo <= hi;
}
}  // namespace detail

/// Calls cover(i, j, t) for every pixel of segment (x0, y0) -> (x1, y1) of width `line_width`
/// under the column-centre rule above, in a width x height image.
template <class Cover>
void for_each_line_pixel(double x0, double y0, double x1, double y1, int line_width, int width,
                         int height, Cover&& cover) {
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) return;
  if (line_width < 1) line_width = 1;
  const double dx = x1 - x0, dy = y1 - y0;
  if (dx == 0 && dy == 0) return;
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  // Major axis a (x or y), minor axis b.
  const double a0 = x_major ? x0 : y0, a1 = x_major ? x1 : y1;
  const double b0 = x_major ? y0 : x0, b1 = x_major ? y1 : x1;
  const int major_n = x_major ? width : height, minor_n = x_major ? height : width;
  const double da = a1 - a0, db = b1 - b0;
  // Centres c = k + 1/2 in [a0, a1) for da > 0, in (a1, a0] for da < 0.
  double kfirst, klast;
  if (da > 0) {
    kfirst = std::ceil(a0 - 0.5);
    klast = std::ceil(a1 - 0.5) - 1;
  } else {
    kfirst = std::floor(a1 - 0.5) + 1;
    klast = std::floor(a0 - 0.5);
  }
  kfirst = std::max(kfirst, 0.0);
  klast = std::min(klast, static_cast<double>(major_n - 1));
  if (!(kfirst <= klast)) return;
  const int k0 = static_cast<int>(kfirst), k1 = static_cast<int>(klast);
  for (int k = k0; k <= k1; ++k) {
    const double c = k + 0.5;
    const double t = std::min(1.0, std::max(0.0, (c - a0) / da));
    const double b = b0 + (c - a0) * (db / da);
    int lo, hi;
    if (!detail::band(b, line_width, minor_n, lo, hi)) continue;
    for (int m = lo; m <= hi; ++m) {
      if (x_major)
        cover(k, m, t);
      else
        cover(m, k, t);
    }
  }
}

/// Calls cover(i, j, 0) for the line_width x line_width pixels of a lone point (x, y).
template <class Cover>
void for_each_point_pixel(double x, double y, int line_width, int width, int height,
                          Cover&& cover) {
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  if (line_width < 1) line_width = 1;
  int i0, i1, j0, j1;
  if (!detail::band(x, line_width, width, i0, i1) || !detail::band(y, line_width, height, j0, j1))
    return;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) cover(i, j, 0.0);
}

}  // namespace exbsp::view
