// SPDX-License-Identifier: LGPL-3.0-or-later
// The hidden-line oracle (issue 23): an independent judge of the edges of a vector drawing
// (view/vector_drawing.h: the solid visible_edge and dashed hidden_edge runs of the SVG).
//
// It shares no code with exbsp's edge finder or its visibility: it welds the soup, finds the
// feature edges, and decides each sample point of each edge by casting a ray to the eye.
//
// The rule. A point p of a feature edge is hidden when the open segment from p to the eye (a
// parallel view: the open ray from p towards the viewer, direction -view.direction) crosses the
// plane of some face transversally at a point of that face's relative interior, or of one of its
// edges that is not a feature edge of the view. Faces seen edge-on hide nothing; touching a
// feature edge hides nothing. Feature edges (vertices welded by exact position; degenerate
// triangles, exactly collinear, are left out): boundary (one face), non-manifold (three or more
// faces, or more than two triangles of two faces), crease (the angle between the two face
// normals (b - a) x (c - a) exceeds crease_deg) and silhouette (one face turned towards the
// eye, the other not: orientation(a, b, c, eye) > 0; a parallel view: n . (-direction) > 0).
// Two triangles of one face id never make a feature edge (a fan diagonal).
// Per triangle that means: the segment crosses its plane (the sample and the eye strictly on
// opposite sides), and the line through them meets the triangle inside (hidden), on an edge
// (hidden unless that welded edge is a feature edge; a fan diagonal is not) or at a vertex
// (hidden unless a feature edge ends at that welded vertex: "touching a feature edge").
// A hiding point that the near plane clips away (not drawn) makes the sample unknown.
//
// Arithmetic. Every coordinate, the eye and the direction are doubles; a sample is the
// rational point a + t (b - a). `exact` evaluates every sign with GMP rationals; `filtered`
// evaluates them in doubles with an error bound and recomputes with rationals only when the
// bound cannot decide, so its answers are the exact ones too (a test checks the two agree);
// `automatic` takes exact below exact_below triangles. Occluders are culled by their
// projected bounding boxes (a grid of 16-pixel cells).
//
// The check (check_hidden_lines). Samples: samples_per_edge per edge, at t = (2k + 1) / 2N,
// more on long edges (one per sample_spacing_px), none outside the view volume. Each is
// projected to the drawing grid (100 * (window - viewport origin), y up) and judged:
//   visible: within `tolerance` grid units of a solid run (else "drawn dashed" or "missing");
//   hidden:  not within `tolerance` of a solid run, and (when hidden edges are drawn) within
//            `tolerance` of a dashed run; both waived when a visible point of some feature
//            edge projects within 2 tolerance (coincidence: only the visible line is drawn).
// Skipped as ambiguous: samples within `ambiguity` grid units (in the image) of a place where
// the oracle's visibility changes along the edge (found by bisection between the samples and
// the ends), of the ends of the edge's image in the view volume (rounded run ends, crumbs) or
// of the viewport's border, and unknown samples.
// The drawing is then checked the other way (check_drawing): points every 2 pixels along each
// run, away from its ends, must lie within `tolerance` of a feature edge that is visible there
// (solid) or hidden there and not coinciding with a visible edge (dashed).
#pragma once
#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <exbsp/mesh/soup.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/vector_drawing.h>

namespace exbsp_test {

/// How the oracle evaluates its signs (both give the exact answers; see above).
enum class oracle_arithmetic { automatic, exact, filtered };

struct hidden_line_options {
  oracle_arithmetic arithmetic = oracle_arithmetic::automatic;
  std::size_t exact_below = 200;   ///< automatic: exact for fewer triangles than this
  int samples_per_edge = 16;       ///< at least this many samples per edge
  double sample_spacing_px = 4;    ///< and one per this many pixels of the edge's image
  int max_samples_per_edge = 256;  ///< at most
  double tolerance = 3;            ///< grid units (1/100 pixel) between a sample and a run
  double ambiguity = 8;            ///< grid units around a visibility change: skipped
  bool check_drawing = true;       ///< also check the drawn runs against the oracle
  double run_spacing_px = 2;       ///< check_drawing: one point per this many pixels of a run
  std::size_t max_examples = 6;    ///< failures kept in the report for messages
  /// When not empty: only the samples of these feature edges (end points in either order)
  /// and the run points within `tolerance` of their images are checked; the others are not
  /// counted.
  std::vector<std::array<exbsp::vec3d, 2>> only_edges;
};

/// Why an edge is a feature edge (the first reason that applies, in this order).
enum class feature_kind { boundary, non_manifold, crease, silhouette };
const char* to_string(feature_kind k);

/// A feature edge of the view: end points (a < b by welded vertex order) and its face ids.
struct oracle_edge {
  exbsp::vec3d a, b;
  std::vector<std::uint32_t> faces;  ///< distinct face ids around it
  feature_kind kind = feature_kind::boundary;
};

/// The oracle's verdict on one point.
enum class point_visibility {
  visible,
  hidden,
  unknown  ///< hidden only by parts of faces that the near plane clips away
};
const char* to_string(point_visibility v);

/// A triangle that hides a point (hidden_line_oracle::hiding), for messages.
struct occluder_hit {
  std::uint32_t face = 0;
  std::array<exbsp::vec3d, 3> corners{};
  exbsp::vec3d crossing{};  ///< where the line of sight crosses its plane (doubles)
  const char* where =
      "";                ///< "inside", "on a non-feature edge", "at a vertex with no feature edge"
  bool clipped = false;  ///< the crossing is in front of the near plane
};

/// An edge's image inside the view volume: the part t0 <= t <= t1 of the edge, whose ends
/// project to grid points g0 and g1.
struct edge_image {
  double t0 = 0, t1 = 1;
  std::array<double, 2> g0{}, g1{};
  double w0 = 1, w1 = 1;  ///< clip-space w at t0 and t1
  double length() const;  ///< grid units
  /// The edge parameter t of the point at fraction u (0..1) of the image from g0 to g1.
  double t_at(double u) const;
};

/// The oracle of one frame (after its pipeline ran or not: it reads f.soup, f.view and
/// f.vector only, and keeps copies).
class hidden_line_oracle {
 public:
  explicit hidden_line_oracle(const exbsp::view::frame& f, const hidden_line_options& opt = {});
  ~hidden_line_oracle();
  hidden_line_oracle(hidden_line_oracle&&) noexcept;
  hidden_line_oracle& operator=(hidden_line_oracle&&) noexcept;

  const hidden_line_options& options() const;
  /// True when every sign is evaluated with rationals (oracle_arithmetic::exact or automatic
  /// below exact_below triangles).
  bool exact() const;
  /// Whether the frame asks for hidden edges ("visible+hidden").
  bool hidden_drawn() const;
  /// The feature edges of the view, in a fixed order.
  const std::vector<oracle_edge>& edges() const;
  /// Non-degenerate triangles of the soup (the occluders).
  std::size_t triangle_count() const;
  /// Signs that the filter could not decide and rationals did (filtered arithmetic).
  std::size_t exact_fallbacks() const;

  /// The verdict on the point a + t (b - a) of edges()[e]; 0 < t < 1 (exact rational).
  point_visibility classify(std::size_t e, const mpq_class& t) const;
  /// The same for a double t (taken exactly).
  point_visibility classify(std::size_t e, double t) const;
  /// Every triangle that hides that point (empty: visible), for messages.
  std::vector<occluder_hit> hiding(std::size_t e, const mpq_class& t) const;
  /// The image of edges()[e] clipped to the view volume; false when nothing of it is inside.
  bool image_of(std::size_t e, edge_image& out) const;
  /// The grid point of a world point; false behind the eye.
  bool grid_of(const exbsp::vec3d& p, std::array<double, 2>& g) const;
  /// True when some feature edge other than `except` has a visible point whose image lies
  /// within `radius` grid units of g (`radius` at most 2 tolerance + ambiguity).
  bool visible_near(const std::array<double, 2>& g, double radius, std::size_t except) const;
  /// Width and height of the viewport in grid units.
  std::array<double, 2> grid_size() const;

  struct impl;
  /// The oracle's state, for the check and the reference drawing (hidden_line_oracle.cpp).
  const impl& internals() const { return *impl_; }

 private:
  std::unique_ptr<impl> impl_;
};

/// One disagreement, for messages.
struct hidden_line_example {
  std::string problem;           ///< e.g. "visible point drawn dashed"
  std::string where;             ///< the edge (world end points, t) or the run (grid end points)
  std::array<double, 2> grid{};  ///< the point in the drawing grid
  std::string describe() const;
};

/// The comparison of a drawing with the oracle.
struct hidden_line_report {
  bool exact = false;
  bool hidden_drawn = false;
  std::size_t triangles = 0, feature_edges = 0, edges_in_view = 0;
  // Samples of the feature edges.
  std::size_t samples = 0;
  std::size_t visible_ok = 0, hidden_ok = 0;
  std::size_t hidden_covered = 0;  ///< of hidden_ok: waived by a coinciding visible edge
  std::size_t visible_dashed = 0, visible_missing = 0;  ///< visible samples drawn wrong
  std::size_t hidden_solid = 0, hidden_missing = 0;     ///< hidden samples drawn wrong
  std::size_t skipped_outside = 0, skipped_ambiguous = 0;
  // Points along the drawn runs (check_drawing).
  std::size_t run_points = 0, run_ok = 0, run_skipped = 0;
  std::size_t solid_over_hidden = 0;     ///< solid where every nearby edge is hidden
  std::size_t dashed_under_visible = 0;  ///< dashed along a visible edge
  std::size_t spurious = 0;              ///< a run where no feature edge is
  std::size_t exact_fallbacks = 0;
  std::vector<hidden_line_example> examples;

  std::size_t checked() const { return visible_ok + hidden_ok + wrong(); }
  std::size_t wrong() const {
    return visible_dashed + visible_missing + hidden_solid + hidden_missing;
  }
  std::size_t run_wrong() const { return solid_over_hidden + dashed_under_visible + spurious; }
  /// Fraction of the checked samples that agree (0 when none was checked).
  double agreement() const;
  /// Fraction of the checked run points that agree (1 when none was checked).
  double run_agreement() const;
  /// One paragraph: counts, agreements and the examples.
  std::string summary() const;
};

/// Compares the edges of drawing `d` (the visible_drawing of frame `f`) with the oracle.
hidden_line_report check_hidden_lines(const exbsp::view::frame& f,
                                      const exbsp::view::vector_drawing& d,
                                      const hidden_line_options& opt = {});
/// The same with an oracle already built (for several drawings of one frame).
hidden_line_report check_hidden_lines(const hidden_line_oracle& oracle,
                                      const exbsp::view::vector_drawing& d);

/// The oracle's own drawing of the edges: one visible_edge path and (when hidden edges are
/// asked for) one hidden_edge path, both of mesh 0, with runs split where the visibility
/// changes (bisection to a quarter of a grid unit) and hidden runs left out where a visible
/// point of another edge lies within tolerance + 1.5 grid units (coincidence, with a margin
/// for the rounding of run ends). A correct drawing by construction: the oracle's tests check that
/// it passes and that broken copies of it fail.
exbsp::view::vector_drawing reference_drawing(const hidden_line_oracle& oracle);

}  // namespace exbsp_test
