// SPDX-License-Identifier: LGPL-3.0-or-later
// Curves: flattening, BSP cell placement and homogeneous clipping (notation in curves.h).
#include "view/curves.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <exbsp/core/errors.h>
#include <exbsp/view/bezier.h>
#include "view/clip_stage.h"

namespace exbsp::view {

namespace {

/// Visits the tree once for a view: nodes, the eye's sides, and each cell's position = the
/// drawn fragments visited before it.
class cell_collector final : public bsp_visitor {
 public:
  cell_collector(curve_cells& cells, const std::vector<std::uint8_t>& drawn)
      : cells_(cells), drawn_(drawn) {}
  void enter(const bsp_node& n, int eye_side) override {
    cells_.nodes[n.index] = n;
    cells_.near[n.index] = eye_side < 0 ? -1 : 1;
  }
  void fragments(const bsp_node& n) override {
    for (std::uint32_t k = 0; k < n.fragment_count; ++k)
      drawn_before_ += drawn_[n.first_fragment + k];
  }
  void cell(const bsp_node& n, int side) override {
    cells_.position[n.index][side > 0] = drawn_before_;
  }

 private:
  curve_cells& cells_;
  const std::vector<std::uint8_t>& drawn_;
  std::size_t drawn_before_ = 0;
};

/// The exact side of p against n's plane, clamped into [lo, hi] (the hull's sign range).
int clamped_side(const bsp_node& n, const vec3d& p, int lo, int hi) {
  return std::min(hi, std::max(lo, side_of_plane(n, p)));
}

}  // namespace

curve_cells make_curve_cells(const bsp& tree, const view_setup& view,
                             const std::vector<std::uint32_t>& drawn_order) {
  curve_cells cells;
  const std::size_t n = tree.node_count();
  cells.nodes.resize(n);
  cells.near.assign(n, 1);
  cells.position.assign(n, {0, 0});
  std::vector<std::uint8_t> drawn(tree.fragment_count(), 0);
  for (std::uint32_t frag : drawn_order) {
    if (frag >= drawn.size()) throw usage_error("curves: the order names an unknown fragment");
    drawn[frag] = 1;
  }
  cell_collector collector(cells, drawn);
  if (view.is_parallel())
    tree.traverse_for_direction({view.direction.x, view.direction.y, view.direction.z}, collector);
  else
    tree.traverse_from_eye(to_vec3d(view.cam.eye), collector);
  return cells;
}

void place_chord(const curve_cells& cells, const vec3d& a, const vec3d& b,
                 const std::vector<vec3d>& hull, std::uint32_t curve, std::size_t segment,
                 bool point, std::vector<curve_piece>& out,
                 std::vector<std::uint8_t>* hull_ranges) {
  if (cells.nodes.empty()) {
    out.push_back({a, b, 0, curve, segment, 0.0, point});
    return;
  }
  const vec3d d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const auto at = [&](double t) -> vec3d {
    if (t == 0) return a;
    if (t == 1) return b;
    return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
  };
  // A piece is the part [t0, t1] of the chord inside node `node`'s region.
  struct task {
    double t0, t1;
    std::int32_t node;
  };
  std::vector<task> stack{{0.0, 1.0, 0}};
  while (!stack.empty()) {
    const task t = stack.back();
    stack.pop_back();
    const bsp_node& nd = cells.nodes[static_cast<std::size_t>(t.node)];
    auto go = [&](int side, double t0, double t1) {
      const std::int32_t next = side > 0 ? nd.positive : nd.negative;
      if (next >= 0) {
        stack.push_back({t0, t1, next});
        return;
      }
      const vec3d pa = at(t0), pb = at(t1);
      if (!point && (t0 > 0 || t1 < 1) && pa == pb)
        return;  // a split-off sliver that rounds to a point
      out.push_back({pa, pb, cells.position[nd.index][side > 0], curve, segment, t0, point});
    };
    int lo = 1, hi = -1;  // the hull's sign range, once per node and curve
    std::uint8_t* cached = hull_ranges ? &(*hull_ranges)[nd.index] : nullptr;
    if (cached && *cached != unknown_range) {
      lo = *cached / 3 - 1, hi = *cached % 3 - 1;
    } else {
      for (const vec3d& h : hull) {
        const int s = side_of_plane(nd, h);
        lo = std::min(lo, s), hi = std::max(hi, s);
      }
      if (cached) *cached = static_cast<std::uint8_t>(3 * (lo + 1) + (hi + 1));
    }
    // The chord's ends decide (a convex piece of the chord lies between them): exactly.
    const int sa = clamped_side(nd, a, lo, hi), sb = clamped_side(nd, b, lo, hi);
    if (sa == 0 && sb == 0) {
      go(cells.near[nd.index], t.t0, t.t1);  // on the plane: drawn on the eye's side
    } else if (sa >= 0 && sb >= 0) {
      go(1, t.t0, t.t1);
    } else if (sa <= 0 && sb <= 0) {
      go(-1, t.t0, t.t1);
    } else {  // the chord crosses the plane at t_N (in double: the only rounding of the rule)
      const double ha = plane_value(nd, a), hb = plane_value(nd, b);
      const double s = ha / (ha - hb);
      const double tn = std::isnan(s) ? 0.5 : std::min(1.0, std::max(0.0, s));
      if (t.t1 <= tn) {
        go(sa, t.t0, t.t1);
      } else if (t.t0 >= tn) {
        go(sb, t.t0, t.t1);
      } else {  // pushed in reverse so that the part nearer to a is handled first
        go(sb, tn, t.t1);
        go(sa, t.t0, tn);
      }
    }
  }
}

placed_curves place_curves(const frame& f) {
  const mat4 pm = f.view.projection * f.view.model_view;
  const viewport& vp = f.view.vp;
  // This view of the tree: nodes, the eye's sides and the cells' positions.
  placed_curves out;
  const curve_cells cells =
      f.tree && !f.fragments.empty() ? make_curve_cells(*f.tree, f.view, f.order) : curve_cells{};
  out.nodes = cells.nodes.size();

  // 1. Flatten, 2. place.
  auto project = [&](const vec3d& p) -> vec2d {
    const hpoint c = pm * to_point(p);
    if (!(c.w > 0) || c.z < -2 * c.w) return {std::numeric_limits<double>::quiet_NaN(), 0.0};
    const window_point w = to_window(vp, c.x / c.w, c.y / c.w, c.z / c.w);
    return {w.x, w.y};
  };
  std::vector<curve_piece>& pieces = out.pieces;
  std::vector<std::uint8_t> hull_ranges;  // per node: the current curve's hull sign range
  for (std::uint32_t k = 0; k < f.curves.size(); ++k) {
    if (f.curves[k].polyline) {  // "lines": the segments are the chords
      const std::vector<vec3d>& pts = f.curves[k].control_points;
      for (std::size_t s = 0; s + 1 < pts.size(); ++s) {
        ++out.chords;
        place_chord(cells, pts[s], pts[s + 1], {pts[s], pts[s + 1]}, k, s, false, pieces);
      }
      continue;
    }
    const bezier_curve curve(f.curves[k].control_points);
    hull_ranges.assign(cells.nodes.size(), unknown_range);
    if (curve.degree() == 0) {
      const vec3d p = curve.control_points()[0];
      place_chord(cells, p, p, curve.control_points(), k, 0, true, pieces);
      continue;
    }
    const flattened_curve poly = flatten(curve, project, curve_tolerance_px);
    out.forced += poly.forced_chords;
    for (std::size_t s = 0; s + 1 < poly.points.size(); ++s) {
      ++out.chords;
      place_chord(cells, poly.points[s], poly.points[s + 1], curve.control_points(), k, s, false,
                  pieces, &hull_ranges);
    }
  }
  std::stable_sort(pieces.begin(), pieces.end(), [](const curve_piece& x, const curve_piece& y) {
    if (x.order_position != y.order_position) return x.order_position < y.order_position;
    if (x.curve != y.curve) return x.curve < y.curve;
    if (x.segment != y.segment) return x.segment < y.segment;
    return x.t_begin < y.t_begin;
  });
  return out;
}

std::string curves_stage(frame& f) {
  f.lines.clear();
  const mat4 pm = f.view.projection * f.view.model_view;
  const viewport& vp = f.view.vp;
  const placed_curves placed = place_curves(f);

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
  for (const curve_piece& piece : placed.pieces) {
    hpoint ca, cb;
    if (!clip_segment_to_view_volume(pm * to_point(piece.a), pm * to_point(piece.b), ca, cb,
                                     nullptr, nullptr, f.curves[piece.curve].clipper))
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
  return std::to_string(f.curves.size()) + " curves, " + std::to_string(placed.chords) +
         " chords (" + std::to_string(placed.forced) + " forced), " +
         std::to_string(placed.pieces.size()) + " pieces in " + std::to_string(placed.nodes) +
         " nodes, " + std::to_string(f.lines.size()) + " lines drawn";
}

}  // namespace exbsp::view
