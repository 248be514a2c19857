// SPDX-License-Identifier: LGPL-3.0-or-later
// Coverage of the visible-region drawing (notation in visible_cover.h and vector_drawing.h):
// polygon tests on the integer grid (separation, convexity, ear triangles), overlap areas by
// Sutherland–Hodgman in doubles, the tiled coverage of disjoint pieces, and the T-junction
// mender. The Booleans are Clipper's (libpolyclipping), used only for partly hidden polygons.
#include "view/visible_cover.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <exbsp/view/vector_drawing.h>

namespace exbsp::view::cover {

namespace cl = ClipperLib;

namespace {

/// Twice the signed area of a ring, its points taken relative to `o` (small products, so the
/// double sum is exact to far below one square unit).
double twice_area_from(const cl::Path& p, double ox, double oy) {
  double a = 0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const double xi = static_cast<double>(p[i].X) - ox, yi = static_cast<double>(p[i].Y) - oy;
    const double xj = static_cast<double>(p[j].X) - ox, yj = static_cast<double>(p[j].Y) - oy;
    a += xj * yi - xi * yj;
  }
  return a;
}

}  // namespace

bool convex_ccw(const cl::Path& r) {
  const std::size_t n = r.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const cl::IntPoint& a = r[i];
    const cl::IntPoint& b = r[(i + 1) % n];
    const cl::IntPoint& c = r[(i + 2) % n];
    if ((b.X - a.X) * (c.Y - b.Y) - (b.Y - a.Y) * (c.X - b.X) < 0) return false;
  }
  return true;
}

cl::Path without_straight_vertices(const cl::Path& r) {
  cl::Path out(r);
  for (bool changed = true; changed && out.size() > 3;) {
    changed = false;
    for (std::size_t i = 0; i < out.size() && out.size() > 3; ++i) {
      const std::size_t n = out.size();
      const cl::IntPoint& a = out[(i + n - 1) % n];
      const cl::IntPoint& b = out[i];
      const cl::IntPoint& c = out[(i + 1) % n];
      if ((b.X - a.X) * (c.Y - b.Y) - (b.Y - a.Y) * (c.X - b.X) == 0) {
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
  return out;
}

bool union_by_shared_edges(const std::vector<const cl::Path*>& rings, cl::Paths& out) {
  struct edge {
    cl::IntPoint a, b;
  };
  auto less = [](const cl::IntPoint& p, const cl::IntPoint& q) {
    return p.X != q.X ? p.X < q.X : p.Y < q.Y;
  };
  auto edge_less = [&](const edge& e, const edge& f) {
    return less(e.a, f.a) || (e.a == f.a && less(e.b, f.b));
  };
  std::vector<edge> edges;
  long long twice = 0;
  for (const cl::Path* r : rings)
    for (std::size_t i = 0; i < r->size(); ++i) {
      const cl::IntPoint& a = (*r)[i];
      const cl::IntPoint& b = (*r)[(i + 1) % r->size()];
      if (!(a == b)) edges.push_back({a, b});
      twice += a.X * b.Y - b.X * a.Y;
    }
  std::sort(edges.begin(), edges.end(), edge_less);
  // Cancel each edge against its reverse (sorted order: deterministic on every machine).
  std::vector<char> gone(edges.size(), 0);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (gone[i]) continue;
    const edge rev{edges[i].b, edges[i].a};
    auto it = std::lower_bound(edges.begin(), edges.end(), rev, edge_less);
    for (; it != edges.end() && it->a == rev.a && it->b == rev.b; ++it) {
      const auto k = static_cast<std::size_t>(it - edges.begin());
      if (!gone[k]) {
        gone[i] = gone[k] = 1;
        break;
      }
    }
  }
  std::vector<edge> left;
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (!gone[i]) left.push_back(edges[i]);
  // Each start point must have exactly one edge left (sorted by start: neighbours).
  for (std::size_t i = 1; i < left.size(); ++i)
    if (left[i].a == left[i - 1].a) return false;
  out.clear();
  std::vector<char> used(left.size(), 0);
  long long twice_out = 0;
  for (std::size_t s = 0; s < left.size(); ++s) {
    if (used[s]) continue;
    cl::Path ring;
    std::size_t k = s;
    while (!used[k]) {
      used[k] = 1;
      ring.push_back(left[k].a);
      twice_out += left[k].a.X * left[k].b.Y - left[k].b.X * left[k].a.Y;
      const edge key{left[k].b, {}};
      auto it = std::lower_bound(left.begin(), left.end(), key,
                                 [&](const edge& e, const edge& f) { return less(e.a, f.a); });
      if (it == left.end() || !(it->a == left[k].b)) return false;  // an open chain
      k = static_cast<std::size_t>(it - left.begin());
    }
    if (k != s) return false;  // joined a chain that started elsewhere
    out.push_back(without_straight_vertices(ring));
  }
  return twice_out == twice;
}

void cell_areas(const cl::Paths& rings, long long ox, long long oy, long long side, int cols,
                int rows, std::vector<double>& area, std::vector<double>& cover) {
  const std::size_t n = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  area.assign(n, 0.0);
  // cover[r * (cols + 1) + c]: rise of the boundary in row r within column c (or right of
  // every column, c = cols), which counts a full width in each column left of c.
  cover.assign(static_cast<std::size_t>(cols + 1) * static_cast<std::size_t>(rows), 0.0);
  const double w = static_cast<double>(side);
  const double top = w * rows, right = w * cols;
  // A piece of an edge within row r, from (xa, ya) to (xb, yb): split at the column lines.
  auto add_in_row = [&](int r, double xa, double ya, double xb, double yb) {
    double* row_area = area.data() + static_cast<std::size_t>(r) * cols;
    double* row_cover = cover.data() + static_cast<std::size_t>(r) * (cols + 1);
    auto add_in_column = [&](double x0, double y0, double x1, double y1) {
      const double mid = 0.5 * (x0 + x1), dy = y1 - y0;
      if (mid <= 0) return;  // left of every column: nothing of any cell lies left of it
      if (mid >= right) {
        row_cover[cols] += dy;
        return;
      }
      const int c = std::min(cols - 1, static_cast<int>(mid / w));
      row_area[c] += (mid - c * w) * dy;
      row_cover[c] += dy;
    };
    if (xa == xb) {
      add_in_column(xa, ya, xb, yb);
      return;
    }
    // Column lines strictly between xa and xb, in the edge's direction.
    const bool forward = xb > xa;
    const double lo = std::min(xa, xb), hi = std::max(xa, xb);
    int c = forward ? static_cast<int>(std::floor(lo / w)) + 1
                    : static_cast<int>(std::ceil(hi / w)) - 1;
    c = std::clamp(c, 0, cols);
    double px = xa, py = ya;
    for (;; c += forward ? 1 : -1) {
      if (c < 0 || c > cols) break;
      const double lx = c * w;
      if (forward ? lx >= xb : lx <= xb) break;
      if (forward ? lx <= px : lx >= px) continue;
      const double ly = ya + (lx - xa) * (yb - ya) / (xb - xa);
      add_in_column(px, py, lx, ly);
      px = lx;
      py = ly;
    }
    add_in_column(px, py, xb, yb);
  };
  for (const cl::Path& ring : rings)
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      double xa = static_cast<double>(ring[j].X - ox), ya = static_cast<double>(ring[j].Y - oy);
      double xb = static_cast<double>(ring[i].X - ox), yb = static_cast<double>(ring[i].Y - oy);
      if (ya == yb) continue;  // no rise: adds nothing
      // The edge's part in [0, top], then its pieces in each row, in its direction.
      const double y_lo = std::max(0.0, std::min(ya, yb)), y_hi = std::min(top, std::max(ya, yb));
      if (y_lo >= y_hi) continue;
      auto x_at = [&](double y) { return xa + (y - ya) * (xb - xa) / (yb - ya); };
      const bool up = yb > ya;
      const double y_start = up ? y_lo : y_hi, y_end = up ? y_hi : y_lo;
      double px = y_start == ya ? xa : x_at(y_start), py = y_start;
      const double x_end = y_end == yb ? xb : x_at(y_end);
      // The row the edge enters first: above y_lo going up, below y_hi going down.
      int r =
          up ? static_cast<int>(std::floor(y_lo / w)) : static_cast<int>(std::ceil(y_hi / w)) - 1;
      r = std::clamp(r, 0, rows - 1);
      for (;;) {
        const double line = up ? (r + 1) * w : r * w;  // the row's far line in the edge's direction
        const bool last = up ? y_end <= line : y_end >= line;
        if (last) {
          add_in_row(r, px, py, x_end, y_end);
          break;
        }
        const double lx = x_at(line);
        add_in_row(r, px, py, lx, line);
        px = lx;
        py = line;
        r += up ? 1 : -1;
        if (r < 0 || r >= rows) break;
      }
    }
  for (int r = 0; r < rows; ++r) {
    const double* row_cover = cover.data() + static_cast<std::size_t>(r) * (cols + 1);
    double* row_area = area.data() + static_cast<std::size_t>(r) * cols;
    double rise_right = row_cover[cols];
    for (int c = cols - 1; c >= 0; --c) {
      row_area[c] += w * rise_right;
      rise_right += row_cover[c];
    }
  }
}

namespace {

/// Polygons in doubles, relative to an origin on the grid, for overlap areas: Sutherland–
/// Hodgman clipping by convex windows. (Clipper's Booleans give exact integer polygons, which
/// the output needs; the coverage only needs areas, at a twentieth of the cost.) A non-convex
/// polygon clipped by a convex window keeps its area, even where the result touches itself.
struct point_d {
  double x, y;
};
using polygon_d = std::vector<point_d>;

/// Keeps the part of `a` where dx (y - py) - dy (x - px) >= 0 (left of the directed line).
void clip_half_plane(polygon_d& a, polygon_d& scratch, double px, double py, double dx, double dy) {
  if (a.empty() || (dx == 0 && dy == 0)) return;
  auto f = [&](const point_d& q) { return dx * (q.y - py) - dy * (q.x - px); };
  // Nothing to cut when every vertex is on the kept side (most calls): a is left as it is.
  double fj = f(a.back());
  bool all_in = fj >= 0;
  for (std::size_t i = 0; i + 1 < a.size() && all_in; ++i) all_in = f(a[i]) >= 0;
  if (all_in) return;
  scratch.clear();
  for (std::size_t i = 0, j = a.size() - 1; i < a.size(); j = i++) {
    const double fi = f(a[i]);  // each vertex's value once (fj is the previous one's)
    if ((fi >= 0) != (fj >= 0)) {
      const double t = fj / (fj - fi);
      scratch.push_back({a[j].x + (a[i].x - a[j].x) * t, a[j].y + (a[i].y - a[j].y) * t});
    }
    if (fi >= 0) scratch.push_back(a[i]);
    fj = fi;
  }
  a.swap(scratch);
}

double signed_area(const polygon_d& a) {
  double twice = 0;
  for (std::size_t i = 0, j = a.size() - 1; i < a.size(); j = i++)
    twice += a[j].x * a[i].y - a[i].x * a[j].y;
  return 0.5 * twice;
}

/// `ring` relative to (ox, oy), clipped by the convex counter-clockwise `window`.
void clip_by_convex(const cl::Path& ring, const cl::Path& window, long long ox, long long oy,
                    polygon_d& out, polygon_d& scratch) {
  out.clear();
  for (const cl::IntPoint& q : ring)
    out.push_back({static_cast<double>(q.X - ox), static_cast<double>(q.Y - oy)});
  for (std::size_t k = 0; k < window.size() && !out.empty(); ++k) {
    const cl::IntPoint& w0 = window[k];
    const cl::IntPoint& w1 = window[(k + 1) % window.size()];
    clip_half_plane(out, scratch, static_cast<double>(w0.X - ox), static_cast<double>(w0.Y - oy),
                    static_cast<double>(w1.X - w0.X), static_cast<double>(w1.Y - w0.Y));
  }
}

/// Signed area of the part of `a` (relative coordinates) inside [x0, x1] x [y0, y1]; `work`
/// and `scratch` are buffers.
double area_in_box(const polygon_d& a, polygon_d& work, polygon_d& scratch, double x0, double y0,
                   double x1, double y1) {
  if (a.empty()) return 0;
  // Only the box's lines that cut the polygon's box clip it (most pieces cross one or two).
  double ax0 = a[0].x, ax1 = a[0].x, ay0 = a[0].y, ay1 = a[0].y;
  for (const point_d& q : a) {
    ax0 = std::min(ax0, q.x);
    ax1 = std::max(ax1, q.x);
    ay0 = std::min(ay0, q.y);
    ay1 = std::max(ay1, q.y);
  }
  if (ax1 <= x0 || ax0 >= x1 || ay1 <= y0 || ay0 >= y1) return 0;
  work.assign(a.begin(), a.end());
  if (ax0 < x0) clip_half_plane(work, scratch, x0, y0, 0, -1);  // x >= x0
  if (ax1 > x1) clip_half_plane(work, scratch, x1, y0, 0, 1);   // x <= x1
  if (ay0 < y0) clip_half_plane(work, scratch, x0, y0, 1, 0);   // y >= y0
  if (ay1 > y1) clip_half_plane(work, scratch, x0, y1, -1, 0);  // y <= y1
  return work.empty() ? 0 : signed_area(work);
}

/// The counter-clockwise simple ring cut into convex counter-clockwise triangles by ear
/// clipping (integer predicates, exact); false when no ear is found (a degenerate ring).
/// Straight vertices (collinear with their neighbours) are dropped first.
bool ear_triangles(const cl::Path& ring, std::vector<cl::Path>& out) {
  auto cross = [](const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
    return (b.X - a.X) * (c.Y - a.Y) - (b.Y - a.Y) * (c.X - a.X);
  };
  cl::Path r = ring;
  out.clear();
  while (r.size() > 3) {
    const std::size_t n = r.size();
    bool cut = false;
    for (std::size_t i = 0; i < n && !cut; ++i) {
      const cl::IntPoint& a = r[(i + n - 1) % n];
      const cl::IntPoint& b = r[i];
      const cl::IntPoint& c = r[(i + 1) % n];
      const long long turn = cross(a, b, c);
      if (turn == 0) {  // straight or a spike: no area at b
        r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
        cut = true;
        break;
      }
      if (turn < 0) continue;
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k) {
        if (k == i || k == (i + 1) % n || k == (i + n - 1) % n) continue;
        const cl::IntPoint& q = r[k];
        empty = !(cross(a, b, q) >= 0 && cross(b, c, q) >= 0 && cross(c, a, q) >= 0);
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
      cut = true;
    }
    if (!cut) return false;
  }
  if (r.size() == 3 && cross(r[0], r[1], r[2]) > 0) out.push_back(r);
  return true;
}

/// The lines through the edges of a polygon p, each with the range [lo, hi] of the sides (cross
/// products) of p's own vertices: what separated() reads of p, found once for all the pieces p
/// is tested against. Lines crossing p (lo < 0 < hi), of zero-length edges, or with all of p on
/// them separate nothing and are left out. For a convex counter-clockwise p with area every
/// line has p on its closed left, some vertex strictly: lo = 0 < hi, without reading p.
struct edge_lines {
  struct line {
    cl::IntPoint a;
    long long dx, dy, lo, hi;
  };
  std::vector<line> lines;

  void set(const cl::Path& p, bool convex) {
    lines.clear();
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
      const cl::IntPoint a = p[j], b = p[i];
      const long long dx = b.X - a.X, dy = b.Y - a.Y;
      if (dx == 0 && dy == 0) continue;
      long long lo = 0, hi = 1;
      if (!convex) {
        hi = 0;
        for (const cl::IntPoint& v : p) {
          const long long c = dx * (v.Y - a.Y) - dy * (v.X - a.X);
          lo = std::min(lo, c);
          hi = std::max(hi, c);
        }
        if ((lo < 0 && hi > 0) || (lo == 0 && hi == 0)) continue;
      }
      lines.push_back({a, dx, dy, lo, hi});
    }
  }
};

/// A ring's points, wherever they are kept.
struct ring_view {
  const cl::IntPoint* data = nullptr;
  std::size_t count = 0;
  const cl::IntPoint* begin() const { return data; }
  const cl::IntPoint* end() const { return data + count; }
  std::size_t size() const { return count; }
  const cl::IntPoint& operator[](std::size_t i) const { return data[i]; }
};

/// True when a line through an edge of p (its lines: pl) or of a ring of q has all of p on one
/// closed side and all of q on the other: then the interiors of any polygons with these
/// vertices are disjoint (each lies in the convex hull of its vertices). Integer cross
/// products, exact. q_convex: q is one convex counter-clockwise ring with area, so it lies on
/// the closed left of each of its own edges and only p's side needs reading there.
bool separated(const edge_lines& pl, const cl::Path& p, const std::vector<ring_view>& q,
               bool q_convex) {
  for (const edge_lines::line& l : pl.lines) {
    bool apart = true;
    for (const ring_view& r : q) {
      for (const cl::IntPoint& v : r) {
        const long long c = l.dx * (v.Y - l.a.Y) - l.dy * (v.X - l.a.X);
        if ((l.hi > 0 && c > 0) || (l.lo < 0 && c < 0)) {
          apart = false;
          break;
        }
      }
      if (!apart) break;
    }
    if (apart) return true;
  }
  for (const ring_view& ring : q)
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const cl::IntPoint a = ring[j], b = ring[i];
      const long long dx = b.X - a.X, dy = b.Y - a.Y;
      if (dx == 0 && dy == 0) continue;
      auto side = [&](const cl::IntPoint& v) { return dx * (v.Y - a.Y) - dy * (v.X - a.X); };
      if (q_convex) {  // q on the closed left: p must lie on the closed right (p has area)
        if (std::all_of(p.begin(), p.end(), [&](const cl::IntPoint& v) { return side(v) <= 0; }))
          return true;
        continue;
      }
      long long p_min = 0, p_max = 0;
      for (const cl::IntPoint& v : p) {
        const long long c = side(v);
        p_min = std::min(p_min, c);
        p_max = std::max(p_max, c);
      }
      if ((p_min < 0 && p_max > 0) || (p_min == 0 && p_max == 0)) continue;
      bool apart = true;
      for (const ring_view& r : q) {
        for (const cl::IntPoint& v : r) {
          const long long c = side(v);
          if ((p_max > 0 && c > 0) || (p_min < 0 && c < 0)) {
            apart = false;
            break;
          }
        }
        if (!apart) break;
      }
      if (apart) return true;
    }
  return false;
}

/// The winding number of the ring about q + (e, e^2) for every small enough e > 0 (Sunday's
/// crossing rule; a zero cross product is decided by the nudge's first nonzero term: exact).
int nudged_winding(const cl::Path& r, const cl::IntPoint& q) {
  int w = 0;
  for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    const cl::IntPoint& a = r[j];
    const cl::IntPoint& b = r[i];
    // Side of the nudged q: positive to the left of a -> b.
    long long side = (b.X - a.X) * (q.Y - a.Y) - (q.X - a.X) * (b.Y - a.Y);
    if (side == 0) side = b.Y != a.Y ? a.Y - b.Y : b.X - a.X;
    // Integer ordinates: q.Y + e^2 is above a.Y iff q.Y >= a.Y, below b.Y iff q.Y < b.Y.
    if (a.Y <= q.Y) {
      if (b.Y > q.Y && side > 0) ++w;
    } else if (b.Y <= q.Y && side < 0) {
      --w;
    }
  }
  return w;
}

/// True when the box lies on the closed right side of the line through an edge of the convex
/// counter-clockwise ring p (p on its left): then separated(p, q) holds for any q in the box,
/// found from one corner per edge (the one farthest left) without reading q.
bool box_beyond_an_edge(const cl::Path& p, const bbox_i& box) {
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const cl::IntPoint a = p[j], b = p[i];
    const long long dx = b.X - a.X, dy = b.Y - a.Y;
    const long long x = dy > 0 ? box.x0 : box.x1, y = dx > 0 ? box.y1 : box.y0;
    if (dx * (y - a.Y) - dy * (x - a.X) <= 0) return true;
  }
  return false;
}

}  // namespace

/// tiled_coverage's state: screen coverage as the list of visible pieces so far (disjoint: each is
/// what was left of a polygon after removing the earlier ones), indexed by square tiles. A piece is
/// listed in every tile its bounding box meets, whole (never cut at tile lines, so no rounded point
/// is made there); each tile sums the area of the pieces inside it, and a tile whose sum reaches
/// its own area is full: it rejects everything behind it at once, and stands for its pieces
/// as one square. A new polygon P is fully visible when a line through an edge separates it
/// from every nearby piece (integer cross products: exact; shared edges of a mesh separate);
/// the pieces it is not separated from are then weighed by overlap area (overlap_outcome:
/// none, visible; all of P, hidden), and only a partly hidden P goes to Clipper, with those
/// pieces. Nonzero fill with every outer ring counter-clockwise (holes clockwise) makes a list
/// of pieces mean their union.
class tiled_coverage::impl {
 public:
  static constexpr long long tile_side = tiled_coverage::tile_side;

  /// Tile rows [row0, row0 + rows) of a viewport `width` grid units wide.
  impl(long long width, int row0, int rows)
      : nx_(static_cast<int>(std::max<long long>(1, (width + tile_side - 1) / tile_side))),
        ny_(std::max(1, rows)),
        row0_(row0),
        tiles_(static_cast<std::size_t>(nx_) * ny_) {}

  /// True when every tile the box meets is full.
  bool hides(const bbox_i& box) const {
    const auto [tx0, ty0, tx1, ty1] = tile_range(box);
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx)
        if (!tiles_[index(tx, ty)].full) return false;
    return true;
  }

  /// Adds the counter-clockwise polygon p (moved from when wholly visible); returns the id of
  /// its part not covered before (a piece: rings()), or no_piece when it is hidden.
  std::uint32_t add(cl::Path& p, std::uint32_t mesh) {
    if (hides(bbox_of(p))) return no_piece;
    near_.clear();
    const bool convex = convex_ccw(p);
    lines_.set(p, convex);
    gather(bbox_of(p), [&](const cl::Paths& rings, bool square, bool convex_piece,
                           const bbox_i& box, const std::vector<ring_view>& points) {
      if (convex && box_beyond_an_edge(p, box)) return;  // separated (a cheaper first test)
      if (!separated(lines_, p, points, convex_piece)) near_.push_back({&rings, square});
    });
    switch (near_.empty() ? outcome::visible : overlap_outcome(p)) {
      case outcome::visible: {
        cl::Paths whole(1);
        whole[0].swap(p);
        return insert(std::move(whole), mesh);
      }
      case outcome::hidden:
        return no_piece;
      case outcome::unknown:
        break;
    }
    clipper_.Clear();
    clipper_.AddPath(p, cl::ptSubject, true);
    for (const candidate& c : near_) clipper_.AddPaths(*c.rings, cl::ptClip, true);
    cl::Paths out;
    clipper_.Execute(cl::ctDifference, out, cl::pftNonZero, cl::pftNonZero);

    return out.empty() ? no_piece : insert(std::move(out), mesh);
  }

  /// Rectangles (counter-clockwise) tiling the full tiles whose pieces all belong to `mesh`:
  /// runs along each row of tiles.
  cl::Paths full_tiles_of(std::uint32_t mesh) const {
    cl::Paths out;
    for (int ty = 0; ty < ny_; ++ty)
      for (int tx = 0; tx < nx_;) {
        if (!of_mesh(tx, ty, mesh)) {
          ++tx;
          continue;
        }
        int end = tx + 1;
        while (end < nx_ && of_mesh(end, ty, mesh)) ++end;
        const long long x0 = tx * tile_side, x1 = end * tile_side, y0 = (ty + row0_) * tile_side,
                        y1 = y0 + tile_side;
        out.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
        tx = end;
      }
    return out;
  }

  /// True when every tile the box meets is full of pieces of `mesh` only.
  bool inside_full_tiles_of(const bbox_i& box, std::uint32_t mesh) const {
    const auto [tx0, ty0, tx1, ty1] = tile_range(box);
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx)
        if (!of_mesh(tx, ty, mesh)) return false;
    return true;
  }

  /// The rings of piece `id` (outer rings counter-clockwise, holes clockwise).
  const cl::Paths& rings(std::uint32_t id) const { return pieces_[id].rings; }

  /// The parts of the open polyline `line` outside the coverage.
  cl::Paths outside(const cl::Path& line) {
    cl::Paths clip;
    gather(bbox_of(line),
           [&](const cl::Paths& rings, bool, bool, const bbox_i&, const std::vector<ring_view>&) {
             clip.insert(clip.end(), rings.begin(), rings.end());
           });
    if (clip.empty()) return {line};
    clipper_.Clear();
    clipper_.AddPath(line, cl::ptSubject, false);
    clipper_.AddPaths(clip, cl::ptClip, true);
    cl::PolyTree tree;
    clipper_.Execute(cl::ctDifference, tree, cl::pftNonZero, cl::pftNonZero);
    cl::Paths out;
    cl::OpenPathsFromPolyTree(tree, out);
    return out;
  }

  /// True when the point q + (e, e^2), for every small enough e > 0, has a nonzero winding
  /// number in the coverage: q nudged off every line through it, so that a point on the shared
  /// boundary of two pieces or two full tiles counts as covered, as it is.
  bool covers(const cl::IntPoint& q) {
    int winding = 0;
    gather({q.X, q.Y, q.X, q.Y},
           [&](const cl::Paths& rings, bool, bool, const bbox_i&, const std::vector<ring_view>&) {
             for (const cl::Path& r : rings) winding += nudged_winding(r, q);
           });
    return winding != 0;
  }

 private:
  struct piece {
    cl::Paths rings;  ///< outer rings counter-clockwise, holes clockwise
  };
  /// A piece as listed in a tile: its id and box (grid units fit 32 bits), so that the box
  /// test reads the tile's own memory.
  struct listed {
    std::int32_t x0, y0, x1, y1;
    std::uint32_t id;
    std::uint32_t flat;   ///< its one ring's first point in flat_ (count > 0)
    std::uint16_t count;  ///< its one ring's points in flat_; 0: read its rings
    bool convex;          ///< one convex counter-clockwise ring
  };
  struct tile {
    std::vector<listed> pieces;
    double area = 0;  ///< of the pieces' parts inside the tile, square units
    bool full = false;
    cl::Paths square;        ///< once full: the tile's square, standing for its pieces
    std::int64_t mesh = -1;  ///< the mesh of every piece listed here; -1 none yet, -2 several
  };

  std::size_t index(int tx, int ty) const { return static_cast<std::size_t>(ty) * nx_ + tx; }

  bool of_mesh(int tx, int ty, std::uint32_t mesh) const {
    const tile& t = tiles_[index(tx, ty)];
    return t.full && t.mesh == mesh;
  }

  std::array<int, 4> tile_range(const bbox_i& b) const {
    auto clamp_x = [&](long long v) {
      return static_cast<int>(std::clamp<long long>(v / tile_side, 0, nx_ - 1));
    };
    auto clamp_y = [&](long long v) {
      return static_cast<int>(std::clamp<long long>(v / tile_side - row0_, 0, ny_ - 1));
    };
    return {clamp_x(std::max(0LL, b.x0)), clamp_y(std::max(0LL, b.y0)),
            clamp_x(std::max(0LL, b.x1)), clamp_y(std::max(0LL, b.y1))};
  }

  cl::Path square(int tx, int ty) const {
    const long long x0 = tx * tile_side, y0 = (ty + row0_) * tile_side;
    return {{x0, y0}, {x0 + tile_side, y0}, {x0 + tile_side, y0 + tile_side}, {x0, y0 + tile_side}};
  }

  /// Lists the piece in the tiles its box meets and adds its area to theirs.
  std::uint32_t insert(cl::Paths rings, std::uint32_t mesh) {
    bbox_i box = bbox_of(rings[0]);
    for (const cl::Path& r : rings) {
      const bbox_i b = bbox_of(r);
      box = {std::min(box.x0, b.x0), std::min(box.y0, b.y0), std::max(box.x1, b.x1),
             std::max(box.y1, b.y1)};
    }
    const auto id = static_cast<std::uint32_t>(pieces_.size());
    // Plain variables (a lambda below reads them; clang refuses structured bindings there).
    const std::array<int, 4> range = tile_range(box);
    const int tx0 = range[0], ty0 = range[1], tx1 = range[2], ty1 = range[3];
    const double tile_area = static_cast<double>(tile_side) * static_cast<double>(tile_side);
    const bool convex = rings.size() == 1 && convex_ccw(rings[0]);
    // A piece of one ring is also copied to flat_, read by the tiles' lists directly (one
    // memory read where the rings are three, each likely a cache miss).
    const auto flat = static_cast<std::uint32_t>(flat_.size());
    std::uint16_t count = 0;
    if (rings.size() == 1 && rings[0].size() <= 0xffff &&
        flat_.size() + rings[0].size() <= 0xffffffffu) {
      count = static_cast<std::uint16_t>(rings[0].size());
      flat_.insert(flat_.end(), rings[0].begin(), rings[0].end());
    }
    // A piece in one tile adds its area there; one over several tiles adds its part in each,
    // all found in one pass over its edges (cell_areas).
    const long long ox = tx0 * tile_side, oy = (ty0 + row0_) * tile_side;
    const bool in_one =
        box.x0 >= ox && box.x1 <= ox + tile_side && box.y0 >= oy && box.y1 <= oy + tile_side;
    const int cols = tx1 - tx0 + 1;
    if (!in_one) cell_areas(rings, ox, oy, tile_side, cols, ty1 - ty0 + 1, cell_area_, cell_cover_);
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        tile& t = tiles_[index(tx, ty)];
        if (t.full) continue;
        t.mesh = t.mesh == -1 || t.mesh == mesh ? mesh : -2;
        t.pieces.push_back({static_cast<std::int32_t>(box.x0), static_cast<std::int32_t>(box.y0),
                            static_cast<std::int32_t>(box.x1), static_cast<std::int32_t>(box.y1),
                            id, flat, count, convex});
        if (!in_one) {
          t.area += cell_area_[static_cast<std::size_t>((ty - ty0) * cols + (tx - tx0))];
        } else if (tx == tx0 && ty == ty0) {
          for (const cl::Path& r : rings)
            t.area += 0.5 * twice_area_from(r, static_cast<double>(ox), static_cast<double>(oy));
        }
        // Pieces are disjoint, so the sum never exceeds the tile but by rounding; a shortfall
        // under half a square unit is no gap any region could be seen through.
        if (t.area >= tile_area - 0.5) {
          t.full = true;
          t.pieces.clear();
          t.pieces.shrink_to_fit();
          t.square = {square(tx, ty)};
        }
      }
    pieces_.push_back({std::move(rings)});
    stamp_.push_back(0);
    return id;
  }

  /// Calls visit(rings, is_square, is_convex, its box, its rings' points) for each piece near
  /// `box` (each once) and for the square of each full tile `box` meets (convex).
  template <class Visit>
  void gather(const bbox_i& box, Visit visit) {
    ++query_;
    const auto [tx0, ty0, tx1, ty1] = tile_range(box);
    const bool point = box.x0 == box.x1 && box.y0 == box.y1;
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        const tile& t = tiles_[index(tx, ty)];
        if (t.full) {
          const cl::Path& sq = t.square[0];
          views_.assign(1, ring_view{sq.data(), sq.size()});
          visit(t.square, true, true, bbox_i{sq[0].X, sq[0].Y, sq[2].X, sq[2].Y}, views_);
          continue;
        }
        for (const listed& l : t.pieces) {
          // Boxes meeting only along a line cannot overlap (unless the query is a point).
          const bool apart =
              point ? l.x1 < box.x0 || l.x0 > box.x1 || l.y1 < box.y0 || l.y0 > box.y1
                    : l.x1 <= box.x0 || l.x0 >= box.x1 || l.y1 <= box.y0 || l.y0 >= box.y1;
          if (apart || stamp_[l.id] == query_) continue;
          stamp_[l.id] = query_;
          const cl::Paths& rings = pieces_[l.id].rings;  // read only when needed
          views_.clear();
          if (l.count > 0) {
            views_.push_back({flat_.data() + l.flat, l.count});
          } else {
            for (const cl::Path& r : rings) views_.push_back({r.data(), r.size()});
          }
          visit(rings, false, l.convex, bbox_i{l.x0, l.y0, l.x1, l.y1}, views_);
        }
      }
  }

  enum class outcome { visible, hidden, unknown };

  /// What the candidates near_ (pieces and full squares not separated from p) leave of p, when
  /// areas decide it. p is cut into convex windows (itself, or its ear triangles), each
  /// candidate clipped by them. Every overlap under min_overlap (times p's area when that is
  /// under one square unit): p is visible (the T-junction chains of a mesh, which no single
  /// line separates). The covered area (full squares, plus
  /// the pieces outside them: pieces are disjoint, squares are disjoint, but a piece may reach
  /// into a full square) within half a square unit of p's: hidden. Otherwise (a partial
  /// overlap, or no convex windows) Clipper decides.
  outcome overlap_outcome(const cl::Path& p) {
    // The windows: p itself when convex (not copied), or its ear triangles.
    const cl::Path* window_list = &p;
    std::size_t window_count = 1;
    const double area = cl::Area(p);
    if (!convex_ccw(p)) {
      if (!ear_triangles(p, windows_)) return outcome::unknown;
      long long twice = 0;
      for (const cl::Path& w : windows_)
        twice += (w[1].X - w[0].X) * (w[2].Y - w[0].Y) - (w[1].Y - w[0].Y) * (w[2].X - w[0].X);
      if (static_cast<double>(twice) != 2 * area) return outcome::unknown;
      window_list = windows_.data();
      window_count = windows_.size();
    }
    const long long ox = p[0].X, oy = p[0].Y;
    double covered = 0, largest = 0;
    for (const candidate& c : near_) {
      double overlap = 0, in_squares = 0;
      for (std::size_t k = 0; k < window_count; ++k)
        for (const cl::Path& r : *c.rings) {
          clip_by_convex(r, window_list[k], ox, oy, poly_, scratch_);
          if (poly_.empty()) continue;
          overlap += signed_area(poly_);
          if (c.square) continue;
          for (const candidate& q : near_)
            if (q.square) {
              const cl::Path& sq = (*q.rings)[0];
              in_squares +=
                  area_in_box(poly_, work_, scratch_, static_cast<double>(sq[0].X - ox),
                              static_cast<double>(sq[0].Y - oy), static_cast<double>(sq[2].X - ox),
                              static_cast<double>(sq[2].Y - oy));
            }
        }
      largest = std::max(largest, overlap);
      covered += overlap - in_squares;
      // What is left of the candidates only adds cover (each term is an area outside the
      // squares): once p is covered, it is hidden whatever they hold.
      if (covered >= area - 0.5 && largest >= min_overlap * std::min(1.0, area))
        return outcome::hidden;
    }
    if (largest < min_overlap * std::min(1.0, area)) return outcome::visible;
    if (covered >= area - 0.5) return outcome::hidden;
    return outcome::unknown;
  }

  /// Overlaps under this many square units are rounding, not cover (1/10^7 pixel).
  static constexpr double min_overlap = 1e-3;

  struct candidate {
    const cl::Paths* rings;
    bool square;
  };
  std::vector<candidate> near_;
  edge_lines lines_;  ///< add's polygon's
  std::vector<cl::Path> windows_;
  polygon_d poly_, work_, scratch_;
  std::vector<double> cell_area_, cell_cover_;  ///< insert's cell_areas

  int nx_, ny_;
  int row0_;  ///< the first tile row held (tile_range and the tiles' corners count from it)
  std::vector<tile> tiles_;
  std::vector<piece> pieces_;
  std::vector<std::uint32_t> stamp_;
  std::vector<cl::IntPoint> flat_;  ///< the points of the pieces of one ring (listed::flat)
  std::vector<ring_view> views_;    ///< gather's, for the piece it visits
  std::uint32_t query_ = 0;
  cl::Clipper clipper_;
};

tiled_coverage::tiled_coverage(long long width, long long height)
    : impl_(std::make_unique<impl>(width, 0,
                                   static_cast<int>((height + tile_side - 1) / tile_side))) {}
tiled_coverage::tiled_coverage(long long width, int row0, int rows)
    : impl_(std::make_unique<impl>(width, row0, rows)) {}
tiled_coverage::~tiled_coverage() = default;
bool tiled_coverage::hides(const bbox_i& box) const { return impl_->hides(box); }
std::uint32_t tiled_coverage::add(cl::Path& p, std::uint32_t mesh) { return impl_->add(p, mesh); }
const cl::Paths& tiled_coverage::rings(std::uint32_t id) const { return impl_->rings(id); }
cl::Paths tiled_coverage::full_tiles_of(std::uint32_t mesh) const {
  return impl_->full_tiles_of(mesh);
}
bool tiled_coverage::inside_full_tiles_of(const bbox_i& box, std::uint32_t mesh) const {
  return impl_->inside_full_tiles_of(box, mesh);
}
cl::Paths tiled_coverage::outside(const cl::Path& line) { return impl_->outside(line); }
bool tiled_coverage::covers(const cl::IntPoint& q) { return impl_->covers(q); }

/// t_junction_mender's state. T-junctions: where a vertex of one polygon lies inside an edge of
/// another (a BSP split point on a neighbour's edge), rounding to the grid moves it up to half a
/// unit off that edge and opens a crack through which what is behind would show. Every vertex lying
/// less than one unit from the inside of an edge of another polygon is inserted into that edge, so
/// the two share the boundary exactly. Vertices are found in a grid of 1-pixel cells (each cell's
/// distinct points, sorted, in one array: a counting sort), walking the cells along each edge;
/// a polygon is mended only when it may be visible.
class t_junction_mender::impl {
 public:
  impl(const std::vector<cl::IntPoint>& points, long long width, long long height)
      : nx_(std::max<long long>(1, (width + cell - 1) / cell + 2)),
        ny_(std::max<long long>(1, (height + cell - 1) / cell + 2)),
        start_(static_cast<std::size_t>(nx_ * ny_) + 1, 0) {
    for (const cl::IntPoint& q : points) ++start_[cell_index(q.X, q.Y) + 1];
    for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
    points_.resize(start_.back());
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (const cl::IntPoint& q : points) points_[next[cell_index(q.X, q.Y)]++] = q;
    // Each cell's points sorted and made distinct (shared corners appear once per polygon).
    std::size_t out = 0;
    for (std::size_t c = 0; c + 1 < start_.size(); ++c) {
      const auto first = points_.begin() + static_cast<std::ptrdiff_t>(start_[c]);
      const auto last = points_.begin() + static_cast<std::ptrdiff_t>(start_[c + 1]);
      start_[c] = out;
      if (last - first <= 1) {  // most cells hold none or one point: nothing to sort
        if (last != first) points_[out++] = *first;
        continue;
      }
      std::sort(first, last, [](const cl::IntPoint& a, const cl::IntPoint& b) {
        return a.X != b.X ? a.X < b.X : a.Y < b.Y;
      });
      const auto end = std::unique(first, last);
      out = static_cast<std::size_t>(
          std::copy(first, end, points_.begin() + static_cast<std::ptrdiff_t>(out)) -
          points_.begin());
    }
    start_.back() = out;
    points_.resize(out);
  }

  /// Inserts into p's edges the vertices lying less than one unit from their insides.
  void mend(cl::Path& p, t_junction_mender::scratch& s) const {
    cl::Path& mended = s.mended;
    cl::Path& near = s.candidates;
    std::vector<std::pair<double, cl::IntPoint>>& on_edge = s.on_edge;
    mended.clear();
    // Candidates: the indexed points in the cells met by the polygon's box grown by two units
    // (one for the one-unit neighbourhood, one for rounding). A point less than one unit from
    // an edge's inside lies in it. The cells of one row are contiguous in points_, so a row
    // of cells is one range (two reads of start_, whose millions of entries miss the cache).
    // Most polygons are a few pixels wide: their candidates are a handful of points, gathered
    // once for all their edges. A large polygon gathers per edge, from the rows of cells met by
    // pieces of at most one cell of the edge.
    const bbox_i box = bbox_of(p);
    const long long px0 = cell_x(box.x0 - 2), px1 = cell_x(box.x1 + 2);
    const long long py0 = cell_y(box.y0 - 2), py1 = cell_y(box.y1 + 2);
    const bool per_polygon = (px1 - px0 + 1) * (py1 - py0 + 1) <= 36;
    if (per_polygon) {
      near.clear();
      gather(px0, px1, py0, py1, near);
      // Only points less than one unit from the polygon can be less than one unit from an
      // edge: those in its box grown by one (about half the cells' points), tested per edge.
      near.erase(std::remove_if(near.begin(), near.end(),
                                [&](const cl::IntPoint& v) {
                                  return v.X < box.x0 - 1 || v.X > box.x1 + 1 || v.Y < box.y0 - 1 ||
                                         v.Y > box.y1 + 1;
                                }),
                 near.end());
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
      const cl::IntPoint a = p[i], b = p[(i + 1) % p.size()];
      mended.push_back(a);
      const double dx = static_cast<double>(b.X - a.X), dy = static_cast<double>(b.Y - a.Y);
      const double len2 = dx * dx + dy * dy, len = std::sqrt(len2);
      on_edge.clear();
      const auto test = [&](const cl::IntPoint& v) {
        const double vx = static_cast<double>(v.X - a.X), vy = static_cast<double>(v.Y - a.Y);
        const double along = vx * dx + vy * dy;
        if (along <= 0 || along >= len2) return;
        if (std::abs(vx * dy - vy * dx) >= len) return;  // one unit or more off the line
        on_edge.push_back({along, v});
      };
      if (per_polygon) {
        for (const cl::IntPoint& v : near) test(v);
      } else {
        near.clear();
        const long long pieces = static_cast<long long>(len / cell) + 1;
        for (long long k = 0; k < pieces; ++k) {
          const double t0 = static_cast<double>(k) / static_cast<double>(pieces),
                       t1 = static_cast<double>(k + 1) / static_cast<double>(pieces);
          const long long x0 = a.X + std::llround(t0 * dx), x1 = a.X + std::llround(t1 * dx);
          const long long y0 = a.Y + std::llround(t0 * dy), y1 = a.Y + std::llround(t1 * dy);
          gather(cell_x(std::min(x0, x1) - 2), cell_x(std::max(x0, x1) + 2),
                 cell_y(std::min(y0, y1) - 2), cell_y(std::max(y0, y1) + 2), near);
        }
        for (const cl::IntPoint& v : near) test(v);  // repeats sort next to each other
      }
      std::sort(on_edge.begin(), on_edge.end(), [](const auto& x, const auto& y) {
        return x.first != y.first
                   ? x.first < y.first
                   : (x.second.X != y.second.X ? x.second.X < y.second.X : x.second.Y < y.second.Y);
      });
      for (const auto& [along, v] : on_edge)
        if (!(mended.back() == v)) mended.push_back(v);
    }
    if (mended.size() != p.size()) p.assign(mended.begin(), mended.end());
  }

 private:
  static constexpr long long cell = grid_per_pixel;
  // Cells are clamped into the grid, with one extra cell on every side for points rounded
  // just outside the viewport: a point is always found in the cell it was filed under.
  long long cell_x(long long v) const {
    return std::clamp<long long>(floor_div(v, cell) + 1, 0, nx_ - 1);
  }
  long long cell_y(long long v) const {
    return std::clamp<long long>(floor_div(v, cell) + 1, 0, ny_ - 1);
  }
  std::size_t cell_index(long long x, long long y) const {
    return static_cast<std::size_t>(cell_y(y) * nx_ + cell_x(x));
  }
  /// Appends the points of the cells [cx0, cx1] x [cy0, cy1] to `out`.
  void gather(long long cx0, long long cx1, long long cy0, long long cy1, cl::Path& out) const {
    for (long long cy = cy0; cy <= cy1; ++cy) {
      const auto row = static_cast<std::size_t>(cy * nx_);
      out.insert(out.end(), points_.begin() + static_cast<std::ptrdiff_t>(start_[row + cx0]),
                 points_.begin() + static_cast<std::ptrdiff_t>(start_[row + cx1 + 1]));
    }
  }

  long long nx_, ny_;
  std::vector<std::size_t> start_;  ///< cell c's points: points_[start_[c], start_[c + 1])
  std::vector<cl::IntPoint> points_;
};

t_junction_mender::t_junction_mender(const std::vector<cl::IntPoint>& points, long long width,
                                     long long height)
    : impl_(std::make_unique<impl>(points, width, height)) {}
t_junction_mender::~t_junction_mender() = default;
void t_junction_mender::mend(cl::Path& p, scratch& s) const { impl_->mend(p, s); }

}  // namespace exbsp::view::cover
