// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact sections (notation in section.h). One cut is three passes over an "exact mesh"
// (Epeck points, triangles as point indices with face ids):
//   1. signs and split: each triangle is classified by the exact signs of its points and
//      split by the section 3 convention; a cut point is made once per crossing edge (keyed
//      by its two point indices), so neighbouring pieces share it combinatorially;
//   2. the points on the plane are merged by exact comparison (only non-conforming input
//      makes two of them equal), then the in-plane edges of kept and removed pieces are
//      counted: net use (u,v) - (v,u) in kept pieces, kept uses, removed uses;
//   3. the outline edges are chained into loops and polylines, and for a closed input the
//      cap, when a cap builder is given (section_cap.cpp, the GPL component: CGAL's
//      constrained Delaunay triangulation), covers the region the outline winds around; the
//      kept triangles and the outline are then refined along the edges it subdivided.
// The split runs here on point indices rather than on points (the outline and the cap need
// to know which edge made each cut point): geom::apply_split with the edge visitor, the same
// combinatorics as the tree's (geom/split_pattern.h), and the cut points are
// geom::plane_segment_intersection's (test_section checks that the pieces equal the clipping
// oracle's, tests/support/exact_triangle_clip.h, exactly).
#include <exbsp/clip/section.h>

#include "clip/section_impl.h"

#include <gmpxx.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <exbsp/core/errors.h>
#include "geom/cut_plane.h"
#include "geom/rational.h"
#include "geom/split_pattern.h"
#include "geom/weld.h"

namespace exbsp {

namespace section_detail {

namespace {

/// The soup as an exact mesh: the vertices the triangles use, in order of first use, welded
/// by geom::weld (equal doubles, so -0 equals +0); a welded point keeps its first vertex's
/// coordinates with zeros made +0 (the doubles written out for it).
exact_mesh from_soup(const triangle_soup& soup) {
  std::vector<std::uint32_t> use(soup.vertices.size(), no_point);  // vertex -> first-use rank
  std::vector<vec3d> used;
  for (const soup_triangle& t : soup.triangles)
    for (std::uint32_t v : t.v)
      if (use[v] == no_point) {
        use[v] = static_cast<std::uint32_t>(used.size());
        used.push_back(soup.vertices[v]);
      }
  const geom::welded_ids welded = geom::weld(used);
  exact_mesh m;
  m.pts.reserve(welded.count);
  m.input.reserve(welded.count);
  for (std::size_t i = 0; i < used.size(); ++i)
    if (welded.id[i] == m.pts.size()) {  // the first vertex of its welded point
      const vec3d q{used[i][0] + 0.0, used[i][1] + 0.0, used[i][2] + 0.0};
      m.add(point3(q[0], q[1], q[2]), q);
    }
  m.tris.reserve(soup.triangles.size());
  for (const soup_triangle& t : soup.triangles)
    m.tris.push_back(
        {{welded.id[use[t.v[0]]], welded.id[use[t.v[1]]], welded.id[use[t.v[2]]]}, t.face});
  return m;
}

/// Every directed edge used as often as its reverse.
bool is_closed(const std::vector<tri>& tris) {
  std::unordered_map<std::uint64_t, int> net;
  net.reserve(tris.size() * 2);
  for (const tri& t : tris)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t.v[k], b = t.v[(k + 1) % 3];
      if (a == b) continue;
      net[a < b ? edge_key(a, b) : edge_key(b, a)] += a < b ? 1 : -1;
    }
  return std::all_of(net.begin(), net.end(), [](const auto& e) { return e.second == 0; });
}

bool collinear_triangle(const exact_mesh& m, const tri& t) {
  return CGAL::collinear(m.pts[t.v[0]], m.pts[t.v[1]], m.pts[t.v[2]]);
}

/// In-plane edge uses (key: smaller index first).
struct edge_use {
  int net = 0;             ///< uses lo->hi minus hi->lo in kept pieces
  std::uint32_t kept = 0;  ///< uses in kept pieces
  std::uint32_t removed = 0;
  std::uint32_t first_from = no_point, first_to = no_point;  ///< first kept use
};

bool by_ends(const directed_edge& a, const directed_edge& b) {
  return a.from != b.from ? a.from < b.from : a.to < b.to;
}

/// Result of one cut of an exact mesh.
struct cut_result {
  std::vector<tri> kept;
  std::vector<directed_edge> outline;  ///< with multiplicity, sorted
  std::vector<tri> cap;
  bool closed = false;
};

/// Splits kept triangles along the subdivided outline edges (fans from the opposite
/// corner, one edge at a time, with a worklist) so that kept and cap share every edge.
void refine_kept(std::vector<tri>& kept, const subdivision& split) {
  std::vector<tri> out, work;
  for (const tri& t : kept) {
    work.push_back(t);
    while (!work.empty()) {
      const tri u = work.back();
      work.pop_back();
      bool done = true;
      for (int k = 0; k < 3 && done; ++k) {
        const std::uint32_t a = u.v[k], b = u.v[(k + 1) % 3], c = u.v[(k + 2) % 3];
        const auto it = split.find(a < b ? edge_key(a, b) : edge_key(b, a));
        if (it == split.end()) continue;
        std::vector<std::uint32_t> chain{a};
        if (a < b)
          chain.insert(chain.end(), it->second.begin(), it->second.end());
        else
          chain.insert(chain.end(), it->second.rbegin(), it->second.rend());
        chain.push_back(b);
        for (std::size_t i = chain.size() - 1; i > 0; --i)
          work.push_back(tri{{chain[i - 1], chain[i], c}, u.face});
        done = false;
      }
      if (done) out.push_back(u);
    }
  }
  kept.swap(out);
}

/// The outline with subdivided edges replaced by their pieces; pieces that overlap in
/// opposite directions cancel (net use per edge, as the outline itself is made).
std::vector<directed_edge> refine_outline(const std::vector<directed_edge>& outline,
                                          const subdivision& split) {
  std::unordered_map<std::uint64_t, int> net;
  auto add = [&net](std::uint32_t a, std::uint32_t b) {
    net[a < b ? edge_key(a, b) : edge_key(b, a)] += a < b ? 1 : -1;
  };
  for (const directed_edge& e : outline) {
    const auto it = split.find(e.from < e.to ? edge_key(e.from, e.to) : edge_key(e.to, e.from));
    if (it == split.end()) {
      add(e.from, e.to);
      continue;
    }
    std::vector<std::uint32_t> chain{e.from};
    if (e.from < e.to)
      chain.insert(chain.end(), it->second.begin(), it->second.end());
    else
      chain.insert(chain.end(), it->second.rbegin(), it->second.rend());
    chain.push_back(e.to);
    for (std::size_t i = 1; i < chain.size(); ++i) add(chain[i - 1], chain[i]);
  }
  std::vector<directed_edge> out;
  for (const auto& [key, n] : net) {
    const std::uint32_t lo = static_cast<std::uint32_t>(key >> 32),
                        hi = static_cast<std::uint32_t>(key & 0xffffffffu);
    for (int k = 0; k < std::abs(n); ++k)
      out.push_back(n > 0 ? directed_edge{lo, hi} : directed_edge{hi, lo});
  }
  std::sort(out.begin(), out.end(), by_ends);
  return out;
}

// --- passes 1 to 3a: split, merge, count, outline ------------------------------------------

cut_result cut(exact_mesh& m, const cut_plane& plane, cap_builder build_cap, std::uint32_t cap_face,
               section_stats& stats) {
  cut_result r;
  r.closed = is_closed(m.tris);
  stats.input_triangles += m.tris.size();

  std::vector<signed char> sign(m.pts.size(), 2);  // 2: not computed yet
  auto side = [&](std::uint32_t i) {
    if (sign[i] == 2) sign[i] = static_cast<signed char>(plane.side(m.pts[i]));
    return static_cast<int>(sign[i]);
  };
  std::unordered_map<std::uint64_t, std::uint32_t> cut_point;  // crossing edge -> point
  auto cross = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint64_t key = a < b ? edge_key(a, b) : edge_key(b, a);
    auto [it, fresh] = cut_point.emplace(key, 0u);
    if (fresh) {
      it->second =
          m.add(geom::plane_segment_intersection<K>(plane.p, m.pts[a], m.pts[b]), {NAN, NAN, NAN});
      sign.push_back(0);
      ++stats.cut_points;
    }
    return it->second;
  };

  // Pass 1: split (section 3 convention). Removed pieces only leave their in-plane edges.
  std::vector<directed_edge> removed_edges;
  auto in_plane_edges = [&](const tri& t, std::vector<directed_edge>& out) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t.v[k], b = t.v[(k + 1) % 3];
      if (a != b && sign[a] == 0 && sign[b] == 0) out.push_back({a, b});
    }
  };
  auto emit = [&](int s, const tri& t) {
    if (s > 0)
      r.kept.push_back(t);
    else
      in_plane_edges(t, removed_edges);
  };
  for (const tri& t : m.tris) {
    if (collinear_triangle(m, t)) ++stats.degenerate_input;
    const std::array<int, 3> s{side(t.v[0]), side(t.v[1]), side(t.v[2])};
    const geom::classification c = geom::classify_signs(s);
    if (c == geom::classification::positive || c == geom::classification::coplanar) {
      r.kept.push_back(t);
      ++stats.kept_whole;
      if (c == geom::classification::coplanar) ++stats.in_plane;
      continue;
    }
    if (c == geom::classification::negative) {
      ++stats.removed;
      in_plane_edges(t, removed_edges);
      continue;
    }
    ++stats.split;
    geom::apply_split(geom::make_split_pattern(s), t.v, cross,
                      [&](int piece_side, const std::array<std::uint32_t, 3>& v) {
                        emit(piece_side, tri{v, t.face});
                      });
  }

  // Pass 2: merge equal points on the plane (non-conforming input only), count edge uses.
  std::vector<std::uint32_t> on_plane;
  for (const tri& t : r.kept)
    for (std::uint32_t v : t.v)
      if (sign[v] == 0) on_plane.push_back(v);
  for (const directed_edge& e : removed_edges) {
    on_plane.push_back(e.from);
    on_plane.push_back(e.to);
  }
  std::sort(on_plane.begin(), on_plane.end());
  on_plane.erase(std::unique(on_plane.begin(), on_plane.end()), on_plane.end());
  std::sort(on_plane.begin(), on_plane.end(), [&](std::uint32_t a, std::uint32_t b) {
    const CGAL::Comparison_result c = CGAL::compare_xyz(m.pts[a], m.pts[b]);
    return c == CGAL::SMALLER || (c == CGAL::EQUAL && a < b);
  });
  std::unordered_map<std::uint32_t, std::uint32_t> same;  // point -> first equal point
  for (std::size_t i = 1; i < on_plane.size(); ++i)
    if (m.pts[on_plane[i]] == m.pts[on_plane[i - 1]])
      same[on_plane[i]] = same.count(on_plane[i - 1]) ? same[on_plane[i - 1]] : on_plane[i - 1];
  if (!same.empty()) {
    auto remap = [&](std::uint32_t& v) {
      const auto it = same.find(v);
      if (it != same.end()) v = it->second;
    };
    for (tri& t : r.kept)
      for (std::uint32_t& v : t.v) remap(v);
    for (directed_edge& e : removed_edges) {
      remap(e.from);
      remap(e.to);
    }
  }

  std::unordered_map<std::uint64_t, edge_use> uses;
  std::vector<directed_edge> kept_edges;
  for (const tri& t : r.kept) in_plane_edges(t, kept_edges);
  for (const directed_edge& e : kept_edges) {
    if (e.from == e.to) continue;
    const bool up = e.from < e.to;
    edge_use& u = uses[up ? edge_key(e.from, e.to) : edge_key(e.to, e.from)];
    u.net += up ? 1 : -1;
    ++u.kept;
    if (u.first_from == no_point) {
      u.first_from = e.from;
      u.first_to = e.to;
    }
  }
  for (const directed_edge& e : removed_edges) {
    if (e.from == e.to) continue;
    ++uses[e.from < e.to ? edge_key(e.from, e.to) : edge_key(e.to, e.from)].removed;
  }

  // Pass 3a: outline edges.
  for (const auto& [key, u] : uses) {
    const std::uint32_t lo = static_cast<std::uint32_t>(key >> 32),
                        hi = static_cast<std::uint32_t>(key & 0xffffffffu);
    if (r.closed) {
      for (int k = 0; k < std::abs(u.net); ++k)
        r.outline.push_back(u.net > 0 ? directed_edge{lo, hi} : directed_edge{hi, lo});
    } else if (u.kept > 0 && u.removed > 0) {
      if (u.net != 0)
        r.outline.push_back(u.net > 0 ? directed_edge{lo, hi} : directed_edge{hi, lo});
      else
        r.outline.push_back({u.first_from, u.first_to});
    }
  }
  std::sort(r.outline.begin(), r.outline.end(), by_ends);
  stats.outline_edges += r.outline.size();

  if (r.closed && build_cap) {
    subdivision split;
    r.cap = build_cap(m, plane, r.outline, cap_face, stats, split);
    stats.cap_triangles += r.cap.size();
    if (!split.empty()) {
      refine_kept(r.kept, split);
      r.outline = refine_outline(r.outline, split);
    }
  }
  return r;
}

/// Chains directed edges into open polylines (from points with more out- than in-edges)
/// and then simple closed loops (a walk is cut at the first repeated point).
std::vector<section_chain> chain_edges(const std::vector<directed_edge>& edges) {
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> out;  // edges by start, in order
  std::unordered_map<std::uint32_t, int> excess;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    out[edges[i].from].push_back(i);
    ++excess[edges[i].from];
    --excess[edges[i].to];
  }
  std::unordered_map<std::uint32_t, std::size_t> next_out;  // first unused index in out[p]
  std::vector<bool> used(edges.size(), false);
  auto take = [&](std::uint32_t p) -> std::size_t {
    auto it = out.find(p);
    if (it == out.end()) return edges.size();
    std::size_t& k = next_out[p];
    while (k < it->second.size() && used[it->second[k]]) ++k;
    if (k == it->second.size()) return edges.size();
    used[it->second[k]] = true;
    return it->second[k];
  };

  std::vector<section_chain> polylines, loops;
  std::vector<std::uint32_t> starts;
  for (const auto& [p, x] : excess)
    if (x > 0) starts.push_back(p);
  std::sort(starts.begin(), starts.end());
  for (std::uint32_t s : starts)
    for (int k = 0; k < excess[s]; ++k) {
      section_chain c{{s}, false};
      for (std::size_t e = take(s); e != edges.size(); e = take(c.p.back()))
        c.p.push_back(edges[e].to);
      if (c.p.size() > 1) polylines.push_back(std::move(c));
    }
  for (std::size_t e0 = 0; e0 < edges.size(); ++e0) {
    if (used[e0]) continue;
    used[e0] = true;
    std::vector<std::uint32_t> path{edges[e0].from};
    std::unordered_map<std::uint32_t, std::size_t> pos{{edges[e0].from, 0}};
    std::uint32_t cur = edges[e0].to;
    while (true) {
      const auto it = pos.find(cur);
      if (it != pos.end()) {
        const std::size_t i = it->second;
        loops.push_back(
            {std::vector<std::uint32_t>(path.begin() + static_cast<std::ptrdiff_t>(i), path.end()),
             true});
        for (std::size_t k = i + 1; k < path.size(); ++k) pos.erase(path[k]);
        path.resize(i + 1);
        if (path.size() == 1) break;
      } else {
        pos.emplace(cur, path.size());
        path.push_back(cur);
      }
      const std::size_t e = take(path.back());
      if (e == edges.size()) {  // only for unbalanced input
        if (path.size() > 1) polylines.push_back({path, false});
        break;
      }
      cur = edges[e].to;
    }
  }
  loops.insert(loops.end(), std::make_move_iterator(polylines.begin()),
               std::make_move_iterator(polylines.end()));
  return loops;
}

double coordinate_double(const exact_mesh& m, std::uint32_t i, int k) {
  const double d = m.input[i][k];
  if (!std::isnan(d)) return d;
  return geom::rational_to_double(geom::mpq_of(CGAL::exact(m.pts[i][k])));
}

}  // namespace

section_result section(const triangle_soup& soup, const section_plane& plane,
                       const section_options& options, cap_builder build_cap) {
  check_section_plane(plane);
  const auto t0 = std::chrono::steady_clock::now();
  section_result out;
  out.plane = plane;
  out.cap_face = soup.face_count;
  exact_mesh m = from_soup(soup);
  const cut_plane cp(plane);
  cut_result r = cut(m, cp, build_cap, soup.face_count, out.stats);
  out.closed = r.closed;
  const std::vector<section_chain> chains = chain_edges(r.outline);

  // Compact the points used, in order of first use: kept, cap, outline.
  std::vector<std::uint32_t> index(m.pts.size(), no_point);
  auto use = [&](std::uint32_t i) {
    if (index[i] == no_point) {
      index[i] = static_cast<std::uint32_t>(out.points.size());
      section_point p;
      for (int k = 0; k < 3; ++k) {
        p.v[k] = coordinate_double(m, i, k);
        if (options.exact_text)
          p.exact[k] = geom::rational_to_string(geom::mpq_of(CGAL::exact(m.pts[i][k])));
      }
      out.points.push_back(std::move(p));
    }
    return index[i];
  };
  auto convert = [&](const std::vector<tri>& in, std::vector<section_triangle>& to) {
    to.reserve(in.size());
    for (const tri& t : in) to.push_back({{use(t.v[0]), use(t.v[1]), use(t.v[2])}, t.face});
  };
  convert(r.kept, out.kept);
  convert(r.cap, out.cap);
  for (const section_chain& c : chains) {
    section_chain o{{}, c.closed};
    for (std::uint32_t i : c.p) o.p.push_back(use(i));
    out.outline.push_back(std::move(o));
  }
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

triangle_soup clip_soup(const triangle_soup& soup, const std::vector<section_plane>& planes,
                        cap_builder build_cap) {
  for (std::size_t i = 0; i < planes.size(); ++i)
    check_section_plane(planes[i], "plane " + std::to_string(i));
  exact_mesh m = from_soup(soup);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    section_stats stats;
    const std::uint32_t cap_face = soup.face_count + static_cast<std::uint32_t>(i);
    cut_result r = cut(m, cut_plane(planes[i]), build_cap, cap_face, stats);
    m.tris = std::move(r.kept);
    m.tris.insert(m.tris.end(), r.cap.begin(), r.cap.end());
  }
  triangle_soup out;
  out.source = soup.source;
  out.face_count = soup.face_count + (build_cap ? static_cast<std::uint32_t>(planes.size()) : 0);
  std::vector<std::uint32_t> index(m.pts.size(), no_point);
  out.triangles.reserve(m.tris.size());
  for (const tri& t : m.tris) {
    soup_triangle s{{}, t.face};
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& i = index[t.v[k]];
      if (i == no_point) {
        i = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back({coordinate_double(m, t.v[k], 0), coordinate_double(m, t.v[k], 1),
                                coordinate_double(m, t.v[k], 2)});
      }
      s.v[k] = i;
    }
    out.triangles.push_back(s);
  }
  return out;
}

}  // namespace section_detail

void check_section_plane(const section_plane& plane, const std::string& what) {
  for (double x : plane)
    if (!std::isfinite(x)) throw usage_error(what + ": A, B, C, D must be finite numbers");
  if (plane[0] == 0 && plane[1] == 0 && plane[2] == 0)
    throw usage_error(what + ": the normal (A, B, C) must not be zero");
}

section_result section(const triangle_soup& soup, const section_plane& plane,
                       const section_options& options) {
  return section_detail::section(soup, plane, options, nullptr);
}

triangle_soup clip_soup(const triangle_soup& soup, const std::vector<section_plane>& planes) {
  return section_detail::clip_soup(soup, planes, nullptr);
}

}  // namespace exbsp
