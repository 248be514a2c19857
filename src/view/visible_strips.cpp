// SPDX-License-Identifier: LGPL-3.0-or-later
// The striped coverage (visible_strips.h): where the strips go, how a polygon is cut at a strip
// line, and the queries the regions and underlays make across strips.
#include "view/visible_strips.h"

#include <algorithm>

namespace exbsp::view::cover {

namespace cl = ClipperLib;

std::vector<int> strip_rows(const std::vector<long long>& centres_y, long long height, int count,
                            const std::vector<long long>& avoid_y) {
  constexpr long long side = tiled_coverage::tile_side;
  const int rows = static_cast<int>(std::max<long long>(1, (height + side - 1) / side));
  // The centres by tile row, then cuts at the quantiles of that histogram, on rows whose line
  // holds no ordinate to avoid.
  std::vector<std::size_t> per_row(static_cast<std::size_t>(rows), 0);
  for (const long long c : centres_y)
    ++per_row[static_cast<std::size_t>(std::clamp<long long>(c / side, 0, rows - 1))];
  const std::size_t total = centres_y.size();
  std::vector<int> cuts{0};
  if (total == 0) {
    cuts.push_back(rows);
    return cuts;
  }
  auto allowed = [&](int r) {
    return !std::binary_search(avoid_y.begin(), avoid_y.end(), static_cast<long long>(r) * side);
  };
  std::size_t seen = 0;
  int made = 1;
  for (int r = 0; r < rows && made < count; ++r) {
    seen += per_row[static_cast<std::size_t>(r)];
    // Cut after row r once it holds its share of the centres (and rows remain above it).
    if (seen * static_cast<std::size_t>(count) >= total * static_cast<std::size_t>(made) &&
        r + 1 < rows && r + 1 > cuts.back() && allowed(r + 1)) {
      cuts.push_back(r + 1);
      ++made;
    }
  }
  cuts.push_back(rows);
  return cuts;
}

long long crossing_x(const cl::IntPoint& a, const cl::IntPoint& b, long long y) {
  const bool swap = b.X < a.X || (b.X == a.X && b.Y < a.Y);
  const cl::IntPoint& p = swap ? b : a;
  const cl::IntPoint& q = swap ? a : b;
  // x = p.X + (q.X - p.X) (y - p.Y) / (q.Y - p.Y), rounded half up, in integers: grid
  // coordinates are below 2^31 (the viewport's), so the products stay below 2^63.
  long long num = (q.X - p.X) * (y - p.Y);
  long long den = q.Y - p.Y;
  if (den < 0) {
    num = -num;
    den = -den;
  }
  return p.X + floor_div(2 * num + den, 2 * den);  // = round(num / den), halves up
}

bool cut_to_band(const cl::Path& p, long long y0, long long y1, cl::Path& out) {
  out.clear();
  auto push = [&](const cl::IntPoint& q) {
    if (out.empty() || !(out.back() == q)) out.push_back(q);
  };
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const cl::IntPoint& a = p[i];
    const cl::IntPoint& b = p[(i + 1) % n];
    if (a.Y >= y0 && a.Y <= y1) push(a);
    // The band's lines crossed strictly inside the edge, in order from a to b.
    const long long lo = std::min(a.Y, b.Y), hi = std::max(a.Y, b.Y);
    const bool cross0 = lo < y0 && y0 < hi, cross1 = lo < y1 && y1 < hi;
    if (cross0 && cross1) {
      const long long first = a.Y < b.Y ? y0 : y1, second = a.Y < b.Y ? y1 : y0;
      push({crossing_x(a, b, first), first});
      push({crossing_x(a, b, second), second});
    } else if (cross0) {
      push({crossing_x(a, b, y0), y0});
    } else if (cross1) {
      push({crossing_x(a, b, y1), y1});
    }
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out.size() >= 3 && cl::Area(out) > 0;
}

bool segment_in_band(const cl::IntPoint& a, const cl::IntPoint& b, long long y0, long long y1,
                     cl::Path& out) {
  out.clear();
  if (a.Y == b.Y) {
    if (a.Y < y0 || a.Y >= y1) return false;
    out = {a, b};
    return true;
  }
  auto end_in_band = [&](const cl::IntPoint& e) -> cl::IntPoint {
    if (e.Y < y0) return {crossing_x(a, b, y0), y0};
    if (e.Y > y1) return {crossing_x(a, b, y1), y1};
    return e;
  };
  if (std::max(a.Y, b.Y) <= y0 || std::min(a.Y, b.Y) >= y1) return false;  // a point at most
  out = {end_in_band(a), end_in_band(b)};
  return true;
}

striped_coverage::striped_coverage(long long width, const std::vector<int>& rows) {
  constexpr long long side = tiled_coverage::tile_side;
  constexpr long long far = 1LL << 60;  // beyond any grid point
  for (std::size_t s = 0; s + 1 < rows.size(); ++s)
    strips_.push_back({std::make_unique<tiled_coverage>(width, rows[s], rows[s + 1] - rows[s]),
                       s == 0 ? -far : rows[s] * side,
                       s + 2 == rows.size() ? far : rows[s + 1] * side});
}

cl::Paths striped_coverage::full_tiles_of(std::uint32_t mesh) const {
  cl::Paths out;
  for (const band& b : strips_) {
    cl::Paths part = b.coverage->full_tiles_of(mesh);
    out.insert(out.end(), std::make_move_iterator(part.begin()),
               std::make_move_iterator(part.end()));
  }
  return out;
}

bool striped_coverage::inside_full_tiles_of(const bbox_i& box, std::uint32_t mesh) const {
  for (const band& b : strips_) {
    // The tile rows of the box in this strip (a box on a strip line reaches the row above it).
    if (box.y1 < b.y0 || box.y0 > b.y1) continue;
    const bbox_i part{box.x0, std::max(box.y0, b.y0), box.x1, std::min(box.y1, b.y1)};
    if (!b.coverage->inside_full_tiles_of(part, mesh)) return false;
  }
  return true;
}

}  // namespace exbsp::view::cover
