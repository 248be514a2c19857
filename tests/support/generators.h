// SPDX-License-Identifier: LGPL-3.0-or-later
// RapidCheck generators of triangle soups (tests/HARD_CASES.md says what each is for and
// what each invariant of the checker proves), the CAD corpus cases, and the glue that builds
// a generated soup with every heuristic and fails the property on any broken invariant
// (the checker itself: tree_checker.h).
//
// Notation (docs/contract.md "The BSP"): triangle (a,b,c), normal n = (b-a)x(c-a). Generators and
// pick_* must be dereferenced inside a RapidCheck generation context (a property or
// rc::gen::exec).
#pragma once
#include <rapidcheck.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "support/observable.h"
#include "support/tree_checker.h"

namespace exbsp_test {

using tri_d = std::array<vec3d, 3>;

// --- soups as generated values -----------------------------------------------------------------

/// A generated soup: its generator's name, the triangles (doubles, the exact input) and
/// optional face ids (empty: face id = triangle index).
struct soup_case {
  std::string kind;
  std::vector<tri_d> tris;
  std::vector<std::uint32_t> faces;

  std::uint32_t face_of(std::size_t i) const {
    return faces.empty() ? static_cast<std::uint32_t>(i) : faces[i];
  }
  exbsp::triangle_soup soup() const;
};

/// The case as an OFF file (reading it back gives the same doubles).
std::string to_off(const soup_case& c);

/// How RapidCheck prints a counterexample: reproducible as an OFF file.
void showValue(const soup_case& c, std::ostream& os);

inline soup_case case_of(const std::string& kind, const std::vector<tri_d>& tris) {
  return soup_case{kind, tris, {}};
}

inline tri_d flipped(const tri_d& t) { return {t[0], t[2], t[1]}; }

/// x moved by k ulps (k > 0 up, k < 0 down).
inline double ulps_from(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

// --- drawing values (only inside a RapidCheck generation context) -------------------------------

inline int pick_int(int lo, int hi) { return *rc::gen::inRange(lo, hi + 1); }
inline bool pick_bool() { return pick_int(0, 1) == 1; }
/// A double in [lo, hi] with (up to) 52 random mantissa bits: generic position.
inline double pick_real(double lo, double hi) {
  const std::int64_t k = *rc::gen::inRange<std::int64_t>(0, (std::int64_t{1} << 52) + 1);
  return lo + (hi - lo) * std::ldexp(static_cast<double>(k), -52);
}
inline vec3d pick_point(double lo, double hi) {
  return {pick_real(lo, hi), pick_real(lo, hi), pick_real(lo, hi)};
}
/// k/2 for an integer k in [2*lo, 2*hi]: exact, and exactly representable sums and products.
inline double pick_half(int lo, int hi) { return pick_int(2 * lo, 2 * hi) / 2.0; }

template <class T>
void shuffle_picked(std::vector<T>& v) {
  for (std::size_t i = v.size(); i > 1; --i) {
    const std::size_t j = *rc::gen::inRange<std::size_t>(0, i);
    std::swap(v[i - 1], v[j]);
  }
}

// --- generators ----------------------------------------------------------------------------------

/// Generic random soups: 1..max_triangles triangles with 52-bit random coordinates in [-10,10].
rc::Gen<soup_case> random_soup(int max_triangles = 8);
/// Soups on the 5x5x5 lattice {-1, -0.5, 0, 0.5, 1}^3: exact coincidences of every kind
/// (shared vertices and edges, vertices on planes, coplanar and collinear triangles).
rc::Gen<soup_case> grid_soup(int max_triangles = 10);
/// Overlapping coplanar triangles in both orientations on one lattice plane (duplicates and
/// reversed copies included) and crossers of every kind (straddling, a vertex on the plane,
/// touching with a vertex or an edge, parallel), shuffled.
rc::Gen<soup_case> coplanar_stack();
/// Vertices exactly on other triangles' planes (on 0..3 axis planes, their lines and common
/// point, and on a sloped lattice plane).
rc::Gen<soup_case> vertex_on_plane();
/// Triangles in a plane z = h, x = h or y = x and triangles 0, 1 or 2 ulps off it (subnormal
/// offsets for h = 0).
rc::Gen<soup_case> near_coplanar();
/// Scale disparity: coordinates near 1e9 with 1e-3 features and huge triangles, coordinates
/// near 1e-300 (products underflow), unit triangles crossed by 1e-300 ones.
rc::Gen<soup_case> scale_disparity();
/// Needles, caps and thin isosceles triangles (relative widths 1e-3 .. 1e-15) crossing each
/// other; sometimes an exactly collinear triangle.
rc::Gen<soup_case> slivers();
/// Integer height fields with T-junctions, exact duplicates, reversed copies, a crossing
/// sheet and lattice crossers.
rc::Gen<soup_case> mesh_like();
/// Pinwheels of n sticks rising around the z axis: true depth cycles seen from above.
rc::Gen<soup_case> cyclic_sticks(int min_n = 3, int max_n = 8);
/// Every small generator above (not the sticks): for properties that hold for any soup.
rc::Gen<soup_case> any_small_soup();

// --- the CGAL corpus -----------------------------------------------------------------------------

/// The triangles and face ids of data/meshes/NAME (read once), or nullptr if it is missing.
const soup_case* cad_mesh(const std::string& name);
/// The CAD meshes of the corpus used by the subset generators, those present.
std::vector<std::string> present_cad_meshes();
/// A contiguous run of at most max_triangles triangles of one of `files` (all present), with
/// a random rigid motion: exact (axis permutation, reflections, power-of-two scale) or rounded
/// (a random rotation and translation in double). Face ids are the file's.
rc::Gen<soup_case> cad_subset(std::vector<std::string> files, std::size_t max_triangles);

// --- building and checking -----------------------------------------------------------------------

/// Builds the tree of `c` with `heuristic` in kernel K and checks it.
template <class K>
check_report build_and_check(const soup_case& c, const std::string& heuristic,
                             const check_options& o, std::uint64_t build_seed = 0);

/// Inside a RapidCheck property: builds `c` with every heuristic in kernel K (the build seed
/// and the viewpoints drawn from RapidCheck) and fails the property on any broken invariant.
/// Tags the case with its generator and whether the tree needed splits.
template <class K>
void rc_assert_invariants_for_every_heuristic(const soup_case& c, std::size_t max_rays = 160,
                                              const check_options& extra = {});

}  // namespace exbsp_test
