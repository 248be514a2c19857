// SPDX-License-Identifier: LGPL-3.0-or-later
// Feature edges (notation in feature_edges.h). Each triangle side becomes a half-edge keyed by
// its welded vertex pair; sorting the keys groups the triangles around each edge.
#include "geom/feature_edges.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geom/weld.h"

namespace exbsp::geom {

namespace {

vec3d sub(const vec3d& a, const vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
vec3d cross(const vec3d& a, const vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const vec3d& a, const vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

int facing(const vec3d& a, const vec3d& b, const vec3d& c, const hpoint& viewer) {
  // D(a, b, c, E) = -orientation(a, b, c, E) (homogeneous_det.cpp).
  const rounding_guard guard;
  return -det_value(point_of(a), point_of(b), point_of(c), viewer).sign();
}

int facing_filtered(const vec3d& a, const vec3d& b, const vec3d& c, const hpoint& viewer) {
  // facing = sign((b - a) x (c - a) . V), V = E - a (w = 1) or the direction E (w = 0): the
  // triple product of rows r0 = b - a, r1 = c - a, r2 = V. Each row is rounded once (relative
  // error u per coordinate, moving the determinant by at most about 3u x its permanent P), and
  // the evaluation adds about 5u P: a bound of 32u P decides the sign; near underflow or
  // overflow, or within the bound, the exact facing().
  double r[3][3];
  for (int k = 0; k < 3; ++k) {
    r[0][k] = b[k] - a[k];
    r[1][k] = c[k] - a[k];
  }
  r[2][0] = viewer.w ? viewer.x - a[0] : viewer.x;
  r[2][1] = viewer.w ? viewer.y - a[1] : viewer.y;
  r[2][2] = viewer.w ? viewer.z - a[2] : viewer.z;
  const rounded_det3 d = det3_in_double(r);
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  const double bound = 32 * u * d.permanent;
  if (std::isfinite(d.value) && std::isfinite(bound) && d.permanent > 1e-250) {
    if (d.value > bound) return 1;
    if (d.value < -bound) return -1;
  }
  return facing(a, b, c, viewer);
}

edge_graph edge_graph_of(const triangle_soup& s, double crease_deg) {
  const welded_ids welded = weld(s.vertices);
  const std::vector<std::uint32_t>& id = welded.id;
  edge_graph g;
  g.crease_deg = crease_deg;
  const std::size_t n = s.triangles.size();
  g.degenerate.assign(n, 0);
  std::vector<vec3d> normal(n);
  struct keyed {
    std::uint64_t key;
    edge_graph::half h;
  };
  std::vector<keyed> halves;
  halves.reserve(3 * n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& v = s.triangles[t].v;
    normal[t] =
        cross(sub(s.vertices[v[1]], s.vertices[v[0]]), sub(s.vertices[v[2]], s.vertices[v[0]]));
    if (id[v[0]] == id[v[1]] || id[v[1]] == id[v[2]] || id[v[2]] == id[v[0]] ||
        dot(normal[t], normal[t]) == 0) {
      g.degenerate[t] = 1;
      continue;  // degenerate: no plane, not drawn
    }
    for (std::uint32_t k = 0; k < 3; ++k) {
      std::uint64_t p = id[v[k]], q = id[v[(k + 1) % 3]];
      if (p > q) std::swap(p, q);
      halves.push_back({p << 32 | q, {static_cast<std::uint32_t>(t), k}});
    }
  }
  std::sort(halves.begin(), halves.end(), [](const keyed& x, const keyed& y) {
    return x.key != y.key ? x.key < y.key : x.h.tri < y.h.tri;
  });
  g.halves.reserve(halves.size());
  for (const keyed& k : halves) g.halves.push_back(k.h);
  const double cos_crease = std::cos(crease_deg * M_PI / 180.0);
  std::vector<std::uint32_t> tris;
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    while (j < halves.size() && halves[j].key == halves[i].key) ++j;
    // Distinct faces around the edge (two triangles of one face: a fan diagonal).
    tris.clear();
    for (std::size_t k = i; k < j; ++k) {
      const std::uint32_t t = halves[k].h.tri;
      if (std::none_of(tris.begin(), tris.end(),
                       [&](std::uint32_t u) { return s.triangles[u].face == s.triangles[t].face; }))
        tris.push_back(t);
    }
    const std::size_t uses = j - i;
    edge_graph::edge e;
    bool kept = true;
    if (uses >= 3) {
      e.kind = feature_kind::non_manifold;
    } else if (tris.size() == 1) {
      kept = uses == 1;  // boundary; two triangles of one face: a fan diagonal
      e.kind = feature_kind::boundary;
    } else {
      const vec3d& n0 = normal[tris[0]];
      const vec3d& n1 = normal[tris[1]];
      e.kind = dot(n0, n1) < cos_crease * std::sqrt(dot(n0, n0) * dot(n1, n1))
                   ? feature_kind::crease
                   : feature_kind::silhouette;
    }
    if (kept) {
      const edge_graph::half& h = halves[i].h;
      const auto& tv = s.triangles[h.tri].v;
      e.first = static_cast<std::uint32_t>(i);
      e.end = static_cast<std::uint32_t>(j);
      e.a = tv[h.side];
      e.b = tv[(h.side + 1) % 3];
      e.tris[0] = tris[0];
      e.tris[1] = tris.size() > 1 ? tris[1] : tris[0];
      g.edges.push_back(e);
    }
    i = j;
  }
  return g;
}

view_features find_feature_edges(const edge_graph& g, const triangle_soup& s,
                                 const hpoint& viewer) {
  view_features out;
  const std::size_t n = s.triangles.size();
  out.facing.assign(n, 0);
  out.feature_sides.assign(n, 0);
  for (std::size_t t = 0; t < n; ++t) {
    if (g.degenerate[t]) continue;
    const auto& v = s.triangles[t].v;
    out.facing[t] = static_cast<std::int8_t>(
        facing_filtered(s.vertices[v[0]], s.vertices[v[1]], s.vertices[v[2]], viewer));
  }
  for (const edge_graph::edge& ge : g.edges) {
    // A smooth edge between two faces is drawn where one faces the viewer and the other not.
    if (ge.kind == feature_kind::silhouette &&
        (out.facing[ge.tris[0]] > 0) == (out.facing[ge.tris[1]] > 0))
      continue;
    feature_edge e;
    e.a = ge.a;
    e.b = ge.b;
    e.tris[0] = ge.tris[0];
    e.tris[1] = ge.tris[1];
    e.faces[0] = s.triangles[e.tris[0]].face;
    e.faces[1] = s.triangles[e.tris[1]].face;
    e.kind = ge.kind;
    out.edges.push_back(e);
    for (std::uint32_t k = ge.first; k < ge.end; ++k)
      out.feature_sides[g.halves[k].tri] |= static_cast<std::uint8_t>(1u << g.halves[k].side);
  }
  return out;
}

view_features find_feature_edges(const triangle_soup& s, const hpoint& viewer, double crease_deg) {
  return find_feature_edges(edge_graph_of(s, crease_deg), s, viewer);
}

}  // namespace exbsp::geom
