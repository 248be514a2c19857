// SPDX-License-Identifier: LGPL-3.0-or-later
// Sutherland–Hodgman clipping (see sutherland_hodgman.h for the notation).
// `in` and `out` are the polygons before and after one half-space; `f` holds f(in[i]).
#include <exbsp/clip/sutherland_hodgman.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include "clip/clip_checks.h"

namespace exbsp::clip {
namespace {

/// Normal component index of a 2D/3D plane, or -1 when it is not axis-aligned.
int axis_of(const half_plane2& h) {
  if (h.a != 0.0 && h.b == 0.0) return 0;
  if (h.a == 0.0 && h.b != 0.0) return 1;
  return -1;
}
int axis_of(const half_space3& h) {
  int axis = -1;
  for (std::size_t k = 0; k < 3; ++k) {
    if (h.n[k] == 0.0) continue;
    if (axis >= 0) return -1;
    axis = static_cast<int>(k);
  }
  return axis;
}
double normal_component(const half_plane2& h, int k) { return k == 0 ? h.a : h.b; }
double normal_component(const half_space3& h, int k) { return h.n[static_cast<std::size_t>(k)]; }
double offset(const half_plane2& h) { return h.c; }
double offset(const half_space3& h) { return h.d; }

bool finite_plane(const half_plane2& h) {
  return std::isfinite(h.a) && std::isfinite(h.b) && std::isfinite(h.c);
}
bool finite_plane(const half_space3& h) { return detail::all_finite(h.n) && std::isfinite(h.d); }

/// Crossing point of edge (p, q) with f(p), f(q) of strictly opposite signs, computed from
/// the lexicographically smaller endpoint so that the edge's direction does not matter.
template <class P, class H>
P crossing(const P& p, double fp, const P& q, double fq, const H& h, int axis) {
  const bool swap = q < p;
  const P& lo = swap ? q : p;
  const P& hi = swap ? p : q;
  const double f_lo = swap ? fq : fp;
  const double f_hi = swap ? fp : fq;
  const double t = f_lo / (f_lo - f_hi);  // in [0, 1]: |f_lo - f_hi| >= |f_lo|
  P x;
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = detail::lerp_within(lo[k], hi[k], t);
  if (axis >= 0) x[static_cast<std::size_t>(axis)] = -offset(h) / normal_component(h, axis);
  return x;
}

/// One half-space step of the textbook algorithm: `in` clipped by h (fewer than 3 vertices
/// when nothing with area is left).
template <class P, class H>
std::vector<P> clip_one(const std::vector<P>& in, const std::vector<double>& f, const H& h) {
  const int axis = axis_of(h);
  std::vector<P> out;
  const std::size_t n = in.size();
  std::size_t s = n - 1;
  for (std::size_t e = 0; e < n; s = e, ++e) {
    if ((f[s] > 0.0 && f[e] < 0.0) || (f[s] < 0.0 && f[e] > 0.0))
      out.push_back(crossing(in[s], f[s], in[e], f[e], h, axis));
    if (f[e] >= 0.0) out.push_back(in[e]);
  }
  return out;
}

template <class P, class H>
std::vector<P> clip_n(const std::vector<P>& polygon, const std::vector<H>& region) {
  const char* function = "sutherland_hodgman_clip";
  for (const P& p : polygon) detail::require_finite(p, function, "polygon vertex");
  for (const H& h : region)
    if (!finite_plane(h))
      throw usage_error(std::string(function) + ": half-space has a NaN or infinite coefficient");
  if (polygon.size() < 3) return {};

  std::vector<P> in = polygon;
  std::vector<double> f;
  for (const H& h : region) {
    const std::size_t n = in.size();
    f.resize(n);
    bool all_inside = true;
    for (std::size_t i = 0; i < n; ++i) {
      f[i] = h.value(in[i]);
      all_inside = all_inside && f[i] >= 0.0;
    }
    if (all_inside) continue;
    std::vector<P> out = clip_one(in, f, h);
    if (out.size() < 3) return {};
    std::swap(in, out);
  }
  return in;
}

vec3d lift(const vec2d& p) { return {p[0], p[1], 0.0}; }
vec3d lift(const vec3d& p) { return p; }
vec3d normal_of(const half_plane2& h) { return {h.a, h.b, 0.0}; }
vec3d normal_of(const half_space3& h) { return h.n; }
vec3d cross3(const vec3d& a, const vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot3(const vec3d& a, const vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Newell's normal of a polygon (length twice its area; zero for a degenerate polygon).
template <class P>
vec3d newell_normal(const std::vector<P>& poly) {
  vec3d n{0.0, 0.0, 0.0};
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const vec3d a = lift(poly[j]), b = lift(poly[i]);
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

/// One half-space step split into pieces (notation in sutherland_hodgman.h). Appends the
/// pieces of `in` to `out`.
template <class P, class H>
void split_one(const std::vector<P>& in, const H& h, const vec3d& normal,
               std::vector<std::vector<P>>& out) {
  const std::size_t n = in.size();
  std::vector<double> f(n);
  std::size_t first_out = n;
  bool any_inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = h.value(in[i]);
    if (f[i] < 0.0 && first_out == n) first_out = i;
    any_inside = any_inside || f[i] > 0.0;
  }
  if (first_out == n) {  // nothing outside
    out.push_back(in);
    return;
  }
  if (!any_inside) return;  // at most a segment on the line is left
  const int axis = axis_of(h);
  struct chain {
    std::vector<P> points;
    bool has_area = false;
  };
  std::vector<chain> chains;
  // Walk the edges starting from an outside vertex, so every chain starts inside the walk.
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t s = (first_out + k - 1) % n, e = (first_out + k) % n;
    if (f[s] < 0.0 && f[e] >= 0.0) chains.push_back({});
    if ((f[s] > 0.0 && f[e] < 0.0) || (f[s] < 0.0 && f[e] > 0.0))
      chains.back().points.push_back(crossing(in[s], f[s], in[e], f[e], h, axis));
    if (f[e] >= 0.0) {
      chains.back().points.push_back(in[e]);
      chains.back().has_area = chains.back().has_area || f[e] > 0.0;
    }
  }
  chains.erase(
      std::remove_if(chains.begin(), chains.end(), [](const chain& c) { return !c.has_area; }),
      chains.end());
  if (chains.size() <= 1) {  // one piece: the textbook result itself, in its vertex order
    std::vector<P> one = clip_one(in, f, h);
    if (one.size() >= 3) out.push_back(std::move(one));
    return;
  }
  // Pair the k-th exit with the k-th entry along t.
  const vec3d t = cross3(normal_of(h), normal);
  std::vector<std::size_t> exits(chains.size()), entries(chains.size());
  for (std::size_t i = 0; i < chains.size(); ++i) exits[i] = entries[i] = i;
  std::sort(exits.begin(), exits.end(), [&](std::size_t a, std::size_t b) {
    return dot3(lift(chains[a].points.back()), t) < dot3(lift(chains[b].points.back()), t);
  });
  std::sort(entries.begin(), entries.end(), [&](std::size_t a, std::size_t b) {
    return dot3(lift(chains[a].points.front()), t) < dot3(lift(chains[b].points.front()), t);
  });
  std::vector<std::size_t> next(chains.size());
  for (std::size_t k = 0; k < chains.size(); ++k) next[exits[k]] = entries[k];
  std::vector<bool> used(chains.size(), false);
  for (std::size_t start = 0; start < chains.size(); ++start) {
    if (used[start]) continue;
    std::vector<P> piece;
    for (std::size_t c = start; !used[c]; c = next[c]) {
      used[c] = true;
      piece.insert(piece.end(), chains[c].points.begin(), chains[c].points.end());
    }
    if (piece.size() >= 3) out.push_back(std::move(piece));
  }
}

template <class P, class H>
std::vector<std::vector<P>> pieces_n(const std::vector<P>& polygon, const std::vector<H>& region) {
  const std::vector<P> whole = clip_n(polygon, region);  // checks the input
  if (whole.empty()) return {};
  const vec3d normal = newell_normal(polygon);
  if (normal == vec3d{0.0, 0.0, 0.0}) return {whole};  // no orientation: nothing to split by
  std::vector<std::vector<P>> pieces{polygon}, next;
  for (const H& h : region) {
    next.clear();
    for (const std::vector<P>& p : pieces) split_one(p, h, normal, next);
    std::swap(pieces, next);
  }
  return pieces;
}

void require_view_volume(double left, double right, double bottom, double top, double near,
                         double far, const char* function) {
  for (double v : {left, right, bottom, top, near, far})
    if (!std::isfinite(v)) throw usage_error(std::string(function) + ": NaN or infinite bound");
  if (!(left < right)) throw usage_error(std::string(function) + ": left must be < right");
  if (!(bottom < top)) throw usage_error(std::string(function) + ": bottom must be < top");
  if (!(near < far)) throw usage_error(std::string(function) + ": near must be < far");
}

}  // namespace

std::vector<vec2d> sutherland_hodgman_clip(const std::vector<vec2d>& polygon,
                                           const std::vector<half_plane2>& region) {
  return clip_n(polygon, region);
}

std::vector<vec3d> sutherland_hodgman_clip(const std::vector<vec3d>& polygon,
                                           const std::vector<half_space3>& region) {
  return clip_n(polygon, region);
}

std::vector<std::vector<vec2d>> sutherland_hodgman_pieces(const std::vector<vec2d>& polygon,
                                                          const std::vector<half_plane2>& region) {
  return pieces_n(polygon, region);
}

std::vector<std::vector<vec3d>> sutherland_hodgman_pieces(const std::vector<vec3d>& polygon,
                                                          const std::vector<half_space3>& region) {
  return pieces_n(polygon, region);
}

std::vector<half_plane2> window_half_planes(const window2& w) {
  detail::require_valid_box(w, "window_half_planes");
  return {
      {1.0, 0.0, -w.min[0]}, {-1.0, 0.0, w.max[0]}, {0.0, 1.0, -w.min[1]}, {0.0, -1.0, w.max[1]}};
}

std::vector<half_space3> box_half_spaces(const box3& b) {
  detail::require_valid_box(b, "box_half_spaces");
  std::vector<half_space3> out;
  for (std::size_t k = 0; k < 3; ++k) {
    vec3d n{0.0, 0.0, 0.0};
    n[k] = 1.0;
    out.push_back({n, -b.min[k]});
    n[k] = -1.0;
    out.push_back({n, b.max[k]});
  }
  return out;
}

std::vector<half_space3> frustum_half_spaces(double left, double right, double bottom, double top,
                                             double near, double far) {
  const char* function = "frustum_half_spaces";
  require_view_volume(left, right, bottom, top, near, far, function);
  if (!(near > 0.0)) throw usage_error(std::string(function) + ": near must be > 0");
  // A side plane passes through the eye and one edge of the near rectangle z = -near:
  // x / -z >= left / near  <=>  near * x + left * z >= 0 (for z < 0), and so on.
  return {{{near, 0.0, left}, 0.0},  {{-near, 0.0, -right}, 0.0}, {{0.0, near, bottom}, 0.0},
          {{0.0, -near, -top}, 0.0}, {{0.0, 0.0, -1.0}, -near},   {{0.0, 0.0, 1.0}, far}};
}

std::vector<half_space3> orthographic_half_spaces(double left, double right, double bottom,
                                                  double top, double near, double far) {
  require_view_volume(left, right, bottom, top, near, far, "orthographic_half_spaces");
  return box_half_spaces(box3{{left, bottom, -far}, {right, top, -near}});
}

}  // namespace exbsp::clip
