// Curves: flattening, BSP cell placement and homogeneous clipping (notation in curves.h).
#include "view/curves.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.h"
#include "view/bezier.h"
#include "view/segment_clip.h"

namespace exbsp::view {

namespace {

vec3d sub(const vec3d& p, const vec3d& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
double dot3(const vec3d& p, const vec3d& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
vec3d cross3(const vec3d& p, const vec3d& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
double max_abs(const vec3d& p) { return std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])}); }

/// h_N(p) and its "on the plane" tolerance.
struct plane_value {
  double h, tolerance;
};
plane_value evaluate(const bsp_cell_tree::node& nd, const vec3d& p) {
  const double nlen = std::sqrt(dot3(nd.n, nd.n));
  return {dot3(nd.n, sub(p, nd.a)), 1e-9 * nlen * (1 + std::max(max_abs(nd.a), max_abs(p)))};
}
int sign_of(const plane_value& v) { return v.h > v.tolerance ? 1 : v.h < -v.tolerance ? -1 : 0; }

}  // namespace

bsp_cell_tree make_cell_tree(const bsp& tree, const std::vector<fragment_d>& fragments) {
  bsp_cell_tree cells;
  if (fragments.empty()) return cells;
  cells.nodes.emplace_back();
  cells.node_of_fragment.assign(fragments.size(), 0);
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    std::int32_t at = 0;
    for (const bsp::ancestor& step : tree.ancestors(i)) {
      const int s = step.side > 0 ? 1 : 0;
      if (cells.nodes[at].child[s] < 0) {
        bsp_cell_tree::node child;
        child.parent = at;
        child.side_in_parent = s;
        cells.nodes.push_back(std::move(child));
        cells.nodes[at].child[s] = static_cast<std::int32_t>(cells.nodes.size() - 1);
      }
      at = cells.nodes[at].child[s];
    }
    cells.nodes[at].fragments.push_back(static_cast<std::uint32_t>(i));
    cells.node_of_fragment[i] = at;
  }
  // Each node's plane: its largest fragment (the most stable normal).
  for (bsp_cell_tree::node& nd : cells.nodes) {
    double best = 0;
    for (std::uint32_t i : nd.fragments) {
      const fragment_d& fr = fragments[i];
      const vec3d n = cross3(sub(fr.v[1], fr.v[0]), sub(fr.v[2], fr.v[0]));
      const double len2 = dot3(n, n);
      if (len2 > best && std::isfinite(len2)) {
        best = len2;
        nd.a = fr.v[0];
        nd.n = n;
        nd.has_plane = true;
      }
    }
  }
  // Orientation: coplanar fragments may face either way, so orient each plane by the
  // fragments below it: the vertex farthest from the plane in each child subtree tells its side.
  std::vector<double> farthest(2 * cells.nodes.size(), 0.0);
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    std::int32_t child = cells.node_of_fragment[i];
    while (cells.nodes[child].parent >= 0) {
      const std::int32_t parent = cells.nodes[child].parent;
      const bsp_cell_tree::node& p = cells.nodes[parent];
      double& far = farthest[2 * parent + cells.nodes[child].side_in_parent];
      if (p.has_plane)
        for (const vec3d& v : fragments[i].v) {
          const double h = dot3(p.n, sub(v, p.a));
          if (std::fabs(h) > std::fabs(far)) far = h;
        }
      child = parent;
    }
  }
  for (std::size_t k = 0; k < cells.nodes.size(); ++k) {
    bsp_cell_tree::node& nd = cells.nodes[k];
    const double pos = farthest[2 * k + 1], neg = farthest[2 * k];
    const bool flip = pos != 0 ? pos < 0 : neg > 0;
    if (flip) nd.n = {-nd.n[0], -nd.n[1], -nd.n[2]};
  }
  return cells;
}

cell_view make_cell_view(const bsp_cell_tree& cells, const std::vector<std::uint32_t>& full_order,
                         const std::vector<std::uint32_t>& drawn_order, const view_setup& view) {
  cell_view cv;
  const std::size_t n = cells.nodes.size();
  cv.near.assign(n, 1);
  cv.here.assign(n, 0);
  cv.subtree.assign(n, 0);
  if (n == 0) return cv;
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> own(n, none), lowest(n, none);
  for (std::size_t k = 0; k < full_order.size(); ++k) {
    const std::uint32_t frag = full_order[k];
    if (frag >= cells.node_of_fragment.size()) throw usage_error("curves: the order names an unknown fragment");
    const std::int32_t nd = cells.node_of_fragment[frag];
    own[nd] = std::min(own[nd], k);
  }
  for (std::uint32_t frag : drawn_order) {
    if (frag >= cells.node_of_fragment.size()) throw usage_error("curves: the order names an unknown fragment");
    ++cv.here[cells.node_of_fragment[frag]];
  }
  // Children come after their parents in `nodes`: accumulate bottom-up.
  for (std::size_t k = n; k-- > 0;) {
    lowest[k] = std::min(lowest[k], own[k]);
    cv.subtree[k] += cv.here[k];
    const std::int32_t p = cells.nodes[k].parent;
    if (p >= 0) {
      lowest[p] = std::min(lowest[p], lowest[k]);
      cv.subtree[p] += cv.subtree[k];
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    const bsp_cell_tree::node& nd = cells.nodes[k];
    const std::int32_t c0 = nd.child[0], c1 = nd.child[1];
    if (own[k] != none && c0 >= 0 && lowest[c0] != none) {
      cv.near[k] = lowest[c0] > own[k] ? 0 : 1;
    } else if (own[k] != none && c1 >= 0 && lowest[c1] != none) {
      cv.near[k] = lowest[c1] > own[k] ? 1 : 0;
    } else if (nd.has_plane) {
      double s;
      if (view.is_parallel()) {
        s = -(nd.n[0] * view.direction.x + nd.n[1] * view.direction.y + nd.n[2] * view.direction.z);
      } else {
        s = dot3(nd.n, sub(to_vec3d(view.cam.eye), nd.a));
      }
      cv.near[k] = s < 0 ? 0 : 1;  // s > 0: negative, list, positive; s = 0 as s > 0
    }
  }
  return cv;
}

void place_chord(const bsp_cell_tree& cells, const cell_view& view, const vec3d& a, const vec3d& b,
                 std::uint32_t curve, std::size_t segment, bool point, std::vector<curve_piece>& out) {
  if (cells.nodes.empty()) {
    out.push_back({a, b, 0, curve, segment, 0.0, point});
    return;
  }
  struct task {
    vec3d a, b;
    double ta, tb;  // parameters of a and b on the chord
    std::int32_t node;
    std::size_t position;
  };
  std::vector<task> stack{{a, b, 0.0, 1.0, 0, 0}};
  const vec3d d = sub(b, a);
  while (!stack.empty()) {
    const task t = stack.back();
    stack.pop_back();
    const bsp_cell_tree::node& nd = cells.nodes[t.node];
    const std::uint8_t near = view.near[t.node];
    auto go = [&](int side, const vec3d& pa, const vec3d& pb, double ta, double tb) {
      std::size_t position = t.position;
      if (side == near) {  // after this node's list and its far subtree
        const std::int32_t far = nd.child[1 - side];
        position += view.here[t.node] + (far >= 0 ? view.subtree[far] : 0);
      }
      const std::int32_t next = nd.child[side];
      if (next < 0)
        out.push_back({pa, pb, position, curve, segment, ta, point});
      else
        stack.push_back({pa, pb, ta, tb, next, position});
    };
    if (!nd.has_plane) {
      go(near, t.a, t.b, t.ta, t.tb);
      continue;
    }
    const plane_value va = evaluate(nd, t.a), vb = evaluate(nd, t.b);
    const int sa = sign_of(va), sb = sign_of(vb);
    if (sa == 0 && sb == 0) {
      go(near, t.a, t.b, t.ta, t.tb);  // on the plane: drawn on the eye's side
    } else if (sa >= 0 && sb >= 0) {
      go(1, t.a, t.b, t.ta, t.tb);
    } else if (sa <= 0 && sb <= 0) {
      go(0, t.a, t.b, t.ta, t.tb);
    } else {  // crosses the plane: split where h_N = 0
      const double s = va.h / (va.h - vb.h);
      const double tm = t.ta + s * (t.tb - t.ta);
      const vec3d m{a[0] + tm * d[0], a[1] + tm * d[1], a[2] + tm * d[2]};
      // Pushed in reverse so that the part nearer to a is handled first.
      go(sb > 0 ? 1 : 0, m, t.b, tm, t.tb);
      go(sa > 0 ? 1 : 0, t.a, m, t.ta, tm);
    }
  }
}

std::string curves_stage(frame& f) {
  f.lines.clear();
  const mat4 pm = f.view.projection * f.view.model_view;
  const viewport& vp = f.view.vp;

  // The tree's shape (once per tree) and this view of it.
  if (f.tree && !f.fragments.empty() && !f.cells)
    f.cells = std::make_shared<const bsp_cell_tree>(make_cell_tree(*f.tree, f.fragments));
  static const bsp_cell_tree no_cells;
  const bsp_cell_tree& cells = f.cells && f.tree ? *f.cells : no_cells;
  cell_view cv;
  if (!cells.nodes.empty()) {
    const bool complete = f.culled == 0 && f.order.size() == f.fragments.size();
    std::vector<std::uint32_t> full;
    if (!complete) {
      if (f.view.is_parallel()) {
        const vector3& dir = f.view.direction;
        full = f.tree->order_for_direction({dir.x, dir.y, dir.z});
      } else {
        full = f.tree->order_from_eye(to_vec3d(f.view.cam.eye));
      }
    }
    cv = make_cell_view(cells, complete ? f.order : full, f.order, f.view);
  }

  // 1. Flatten, 2. place.
  auto project = [&](const vec3d& p) -> vec2d {
    const hpoint c = pm * to_point(p);
    if (!(c.w > 0) || c.z < -2 * c.w) return {std::numeric_limits<double>::quiet_NaN(), 0.0};
    const window_point w = to_window(vp, c.x / c.w, c.y / c.w, c.z / c.w);
    return {w.x, w.y};
  };
  std::vector<curve_piece> pieces;
  std::size_t chords = 0, forced = 0;
  for (std::uint32_t k = 0; k < f.curves.size(); ++k) {
    if (f.curves[k].polyline) {  // "lines": the segments are the chords
      const std::vector<vec3d>& pts = f.curves[k].control_points;
      for (std::size_t s = 0; s + 1 < pts.size(); ++s) {
        ++chords;
        place_chord(cells, cv, pts[s], pts[s + 1], k, s, false, pieces);
      }
      continue;
    }
    const bezier_curve curve(f.curves[k].control_points);
    if (curve.degree() == 0) {
      const vec3d p = curve.control_points()[0];
      place_chord(cells, cv, p, p, k, 0, true, pieces);
      continue;
    }
    const flattened_curve poly = flatten(curve, project, curve_tolerance_px);
    forced += poly.forced_chords;
    for (std::size_t s = 0; s + 1 < poly.points.size(); ++s) {
      ++chords;
      place_chord(cells, cv, poly.points[s], poly.points[s + 1], k, s, false, pieces);
    }
  }
  std::stable_sort(pieces.begin(), pieces.end(), [](const curve_piece& x, const curve_piece& y) {
    if (x.order_position != y.order_position) return x.order_position < y.order_position;
    if (x.curve != y.curve) return x.curve < y.curve;
    if (x.segment != y.segment) return x.segment < y.segment;
    return x.t_begin < y.t_begin;
  });

  // Order positions (in f.order) to slots (in f.polygons, which skips fully clipped fragments).
  std::vector<std::size_t> slot_of_position(f.order.size() + 1, 0);
  {
    std::vector<std::size_t> position_of_fragment(f.fragments.size(), 0);
    for (std::size_t k = 0; k < f.order.size(); ++k) position_of_fragment.at(f.order[k]) = k;
    std::size_t p = 0;
    for (std::size_t k = 0; k <= f.order.size(); ++k) {
      while (p < f.polygons.size() && position_of_fragment.at(f.polygons[p].fragment) < k) ++p;
      slot_of_position[k] = p;
    }
  }

  // 3. Clip in homogeneous coordinates, divide, viewport.
  for (const curve_piece& piece : pieces) {
    hpoint ca, cb;
    if (!clip_segment_to_view_volume(pm * to_point(piece.a), pm * to_point(piece.b), ca, cb, nullptr, nullptr,
                                     f.curves[piece.curve].clipper))
      continue;
    if (!(ca.w > 0) || !(cb.w > 0)) continue;
    screen_line line;
    line.a = to_window(vp, ca.x / ca.w, ca.y / ca.w, ca.z / ca.w);
    line.b = to_window(vp, cb.x / cb.w, cb.y / cb.w, cb.z / cb.w);
    line.color = f.curves[piece.curve].color;
    line.slot = slot_of_position[std::min(piece.order_position, f.order.size())];
    line.curve = piece.curve;
    line.point = piece.point;
    f.lines.push_back(line);
  }
  return std::to_string(f.curves.size()) + " curves, " + std::to_string(chords) + " chords (" +
         std::to_string(forced) + " forced), " + std::to_string(pieces.size()) + " pieces in " +
         std::to_string(cells.nodes.size()) + " nodes, " + std::to_string(f.lines.size()) + " lines drawn";
}

}  // namespace exbsp::view
