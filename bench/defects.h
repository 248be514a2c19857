// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact defect counts of a built tree: how far an inexact kernel's tree is from the exact
// contract (docs/contract.md "The BSP"). The checks are the tests' exact tree checker
// (tests/support/tree_checker.h), run on large trees: the tree is copied exactly into Epeck
// (a double is a rational), every test is exact, no epsilon anywhere. The Epeck tree is
// checked the same way (it must have 0 defects: a control of the checker).
//
// Defects (the checker's invariant names in brackets):
//   non_finite      fragments with an infinite or NaN coordinate (a rounded construction that
//                   divided by a rounded zero); left out of the other checks.
//   off_plane       fragments with a vertex not in the plane of their source triangle
//                   [source_plane].
//   not_tiling      sources whose fragments' normals (q1 - q0) x (q2 - q0) do not sum exactly
//                   to the source's (b - a) x (c - a) [tiling_area]; counted over the split
//                   sources (>= 2 fragments) with finite fragments.
//   misclassified   fragments with a vertex strictly on the wrong side of the plane of an
//                   ancestor node: the closed side they were sent to is violated [ancestor_side].
//   order errors    for each eye and each sampled point q (fragment centroids of a stride),
//                   the ray from the eye through q is intersected exactly with every fragment
//                   it crosses inside; each pair of fragments crossed at different depths is an
//                   "occluding pair" (the nearer hides the farther there), and an ORDER ERROR
//                   when the back-to-front order draws the nearer one first [order].
#pragma once
#include <cstddef>
#include <cstdint>

#include <exbsp/mesh/soup.h>
#include "bsp/bsp_tree.h"
#include "bsp/geometry_cgal.h"

namespace exbsp::bench {

struct defect_options {
  bool order = true;                 ///< run the order check
  std::size_t eyes = 4;              ///< eyes at fixed directions, 2 diagonals from the centre
  std::size_t samples = 20000;       ///< sample rays per eye (0: every fragment's centroid)
  std::size_t exact_samples = 2000;  ///< the same for the exact (control) kernel
};

struct defect_report {
  std::size_t fragments = 0;
  std::size_t non_finite = 0;  ///< fragments with an infinite or NaN coordinate (rounded division)
  std::size_t off_plane = 0;
  std::size_t split_sources = 0;  ///< sources with >= 2 fragments (the ones tiling is checked on)
  std::size_t not_tiling = 0;
  std::size_t misclassified = 0;
  std::size_t ancestor_tests = 0;  ///< (fragment, ancestor) pairs checked
  std::size_t eyes = 0;
  std::size_t order_samples = 0;  ///< sample rays over all eyes
  std::size_t occluding_pairs = 0;
  std::size_t order_errors = 0;
  double seconds = 0;  ///< whole check, the exact copy of the tree included
  double seconds_plane = 0, seconds_tiling = 0, seconds_classification = 0, seconds_order = 0;
};

/// Checks a tree built from `soup`. Defined for double_kernel, epick_kernel, epeck_kernel.
template <class K>
defect_report check_defects(const bsp_tree<K>& tree, const triangle_soup& soup,
                            const defect_options& options);

}  // namespace exbsp::bench
