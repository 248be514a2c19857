// SPDX-License-Identifier: LGPL-3.0-or-later
// Visible regions, hidden-line edges and curves for vector output (notation in
// vector_drawing.h). The 2D Booleans are Clipper's (libpolyclipping): integer coordinates, so
// the grid points of the drawing are its exact input and output; a measurement against CGAL's
// Boolean_set_operations_2 on an exact kernel is in bench/vector_output.md.
#include <exbsp/view/vector_drawing.h>

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <map>
#include <memory>
#include <optional>

#include <exbsp/core/errors.h>
#include <exbsp/view/pipeline.h>
#include "geom/closed_shells.h"
#include "geom/soup_cache.h"
#include "view/clip_stage.h"
#include "view/edge_paths.h"
#include "view/hidden_back_faces.h"
#include "view/visible_cover.h"
#include "view/visible_strips.h"
#include "view/workers.h"
#include "core/name_list.h"

namespace exbsp::view {

namespace cl = ClipperLib;
using cover::bbox_i;
using cover::convex_ccw;
using cover::cut_to_band;
using cover::striped_coverage;
using cover::t_junction_mender;
using cover::tiled_coverage;
using cover::without_straight_vertices;

const char* to_string(vector_options::mode_kind m) {
  return m == vector_options::mode_kind::painter ? "painter" : "visible";
}

const char* to_string(vector_options::edges_kind e) {
  switch (e) {
    case vector_options::edges_kind::none:
      return "none";
    case vector_options::edges_kind::visible:
      return "visible";
    case vector_options::edges_kind::visible_hidden:
      return "visible+hidden";
  }
  return "?";
}

namespace {
constexpr vector_options::edges_kind all_edges_kinds[] = {
    vector_options::edges_kind::none, vector_options::edges_kind::visible,
    vector_options::edges_kind::visible_hidden};
}  // namespace

std::optional<vector_options::edges_kind> edges_kind_named(const std::string& name) {
  for (const vector_options::edges_kind e : all_edges_kinds)
    if (name == to_string(e)) return e;
  return std::nullopt;
}

std::string edges_kind_names() {
  std::vector<std::string> names;
  for (const vector_options::edges_kind e : all_edges_kinds) names.push_back(to_string(e));
  return name_list(names, "or");
}

long long to_grid(double v) {
  const double s = v * static_cast<double>(grid_per_pixel);
  // std::llround(s) without its library call (40 instructions; a third of the snap): truncate,
  // then round the remainder half away from zero. The remainder s - trunc(s) is exact (the
  // fraction bits of s), so the result is llround's for every s in range.
  if (!(std::abs(s) < 0x1p62)) return std::llround(s);
  const auto t = static_cast<long long>(s);
  const double rest = s - static_cast<double>(t);
  return rest >= 0.5 ? t + 1 : rest <= -0.5 ? t - 1 : t;
}

drawing_counts count_paths(const vector_drawing& d) {
  drawing_counts c;
  for (const vector_path& p : d.paths) {
    switch (p.kind) {
      case vector_path::kind_type::underlay:
        ++c.underlays;
        break;
      case vector_path::kind_type::region:
        ++c.regions;
        c.rings += p.rings.size();
        break;
      case vector_path::kind_type::visible_edge:
        for (const auto& r : p.rings) c.visible_edges += r.size() - 1;
        break;
      case vector_path::kind_type::hidden_edge:
        for (const auto& r : p.rings) c.hidden_edges += r.size() - 1;
        break;
      case vector_path::kind_type::curve:
      case vector_path::kind_type::point:
        ++c.curves;
        break;
    }
  }
  return c;
}

namespace {

cl::IntPoint grid_of(const viewport& vp, const window_point& w) {
  return {to_grid(w.x - vp.x), to_grid(w.y - vp.y)};
}

std::vector<grid_point> to_ring(const cl::Path& p) {
  std::vector<grid_point> r;
  r.reserve(p.size());
  for (const cl::IntPoint& q : p) r.push_back({q.X, q.Y});
  return r;
}

/// A drawing's ring as a Clipper path, in `out` (its buffer reused).
void to_path(const std::vector<grid_point>& ring, cl::Path& out) {
  out.clear();
  for (const grid_point& q : ring) out.push_back({q.x, q.y});
}

/// Mean width 2 |area| / perimeter of a closed ring, in grid units.
double mean_width(const cl::Path& p) {
  double perimeter = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const cl::IntPoint& a = p[i];
    const cl::IntPoint& b = p[(i + 1) % p.size()];
    perimeter += std::hypot(static_cast<double>(b.X - a.X), static_cast<double>(b.Y - a.Y));
  }
  return perimeter > 0 ? 2 * std::abs(cl::Area(p)) / perimeter : 0;
}

/// True when b is the tip of a spike a -> b -> c: a and c lie on the same side of b, the
/// nearer of them less than one grid unit from the line through b and the farther one. Such
/// zero-area antennas appear where a region shows through a rounding crack (a T-junction of
/// the polygons in front of it); they are no part of any true region.
bool spike_at(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
  const double ax = static_cast<double>(a.X - b.X), ay = static_cast<double>(a.Y - b.Y);
  const double cx = static_cast<double>(c.X - b.X), cy = static_cast<double>(c.Y - b.Y);
  if (ax * cx + ay * cy <= 0) return false;
  const double longer = std::max(std::hypot(ax, ay), std::hypot(cx, cy));
  return longer > 0 && std::abs(ax * cy - ay * cx) < longer;
}

/// The ring without spikes (spike_at), removed until none is left, but for tips on the lines
/// y = keep_y (sorted): the strip lines, where a polygon cut by a strip line has two crossings
/// that may lie a unit apart and the face across the line has the same two; taking one as a
/// spike's tip would cut a unit-wide sliver along the long edge beside it, and a crack between
/// the two faces.
void remove_spikes(cl::Path& ring, const std::vector<long long>& keep_y) {
  auto spike = [&](const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
    return spike_at(a, b, c) && !std::binary_search(keep_y.begin(), keep_y.end(), b.Y);
  };
  cl::Path out;
  out.reserve(ring.size());
  for (const cl::IntPoint& p : ring) {
    out.push_back(p);
    while (out.size() >= 3 && spike(out[out.size() - 3], out[out.size() - 2], out.back()))
      out.erase(out.end() - 2);
  }
  for (bool changed = true; changed && out.size() >= 3;) {
    changed = false;
    const std::size_t n = out.size();
    if (spike(out[n - 2], out[n - 1], out[0])) {
      out.pop_back();
      changed = true;
    } else if (spike(out[n - 1], out[0], out[1])) {
      out.erase(out.begin());
      changed = true;
    }
  }
  ring.swap(out);
}

rgb8 shaded(const frame& f, rgb8 c, double x, double y, double z) {
  return f.shader ? f.shader->shade(c, x, y, z) : c;
}

/// A curve piece (or point) as a path, shaded at its midpoint.
vector_path curve_path(const frame& f, const screen_line& l) {
  vector_path p;
  p.kind = l.point ? vector_path::kind_type::point : vector_path::kind_type::curve;
  p.face = l.curve;
  p.color = shaded(f, l.color, 0.5 * (l.a.x + l.b.x), 0.5 * (l.a.y + l.b.y), 0.5 * (l.a.z + l.b.z));
  const viewport& vp = f.view.vp;
  p.rings.push_back({{to_grid(l.a.x - vp.x), to_grid(l.a.y - vp.y)}});
  if (!l.point) p.rings.back().push_back({to_grid(l.b.x - vp.x), to_grid(l.b.y - vp.y)});
  return p;
}

/// Appends `piece` to the drawing, joined to the previous curve path when it continues it
/// (same curve, same colour).
void append_curve(vector_drawing& d, vector_path&& piece) {
  if (piece.kind == vector_path::kind_type::curve && !d.paths.empty()) {
    vector_path& last = d.paths.back();
    if (last.kind == vector_path::kind_type::curve && last.face == piece.face &&
        last.color == piece.color) {
      for (auto& r : piece.rings) {
        if (!last.rings.empty() && last.rings.back().back() == r.front())
          last.rings.back().insert(last.rings.back().end(), r.begin() + 1, r.end());
        else
          last.rings.push_back(std::move(r));
      }
      return;
    }
  }
  d.paths.push_back(std::move(piece));
}

/// The frame's polygons on the grid, counter-clockwise, in one array (polygon k: points
/// [start[k], start[k + 1]), none when it has no area), with their boxes. Paths are made only
/// for the polygons the coverage walk takes (most hidden ones never need one).
struct snapped_polygons {
  std::vector<cl::IntPoint> points;
  std::vector<std::size_t> start;
  std::vector<bbox_i> boxes;

  bool has_area(std::size_t k) const { return start[k + 1] > start[k]; }
  /// Polygon k in `out` (its buffer reused).
  void path(std::size_t k, cl::Path& out) const {
    out.assign(points.begin() + static_cast<std::ptrdiff_t>(start[k]),
               points.begin() + static_cast<std::ptrdiff_t>(start[k + 1]));
  }
};

/// Snaps the polygons [k0, k1) of the frame into s (polygon k0 + i is s's polygon i).
void snap_range(const frame& f, const std::vector<std::uint8_t>& hidden_face, std::size_t k0,
                std::size_t k1, snapped_polygons& s) {
  s.start.reserve(k1 - k0 + 1);
  s.boxes.resize(k1 - k0);
  s.start.push_back(0);
  cl::Path poly;  // polygon k for Clipper's area, one buffer for all
  for (std::size_t k = k0; k < k1; ++k) {
    const std::size_t first = s.points.size();
    if (left_out(hidden_face, f.polygons[k])) {  // a back face left out: walked nowhere
      s.start.push_back(first);
      continue;
    }
    for (const window_point& w : f.polygons[k].v) {
      const cl::IntPoint q = grid_of(f.view.vp, w);
      if (s.points.size() == first || !(s.points.back() == q)) s.points.push_back(q);
    }
    while (s.points.size() > first + 1 && s.points[first] == s.points.back()) s.points.pop_back();
    poly.assign(s.points.begin() + static_cast<std::ptrdiff_t>(first), s.points.end());
    const double area = poly.size() < 3 ? 0 : cl::Area(poly);
    if (area == 0) {  // seen edge-on: no area
      s.points.resize(first);
    } else {
      if (area < 0)
        std::reverse(s.points.begin() + static_cast<std::ptrdiff_t>(first), s.points.end());
      s.boxes[k - k0] = cover::bbox_of(poly);
    }
    s.start.push_back(s.points.size());
  }
}

/// Snaps every polygon of the frame (snapped_polygons): in a fixed number of blocks of
/// consecutive polygons, snapped on the workers and joined in order (the same arrays whatever
/// the number of workers).
snapped_polygons snap(const frame& f, const std::vector<std::uint8_t>& hidden_face,
                      unsigned workers) {
  constexpr std::size_t blocks = 16;
  const std::size_t n = f.polygons.size();
  std::vector<snapped_polygons> part(blocks);
  parallel_for(blocks, workers, [&](std::size_t b, unsigned) {
    snap_range(f, hidden_face, n * b / blocks, n * (b + 1) / blocks, part[b]);
  });
  snapped_polygons s;
  std::size_t points = 0;
  for (const snapped_polygons& p : part) points += p.points.size();
  s.points.reserve(points);
  s.start.reserve(n + 1);
  s.boxes.reserve(n);
  s.start.push_back(0);
  for (const snapped_polygons& p : part) {
    const std::size_t base = s.points.size();
    s.points.insert(s.points.end(), p.points.begin(), p.points.end());
    for (std::size_t i = 1; i < p.start.size(); ++i) s.start.push_back(base + p.start[i]);
    s.boxes.insert(s.boxes.end(), p.boxes.begin(), p.boxes.end());
  }
  return s;
}

/// Per face: the pieces of its visible region and the data for its colour.
struct face_accumulator {
  std::vector<cover::piece_ref> pieces;  ///< its visible pieces in the coverage
  rgb8 color;
  double shown = 0;  ///< visible area of the fragment that gave the colour
  bool seen = false;
  double sx = 0, sy = 0, sz = 0;
  std::size_t n = 0;
};

}  // namespace

drawing_placement placement_of(const frame& f) {
  const view_setup& v = f.view;
  if (!v.needs_placement()) return {};
  return {v.image_width, v.image_height, v.place_x, v.place_y, f.background};
}

namespace {

/// A drawing of the frame's viewport with nothing on it: its size, background (the sample
/// shader's when a screen effect installed one) and placement in the image.
vector_drawing empty_drawing(const frame& f) {
  vector_drawing d;
  d.width = f.view.vp.width;
  d.height = f.view.vp.height;
  d.background = f.shader ? f.shader->background : f.background;
  d.placement = placement_of(f);
  return d;
}

/// Strips of the coverage walk (visible_strips.h): a constant, so that the drawing does not
/// depend on the machine; eight keep the cores evenly busy while the edges take their share
/// (bunny00 at 1024 x 768 on 2 cores: the svg stage 0.95x the time with four).
constexpr int coverage_strips = 8;

/// A fragment's piece in a strip: the polygon, the piece's id there, its area.
struct strip_hit {
  std::uint32_t polygon;
  std::uint32_t piece;
  double area;
};

/// What the walk of one strip found.
struct strip_walk {
  std::vector<strip_hit> hits;        ///< in walk order (front to back)
  std::vector<cl::Paths> line_parts;  ///< per line (segments): its parts left visible here
  std::vector<char> point_shown;      ///< per line (points in this strip): not covered
};

/// The walk of strip s, front to back: each polygon meeting the strip (mended, cut to the strip
/// when it crosses a strip line) loses what the ones before it cover there; the lines of each
/// slot are clipped when the walk reaches it.
void walk_strip(const frame& f, const snapped_polygons& snapped, const t_junction_mender& mender,
                striped_coverage& coverage, std::size_t s, strip_walk& out) {
  tiled_coverage& cov = coverage.strip(s);
  const long long y0 = coverage.y0(s), y1 = coverage.y1(s);
  const viewport& vp = f.view.vp;
  out.line_parts.assign(f.lines.size(), {});
  out.point_shown.assign(f.lines.size(), 0);
  cover::t_junction_mender::scratch scratch;
  cl::Path poly, cut, segment;
  auto clip_line = [&](std::size_t i) {
    const screen_line& l = f.lines[i];
    const cl::IntPoint a = grid_of(vp, l.a), b = grid_of(vp, l.b);
    if (l.point) {
      // Each point in one strip (strip lines avoid the points' ordinates: strip_rows).
      if (a.Y >= y0 && a.Y < y1) out.point_shown[i] = !cov.covers(a);
    } else if (cover::segment_in_band(a, b, y0, y1, segment)) {
      out.line_parts[i] = cov.outside(segment);
    }
  };
  std::size_t next_line = f.lines.size();  // lines are sorted by slot; taken from the back
  for (std::size_t k = f.polygons.size(); k-- > 0;) {
    // Lines of slot k + 1 lie behind polygons k + 1 .. n - 1: clip them now.
    while (next_line > 0 && f.lines[next_line - 1].slot > k) clip_line(--next_line);
    if (!snapped.has_area(k)) continue;  // edge-on, or a back face left out
    const bbox_i& b = snapped.boxes[k];
    if (b.y1 <= y0 || b.y0 >= y1) continue;  // no area in this strip
    if (cov.hides({b.x0, std::max(b.y0, y0), b.x1, std::min(b.y1, y1)})) continue;
    snapped.path(k, poly);
    mender.mend(poly, scratch);
    cl::Path* p = &poly;
    if (b.y0 < y0 || b.y1 > y1) {
      if (!cut_to_band(poly, y0, y1, cut)) continue;
      p = &cut;
    }
    const std::uint32_t piece = cov.add(*p, f.mesh_of(f.polygons[k].face));
    if (piece == tiled_coverage::no_piece) continue;
    double area = 0;
    for (const cl::Path& r : cov.rings(piece)) area += cl::Area(r);
    out.hits.push_back({static_cast<std::uint32_t>(k), piece, area});
  }
  while (next_line > 0) clip_line(--next_line);
}

}  // namespace

vector_drawing visible_drawing(const frame& f) {
  const vector_options& opt = f.vector;
  if (!(opt.crease_deg > 0 && opt.crease_deg <= 180))
    throw usage_error("svg: crease_deg must be in (0, 180], got " + std::to_string(opt.crease_deg));
  const viewport& vp = f.view.vp;
  vector_drawing d = empty_drawing(f);
  // The edges depend on the frame alone, not on the regions: they are found on a second thread
  // meanwhile (the frame is only read; an exception reaches the caller through get()).
  using clock = std::chrono::steady_clock;
  auto since = [](clock::time_point t0) {
    return std::chrono::duration<double>(clock::now() - t0).count();
  };
  // Which meshes are outward closed (kept across views; for a new soup made on a third thread,
  // the edges' thread starting meanwhile): their back faces are left out (hidden_back_faces.h).
  std::future<std::shared_ptr<const std::vector<std::uint8_t>>> closed;
  if (may_leave_out_back_faces(f))
    closed = std::async(std::launch::async, [&f] {
      return f.soup_products ? f.soup_products->outward_closed_for(f.soup, f.mesh_face_offsets)
                             : std::make_shared<const std::vector<std::uint8_t>>(
                                   geom::outward_closed_meshes(f.soup, f.mesh_face_offsets));
    });
  std::future<std::vector<vector_path>> edges;
  if (opt.edges != vector_options::edges_kind::none)
    edges = std::async(std::launch::async, [&f, &d, since] {
      const clock::time_point t0 = clock::now();
      vector_drawing e;
      add_edge_paths(f, f.vector, e);
      d.seconds.edges = since(t0);  // read by the caller only after get()
      return std::move(e.paths);
    });
  clock::time_point t0 = clock::now();
  const long long width = static_cast<long long>(vp.width) * grid_per_pixel;
  const long long height = static_cast<long long>(vp.height) * grid_per_pixel;
  std::uint32_t face_end = 0;
  for (const screen_polygon& p : f.polygons) face_end = std::max(face_end, p.face + 1);
  std::vector<face_accumulator> faces(face_end);
  // Snap the polygons to the grid (counter-clockwise), in blocks over the workers, then index
  // the points for mending T-junctions (on this thread: built in bands over the workers it was
  // no faster on 2 cores, the edges' thread running meanwhile). Back faces left out are not
  // snapped: they are drawn nowhere, so no crack can open towards their points either.
  const unsigned workers = hardware_workers();  // strips, regions, underlay groups: in slots
  const std::vector<std::uint8_t> hidden_face =
      closed.valid() ? hidden_back_faces(f, *closed.get(), workers) : std::vector<std::uint8_t>();
  const snapped_polygons snapped = snap(f, hidden_face, workers);
  const t_junction_mender mender(snapped.points, width, height);
  d.seconds.snap = since(t0);
  t0 = clock::now();
  // The walk, front to back, in strips (visible_strips.h) that the workers take in turn.
  std::vector<long long> centres;
  for (std::size_t k = 0; k < f.polygons.size(); ++k) {
    d.back_faces_left_out += left_out(hidden_face, f.polygons[k]);
    if (snapped.has_area(k)) centres.push_back((snapped.boxes[k].y0 + snapped.boxes[k].y1) / 2);
  }
  std::vector<long long> avoid;  // the lines' points and horizontal segments
  for (const screen_line& l : f.lines) {
    const cl::IntPoint a = grid_of(vp, l.a), b = grid_of(vp, l.b);
    if (l.point || a.Y == b.Y) avoid.push_back(a.Y);
  }
  std::sort(avoid.begin(), avoid.end());
  striped_coverage coverage(width, cover::strip_rows(centres, height, coverage_strips, avoid));
  centres = {};
  std::vector<strip_walk> walks(coverage.size());
  parallel_for(coverage.size(), workers, [&](std::size_t s, unsigned) {
    walk_strip(f, snapped, mender, coverage, s, walks[s]);
  });
  // Each face's pieces (strip by strip, each strip in walk order) and its colour: that of the
  // fragment showing most of it, over all strips (a sliver fragment's normal, from its rounded
  // corners, may be far off: lighting is per fragment).
  std::vector<double> shown(f.polygons.size(), -1);  // -1: no visible piece
  for (std::size_t s = 0; s < walks.size(); ++s)
    for (const strip_hit& h : walks[s].hits) {
      faces[f.polygons[h.polygon].face].pieces.push_back({static_cast<std::uint32_t>(s), h.piece});
      shown[h.polygon] = std::max(shown[h.polygon], 0.0) + h.area;
    }
  for (std::size_t k = f.polygons.size(); k-- > 0;) {
    if (shown[k] < 0) continue;
    const screen_polygon& p = f.polygons[k];
    face_accumulator& acc = faces[p.face];
    if (!acc.seen || shown[k] > acc.shown) {
      acc.seen = true;
      acc.color = p.color;
      acc.shown = shown[k];
    }
    for (const window_point& w : p.v) {
      acc.sx += w.x;
      acc.sy += w.y;
      acc.sz += w.z;
      ++acc.n;
    }
  }
  shown = {};
  // The lines, front to back as the walk met them: the parts the strips left of each.
  std::vector<vector_path> curve_paths;
  for (std::size_t i = f.lines.size(); i-- > 0;) {
    const screen_line& l = f.lines[i];
    vector_path p = curve_path(f, l);
    if (l.point) {
      if (std::any_of(walks.begin(), walks.end(),
                      [&](const strip_walk& w) { return w.point_shown[i] != 0; }))
        curve_paths.push_back(std::move(p));
      continue;
    }
    p.rings.clear();
    const bool up = l.b.y >= l.a.y;  // grid y grows with window y: strips in the line's order
    for (std::size_t j = 0; j < walks.size(); ++j)
      for (const cl::Path& part : walks[up ? j : walks.size() - 1 - j].line_parts[i]) {
        if (part.size() < 2) continue;
        std::vector<grid_point> ring = to_ring(part);
        if (!p.rings.empty() && p.rings.back().back() == ring.front())
          p.rings.back().insert(p.rings.back().end(), ring.begin() + 1, ring.end());
        else
          p.rings.push_back(std::move(ring));
      }
    if (!p.rings.empty()) curve_paths.push_back(std::move(p));
  }
  walks = {};
  d.seconds.coverage = since(t0);
  t0 = clock::now();

  std::vector<long long> strip_lines;  // sorted
  for (std::size_t s = 1; s < coverage.size(); ++s) strip_lines.push_back(coverage.y0(s));
  // One region per face: the union of its pieces, rounding slivers dropped.
  std::vector<std::uint32_t> face_ids;
  for (std::uint32_t face = 0; face < face_end; ++face)
    if (faces[face].seen) face_ids.push_back(face);
  std::sort(face_ids.begin(), face_ids.end(), [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t ma = f.mesh_of(a), mb = f.mesh_of(b);
    return ma != mb ? ma < mb : a < b;
  });
  // Faces are independent: split over the workers, each with its own Clipper, into slots.
  struct worker_state {
    cl::Clipper clipper;
    cl::Paths merged;
    std::vector<const cl::Path*> rings;
  };
  std::vector<worker_state> work(workers);
  std::vector<vector_path> slots(face_ids.size());
  parallel_for(face_ids.size(), workers, [&](std::size_t i, unsigned w) {
    const std::uint32_t face = face_ids[i];
    const face_accumulator& acc = faces[face];
    cl::Paths& merged = work[w].merged;
    std::vector<const cl::Path*>& rings = work[w].rings;
    merged.clear();
    const cl::Paths& first = coverage.rings(acc.pieces[0]);
    // The pieces of a face (most faces: the fragments of a face seen whole, convex) meet along
    // edges they share exactly, mended: their union is their boundary. Where they do not
    // (a T-junction between pieces, rings touching at a vertex), Clipper's union.
    rings.clear();
    for (const cover::piece_ref piece : acc.pieces)
      for (const cl::Path& r : coverage.rings(piece)) rings.push_back(&r);
    if (rings.size() == 1 && convex_ccw(first[0])) {
      merged.push_back(without_straight_vertices(first[0]));
    } else if (!cover::union_by_shared_edges(rings, merged)) {
      merged.clear();
      cl::Clipper& clipper = work[w].clipper;
      clipper.Clear();
      for (const cover::piece_ref piece : acc.pieces)
        clipper.AddPaths(coverage.rings(piece), cl::ptSubject, true);
      clipper.Execute(cl::ctUnion, merged, cl::pftNonZero, cl::pftNonZero);
    }
    vector_path& r = slots[i];
    r.kind = vector_path::kind_type::region;
    r.face = face;
    r.mesh = f.mesh_of(face);
    const double n = static_cast<double>(acc.n);
    r.color = shaded(f, acc.color, acc.sx / n, acc.sy / n, acc.sz / n);
    for (cl::Path& ring : merged) {
      remove_spikes(ring, strip_lines);
      if (ring.size() >= 3 && mean_width(ring) >= min_region_width)
        r.rings.push_back(to_ring(ring));
    }
  });
  std::vector<vector_path> regions;
  regions.reserve(slots.size());
  for (vector_path& r : slots)
    if (!r.rings.empty()) regions.push_back(std::move(r));
  slots = {};
  d.seconds.regions = since(t0);
  t0 = clock::now();
  // Underlays (notation): the union of a group of regions, in one colour, under them.
  // The union is taken per group of regions near each other (by the square of side
  // underlay_side holding the first point of their first ring) and the groups' unions are one
  // path: a renderer fills a path's rings together (nonzero), so where two groups abut or
  // overlap no seam shows, and each union stays small (one union of a whole mesh cost 0.9 s
  // on bunny00). A mesh's underlay starts with the coverage's full tiles holding its pieces
  // only (row runs of squares: inside the union of its regions, but for rounding slivers),
  // and its regions lying wholly in them join no union.
  constexpr long long underlay_side = 64 * grid_per_pixel;
  // The underlays to draw, in order: their regions, colour and mesh (full tiles), then their
  // groups; all groups' unions are taken in one pass over the workers (one pass per underlay
  // started threads thousands of times on a lit mesh, whose colours are many).
  struct underlay_job {
    const std::vector<std::size_t>* members;  ///< its regions
    rgb8 color;
    std::optional<std::uint32_t> mesh;
    std::vector<std::vector<std::size_t>> groups;  ///< regions, per square, in the squares' order
  };
  std::vector<underlay_job> jobs;
  // A job's groups (independent of the other jobs: found on the workers).
  auto group_job = [&](underlay_job& job) {
    const std::optional<std::uint32_t>& mesh = job.mesh;
    std::map<std::pair<long long, long long>, std::vector<std::size_t>> groups;
    for (std::size_t k : *job.members) {
      if (mesh) {
        bbox_i b{regions[k].rings[0][0].x, regions[k].rings[0][0].y, regions[k].rings[0][0].x,
                 regions[k].rings[0][0].y};
        for (const auto& ring : regions[k].rings)
          for (const grid_point& q : ring)
            b = {std::min(b.x0, q.x), std::min(b.y0, q.y), std::max(b.x1, q.x),
                 std::max(b.y1, q.y)};
        if (coverage.inside_full_tiles_of(b, *mesh)) continue;
      }
      const grid_point& q = regions[k].rings[0][0];
      groups[{q.x / underlay_side, q.y / underlay_side}].push_back(k);
    }
    for (auto& entry : groups) job.groups.push_back(std::move(entry.second));
  };
  // First one per mesh of two or more regions, in their mean colour weighted by area: under
  // a seam between two lit faces of a part shows a colour near both, not the background.
  std::map<std::uint32_t, std::vector<std::size_t>> by_mesh;
  std::vector<std::pair<std::vector<std::size_t>, rgb8>> done;  // to draw no underlay twice
  for (std::size_t k = 0; k < regions.size(); ++k) by_mesh[regions[k].mesh].push_back(k);
  for (const auto& [mesh, members] : by_mesh) {
    if (members.size() < 2) continue;
    double sum[3] = {0, 0, 0}, total = 0;
    cl::Path p;  // one buffer for every ring's area
    for (std::size_t k : members) {
      double area = 0;
      for (const auto& ring : regions[k].rings) {
        to_path(ring, p);
        area += cl::Area(p);
      }
      area = std::abs(area);
      const rgb8& c = regions[k].color;
      sum[0] += area * c.r;
      sum[1] += area * c.g;
      sum[2] += area * c.b;
      total += area;
    }
    if (!(total > 0)) continue;
    auto mean = [&](double v) { return static_cast<std::uint8_t>(std::lround(v / total)); };
    const rgb8 color{mean(sum[0]), mean(sum[1]), mean(sum[2])};
    jobs.push_back({&members, color, mesh, {}});
    done.push_back({members, color});
  }
  // Then one per colour used by two or more regions: where faces of one colour meet, the
  // seam shows exactly that colour.
  // The regions of each colour, in the order of (r, g, b) and of the regions: sorted pairs of
  // the colour packed in one integer and the region (a std::map of colours cost 8 ms here on
  // bunny00, its nodes and lists allocated one by one).
  std::vector<std::pair<std::uint32_t, std::size_t>> keyed(regions.size());
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const rgb8& c = regions[k].color;
    keyed[k] = {static_cast<std::uint32_t>(c.r) << 16 | static_cast<std::uint32_t>(c.g) << 8 | c.b,
                k};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::vector<std::size_t>> by_color;  // colours of two or more regions
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i;
    while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    if (j - i >= 2) {
      by_color.emplace_back();
      for (std::size_t k = i; k < j; ++k) by_color.back().push_back(keyed[k].second);
    }
    i = j;
  }
  for (const std::vector<std::size_t>& members : by_color) {
    const rgb8 color = regions[members[0]].color;
    const bool drawn = std::any_of(done.begin(), done.end(), [&](const auto& u) {
      return u.second == color && u.first == members;
    });
    if (!drawn) jobs.push_back({&members, color, std::nullopt, {}});
  }
  parallel_for(jobs.size(), workers, [&](std::size_t j, unsigned) { group_job(jobs[j]); });
  // Every group's union, over the workers, into slots in the jobs' order.
  std::vector<const std::vector<std::size_t>*> group_list;
  for (const underlay_job& job : jobs)
    for (const std::vector<std::size_t>& g : job.groups) group_list.push_back(&g);
  std::vector<std::vector<std::vector<grid_point>>> unions(group_list.size());
  parallel_for(group_list.size(), workers, [&](std::size_t g, unsigned w) {
    cl::Clipper& clipper = work[w].clipper;
    cl::Paths& merged = work[w].merged;
    clipper.Clear();
    cl::Path p;
    for (std::size_t k : *group_list[g])
      for (const auto& ring : regions[k].rings) {
        to_path(ring, p);
        clipper.AddPath(p, cl::ptSubject, true);
      }
    merged.clear();
    clipper.Execute(cl::ctUnion, merged, cl::pftNonZero, cl::pftNonZero);
    for (cl::Path& ring : merged) {
      remove_spikes(ring, strip_lines);
      if (ring.size() >= 3) unions[g].push_back(to_ring(ring));
    }
  });
  std::size_t next_group = 0;
  for (const underlay_job& job : jobs) {
    vector_path u;
    u.kind = vector_path::kind_type::underlay;
    u.color = job.color;
    if (job.mesh)
      for (const cl::Path& r : coverage.full_tiles_of(*job.mesh)) u.rings.push_back(to_ring(r));
    for (std::size_t g = 0; g < job.groups.size(); ++g, ++next_group)
      u.rings.insert(u.rings.end(), std::make_move_iterator(unions[next_group].begin()),
                     std::make_move_iterator(unions[next_group].end()));
    if (!u.rings.empty()) d.paths.push_back(std::move(u));
  }
  d.paths.insert(d.paths.end(), std::make_move_iterator(regions.begin()),
                 std::make_move_iterator(regions.end()));
  // The coverage's pieces and the faces' lists of them are many small blocks: freed on the
  // workers (freed on return, one after the other, they cost a twentieth of the stage).
  constexpr std::size_t face_blocks = 8;
  parallel_for(coverage.size() + face_blocks, workers, [&](std::size_t i, unsigned) {
    if (i < coverage.size()) {
      coverage.release(i);
      return;
    }
    const std::size_t b = i - coverage.size();
    for (std::size_t k = faces.size() * b / face_blocks; k < faces.size() * (b + 1) / face_blocks;
         ++k)
      faces[k].pieces = {};
  });
  d.seconds.underlays = since(t0);
  if (edges.valid()) {
    t0 = clock::now();
    std::vector<vector_path> e = edges.get();
    d.seconds.edges_wait = since(t0);
    d.paths.insert(d.paths.end(), std::make_move_iterator(e.begin()),
                   std::make_move_iterator(e.end()));
  }
  // Curve pieces were clipped front to back: put them back in back-to-front order.
  for (auto it = curve_paths.rbegin(); it != curve_paths.rend(); ++it)
    append_curve(d, std::move(*it));
  return d;
}

vector_drawing painter_drawing(const frame& f) {
  const viewport& vp = f.view.vp;
  vector_drawing d = empty_drawing(f);
  d.painter = true;
  std::size_t next_line = 0;
  for (std::size_t k = 0; k <= f.polygons.size(); ++k) {
    while (next_line < f.lines.size() && f.lines[next_line].slot <= k)
      append_curve(d, curve_path(f, f.lines[next_line++]));
    if (k == f.polygons.size()) break;
    const screen_polygon& p = f.polygons[k];
    vector_path r;
    r.kind = vector_path::kind_type::region;
    r.face = p.face;
    r.fragment = p.fragment;
    r.mesh = f.mesh_of(p.face);
    double sx = 0, sy = 0, sz = 0;
    std::vector<grid_point> ring;
    for (const window_point& w : p.v) {
      sx += w.x;
      sy += w.y;
      sz += w.z;
      const cl::IntPoint q = grid_of(vp, w);
      ring.push_back({q.X, q.Y});
    }
    const double n = static_cast<double>(p.v.size());
    r.color = shaded(f, p.color, sx / n, sy / n, sz / n);
    r.rings.push_back(std::move(ring));
    d.paths.push_back(std::move(r));
  }
  return d;
}

}  // namespace exbsp::view
