// SPDX-License-Identifier: LGPL-3.0-or-later
// Bézier curves in the painter's sequence: the "curves" stage (after transform+clip; it exists
// only when the scene has curves).
//
// Notation: world points p; clip coordinates c = P Mv p = (x, y, z, w); window points as in
// viewport.h. A BSP node N has the plane of its fragments, written h_N(p) = n_N . (p - a_N),
// oriented like the tree's node plane (positive where n_N points); its children are the
// negative and positive half-spaces. The empty children of the tree (the leaves) are convex
// cells; the back-to-front traversal visits node lists and cells in one sequence.
//
// 1. Flattening. Each curve is flattened (bezier.h, flatten) with the full projection and
//    viewport as the projection functor, tolerance curve_tolerance_px pixels. Points behind
//    or too close to the eye cannot be projected: the functor returns NaN for a point with
//    w <= 0 or z < -2w (before about 2/3 of the near distance for a perspective view), so
//    flatten isolates where the curve crosses into that region and emits the part beyond as
//    chords. Nothing there is visible (it lies outside w + z >= 0, the near half-space), and
//    every chord is clipped in step 3 before any divide, so no point behind the eye wraps
//    around. The guarantee "within tolerance of the curve" therefore holds for every visible
//    part (all its control points have w > 0 there, where flatten's guarantee applies).
// 2. DEPTH RULE (cells). A point of a curve belongs to the BSP cell containing it
// (bsp/traversal.h),
//    and curve pieces are drawn when the back-to-front traversal reaches their cell. Each chord
//    is pushed down the tree: at node N both ends are classified by the EXACT sign of h_N
//    (side_of_plane), clamped into the sign range of the curve's control points (the
//    curve lies in their convex hull: when they are all >= 0, so is every point of the curve,
//    and a flattened point found < 0 is a rounding of a point on the plane; all control
//    points on the plane put the whole curve there); for a line segment the range is that
//    of its two ends, so the clamp only matters for the pieces split off it. A chord on one
//    side goes to that child, a chord crossing the plane is split where h_N = 0 (interpolated
//    in double: the only rounding of the rule), and a chord lying on the plane goes to the
//    side of the eye (so a curve drawn ON a face is drawn after that face, as a decal, when the
//    face is seen from its front). A piece that reaches an empty child is in that cell; its
//    slot in the painter's sequence is the number of fragments of f.order the traversal
//    visits before the cell. This is the BSP's own visibility argument applied to a point:
//    for a point p in cell C and a fragment F drawn before C, some node plane separates them
//    with F on the far side (or F on the plane and p on the eye's side), so F cannot hide p;
//    every fragment drawn after C and covering p's pixel lies on the eye's side of a plane
//    that p is behind, so it does hide p. The rule is thus exact for opaque polygons,
//    whatever the curve does (pierces a face, passes in front of one face and behind
//    another), up to rounding in the split points; it needs no depth buffer, and the same
//    slots order the SVG <path>s. Pieces in the same slot are drawn in curve order, then
//    along each curve. The nodes, the eye's side of each and the cells' positions come from
//    one bsp::traverse_from_eye (traverse_for_direction) per view: the same walk as f.order.
// 3. Clipping. Every piece is clipped in clip coordinates against -w <= x, y, z <= w
//    (clip_stage.h: Liang–Barsky in 4D, or Cohen–Sutherland for a line that names it),
//    then divided and mapped to the window.
// Lines (curve_spec::polyline, a scene's "lines") skip step 1: their segments are the chords.
// Pieces are drawn as 1-pixel lines (line_raster.h) in PNG and as stroked polylines in SVG.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// Flattening tolerance in pixels of the output image.
constexpr double curve_tolerance_px = 0.25;

/// A piece of a curve chord inside one cell, in world space, with its painter's position.
struct curve_piece {
  vec3d a, b;
  std::size_t order_position = 0;  ///< fragments of the order drawn before it
  std::uint32_t curve = 0;
  std::size_t segment = 0;  ///< chord index along the curve's polyline
  double t_begin = 0;       ///< where the piece starts on its chord (for sorting)
  bool point = false;       ///< degree-0 curve
};

/// The tree as one view sees it (depth rule above): its nodes, the eye's side of each and
/// the painter's position of each cell.
struct curve_cells {
  std::vector<bsp_node> nodes;    ///< by node id
  std::vector<std::int8_t> near;  ///< per node: +1 or -1, the eye's side (s = 0: +1)
  std::vector<std::array<std::size_t, 2>>
      position;  ///< per node: [0] negative, [1] positive cell's position
};

/// The cells of `tree` for `view`, positions counted over `drawn_order` (f.order: the
/// traversal's order, possibly without culled fragments). Throws usage_error when
/// drawn_order names a fragment the tree does not have.
curve_cells make_curve_cells(const bsp& tree, const view_setup& view,
                             const std::vector<std::uint32_t>& drawn_order);

/// hull_ranges entry of a node whose hull sign range is not known yet (else 3 (lo + 1) + hi + 1).
constexpr std::uint8_t unknown_range = 0xff;

/// Pushes chord (a, b) of polyline segment `segment` of curve `curve` down the tree (depth
/// rule above; `hull`: the curve's control points, or the segment's two ends) and appends
/// its pieces to `out`. With no nodes: one piece at position 0. `hull_ranges` (optional, one
/// entry per node, unknown_range at first) keeps the hull's sign ranges for the curve's next
/// chords.
void place_chord(const curve_cells& cells, const vec3d& a, const vec3d& b,
                 const std::vector<vec3d>& hull, std::uint32_t curve, std::size_t segment,
                 bool point, std::vector<curve_piece>& out,
                 std::vector<std::uint8_t>* hull_ranges = nullptr);

/// Steps 1 and 2 for f.curves: the pieces sorted by position, then curve, then along the curve.
struct placed_curves {
  std::vector<curve_piece> pieces;
  std::size_t chords = 0, forced = 0;  ///< chords placed; chords flatten forced (behind the eye)
  std::size_t nodes = 0;               ///< nodes of the tree
};
/// Precondition: the order stage ran (f.order, f.tree).
placed_curves place_curves(const frame& f);

/// "curves": flattens, places and clips f.curves into f.lines (sorted by slot, then curve,
/// then along the curve). Precondition: transform+clip ran.
std::string curves_stage(frame& f);

}  // namespace exbsp::view
