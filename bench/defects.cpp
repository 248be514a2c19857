// Exact defect counts of a built tree; notation and definitions at the top of defects.h.
#include "defects.h"

#include <gmpxx.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "bsp/kernel_double.h"
#include "bsp/kernel_epeck.h"
#include "bsp/kernel_epick.h"
#include "generators.h"

namespace exbsp::bench {
namespace {

using epick = CGAL::Epick;
using epeck = CGAL::Epeck;

/// The exact view of a tree's points: E is the kernel whose predicates are evaluated (exact
/// on E's points), point() converts a tree point exactly, coordinate() gives a rational.
template <class K>
struct check_space;

template <>
struct check_space<double_kernel> {
  using E = epick;
  static E::Point_3 point(const double_kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }
};

template <>
struct check_space<epick_kernel> {
  using E = epick;
  static const E::Point_3& point(const epick_kernel::Point_3& p) { return p; }
};

template <>
struct check_space<epeck_kernel> {
  using E = epeck;
  static const E::Point_3& point(const epeck_kernel::Point_3& p) { return p; }
};

mpq_class rational(double x) { return mpq_class(x); }
mpq_class rational(const epeck::FT& x) { return mpq_class(kernel_traits<epeck_kernel>::rational(x)); }

epeck::Point_3 to_epeck(const epick::Point_3& p) { return {p.x(), p.y(), p.z()}; }
const epeck::Point_3& to_epeck(const epeck::Point_3& p) { return p; }

/// Exact (b - a) x (c - a) in rationals.
template <class P>
std::array<mpq_class, 3> cross_product_exact(const P& a, const P& b, const P& c) {
  const mpq_class ax = rational(a.x()), ay = rational(a.y()), az = rational(a.z());
  const mpq_class ux = rational(b.x()) - ax, uy = rational(b.y()) - ay, uz = rational(b.z()) - az;
  const mpq_class vx = rational(c.x()) - ax, vy = rational(c.y()) - ay, vz = rational(c.z()) - az;
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

/// Sign of w0 s0 + w1 s1 + w2 s2 for unknown positive weights, from the signs alone:
/// -1, 0, +1, or 2 when two signs are opposite (undecided).
int combine_signs(int s0, int s1, int s2) {
  const bool pos = s0 > 0 || s1 > 0 || s2 > 0, neg = s0 < 0 || s1 < 0 || s2 < 0;
  if (pos && neg) return 2;
  return pos ? 1 : neg ? -1 : 0;
}

/// A bounding-volume hierarchy of boxes (median split on the longest axis), queried with a
/// segment against boxes widened by a margin. Boxes only select candidates.
class box_tree {
public:
  explicit box_tree(std::vector<CGAL::Bbox_3> boxes) : boxes_(std::move(boxes)) {
    items_.resize(boxes_.size());
    for (std::size_t i = 0; i < items_.size(); ++i) items_[i] = static_cast<std::uint32_t>(i);
    if (items_.empty()) return;
    struct range { std::uint32_t node, begin, end; };
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
                         return boxes_[a].min(axis) + boxes_[a].max(axis) < boxes_[b].min(axis) + boxes_[b].max(axis);
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

  /// Calls visit(item) for every item whose widened box may meet the segment [e, e + d].
  template <class Visit>
  void segment_query(const std::array<double, 3>& e, const std::array<double, 3>& d, double margin,
                     Visit visit) const {
    if (nodes_.empty()) return;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const node& nd = nodes_[stack.back()];
      stack.pop_back();
      if (!hits(nd.box, e, d, margin)) continue;
      if (nd.count > 0) {
        for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k)
          if (hits(boxes_[items_[k]], e, d, margin)) visit(items_[k]);
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

  static bool hits(const CGAL::Bbox_3& b, const std::array<double, 3>& e, const std::array<double, 3>& d,
                   double margin) {
    double t0 = 0, t1 = 1;
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

/// Fixed eye directions (not unit: the eye is a double point, exact as it is).
constexpr double eye_directions[8][3] = {{1, 0.6, 0.3},  {-0.4, 1, -0.7}, {0.2, -0.5, 1},  {-1, -0.8, -0.6},
                                         {0.7, -1, 0.1}, {-0.3, 0.2, -1}, {0.9, 0.9, -0.8}, {-0.6, -0.1, 0.9}};

}  // namespace

template <class K>
defect_report check_defects(const bsp_tree<K>& tree, const triangle_soup& soup, const defect_options& options) {
  using space = check_space<K>;
  using E = typename space::E;
  using P = typename E::Point_3;
  const auto start = std::chrono::steady_clock::now();
  const auto orientation = E().orientation_3_object();
  const auto& frags = tree.fragments();
  const auto& nodes = tree.nodes();
  const std::size_t F = frags.size();
  defect_report r;
  r.fragments = F;

  // Rounded constructions can overflow or divide by a rounded zero: such fragments are
  // counted as non_finite and left out of every other check (their source counts as not tiling).
  std::vector<std::array<P, 3>> fp(F);
  std::vector<char> finite(F, 1);
  for (std::size_t i = 0; i < F; ++i)
    for (int k = 0; k < 3; ++k) {
      const auto& v = frags[i].v[k];
      if (!CGAL::is_finite(CGAL::to_double(v.x())) || !CGAL::is_finite(CGAL::to_double(v.y())) ||
          !CGAL::is_finite(CGAL::to_double(v.z()))) {
        finite[i] = 0;
        continue;
      }
      fp[i][k] = space::point(v);
    }
  for (std::size_t i = 0; i < F; ++i) r.non_finite += finite[i] ? 0 : 1;
  std::vector<P> vertex(soup.vertices.size());
  for (std::size_t v = 0; v < vertex.size(); ++v)
    vertex[v] = P(soup.vertices[v][0], soup.vertices[v][1], soup.vertices[v][2]);
  const auto source_point = [&](std::uint32_t s, int k) -> const P& { return vertex[soup.triangles[s].v[k]]; };
  const auto side_of_source = [&](std::uint32_t s, const P& p) {
    return static_cast<int>(orientation(source_point(s, 0), source_point(s, 1), source_point(s, 2), p));
  };

  // 1. Fragments off their source's plane.
  for (std::size_t i = 0; i < F; ++i)
    for (int k = 0; k < 3 && finite[i]; ++k)
      if (side_of_source(frags[i].source, fp[i][k]) != 0) {
        ++r.off_plane;
        break;
      }

  auto lap = [last = start](double& into) mutable {
    const auto now = std::chrono::steady_clock::now();
    into = std::chrono::duration<double>(now - last).count();
    last = now;
  };
  lap(r.seconds_plane);

  // 2. Tiling: exact sums of cross products per split source.
  {
    std::vector<std::uint32_t> count(soup.triangles.size() + 1, 0);
    for (const auto& f : frags) ++count[f.source + 1];
    for (std::size_t s = 1; s < count.size(); ++s) count[s] += count[s - 1];
    std::vector<std::uint32_t> by_source(F);
    std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
    for (std::size_t i = 0; i < F; ++i) by_source[fill[frags[i].source]++] = static_cast<std::uint32_t>(i);
    for (std::uint32_t s = 0; s + 1 < count.size(); ++s) {
      if (count[s + 1] - count[s] < 2) continue;
      ++r.split_sources;
      std::array<mpq_class, 3> sum{0, 0, 0};
      bool all_finite = true;
      for (std::uint32_t k = count[s]; k < count[s + 1] && all_finite; ++k) {
        all_finite = finite[by_source[k]] != 0;
        if (!all_finite) break;
        const auto& q = fp[by_source[k]];
        const auto c = cross_product_exact(q[0], q[1], q[2]);
        for (int a = 0; a < 3; ++a) sum[a] += c[a];
      }
      const auto want = cross_product_exact(source_point(s, 0), source_point(s, 1), source_point(s, 2));
      if (!all_finite || sum[0] != want[0] || sum[1] != want[1] || sum[2] != want[2]) ++r.not_tiling;
    }
  }

  lap(r.seconds_tiling);

  // 3. Classification against every ancestor plane (closed side).
  {
    std::vector<std::pair<std::uint32_t, int>> chain;
    for (const auto& nd : nodes) {
      chain.clear();
      const auto* at = &nd;
      while (at->parent >= 0) {
        chain.push_back({nodes[at->parent].plane_source, at->side_in_parent});
        at = &nodes[at->parent];
      }
      for (std::uint32_t i = nd.first; i < nd.first + nd.count; ++i) {
        if (!finite[i]) continue;
        bool bad = false;
        for (const auto& [plane, side] : chain) {
          ++r.ancestor_tests;
          for (int k = 0; k < 3 && !bad; ++k) bad = side_of_source(plane, fp[i][k]) == -side;
          if (bad) break;
        }
        if (bad) ++r.misclassified;
      }
    }
  }

  lap(r.seconds_classification);

  // 4. Order errors for sampled eyes and sampled fragments (centroids).
  if (options.order && F > 0) {
    std::vector<CGAL::Bbox_3> boxes(F);
    // Non-finite fragments get an empty box far away: never a candidate.
    for (std::size_t i = 0; i < F; ++i)
      boxes[i] = finite[i] ? fp[i][0].bbox() + fp[i][1].bbox() + fp[i][2].bbox()
                           : CGAL::Bbox_3(1e300, 1e300, 1e300, 1e300, 1e300, 1e300);
    const box_tree bvh(std::move(boxes));
    const bounds b = soup_bounds(soup);
    double largest = 0;
    for (int k = 0; k < 3; ++k) largest = std::max({largest, std::fabs(b.lo[k]), std::fabs(b.hi[k])});
    const double margin = 1e-9 * (b.diagonal() + largest);
    const auto approx = [](const P& p) {
      return std::array<double, 3>{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    };
    const std::size_t wanted = kernel_traits<K>::exact ? options.exact_samples : options.samples;
    const std::size_t samples = wanted == 0 ? F : std::min(F, wanted);
    const auto eye_count = std::min<std::size_t>(options.eyes, 8);
    std::vector<std::uint32_t> position(F);
    std::vector<std::int8_t> eye_side(F);
    for (std::size_t eye_index = 0; eye_index < eye_count; ++eye_index) {
      const vec3d c = b.centre();
      const double* dir = eye_directions[eye_index];
      const vec3d eye_d{c[0] + 2 * b.diagonal() * dir[0], c[1] + 2 * b.diagonal() * dir[1],
                        c[2] + 2 * b.diagonal() * dir[2]};
      const P eye(eye_d[0], eye_d[1], eye_d[2]);
      const epeck::Point_3 eye_exact(eye_d[0], eye_d[1], eye_d[2]);
      const std::vector<std::uint32_t> order =
          tree.order_from_eye(typename K::Point_3(eye_d[0], eye_d[1], eye_d[2]));
      for (std::size_t k = 0; k < order.size(); ++k) position[order[k]] = static_cast<std::uint32_t>(k);
      for (std::size_t i = 0; i < F; ++i)
        eye_side[i] = finite[i] ? static_cast<std::int8_t>(orientation(fp[i][0], fp[i][1], fp[i][2], eye)) : 0;
      ++r.eyes;
      for (std::size_t s = 0; s < samples; ++s) {
        const std::size_t j = samples == F ? s : s * F / samples;
        if (!finite[j]) continue;
        const auto& q = fp[j];
        std::optional<epeck::Point_3> q_exact;  // the centroid, built only when signs do not decide
        const auto centroid_exact = [&]() -> const epeck::Point_3& {
          if (!q_exact) {
            ++r.exact_fallbacks;
            q_exact = CGAL::centroid(to_epeck(q[0]), to_epeck(q[1]), to_epeck(q[2]));
          }
          return *q_exact;
        };
        const auto a0 = approx(q[0]), a1 = approx(q[1]), a2 = approx(q[2]);
        const std::array<double, 3> qd{(a0[0] + a1[0] + a2[0]) / 3, (a0[1] + a1[1] + a2[1]) / 3,
                                       (a0[2] + a1[2] + a2[2]) / 3};
        const std::array<double, 3> d{qd[0] - eye_d[0], qd[1] - eye_d[1], qd[2] - eye_d[2]};
        ++r.order_samples;
        bvh.segment_query(eye_d, d, margin, [&](std::uint32_t i) {
          if (i == j || eye_side[i] == 0) return;
          const auto& t = fp[i];
          // q strictly on the other side of i's plane than the eye.
          int sq = combine_signs(static_cast<int>(orientation(t[0], t[1], t[2], q[0])),
                                 static_cast<int>(orientation(t[0], t[1], t[2], q[1])),
                                 static_cast<int>(orientation(t[0], t[1], t[2], q[2])));
          if (sq == 2)
            sq = static_cast<int>(CGAL::orientation(to_epeck(t[0]), to_epeck(t[1]), to_epeck(t[2]), centroid_exact()));
          if (sq != -eye_side[i]) return;
          // The line e q crosses the plane strictly inside triangle i.
          int first = 0;
          for (int u = 0; u < 3; ++u) {
            const P& a = t[u];
            const P& c2 = t[(u + 1) % 3];
            int s = combine_signs(static_cast<int>(orientation(eye, q[0], a, c2)),
                                  static_cast<int>(orientation(eye, q[1], a, c2)),
                                  static_cast<int>(orientation(eye, q[2], a, c2)));
            if (s == 2)
              s = static_cast<int>(CGAL::orientation(eye_exact, centroid_exact(), to_epeck(a), to_epeck(c2)));
            if (s == 0 || (first != 0 && s != first)) return;
            first = s;
          }
          ++r.occluding_pairs;
          if (position[i] < position[j]) ++r.order_errors;
        });
      }
    }
  }
  lap(r.seconds_order);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

template defect_report check_defects<double_kernel>(const bsp_tree<double_kernel>&, const triangle_soup&,
                                                    const defect_options&);
template defect_report check_defects<epick_kernel>(const bsp_tree<epick_kernel>&, const triangle_soup&,
                                                   const defect_options&);
template defect_report check_defects<epeck_kernel>(const bsp_tree<epeck_kernel>&, const triangle_soup&,
                                                   const defect_options&);

}  // namespace exbsp::bench
