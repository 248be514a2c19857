// SPDX-License-Identifier: GPL-3.0-or-later
// Concave clipping by CGAL's 2D regularized Boolean set operations (notation in
// polygon_boolean.h). CGAL's Booleans stand in for a hand-written Weiler–Atherton (the course
// material's algorithm for concave polygons with holes; issue 29 allows them, said here): the
// subject and the region become Polygon_set_2 objects on the exact kernel (Epeck, the input
// doubles converted exactly), their regularized intersection is read back as polygons with
// holes, and each coordinate is rounded once to the nearest double (MPFR, geom/rational.h).
// Segments: the breakpoints of the segment (its ends and every exact intersection with a
// boundary edge of the region, the ends of collinear overlaps included) cut it into open
// pieces that are wholly inside, wholly on the boundary or wholly outside; each breakpoint and
// each piece's midpoint is located in the region's arrangement (closed membership), and the
// runs of kept points become sub-segments. Polygon_set_2 and its arrangement are GPL-3.0-or-
// later in CGAL, so this file is the GPL component exbsp::gpl (docs/licence.md). CGAL's
// failures (CGAL::Failure_exception) become usage_error; nothing here recurses deeper than
// CGAL's own sweep.
#include <exbsp/clip/polygon_boolean.h>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>

#include <exbsp/core/errors.h>
#include "clip/clip_checks.h"
#include "geom/rational.h"

namespace exbsp::clip {

namespace {

using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ft = kernel::FT;
using point = kernel::Point_2;
using exact_segment = kernel::Segment_2;
using exact_polygon = CGAL::Polygon_2<kernel>;
using exact_polygon_with_holes = CGAL::Polygon_with_holes_2<kernel>;
using polygon_set = CGAL::Polygon_set_2<kernel>;

double nearest(const ft& v) { return geom::rational_to_double(geom::mpq_of(CGAL::exact(v))); }

vec2d rounded(const point& p) { return {nearest(p.x()), nearest(p.y())}; }

bool finite(const vec2d& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

/// The ring's points without consecutive repeats (cyclically: a last point equal to the first
/// goes too).
std::vector<point> ring_points(const std::vector<vec2d>& ring) {
  std::vector<point> out;
  for (const vec2d& v : ring) {
    const point q(v[0], v[1]);
    if (out.empty() || out.back() != q) out.push_back(q);
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

std::string problem_of(const std::vector<vec2d>& ring) {
  for (const vec2d& v : ring)
    if (!finite(v)) return "has a NaN or infinite coordinate";
  std::vector<point> pts = ring_points(ring);
  std::vector<vec2d> distinct(ring);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() < 3)
    return "has fewer than 3 distinct points (" + std::to_string(distinct.size()) + ")";
  const kernel traits;  // a named object: GCC's -Wmaybe-uninitialized flags a temporary one
  if (!CGAL::is_simple_2(pts.begin(), pts.end(), traits))
    return "is not simple: two of its edges cross, touch or overlap";
  return {};
}

/// The valid ring (ring_problem is empty) as a counter-clockwise exact polygon.
exact_polygon ccw_polygon(const std::vector<vec2d>& ring) {
  const std::vector<point> pts = ring_points(ring);
  exact_polygon p(pts.begin(), pts.end());
  if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
  return p;
}

void require_ring(const std::vector<vec2d>& ring, const char* function, const std::string& which) {
  const std::string problem = problem_of(ring);
  if (!problem.empty()) throw usage_error(std::string(function) + ": " + which + " " + problem);
}

bool inside(const exact_polygon& inner, const exact_polygon& outer) {
  polygon_set s(inner);
  s.difference(outer);
  return s.is_empty();
}

/// The closed region of a validated polygon with holes, as a polygon set.
polygon_set region_set(const polygon_with_holes2& p, const char* function) {
  require_ring(p.outer, function, "the outer ring");
  const exact_polygon outer = ccw_polygon(p.outer);
  polygon_set s(outer);
  for (std::size_t i = 0; i < p.holes.size(); ++i) {
    const std::string which = "hole " + std::to_string(i);
    require_ring(p.holes[i], function, which);
    const exact_polygon hole = ccw_polygon(p.holes[i]);
    if (!inside(hole, outer))
      throw usage_error(std::string(function) + ": " + which + " is not inside the outer ring");
    s.difference(hole);
  }
  return s;
}

/// Rounded ring, starting at its lexicographically smallest vertex.
std::vector<vec2d> rounded_ring(const exact_polygon& p) {
  std::vector<vec2d> ring;
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) ring.push_back(rounded(*it));
  if (!ring.empty())
    std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
  return ring;
}

std::vector<polygon_with_holes2> rounded_polygons(const polygon_set& s) {
  std::vector<exact_polygon_with_holes> parts;
  s.polygons_with_holes(std::back_inserter(parts));
  std::vector<polygon_with_holes2> out;
  for (exact_polygon_with_holes& pwh : parts) {
    exact_polygon outer = pwh.outer_boundary();
    if (outer.orientation() == CGAL::CLOCKWISE) outer.reverse_orientation();
    polygon_with_holes2 r;
    r.outer = rounded_ring(outer);
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
      exact_polygon hole = *h;
      if (hole.orientation() == CGAL::COUNTERCLOCKWISE) hole.reverse_orientation();
      r.holes.push_back(rounded_ring(hole));
    }
    std::sort(r.holes.begin(), r.holes.end());
    out.push_back(std::move(r));
  }
  std::sort(out.begin(), out.end(), [](const polygon_with_holes2& a, const polygon_with_holes2& b) {
    return a.outer < b.outer;
  });
  return out;
}

/// Runs `body`, turning CGAL's failures into usage_error (the library never aborts).
template <class Body>
auto guarded(const char* function, Body&& body) {
  try {
    return body();
  } catch (const CGAL::Failure_exception& e) {
    throw usage_error(std::string(function) + ": CGAL failed: " + e.what());
  }
}

}  // namespace

struct polygon_region::impl {
  polygon_set set;
  std::vector<exact_segment> edges;  ///< the boundary of the regularized region
};

std::string ring_problem(const std::vector<vec2d>& ring) {
  return guarded("ring_problem", [&] { return problem_of(ring); });
}

bool ring_inside(const std::vector<vec2d>& inner, const std::vector<vec2d>& outer) {
  return guarded("ring_inside", [&] {
    require_ring(inner, "ring_inside", "the inner ring");
    require_ring(outer, "ring_inside", "the outer ring");
    return inside(ccw_polygon(inner), ccw_polygon(outer));
  });
}

polygon_region::polygon_region(const polygon_with_holes2& region) {
  impl_ = guarded("polygon_region", [&] {
    auto m = std::make_shared<impl>();
    m->set = region_set(region, "polygon_region");
    std::vector<exact_polygon_with_holes> parts;
    m->set.polygons_with_holes(std::back_inserter(parts));
    auto add_edges = [&](const exact_polygon& p) {
      for (auto e = p.edges_begin(); e != p.edges_end(); ++e) m->edges.push_back(*e);
    };
    for (const auto& pwh : parts) {
      add_edges(pwh.outer_boundary());
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) add_edges(*h);
    }
    return std::shared_ptr<const impl>(std::move(m));
  });
}

std::vector<polygon_with_holes2> polygon_region::intersect(
    const polygon_with_holes2& subject) const {
  return guarded("polygon_region::intersect", [&] {
    polygon_set s = region_set(subject, "polygon_region::intersect");
    s.intersection(impl_->set);
    return rounded_polygons(s);
  });
}

bool polygon_region::contains(const vec2d& p) const {
  if (!finite(p)) throw usage_error("polygon_region::contains: NaN or infinite point");
  return guarded("polygon_region::contains", [&] {
    return impl_->set.oriented_side(point(p[0], p[1])) != CGAL::ON_NEGATIVE_SIDE;
  });
}

std::vector<segment2> polygon_region::clip_segment(const segment2& s) const {
  if (!finite(s.p0) || !finite(s.p1))
    throw usage_error("polygon_region::clip_segment: NaN or infinite segment end");
  return guarded("polygon_region::clip_segment", [&] {
    std::vector<segment2> out;
    const point a(s.p0[0], s.p0[1]), b(s.p1[0], s.p1[1]);
    auto in = [&](const point& q) { return impl_->set.oriented_side(q) != CGAL::ON_NEGATIVE_SIDE; };
    if (a == b) {
      if (in(a)) out.push_back(s);
      return out;
    }
    // Breakpoints as parameters t of a + t (b - a), t in [0, 1].
    const kernel::Vector_2 d = b - a;
    const ft dd = d.squared_length();
    auto parameter = [&](const point& q) { return ((q - a) * d) / dd; };
    std::vector<ft> ts{ft(0), ft(1)};
    const exact_segment seg(a, b);
    for (const exact_segment& e : impl_->edges) {
      if (!CGAL::do_intersect(seg, e)) continue;
      const auto x = CGAL::intersection(seg, e);
      if (!x) continue;
      if (const point* p = boost::get<point>(&*x)) {
        ts.push_back(parameter(*p));
      } else if (const exact_segment* o = boost::get<exact_segment>(&*x)) {
        ts.push_back(parameter(o->source()));
        ts.push_back(parameter(o->target()));
      }
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    auto at = [&](const ft& t) -> vec2d {
      if (t == 0) return s.p0;
      if (t == 1) return s.p1;
      return rounded(a + t * d);
    };
    // Runs of kept breakpoints joined by kept open pieces.
    bool open = false;
    ft start = 0;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      if (!open) {
        if (!in(a + ts[i] * d)) continue;
        open = true;
        start = ts[i];
      }
      const bool next_kept = i + 1 < ts.size() && in(a + ((ts[i] + ts[i + 1]) / 2) * d);
      if (!next_kept) {
        out.push_back({at(start), at(ts[i])});
        open = false;
      }
    }
    return out;
  });
}

std::vector<polygon_with_holes2> polygon_region::polygons() const {
  return guarded("polygon_region::polygons", [&] { return rounded_polygons(impl_->set); });
}

}  // namespace exbsp::clip
