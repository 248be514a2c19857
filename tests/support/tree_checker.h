// SPDX-License-Identifier: LGPL-3.0-or-later
// The exact invariant checker of BSP trees, shared by the tests (tests/test_properties.cpp,
// test_degenerate.cpp: every invariant of tests/HARD_CASES.md must hold) and the benchmarks
// (bench/defects.cpp: how many items an inexact kernel's tree breaks). Compiled once, in
// tree_checker.cpp, for the CGAL kernels double, Epick, Epeck and Gmpq.
//
// Notation (docs/contract.md "The BSP"): triangle (a,b,c), normal n = (b-a)x(c-a), f(p) = sign of
// orientation(a,b,c,p). A "view" is a copy of a built tree in an exact kernel E: for the exact
// kernels (Epeck, Gmpq) E is the kernel itself and nothing is converted; for the inexact ones
// (double, Epick) the rounded output is converted exactly into Epeck, so every invariant is
// always evaluated exactly and an inexact kernel "breaks" an invariant when its rounded
// fragments really violate it. No epsilon anywhere: the one tolerance, in the order check,
// only widens the boxes that select candidate fragments for a ray (more candidates, never
// fewer); every decision is exact.
//
// The checker never draws from RapidCheck: it takes explicit seeds.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/mesh/soup.h>
#include "bsp/bsp_tree.h"
#include "bsp/geometry_cgal.h"
#include "bsp/kernel_double.h"
#include "bsp/kernel_epeck.h"
#include "bsp/kernel_epick.h"
#include "bsp/kernel_gmpq.h"

namespace exbsp_test {

using exbsp::vec3d;

/// Broken invariants by name (with the number of broken items), and the first few messages.
struct check_report {
  std::map<std::string, std::size_t> broken;
  std::vector<std::string> messages;
  void fail(const std::string& invariant, const std::string& message);
  bool ok() const { return broken.empty(); }
  /// Items that broke `invariant` (0 when it held).
  std::size_t count(const std::string& invariant) const;
  std::string text() const;
};

/// The kernel a tree of kernel K is checked in: K itself when exact, else Epeck.
template <class K>
using exact_kernel_of = std::conditional_t<exbsp::kernel_traits<K>::exact, K, exbsp::epeck_kernel>;

/// A built tree copied into the exact kernel E.
template <class E>
struct tree_view {
  using point = typename E::Point_3;
  using triangle = std::array<point, 3>;
  struct node {
    std::uint32_t plane_source, first, count;
    std::int32_t negative, positive, parent, side_in_parent;
    std::uint32_t depth;
  };
  std::vector<triangle> fragments;
  std::vector<char> finite;  ///< false: a coordinate was NaN/Inf (inexact kernels)
  std::vector<std::uint32_t> source, face;
  std::vector<std::size_t> node_of;  ///< as the tree reports it (node_of_fragment)
  std::vector<node> nodes;
  std::vector<triangle> sources;  ///< input triangles, exact doubles from the soup
  std::vector<std::uint32_t> source_face;
  std::vector<char> degenerate;  ///< exactly collinear input, computed here
  exbsp::build_stats stats;
  std::size_t nonfinite = 0;
};

template <class E>
typename E::Point_3 exact_point(const vec3d& p) {
  return typename E::Point_3(p[0], p[1], p[2]);
}

template <class E>
typename E::Vector_3 normal_of(const std::array<typename E::Point_3, 3>& t) {
  return CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
}

/// The tree of kernel K copied into E = exact_kernel_of<K> (K's own points when exact,
/// rounded doubles taken exactly otherwise).
template <class E, class K>
tree_view<E> view_of(const exbsp::bsp_tree<K>& t, const exbsp::triangle_soup& soup);

/// Node array, parent/child links, depths, contiguous fragment ranges, node_of_fragment,
/// face ids, and the splitter of each node stored at it ("structure").
template <class E>
void check_structure(const tree_view<E>& v, check_report& r);

/// Fragments lie in their source's plane ("source_plane", one per fragment) with the same
/// orientation ("orientation").
template <class E>
void check_source_planes(const tree_view<E>& v, check_report& r);

/// The fragments of each source tile it exactly: their normals sum to the source's
/// ("tiling_area", one per source), every vertex is in the closed source triangle
/// ("inside_source") and, when `pairwise`, no two have overlapping interiors ("overlap";
/// quadratic in the fragments of a source). Same area, inside and disjoint interiors: they
/// cover it, no gaps and no overlaps. Sources with a non-finite fragment are skipped.
template <class E>
void check_tiling(const tree_view<E>& v, check_report& r, bool pairwise = true);

/// Each fragment lies in its node's plane ("node_plane"), on the closed side side_in_parent
/// of every ancestor's plane ("ancestor_side": a vertex strictly on the wrong side of one) and
/// strictly off each ancestor's plane somewhere ("ancestor_plane": else it would have been
/// stored there). Each is counted once per fragment.
template <class E>
void check_node_planes(const tree_view<E>& v, check_report& r);

/// Statistics against the tree and the input ("stats"). `expected_heuristic` empty: not checked.
template <class E>
void check_stats(const tree_view<E>& v, const std::string& expected_kernel,
                 const std::string& expected_heuristic, check_report& r);

/// An eye point or a direction of projection (from the eye into the scene).
template <class E>
struct viewpoint {
  bool is_eye = true;
  typename E::Point_3 eye;
  typename E::Vector_3 direction;
  std::string what;
};

/// What the order check along rays saw.
struct order_tally {
  std::size_t rays = 0;        ///< sample rays cast
  std::size_t pairs = 0;       ///< pairs of fragments crossed by one ray at different depths
  std::size_t misordered = 0;  ///< of those, the pairs drawn in the wrong order ("order")
};

/// Exact visibility check of a back-to-front order along rays: for the ray from the eye
/// through sample points of the fragments (or the line through them along the direction of
/// projection), every fragment whose interior the ray crosses strictly in front of the eye is
/// found with its exact ray parameter; a pair of them at different depths is misordered
/// when the nearer one is drawn first. At most max_rays sample points (4 per fragment while
/// that fits, else the centroids of a stride; 0: 4 per fragment). Candidates for a ray come
/// from a hierarchy of double boxes widened by a bound on the rounding of the ray, so no
/// fragment the ray crosses is ever missed, and interval signs reject most of them before the
/// exact test (`prune` false: every fragment is a candidate, for testing the pruning).
template <class E>
order_tally check_order_along_rays(const tree_view<E>& v, const viewpoint<E>& vp,
                                   const std::vector<std::uint32_t>& order, std::size_t max_rays,
                                   check_report& r, bool prune = true);

/// Viewpoints for a view: a random eye, an eye exactly on a node's plane (outside its
/// triangle), an eye at a fragment vertex (a split point: on several planes), an eye at an
/// input vertex, a random direction and a direction parallel to a node's plane.
template <class E>
std::vector<viewpoint<E>> standard_viewpoints(const tree_view<E>& v, std::uint64_t seed);

/// The tree's own order for a viewpoint; for inexact kernels the viewpoint's coordinates are
/// rounded to double first.
template <class K, class E>
std::vector<std::uint32_t> tree_order(const exbsp::bsp_tree<K>& t, const viewpoint<E>& vp,
                                      bool back_to_front = true);

/// All order checks for one viewpoint: a permutation, the contract's traversal, front-to-back
/// is the exact reverse, and the exact ray check. `v` may be the tree's view scaled by 2^k
/// (see check_tree); the tree itself is asked with the unscaled viewpoint.
template <class K, class E>
void check_orders(const exbsp::bsp_tree<K>& t, const tree_view<E>& v, viewpoint<E> vp,
                  std::size_t max_rays, check_report& r, int k = 0);

/// Options of a full check.
struct check_options {
  std::uint64_t seed = 1;               ///< viewpoints
  std::size_t max_rays = 160;           ///< sample rays per viewpoint
  std::size_t viewpoints = 6;           ///< at most this many of standard_viewpoints
  std::string heuristic;                ///< expected in the stats (empty: not checked)
  std::vector<vec3d> eyes, directions;  ///< extra viewpoints, checked after the standard ones
};

/// Every invariant of tests/HARD_CASES.md for a built tree; the report says which broke.
template <class K>
check_report check_tree(const exbsp::bsp_tree<K>& t, const exbsp::triangle_soup& soup,
                        const check_options& o);

}  // namespace exbsp_test
