// SPDX-License-Identifier: LGPL-3.0-or-later
// The painter (notation in paint.h).
#include "view/paint.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <exbsp/core/errors.h>
#include "view/line_raster.h"
#include "view/rasterizer.h"
#include "view/smooth_shading.h"
#include "view/texture_uvs.h"
#include "view/workers.h"

namespace exbsp::view {

namespace {

void put(std::uint8_t* p, rgb8 c) {
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}

/// Window row j of an image as a pointer to its first byte (storage row height - 1 - j).
struct pixel_rows {
  std::uint8_t* base;
  int width, height;
  std::uint8_t* row(int j) const {
    return base + 3 * static_cast<std::size_t>(height - 1 - j) * width;
  }
};

/// One bit per pixel of the front-to-back walk over the band of rows first_row..last_row: set
/// once a polygon has painted the pixel. Bit i % 64 of word i / 64 of band row j - first_row
/// is pixel (i, j). Written by hand: a bitset whose word operations (masked range test, claim
/// with count-trailing-zeros) are the whole point.
class coverage_mask {
 public:
  coverage_mask(int width, int first_row, int last_row)
      : first_row_(first_row),
        last_row_(last_row),
        words_((width + 63) / 64),
        bits_(static_cast<std::size_t>(words_) * (last_row - first_row + 1), 0),
        uncovered_(static_cast<std::size_t>(width) * (last_row - first_row + 1)) {}

  int first_row() const { return first_row_; }
  int last_row() const { return last_row_; }

  /// True when every pixel of [i0, i1] x [j0, j1] (rows within the band) is set.
  bool box_covered(int i0, int i1, int j0, int j1) const {
    for (int j = j0; j <= j1; ++j) {
      const std::uint64_t* row = row_bits(j);
      for (int w = i0 >> 6; w <= i1 >> 6; ++w) {
        const std::uint64_t m = range(w, i0, i1);
        if ((row[w] & m) != m) return false;
      }
    }
    return true;
  }

  /// Sets the pixels lo..hi of row j and calls fresh(i) for each that was not set before.
  template <class Fresh>
  void claim(int j, int lo, int hi, Fresh&& fresh) {
    std::uint64_t* row = &bits_[static_cast<std::size_t>(j - first_row_) * words_];
    for (int w = lo >> 6; w <= hi >> 6; ++w) {
      const std::uint64_t m = range(w, lo, hi);
      std::uint64_t todo = m & ~row[w];
      row[w] |= m;
      uncovered_ -= static_cast<std::size_t>(__builtin_popcountll(todo));
      for (; todo != 0; todo &= todo - 1) fresh(64 * w + __builtin_ctzll(todo));
    }
  }

  /// Shrinks lo..hi of row j to its first and last pixels not set yet; false when all are set.
  bool narrow_to_unset(int j, int& lo, int& hi) const {
    if (j < first_row_ || j > last_row_) return false;  // another band's row
    const std::uint64_t* row = row_bits(j);
    int w = lo >> 6;
    const int w_hi = hi >> 6;
    std::uint64_t free_bits = ~row[w] & range(w, lo, hi);
    while (free_bits == 0) {
      if (++w > w_hi) return false;
      free_bits = ~row[w] & range(w, lo, hi);
    }
    lo = 64 * w + __builtin_ctzll(free_bits);
    w = w_hi;
    free_bits = ~row[w] & range(w, lo, hi);
    while (free_bits == 0) {  // stops at lo's word at the latest
      --w;
      free_bits = ~row[w] & range(w, lo, hi);
    }
    hi = 64 * w + 63 - __builtin_clzll(free_bits);
    return true;
  }

  /// True when every pixel is set: nothing behind can show any more.
  bool full() const { return uncovered_ == 0; }

 private:
  const std::uint64_t* row_bits(int j) const {
    return &bits_[static_cast<std::size_t>(j - first_row_) * words_];
  }

  /// The bits of word w that lie in pixel range lo..hi.
  static std::uint64_t range(int w, int lo, int hi) {
    const int a = w == lo >> 6 ? lo & 63 : 0, b = w == hi >> 6 ? hi & 63 : 63;
    return (~std::uint64_t{0} >> (63 - b)) & (~std::uint64_t{0} << a);
  }

  int first_row_, last_row_, words_;
  std::vector<std::uint64_t> bits_;
  std::size_t uncovered_;
};

/// Paints polygon `poly` (image pixel coordinates), colour shade(i, j): every covered pixel
/// (mask == nullptr, back to front) or only the pixels no nearer polygon painted (front to
/// back). Front to back, a polygon whose box of pixel centres is entirely covered is skipped.
template <class Shade>
void paint_spans(const std::vector<point2>& poly, const pixel_rows& rows, coverage_mask* mask,
                 Shade&& shade) {
  if (!mask) {
    for_each_covered_span_polygon(poly, rows.width, rows.height, [&](int j, int lo, int hi) {
      std::uint8_t* r = rows.row(j);
      for (int i = lo; i <= hi; ++i) put(r + 3 * i, shade(i, j));
    });
    return;
  }
  // The box of the finite vertices holds every pixel of every fan triangle (a triangle with a
  // non-finite vertex covers nothing).
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for (const point2& v : poly)
    if (std::isfinite(v.x) && std::isfinite(v.y)) {
      x0 = std::min(x0, v.x), x1 = std::max(x1, v.x);
      y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
    }
  int i0, i1, j0, j1;
  if (!detail::pixel_range(x0, x1, rows.width, i0, i1) ||
      !detail::pixel_range(y0, y1, rows.height, j0, j1))
    return;
  j0 = std::max(j0, mask->first_row()), j1 = std::min(j1, mask->last_row());
  if (j0 > j1 || mask->box_covered(i0, i1, j0, j1)) return;
  for_each_covered_span_polygon(
      poly, rows.width, rows.height,
      [&](int j, int lo, int hi) {
        std::uint8_t* r = rows.row(j);
        mask->claim(j, lo, hi, [&](int i) { put(r + 3 * i, shade(i, j)); });
      },
      [&](int j, int& lo, int& hi) { return mask->narrow_to_unset(j, lo, hi); });
}

void paint_line(const frame& f, const screen_line& l, int scale, image& img) {
  const viewport& vp = f.view.vp;
  const double ax = scale * (l.a.x - vp.x), ay = scale * (l.a.y - vp.y);
  const double bx = scale * (l.b.x - vp.x), by = scale * (l.b.y - vp.y);
  auto cover = [&](int i, int j, double t) {
    if (!f.shader) {
      img.set_pixel(i, j, l.color);
      return;
    }
    const double x = l.a.x + t * (l.b.x - l.a.x), y = l.a.y + t * (l.b.y - l.a.y),
                 z = l.a.z + t * (l.b.z - l.a.z);
    img.set_pixel(i, j, f.shader->shade(l.color, x, y, z));
  };
  if (l.point)
    for_each_point_pixel(ax, ay, scale, img.width(), img.height(), cover);
  else
    for_each_line_pixel(ax, ay, bx, by, scale, img.width(), img.height(), cover);
}

void paint_polygon(const frame& f, const screen_polygon& p, int scale, std::vector<point2>& poly,
                   const pixel_rows& rows, coverage_mask* mask) {
  const viewport& vp = f.view.vp;
  poly.clear();
  for (const window_point& w : p.v) poly.push_back({scale * (w.x - vp.x), scale * (w.y - vp.y)});
  std::optional<corner_interpolator> smooth;  // smooth shading (smooth_shading.h)
  if (!f.corner_colors.empty())
    smooth.emplace(f.fragments[p.fragment], f.corner_colors[p.fragment], f.view);
  std::optional<uv_interpolator> uvs;  // a textured mesh (texture_uvs.h)
  const texture* tex = f.fragment_uvs.empty() ? nullptr : f.texture_of(p.face);
  if (tex) uvs.emplace(f.fragments[p.fragment], f.fragment_uvs[p.fragment], f.view);
  if (!f.shader && !smooth && !tex) {
    paint_spans(poly, rows, mask, [&](int, int) { return p.color; });
    return;
  }
  const depth_plane plane = f.shader ? polygon_depth_plane(p.v) : depth_plane{};
  const double lo = std::min(vp.depth_near, vp.depth_far),
               hi = std::max(vp.depth_near, vp.depth_far);
  paint_spans(poly, rows, mask, [&](int i, int j) {
    const double x = vp.x + (i + 0.5) / scale, y = vp.y + (j + 0.5) / scale;
    rgb8 c = smooth ? smooth->at(x, y, p.color) : p.color;
    if (tex) {
      const vec2d uv = uvs->at(x, y);
      c = modulate(tex->sample(uv[0], uv[1]), c);
    }
    if (!f.shader) return c;
    const double z = std::min(hi, std::max(lo, plane.at(x, y)));
    return f.shader->shade(c, x, y, z);
  });
}

/// The front-to-back walk, the image cut into f.raster_threads horizontal bands painted in
/// parallel (0: one per hardware thread, at most 8, bands of at least 64 rows): each band has
/// its own coverage mask and writes only its own rows, so the bands share nothing but the
/// read-only frame.
void paint_front_to_back(const frame& f, int scale, const pixel_rows& rows) {
  const int bands =
      f.raster_threads > 0
          ? std::min(static_cast<int>(std::min(f.raster_threads, 1024u)), rows.height)
          : std::max(1, std::min(static_cast<int>(hardware_workers()), rows.height / 64));
  run_workers(static_cast<unsigned>(bands), [&](unsigned w) {
    const int b = static_cast<int>(w);
    coverage_mask mask(rows.width, rows.height * b / bands, rows.height * (b + 1) / bands - 1);
    std::vector<point2> poly;
    for (auto p = f.polygons.rbegin(); p != f.polygons.rend() && !mask.full(); ++p)
      paint_polygon(f, *p, scale, poly, rows, &mask);
  });
}

}  // namespace

paint_order effective_paint_order(const frame& f) {
  return f.lines.empty() ? f.painter : paint_order::back_to_front;
}

image paint_frame(const frame& f, int scale) {
  const viewport& vp = f.view.vp;
  if (scale < 1) throw usage_error("paint_frame: scale must be >= 1");
  const long long w = static_cast<long long>(vp.width) * scale,
                  h = static_cast<long long>(vp.height) * scale;
  if (w > 65536 || h > 65536)
    throw usage_error("paint_frame: the supersampled image would exceed 65536 pixels a side");
  image img(static_cast<int>(w), static_cast<int>(h),
            f.shader ? f.shader->background : f.background);
  const pixel_rows rows{img.data().data(), img.width(), img.height()};
  if (effective_paint_order(f) == paint_order::front_to_back) {
    paint_front_to_back(f, scale, rows);
    return img;
  }
  std::vector<point2> poly;
  std::size_t next_line = 0;
  for (std::size_t k = 0; k <= f.polygons.size(); ++k) {
    while (next_line < f.lines.size() && f.lines[next_line].slot <= k)
      paint_line(f, f.lines[next_line++], scale, img);
    if (k < f.polygons.size()) paint_polygon(f, f.polygons[k], scale, poly, rows, nullptr);
  }
  return img;
}

image box_downsample(const image& hi, int n) {
  if (n < 1 || hi.width() % n != 0 || hi.height() % n != 0)
    throw usage_error("box_downsample: the image sides must be multiples of the factor");
  if (n == 1) return hi;
  const int w = hi.width() / n, h = hi.height() / n;
  image out(w, h, rgb8{});
  const unsigned count = static_cast<unsigned>(n) * static_cast<unsigned>(n);
  std::vector<unsigned> sum(3 * static_cast<std::size_t>(w));
  const std::vector<std::uint8_t>& src = hi.data();
  std::vector<std::uint8_t>& dst = out.data();
  for (int r = 0; r < h; ++r) {
    std::fill(sum.begin(), sum.end(), 0u);
    for (int rr = 0; rr < n; ++rr) {
      const std::uint8_t* row = &src[3 * static_cast<std::size_t>(r * n + rr) * hi.width()];
      for (int c = 0; c < w; ++c)
        for (int cc = 0; cc < n; ++cc)
          for (int ch = 0; ch < 3; ++ch) sum[3 * c + ch] += row[3 * (c * n + cc) + ch];
    }
    std::uint8_t* out_row = &dst[3 * static_cast<std::size_t>(r) * w];
    for (std::size_t k = 0; k < sum.size(); ++k)
      out_row[k] = static_cast<std::uint8_t>((sum[k] + count / 2) / count);
  }
  return out;
}

}  // namespace exbsp::view
