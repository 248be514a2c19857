// SPDX-License-Identifier: LGPL-3.0-or-later
// The outward-closed certificate (notation in closed_shells.h).
//
// Written here rather than with CGAL's Polygon_mesh_processing (is_closed, does_self_intersect,
// is_outward_oriented): those packages, and Surface_mesh and Box_intersection_d under them, are
// GPL, and this file belongs to the LGPL core (docs/licence.md). The exact tests themselves are
// CGAL's LGPL kernel predicates (collinear, coplanar, coplanar_orientation, do_intersect of
// triangles and segments with Epick's filtered exact predicates); the boxes are paired by a
// Boost.Geometry R-tree.
#include "geom/closed_shells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "geom/homogeneous_det.h"
#include "geom/weld.h"

namespace exbsp::geom {

namespace {

using kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using point3 = kernel::Point_3;
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using box_point = bg::model::point<double, 3, bg::cs::cartesian>;

/// One mesh's triangles over its welded vertices.
struct welded_mesh {
  std::vector<point3> points;                      ///< by welded id
  std::vector<std::array<std::uint32_t, 3>> tris;  ///< welded ids, the soup's corner order
};

/// Mesh `triangles` over compact ids of the soup's welded vertices (`welded`: weld() of
/// soup.vertices; `local`: welded.count entries, all unset, and left so).
welded_mesh weld_mesh(const triangle_soup& soup, const std::vector<std::uint32_t>& triangles,
                      const welded_ids& welded, std::vector<std::uint32_t>& local) {
  constexpr std::uint32_t unset = std::numeric_limits<std::uint32_t>::max();
  welded_mesh m;
  m.tris.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = soup.triangles[triangles[t]].v[k];
      std::uint32_t& id = local[welded.id[v]];
      if (id == unset) {
        id = static_cast<std::uint32_t>(m.points.size());
        const vec3d& p = soup.vertices[v];
        m.points.emplace_back(p[0], p[1], p[2]);
      }
      m.tris[t][k] = id;
    }
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t v : soup.triangles[triangles[t]].v) local[welded.id[v]] = unset;
  return m;
}

/// True when triangles i and j meet beyond their shared welded vertices and edges.
bool meet_beyond_shared(const welded_mesh& m, std::size_t i, std::size_t j) {
  const auto& a = m.tris[i];
  const auto& b = m.tris[j];
  int shared = 0, ai = -1, bj = -1;  // the first shared corner's positions in a and b
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      if (a[x] == b[y]) {
        if (shared++ == 0) {
          ai = x;
          bj = y;
        }
      }
  const auto P = [&](std::uint32_t v) -> const point3& { return m.points[v]; };
  if (shared == 3) return true;  // the same three points: they overlap
  if (shared == 2) {
    // Sharing edge pq: non-coplanar triangles meet only in it; coplanar ones overlap when their
    // third corners lie on the same side of pq.
    std::uint32_t p = 0, q = 0, r = 0, s = 0;
    int found = 0;
    for (int x = 0; x < 3; ++x) {
      if (a[x] == b[0] || a[x] == b[1] || a[x] == b[2])
        (found++ == 0 ? p : q) = a[x];
      else
        r = a[x];
    }
    for (int y = 0; y < 3; ++y)
      if (b[y] != p && b[y] != q) s = b[y];
    if (!CGAL::coplanar(P(p), P(q), P(r), P(s))) return false;
    return CGAL::coplanar_orientation(P(p), P(q), P(r), P(s)) == CGAL::POSITIVE;
  }
  if (shared == 1) {
    // Sharing vertex p only: they meet elsewhere exactly when the side of one opposite p meets
    // the other (along a ray from p in both, the shorter of the two segments ends on such a
    // side, inside the other triangle).
    // Most such pairs are settled by a plane: when both other corners of one triangle lie
    // strictly on one side of the other's plane, they meet that plane at p alone.
    const point3 &p = P(a[ai]), &q = P(a[(ai + 1) % 3]), &r = P(a[(ai + 2) % 3]);
    const point3 &s = P(b[(bj + 1) % 3]), &t = P(b[(bj + 2) % 3]);
    const CGAL::Orientation os = CGAL::orientation(p, q, r, s);
    if (os != CGAL::COPLANAR && os == CGAL::orientation(p, q, r, t)) return false;
    const CGAL::Orientation oq = CGAL::orientation(p, s, t, q);
    if (oq != CGAL::COPLANAR && oq == CGAL::orientation(p, s, t, r)) return false;
    return CGAL::do_intersect(kernel::Segment_3(q, r), kernel::Triangle_3(p, s, t)) ||
           CGAL::do_intersect(kernel::Segment_3(s, t), kernel::Triangle_3(p, q, r));
  }
  return CGAL::do_intersect(kernel::Triangle_3(P(a[0]), P(a[1]), P(a[2])),
                            kernel::Triangle_3(P(b[0]), P(b[1]), P(b[2])));
}

/// Per vertex: 1 when its star is certified embedded: its triangles form one cycle around it
/// (each (p, a, b) followed by the one starting (p, b, ...)), and dropping one coordinate (that
/// of the first triangle's largest normal component, a choice only) maps every one of them to
/// a counter-clockwise triangle while the cycle winds exactly once around p. The projected
/// triangles then tile the angle around p once, so two of them meet only in p or in their
/// shared side, and so do the triangles themselves (a projection of a triangle with area is
/// one to one). Every test is exact: orient2d on the input doubles, comparisons of coordinates.
std::vector<std::uint8_t> embedded_stars(const welded_mesh& m) {
  const std::size_t nv = m.points.size();
  std::vector<std::uint32_t> start(nv + 1, 0);  // the star of v: corners [start[v], start[v+1])
  for (const auto& t : m.tris)
    for (std::uint32_t v : t) ++start[v + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fan(start.back());  // (a, b) of (p, a, b)
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (const auto& t : m.tris)
    for (int k = 0; k < 3; ++k) fan[next[t[k]]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
  using point2 = kernel::Point_2;
  std::vector<std::uint8_t> ok(nv, 0);
  std::vector<std::uint32_t> cycle;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t first = start[v], deg = start[v + 1] - first;
    if (deg < 3) continue;
    cycle.clear();
    cycle.push_back(fan[first].first);
    std::uint32_t b = fan[first].second;
    while (b != cycle.front() && cycle.size() <= deg) {
      cycle.push_back(b);
      std::uint32_t found = deg;
      for (std::uint32_t i = 0; i < deg; ++i)
        if (fan[first + i].first == b) found = i;
      if (found == deg) break;
      b = fan[first + found].second;
    }
    if (b != cycle.front() || cycle.size() != deg) continue;  // pinched or open: not one cycle
    const point3& p = m.points[v];
    const point3& qa = m.points[cycle[0]];
    const point3& qb = m.points[cycle[1]];
    const double n[3] = {(qa.y() - p.y()) * (qb.z() - p.z()) - (qa.z() - p.z()) * (qb.y() - p.y()),
                         (qa.z() - p.z()) * (qb.x() - p.x()) - (qa.x() - p.x()) * (qb.z() - p.z()),
                         (qa.x() - p.x()) * (qb.y() - p.y()) - (qa.y() - p.y()) * (qb.x() - p.x())};
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (std::abs(n[a]) > std::abs(n[axis])) axis = a;
    const double flip = n[axis] < 0 ? -1 : 1;    // negating a double is exact
    const auto project = [&](const point3& q) {  // (u, v) cyclic after the dropped axis
      const double c[3] = {q.x(), q.y(), q.z()};
      return point2(flip * c[(axis + 1) % 3], c[(axis + 2) % 3]);
    };
    const point2 pp = project(p);
    const auto upper = [&](const point2& q) {  // the half-plane of angles [0, pi) around pp
      return q.y() > pp.y() || (q.y() == pp.y() && q.x() > pp.x());
    };
    bool turning = true;
    int wraps = 0;
    point2 prev = project(m.points[cycle.back()]);
    for (std::uint32_t i = 0; i < deg && turning; ++i) {
      const point2 q = project(m.points[cycle[i]]);
      turning = CGAL::orientation(pp, prev, q) == CGAL::LEFT_TURN;
      wraps += !upper(prev) && upper(q);  // a turn in (0, pi) from below crosses angle 0
      prev = q;
    }
    ok[v] = turning && wraps == 1;
  }
  return ok;
}

/// True when triangles i and j lie in one certified star (embedded_stars): they meet only in
/// their shared vertex or side, no test needed.
bool certified_apart(const welded_mesh& m, const std::vector<std::uint8_t>& star_ok, std::size_t i,
                     std::size_t j) {
  const auto& a = m.tris[i];
  const auto& b = m.tris[j];
  for (std::uint32_t v : a)
    if (star_ok[v] && (v == b[0] || v == b[1] || v == b[2])) return true;
  return false;
}

/// A triangle's bounding box.
struct tri_box {
  double lo[3], hi[3];
};

bool boxes_meet(const tri_box& a, const tri_box& b) {  // closed boxes: touching counts
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

/// Some pair of triangles meets beyond its shared vertices and edges. Candidate pairs are those
/// whose boxes meet: found in a uniform grid of cells twice the median triangle's size (each
/// pair tested once, in the cell holding the low corner of the boxes' common part; pairs in one
/// certified star skipped); triangles over more than 64 cells are paired with every other
/// through a Boost.Geometry R-tree instead.
bool self_intersecting(const welded_mesh& m) {
  const std::vector<std::uint8_t> star_ok = embedded_stars(m);
  const std::size_t n = m.tris.size();
  std::vector<tri_box> boxes(n);
  tri_box all{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  std::vector<double> extent(n);
  for (std::size_t t = 0; t < n; ++t) {
    tri_box& b = boxes[t];
    for (int k = 0; k < 3; ++k) {
      const point3& p = m.points[m.tris[t][k]];
      const double c[3] = {p.x(), p.y(), p.z()};
      for (int a = 0; a < 3; ++a) {
        b.lo[a] = k == 0 ? c[a] : std::min(b.lo[a], c[a]);
        b.hi[a] = k == 0 ? c[a] : std::max(b.hi[a], c[a]);
      }
    }
    extent[t] = 0;
    for (int a = 0; a < 3; ++a) {
      all.lo[a] = std::min(all.lo[a], b.lo[a]);
      all.hi[a] = std::max(all.hi[a], b.hi[a]);
      extent[t] = std::max(extent[t], b.hi[a] - b.lo[a]);
    }
  }
  std::nth_element(extent.begin(), extent.begin() + static_cast<std::ptrdiff_t>(n / 2),
                   extent.end());
  // Cells: at most 8 per triangle in all (a larger cell otherwise); the cell arithmetic only
  // chooses candidates, every decision is the exact test's.
  double h = 2 * extent[n / 2];
  double dims[3];
  for (;;) {
    double cells = 1;
    for (int a = 0; a < 3; ++a) {
      dims[a] = std::floor((all.hi[a] - all.lo[a]) / h) + 1;
      cells *= dims[a];
    }
    if (std::isfinite(cells) && cells <= 8.0 * static_cast<double>(n) + 64) break;
    h *= 2;
  }
  const auto cell_of = [&](double x, int a) {
    return static_cast<std::uint64_t>(std::min(dims[a] - 1, std::floor((x - all.lo[a]) / h)));
  };
  const auto key_of = [&](std::uint64_t cx, std::uint64_t cy, std::uint64_t cz) {
    return (cx * static_cast<std::uint64_t>(dims[1]) + cy) * static_cast<std::uint64_t>(dims[2]) +
           cz;
  };
  // Triangles over at most 64 cells are filed in each (a counting sort by cell); wider ones
  // (few: the large faces of CAD parts) go to the R-tree below.
  const auto cells_total = static_cast<std::size_t>(dims[0] * dims[1] * dims[2]);
  std::vector<std::uint32_t> start(cells_total + 1, 0), lo_cell(n * 3), hi_cell(n * 3);
  std::vector<std::uint32_t> large;
  std::vector<std::uint8_t> is_large(n, 0);
  for (std::size_t t = 0; t < n; ++t) {
    std::uint64_t span = 1;
    for (int a = 0; a < 3; ++a) {
      lo_cell[t * 3 + a] = static_cast<std::uint32_t>(cell_of(boxes[t].lo[a], a));
      hi_cell[t * 3 + a] = static_cast<std::uint32_t>(cell_of(boxes[t].hi[a], a));
      span *= hi_cell[t * 3 + a] - lo_cell[t * 3 + a] + 1;
    }
    if (span > 64) {
      large.push_back(static_cast<std::uint32_t>(t));
      is_large[t] = 1;
    }
  }
  const auto each_cell = [&](std::size_t t, auto&& visit) {
    for (std::uint64_t x = lo_cell[t * 3]; x <= hi_cell[t * 3]; ++x)
      for (std::uint64_t y = lo_cell[t * 3 + 1]; y <= hi_cell[t * 3 + 1]; ++y)
        for (std::uint64_t z = lo_cell[t * 3 + 2]; z <= hi_cell[t * 3 + 2]; ++z)
          visit(key_of(x, y, z));
  };
  for (std::size_t t = 0; t < n; ++t)
    if (!is_large[t]) each_cell(t, [&](std::uint64_t c) { ++start[c + 1]; });
  for (std::size_t c = 0; c < cells_total; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> filed(start.back()), fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < n; ++t)
    if (!is_large[t])
      each_cell(t, [&](std::uint64_t c) { filed[fill[c]++] = static_cast<std::uint32_t>(t); });
  for (std::size_t c = 0; c < cells_total; ++c)
    for (std::uint32_t x = start[c]; x < start[c + 1]; ++x)
      for (std::uint32_t y = x + 1; y < start[c + 1]; ++y) {
        const std::uint32_t i = filed[x], j = filed[y];
        if (certified_apart(m, star_ok, i, j)) continue;  // cheapest first
        const tri_box &a = boxes[i], &b = boxes[j];
        if (!boxes_meet(a, b)) continue;
        const std::uint64_t home =
            key_of(cell_of(std::max(a.lo[0], b.lo[0]), 0), cell_of(std::max(a.lo[1], b.lo[1]), 1),
                   cell_of(std::max(a.lo[2], b.lo[2]), 2));
        if (home == c && meet_beyond_shared(m, i, j)) return true;
      }
  if (large.empty()) return false;
  using rtree_box = bg::model::box<box_point>;
  std::vector<std::pair<rtree_box, std::uint32_t>> indexed(n);
  for (std::size_t t = 0; t < n; ++t)
    indexed[t] = {rtree_box(box_point(boxes[t].lo[0], boxes[t].lo[1], boxes[t].lo[2]),
                            box_point(boxes[t].hi[0], boxes[t].hi[1], boxes[t].hi[2])),
                  static_cast<std::uint32_t>(t)};
  const bgi::rtree<std::pair<rtree_box, std::uint32_t>, bgi::rstar<16>> tree(indexed.begin(),
                                                                             indexed.end());
  std::vector<std::pair<rtree_box, std::uint32_t>> near;
  for (std::uint32_t i : large) {
    near.clear();
    tree.query(bgi::intersects(indexed[i].first), std::back_inserter(near));
    for (const auto& hit : near) {
      const std::uint32_t j = hit.second;
      if (j == i || (is_large[j] && j < i)) continue;  // two large ones: once
      if (!certified_apart(m, star_ok, i, j) && meet_beyond_shared(m, i, j)) return true;
    }
  }
  return false;
}

/// The components of a closed, consistently turned mesh: every undirected edge used by exactly
/// two triangles, once in each direction (else false). Fills a label per triangle (0 .. count
/// - 1, connected through shared edges).
bool closed_components(const welded_mesh& m, std::vector<std::uint32_t>& label,
                       std::uint32_t& count) {
  // Each side (u, v) filed under min(u, v) as (max(u, v), triangle << 1 | direction): a
  // counting sort by vertex, then each vertex's few sides sorted; one pass serves both questions.
  const std::size_t nv = m.points.size();
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (const auto& t : m.tris)
    for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sides(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < m.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = m.tris[t][k], v = m.tris[t][(k + 1) % 3];
      sides[fill[std::min(u, v)]++] = {std::max(u, v),
                                       static_cast<std::uint32_t>(t << 1 | (u < v ? 1u : 0u))};
    }
  for (std::size_t v = 0; v < nv; ++v)
    std::sort(sides.begin() + start[v], sides.begin() + start[v + 1]);
  std::vector<std::uint32_t> parent(m.tris.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t v = 0; v < nv; ++v)  // within one vertex's sides: pairs of the same edge
    for (std::size_t e = start[v]; e < start[v + 1]; e += 2) {
      if (e + 1 >= start[v + 1] || sides[e].first != sides[e + 1].first ||
          (e + 2 < start[v + 1] && sides[e + 2].first == sides[e].first) ||
          (sides[e].second & 1u) == (sides[e + 1].second & 1u))
        return false;
      parent[find(sides[e].second >> 1)] = find(sides[e + 1].second >> 1);
    }
  label.assign(m.tris.size(), 0);
  std::vector<std::uint32_t> id(m.tris.size(), std::numeric_limits<std::uint32_t>::max());
  count = 0;
  for (std::size_t t = 0; t < m.tris.size(); ++t) {
    std::uint32_t& r = id[find(static_cast<std::uint32_t>(t))];
    if (r == std::numeric_limits<std::uint32_t>::max()) r = count++;
    label[t] = r;
  }
  return true;
}

/// Sign of 6 x the signed volume of the triangles `tris` (a closed 2-cycle, so any origin gives
/// the same value): in double about the first corner, with a bound on the rounding of the
/// translation, the products and the sum; exactly in rationals when the bound does not settle it.
int volume_sign(const welded_mesh& m, const std::vector<std::uint32_t>& tris) {
  const point3& o = m.points[m.tris[tris.front()][0]];
  double sum = 0, magnitude = 0, terms = 0;
  for (std::uint32_t t : tris) {
    double r[3][3];
    for (int k = 0; k < 3; ++k) {
      const point3& p = m.points[m.tris[t][k]];
      r[k][0] = p.x() - o.x();
      r[k][1] = p.y() - o.y();
      r[k][2] = p.z() - o.z();
    }
    const rounded_det3 d = det3_in_double(r);
    sum += d.value;
    magnitude += d.permanent;
    terms += std::abs(d.value);
  }
  // u = 2^-53. Per term: the translated coordinates are within u (relative) of the true ones,
  // which moves the determinant by at most about 3u x its permanent; computing it costs about
  // 5u x the permanent more; summing n terms at most n u x the sum of their sizes. Doubled,
  // and refused (exact path) near underflow or overflow.
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  const double n = static_cast<double>(tris.size());
  const double bound = 32 * u * magnitude + 2 * n * u * terms;
  if (std::isfinite(bound) && std::isfinite(sum) && magnitude > 1e-250) {
    if (sum > bound) return 1;
    if (sum < -bound) return -1;
  }
  // Exactly, about the origin: D(a, b, c, O) = det [a; b; c] (homogeneous_det.h), summed.
  const rounding_guard guard;
  const hpoint origin{0, 0, 0, 1};
  const auto row = [&](std::uint32_t v) {
    const point3& p = m.points[v];
    return hpoint{p.x(), p.y(), p.z(), 1};
  };
  mpq_class exact = 0;
  for (std::uint32_t t : tris)
    exact += det_value(row(m.tris[t][0]), row(m.tris[t][1]), row(m.tris[t][2]), origin).exact();
  return sgn(exact);
}

/// The verdict (closed_shells.h) of mesh `triangles`; welded and local as weld_mesh has them.
shell_verdict verdict_of(const triangle_soup& soup, const std::vector<std::uint32_t>& triangles,
                         const welded_ids& welded, std::vector<std::uint32_t>& local) {
  if (triangles.empty()) return shell_verdict::empty;
  const welded_mesh m = weld_mesh(soup, triangles, welded, local);
  for (const point3& p : m.points)  // a non-finite corner has no plane either
    if (!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
      return shell_verdict::degenerate_triangle;
  for (const auto& t : m.tris)
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] ||
        CGAL::collinear(m.points[t[0]], m.points[t[1]], m.points[t[2]]))
      return shell_verdict::degenerate_triangle;
  std::vector<std::uint32_t> label;
  std::uint32_t count = 0;
  if (!closed_components(m, label, count)) return shell_verdict::not_closed;
  if (self_intersecting(m)) return shell_verdict::self_intersecting;
  std::vector<std::vector<std::uint32_t>> components(count);
  for (std::size_t t = 0; t < label.size(); ++t)
    components[label[t]].push_back(static_cast<std::uint32_t>(t));
  for (const auto& c : components)
    if (volume_sign(m, c) <= 0) return shell_verdict::not_outward;
  return shell_verdict::outward_closed;
}

}  // namespace

shell_verdict shell_verdict_of(const triangle_soup& soup,
                               const std::vector<std::uint32_t>& triangles) {
  const welded_ids welded = weld(soup.vertices);
  std::vector<std::uint32_t> local(welded.count, std::numeric_limits<std::uint32_t>::max());
  return verdict_of(soup, triangles, welded, local);
}

std::vector<std::uint8_t> outward_closed_meshes(
    const triangle_soup& soup, const std::vector<std::uint32_t>& mesh_face_offsets) {
  const std::size_t meshes = mesh_count(mesh_face_offsets);
  std::vector<std::vector<std::uint32_t>> members(meshes);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const std::uint32_t k = mesh_of_face(mesh_face_offsets, soup.triangles[t].face);
    if (k < meshes) members[k].push_back(static_cast<std::uint32_t>(t));  // past the end: none
  }
  const welded_ids welded = weld(soup.vertices);
  std::vector<std::uint32_t> local(welded.count, std::numeric_limits<std::uint32_t>::max());
  std::vector<std::uint8_t> out(meshes, 0);
  for (std::size_t k = 0; k < meshes; ++k)
    out[k] = verdict_of(soup, members[k], welded, local) == shell_verdict::outward_closed;
  return out;
}

}  // namespace exbsp::geom
