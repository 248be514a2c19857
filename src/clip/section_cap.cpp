// SPDX-License-Identifier: GPL-3.0-or-later
// The caps of exact sections (notation in section.h and section_impl.h): for a closed input,
// the region the outline winds around is triangulated by CGAL's constrained Delaunay
// triangulation (Epeck, Exact_intersections_tag) of the outline projected along the dominant
// axis of n, each face covered w times where w is the outline's winding number around it,
// found by an explicit-stack traversal from the infinite face (w changes by the net use of
// each constrained edge crossed).
//
// This file is the GPL component exbsp::gpl (libexbsp_gpl): CGAL's Triangulation_2 and TDS_2
// packages are GPL-3.0-or-later (docs/licence.md). The rest of the section (split, outline,
// refinement) is in the LGPL core, section.cpp, which calls build_cap through
// section_detail::section.
#include <exbsp/clip/section_cap.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "clip/section_impl.h"

namespace exbsp {

namespace {

using namespace section_detail;

struct vertex_info {
  std::uint32_t id = no_point;
};
struct face_info {
  int winding = 0;
  bool seen = false;
};
using cdt_vb = CGAL::Triangulation_vertex_base_with_info_2<vertex_info, K>;
using cdt_fb =
    CGAL::Triangulation_face_base_with_info_2<face_info, K,
                                              CGAL::Constrained_triangulation_face_base_2<K>>;
using cdt_tds = CGAL::Triangulation_data_structure_2<cdt_vb, cdt_fb>;
using cdt = CGAL::Constrained_Delaunay_triangulation_2<K, cdt_tds, CGAL::Exact_intersections_tag>;

/// Triangles covering the region the outline winds around, each face -w times (reversed
/// when w > 0) so that the cap's boundary is the outline reversed. Steiner points (crossing
/// outline edges) are lifted to the plane and appended to m; outline edges that pass through
/// other outline points or Steiner points are reported in `split` (non-conforming or
/// self-intersecting input only).
std::vector<tri> build_cap(exact_mesh& m, const cut_plane& plane,
                           const std::vector<directed_edge>& outline, std::uint32_t cap_face,
                           section_stats& stats, subdivision& split) {
  std::vector<tri> cap;
  if (outline.empty()) return cap;
  std::unordered_map<std::uint64_t, int> net;  // lo->hi multiplicity
  std::vector<std::uint32_t> ids;
  for (const directed_edge& e : outline) {
    const bool up = e.from < e.to;
    net[up ? edge_key(e.from, e.to) : edge_key(e.to, e.from)] += up ? 1 : -1;
    ids.push_back(e.from);
    ids.push_back(e.to);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());

  cdt tr;
  std::unordered_map<std::uint32_t, cdt::Vertex_handle> handle;
  std::unordered_map<std::uint32_t, point2> flat;
  for (std::uint32_t id : ids) {
    const point2 q = plane.project(m.pts[id]);
    flat.emplace(id, q);
    cdt::Vertex_handle h = tr.insert(q);
    h->info().id = id;
    handle.emplace(id, h);
  }
  std::vector<std::pair<std::uint64_t, int>> constraints(net.begin(), net.end());
  std::sort(constraints.begin(), constraints.end());
  for (const auto& [key, n] : constraints) {
    if (n == 0) continue;
    tr.insert_constraint(handle.at(static_cast<std::uint32_t>(key >> 32)),
                         handle.at(static_cast<std::uint32_t>(key & 0xffffffffu)));
  }

  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    if (v->info().id != no_point) continue;
    v->info().id = m.add(plane.lift(v->point()), {NAN, NAN, NAN});
    ++stats.cap_steiner_points;
  }
  // Subdivided constraints (no triangulation edge joins their ends): walk each from lo to
  // hi along collinear constrained edges and record the points passed.
  for (const auto& [key, n] : constraints) {
    if (n == 0) continue;
    const cdt::Vertex_handle va = handle.at(static_cast<std::uint32_t>(key >> 32));
    const cdt::Vertex_handle vb = handle.at(static_cast<std::uint32_t>(key & 0xffffffffu));
    if (tr.is_edge(va, vb)) continue;
    std::vector<std::uint32_t> mids;
    for (cdt::Vertex_handle v = va; v != vb;) {
      cdt::Vertex_handle next;
      auto ec = tr.incident_edges(v);
      const auto done = ec;
      do {
        if (tr.is_infinite(*ec) || !tr.is_constrained(*ec)) continue;
        const cdt::Face_handle f = ec->first;
        const int i = ec->second;
        const cdt::Vertex_handle w =
            f->vertex(cdt::cw(i)) == v ? f->vertex(cdt::ccw(i)) : f->vertex(cdt::cw(i));
        if (CGAL::collinear(va->point(), vb->point(), w->point()) &&
            CGAL::collinear_are_strictly_ordered_along_line(v->point(), w->point(), vb->point()))
          next = w;
        else if (w == vb)
          next = w;
      } while (next == cdt::Vertex_handle() && ++ec != done);
      if (next == cdt::Vertex_handle()) break;  // cannot happen for a constraint of tr
      if (next != vb) mids.push_back(next->info().id);
      v = next;
    }
    if (!mids.empty()) {
      ++stats.split_constraints;
      split.emplace(key, std::move(mids));
    }
  }

  // Net multiplicity of the outline along the triangulation edge u->v: the outline edge u-v
  // itself, plus every subdivided outline edge that contains u-v.
  auto multiplicity = [&](cdt::Vertex_handle u, cdt::Vertex_handle v) {
    const std::uint32_t a = u->info().id, b = v->info().id;
    const auto it = net.find(a < b ? edge_key(a, b) : edge_key(b, a));
    int w = it == net.end() ? 0 : a < b ? it->second : -it->second;
    for (const auto& entry : split) {
      const point2& p = flat.at(static_cast<std::uint32_t>(entry.first >> 32));
      const point2& q = flat.at(static_cast<std::uint32_t>(entry.first & 0xffffffffu));
      if (!CGAL::collinear(p, q, u->point()) || !CGAL::collinear(p, q, v->point())) continue;
      if (!CGAL::collinear_are_ordered_along_line(p, u->point(), q) ||
          !CGAL::collinear_are_ordered_along_line(p, v->point(), q))
        continue;
      const int n = net.at(entry.first);
      w += CGAL::collinear_are_ordered_along_line(p, u->point(), v->point()) ? n : -n;
    }
    return w;
  };

  std::vector<cdt::Face_handle> stack{tr.infinite_face()};
  tr.infinite_face()->info().seen = true;
  while (!stack.empty()) {
    const cdt::Face_handle f = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const cdt::Face_handle g = f->neighbor(i);
      if (g->info().seen) continue;
      int w = f->info().winding;
      if (f->is_constrained(i)) w -= multiplicity(f->vertex(cdt::ccw(i)), f->vertex(cdt::cw(i)));
      g->info().winding = w;
      g->info().seen = true;
      stack.push_back(g);
    }
  }

  for (auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f) {
    const int w = f->info().winding;
    const std::uint32_t a = f->vertex(0)->info().id, b = f->vertex(1)->info().id,
                        c = f->vertex(2)->info().id;
    for (int k = 0; k < std::abs(w); ++k)
      cap.push_back(w > 0 ? tri{{a, c, b}, cap_face} : tri{{a, b, c}, cap_face});
  }
  return cap;
}

}  // namespace

section_result section_with_cap(const triangle_soup& soup, const section_plane& plane,
                                const section_options& options) {
  return section_detail::section(soup, plane, options, &build_cap);
}

triangle_soup clip_soup_with_caps(const triangle_soup& soup,
                                  const std::vector<section_plane>& planes) {
  return section_detail::clip_soup(soup, planes, &build_cap);
}

}  // namespace exbsp
