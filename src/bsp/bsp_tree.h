// The BSP tree, templated on a CGAL kernel K (explicitly instantiated in bsp_<kernel>.cpp).
//
// Notation (DESIGN.md section 3):
//   triangle (a,b,c), normal n = (b-a)x(c-a), f(p) = sign of orientation(a,b,c,p):
//   f > 0 on the side n points to. A node's plane is the plane of its splitter's SOURCE
//   input triangle (three input points, doubles): a fragment lies exactly in its source's
//   plane with the same orientation, so every side test is one orientation predicate on
//   three input points and one (possibly constructed) point.
//   Classification of a triangle with signs (s0,s1,s2): all 0 -> coplanar; all >= 0 ->
//   positive; all <= 0 -> negative; otherwise straddling (then split, see split_triangle).
// Everything is iterative: building, traversal and destruction use explicit stacks or flat
// vectors, so a degenerate tree of depth 10^5 cannot overflow the stack.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "bsp/engine.h"
#include "bsp/fast_orientation.h"
#include "mesh/soup.h"

namespace exbsp {

enum class classification { coplanar, positive, negative, straddling };

/// Classification from the three vertex signs (each -1, 0 or +1).
classification classify_signs(const std::array<int, 3>& s);

/// Up to three pieces of a split triangle, in the contract's order, each with its side.
template <class K>
struct split_pieces {
  std::array<std::array<typename K::Point_3, 3>, 3> piece;
  std::array<int, 3> side{};  ///< +1 or -1 for each piece
  /// origin[i][k]: index (0..2) of the input triangle's vertex that piece i's vertex k is,
  /// or -1 for a constructed intersection point.
  std::array<std::array<int, 3>, 3> origin{};
  int count = 0;              ///< 2 (vertex on plane) or 3
};

/// Splits triangle t that straddles `plane` (three points; signs s of t's vertices against
/// it, as returned by orientation). Pieces keep t's orientation:
///   no vertex on the plane: relabel cyclically so c is alone; A = plane ∩ [c,a],
///     B = plane ∩ [b,c]; pieces (a,b,A), (b,B,A) on a/b's side, (A,B,c) on c's side;
///   one vertex z on the plane: relabel to (z,a,b); X = plane ∩ [a,b];
///     pieces (z,a,X) on a's side, (z,X,b) on b's side.
/// Precondition: classify_signs(s) == straddling (throws usage_error otherwise).
template <class K>
split_pieces<K> split_triangle(const std::array<typename K::Point_3, 3>& plane,
                               const std::array<typename K::Point_3, 3>& t,
                               const std::array<int, 3>& s);

/// The point where segment [p,q] meets the plane through plane[0..2]; p = q's side must differ.
template <class K>
typename K::Point_3 plane_segment_intersection(const std::array<typename K::Point_3, 3>& plane,
                                               const typename K::Point_3& p,
                                               const typename K::Point_3& q);

template <class K>
class bsp_tree {
public:
  using point = typename K::Point_3;
  using vector = typename K::Vector_3;
  using triangle = std::array<point, 3>;

  /// A triangle stored in the tree: its vertices, the index of its source input triangle
  /// (soup.triangles) and its face id.
  struct fragment {
    triangle v;
    std::array<vec3d, 3> d;     ///< double approximations of the vertices flagged in double_mask
    std::array<double, 3> r;    ///< vertex k lies within r[k] (max norm) of d[k]; 0: exactly d[k]
    std::uint8_t double_mask;   ///< bit k: d[k], r[k] are valid (input points, Epick points,
                                ///< Epeck constructions via their interval approximation)
    std::uint32_t source;
    std::uint32_t face;
  };

  /// A node: the plane of input triangle `plane_source`, its coplanar fragments
  /// fragments()[first, first+count) in list order, children (-1: none), parent and the
  /// side (+1/-1) of the parent's plane it lies on, and its depth (root: 1).
  struct node {
    std::uint32_t plane_source;
    std::uint32_t first, count;
    std::int32_t negative = -1, positive = -1, parent = -1;
    std::int32_t side_in_parent = 0;
    std::uint32_t depth = 1;
  };

  /// Builds the tree. Throws usage_error (unknown heuristic, non-finite coordinates),
  /// limit_error (options.max_fragments exceeded).
  bsp_tree(const triangle_soup& soup, const build_options& options);

  const build_stats& stats() const { return stats_; }
  const std::vector<fragment>& fragments() const { return fragments_; }
  const std::vector<node>& nodes() const { return nodes_; }
  /// The three input points of input triangle `source` (empty points for degenerate ones).
  const triangle& source_triangle(std::uint32_t source) const { return sources_[source]; }
  /// Index of the node whose coplanar list holds fragment i.
  std::size_t node_of_fragment(std::size_t i) const;

  /// Fragment indices back to front (or front to back) for a perspective eye.
  std::vector<std::uint32_t> order_from_eye(const point& eye, bool back_to_front = true) const;
  /// Same for a parallel projection with direction of projection d (eye into the scene).
  std::vector<std::uint32_t> order_for_direction(const vector& d, bool back_to_front = true) const;

private:
  /// Refs to fragments: a pool_ index, or local_ref | index into a subtree's own pieces.
  static constexpr std::uint32_t local_ref = 0x80000000u;
  struct work {
    std::vector<std::uint32_t> list;  ///< fragment refs, in list order
    std::int32_t parent;              ///< parent node (index in the subtree being grown), -1: none
    std::int32_t side;
    std::uint32_t depth;
    std::uint64_t key;                ///< path key: root 1, children mix64(2 key + (side > 0))
  };
  /// Nodes, fragment refs and pieces of one independently grown subtree.
  struct subtree {
    std::vector<node> nodes;
    std::vector<std::uint32_t> node_fragments;
    std::vector<fragment> pieces;
    std::int32_t root_parent = -1;
    std::int32_t root_side = 0;
  };
  struct build_context;
  template <class PushChild>
  void grow_node(work&& w, subtree& part, build_context& ctx, PushChild&& push_child);
  /// Appends a grown subtree (its refs already remapped to pool_) to nodes_.
  void append_subtree(subtree& part);
  /// The fragment a ref names: a pool_ index, or one of `part`'s own pieces.
  const fragment& resolve(const subtree& part, std::uint32_t ref) const {
    return (ref & local_ref) ? part.pieces[ref & ~local_ref] : pool_[ref];
  }
  template <class SideOf>
  std::vector<std::uint32_t> traverse(SideOf side_of, bool back_to_front) const;
  std::size_t choose_splitter(const std::vector<std::uint32_t>& list, const subtree& part, int heuristic,
                              std::uint64_t seed, std::uint64_t node_key, unsigned threads) const;
  std::size_t choose_min_split(const std::vector<std::uint32_t>& list, const subtree& part,
                               unsigned threads) const;
  std::size_t choose_sampled(const std::vector<std::uint32_t>& list, const subtree& part,
                             std::uint64_t seed, std::uint64_t node_key) const;

  static fragment make_piece(const fragment& parent, const split_pieces<K>& pieces, int i);

  std::vector<triangle> sources_;
  std::vector<fast_plane> fast_;
  std::vector<fragment> pool_;  ///< build time only: every fragment made, by index
  std::vector<std::uint32_t> node_fragments_;  ///< build time only: pool indices, node by node
  std::vector<fragment> fragments_;
  std::vector<node> nodes_;
  build_stats stats_;
};

}  // namespace exbsp
