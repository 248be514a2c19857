// Triangle rasterization by edge functions with the top-left rule (DESIGN.md section 6).
//
// Notation: window coordinates, y UP (viewport.h); pixel (i, j) has centre p = (i+1/2, j+1/2).
// A triangle is first made counter-clockwise (b and c swapped when clockwise), so its interior
// is to the LEFT of each directed edge e = (s -> t): E_e(p) = orient2d(s, t, p) > 0 (exact).
// The pixel belongs to the triangle when every E_e(p) > 0, or E_e(p) == 0 on an edge that is
//   - a LEFT edge:  t.y < s.y                 (going down; the interior lies to its right, +x), or
//   - a TOP edge:   t.y == s.y and t.x < s.x  (horizontal; the interior lies below it, -y).
// An edge shared by two triangles is traversed in opposite directions after both are made
// counter-clockwise, so exactly one of them owns its centres: never painted twice, never
// missed. A pixel centre exactly on a vertex shared by a closed fan is owned by exactly one
// triangle of the fan. Triangles of zero area cover nothing. Either input winding works.
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "view/image.h"
#include "view/orient2d.h"

namespace exbsp::view {

/// A point in the window plane (x right, y up).
struct vec2 {
  double x = 0, y = 0;
};

namespace detail {
/// Index range [lo, hi] of pixels whose centres k + 1/2 may lie in [vmin, vmax], clamped to
/// [0, n - 1]; returns false when empty.
inline bool pixel_range(double vmin, double vmax, int n, int& lo, int& hi) {
  const double flo = std::floor(vmin - 0.5), fhi = std::ceil(vmax - 0.5);
  if (!(fhi >= 0) || !(flo <= n - 1)) return false;
  lo = flo < 0 ? 0 : static_cast<int>(flo);
  hi = fhi > n - 1 ? n - 1 : static_cast<int>(fhi);
  return lo <= hi;
}
inline bool owns_edge(const vec2& s, const vec2& t) { return t.y < s.y || (t.y == s.y && t.x < s.x); }
inline bool inside_edge(const vec2& s, const vec2& t, double px, double py, bool owned) {
  const int o = orient2d(s.x, s.y, t.x, t.y, px, py);
  return o > 0 || (o == 0 && owned);
}
}  // namespace detail

/// Calls cover(i, j) once for every pixel (i, j) of a width x height window whose centre
/// belongs to triangle (a, b, c) under the top-left rule above. Either winding; zero-area or
/// non-finite triangles cover nothing. Rows are visited bottom-up, pixels left to right.
template <class Cover>
void for_each_covered_pixel(vec2 a, vec2 b, vec2 c, int width, int height, Cover&& cover) {
  for (const vec2* p : {&a, &b, &c})
    if (!std::isfinite(p->x) || !std::isfinite(p->y)) return;
  const int o = orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
  if (o == 0) return;
  if (o < 0) std::swap(b, c);
  int i0, i1, j0, j1;
  if (!detail::pixel_range(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), width, i0, i1)) return;
  if (!detail::pixel_range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), height, j0, j1)) return;
  const bool own_ab = detail::owns_edge(a, b), own_bc = detail::owns_edge(b, c), own_ca = detail::owns_edge(c, a);
  for (int j = j0; j <= j1; ++j) {
    const double py = j + 0.5;
    bool entered = false;
    for (int i = i0; i <= i1; ++i) {
      const double px = i + 0.5;
      if (detail::inside_edge(a, b, px, py, own_ab) && detail::inside_edge(b, c, px, py, own_bc) &&
          detail::inside_edge(c, a, px, py, own_ca)) {
        entered = true;
        cover(i, j);
      } else if (entered) {
        break;  // a triangle is convex: its pixels in a row are contiguous
      }
    }
  }
}

/// Calls cover(i, j) for the pixels of a convex polygon, fan-triangulated from its first
/// vertex: (v0, v[k], v[k+1]). Fan diagonals are shared edges, so no pixel is reported twice
/// when the polygon is convex (as every clipped triangle is).
template <class Cover>
void for_each_covered_pixel_polygon(const std::vector<vec2>& poly, int width, int height, Cover&& cover) {
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) for_each_covered_pixel(poly[0], poly[k], poly[k + 1], width, height, cover);
}

/// Paints triangle (a, b, c) in colour `color` (no depth test).
void fill_triangle(image& img, const vec2& a, const vec2& b, const vec2& c, rgb8 color);

/// Paints a convex polygon (fan from its first vertex) in colour `color` (no depth test).
void fill_convex_polygon(image& img, const std::vector<vec2>& poly, rgb8 color);

}  // namespace exbsp::view
