// Exact defect counts of a built tree: how far an inexact kernel's tree is from the exact
// contract (DESIGN.md section 3). No epsilon anywhere: every test is exact.
//
// Notation: a fragment is a triangle (p0, p1, p2) stored in the tree with its source input
// triangle (a, b, c); orient(a, b, c, p) = sign of det[b - a, c - a, p - a]. Inexact kernels
// (double, Epick) store double coordinates; they are taken exactly as they are (a double is
// a rational) and
//   - signs of orient on double points use CGAL's Epick predicates, which are exact on
//     double input (static and interval filters, exact multiprecision fallback);
//   - signs at a rational point (a centroid) use that orient(...) is affine in each point:
//     orient(.., (p0+p1+p2)/3) has the sign of orient(.., p0) + orient(.., p1) +
//     orient(.., p2), which the three exact signs decide unless two are opposite; then the
//     centroid is constructed in Epeck and the predicate evaluated there (exactly);
//   - sums of cross products use GMP rationals (mpq_class), exactly.
// The Epeck tree is checked the same way on its own exact points (it must have 0 defects:
// a control of the checker).
//
// Defects:
//   non_finite      fragments with an infinite or NaN coordinate (a rounded construction that
//                   divided by a rounded zero); left out of the other checks.
//   off_plane       fragments with a vertex not in the plane of their source triangle.
//   not_tiling      split source triangles whose fragments' exact sum of cross products
//                   sum (q1 - q0) x (q2 - q0) differs from the source's (b - a) x (c - a).
//   misclassified   fragments with a vertex strictly on the wrong side of the plane of an
//                   ancestor node (the closed side they were sent to is violated).
//   order errors    for each sampled eye e and each sampled fragment j with centroid q:
//                   every fragment i that the segment [e, q] crosses strictly inside i, with
//                   e and q strictly on opposite sides of i's plane, hides part of j; the
//                   pair is "occluding", and it is an ORDER ERROR when the back-to-front
//                   order draws i before j (j then paints over i at q).
//   Candidates i for a segment come from a bounding-volume hierarchy whose boxes are
//   widened by a margin (1e-9 of the scene size): that only selects candidates (it can
//   select more, never fewer); the decision for each candidate is the exact test above.
#pragma once
#include <cstddef>
#include <cstdint>

#include "bsp/bsp_tree.h"
#include "bsp/geometry_cgal.h"
#include "mesh/soup.h"

namespace exbsp::bench {

struct defect_options {
  bool order = true;              ///< run the order check
  std::size_t eyes = 4;           ///< eyes at fixed directions, 2 diagonals from the centre
  std::size_t samples = 20000;    ///< sampled fragments j per eye (0: all)
  std::size_t exact_samples = 2000; ///< the same for the exact (control) kernel, whose points are slower
};

struct defect_report {
  std::size_t fragments = 0;
  std::size_t non_finite = 0;     ///< fragments with an infinite or NaN coordinate (rounded division)
  std::size_t off_plane = 0;
  std::size_t split_sources = 0;  ///< sources with >= 2 fragments (the ones tiling is checked on)
  std::size_t not_tiling = 0;
  std::size_t misclassified = 0;
  std::size_t ancestor_tests = 0; ///< (fragment, ancestor) pairs checked
  std::size_t eyes = 0;
  std::size_t order_samples = 0;  ///< sampled (eye, fragment) points
  std::size_t occluding_pairs = 0;
  std::size_t order_errors = 0;
  std::size_t exact_fallbacks = 0;///< centroid signs that needed an Epeck construction
  double seconds = 0;              ///< whole check
  double seconds_plane = 0, seconds_tiling = 0, seconds_classification = 0, seconds_order = 0;
};

/// Checks a tree built from `soup`. Defined for double_kernel, epick_kernel, epeck_kernel.
template <class K>
defect_report check_defects(const bsp_tree<K>& tree, const triangle_soup& soup, const defect_options& options);

}  // namespace exbsp::bench
