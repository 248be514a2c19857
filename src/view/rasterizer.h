// SPDX-License-Identifier: LGPL-3.0-or-later
// Triangle rasterization by edge functions with the top-left rule (docs/contract.md "Pixels").
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
// for_each_covered_pixel_reference tests every centre of the box: the definition.
// for_each_covered_span finds each row's covered run from a rounded edge crossing settled by
// the exact predicate: the same pixels, a few predicate calls per row (tests/test_raster.cpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <exbsp/view/image.h>
#include "view/orient2d.h"

namespace exbsp::view {

/// A point in the window plane (x right, y up).
struct point2 {
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
inline bool owns_edge(const point2& s, const point2& t) {
  return t.y < s.y || (t.y == s.y && t.x < s.x);
}
inline bool inside_edge(const point2& s, const point2& t, double px, double py, bool owned) {
  const int o = orient2d(s.x, s.y, t.x, t.y, px, py);
  return o > 0 || (o == 0 && owned);
}
}  // namespace detail

/// The definition of the pixel set, pixel by pixel: calls cover(i, j) once for every pixel
/// (i, j) of a width x height window whose centre belongs to triangle (a, b, c) under the
/// top-left rule above, rows bottom-up, pixels left to right. Either winding; zero-area or
/// non-finite triangles cover nothing. The reference that for_each_covered_span must
/// reproduce exactly (tests/test_raster.cpp); the painters use the span version.
template <class Cover>
void for_each_covered_pixel_reference(point2 a, point2 b, point2 c, int width, int height,
                                      Cover&& cover) {
  for (const point2* p : {&a, &b, &c})
    if (!std::isfinite(p->x) || !std::isfinite(p->y)) return;
  const int o = orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
  if (o == 0) return;
  if (o < 0) std::swap(b, c);
  int i0, i1, j0, j1;
  if (!detail::pixel_range(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), width, i0, i1))
    return;
  if (!detail::pixel_range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), height, j0, j1))
    return;
  const bool own_ab = detail::owns_edge(a, b), own_bc = detail::owns_edge(b, c),
             own_ca = detail::owns_edge(c, a);
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

namespace detail {
/// One directed edge s -> t of a counter-clockwise triangle, prepared for span search.
/// For a fixed row py, E(px) = orient2d(s, t, (px, py)) is an exact linear function of px with
/// slope s.y - t.y, so "centre i is inside this edge" is monotone in i: non-decreasing for a
/// descending edge (t.y < s.y: the interior is on the +x side, side = +1), non-increasing for an
/// ascending one (side = -1), constant in i for a horizontal one (side = 0). The crossing
/// x*(py) = s.x + (py - s.y) (t.x - s.x) / (t.y - s.y), rounded, is only a starting guess: the
/// span end is then settled by the exact predicate on the neighbouring centres, so the result
/// is the exact pixel set whatever the rounding of the guess.
struct span_edge {
  point2 s, t;
  bool owned = false;
  int side = 0;
  double inverse_slope = 0;  ///< (t.x - s.x) / (t.y - s.y); unused when side == 0

  span_edge(const point2& from, const point2& to) : s(from), t(to), owned(owns_edge(from, to)) {
    side = t.y < s.y ? 1 : (t.y > s.y ? -1 : 0);
    if (side != 0) inverse_slope = (t.x - s.x) / (t.y - s.y);
  }
  bool inside(int i, double py) const { return inside_edge(s, t, i + 0.5, py, owned); }
  /// Index near the crossing in [lo, hi]: the first centre at or right of x* (side +1) or the
  /// last at or left of it (side -1); lo or hi when x* is out of range or not a number.
  int guess(double py, int lo, int hi) const {
    const double x = s.x + (py - s.y) * inverse_slope - 0.5;
    if (!(x > lo)) return lo;
    if (!(x < hi)) return hi;
    return static_cast<int>(side > 0 ? std::ceil(x) : std::floor(x));
  }
  /// Narrows [lo, hi] to the centres of row py inside this edge; false when none is.
  bool clip(double py, int& lo, int& hi) const {
    if (side == 0) return inside(lo, py);
    int k = guess(py, lo, hi);
    if (side > 0) {  // inside for i >= first: find first
      if (inside(k, py)) {
        while (k > lo && inside(k - 1, py)) --k;
      } else {
        do ++k;
        while (k <= hi && !inside(k, py));
        if (k > hi) return false;
      }
      lo = k;
    } else {  // inside for i <= last: find last
      if (inside(k, py)) {
        while (k < hi && inside(k + 1, py)) ++k;
      } else {
        do --k;
        while (k >= lo && !inside(k, py));
        if (k < lo) return false;
      }
      hi = k;
    }
    return true;
  }
};
}  // namespace detail

/// The covered runs of triangle (a, b, c) (see the overload below), but first asks
/// narrow(j, lo, hi) for each row of the triangle's box, with lo..hi the box's columns: it
/// may shrink lo..hi to the columns the caller still needs, or return false to skip the row.
/// span(j, lo, hi) then reports the covered run within the narrowed columns (the
/// front-to-back painter narrows to the pixels not yet painted).
template <class Span, class Narrow>
void for_each_covered_span(point2 a, point2 b, point2 c, int width, int height, Span&& span,
                           Narrow&& narrow) {
  for (const point2* p : {&a, &b, &c})
    if (!std::isfinite(p->x) || !std::isfinite(p->y)) return;
  int i0, i1, j0, j1;  // the box first: most fragments of a fine mesh miss every centre
  if (!detail::pixel_range(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), width, i0, i1))
    return;
  if (!detail::pixel_range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), height, j0, j1))
    return;
  const int o = orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
  if (o == 0) return;
  if (o < 0) std::swap(b, c);
  // On row py, only the edges whose closed y-range holds py bound the run: the third edge's
  // line meets the row outside the triangle, so every centre between the other two lies
  // strictly inside it (E > 0 exactly) and testing it changes nothing. A row outside the
  // triangle's y-range (the box's rows are rounded outwards) has no such edge: empty.
  const detail::span_edge e[3] = {{a, b}, {b, c}, {c, a}};
  double e_lo[3], e_hi[3];
  for (int k = 0; k < 3; ++k)
    e_lo[k] = std::min(e[k].s.y, e[k].t.y), e_hi[k] = std::max(e[k].s.y, e[k].t.y);
  for (int j = j0; j <= j1; ++j) {
    const double py = j + 0.5;
    int lo = i0, hi = i1, crossed = 0;
    if (!narrow(j, lo, hi)) continue;
    bool any = true;
    for (int k = 0; k < 3 && any; ++k)
      if (e_lo[k] <= py && py <= e_hi[k]) {
        ++crossed;
        any = e[k].clip(py, lo, hi);
      }
    if (any && crossed > 0) span(j, lo, hi);
  }
}

/// The pixels of for_each_covered_pixel_reference, one row at a time: calls span(j, lo, hi)
/// for every row j (bottom-up) whose covered pixels are the non-empty run lo..hi. Same pixel
/// set exactly (the exact predicate settles every span end); a few predicate calls per row
/// instead of three per pixel.
template <class Span>
void for_each_covered_span(point2 a, point2 b, point2 c, int width, int height, Span&& span) {
  for_each_covered_span(a, b, c, width, height, span, [](int, int&, int&) { return true; });
}

/// Calls cover(i, j) once for every pixel (i, j) of a width x height window whose centre
/// belongs to triangle (a, b, c) under the top-left rule above. Either winding; zero-area or
/// non-finite triangles cover nothing. Rows are visited bottom-up, pixels left to right.
template <class Cover>
void for_each_covered_pixel(point2 a, point2 b, point2 c, int width, int height, Cover&& cover) {
  for_each_covered_span(a, b, c, width, height, [&](int j, int lo, int hi) {
    for (int i = lo; i <= hi; ++i) cover(i, j);
  });
}

/// Calls cover(i, j) for the pixels of a convex polygon, fan-triangulated from its first
/// vertex: (v0, v[k], v[k+1]). Fan diagonals are shared edges, so no pixel is reported twice
/// when the polygon is convex (as every clipped triangle is).
template <class Cover>
void for_each_covered_pixel_polygon(const std::vector<point2>& poly, int width, int height,
                                    Cover&& cover) {
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    for_each_covered_pixel(poly[0], poly[k], poly[k + 1], width, height, cover);
}

/// Calls span(j, lo, hi) for the covered runs of each fan triangle of a convex polygon (as
/// for_each_covered_pixel_polygon, a run per triangle and row).
template <class Span>
void for_each_covered_span_polygon(const std::vector<point2>& poly, int width, int height,
                                   Span&& span) {
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    for_each_covered_span(poly[0], poly[k], poly[k + 1], width, height, span);
}

/// The same with a row filter `narrow` for each fan triangle (for_each_covered_span).
template <class Span, class Narrow>
void for_each_covered_span_polygon(const std::vector<point2>& poly, int width, int height,
                                   Span&& span, Narrow&& narrow) {
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    for_each_covered_span(poly[0], poly[k], poly[k + 1], width, height, span, narrow);
}

/// Paints triangle (a, b, c) in colour `color` (no depth test).
void fill_triangle(image& img, const point2& a, const point2& b, const point2& c, rgb8 color);

/// Paints a convex polygon (fan from its first vertex) in colour `color` (no depth test).
void fill_convex_polygon(image& img, const std::vector<point2>& poly, rgb8 color);

}  // namespace exbsp::view
