// SPDX-License-Identifier: LGPL-3.0-or-later
// Plane ∩ segment for a CGAL kernel K, the one construction the tree (bsp/geometry_cgal.h),
// the section (clip/section.cpp) and the clipping oracle of the tests share. In the style of
// CGAL's cut-plane traits (Polygon_mesh_processing's Three_point_cut_plane_traits): a functor
// per job, got from the traits object.
//
// Notation: a cut plane is three points (a, b, c) with normal n = (b - a) x (c - a), positive
// side where n points (docs/contract.md, the BSP), or CGAL's K::Plane_3 (coefficients A, B,
// C, D: a section plane). f is the plane's affine function, n . (x - a) or A x + B y + C z + D.
// For p and q with fp = f(p) != fq = f(q) the crossing of the line (p, q) is
//   X = p + fp / (fp - fq) (q - p)          any kernel, evaluated in this order;
//   X = (fp q - fq p) / (fp - fq)           Epeck: on the exact values, wrapped as a one-level
//                                           lazy point (no DAG of a dozen lazy nodes).
// With an exact kernel both are the same point whichever end is p. With a rounding kernel
// (Epick, double) the first depends on it: plane_segment_intersection takes the ends in
// lexicographic order, so [p, q] and [q, p] agree; the tree calls the construction itself
// with the ends in the split pattern's order (split_pattern.h), which its rounded trees keep.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <type_traits>

namespace exbsp::geom {

template <class K>
struct cut_plane_traits {
  using FT = typename K::FT;
  using Point_3 = typename K::Point_3;
  using Vector_3 = typename K::Vector_3;
  /// A cut plane through three points (notation).
  using Plane_3 = std::array<Point_3, 3>;

  /// n = (b - a) x (c - a).
  struct Construct_normal_3 {
    Vector_3 operator()(const Plane_3& h) const {
      return CGAL::cross_product(h[1] - h[0], h[2] - h[0]);
    }
  };

  /// The side of p as -1, 0 or +1 (+1 where the normal points).
  struct Oriented_side_3 {
    int operator()(const Plane_3& h, const Point_3& p) const {
      return static_cast<int>(CGAL::orientation(h[0], h[1], h[2], p));
    }
    int operator()(const typename K::Plane_3& h, const Point_3& p) const {
      return static_cast<int>(h.oriented_side(p));
    }
  };

  /// The point where the line (p, q) crosses the plane, computed from p (notation).
  /// Precondition: f(p) != f(q).
  struct Construct_plane_line_intersection_point_3 {
    /// The plane through a with normal n (a caller cutting many segments makes n once).
    Point_3 operator()(const Point_3& a, const Vector_3& n, const Point_3& p,
                       const Point_3& q) const {
      if constexpr (lazy_exact) {
        using ET = typename K::Exact_kernel::FT;
        const auto& ea = CGAL::exact(a);
        const auto& en = CGAL::exact(n);
        const auto& ep = CGAL::exact(p);
        const auto& eq = CGAL::exact(q);
        const ET fp = en * (ep - ea);
        const ET fq = en * (eq - ea);
        return from_exact_values(fp, fq, ep, eq);
      } else {
        return from_values(n * (p - a), n * (q - a), p, q);
      }
    }
    Point_3 operator()(const Plane_3& h, const Point_3& p, const Point_3& q) const {
      return (*this)(h[0], Construct_normal_3()(h), p, q);
    }
    Point_3 operator()(const typename K::Plane_3& h, const Point_3& p, const Point_3& q) const {
      if constexpr (lazy_exact) {
        using ET = typename K::Exact_kernel::FT;
        const auto& eh = CGAL::exact(h);
        const auto& ep = CGAL::exact(p);
        const auto& eq = CGAL::exact(q);
        const ET fp = eh.a() * ep.x() + eh.b() * ep.y() + eh.c() * ep.z() + eh.d();
        const ET fq = eh.a() * eq.x() + eh.b() * eq.y() + eh.c() * eq.z() + eh.d();
        return from_exact_values(fp, fq, ep, eq);
      } else {
        const FT fp = h.a() * p.x() + h.b() * p.y() + h.c() * p.z() + h.d();
        const FT fq = h.a() * q.x() + h.b() * q.y() + h.c() * q.z() + h.d();
        return from_values(fp, fq, p, q);
      }
    }
  };

  Construct_normal_3 construct_normal_3_object() const { return {}; }
  Oriented_side_3 oriented_side_3_object() const { return {}; }
  Construct_plane_line_intersection_point_3 construct_plane_line_intersection_point_3_object()
      const {
    return {};
  }

 private:
  /// Epeck: the construction runs on the exact values.
  static constexpr bool lazy_exact =
      std::is_same_v<K, CGAL::Exact_predicates_exact_constructions_kernel>;

  static Point_3 from_values(const FT& fp, const FT& fq, const Point_3& p, const Point_3& q) {
    const FT t = fp / (fp - fq);
    return p + t * (q - p);
  }
  template <class ET, class EP>
  static Point_3 from_exact_values(const ET& fp, const ET& fq, const EP& p, const EP& q) {
    const ET den = fp - fq;
    const ET x = (fp * q.x() - fq * p.x()) / den;
    const ET y = (fp * q.y() - fq * p.y()) / den;
    const ET z = (fp * q.z() - fq * p.z()) / den;
    return {FT(x), FT(y), FT(z)};
  }
};

/// The point where segment [p, q] crosses the plane h (three points or a K::Plane_3),
/// computed from the lexicographically smaller end (CGAL::compare_xyz), so that [p, q] and
/// [q, p] give the same point with any kernel. Precondition: p and q strictly on opposite
/// sides of h.
template <class K, class Plane>
typename K::Point_3 plane_segment_intersection(const Plane& h, const typename K::Point_3& p,
                                               const typename K::Point_3& q) {
  const bool swap = CGAL::compare_xyz(q, p) == CGAL::SMALLER;
  return cut_plane_traits<K>().construct_plane_line_intersection_point_3_object()(h, swap ? q : p,
                                                                                  swap ? p : q);
}

}  // namespace exbsp::geom
