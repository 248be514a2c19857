// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact sections of triangle meshes by planes (CAD section views): `exbsp section` and the
// scenes' "clip_planes" (docs/contract.md, "Command line" and "Scenes"). This header hides CGAL;
// the work is done in section.cpp on CGAL's Epeck kernel. section() and clip_soup() are in the
// LGPL core and make no caps; section_with_cap() and clip_soup_with_caps() (section_cap.h) are
// in the GPL component exbsp::gpl, because the cap needs CGAL's GPL triangulation.
//
// Notation: the plane P = (A, B, C, D) holds four doubles; n = (A, B, C) and the side of a
// point p is the exact sign of f(p) = A*px + B*py + C*pz + D (evaluated on the exact input,
// never rounded). The kept side is f >= 0 (glClipPlane's rule).
//   - Kept: every input triangle with all signs >= 0 (triangles in the plane included) and the
//     pieces on the f >= 0 side of straddling ones, split by the section 3 convention (pieces
//     in order, replacing their parent in list order). Pieces keep the parent's face id.
//   - Input vertices with equal coordinates are one point (merged exactly); a cut point is
//     made once per input edge, so neighbouring pieces share it.
//   - The input is "closed" when every directed edge (u, v) is used as often as (v, u)
//     (each edge exactly twice, once each way, for a manifold).
//   - Outline: the in-plane edges of kept triangles that the cut exposes, directed as in
//     the kept triangles (closed input: each edge's net use (u,v) minus (v,u); open input:
//     the in-plane edges shared by a kept and a removed piece). They are chained into simple
//     loops, oriented counter-clockwise seen from the kept side (around +n: outer boundaries
//     counter-clockwise, holes clockwise), and, for open input, open polylines.
//   - Cap (closed input only; section_cap.h): the region the outline encloses (holes and nested
//   islands
//     included: each region is covered as many times as the outline winds around it),
//     triangulated by an exact constrained Delaunay triangulation in the plane, facing -n
//     (outward from the kept part). The boundary of the cap is the outline reversed, so
//     kept ∪ cap is closed again: every edge is used as often in each direction.
//   - A face in the plane is kept. When the solid is on the negative side of such a face, the
//     kept part is the face alone and the cap is that face reversed (a flat double-sided
//     sheet, still closed); a plane that only touches the mesh along an edge or at a vertex
//     cuts nothing (no outline, no cap).
//   - Loops of the outline that cross or overlap along an edge (self-intersecting or
//     non-conforming input, e.g. two solids sharing part of a face) make the triangulation
//     subdivide outline edges (at Steiner points where loops cross, or at outline points on
//     another loop's edge): the kept triangles on those edges are then split by a fan from
//     the opposite corner and the outline edges replaced by their pieces, so kept ∪ cap stays
//     closed (counted in section_stats::cap_steiner_points and split_constraints; only there
//     does the kept list differ from the plain section 3 pieces).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <exbsp/core/export.h>

#include <exbsp/mesh/soup.h>

namespace exbsp {

/// Cut plane A*x + B*y + C*z + D = 0; the kept side is where it is >= 0.
using section_plane = std::array<double, 4>;

/// Throws usage_error unless the four numbers are finite and (A, B, C) is not zero.
/// `what` names the plane in the message (e.g. "--plane").
EXBSP_EXPORT void check_section_plane(const section_plane& plane,
                                      const std::string& what = "plane");

/// A point of a section: correctly rounded doubles and, when asked for, the exact
/// coordinates as reduced rationals "p/q" (or "p").
struct section_point {
  vec3d v;
  std::array<std::string, 3> exact;
};

/// A triangle of a section: three indices into section_result::points and the face id
/// (kept: the input face; cap: section_result::cap_face).
struct section_triangle {
  std::array<std::uint32_t, 3> p;
  std::uint32_t face;
};

/// A chain of the outline: point indices; closed loops do not repeat their first point.
struct section_chain {
  std::vector<std::uint32_t> p;
  bool closed;
};

/// Counters of one section.
struct section_stats {
  std::size_t input_triangles = 0;  ///< triangles of the soup
  std::size_t degenerate_input =
      0;                       ///< exactly collinear input triangles (kept or dropped like others)
  std::size_t kept_whole = 0;  ///< input triangles kept unsplit (in-plane ones included)
  std::size_t in_plane = 0;    ///< input triangles lying in the plane (kept)
  std::size_t split = 0;       ///< straddling triangles that were split
  std::size_t removed = 0;     ///< input triangles entirely on the negative side
  std::size_t cut_points = 0;  ///< points made on crossing edges
  std::size_t outline_edges = 0;  ///< directed outline edges (with multiplicity)
  std::size_t cap_triangles = 0;
  std::size_t cap_steiner_points =
      0;  ///< triangulation vertices not on the outline (crossing loops)
  std::size_t split_constraints =
      0;               ///< outline edges the triangulation subdivided (kept refined there)
  double seconds = 0;  ///< wall time of the section
};

/// Everything a section produces.
struct section_result {
  section_plane plane{};
  bool closed = false;                 ///< the input is closed (see the notation above)
  std::vector<section_point> points;   ///< every point used below, merged exactly
  std::vector<section_triangle> kept;  ///< kept triangles in section 3 order
  std::vector<section_chain> outline;  ///< loops first (closed input: loops only)
  std::vector<section_triangle> cap;   ///< section_with_cap only, and only when `closed`
  std::uint32_t cap_face = 0;          ///< face id of the cap triangles (= input face_count)
  section_stats stats;
};

/// (Written like engine.h's for_each_stat: one visitor per statistics struct is the one place
/// its fields are listed for output.)
/// Every counter of the section `r` as visit(name, value), in the order the command line's
/// JSON and the Python module's dict list them: section_stats' counts (std::size_t), with
/// "kept" (kept triangles) after "removed", then "seconds" (double).
template <class Visit>
void for_each_section_stat(const section_result& r, Visit&& visit) {
  // The counts in output order; "kept" (no member) counts r.kept.
  using count = std::size_t section_stats::*;
  static constexpr std::pair<const char*, count> counts[] = {
      {"input_triangles", &section_stats::input_triangles},
      {"degenerate_input", &section_stats::degenerate_input},
      {"kept_whole", &section_stats::kept_whole},
      {"in_plane", &section_stats::in_plane},
      {"split", &section_stats::split},
      {"removed", &section_stats::removed},
      {"kept", nullptr},
      {"cut_points", &section_stats::cut_points},
      {"outline_edges", &section_stats::outline_edges},
      {"cap_triangles", &section_stats::cap_triangles},
      {"cap_steiner_points", &section_stats::cap_steiner_points},
      {"split_constraints", &section_stats::split_constraints}};
  for (const auto& [name, member] : counts) visit(name, member ? r.stats.*member : r.kept.size());
  visit("seconds", r.stats.seconds);
}

/// Options of section().
struct section_options {
  bool exact_text = true;  ///< fill section_point::exact (costs time; off for rendering)
};

/// Cuts `soup` by `plane` exactly (see the notation above): kept triangles and outline, no
/// cap (section_with_cap in section_cap.h makes it). Throws usage_error for a bad plane
/// (check_section_plane); never aborts.
EXBSP_EXPORT section_result section(const triangle_soup& soup, const section_plane& plane,
                                    const section_options& options = {});

/// Clips `soup` by every plane in turn (keeping f >= 0 of each, i.e. the intersection of the
/// half-spaces), without caps (clip_soup_with_caps in section_cap.h adds them). The cut is
/// exact; the returned soup holds the exact points rounded once to the nearest doubles (the
/// BSP's input is doubles, docs/contract.md "Input"); face_count is unchanged. Throws
/// usage_error for a bad plane.
EXBSP_EXPORT triangle_soup clip_soup(const triangle_soup& soup,
                                     const std::vector<section_plane>& planes);

/// Output formats of `exbsp section` (docs/contract.md "Command line").
///   json: {"plane", "closed", "kept": [{"face", "v", "exact"}], "outline": [{"closed", "v",
///         "exact"}], "cap": [{"v", "exact"}], "stats"} (doubles with 17 significant digits);
///   off:  kept ∪ cap as one OFF mesh, shared points merged exactly (one vertex each);
///   svg:  the outline drawn in the cut plane (see section_svg_basis), loops filled with
///         `cap_color` under the nonzero rule, open polylines stroked.
/// Precondition for json: the result was made with exact_text.
EXBSP_EXPORT std::string section_json(const section_result& r);
EXBSP_EXPORT std::string section_off(const section_result& r);
EXBSP_EXPORT std::string section_svg(const section_result& r,
                                     const std::array<unsigned char, 3>& cap_color = {200, 60, 50});

/// The in-plane basis of the SVG drawing: n̂ = n/|n|; m = the axis of the smallest |n_m|
/// (first on ties); u = e_m - (e_m·n̂) n̂ normalised; v = n̂ × u; so (u, v, n̂) is right-handed
/// and the drawing is seen from the kept side (plane z = c: u = x, v = y). The SVG shows
/// (u·p, v·p) with v upwards.
EXBSP_EXPORT std::array<vec3d, 2> section_svg_basis(const section_plane& plane);

}  // namespace exbsp
