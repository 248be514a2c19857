// SPDX-License-Identifier: LGPL-3.0-or-later
// Vector output (SVG, PDF) as one intermediate list of paths: the visible-region drawing and
// the painter's stack (docs/contract.md "Pixels").
//
// Notation: the drawing grid. A window point (x, y) (viewport.h, y up) becomes the grid point
//   X = round(100 (x - vp.x)),  Y = round(100 (y - vp.y))
// (integers, 1 unit = 1/100 pixel); the writers print X / 100 and (100 height - Y) / 100, so
// every coordinate of the output is a multiple of 1/100 pixel and two regions that share a
// grid edge share it exactly in the file.
//
// Visible regions: the polygons of the transform+clip stage, taken FRONT TO BACK (the reverse
// of their back-to-front list, docs/contract.md "The BSP"), are snapped to the grid; each loses
// what the polygons before it already cover (visible(P) := P \ covered, covered := covered ∪
// visible(P)), and the visible parts of one source face are merged into one region (holes
// kept). The coverage is kept as its disjoint pieces, listed in 4-pixel tiles: P is fully
// visible when a line through an edge separates it from every piece near it (exact integer
// test: the shared edges of a mesh do), or when its overlaps with them have no area (T-junction
// chains); it is hidden when the pieces' overlaps add up to its area (areas in doubles, by
// Sutherland–Hodgman against convex windows). Only the rest (partly hidden P) goes to Clipper's
// integer Booleans, with the pieces it overlaps; a tile whose pieces' areas fill it rejects
// everything behind it at once. Rounding makes cracks under one grid unit wide where polygons
// in front meet at a T-junction; what shows through them is dropped: spikes (zero-area
// antennas, under one unit wide) are cut off the rings, and rings thinner than
// min_region_width (their area over half their perimeter) are dropped (they cannot decide any
// pixel).
//
// Underlays: anti-aliasing renderers (browsers, PDF viewers) blend each path's edge pixels
// with what is below, so two regions sharing an edge let the background through it
// ("conflation"): a faint light line between faces. The drawing therefore starts with
// underlays, filled unions of regions under them: one per mesh (part) in the area-weighted
// mean colour of its regions (under a seam between two lit faces shows a colour near both),
// then one per colour used by two or more regions (where faces of one colour meet, the seam
// shows exactly that colour). An underlay is one path whose rings are the unions of its
// regions taken in 64-pixel squares (a renderer fills a path's rings together, so no seam
// shows where two squares' unions meet). They add no area (no outline grows, nothing is
// stroked); the regions above stay one path per face.
//
// Edges (the hidden-line drawing): the feature edges (geom/feature_edges.h) split exactly into
// visible and hidden runs by the contract's rule (edge_visibility.h), drawn by edge_paths.h;
// found on a second thread while the regions are made (they depend on the frame alone).
//
// Curves and lines: each clipped piece (curves.h, painter's slot k: behind polygons k..n-1)
// keeps what is outside the coverage of those polygons; drawn over the regions.
// Effects: lighting gives each face its colour (flat per face); a screen effect's sample
// shader (sample_shader.h: fog) is applied flat per region (at the region's mean window
// point) and per curve piece (at its midpoint); depth of
// field and antialias are raster-only (the CLI warns and ignores them for vector output).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/view/image.h>

namespace exbsp::view {

struct frame;

/// "svg": {"mode", "edges", "crease_deg"} of a scene (docs/contract.md "Pixels").
struct vector_options {
  enum class mode_kind { visible, painter };
  enum class edges_kind { none, visible, visible_hidden };
  mode_kind mode = mode_kind::visible;
  /// Default for scenes: none (a scene's picture matches its PNG); `exbsp render MESH` asks for
  /// visible edges.
  edges_kind edges = edges_kind::none;
  double crease_deg = 30;  ///< 0 < crease_deg <= 180

  /// The defaults for a bare mesh drawn without a scene (`exbsp render MESH`): a CAD line
  /// drawing, visible regions with visible edges.
  static vector_options for_mesh() { return {mode_kind::visible, edges_kind::visible, 30}; }
};

/// "visible", "painter" / "none", "visible", "visible+hidden".
EXBSP_EXPORT const char* to_string(vector_options::mode_kind m);
EXBSP_EXPORT const char* to_string(vector_options::edges_kind e);
/// The edges kind whose to_string is `name`; nullopt for any other name.
EXBSP_EXPORT std::optional<vector_options::edges_kind> edges_kind_named(const std::string& name);
/// "none, visible or visible+hidden": the edges kinds' names, for messages.
EXBSP_EXPORT std::string edges_kind_names();

/// A grid point (notation above).
struct grid_point {
  long long x = 0, y = 0;
  bool operator==(const grid_point& o) const { return x == o.x && y == o.y; }
};

/// Grid units per pixel.
constexpr long long grid_per_pixel = 100;
/// Regions (and holes) thinner than this many grid units are rounding slivers (notation).
constexpr double min_region_width = 1.5;

/// One path of a drawing.
struct vector_path {
  enum class kind_type {
    underlay,      ///< filled rings: the union of the regions of one colour (see below)
    region,        ///< filled rings (nonzero), one source face
    visible_edge,  ///< stroked polylines, solid
    hidden_edge,   ///< stroked polylines, dashed
    curve,         ///< stroked polylines, 1 px, butt caps
    point          ///< a 1 x 1 pixel square centred on rings[0][0] (degree-0 curve)
  };
  kind_type kind = kind_type::region;
  rgb8 color;
  std::uint32_t mesh = 0;                      ///< mesh index (regions, edges)
  std::uint32_t face = 0;                      ///< regions: source face id; curves: curve index
  std::uint32_t fragment = 0;                  ///< painter regions: fragment index
  std::vector<std::vector<grid_point>> rings;  ///< closed rings (regions) or open polylines
};

/// Where a drawing goes in the output image (docs/contract.md "Scenes" "image"; the PNG's "place"
/// stage, placement.h): the image is image_width x image_height pixels of `background`, with
/// the drawing's lower-left corner at (x, y) (window coordinates, y up), clipped to the drawing.
struct drawing_placement {
  int image_width = 0, image_height = 0;  ///< 0 x 0: the image is the drawing
  int x = 0, y = 0;
  rgb8 background{255, 255, 255};  ///< the image around the drawing (the scene's background)
};

/// A drawing: background, then the paths in drawing order.
/// Where visible_drawing's time went, in seconds (wall clock), for benchmarks and progress.
struct vector_phase_seconds {
  double snap = 0;        ///< polygons to the grid, T-junction index
  double coverage = 0;    ///< front to back: each polygon's visible piece (mending included)
  double regions = 0;     ///< per face: the union of its pieces
  double underlays = 0;   ///< seam underlays
  double edges = 0;       ///< feature edges, exact visibility, edge paths (on their own thread)
  double edges_wait = 0;  ///< time the regions then waited for the edges
};

struct vector_drawing {
  int width = 0, height = 0;  ///< pixels (the viewport)
  rgb8 background{255, 255, 255};
  bool painter = false;  ///< the painter's stack (one region per fragment, back to front)
  std::vector<vector_path> paths;
  drawing_placement placement;   ///< set from the frame's view (view_setup::needs_placement)
  vector_phase_seconds seconds;  ///< visible_drawing: its phases' times (not output)
  /// visible_drawing: polygons of outward-closed meshes facing away from the viewer, left out
  /// as never visible (not output; view/hidden_back_faces.h).
  std::size_t back_faces_left_out = 0;

  /// True when the image is larger than the drawing or the drawing is not at its origin.
  bool placed() const {
    return placement.image_width > 0 &&
           (placement.image_width != width || placement.image_height != height ||
            placement.x != 0 || placement.y != 0);
  }
};

/// The placement of a frame's drawing (from f.view and f.background).
EXBSP_EXPORT drawing_placement placement_of(const frame& f);

/// The visible-region drawing of a frame whose transform+clip stage ran (and curves and fog
/// stages when present): underlays, regions sorted by (mesh, face), then hidden edges (when asked),
/// visible edges, curves. Meshes come from f.mesh_face_offsets (all faces in mesh 0 when empty).
/// Throws usage_error for a bad crease angle.
EXBSP_EXPORT vector_drawing visible_drawing(const frame& f);

/// The painter's stack of a frame as a drawing (the PDF writer's painter mode): one region
/// per polygon of f.polygons, back to front, with curve pieces in their slots.
EXBSP_EXPORT vector_drawing painter_drawing(const frame& f);

/// Rounds a window coordinate (already relative to the viewport origin) to the grid.
EXBSP_EXPORT long long to_grid(double v);

/// Counts of a drawing, for logs and the bench.
struct drawing_counts {
  std::size_t underlays = 0, regions = 0, rings = 0;
  std::size_t visible_edges = 0, hidden_edges = 0;  ///< straight pieces of the edge chains
  std::size_t curves = 0;
};
EXBSP_EXPORT drawing_counts count_paths(const vector_drawing& d);

}  // namespace exbsp::view
