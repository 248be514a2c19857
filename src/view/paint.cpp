// The painter (notation in paint.h).
#include "view/paint.h"

#include "mesh/errors.h"
#include "view/fog.h"
#include "view/line_raster.h"
#include "view/rasterizer.h"

namespace exbsp::view {

namespace {

/// The plain painter of the "raster" stage: no lines, no fog, scale 1 (the no-effects path).
void paint_polygons(const frame& f, image& img) {
  const viewport& vp = f.view.vp;
  std::vector<vec2> poly;
  for (const screen_polygon& p : f.polygons) {
    poly.clear();
    for (const window_point& w : p.v) poly.push_back({w.x - vp.x, w.y - vp.y});
    fill_convex_polygon(img, poly, p.color);
  }
}

void paint_line(const frame& f, const screen_line& l, int scale, image& img) {
  const viewport& vp = f.view.vp;
  const double ax = scale * (l.a.x - vp.x), ay = scale * (l.a.y - vp.y);
  const double bx = scale * (l.b.x - vp.x), by = scale * (l.b.y - vp.y);
  auto cover = [&](int i, int j, double t) {
    if (!f.fog) {
      img.set_pixel(i, j, l.color);
      return;
    }
    const double x = l.a.x + t * (l.b.x - l.a.x), y = l.a.y + t * (l.b.y - l.a.y), z = l.a.z + t * (l.b.z - l.a.z);
    img.set_pixel(i, j, fog_color(*f.fog, l.color, eye_distance(*f.fog, x, y, z)));
  };
  if (l.point)
    for_each_point_pixel(ax, ay, scale, img.width(), img.height(), cover);
  else
    for_each_line_pixel(ax, ay, bx, by, scale, img.width(), img.height(), cover);
}

void paint_polygon(const frame& f, const screen_polygon& p, int scale, std::vector<vec2>& poly, image& img) {
  const viewport& vp = f.view.vp;
  poly.clear();
  for (const window_point& w : p.v) poly.push_back({scale * (w.x - vp.x), scale * (w.y - vp.y)});
  if (!f.fog) {
    for_each_covered_pixel_polygon(poly, img.width(), img.height(), [&](int i, int j) { img.set_pixel(i, j, p.color); });
    return;
  }
  const depth_plane plane = polygon_depth_plane(p.v);
  const double lo = std::min(vp.depth_near, vp.depth_far), hi = std::max(vp.depth_near, vp.depth_far);
  for_each_covered_pixel_polygon(poly, img.width(), img.height(), [&](int i, int j) {
    const double x = vp.x + (i + 0.5) / scale, y = vp.y + (j + 0.5) / scale;
    const double z = std::min(hi, std::max(lo, plane.at(x, y)));
    img.set_pixel(i, j, fog_color(*f.fog, p.color, eye_distance(*f.fog, x, y, z)));
  });
}

}  // namespace

image paint_frame(const frame& f, int scale) {
  const viewport& vp = f.view.vp;
  if (scale < 1) throw usage_error("paint_frame: scale must be >= 1");
  const long long w = static_cast<long long>(vp.width) * scale, h = static_cast<long long>(vp.height) * scale;
  if (w > 65536 || h > 65536) throw usage_error("paint_frame: the supersampled image would exceed 65536 pixels a side");
  image img(static_cast<int>(w), static_cast<int>(h), f.fog ? f.fog->settings.color : f.background);
  if (scale == 1 && !f.fog && f.lines.empty()) {
    paint_polygons(f, img);
    return img;
  }
  std::vector<vec2> poly;
  std::size_t next_line = 0;
  for (std::size_t k = 0; k <= f.polygons.size(); ++k) {
    while (next_line < f.lines.size() && f.lines[next_line].slot <= k) paint_line(f, f.lines[next_line++], scale, img);
    if (k < f.polygons.size()) paint_polygon(f, f.polygons[k], scale, poly, img);
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
    for (std::size_t k = 0; k < sum.size(); ++k) out_row[k] = static_cast<std::uint8_t>((sum[k] + count / 2) / count);
  }
  return out;
}

}  // namespace exbsp::view
