// SPDX-License-Identifier: LGPL-3.0-or-later
// The coverage walk of the visible-region drawing (vector_drawing.h has the notation) in
// horizontal strips: the viewport is cut along tile rows into a fixed number of strips, each
// with its own tiled_coverage, so that the strips' walks run on different cores. The strips
// depend on the frame alone (never on the number of cores or on timing), so the drawing is the
// same on every machine. A polygon crossing a strip line is cut there; its cut points are
// computed from the edge's end points in a fixed order, so that the two halves, and the
// neighbours sharing the edge, meet at the same grid point. Internal to view.
#pragma once
#include <polyclipping/clipper.hpp>

#include <cstdint>
#include <memory>
#include <vector>

#include "view/visible_cover.h"

namespace exbsp::view::cover {

/// A piece of a striped coverage: its strip and its id there.
struct piece_ref {
  std::uint32_t strip;
  std::uint32_t id;
};

/// The strips of a viewport `height` grid units high: tile-row boundaries r_0 = 0 < r_1 < ... <
/// r_n (the viewport's tile rows), at most `count` strips, placed so that each holds about as
/// many of the polygons' centres (`centres_y`, grid units) as the others, and no strip line
/// on an ordinate of `avoid_y` (sorted: the lines' points and horizontal segments, which are
/// then never cut along their length nor split between two strips' answers).
std::vector<int> strip_rows(const std::vector<long long>& centres_y, long long height, int count,
                            const std::vector<long long>& avoid_y = {});

/// The part of the segment a-b in the band y0 <= y <= y1, in `out` (two points, in a-b's
/// direction; crossings by crossing_x). A segment along y = c belongs to the band when
/// y0 <= c < y1 (each strip line to the strip above it). False when no length is left.
bool segment_in_band(const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b, long long y0,
                     long long y1, ClipperLib::Path& out);

/// The part of the counter-clockwise ring `p` in the closed band y0 <= y <= y1, in `out` (one
/// pass over p's edges: the points inside the band and the edges' crossings with its lines,
/// each crossing rounded to the grid from the edge's end points taken in lexicographic order).
/// False when nothing with area is left.
bool cut_to_band(const ClipperLib::Path& p, long long y0, long long y1, ClipperLib::Path& out);

/// The x where the segment a-b crosses the line y (a.Y != b.Y, y between them), rounded to the
/// nearest grid unit (halves up), from a and b in lexicographic order: the same point for
/// both orientations of the segment.
long long crossing_x(const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b, long long y);

/// Screen coverage as strips (strip_rows), each a tiled_coverage of its rows.
class striped_coverage {
 public:
  /// A viewport `width` grid units wide cut at the tile rows `rows` (strip_rows).
  striped_coverage(long long width, const std::vector<int>& rows);

  std::size_t size() const { return strips_.size(); }
  tiled_coverage& strip(std::size_t s) { return *strips_[s].coverage; }
  /// The strip's band, grid units: y0 <= y <= y1 (the first strip reaches down, the last one
  /// up, without end: what was rounded past the viewport's edge belongs to them).
  long long y0(std::size_t s) const { return strips_[s].y0; }
  long long y1(std::size_t s) const { return strips_[s].y1; }

  /// The rings of a piece.
  const ClipperLib::Paths& rings(piece_ref r) const {
    return strips_[r.strip].coverage->rings(r.id);
  }
  /// Frees strip s (its coverage and pieces): nothing of it may be read after.
  void release(std::size_t s) { strips_[s].coverage.reset(); }
  /// Rectangles tiling the full tiles whose pieces all belong to `mesh` (tiled_coverage's).
  ClipperLib::Paths full_tiles_of(std::uint32_t mesh) const;
  /// True when every tile the box meets is full of pieces of `mesh` only.
  bool inside_full_tiles_of(const bbox_i& box, std::uint32_t mesh) const;

 private:
  struct band {
    std::unique_ptr<tiled_coverage> coverage;
    long long y0, y1;
  };
  std::vector<band> strips_;
};

}  // namespace exbsp::view::cover
