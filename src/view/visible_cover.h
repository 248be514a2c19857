// SPDX-License-Identifier: LGPL-3.0-or-later
// The coverage behind the visible-region drawing (vector_drawing.h has the notation): the
// polygons of a frame, snapped to the 1/100-pixel grid and taken front to back, each lose what
// the ones before them cover. tiled_coverage keeps what is covered as disjoint visible pieces
// in 4-pixel tiles and decides each new polygon by exact separation tests on the grid and
// overlap areas (Sutherland–Hodgman in doubles), handing only the partly hidden ones to
// Clipper; t_junction_mender inserts into a polygon's edges the vertices of others lying on
// them, so that neighbours share their boundary point for point. Internal to view.
#pragma once
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <exbsp/view/vector_drawing.h>

namespace exbsp::view::cover {

/// floor(v / d) for d > 0.
inline long long floor_div(long long v, long long d) {
  return v >= 0 ? v / d : -((-v + d - 1) / d);
}

/// A bounding box on the grid.
struct bbox_i {
  long long x0, y0, x1, y1;
};

/// The bounding box of a non-empty sequence of points with members X and Y.
template <class Points>
bbox_i bbox_of(const Points& pts) {
  bbox_i b{pts[0].X, pts[0].Y, pts[0].X, pts[0].Y};
  for (const auto& q : pts) {
    b.x0 = std::min(b.x0, q.X);
    b.y0 = std::min(b.y0, q.Y);
    b.x1 = std::max(b.x1, q.X);
    b.y1 = std::max(b.y1, q.Y);
  }
  return b;
}

/// True when the ring turns left (or goes straight) at every vertex: counter-clockwise and
/// convex. Integer cross products, exact.
bool convex_ccw(const ClipperLib::Path& r);

/// The ring without its vertices collinear with their neighbours (exact integer test).
ClipperLib::Path without_straight_vertices(const ClipperLib::Path& r);

/// The union of disjoint regions (outer rings counter-clockwise, holes clockwise) that meet
/// only along shared edges (the same grid points, walked in opposite directions): the directed
/// edges left after cancelling each one against its reverse, chained into rings (holes
/// clockwise), their straight vertices dropped. False, with `out` unspecified, when the edges left
/// do not chain into rings one way only (rings touching at a vertex, or edges that do not match
/// exactly): then a general Boolean is needed.
bool union_by_shared_edges(const std::vector<const ClipperLib::Path*>& rings,
                           ClipperLib::Paths& out);

/// The signed area (counter-clockwise positive, holes clockwise negative) of the rings inside
/// each square cell of side `side` of the grid of cols x rows cells whose lower left corner is
/// (ox, oy): area[r * cols + c] for cell (c, r). One pass over the edges, as exact-area
/// rasterizers do: the area of a region in a cell is the integral over the cell's rows of
/// the clamped abscissa of the boundary, x clamped to the cell's columns, which each edge adds
/// to the cells it crosses and, as a full width times its rise, to the cells left of it.
/// `cover` is working memory. Doubles: exact to far below one square unit for grid points.
void cell_areas(const ClipperLib::Paths& rings, long long ox, long long oy, long long side,
                int cols, int rows, std::vector<double>& area, std::vector<double>& cover);

/// Screen coverage as disjoint pieces (each the part of a polygon that the earlier ones left
/// visible), indexed by 4-pixel tiles (visible_cover.cpp explains the tests).
class tiled_coverage {
 public:
  static constexpr std::uint32_t no_piece = ~std::uint32_t{0};
  /// The side of a tile, grid units (4 pixels).
  static constexpr long long tile_side = 4 * grid_per_pixel;

  /// A viewport of width x height grid units.
  tiled_coverage(long long width, long long height);
  /// The band of tile rows [row0, row0 + rows) of a viewport `width` grid units wide (a strip
  /// of visible_strips.h): what is added must lie in it.
  tiled_coverage(long long width, int row0, int rows);
  ~tiled_coverage();
  tiled_coverage(const tiled_coverage&) = delete;
  tiled_coverage& operator=(const tiled_coverage&) = delete;

  /// True when every tile the box meets is full.
  bool hides(const bbox_i& box) const;
  /// Adds the counter-clockwise polygon p of mesh `mesh` (p is moved from when wholly
  /// visible); returns the id of its part not covered before (a piece: rings()), or no_piece
  /// when it is hidden.
  std::uint32_t add(ClipperLib::Path& p, std::uint32_t mesh);
  /// The rings of piece `id` (outer rings counter-clockwise, holes clockwise).
  const ClipperLib::Paths& rings(std::uint32_t id) const;
  /// Rectangles (counter-clockwise) tiling the full tiles whose pieces all belong to `mesh`:
  /// runs along each row of tiles.
  ClipperLib::Paths full_tiles_of(std::uint32_t mesh) const;
  /// True when every tile the box meets is full of pieces of `mesh` only.
  bool inside_full_tiles_of(const bbox_i& box, std::uint32_t mesh) const;
  /// The parts of the open polyline `line` outside the coverage.
  ClipperLib::Paths outside(const ClipperLib::Path& line);
  /// True when the point, nudged by (e, e^2) for a small enough e > 0 off every line through
  /// it, is covered (nonzero winding): a point on the shared boundary of two pieces is covered.
  bool covers(const ClipperLib::IntPoint& q);

 private:
  class impl;
  std::unique_ptr<impl> impl_;
};

/// Inserts into polygons' edges the vertices of other polygons lying less than one grid unit
/// from their insides (T-junctions: BSP split points on a neighbour's edge).
class t_junction_mender {
 public:
  /// Indexes the vertices `points` (of all polygons), in a viewport of width x height grid
  /// units.
  t_junction_mender(const std::vector<ClipperLib::IntPoint>& points, long long width,
                    long long height);
  ~t_junction_mender();
  t_junction_mender(const t_junction_mender&) = delete;
  t_junction_mender& operator=(const t_junction_mender&) = delete;

  /// Working memory of mend: one per thread mending at the same time.
  struct scratch {
    ClipperLib::Path candidates;
    std::vector<std::pair<double, ClipperLib::IntPoint>> on_edge;
    ClipperLib::Path mended;
  };

  /// Inserts into p's edges the indexed vertices lying less than one unit from their insides.
  /// Reads only the index: threads may mend different polygons at once, each with its scratch.
  void mend(ClipperLib::Path& p, scratch& s) const;

 private:
  class impl;
  std::unique_ptr<impl> impl_;
};

}  // namespace exbsp::view::cover
