// SPDX-License-Identifier: LGPL-3.0-or-later
// The BSP's geometry for a CGAL kernel K (epeck, gmpq, epick, double): fragments hold K
// points, side tests are K's orientation predicate behind the certified double filter
// (fast_orientation.h) where the kernel allows it, split points are K constructions.
//
// A geometry is what bsp_tree<G> asks of its number type (see geometry_exact.h for the other
// one): a fragment type with .source and .face, add_source, sign, split, side_of_eye,
// side_of_direction, to_double, visit_exact, and a per-subtree scratch object.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include <exbsp/core/errors.h>
#include "bsp/exact_output.h"
#include "bsp/fast_orientation.h"
#include "bsp/kernel_traits.h"
#include "bsp/tree_file.h"
#include "geom/cut_plane.h"
#include "geom/split_pattern.h"

namespace exbsp {
namespace detail {

/// The point where [p,q] meets the plane through `a` with normal n (n = (b-a)x(c-a)),
/// computed from p (geom/cut_plane.h), then collapsed (Epeck: the lazy DAG pruned).
template <class K>
typename K::Point_3 intersect_with_normal(const typename K::Point_3& a,
                                          const typename K::Vector_3& n,
                                          const typename K::Point_3& p,
                                          const typename K::Point_3& q) {
  typename K::Point_3 x =
      geom::cut_plane_traits<K>().construct_plane_line_intersection_point_3_object()(a, n, p, q);
  kernel_traits<K>::collapse(x);
  return x;
}

}  // namespace detail

/// Up to three pieces of a split triangle, in the contract's order, each with its side.
template <class K>
struct split_pieces {
  std::array<std::array<typename K::Point_3, 3>, 3> piece;
  std::array<int, 3> side{};  ///< +1 or -1 for each piece
  int count = 0;              ///< 2 (vertex on plane) or 3
};

/// Splits triangle t that straddles `plane` (three points; signs s of t's vertices against
/// it) by the section 3 convention (geom/split_pattern.h). Pieces keep t's orientation.
/// Precondition: classify_signs(s) == straddling (throws usage_error otherwise).
template <class K>
split_pieces<K> split_triangle(const std::array<typename K::Point_3, 3>& plane,
                               const std::array<typename K::Point_3, 3>& t,
                               const std::array<int, 3>& s) {
  if (geom::classify_signs(s) != geom::classification::straddling)
    throw usage_error("split_triangle: the triangle does not straddle the plane");
  using point = typename K::Point_3;
  const auto n = geom::cut_plane_traits<K>().construct_normal_3_object()(plane);
  split_pieces<K> out;
  geom::apply_split(
      geom::make_split_pattern(s), t,
      [&](const point& p, const point& q) {
        return detail::intersect_with_normal<K>(plane[0], n, p, q);
      },
      [&](int side, const std::array<point, 3>& piece) {
        out.side[out.count] = side;
        out.piece[out.count++] = piece;
      });
  return out;
}

template <class K>
class cgal_geometry {
 public:
  using point = typename K::Point_3;
  using vector = typename K::Vector_3;
  using triangle = std::array<point, 3>;
  static constexpr kernel_id id = kernel_traits<K>::id;
  static constexpr bool exact = kernel_traits<K>::exact;

  /// A triangle stored in the tree: its vertices (with double approximations where known),
  /// the index of its source input triangle and its face id.
  struct fragment {
    triangle v;
    std::array<vec3d, 3> d;    ///< double approximations of the vertices flagged in double_mask
    std::array<double, 3> r;   ///< vertex k lies within r[k] (max norm) of d[k]; 0: exactly d[k]
    std::uint8_t double_mask;  ///< bit k: d[k], r[k] are valid
    std::uint32_t source;
    std::uint32_t face;
  };
  /// Per-subtree state: the normal of the plane being split by, computed once per node.
  struct scratch {
    std::uint32_t plane = ~0u;
    std::optional<vector> normal;
  };

  explicit cgal_geometry(const triangle_soup& soup) {
    sources_.resize(soup.triangles.size());
    source_doubles_.resize(soup.triangles.size());
    fast_.resize(soup.triangles.size());
  }

  /// The three input points of triangle `plane`, the input's doubles (-0 included, which the
  /// exact kernels' numbers do not keep).
  const std::array<vec3d, 3>& source_points(std::uint32_t plane) const {
    return source_doubles_[plane];
  }

  /// Records input triangle i of `soup`; returns false (and no fragment) when it is exactly
  /// degenerate.
  bool add_source(const triangle_soup& soup, std::uint32_t i, fragment& out) {
    const soup_triangle& st = soup.triangles[i];
    const vec3d& a = soup.vertices.at(st.v[0]);
    const vec3d& b = soup.vertices.at(st.v[1]);
    const vec3d& c = soup.vertices.at(st.v[2]);
    for (int k = 0; k < 3; ++k) {
      const vec3d& v = soup.vertices[st.v[k]];
      sources_[i][k] = point(v[0], v[1], v[2]);
      source_doubles_[i][static_cast<std::size_t>(k)] = v;
    }
    // Epick's collinear predicate is exact on double input: every kernel skips the same ones.
    using E = CGAL::Epick;
    if (E().collinear_3_object()(E::Point_3(a[0], a[1], a[2]), E::Point_3(b[0], b[1], b[2]),
                                 E::Point_3(c[0], c[1], c[2])))
      return false;
    fast_[i] = make_fast_plane(a, b, c);
    out = {sources_[i], {a, b, c}, {0, 0, 0}, 7, i, st.face};
    return true;
  }

  /// Incremental insertion (tree_insert.h): fragments hold their own points, so `old`'s are
  /// valid here as they are.
  void import_points(const cgal_geometry& /*old*/, std::vector<fragment>& /*fragments*/) const {}

  /// Sign of orientation(plane of input triangle `plane`, vertex k of f).
  int sign(std::uint32_t plane, const fragment& f, int k) const {
    if constexpr (kernel_traits<K>::fast_path) {
      if ((f.double_mask >> k) & 1) {
        const int s = fast_sign(fast_[plane], f.d[k], f.r[k]);
        if (s != 2) return s;
      }
    }
    const triangle& p = sources_[plane];
    return static_cast<int>(K().orientation_3_object()(p[0], p[1], p[2], f.v[k]));
  }

  /// Writes the pieces of f (straddling `plane` with signs s, pattern pat) to out[0..pieces).
  void split(std::uint32_t plane, const fragment& f, const geom::split_pattern& pat,
             std::array<fragment, 3>& out, scratch& sc) const {
    const triangle& pl = sources_[plane];
    if (sc.plane != plane || !sc.normal) {
      vector n = CGAL::cross_product(pl[1] - pl[0], pl[2] - pl[0]);
      kernel_traits<K>::collapse_vector(n);
      sc.normal = n;
      sc.plane = plane;
    }
    std::array<point, 2> x;
    for (int j = 0; j < pat.new_points; ++j)
      x[j] = detail::intersect_with_normal<K>(pl[0], *sc.normal, f.v[pat.from[j]], f.v[pat.to[j]]);
    for (int i = 0; i < pat.pieces; ++i) {
      fragment& piece = out[i];
      piece.source = f.source;
      piece.face = f.face;
      piece.double_mask = 0;
      piece.r = {0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        const int m = pat.corner[i][k];
        if (m < 3) {
          piece.v[k] = f.v[m];
          if ((f.double_mask >> m) & 1) {
            piece.d[k] = f.d[m];
            piece.r[k] = f.r[m];
            piece.double_mask |= static_cast<std::uint8_t>(1u << k);
          }
        } else {
          piece.v[k] = x[m - 3];
          if (kernel_traits<K>::approximate(piece.v[k], piece.d[k], piece.r[k]))
            piece.double_mask |= static_cast<std::uint8_t>(1u << k);
        }
      }
    }
  }

  int side_of_eye(std::uint32_t plane, const vec3d& eye) const {
    if constexpr (kernel_traits<K>::fast_path) {
      const int s = fast_sign(fast_[plane], eye, 0);
      if (s != 2) return s;
    }
    return side_of_eye(plane, point(eye[0], eye[1], eye[2]));
  }
  int side_of_eye(std::uint32_t plane, const point& eye) const {
    const triangle& p = sources_[plane];
    return static_cast<int>(K().orientation_3_object()(p[0], p[1], p[2], eye));
  }
  int side_of_direction(std::uint32_t plane, const vec3d& d) const {
    return side_of_direction(plane, vector(d[0], d[1], d[2]));
  }
  int side_of_direction(std::uint32_t plane, const vector& d) const {
    const triangle& p = sources_[plane];
    return static_cast<int>(CGAL::sign(CGAL::cross_product(p[1] - p[0], p[2] - p[0]) * -d));
  }

  void prepare_output(const std::vector<fragment>&) const {}
  fragment_d to_double(const fragment& f) const {
    fragment_d out{f.face, {}};
    for (int k = 0; k < 3; ++k)
      out.v[k] = {kernel_traits<K>::to_double(f.v[k].x()), kernel_traits<K>::to_double(f.v[k].y()),
                  kernel_traits<K>::to_double(f.v[k].z())};
    return out;
  }
  void visit_exact(const fragment& f, const exact_visitor& visit) const {
    if constexpr (exact) {
      for (int k = 0; k < 3; ++k) {
        visit(k, 0, kernel_traits<K>::rational(f.v[k].x()));
        visit(k, 1, kernel_traits<K>::rational(f.v[k].y()));
        visit(k, 2, kernel_traits<K>::rational(f.v[k].z()));
      }
    } else {
      (void)f;
      (void)visit;
      throw usage_error("exact coordinates need an exact kernel (exact, epeck or gmpq), not " +
                        to_string(id));
    }
  }
  std::size_t points_memory() const { return 0; }

  /// Saved trees (tree_file_cgal.h, docs/tree-file.md): each fragment as its source and nine
  /// coordinates (exact kernels: canonical rationals; inexact ones: double bit patterns).
  /// read_fragments reads them back into a geometry made from the same soup, in which
  /// `usable[i]` says whether add_source accepted triangle i; throws input_error through `in`.
  void write_fragments(tree_file::writer& out, const std::vector<fragment>& fragments) const;
  void read_fragments(tree_file::reader& in, const triangle_soup& soup,
                      const std::vector<char>& usable, std::vector<fragment>& fragments) const;

 private:
  std::vector<triangle> sources_;
  std::vector<std::array<vec3d, 3>> source_doubles_;  ///< the same, as the input's doubles
  std::vector<fast_plane> fast_;
};

}  // namespace exbsp

#include "bsp/tree_file_cgal.h"
