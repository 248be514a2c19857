// SPDX-License-Identifier: LGPL-3.0-or-later
// The exact invariant checker of BSP trees; notation and what each check means at the top of
// tree_checker.h. Compiled once here for the CGAL kernels (explicit instantiations at the end).
//
// Ray candidates (check_order_along_rays): a ray from exact points `from` through `to` is
// approximated by doubles e (the centre of from's interval box) and d = to' - e; for every
// parameter t with |t| <= T (T: where the line has left the box of all fragments), the exact
// point from + t (to - from) lies within D = ef + T (ef + et) + T |d| 2^-51 of e + t d
// (ef, et: the radii of the two boxes). A bounding-volume hierarchy of the fragments' double
// boxes, each widened by D plus 1e-9 of the scene's size (which covers the rounding of the
// slab test), therefore returns every fragment the exact ray crosses, and usually few more.
#include "support/tree_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <CGAL/Interval_nt.h>

#include "support/inputs.h"

namespace exbsp_test {

void check_report::fail(const std::string& invariant, const std::string& message) {
  ++broken[invariant];
  if (messages.size() < 8) messages.push_back(invariant + ": " + message);
}

std::size_t check_report::count(const std::string& invariant) const {
  const auto it = broken.find(invariant);
  return it == broken.end() ? 0 : it->second;
}

std::string check_report::text() const {
  std::string s;
  for (const auto& [k, v] : broken) s += k + "=" + std::to_string(v) + " ";
  for (const auto& m : messages) s += "\n  " + m;
  return s;
}

namespace {

/// Double boxes of items in a bounding-volume hierarchy (median split on the longest axis),
/// queried with a parametric line e + t d, t in [t0, t1] (infinite ends allowed), against
/// boxes widened by a margin. Boxes only select candidates.
class box_tree {
 public:
  explicit box_tree(std::vector<CGAL::Bbox_3> boxes) : boxes_(std::move(boxes)) {
    items_.resize(boxes_.size());
    for (std::size_t i = 0; i < items_.size(); ++i) items_[i] = static_cast<std::uint32_t>(i);
    if (items_.empty()) return;
    struct range {
      std::uint32_t node, begin, end;
    };
    nodes_.push_back({});
    std::vector<range> stack{{0, 0, static_cast<std::uint32_t>(items_.size())}};
    while (!stack.empty()) {
      const range r = stack.back();
      stack.pop_back();
      CGAL::Bbox_3 box = boxes_[items_[r.begin]];
      for (std::uint32_t k = r.begin + 1; k < r.end; ++k) box += boxes_[items_[k]];
      nodes_[r.node].box = box;
      if (r.end - r.begin <= 4) {
        nodes_[r.node].first = r.begin;
        nodes_[r.node].count = r.end - r.begin;
        continue;
      }
      int axis = 0;
      double widest = -1;
      for (int k = 0; k < 3; ++k)
        if (box.max(k) - box.min(k) > widest) widest = box.max(k) - box.min(k), axis = k;
      const std::uint32_t mid = r.begin + (r.end - r.begin) / 2;
      std::nth_element(items_.begin() + r.begin, items_.begin() + mid, items_.begin() + r.end,
                       [&](std::uint32_t a, std::uint32_t b) {
                         return boxes_[a].min(axis) + boxes_[a].max(axis) <
                                boxes_[b].min(axis) + boxes_[b].max(axis);
                       });
      const auto left = static_cast<std::uint32_t>(nodes_.size());
      nodes_.push_back({});
      nodes_.push_back({});
      nodes_[r.node].first = left;
      nodes_[r.node].count = 0;
      stack.push_back({left, r.begin, mid});
      stack.push_back({left + 1, mid, r.end});
    }
  }

  bool empty() const { return nodes_.empty(); }
  const CGAL::Bbox_3& bounds() const { return nodes_.front().box; }

  /// Calls visit(item) for every item whose widened box may meet the line e + t d, t in [t0, t1].
  template <class Visit>
  void line_query(const vec3d& e, const vec3d& d, double t0, double t1, double margin,
                  Visit visit) const {
    if (nodes_.empty()) return;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const node& nd = nodes_[stack.back()];
      stack.pop_back();
      if (!hits(nd.box, e, d, t0, t1, margin)) continue;
      if (nd.count > 0) {
        for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k)
          if (hits(boxes_[items_[k]], e, d, t0, t1, margin)) visit(items_[k]);
      } else {
        stack.push_back(nd.first);
        stack.push_back(nd.first + 1);
      }
    }
  }

 private:
  struct node {
    CGAL::Bbox_3 box;
    std::uint32_t first = 0, count = 0;  ///< count > 0: leaf items; else children first, first + 1
  };

  static bool hits(const CGAL::Bbox_3& b, const vec3d& e, const vec3d& d, double t0, double t1,
                   double margin) {
    for (int k = 0; k < 3; ++k) {
      const double lo = b.min(k) - margin, hi = b.max(k) + margin;
      if (d[k] == 0) {
        if (e[k] < lo || e[k] > hi) return false;
        continue;
      }
      double a = (lo - e[k]) / d[k], c = (hi - e[k]) / d[k];
      if (a > c) std::swap(a, c);
      t0 = std::max(t0, a);
      t1 = std::min(t1, c);
      if (t0 > t1) return false;
    }
    return true;
  }

  std::vector<CGAL::Bbox_3> boxes_;
  std::vector<std::uint32_t> items_;
  std::vector<node> nodes_;
};

/// Centre of the point's interval box and its radius (max norm), rounding included.
template <class P>
std::pair<vec3d, double> approximate(const P& p) {
  const CGAL::Bbox_3 b = p.bbox();
  vec3d c;
  double r = 0;
  for (int k = 0; k < 3; ++k) {
    c[static_cast<std::size_t>(k)] = b.min(k) + 0.5 * (b.max(k) - b.min(k));
    r = std::max(r,
                 0.5 * (b.max(k) - b.min(k)) + 0x1p-52 * std::fabs(c[static_cast<std::size_t>(k)]));
  }
  return {c, r};
}

/// A point as intervals (its box), and the sign of orientation(a, b, c, d) evaluated on
/// them: certain, or undecided. Callers hold Protect_FPU_rounding (upward rounding).
struct interval_point {
  CGAL::Interval_nt_advanced x, y, z;
};

template <class P>
interval_point interval_of(const P& p) {
  const CGAL::Bbox_3 b = p.bbox();
  return {{b.xmin(), b.xmax()}, {b.ymin(), b.ymax()}, {b.zmin(), b.zmax()}};
}

CGAL::Uncertain<CGAL::Sign> interval_orientation(const interval_point& a, const interval_point& b,
                                                 const interval_point& c, const interval_point& d) {
  const auto ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const auto vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const auto wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  return CGAL::sign(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx));
}

/// p * 2^k, exactly.
template <class E>
typename E::Point_3 scaled_point(const typename E::Point_3& p, int k) {
  return CGAL::ORIGIN + (p - CGAL::ORIGIN) * typename E::FT(std::ldexp(1.0, k));
}

/// The exponent k that brings the largest input coordinate near 1 when the input is tiny or
/// huge (|x| < 2^-100 or > 2^100), else 0. Every invariant is invariant under the exact
/// similarity p -> p * 2^k, and near 1 the interval filters work again (near 1e-300 every
/// product underflows and each predicate would be evaluated in rationals).
template <class E>
int normalising_exponent(const tree_view<E>& v) {
  double big = 0;
  for (const auto& t : v.sources)
    for (const auto& p : t)
      for (int k = 0; k < 3; ++k) big = std::max(big, std::fabs(CGAL::to_double(p[k])));
  if (big == 0 || (big > 0x1p-100 && big < 0x1p100)) return 0;
  int e = 0;
  std::frexp(big, &e);
  return std::max(-1000, std::min(1000, -e));
}

template <class E>
tree_view<E> scaled_view(const tree_view<E>& v, int k) {
  tree_view<E> out = v;
  for (auto& t : out.fragments)
    for (auto& p : t) p = scaled_point<E>(p, k);
  for (auto& t : out.sources)
    for (auto& p : t) p = scaled_point<E>(p, k);
  return out;
}

/// True when the closed triangle t (oriented by n) is separated from the interior of u by the
/// line of one of t's edges.
template <class E>
bool edge_separates(const std::array<typename E::Point_3, 3>& t,
                    const std::array<typename E::Point_3, 3>& u, const typename E::Vector_3& n) {
  for (std::size_t e = 0; e < 3; ++e) {
    const auto& a = t[e];
    const auto& b = t[(e + 1) % 3];
    bool all_out = true;
    for (const auto& q : u)
      if (CGAL::sign(CGAL::cross_product(b - a, q - a) * n) == CGAL::POSITIVE) {
        all_out = false;
        break;
      }
    if (all_out) return true;
  }
  return false;
}

/// The contract's traversal (docs/contract.md "The BSP"), evaluated exactly on the view. Written
/// again on purpose, not bsp_tree::traverse: an oracle must not share the code it checks.
template <class E>
std::vector<std::uint32_t> reference_order(const tree_view<E>& v, const viewpoint<E>& vp) {
  std::vector<std::uint32_t> out;
  if (v.nodes.empty()) return out;
  struct task {
    std::int32_t node;
    bool emit;
  };
  std::vector<task> stack{{0, false}};
  while (!stack.empty()) {
    const task t = stack.back();
    stack.pop_back();
    const auto& nd = v.nodes[static_cast<std::size_t>(t.node)];
    if (t.emit) {
      for (std::uint32_t k = 0; k < nd.count; ++k) out.push_back(nd.first + k);
      continue;
    }
    const auto& p = v.sources[nd.plane_source];
    const int s = vp.is_eye ? static_cast<int>(CGAL::orientation(p[0], p[1], p[2], vp.eye))
                            : static_cast<int>(CGAL::sign(normal_of<E>(p) * (-vp.direction)));
    const std::int32_t first = s < 0 ? nd.positive : nd.negative;
    const std::int32_t second = s < 0 ? nd.negative : nd.positive;
    if (second >= 0) stack.push_back({second, false});
    stack.push_back({t.node, true});
    if (first >= 0) stack.push_back({first, false});
  }
  return out;
}

/// Interior sample points of the fragments for the ray checks: 4 per fragment (centroid and
/// (4,1,1)/6 rotations) while that stays within max_rays, else centroids of a stride
/// (max_rays 0: every centroid).
template <class E>
std::vector<std::pair<std::size_t, typename E::Point_3>> ray_samples(const tree_view<E>& v,
                                                                     std::size_t max_rays) {
  using FT = typename E::FT;
  std::vector<std::pair<std::size_t, typename E::Point_3>> out;
  const std::size_t m = v.fragments.size();
  const bool four = max_rays > 0 && 4 * m <= max_rays;
  const std::size_t stride =
      max_rays == 0 || four || m <= max_rays ? 1 : (m + max_rays - 1) / max_rays;
  for (std::size_t i = 0; i < m; i += stride) {
    if (!v.finite[i]) continue;
    const auto& f = v.fragments[i];
    const auto e1 = f[1] - f[0], e2 = f[2] - f[0];
    out.emplace_back(i, f[0] + (e1 + e2) * (FT(1) / FT(3)));
    if (four) {
      out.emplace_back(i, f[0] + e1 * (FT(1) / FT(6)) + e2 * (FT(1) / FT(6)));
      out.emplace_back(i, f[0] + e1 * (FT(4) / FT(6)) + e2 * (FT(1) / FT(6)));
      out.emplace_back(i, f[0] + e1 * (FT(1) / FT(6)) + e2 * (FT(4) / FT(6)));
    }
  }
  return out;
}

template <class E>
viewpoint<E> rounded(const viewpoint<E>& vp) {
  viewpoint<E> out = vp;
  out.eye = typename E::Point_3(CGAL::to_double(vp.eye.x()), CGAL::to_double(vp.eye.y()),
                                CGAL::to_double(vp.eye.z()));
  out.direction =
      typename E::Vector_3(CGAL::to_double(vp.direction.x()), CGAL::to_double(vp.direction.y()),
                           CGAL::to_double(vp.direction.z()));
  return out;
}

}  // namespace

template <class E, class K>
tree_view<E> view_of(const exbsp::bsp_tree<K>& t, const exbsp::triangle_soup& soup) {
  tree_view<E> v;
  for (const auto& st : soup.triangles) {
    typename tree_view<E>::triangle tri{exact_point<E>(soup.vertices[st.v[0]]),
                                        exact_point<E>(soup.vertices[st.v[1]]),
                                        exact_point<E>(soup.vertices[st.v[2]])};
    v.degenerate.push_back(CGAL::collinear(tri[0], tri[1], tri[2]) ? 1 : 0);
    v.sources.push_back(tri);
    v.source_face.push_back(st.face);
  }
  const std::size_t m = t.fragments().size();
  v.fragments.reserve(m);
  for (std::size_t i = 0; i < m; ++i) {
    const auto& f = t.fragments()[i];
    typename tree_view<E>::triangle tri;
    bool ok = true;
    for (std::size_t k = 0; k < 3; ++k) {
      if constexpr (std::is_same_v<E, K>) {
        tri[k] = f.v[k];
      } else {
        const double x = f.v[k].x(), y = f.v[k].y(), z = f.v[k].z();
        if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z))
          tri[k] = exact_point<E>({x, y, z});
        else
          ok = false;
      }
    }
    v.fragments.push_back(tri);
    v.finite.push_back(ok ? 1 : 0);
    if (!ok) ++v.nonfinite;
    v.source.push_back(f.source);
    v.face.push_back(f.face);
    v.node_of.push_back(t.node_of_fragment(i));
  }
  for (const auto& n : t.nodes())
    v.nodes.push_back({n.plane_source, n.first, n.count, n.negative, n.positive, n.parent,
                       n.side_in_parent, n.depth});
  v.stats = t.stats();
  return v;
}

template <class E>
void check_source_planes(const tree_view<E>& v, check_report& r) {
  for (std::size_t i = 0; i < v.fragments.size(); ++i) {
    if (!v.finite[i]) continue;
    const auto& f = v.fragments[i];
    if (v.source[i] >= v.sources.size()) {
      r.fail("structure", "fragment " + std::to_string(i) + " has no source");
      continue;
    }
    const auto& s = v.sources[v.source[i]];
    for (std::size_t k = 0; k < 3; ++k)
      if (CGAL::orientation(s[0], s[1], s[2], f[k]) != CGAL::COPLANAR) {
        r.fail("source_plane", "fragment " + std::to_string(i) + " vertex " + std::to_string(k) +
                                   " is off the plane of source " + std::to_string(v.source[i]));
        break;
      }
    const auto n1 = normal_of<E>(f), n2 = normal_of<E>(s);
    if (CGAL::cross_product(n1, n2) != CGAL::NULL_VECTOR || CGAL::sign(n1 * n2) != CGAL::POSITIVE)
      r.fail("orientation", "fragment " + std::to_string(i) +
                                " is not positively parallel to source " +
                                std::to_string(v.source[i]));
  }
}

template <class E>
void check_tiling(const tree_view<E>& v, check_report& r, bool pairwise) {
  std::vector<std::vector<std::size_t>> by_source(v.sources.size());
  for (std::size_t i = 0; i < v.fragments.size(); ++i)
    if (v.source[i] < v.sources.size()) by_source[v.source[i]].push_back(i);
  for (std::size_t s = 0; s < v.sources.size(); ++s) {
    const auto& frags = by_source[s];
    if (v.degenerate[s]) {
      if (!frags.empty())
        r.fail("structure", "degenerate source " + std::to_string(s) + " has fragments");
      continue;
    }
    if (frags.empty()) {
      r.fail("tiling_area", "source " + std::to_string(s) + " has no fragment (face dropped)");
      continue;
    }
    bool all_finite = true;
    for (std::size_t i : frags) all_finite = all_finite && v.finite[i];
    if (!all_finite) continue;
    const auto& src = v.sources[s];
    if (frags.size() == 1 && v.fragments[frags[0]] == src) continue;  // the source itself: tiles it
    const auto n = normal_of<E>(src);
    typename E::Vector_3 sum = CGAL::NULL_VECTOR;
    for (std::size_t i : frags) sum = sum + normal_of<E>(v.fragments[i]);
    if (sum != n)
      r.fail("tiling_area", "normals of the " + std::to_string(frags.size()) +
                                " fragments of source " + std::to_string(s) +
                                " do not sum to its normal");
    for (std::size_t i : frags) {
      bool inside = true;
      for (const auto& p : v.fragments[i])
        for (std::size_t e = 0; e < 3 && inside; ++e)
          if (CGAL::sign(CGAL::cross_product(src[(e + 1) % 3] - src[e], p - src[e]) * n) ==
              CGAL::NEGATIVE)
            inside = false;
      if (!inside)
        r.fail("inside_source",
               "fragment " + std::to_string(i) + " leaves source " + std::to_string(s));
    }
    if (!pairwise) continue;
    for (std::size_t a = 0; a < frags.size(); ++a)
      for (std::size_t b = a + 1; b < frags.size(); ++b) {
        const auto& fa = v.fragments[frags[a]];
        const auto& fb = v.fragments[frags[b]];
        if (CGAL::sign(normal_of<E>(fa) * n) != CGAL::POSITIVE ||
            CGAL::sign(normal_of<E>(fb) * n) != CGAL::POSITIVE)
          continue;  // reported by check_source_planes
        if (!edge_separates<E>(fa, fb, n) && !edge_separates<E>(fb, fa, n))
          r.fail("overlap", "fragments " + std::to_string(frags[a]) + " and " +
                                std::to_string(frags[b]) + " of source " + std::to_string(s) +
                                " overlap");
      }
  }
}

template <class E>
void check_structure(const tree_view<E>& v, check_report& r) {
  const std::size_t N = v.nodes.size(), M = v.fragments.size();
  if ((N == 0) != (M == 0))
    r.fail("structure", std::to_string(N) + " nodes for " + std::to_string(M) + " fragments");
  std::size_t expected_first = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const auto& nd = v.nodes[i];
    const std::string at = "node " + std::to_string(i) + ": ";
    if (nd.first != expected_first)
      r.fail("structure", at + "fragment range does not follow the previous node's");
    if (nd.count == 0) r.fail("structure", at + "no fragment (its splitter must be stored there)");
    expected_first = nd.first + nd.count;
    if (i == 0) {
      if (nd.parent != -1 || nd.depth != 1)
        r.fail("structure", at + "the root has a parent or depth != 1");
    } else {
      if (nd.parent < 0 || static_cast<std::size_t>(nd.parent) >= N ||
          (nd.side_in_parent != 1 && nd.side_in_parent != -1)) {
        r.fail("structure", at + "bad parent link");
        continue;
      }
      const auto& p = v.nodes[static_cast<std::size_t>(nd.parent)];
      if ((nd.side_in_parent > 0 ? p.positive : p.negative) != static_cast<std::int32_t>(i))
        r.fail("structure", at + "parent does not point back");
      if (nd.depth != p.depth + 1) r.fail("structure", at + "depth is not parent's + 1");
    }
    for (std::int32_t child : {nd.negative, nd.positive})
      if (child >= 0 &&
          (static_cast<std::size_t>(child) >= N ||
           v.nodes[static_cast<std::size_t>(child)].parent != static_cast<std::int32_t>(i)))
        r.fail("structure", at + "child does not point back");
    if (nd.plane_source >= v.sources.size() || v.degenerate[nd.plane_source]) {
      r.fail("structure", at + "plane of a degenerate or missing source");
      continue;
    }
    bool splitter_here = false;
    for (std::size_t k = nd.first; k < nd.first + nd.count && k < M; ++k)
      splitter_here |= v.source[k] == nd.plane_source;
    if (!splitter_here)
      r.fail("structure", at + "no fragment of its plane's source is stored at it");
  }
  if (expected_first != M)
    r.fail("structure", "node ranges cover " + std::to_string(expected_first) + " of " +
                            std::to_string(M) + " fragments");
  // Every node reachable exactly once from the root.
  if (N) {
    std::vector<char> seen(N, 0);
    std::vector<std::int32_t> stack{0};
    std::size_t reached = 0;
    while (!stack.empty()) {
      const auto i = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      if (seen[i]++) {
        r.fail("structure", "node " + std::to_string(i) + " reached twice");
        break;
      }
      ++reached;
      for (std::int32_t c : {v.nodes[i].negative, v.nodes[i].positive})
        if (c >= 0 && static_cast<std::size_t>(c) < N) stack.push_back(c);
    }
    if (reached != N)
      r.fail("structure", std::to_string(N - reached) + " nodes unreachable from the root");
  }
  for (std::size_t i = 0; i < M; ++i) {
    const std::size_t n = v.node_of[i];
    if (n >= N || i < v.nodes[n].first || i >= v.nodes[n].first + v.nodes[n].count)
      r.fail("structure", "node_of_fragment(" + std::to_string(i) + ") is wrong");
    if (v.source[i] < v.source_face.size() && v.face[i] != v.source_face[v.source[i]])
      r.fail("structure", "fragment " + std::to_string(i) + " lost its face id");
  }
}

template <class E>
void check_node_planes(const tree_view<E>& v, check_report& r) {
  const std::size_t N = v.nodes.size();
  for (std::size_t i = 0; i < v.fragments.size(); ++i) {
    if (!v.finite[i] || v.node_of[i] >= N) continue;
    const auto& f = v.fragments[i];
    std::size_t at = v.node_of[i];
    const auto& own = v.sources[v.nodes[at].plane_source];
    for (const auto& p : f)
      if (CGAL::orientation(own[0], own[1], own[2], p) != CGAL::COPLANAR) {
        r.fail("node_plane", "fragment " + std::to_string(i) + " is off its node's plane");
        break;
      }
    bool crossed = false, lies_in = false;
    std::size_t guard = 0;
    while (v.nodes[at].parent >= 0 && guard++ < N && !(crossed && lies_in)) {
      const int side = v.nodes[at].side_in_parent;
      const auto parent = static_cast<std::size_t>(v.nodes[at].parent);
      const auto& pl = v.sources[v.nodes[parent].plane_source];
      bool strictly = false, wrong = false;
      for (const auto& p : f) {
        const int o = static_cast<int>(CGAL::orientation(pl[0], pl[1], pl[2], p));
        wrong |= o * side < 0;
        strictly |= o * side > 0;
      }
      const std::string where = " the plane of ancestor node " + std::to_string(parent) +
                                " (side " + std::to_string(side) + ")";
      if (wrong && !crossed)
        r.fail("ancestor_side", "fragment " + std::to_string(i) + " crosses" + where);
      if (!strictly && !lies_in)
        r.fail("ancestor_plane", "fragment " + std::to_string(i) + " lies in" + where);
      crossed |= wrong;
      lies_in |= !strictly;
      at = parent;
    }
  }
}

template <class E>
void check_stats(const tree_view<E>& v, const std::string& expected_kernel,
                 const std::string& expected_heuristic, check_report& r) {
  const auto& s = v.stats;
  std::size_t degenerate = 0;
  for (char d : v.degenerate) degenerate += d ? 1 : 0;
  std::size_t depth = 0;
  for (const auto& n : v.nodes) depth = std::max<std::size_t>(depth, n.depth);
  auto expect = [&](bool ok, const std::string& what) {
    if (!ok) r.fail("stats", what);
  };
  expect(s.input_triangles == v.sources.size(), "input_triangles " +
                                                    std::to_string(s.input_triangles) +
                                                    " != " + std::to_string(v.sources.size()));
  expect(s.degenerate_input == degenerate, "degenerate_input " +
                                               std::to_string(s.degenerate_input) +
                                               " != " + std::to_string(degenerate));
  expect(s.fragments == v.fragments.size(), "fragments != stored fragments");
  expect(s.nodes == v.nodes.size(), "nodes != node array size");
  expect(s.depth == depth,
         "depth " + std::to_string(s.depth) + " != longest path " + std::to_string(depth));
  const std::size_t base = s.input_triangles - std::min(s.input_triangles, s.degenerate_input);
  expect(s.fragments >= base + s.splits && s.fragments <= base + 2 * s.splits,
         "fragments " + std::to_string(s.fragments) +
             " not in [kept + splits, kept + 2 splits] = [" + std::to_string(base + s.splits) +
             ", " + std::to_string(base + 2 * s.splits) + "]");
  expect(s.kernel == expected_kernel, "kernel '" + s.kernel + "'");
  expect(expected_heuristic.empty() || s.heuristic == expected_heuristic,
         "heuristic '" + s.heuristic + "'");
}

template <class E>
order_tally check_order_along_rays(const tree_view<E>& v, const viewpoint<E>& vp,
                                   const std::vector<std::uint32_t>& order, std::size_t max_rays,
                                   check_report& r, bool prune) {
  using FT = typename E::FT;
  order_tally tally;
  const std::size_t m = v.fragments.size();
  std::vector<std::size_t> pos(m);
  for (std::size_t k = 0; k < order.size(); ++k) pos[order[k]] = k;
  std::vector<typename E::Vector_3> normals(m);
  std::vector<CGAL::Bbox_3> boxes(m);
  for (std::size_t i = 0; i < m; ++i) {
    const auto& f = v.fragments[i];
    if (!v.finite[i]) {  // never a candidate
      boxes[i] = CGAL::Bbox_3(HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
      continue;
    }
    normals[i] = normal_of<E>(f);
    boxes[i] = f[0].bbox() + f[1].bbox() + f[2].bbox();
  }
  const box_tree bvh(boxes);
  std::vector<interval_point> corners(3 * m);
  for (std::size_t i = 0; i < m; ++i)
    if (v.finite[i])
      for (std::size_t k = 0; k < 3; ++k) corners[3 * i + k] = interval_of(v.fragments[i][k]);
  if (bvh.empty()) return tally;
  // The scene's box (finite fragments only) and its size, for T and the rounding allowance.
  CGAL::Bbox_3 scene(HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
  for (std::size_t i = 0; i < m; ++i)
    if (v.finite[i]) scene += boxes[i];
  double size = 0;
  for (int k = 0; k < 3; ++k)
    size = std::max(
        {size, scene.max(k) - scene.min(k), std::fabs(scene.min(k)), std::fabs(scene.max(k))});
  const double allowance = 1e-9 * size;

  std::vector<std::size_t> candidates;
  std::vector<std::pair<FT, std::size_t>> hits;
  for (const auto& [j, q] : ray_samples(v, max_rays)) {
    const typename E::Point_3 from = vp.is_eye ? vp.eye : q;
    const typename E::Point_3 to = vp.is_eye ? q : q + vp.direction;
    if (from == to) continue;
    ++tally.rays;
    // Candidates: see the top of this file.
    candidates.clear();
    const auto [e, ef] = approximate(from);
    const auto [t_d, et] = approximate(to);
    const vec3d d{t_d[0] - e[0], t_d[1] - e[1], t_d[2] - e[2]};
    // std::hypot: squares of coordinates near 1e-300 (or 1e200) would underflow (overflow).
    const double dn = std::hypot(d[0], d[1], d[2]) * (1 - 1e-15) - 2 * std::sqrt(3.0) * (ef + et);
    double reach = 0;  // farthest corner of the scene box from e
    for (int cx = 0; cx < 2; ++cx)
      for (int cy = 0; cy < 2; ++cy)
        for (int cz = 0; cz < 2; ++cz) {
          const double x = (cx ? scene.max(0) : scene.min(0)) - e[0],
                       y = (cy ? scene.max(1) : scene.min(1)) - e[1],
                       z = (cz ? scene.max(2) : scene.min(2)) - e[2];
          reach = std::max(reach, std::hypot(x, y, z));
        }
    const double T = (reach + std::sqrt(3.0) * ef) * (1 + 1e-12) / dn;
    if (!prune || !(dn > 0) ||
        !std::isfinite(T)) {  // the rounded direction says nothing: every fragment
      for (std::size_t i = 0; i < m; ++i) candidates.push_back(i);
    } else {
      const double dmax = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
      const double margin = (ef + T * (ef + et) + T * dmax * 0x1p-51) * (1 + 1e-9) + allowance;
      bvh.line_query(e, d, vp.is_eye ? 0.0 : -T, T, margin,
                     [&](std::uint32_t i) { candidates.push_back(i); });
    }
    // Interval signs first: most candidates are rejected by two certain, different signs, so
    // that the exact predicate only runs where the ray passes close to an edge line.
    if (prune) {
      const interval_point a = interval_of(from),
                           b = interval_of(to);  // before: Gmpq's to_interval rounds itself
      CGAL::Protect_FPU_rounding<true> upward;
      std::size_t kept = 0;
      for (std::size_t i : candidates) {
        if (!v.finite[i]) continue;
        bool maybe = true, pos = false, neg = false;
        for (std::size_t e = 0; e < 3 && maybe; ++e) {
          const CGAL::Uncertain<CGAL::Sign> o =
              interval_orientation(a, b, corners[3 * i + e], corners[3 * i + (e + 1) % 3]);
          if (!o.is_certain()) continue;
          const CGAL::Sign sg = o.make_certain();
          pos |= sg == CGAL::POSITIVE;
          neg |= sg == CGAL::NEGATIVE;
          maybe = sg != CGAL::ZERO && !(pos && neg);
        }
        if (maybe) candidates[kept++] = i;
      }
      candidates.resize(kept);
    }
    hits.clear();
    for (std::size_t i : candidates) {
      const auto& f = v.fragments[i];
      const auto o0 = CGAL::orientation(from, to, f[0], f[1]);
      if (o0 == CGAL::COPLANAR) continue;
      if (CGAL::orientation(from, to, f[1], f[2]) != o0 ||
          CGAL::orientation(from, to, f[2], f[0]) != o0)
        continue;
      // The line crosses the interior of fragment i; where?
      const FT g_from = normals[i] * (from - f[0]), g_to = normals[i] * (to - f[0]);
      if (g_from == g_to) continue;           // parallel (cannot happen with a strict crossing)
      const FT t = g_from / (g_from - g_to);  // from + t (to - from) is on i's plane
      if (vp.is_eye && !(t > 0)) continue;    // behind (or at) the eye: not drawn over anything
      hits.emplace_back(t, i);
    }
    std::sort(hits.begin(), hits.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    // A pair (nearer, farther) at different depths is misordered when the nearer is drawn first.
    for (std::size_t g = 0; g < hits.size();) {
      std::size_t h = g;
      while (h < hits.size() && hits[h].first == hits[g].first) ++h;
      for (std::size_t k = g; k < h; ++k) {
        const std::size_t far = hits[k].second;
        tally.pairs += g;
        for (std::size_t n = 0; n < g; ++n) {
          const std::size_t near = hits[n].second;
          if (pos[near] > pos[far]) continue;
          ++tally.misordered;
          r.fail("order", vp.what + ": fragment " + std::to_string(near) + " (face " +
                              std::to_string(v.face[near]) + ") is in front of fragment " +
                              std::to_string(far) + " (face " + std::to_string(v.face[far]) +
                              ") on the ray through a point of fragment " + std::to_string(j) +
                              " but is drawn before it");
        }
      }
      g = h;
    }
  }
  return tally;
}

template <class E>
std::vector<viewpoint<E>> standard_viewpoints(const tree_view<E>& v, std::uint64_t seed) {
  using FT = typename E::FT;
  split_mix rng{seed};
  std::vector<viewpoint<E>> out;
  // Bounding box of the input, in double (only to place random eyes).
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& t : v.sources)
    for (const auto& p : t)
      for (int k = 0; k < 3; ++k) {
        const double x = CGAL::to_double(p[k]);
        lo[k] = std::min(lo[k], x);
        hi[k] = std::max(hi[k], x);
      }
  if (v.sources.empty()) lo[0] = lo[1] = lo[2] = -1, hi[0] = hi[1] = hi[2] = 1;
  vec3d e;
  for (int k = 0; k < 3; ++k) {
    const double c = 0.5 * lo[k] + 0.5 * hi[k], h = std::max(hi[k] - lo[k], 1e-300);
    e[static_cast<std::size_t>(k)] = c + rng.uniform(-1.5, 1.5) * h;
  }
  out.push_back({true, exact_point<E>(e), {}, "random eye"});
  if (!v.nodes.empty()) {
    const auto& nd = v.nodes[rng.below(v.nodes.size())];
    const auto& p = v.sources[nd.plane_source];
    const int a = static_cast<int>(rng.below(5)) - 2, b = static_cast<int>(rng.below(5)) - 1;
    out.push_back({true,
                   p[0] + (p[1] - p[0]) * FT(a) + (p[2] - p[0]) * FT(b),
                   {},
                   "eye on the plane of a node"});
    out.push_back({false, CGAL::ORIGIN, p[1] - p[0], "direction parallel to a node's plane"});
  }
  if (!v.fragments.empty()) {
    const std::size_t i = rng.below(v.fragments.size());
    if (v.finite[i])
      out.push_back({true, v.fragments[i][rng.below(3)], {}, "eye at a fragment vertex"});
  }
  if (!v.sources.empty())
    out.push_back(
        {true, v.sources[rng.below(v.sources.size())][rng.below(3)], {}, "eye at an input vertex"});
  typename E::Vector_3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  if (d == CGAL::NULL_VECTOR) d = typename E::Vector_3(0, 0, -1);
  out.push_back({false, CGAL::ORIGIN, d, "random direction"});
  return out;
}

template <class K, class E>
std::vector<std::uint32_t> tree_order(const exbsp::bsp_tree<K>& t, const viewpoint<E>& vp,
                                      bool back_to_front) {
  if constexpr (std::is_same_v<K, E>) {
    return vp.is_eye ? t.order_from_eye(vp.eye, back_to_front)
                     : t.order_for_direction(vp.direction, back_to_front);
  } else {
    if (vp.is_eye)
      return t.order_from_eye(
          typename K::Point_3(CGAL::to_double(vp.eye.x()), CGAL::to_double(vp.eye.y()),
                              CGAL::to_double(vp.eye.z())),
          back_to_front);
    return t.order_for_direction(
        typename K::Vector_3(CGAL::to_double(vp.direction.x()), CGAL::to_double(vp.direction.y()),
                             CGAL::to_double(vp.direction.z())),
        back_to_front);
  }
}

template <class K, class E>
void check_orders(const exbsp::bsp_tree<K>& t, const tree_view<E>& v, viewpoint<E> vp,
                  std::size_t max_rays, check_report& r, int k) {
  if constexpr (!std::is_same_v<K, E>) vp = rounded(vp);
  const auto order = tree_order<K>(t, vp, true);
  auto reverse = tree_order<K>(t, vp, false);
  if (k) vp.eye = scaled_point<E>(vp.eye, k);
  std::vector<char> seen(v.fragments.size(), 0);
  bool perm = order.size() == v.fragments.size();
  for (std::uint32_t i : order) perm = perm && i < seen.size() && !seen[i]++;
  if (!perm) {
    r.fail("structure", vp.what + ": the order is not a permutation of the fragments");
    return;
  }
  if (order != reference_order(v, vp))
    r.fail("traversal", vp.what + ": order differs from the contract's traversal");
  std::reverse(reverse.begin(), reverse.end());
  if (reverse != order)
    r.fail("traversal", vp.what + ": front-to-back is not the reverse of back-to-front");
  check_order_along_rays(v, vp, order, max_rays, r);
}

template <class K>
check_report check_tree(const exbsp::bsp_tree<K>& t, const exbsp::triangle_soup& soup,
                        const check_options& o) {
  using E = exact_kernel_of<K>;
  check_report r;
  const tree_view<E> v0 = view_of<E>(t, soup);
  if (v0.nonfinite)
    r.fail("nonfinite", std::to_string(v0.nonfinite) + " fragments with NaN/Inf coordinates");
  check_structure(v0, r);
  check_stats(v0, exbsp::to_string(exbsp::kernel_traits<K>::id), o.heuristic, r);
  if (!r.broken.count("structure")) {
    const int k = normalising_exponent(v0);
    const tree_view<E> v = k ? scaled_view(v0, k) : v0;
    check_source_planes(v, r);
    check_tiling(v, r);
    check_node_planes(v, r);
    auto vps = standard_viewpoints(v0, o.seed);
    if (vps.size() > o.viewpoints) vps.resize(o.viewpoints);
    for (const vec3d& e : o.eyes) vps.push_back({true, exact_point<E>(e), {}, "given eye"});
    for (const vec3d& d : o.directions)
      vps.push_back(
          {false, CGAL::ORIGIN, typename E::Vector_3(d[0], d[1], d[2]), "given direction"});
    for (const auto& vp : vps) check_orders(t, v, vp, o.max_rays, r, k);
  }
  return r;
}

// Explicit instantiations: every CGAL kernel K with its exact kernel E = exact_kernel_of<K>.
#define EXBSP_CHECKER_FOR_EXACT(E)                                                               \
  template void check_structure<E>(const tree_view<E>&, check_report&);                          \
  template void check_source_planes<E>(const tree_view<E>&, check_report&);                      \
  template void check_tiling<E>(const tree_view<E>&, check_report&, bool);                       \
  template void check_node_planes<E>(const tree_view<E>&, check_report&);                        \
  template void check_stats<E>(const tree_view<E>&, const std::string&, const std::string&,      \
                               check_report&);                                                   \
  template order_tally check_order_along_rays<E>(const tree_view<E>&, const viewpoint<E>&,       \
                                                 const std::vector<std::uint32_t>&, std::size_t, \
                                                 check_report&, bool);                           \
  template std::vector<viewpoint<E>> standard_viewpoints<E>(const tree_view<E>&, std::uint64_t);
#define EXBSP_CHECKER_FOR_KERNEL(K)                                                           \
  template tree_view<exact_kernel_of<K>> view_of<exact_kernel_of<K>, K>(                      \
      const exbsp::bsp_tree<K>&, const exbsp::triangle_soup&);                                \
  template std::vector<std::uint32_t> tree_order<K, exact_kernel_of<K>>(                      \
      const exbsp::bsp_tree<K>&, const viewpoint<exact_kernel_of<K>>&, bool);                 \
  template void check_orders<K, exact_kernel_of<K>>(                                          \
      const exbsp::bsp_tree<K>&, const tree_view<exact_kernel_of<K>>&,                        \
      viewpoint<exact_kernel_of<K>>, std::size_t, check_report&, int);                        \
  template check_report check_tree<K>(const exbsp::bsp_tree<K>&, const exbsp::triangle_soup&, \
                                      const check_options&);

EXBSP_CHECKER_FOR_EXACT(exbsp::epeck_kernel)
EXBSP_CHECKER_FOR_EXACT(exbsp::gmpq_kernel)
EXBSP_CHECKER_FOR_KERNEL(exbsp::double_kernel)
EXBSP_CHECKER_FOR_KERNEL(exbsp::epick_kernel)
EXBSP_CHECKER_FOR_KERNEL(exbsp::epeck_kernel)
EXBSP_CHECKER_FOR_KERNEL(exbsp::gmpq_kernel)

}  // namespace exbsp_test
