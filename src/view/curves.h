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
// 2. DEPTH RULE (cells). A point of a curve belongs to the BSP cell containing it, and curve
//    pieces are drawn when the back-to-front traversal reaches their cell. Each chord is
//    pushed down the tree: at node N both ends are classified by h_N (within a relative
//    tolerance of 1e-9 a point counts as ON the plane); a chord on one side goes to that child,
//    a chord crossing the plane is split at h_N = 0 into two pieces, and a chord lying on the
//    plane goes to the side of the eye (so a curve drawn ON a face is drawn after that face, as
//    a decal, when the face is seen from its front). A piece that reaches an empty child is
//    in that cell; its slot in the painter's sequence is the number of fragments of f.order
//    the traversal visits before the cell. This is the BSP's own visibility argument applied
//    to a point: for a point p in cell C and a fragment F drawn before C, some node plane
//    separates them with F on the far side (or F on the plane and p on the eye's side), so F
//    cannot hide p; every fragment drawn after C and covering p's pixel lies on the eye's
//    side of a plane that p is behind, so it does hide p. The rule is thus exact for opaque
//    polygons, whatever the curve does (pierces a face, passes in front of one face and
//    behind another), up to rounding in the split points; it needs no depth buffer, and the
//    same slots order the SVG <path>s. Pieces in the same slot are drawn in curve order, then
//    along each curve.
//    The tree's shape is read once per tree through bsp::ancestors() (bsp_cell_tree); which
//    child the traversal visits first at each node is read off f.order's traversal, so slots
//    agree with the BSP's exact order even where a double classification of the eye would not.
// 3. Clipping. Every piece is clipped in clip coordinates against -w <= x, y, z <= w
//    (segment_clip.h: Liang–Barsky in 4D, or Cohen–Sutherland for a line that names it),
//    then divided and mapped to the window.
// Lines (curve_spec::polyline, a scene's "lines") skip step 1: their segments are the chords.
// Pieces are drawn as 1-pixel lines (line_raster.h) in PNG and as stroked polylines in SVG.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bsp/engine.h"
#include "view/pipeline.h"

namespace exbsp::view {

/// Flattening tolerance in pixels of the output image.
constexpr double curve_tolerance_px = 0.25;

/// The shape of a built BSP, rebuilt from bsp::ancestors(): node 0 is the root.
struct bsp_cell_tree {
  struct node {
    std::int32_t child[2] = {-1, -1};  ///< [0] negative side, [1] positive side; -1: empty cell
    std::int32_t parent = -1;
    int side_in_parent = 0;            ///< 0 negative, 1 positive
    std::vector<std::uint32_t> fragments;  ///< fragment indices stored at this node
    vec3d a{}, n{};                    ///< plane n . (p - a) = 0, oriented as the node's plane
    bool has_plane = false;
  };
  std::vector<node> nodes;
  std::vector<std::int32_t> node_of_fragment;
};

/// Rebuilds the shape of `tree` (fragments = tree.fragments_double()). Each node's plane is
/// that of its largest fragment, oriented so that its children's fragments lie on their sides.
/// Empty for a tree without fragments.
bsp_cell_tree make_cell_tree(const bsp& tree, const std::vector<fragment_d>& fragments);

/// A piece of a curve chord inside one cell, in world space, with its painter's position.
struct curve_piece {
  vec3d a, b;
  std::size_t order_position = 0;  ///< fragments of the order drawn before it
  std::uint32_t curve = 0;
  std::size_t segment = 0;         ///< chord index along the curve's polyline
  double t_begin = 0;              ///< where the piece starts on its chord (for sorting)
  bool point = false;              ///< degree-0 curve
};

/// What placing needs to know about one view of the tree.
struct cell_view {
  std::vector<std::uint8_t> near;      ///< per node: the child visited second (the eye's side)
  std::vector<std::size_t> here;       ///< per node: its fragments that are in the drawn order
  std::vector<std::size_t> subtree;    ///< per node: the same over its whole subtree
};

/// The view of `cells` for the back-to-front order `full_order` (every fragment, as the
/// tree's traversal returns it) of which `drawn_order` (f.order, e.g. after culling) is drawn.
/// The near side of a node is read off full_order; only a node whose children are both empty
/// needs the geometric eye test (s = h_N(eye), or n_N . (-d) for parallel views; s >= 0: the
/// positive side is near, as in the BSP traversal).
cell_view make_cell_view(const bsp_cell_tree& cells, const std::vector<std::uint32_t>& full_order,
                         const std::vector<std::uint32_t>& drawn_order, const view_setup& view);

/// Pushes chord (a, b) of polyline segment `segment` of curve `curve` down the tree (depth
/// rule above) and appends its pieces to `out`. With an empty tree: one piece at position 0.
void place_chord(const bsp_cell_tree& cells, const cell_view& view, const vec3d& a, const vec3d& b,
                 std::uint32_t curve, std::size_t segment, bool point, std::vector<curve_piece>& out);

/// "curves": flattens, places and clips f.curves into f.lines (sorted by slot, then curve,
/// then along the curve). Precondition: transform+clip ran.
std::string curves_stage(frame& f);

}  // namespace exbsp::view
