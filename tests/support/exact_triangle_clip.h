// SPDX-License-Identifier: LGPL-3.0-or-later
// The tests' oracle for exact clipping and splitting of triangles by planes with a CGAL kernel:
// triangles as points (no shared vertices, no outline), checked against Sutherland–Hodgman in
// test_clip and against the section's pieces in test_section. Test support only, not in the
// library.
//
// Notation (docs/contract.md "The BSP"): a cut plane is three points (a, b, c); its positive side
// is where (b - a) x (c - a) points, i.e. p is on the positive side when
// CGAL::orientation(a, b, c, p) == POSITIVE. Clipping keeps the closed positive side.
// A triangle's vertex signs decide: all 0 -> coplanar (kept, it lies in the closed positive
// side); all >= 0 -> positive; all <= 0 -> negative; otherwise it straddles and is split:
//   - no vertex on the plane: relabel cyclically so c is alone on its side;
//     A = plane ∩ [c, a], B = plane ∩ [b, c]; pieces (a, b, A), (b, B, A) on the a/b side
//     and (A, B, c) on c's side, in that order;
//   - one vertex z on the plane, the other two opposite: relabel cyclically to (z, a, b);
//     X = plane ∩ [a, b]; pieces (z, a, X) on a's side and (z, X, b) on b's side.
// The classification and the split's combinatorics (which new points, which corners per
// piece) are the BSP's own, geom/split_pattern.h, and the cut points are
// geom::plane_segment_intersection's (geom/cut_plane.h): one split for the tree, this oracle
// and sections (clip/section.cpp).
// Pieces keep the parent's orientation. With exact constructions (Epeck, Gmpq) the pieces of
// both sides tile the parent exactly.
//
// The templates are explicitly instantiated once (exact_triangle_clip.cpp) for
// exbsp_test::oracle::epeck and exbsp_test::oracle::gmpq_kernel; other kernels (e.g. Epick)
// instantiate them implicitly.
#pragma once
#include <array>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <exbsp/core/errors.h>
#include "geom/cut_plane.h"
#include "geom/split_pattern.h"

namespace exbsp_test::oracle {

using epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using gmpq_kernel = CGAL::Simple_cartesian<CGAL::Gmpq>;

/// Triangle (v[0], v[1], v[2]) of kernel K; its orientation is its vertex order.
template <class K>
struct exact_triangle {
  std::array<typename K::Point_3, 3> v;
};

/// Oriented cut plane through a, b, c (not collinear); positive side along (b-a) x (c-a).
template <class K>
struct exact_plane {
  typename K::Point_3 a, b, c;
};

/// How a triangle lies with respect to a plane (see the notation above): the BSP's
/// classification (geom/split_pattern.h).
using triangle_plane_side = exbsp::geom::classification;

/// Both sides of a split: `positive` holds the pieces in the closed positive side (and a
/// coplanar triangle), `negative` those in the open negative side, each in piece order.
template <class K>
struct exact_split {
  std::vector<exact_triangle<K>> positive;
  std::vector<exact_triangle<K>> negative;
};

/// Classifies t against the plane by the exact signs of its vertices.
/// Throws usage_error when the plane's points are collinear.
template <class K>
triangle_plane_side classify_triangle(const exact_triangle<K>& t, const exact_plane<K>& plane);

/// The point where segment [p, q] crosses the plane. Precondition: p and q strictly on
/// opposite sides (throws usage_error otherwise, or when the plane's points are collinear).
/// Computed from the lexicographically smaller endpoint, so [p, q] and [q, p] agree even
/// with a rounding kernel.
template <class K>
typename K::Point_3 plane_segment_intersection(const exact_plane<K>& plane,
                                               const typename K::Point_3& p,
                                               const typename K::Point_3& q);

/// Splits t by the plane into the pieces on each side (section 3 piece convention).
/// A triangle not straddling goes whole to its side (coplanar: positive).
/// Throws usage_error when the plane's points are collinear.
template <class K>
exact_split<K> split_triangle(const exact_triangle<K>& t, const exact_plane<K>& plane);

/// The part of t in the closed positive side of the plane, as triangles with t's
/// orientation (empty when t is entirely on the negative side).
/// Throws usage_error when the plane's points are collinear.
template <class K>
std::vector<exact_triangle<K>> clip_triangle(const exact_triangle<K>& t,
                                             const exact_plane<K>& plane);

/// The part of t in the convex region = intersection of the closed positive sides of all
/// planes, as triangles with t's orientation; planes are applied in order. No planes: {t}.
/// Throws usage_error when a plane's points are collinear.
template <class K>
std::vector<exact_triangle<K>> clip_triangle(const exact_triangle<K>& t,
                                             const std::vector<exact_plane<K>>& planes);

// ---------------------------------------------------------------------------------------
// Definitions. s[i] is the sign (+1, 0, -1) of vertex i of the triangle.
namespace detail {

template <class K>
void require_plane(const exact_plane<K>& plane, const char* function) {
  if (CGAL::collinear(plane.a, plane.b, plane.c))
    throw exbsp::usage_error(std::string(function) + ": the three plane points are collinear");
}

template <class K>
typename exbsp::geom::cut_plane_traits<K>::Plane_3 points_of(const exact_plane<K>& plane) {
  return {plane.a, plane.b, plane.c};
}

template <class K>
int side_of(const exact_plane<K>& plane, const typename K::Point_3& p) {
  return exbsp::geom::cut_plane_traits<K>().oriented_side_3_object()(points_of(plane), p);
}

template <class K>
typename K::Point_3 crossing_unchecked(const exact_plane<K>& plane, const typename K::Point_3& p,
                                       const typename K::Point_3& q) {
  return exbsp::geom::plane_segment_intersection<K>(points_of(plane), p, q);
}

template <class K>
exact_split<K> split_unchecked(const exact_triangle<K>& t, const exact_plane<K>& plane) {
  const std::array<int, 3> s{side_of(plane, t.v[0]), side_of(plane, t.v[1]),
                             side_of(plane, t.v[2])};
  exact_split<K> out;
  switch (exbsp::geom::classify_signs(s)) {
    case triangle_plane_side::coplanar:
    case triangle_plane_side::positive:
      out.positive.push_back(t);
      return out;
    case triangle_plane_side::negative:
      out.negative.push_back(t);
      return out;
    case triangle_plane_side::straddling:
      break;
  }
  using point = typename K::Point_3;
  exbsp::geom::apply_split(
      exbsp::geom::make_split_pattern(s), t.v,
      [&](const point& p, const point& q) { return crossing_unchecked(plane, p, q); },
      [&](int side, const std::array<point, 3>& piece) {
        (side > 0 ? out.positive : out.negative).push_back(exact_triangle<K>{piece});
      });
  return out;
}

}  // namespace detail

template <class K>
triangle_plane_side classify_triangle(const exact_triangle<K>& t, const exact_plane<K>& plane) {
  detail::require_plane(plane, "classify_triangle");
  return exbsp::geom::classify_signs({detail::side_of(plane, t.v[0]),
                                      detail::side_of(plane, t.v[1]),
                                      detail::side_of(plane, t.v[2])});
}

template <class K>
typename K::Point_3 plane_segment_intersection(const exact_plane<K>& plane,
                                               const typename K::Point_3& p,
                                               const typename K::Point_3& q) {
  detail::require_plane(plane, "plane_segment_intersection");
  if (detail::side_of(plane, p) * detail::side_of(plane, q) >= 0)
    throw exbsp::usage_error(
        "plane_segment_intersection: the endpoints are not strictly on opposite sides");
  return detail::crossing_unchecked(plane, p, q);
}

template <class K>
exact_split<K> split_triangle(const exact_triangle<K>& t, const exact_plane<K>& plane) {
  detail::require_plane(plane, "split_triangle");
  return detail::split_unchecked(t, plane);
}

template <class K>
std::vector<exact_triangle<K>> clip_triangle(const exact_triangle<K>& t,
                                             const exact_plane<K>& plane) {
  detail::require_plane(plane, "clip_triangle");
  return detail::split_unchecked(t, plane).positive;
}

template <class K>
std::vector<exact_triangle<K>> clip_triangle(const exact_triangle<K>& t,
                                             const std::vector<exact_plane<K>>& planes) {
  for (const auto& plane : planes) detail::require_plane(plane, "clip_triangle");
  std::vector<exact_triangle<K>> kept{t}, next;
  for (const auto& plane : planes) {
    next.clear();
    for (const auto& piece : kept) {
      auto pieces = detail::split_unchecked(piece, plane).positive;
      next.insert(next.end(), pieces.begin(), pieces.end());
    }
    kept.swap(next);
    if (kept.empty()) break;
  }
  return kept;
}

// Compiled once in exact_triangle_clip.cpp for the two exact kernels.
#define EXBSP_CLIP_EXACT_TEMPLATES(PREFIX, K)                                                     \
  PREFIX template triangle_plane_side classify_triangle<K>(const exact_triangle<K>&,              \
                                                           const exact_plane<K>&);                \
  PREFIX template K::Point_3 plane_segment_intersection<K>(const exact_plane<K>&,                 \
                                                           const K::Point_3&, const K::Point_3&); \
  PREFIX template exact_split<K> split_triangle<K>(const exact_triangle<K>&,                      \
                                                   const exact_plane<K>&);                        \
  PREFIX template std::vector<exact_triangle<K>> clip_triangle<K>(const exact_triangle<K>&,       \
                                                                  const exact_plane<K>&);         \
  PREFIX template std::vector<exact_triangle<K>> clip_triangle<K>(                                \
      const exact_triangle<K>&, const std::vector<exact_plane<K>>&);

EXBSP_CLIP_EXACT_TEMPLATES(extern, epeck)
EXBSP_CLIP_EXACT_TEMPLATES(extern, gmpq_kernel)

}  // namespace exbsp_test::oracle
