// SPDX-License-Identifier: LGPL-3.0-or-later
// The hidden-line oracle (hidden_line_oracle.h): feature edges, ray casts to the eye with
// exact or filtered-exact signs, and the comparison with a drawing's edge runs.
#include "support/hidden_line_oracle.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "core/named_table.h"

namespace exbsp_test {

using exbsp::vec3d;
namespace view = exbsp::view;

namespace {

using qpoint = std::array<mpq_class, 3>;
using gpoint = std::array<double, 2>;
constexpr double eps = std::numeric_limits<double>::epsilon();

qpoint to_q(const vec3d& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }

/// The sign of det(u, v, w), exact.
int det_sign(const qpoint& u, const qpoint& v, const qpoint& w) {
  const mpq_class d = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                      u[2] * (v[0] * w[1] - v[1] * w[0]);
  return sgn(d);
}

qpoint minus(const qpoint& a, const qpoint& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// orient(a, b, c, d) = sign det(b - a, c - a, d - a): positive where (b - a) x (c - a) points.
int orient_exact(const qpoint& a, const qpoint& b, const qpoint& c, const qpoint& d) {
  return det_sign(minus(b, a), minus(c, a), minus(d, a));
}

/// orient(a, b, c, d) in doubles when the error bound decides it, else 2. `u` bounds the
/// error of every input coordinate (0: the doubles are the exact inputs).
int orient_filtered(const vec3d& a, const vec3d& b, const vec3d& c, const vec3d& d, double u) {
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  const double m1 = cy * dz, m2 = cz * dy, m3 = cx * dz, m4 = cz * dx, m5 = cx * dy, m6 = cy * dx;
  const double det = bx * (m1 - m2) - by * (m3 - m4) + bz * (m5 - m6);
  const double perm = std::abs(bx) * (std::abs(m1) + std::abs(m2)) +
                      std::abs(by) * (std::abs(m3) + std::abs(m4)) +
                      std::abs(bz) * (std::abs(m5) + std::abs(m6));
  double m = 0;
  for (double v : {bx, by, bz, cx, cy, cz, dx, dy, dz}) m = std::max(m, std::abs(v));
  if (!std::isfinite(det) || !std::isfinite(perm) || m < 1e-80) return 2;  // under/overflow
  const double err = 16 * eps * perm + 64 * u * m * m + 64 * u * u * m + 64 * u * u * u;
  if (det > err) return 1;
  if (det < -err) return -1;
  return 2;
}

double orient_double(const vec3d& a, const vec3d& b, const vec3d& c, const vec3d& d) {
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  return bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
}

view::hpoint clip_of(const view::mat4& pm, const vec3d& p) {
  return pm * view::point3{p[0], p[1], p[2]};
}

view::hpoint lerp(const view::hpoint& a, const view::hpoint& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z),
          a.w + t * (b.w - a.w)};
}

double dist(const gpoint& a, const gpoint& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

/// Distance from p to segment [a, b], and the fraction of the segment at its nearest point.
double segment_distance(const gpoint& p, const gpoint& a, const gpoint& b, double* at = nullptr) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double l2 = dx * dx + dy * dy;
  double u = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
  u = std::clamp(u, 0.0, 1.0);
  if (at) *at = u;
  return dist(p, {a[0] + u * dx, a[1] + u * dy});
}

/// Segments in the grid plane, bucketed in square cells; each is entered in every cell within
/// `reach` of it, so a query of radius <= reach looks at one cell.
class segment_grid {
 public:
  struct segment {
    gpoint a, b;
    std::size_t id;
  };

  segment_grid(double width, double height, double reach, double cell = 800)
      : reach_(reach), cell_(cell) {
    nx_ = std::max<long long>(1, static_cast<long long>(std::ceil(width / cell_)));
    ny_ = std::max<long long>(1, static_cast<long long>(std::ceil(height / cell_)));
    cells_.resize(static_cast<std::size_t>(nx_ * ny_));
  }

  void add(const gpoint& a, const gpoint& b, std::size_t id) {
    const std::size_t k = segments_.size();
    segments_.push_back({a, b, id});
    const long long x0 = index(std::min(a[0], b[0]) - reach_, nx_);
    const long long x1 = index(std::max(a[0], b[0]) + reach_, nx_);
    const long long y0 = index(std::min(a[1], b[1]) - reach_, ny_);
    const long long y1 = index(std::max(a[1], b[1]) + reach_, ny_);
    for (long long y = y0; y <= y1; ++y)
      for (long long x = x0; x <= x1; ++x)
        cells_[static_cast<std::size_t>(y * nx_ + x)].push_back(k);
  }

  /// Calls f(segment, distance) for every segment within r (<= reach) of p.
  template <class F>
  void visit(const gpoint& p, double r, F&& f) const {
    const auto& c = cells_[static_cast<std::size_t>(index(p[1], ny_) * nx_ + index(p[0], nx_))];
    for (std::size_t k : c) {
      const segment& s = segments_[k];
      const double d = segment_distance(p, s.a, s.b);
      if (d <= r) f(s, d);
    }
  }

  bool any_within(const gpoint& p, double r) const {
    bool found = false;
    visit(p, r, [&](const segment&, double) { found = true; });
    return found;
  }

 private:
  long long index(double v, long long n) const {
    if (!(v > 0)) return 0;
    return std::min<long long>(n - 1, static_cast<long long>(v / cell_));
  }

  double reach_, cell_;
  long long nx_ = 1, ny_ = 1;
  std::vector<segment> segments_;
  std::vector<std::vector<std::size_t>> cells_;
};

/// One occluder: a non-degenerate triangle of the soup.
struct occluder {
  std::array<vec3d, 3> v;
  std::array<qpoint, 3> q;
  std::array<std::uint32_t, 3> id{};  ///< welded vertices
  std::uint32_t face = 0;
  int eye_side = 0;  ///< orientation of the eye (parallel: sign of n . -direction)
  std::array<bool, 3> edge_feature{};     ///< edge k = (v[k], v[k + 1]) is a feature edge
  std::array<bool, 3> vertex_feature{};   ///< a feature edge ends at v[k]
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< grid bounding box, 1 pixel wider
};

constexpr std::size_t no_edge = static_cast<std::size_t>(-1);

}  // namespace

const char* to_string(feature_kind k) {
  static constexpr exbsp::enum_name<feature_kind> names[] = {
      {feature_kind::boundary, "boundary"},
      {feature_kind::non_manifold, "non-manifold"},
      {feature_kind::crease, "crease"},
      {feature_kind::silhouette, "silhouette"}};
  return exbsp::name_of(k, names);
}

const char* to_string(point_visibility v) {
  static constexpr exbsp::enum_name<point_visibility> names[] = {
      {point_visibility::visible, "visible"},
      {point_visibility::hidden, "hidden"},
      {point_visibility::unknown, "unknown"}};
  return exbsp::name_of(v, names);
}

double edge_image::length() const { return dist(g0, g1); }

double edge_image::t_at(double u) const {
  const double s = u * w0 / ((1 - u) * w1 + u * w0);
  return t0 + s * (t1 - t0);
}

struct hidden_line_oracle::impl {
  hidden_line_options opt;
  bool exact = false;
  bool hidden_drawn = false;
  bool parallel = false;
  view::mat4 pm;
  double grid_w = 0, grid_h = 0;
  vec3d eye{}, dir{};
  qpoint eye_q, dir_q;
  std::vector<occluder> occ;
  std::vector<oracle_edge> edges;
  std::vector<view::hpoint> edge_h0, edge_h1;  ///< clip coordinates of the edges' ends
  std::vector<std::optional<edge_image>> images;
  std::vector<std::uint32_t> always;  ///< occluders with no usable bounding box
  double cell = 1600;
  long long nx = 1, ny = 1;
  std::vector<std::vector<std::uint32_t>> buckets;
  std::optional<segment_grid> edge_grid;  ///< images of the feature edges
  mutable std::size_t fallbacks = 0;

  gpoint grid_of_clip(const view::hpoint& h) const {
    return {grid_w * (h.x / h.w + 1) / 2, grid_h * (h.y / h.w + 1) / 2};
  }

  long long bucket_index(double v, long long n) const {
    if (!(v > 0)) return 0;
    return std::min<long long>(n - 1, static_cast<long long>(v / cell));
  }

  void build(const view::frame& f);
  point_visibility classify(std::size_t e, const mpq_class& t,
                            std::vector<occluder_hit>* hits = nullptr) const;
};

void hidden_line_oracle::impl::build(const view::frame& f) {
  const exbsp::triangle_soup& s = f.soup;
  hidden_drawn = f.vector.edges == view::vector_options::edges_kind::visible_hidden;
  parallel = f.view.is_parallel();
  pm = f.view.projection * f.view.model_view;
  grid_w = static_cast<double>(view::grid_per_pixel) * f.view.vp.width;
  grid_h = static_cast<double>(view::grid_per_pixel) * f.view.vp.height;
  eye = {f.view.cam.eye.x, f.view.cam.eye.y, f.view.cam.eye.z};
  dir = {f.view.direction.x, f.view.direction.y, f.view.direction.z};
  eye_q = to_q(eye);
  dir_q = to_q(dir);

  // Weld vertices by exact position (-0 and +0 are one position).
  std::map<vec3d, std::uint32_t> weld;
  std::vector<vec3d> position;
  std::vector<std::uint32_t> wid(s.vertices.size());
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    vec3d v = s.vertices[i];
    for (double& c : v) c = c == 0 ? 0.0 : c;
    const auto it = weld.emplace(v, static_cast<std::uint32_t>(position.size())).first;
    if (it->second == position.size()) position.push_back(v);
    wid[i] = it->second;
  }

  // Occluders: the triangles with a plane, and the eye's side of each (exact).
  for (const exbsp::soup_triangle& t : s.triangles) {
    occluder o;
    for (int k = 0; k < 3; ++k) {
      o.id[k] = wid[t.v[k]];
      o.v[k] = position[o.id[k]];
      o.q[k] = to_q(o.v[k]);
    }
    const qpoint u = minus(o.q[1], o.q[0]), w = minus(o.q[2], o.q[0]);
    const mpq_class nx_ = u[1] * w[2] - u[2] * w[1], ny_ = u[2] * w[0] - u[0] * w[2],
                    nz_ = u[0] * w[1] - u[1] * w[0];
    if (sgn(nx_) == 0 && sgn(ny_) == 0 && sgn(nz_) == 0) continue;  // collinear: no plane
    o.face = t.face;
    o.eye_side = parallel ? -det_sign(u, w, dir_q) : orient_exact(o.q[0], o.q[1], o.q[2], eye_q);
    occ.push_back(std::move(o));
  }

  // Edges: welded pairs and the occluders around each.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> around;
  for (std::size_t i = 0; i < occ.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = occ[i].id[k], q = occ[i].id[(k + 1) % 3];
      around[{std::min(p, q), std::max(p, q)}].push_back(static_cast<std::uint32_t>(i));
    }
  const double crease = f.vector.crease_deg;
  auto normal = [&](const occluder& o) {
    const vec3d u = {o.v[1][0] - o.v[0][0], o.v[1][1] - o.v[0][1], o.v[1][2] - o.v[0][2]};
    const vec3d w = {o.v[2][0] - o.v[0][0], o.v[2][1] - o.v[0][1], o.v[2][2] - o.v[0][2]};
    return std::array<long double, 3>{
        static_cast<long double>(u[1]) * w[2] - static_cast<long double>(u[2]) * w[1],
        static_cast<long double>(u[2]) * w[0] - static_cast<long double>(u[0]) * w[2],
        static_cast<long double>(u[0]) * w[1] - static_cast<long double>(u[1]) * w[0]};
  };
  std::set<std::pair<std::uint32_t, std::uint32_t>> feature;
  std::vector<bool> vertex_feature(position.size(), false);
  for (const auto& [key, tris] : around) {
    std::vector<std::uint32_t> faces;
    for (std::uint32_t t : tris)
      if (std::find(faces.begin(), faces.end(), occ[t].face) == faces.end())
        faces.push_back(occ[t].face);
    feature_kind kind;
    if (tris.size() == 1) {
      kind = feature_kind::boundary;
    } else if (faces.size() == 1) {
      continue;  // a fan diagonal
    } else if (faces.size() >= 3 || tris.size() >= 3) {
      kind = feature_kind::non_manifold;
    } else {
      const auto n0 = normal(occ[tris[0]]), n1 = normal(occ[tris[1]]);
      const long double c0 = n0[1] * n1[2] - n0[2] * n1[1], c1 = n0[2] * n1[0] - n0[0] * n1[2],
                        c2 = n0[0] * n1[1] - n0[1] * n1[0];
      const long double angle = std::atan2(std::sqrt(c0 * c0 + c1 * c1 + c2 * c2),
                                           n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2]) *
                                180 / M_PI;
      if (angle > crease)
        kind = feature_kind::crease;
      else if ((occ[tris[0]].eye_side > 0) != (occ[tris[1]].eye_side > 0))
        kind = feature_kind::silhouette;
      else
        continue;
    }
    feature.insert(key);
    vertex_feature[key.first] = vertex_feature[key.second] = true;
    oracle_edge e;
    e.a = position[key.first];
    e.b = position[key.second];
    e.faces = faces;
    e.kind = kind;
    edges.push_back(std::move(e));
  }
  for (occluder& o : occ)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = o.id[k], q = o.id[(k + 1) % 3];
      o.edge_feature[k] = feature.count({std::min(p, q), std::max(p, q)}) > 0;
      o.vertex_feature[k] = vertex_feature[o.id[k]];
    }

  const std::size_t n = occ.size();
  exact = opt.arithmetic == oracle_arithmetic::exact ||
          (opt.arithmetic == oracle_arithmetic::automatic && n < opt.exact_below);

  // Occluder buckets by projected bounding box (a triangle reaching behind the eye has none).
  nx = std::max<long long>(1, static_cast<long long>(std::ceil(grid_w / cell)));
  ny = std::max<long long>(1, static_cast<long long>(std::ceil(grid_h / cell)));
  buckets.resize(static_cast<std::size_t>(nx * ny));
  for (std::size_t i = 0; i < n; ++i) {
    occluder& o = occ[i];
    view::hpoint h[3];
    int behind = 0;
    for (int k = 0; k < 3; ++k) {
      h[k] = clip_of(pm, o.v[k]);
      behind += !(h[k].w > 0);
    }
    if (behind == 3) continue;  // cannot meet a segment in front of the eye
    if (behind > 0) {
      always.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    o.x0 = o.y0 = std::numeric_limits<double>::infinity();
    o.x1 = o.y1 = -std::numeric_limits<double>::infinity();
    for (const view::hpoint& c : h) {
      const gpoint g = grid_of_clip(c);
      o.x0 = std::min(o.x0, g[0]);
      o.x1 = std::max(o.x1, g[0]);
      o.y0 = std::min(o.y0, g[1]);
      o.y1 = std::max(o.y1, g[1]);
    }
    const double margin = static_cast<double>(view::grid_per_pixel);
    o.x0 -= margin;
    o.y0 -= margin;
    o.x1 += margin;
    o.y1 += margin;
    if (!std::isfinite(o.x0 + o.x1 + o.y0 + o.y1)) {
      always.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    for (long long y = bucket_index(o.y0, ny); y <= bucket_index(o.y1, ny); ++y)
      for (long long x = bucket_index(o.x0, nx); x <= bucket_index(o.x1, nx); ++x)
        buckets[static_cast<std::size_t>(y * nx + x)].push_back(static_cast<std::uint32_t>(i));
  }

  // Edge images: clipped to the view volume (homogeneous Liang-Barsky).
  edge_grid.emplace(grid_w, grid_h, 2 * opt.tolerance + opt.ambiguity);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const view::hpoint a = clip_of(pm, edges[e].a), b = clip_of(pm, edges[e].b);
    edge_h0.push_back(a);
    edge_h1.push_back(b);
    double t0 = 0, t1 = 1;
    bool inside = true;
    const double fa[6] = {a.w + a.x, a.w - a.x, a.w + a.y, a.w - a.y, a.w + a.z, a.w - a.z};
    const double fb[6] = {b.w + b.x, b.w - b.x, b.w + b.y, b.w - b.y, b.w + b.z, b.w - b.z};
    for (int k = 0; k < 6 && inside; ++k) {
      if (fa[k] < 0 && fb[k] < 0) {
        inside = false;
      } else if (fa[k] < 0) {
        t0 = std::max(t0, fa[k] / (fa[k] - fb[k]));
      } else if (fb[k] < 0) {
        t1 = std::min(t1, fa[k] / (fa[k] - fb[k]));
      }
    }
    if (!inside || !(t0 < t1)) {
      images.emplace_back();
      continue;
    }
    edge_image im;
    im.t0 = t0;
    im.t1 = t1;
    const view::hpoint h0 = lerp(a, b, t0), h1 = lerp(a, b, t1);
    im.w0 = h0.w;
    im.w1 = h1.w;
    im.g0 = grid_of_clip(h0);
    im.g1 = grid_of_clip(h1);
    images.push_back(im);
    edge_grid->add(im.g0, im.g1, e);
  }
}

point_visibility hidden_line_oracle::impl::classify(std::size_t e, const mpq_class& t,
                                                    std::vector<occluder_hit>* hits) const {
  const oracle_edge& E = edges[e];
  const double td = t.get_d();
  vec3d p{};
  double mag = 0;
  for (int k = 0; k < 3; ++k) {
    p[k] = E.a[k] + td * (E.b[k] - E.a[k]);
    mag = std::max({mag, std::abs(E.a[k]), std::abs(E.b[k])});
  }
  const double up = 16 * eps * mag + 1e-300;
  std::optional<qpoint> pq;
  auto exact_p = [&]() -> const qpoint& {
    if (!pq) {
      const qpoint a = to_q(E.a), b = to_q(E.b);
      pq = qpoint{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    }
    return *pq;
  };
  // A second point of the line of sight: the eye, or p - direction.
  vec3d q = eye;
  double uq = 0;
  if (parallel) {
    double pm_ = 0;
    for (int k = 0; k < 3; ++k) {
      q[k] = p[k] - dir[k];
      pm_ = std::max(pm_, std::abs(p[k]));
    }
    uq = up + 4 * eps * (pm_ + 1);
  }
  std::optional<qpoint> qq;
  auto exact_q = [&]() -> const qpoint& {
    if (!qq) qq = parallel ? minus(exact_p(), dir_q) : eye_q;
    return *qq;
  };
  const double u = std::max(up, uq);

  const view::hpoint hp = clip_of(pm, p);
  if (!(hp.w > 0)) return point_visibility::unknown;  // behind the eye: not in the view
  const gpoint g = grid_of_clip(hp);
  bool clipped = false, hidden = false;

  // 0: does not hide p; 1: hides it; 2: hides it at a point the near plane clips away.
  auto test = [&](const occluder& o) -> int {
    if (o.eye_side == 0) return 0;  // seen edge-on
    int sp = exact ? 2 : orient_filtered(o.v[0], o.v[1], o.v[2], p, up);
    if (sp == 2) {
      if (!exact) ++fallbacks;
      sp = orient_exact(o.q[0], o.q[1], o.q[2], exact_p());
    }
    if (sp != -o.eye_side) return 0;  // no transversal crossing between p and the eye
    int s[3];
    int zeros = 0, pos = 0, neg = 0;
    for (int k = 0; k < 3; ++k) {
      const vec3d& a = o.v[k];
      const vec3d& b = o.v[(k + 1) % 3];
      s[k] = exact ? 2 : orient_filtered(p, q, a, b, u);
      if (s[k] == 2) {
        if (!exact) ++fallbacks;
        s[k] = orient_exact(exact_p(), exact_q(), o.q[k], o.q[(k + 1) % 3]);
      }
      zeros += s[k] == 0;
      pos += s[k] > 0;
      neg += s[k] < 0;
      if (pos > 0 && neg > 0) return 0;  // the line passes outside the triangle
    }
    bool hides;
    const char* where = "inside";
    if (zeros == 0) {
      hides = true;  // the triangle's inside (its face's relative interior)
    } else if (zeros == 1) {
      const int k = s[0] == 0 ? 0 : s[1] == 0 ? 1 : 2;
      hides = !o.edge_feature[k];  // on an edge: hides unless it is a feature edge
      where = "on a non-feature edge";
    } else {
      // At the vertex shared by the two edges of zero sign.
      const int k = s[0] != 0 ? 2 : s[1] != 0 ? 0 : 1;  // edges k-1 and k share vertex k
      hides = !o.vertex_feature[k];
      where = "at a vertex with no feature edge";
    }
    if (!hides) return 0;
    // Where the line of sight crosses the plane (doubles): clipped by the near plane?
    vec3d x{};
    if (parallel) {
      const double op = orient_double(o.v[0], o.v[1], o.v[2], p);
      const double od = orient_double(o.v[0], o.v[1], o.v[2], q);
      const double s_ = std::clamp(op / (op - od), 0.0, 1e300);
      for (int k = 0; k < 3; ++k) x[k] = p[k] + s_ * (q[k] - p[k]);
    } else {
      const double op = orient_double(o.v[0], o.v[1], o.v[2], p);
      const double oe = orient_double(o.v[0], o.v[1], o.v[2], eye);
      const double s_ = std::clamp(op / (op - oe), 0.0, 1.0);
      for (int k = 0; k < 3; ++k) x[k] = p[k] + s_ * (eye[k] - p[k]);
    }
    const view::hpoint hx = clip_of(pm, x);
    const bool clipped_away = std::isfinite(hx.z) && std::isfinite(hx.w) && hx.z < -hx.w;
    if (hits) hits->push_back({o.face, o.v, x, where, clipped_away});
    return clipped_away ? 2 : 1;
  };

  const auto& bucket =
      buckets[static_cast<std::size_t>(bucket_index(g[1], ny) * nx + bucket_index(g[0], nx))];
  for (std::uint32_t i : bucket) {
    const occluder& o = occ[i];
    if (g[0] < o.x0 || g[0] > o.x1 || g[1] < o.y0 || g[1] > o.y1) continue;
    const int r = test(o);
    hidden = hidden || r == 1;
    if (hidden && !hits) return point_visibility::hidden;
    clipped = clipped || r == 2;
  }
  for (std::uint32_t i : always) {
    const int r = test(occ[i]);
    hidden = hidden || r == 1;
    if (hidden && !hits) return point_visibility::hidden;
    clipped = clipped || r == 2;
  }
  if (hidden) return point_visibility::hidden;
  return clipped ? point_visibility::unknown : point_visibility::visible;
}

// ---- the oracle -----------------------------------------------------------------------------

hidden_line_oracle::hidden_line_oracle(const view::frame& f, const hidden_line_options& opt)
    : impl_(std::make_unique<impl>()) {
  impl_->opt = opt;
  impl_->build(f);
}
hidden_line_oracle::~hidden_line_oracle() = default;
hidden_line_oracle::hidden_line_oracle(hidden_line_oracle&&) noexcept = default;
hidden_line_oracle& hidden_line_oracle::operator=(hidden_line_oracle&&) noexcept = default;

const hidden_line_options& hidden_line_oracle::options() const { return impl_->opt; }
bool hidden_line_oracle::exact() const { return impl_->exact; }
bool hidden_line_oracle::hidden_drawn() const { return impl_->hidden_drawn; }
const std::vector<oracle_edge>& hidden_line_oracle::edges() const { return impl_->edges; }
std::size_t hidden_line_oracle::triangle_count() const { return impl_->occ.size(); }
std::size_t hidden_line_oracle::exact_fallbacks() const { return impl_->fallbacks; }

point_visibility hidden_line_oracle::classify(std::size_t e, const mpq_class& t) const {
  return impl_->classify(e, t);
}

point_visibility hidden_line_oracle::classify(std::size_t e, double t) const {
  return impl_->classify(e, mpq_class(t));
}

std::vector<occluder_hit> hidden_line_oracle::hiding(std::size_t e, const mpq_class& t) const {
  std::vector<occluder_hit> hits;
  impl_->classify(e, t, &hits);
  return hits;
}

bool hidden_line_oracle::image_of(std::size_t e, edge_image& out) const {
  if (!impl_->images[e]) return false;
  out = *impl_->images[e];
  return true;
}

bool hidden_line_oracle::grid_of(const vec3d& p, std::array<double, 2>& g) const {
  const view::hpoint h = clip_of(impl_->pm, p);
  if (!(h.w > 0)) return false;
  g = impl_->grid_of_clip(h);
  return true;
}

std::array<double, 2> hidden_line_oracle::grid_size() const {
  return {impl_->grid_w, impl_->grid_h};
}

bool hidden_line_oracle::visible_near(const std::array<double, 2>& g, double radius,
                                      std::size_t except) const {
  bool found = false;
  impl_->edge_grid->visit(g, radius, [&](const segment_grid::segment& s, double d) {
    if (found || s.id == except) return;
    const edge_image& im = *impl_->images[s.id];
    const double len = im.length();
    double u = 0;
    segment_distance(g, im.g0, im.g1, &u);
    // The part of the image within `radius` of g: u -+ delta.
    const double delta = len > 0 ? std::sqrt(std::max(0.0, radius * radius - d * d)) / len : 0;
    for (double v : {u, u - delta, u + delta}) {
      const double t = std::clamp(im.t_at(std::clamp(v, 0.0, 1.0)), 1e-9, 1 - 1e-9);
      if (classify(s.id, t) == point_visibility::visible) {
        found = true;
        return;
      }
    }
  });
  return found;
}

// ---- the report -----------------------------------------------------------------------------

std::string hidden_line_example::describe() const {
  std::ostringstream o;
  o << std::setprecision(7) << problem << " at grid (" << grid[0] << ", " << grid[1] << "), "
    << where;
  return o.str();
}

double hidden_line_report::agreement() const {
  const std::size_t n = checked();
  return n == 0 ? 0.0 : static_cast<double>(visible_ok + hidden_ok) / static_cast<double>(n);
}

double hidden_line_report::run_agreement() const {
  const std::size_t n = run_ok + run_wrong();
  return n == 0 ? 1.0 : static_cast<double>(run_ok) / static_cast<double>(n);
}

std::string hidden_line_report::summary() const {
  std::ostringstream o;
  o << std::fixed << std::setprecision(2);
  o << (exact ? "exact" : "filtered") << " oracle, " << triangles << " triangles, " << feature_edges
    << " feature edges (" << edges_in_view << " in view)"
    << (hidden_drawn ? "" : ", hidden edges not drawn") << "; samples: " << checked()
    << " checked, agreement " << 100 * agreement() << "% (" << visible_ok << " visible ok, "
    << hidden_ok << " hidden ok of which " << hidden_covered
    << " under a visible edge; wrong: " << visible_dashed << " visible drawn dashed, "
    << visible_missing << " visible missing, " << hidden_solid << " hidden drawn solid, "
    << hidden_missing << " hidden missing; skipped " << skipped_outside << " outside, "
    << skipped_ambiguous << " ambiguous); runs: " << run_ok + run_wrong()
    << " points checked, agreement " << 100 * run_agreement() << "% (" << solid_over_hidden
    << " solid over hidden, " << dashed_under_visible << " dashed under visible, " << spurious
    << " spurious; skipped " << run_skipped << ")";
  if (exact_fallbacks > 0) o << "; " << exact_fallbacks << " exact fallbacks";
  for (const hidden_line_example& x : examples) o << "\n  " << x.describe();
  return o.str();
}

namespace {

/// The t of a sample, exactly (2k + 1) / 2n.
mpq_class sample_t(int k, int n) {
  mpq_class t(2 * k + 1, 2 * n);
  t.canonicalize();
  return t;
}

/// Grid point of edge e's point at t (the clip coordinates are linear in t).
gpoint grid_at(const hidden_line_oracle::impl& m, std::size_t e, double t) {
  return m.grid_of_clip(lerp(m.edge_h0[e], m.edge_h1[e], t));
}

bool near_border(const gpoint& g, const std::array<double, 2>& size, double r) {
  return g[0] < r || g[1] < r || g[0] > size[0] - r || g[1] > size[1] - r;
}

/// Bisects [lo, hi] (status(lo) != status(hi)) until their images are within `precision` grid
/// units; returns the final bracket.
template <class Status>
std::pair<mpq_class, mpq_class> bisect(mpq_class lo, mpq_class hi, int status_lo, Status&& status,
                                       const hidden_line_oracle::impl& m, std::size_t e,
                                       double precision) {
  for (int i = 0; i < 64; ++i) {
    if (dist(grid_at(m, e, lo.get_d()), grid_at(m, e, hi.get_d())) <= precision) break;
    mpq_class mid = (lo + hi) / 2;
    if (status(mid) == status_lo)
      lo = mid;
    else
      hi = mid;
  }
  return {lo, hi};
}

}  // namespace

hidden_line_report check_hidden_lines(const view::frame& f, const view::vector_drawing& d,
                                      const hidden_line_options& opt) {
  const hidden_line_oracle oracle(f, opt);
  return check_hidden_lines(oracle, d);
}

hidden_line_report check_hidden_lines(const hidden_line_oracle& o, const view::vector_drawing& d) {
  const hidden_line_oracle::impl& m = o.internals();
  const hidden_line_options& opt = m.opt;
  const std::size_t fallbacks_before = m.fallbacks;
  hidden_line_report r;
  r.exact = m.exact;
  r.hidden_drawn = m.hidden_drawn;
  r.triangles = m.occ.size();
  r.feature_edges = m.edges.size();
  const std::array<double, 2> size = o.grid_size();
  const double tol = opt.tolerance, amb = opt.ambiguity;
  const double gpp = static_cast<double>(view::grid_per_pixel);
  using kind = view::vector_path::kind_type;
  auto pt = [](const view::grid_point& q) {
    return gpoint{static_cast<double>(q.x), static_cast<double>(q.y)};
  };
  segment_grid solid(size[0], size[1], 2 * tol + amb), dashed(size[0], size[1], 2 * tol + amb);
  for (const view::vector_path& p : d.paths) {
    if (p.kind != kind::visible_edge && p.kind != kind::hidden_edge) continue;
    segment_grid& g = p.kind == kind::visible_edge ? solid : dashed;
    for (std::size_t ri = 0; ri < p.rings.size(); ++ri) {
      const auto& ring = p.rings[ri];
      if (ring.size() == 1) g.add(pt(ring[0]), pt(ring[0]), ri);
      for (std::size_t k = 0; k + 1 < ring.size(); ++k) g.add(pt(ring[k]), pt(ring[k + 1]), ri);
    }
  }
  auto edge_example = [&](const char* problem, std::size_t e, double t, const gpoint& g) {
    if (r.examples.size() >= opt.max_examples) return;
    const oracle_edge& E = m.edges[e];
    std::ostringstream w;
    w << std::setprecision(7) << to_string(E.kind) << " edge (" << E.a[0] << ", " << E.a[1] << ", "
      << E.a[2] << ") - (" << E.b[0] << ", " << E.b[1] << ", " << E.b[2] << ") at t = " << t;
    r.examples.push_back({problem, w.str(), g});
  };
  auto run_example = [&](const char* problem, const gpoint& a, const gpoint& b, const gpoint& g) {
    if (r.examples.size() >= opt.max_examples) return;
    std::ostringstream w;
    w << std::setprecision(7) << "run (" << a[0] << ", " << a[1] << ") - (" << b[0] << ", " << b[1]
      << ")";
    r.examples.push_back({problem, w.str(), g});
  };

  // Samples of the feature edges.
  struct sample {
    mpq_class t;
    double td = 0;
    gpoint g{};
    point_visibility v = point_visibility::unknown;
    bool in_view = false;
  };
  auto status_of = [&](std::size_t e) {
    return [&o, e](const mpq_class& t) { return static_cast<int>(o.classify(e, t)); };
  };
  auto selected = [&](const oracle_edge& E) {
    if (opt.only_edges.empty()) return true;
    return std::any_of(opt.only_edges.begin(), opt.only_edges.end(), [&](const auto& x) {
      return (x[0] == E.a && x[1] == E.b) || (x[0] == E.b && x[1] == E.a);
    });
  };
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    if (!selected(m.edges[e])) continue;
    if (!m.images[e]) {
      r.samples += static_cast<std::size_t>(opt.samples_per_edge);
      r.skipped_outside += static_cast<std::size_t>(opt.samples_per_edge);
      continue;
    }
    ++r.edges_in_view;
    const edge_image& im = *m.images[e];
    const int wanted = static_cast<int>(std::ceil(im.length() / gpp / opt.sample_spacing_px));
    const int n = std::clamp(std::max(opt.samples_per_edge, wanted), 1,
                             std::max(opt.samples_per_edge, opt.max_samples_per_edge));
    std::vector<sample> s(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      sample& x = s[static_cast<std::size_t>(k)];
      x.t = sample_t(k, n);
      x.td = x.t.get_d();
      x.in_view = x.td > im.t0 && x.td < im.t1;
      if (!x.in_view) continue;
      x.g = grid_at(m, e, x.td);
      x.v = o.classify(e, x.t);
    }
    r.samples += s.size();
    // Where the visibility changes (and the ends of the image): ambiguous surroundings.
    // Changes are looked for between the samples and between the ends of the image (moved
    // inside by 2^-30 of its range) and the first and last samples.
    std::vector<gpoint> changes{im.g0, im.g1};
    {
      const mpq_class t0(im.t0), t1(im.t1), inside = (t1 - t0) / (1 << 30);
      std::vector<std::pair<mpq_class, point_visibility>> seq;
      seq.push_back({t0 + inside, o.classify(e, mpq_class(t0 + inside))});
      for (const sample& x : s)
        if (x.in_view) seq.push_back({x.t, x.v});
      seq.push_back({t1 - inside, o.classify(e, mpq_class(t1 - inside))});
      const std::pair<mpq_class, point_visibility>* last = nullptr;
      for (const auto& x : seq) {
        if (x.second == point_visibility::unknown) continue;
        if (last && last->second != x.second) {
          const auto [lo, hi] =
              bisect(last->first, x.first, static_cast<int>(last->second), status_of(e), m, e, 0.5);
          const mpq_class mid = (lo + hi) / 2;
          changes.push_back(grid_at(m, e, mid.get_d()));
        }
        last = &x;
      }
    }
    for (const sample& x : s) {
      if (!x.in_view) {
        ++r.skipped_outside;
        continue;
      }
      if (x.v == point_visibility::unknown || near_border(x.g, size, amb) ||
          std::any_of(changes.begin(), changes.end(),
                      [&](const gpoint& c) { return dist(c, x.g) <= amb; })) {
        ++r.skipped_ambiguous;
        continue;
      }
      const bool near_solid = solid.any_within(x.g, tol);
      const bool near_dashed = dashed.any_within(x.g, tol);
      if (x.v == point_visibility::visible) {
        if (near_solid) {
          ++r.visible_ok;
        } else if (near_dashed) {
          ++r.visible_dashed;
          edge_example("visible point drawn dashed", e, x.td, x.g);
        } else {
          ++r.visible_missing;
          edge_example("visible point not drawn", e, x.td, x.g);
        }
        continue;
      }
      const bool dashed_wanted = m.hidden_drawn && !near_dashed;
      const bool covered = (near_solid || dashed_wanted) && o.visible_near(x.g, 2 * tol, e);
      if (covered) {
        ++r.hidden_ok;
        ++r.hidden_covered;
      } else if (near_solid) {
        ++r.hidden_solid;
        edge_example("hidden point drawn solid", e, x.td, x.g);
      } else if (dashed_wanted) {
        ++r.hidden_missing;
        edge_example("hidden point not drawn dashed", e, x.td, x.g);
      } else {
        ++r.hidden_ok;
      }
    }
  }

  // Points along the drawn runs.
  if (opt.check_drawing) {
    // The oracle's verdict on edge i near g: visible, hidden, or (mixed within `ambiguity`
    // along the image, or unknown) ambiguous.
    auto verdict = [&](std::size_t i, const gpoint& g) {
      const edge_image& im = *m.images[i];
      double u = 0;
      segment_distance(g, im.g0, im.g1, &u);
      const double len = im.length();
      const double du = len > 0 ? amb / len : 0;
      point_visibility v[3];
      int k = 0;
      for (double w : {u - du, u, u + du})
        v[k++] = o.classify(i, std::clamp(im.t_at(std::clamp(w, 0.0, 1.0)), 1e-9, 1 - 1e-9));
      return v[0] == v[1] && v[1] == v[2] ? v[1] : point_visibility::unknown;
    };
    const double step = opt.run_spacing_px * gpp;
    for (const view::vector_path& p : d.paths) {
      if (p.kind != kind::visible_edge && p.kind != kind::hidden_edge) continue;
      const bool is_solid = p.kind == kind::visible_edge;
      for (const auto& ring : p.rings) {
        double total = 0;
        for (std::size_t k = 0; k + 1 < ring.size(); ++k)
          total += dist(pt(ring[k]), pt(ring[k + 1]));
        double start = 0;  // length before segment k
        double at = amb;
        for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
          const gpoint a = pt(ring[k]), b = pt(ring[k + 1]);
          const double len = dist(a, b);
          for (; at <= total - amb && at <= start + len; at += step) {
            if (len == 0) break;
            const double f = (at - start) / len;
            const gpoint g{a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])};
            const gpoint dir{(b[0] - a[0]) / len, (b[1] - a[1]) / len};
            // Near the border, or near a vertex inside a chain (where other edges meet, as at
            // a ring's ends, which `at` keeps `amb` away from): ambiguous.
            const bool near_vertex =
                (k > 0 && at - start < amb) || (k + 2 < ring.size() && start + len - at < amb);
            if (near_border(g, size, amb) || near_vertex) {
              ++r.run_points;
              ++r.run_skipped;
              continue;
            }
            if (!opt.only_edges.empty()) {
              bool along_selected = false;
              m.edge_grid->visit(g, tol, [&](const segment_grid::segment& sg, double) {
                along_selected = along_selected || selected(m.edges[sg.id]);
              });
              if (!along_selected) continue;  // not counted
            }
            ++r.run_points;
            bool none = true, any_visible = false, any_hidden = false, any_unknown = false;
            bool along_visible = false;
            m.edge_grid->visit(g, tol, [&](const segment_grid::segment& sg, double) {
              none = false;
              const point_visibility v = verdict(sg.id, g);
              if (v == point_visibility::visible) {
                any_visible = true;
                // Along it: within tol over +-amb and nearly parallel (sine <= 0.05; a hidden
                // edge leaving a shared vertex at a small angle is not a coincidence).
                const gpoint g1{g[0] - amb * dir[0], g[1] - amb * dir[1]};
                const gpoint g2{g[0] + amb * dir[0], g[1] + amb * dir[1]};
                const double sx = sg.b[0] - sg.a[0], sy = sg.b[1] - sg.a[1];
                const double slen = std::hypot(sx, sy);
                const bool parallel =
                    slen > 0 && std::abs(sx * dir[1] - sy * dir[0]) <= 0.05 * slen;
                if (parallel && segment_distance(g1, sg.a, sg.b) <= tol &&
                    segment_distance(g2, sg.a, sg.b) <= tol)
                  along_visible = true;
              } else if (v == point_visibility::hidden) {
                any_hidden = true;
              } else {
                any_unknown = true;
              }
            });
            if (none) {
              ++r.spurious;
              run_example(is_solid ? "solid run where no feature edge is"
                                   : "dashed run where no feature edge is",
                          a, b, g);
            } else if (is_solid) {
              if (any_visible) {
                ++r.run_ok;
              } else if (any_unknown) {
                ++r.run_skipped;
              } else {
                ++r.solid_over_hidden;
                run_example("solid run over a hidden edge", a, b, g);
              }
            } else if (along_visible) {
              ++r.dashed_under_visible;
              run_example("dashed run along a visible edge", a, b, g);
            } else if (any_hidden) {
              ++r.run_ok;
            } else {
              ++r.run_skipped;
            }
          }
          start += len;
        }
      }
    }
  }
  r.exact_fallbacks = m.fallbacks - fallbacks_before;
  return r;
}

view::vector_drawing reference_drawing(const hidden_line_oracle& o) {
  const hidden_line_oracle::impl& m = o.internals();
  const double gpp = static_cast<double>(view::grid_per_pixel);
  view::vector_drawing d;
  d.width = static_cast<int>(std::lround(m.grid_w / gpp));
  d.height = static_cast<int>(std::lround(m.grid_h / gpp));
  view::vector_path vis, hid;
  vis.kind = view::vector_path::kind_type::visible_edge;
  hid.kind = view::vector_path::kind_type::hidden_edge;
  vis.color = hid.color = {0, 0, 0};
  auto emit = [&](view::vector_path& p, std::size_t e, const mpq_class& a, const mpq_class& b) {
    const gpoint ga = grid_at(m, e, a.get_d()), gb = grid_at(m, e, b.get_d());
    const view::grid_point pa{std::llround(ga[0]), std::llround(ga[1])};
    const view::grid_point pb{std::llround(gb[0]), std::llround(gb[1])};
    if (!(pa == pb)) p.rings.push_back({pa, pb});
  };
  // The runs of `status` over [t0, t1]: start parameters and statuses; n + 1 samples from
  // t0 to t1 (the ends moved inside by 2^-30 of the range), changes bisected to a quarter of
  // a grid unit.
  auto runs_of = [&](std::size_t e, const mpq_class& t0, const mpq_class& t1, int n,
                     const std::function<int(const mpq_class&)>& status) {
    std::vector<std::pair<mpq_class, int>> runs;
    mpq_class prev_t;
    int prev = -1;
    const mpq_class inside(1, 1 << 30);
    for (int j = 0; j <= n; ++j) {
      mpq_class f(j, n);
      f.canonicalize();
      if (j == 0) f = inside;
      if (j == n) f = 1 - inside;
      const mpq_class t = t0 + (t1 - t0) * f;
      const int st = status(t);
      if (prev < 0) {
        runs.push_back({t0, st});
      } else if (st != prev) {
        const auto [lo, hi] = bisect(prev_t, t, prev, status, m, e, 0.25);
        runs.push_back({(lo + hi) / 2, st});
      }
      prev = st;
      prev_t = t;
    }
    return runs;
  };
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    if (!m.images[e]) continue;
    const edge_image& im = *m.images[e];
    const mpq_class t0(im.t0), t1(im.t1);
    // Visibility: a sample every quarter pixel.
    const int n = std::max(16, static_cast<int>(std::ceil(im.length() / 25)));
    const auto visibility = [&](const mpq_class& t) {
      const point_visibility v = o.classify(e, t);
      return v == point_visibility::hidden ? 1 : 0;  // unknown drawn as visible
    };
    const auto runs = runs_of(e, t0, t1, n, visibility);
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const mpq_class& a = runs[k].first;
      const mpq_class b = k + 1 < runs.size() ? runs[k + 1].first : t1;
      if (runs[k].second == 0) {
        emit(vis, e, a, b);
        continue;
      }
      if (!m.hidden_drawn) continue;
      // Hidden: left out where a visible edge coincides in the image (a sample every 2 grid
      // units: a crossing covers at least 2 (tolerance + 1.5) of the run).
      const double len = dist(grid_at(m, e, a.get_d()), grid_at(m, e, b.get_d()));
      const auto covered = [&](const mpq_class& t) {
        return o.visible_near(grid_at(m, e, t.get_d()), m.opt.tolerance + 1.5, e) ? 1 : 0;
      };
      const auto pieces =
          runs_of(e, a, b, std::max(2, static_cast<int>(std::ceil(len / 2))), covered);
      for (std::size_t j = 0; j < pieces.size(); ++j)
        if (pieces[j].second == 0)
          emit(hid, e, pieces[j].first, j + 1 < pieces.size() ? pieces[j + 1].first : b);
    }
  }
  if (m.hidden_drawn && !hid.rings.empty()) d.paths.push_back(std::move(hid));
  if (!vis.rings.empty()) d.paths.push_back(std::move(vis));
  return d;
}

}  // namespace exbsp_test
