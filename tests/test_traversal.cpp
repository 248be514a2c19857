// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of the public tree walk (include/exbsp/bsp/traversal.h): bsp::node, side_of_plane,
// traverse_from_eye / traverse_for_direction against order_from_eye, ancestors() and the
// exact input. Degenerate cases first: the empty tree, eyes exactly on node planes, points a
// double test would put on a plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/bsp/traversal.h>
#include <exbsp/core/errors.h>

namespace {

using exbsp::bsp;
using exbsp::bsp_node;
using exbsp::vec3d;

/// Records every callback of a walk.
struct recorder final : exbsp::bsp_visitor {
  struct event {
    char kind;  ///< 'e' enter, 'f' fragments, 'c' cell
    std::uint32_t node;
    int value;  ///< eye side (enter) or cell side (cell)
  };
  std::vector<event> events;
  std::vector<std::uint32_t>
      order;  ///< fragments in visit order (a node's list last to first when reversed)
  bool reversed = false;
  void enter(const bsp_node& n, int eye_side) override {
    events.push_back({'e', n.index, eye_side});
  }
  void fragments(const bsp_node& n) override {
    events.push_back({'f', n.index, 0});
    for (std::uint32_t k = 0; k < n.fragment_count; ++k)
      order.push_back(reversed ? n.first_fragment + n.fragment_count - 1 - k
                               : n.first_fragment + k);
  }
  void cell(const bsp_node& n, int side) override { events.push_back({'c', n.index, side}); }
};

/// A soup of `n` triangles with coordinates on a coarse grid (so that coplanar, touching and
/// exactly degenerate triangles occur), from a fixed seed.
exbsp::triangle_soup grid_soup(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-4, 4);
  exbsp::triangle_soup s;
  for (std::size_t i = 0; i < n; ++i) {
    const auto base = static_cast<std::uint32_t>(s.vertices.size());
    for (int k = 0; k < 3; ++k)
      s.vertices.push_back({coord(rng) * 0.5, coord(rng) * 0.5, coord(rng) * 0.25});
    s.add_polygon({base, base + 1, base + 2}, static_cast<std::uint32_t>(i));
  }
  return s;
}

/// True when the rational "p/q" (or "p") is a double: q a small power of two.
bool is_double(const std::string& rational) {
  const std::size_t slash = rational.find('/');
  if (slash == std::string::npos) return true;
  if (rational.size() - slash > 18) return false;
  const unsigned long long q = std::stoull(rational.substr(slash + 1));
  return (q & (q - 1)) == 0;
}

/// Walks every check of the visitor contract for one eye or direction.
void expect_walk_matches_order(const bsp& tree, const vec3d& at, bool direction) {
  recorder back, front;
  front.reversed = true;
  if (direction) {
    tree.traverse_for_direction(at, back);
    tree.traverse_for_direction(at, front, false);
    EXPECT_EQ(back.order, tree.order_for_direction(at));
    EXPECT_EQ(front.order, tree.order_for_direction(at, false));
  } else {
    tree.traverse_from_eye(at, back);
    tree.traverse_from_eye(at, front, false);
    EXPECT_EQ(back.order, tree.order_from_eye(at));
    EXPECT_EQ(front.order, tree.order_from_eye(at, false));
  }
  // Each node entered once, before its list; nodes + 1 cells (the empty sides of a binary tree).
  const std::size_t nodes = tree.node_count();
  std::vector<int> entered(nodes, 0), listed(nodes, 0);
  std::size_t cells = 0;
  std::vector<std::pair<std::uint32_t, int>> back_cells, front_cells;
  for (const recorder::event& e : back.events) {
    if (e.kind == 'e') ++entered[e.node];
    if (e.kind == 'f') {
      EXPECT_EQ(entered[e.node], 1);
      ++listed[e.node];
    }
    if (e.kind == 'c') {
      ++cells;
      back_cells.push_back({e.node, e.value});
      const bsp_node n = tree.node(e.node);
      EXPECT_LT(e.value > 0 ? n.positive : n.negative, 0) << "a cell is an empty side";
    }
  }
  for (const recorder::event& e : front.events)
    if (e.kind == 'c') {
      front_cells.push_back({e.node, e.value});
    }
  EXPECT_EQ(std::count(entered.begin(), entered.end(), 1), static_cast<long>(nodes));
  EXPECT_EQ(std::count(listed.begin(), listed.end(), 1), static_cast<long>(nodes));
  EXPECT_EQ(cells, nodes == 0 ? 0 : nodes + 1);
  // Front to back: the cells in exactly the reverse order.
  std::reverse(front_cells.begin(), front_cells.end());
  EXPECT_EQ(front_cells, back_cells);
  // The eye's side is the exact side of the eye (exact kernels; a direction: n . (-d)).
  if (!direction && exbsp::is_exact(tree.kernel())) {
    for (const recorder::event& e : back.events)
      if (e.kind == 'e') {
        EXPECT_EQ(e.value, exbsp::side_of_plane(tree.node(e.node), at));
      }
  }
}

TEST(Traversal, EmptyTreeVisitsNothing) {
  const bsp tree = bsp::build(exbsp::triangle_soup{});
  EXPECT_EQ(tree.node_count(), 0u);
  recorder r;
  tree.traverse_from_eye({0, 0, 1}, r);
  tree.traverse_for_direction({0, 0, -1}, r, false);
  EXPECT_TRUE(r.events.empty());
  EXPECT_THROW(tree.node(0), exbsp::usage_error);
}

TEST(Traversal, BadEyesAndDirectionsAreUsageErrors) {
  const bsp tree = bsp::build(grid_soup(5, 1));
  recorder r;
  EXPECT_THROW(tree.traverse_from_eye({0, std::nan(""), 1}, r), exbsp::usage_error);
  EXPECT_THROW(tree.traverse_for_direction({0, 0, 0}, r), exbsp::usage_error);
  EXPECT_THROW(tree.traverse_for_direction({HUGE_VAL, 0, 0}, r), exbsp::usage_error);
  EXPECT_THROW(tree.node(tree.node_count()), exbsp::usage_error);
  EXPECT_TRUE(r.events.empty());
}

TEST(Traversal, SideOfPlaneIsExactWhereADoubleTestIsNot) {
  bsp_node n;
  n.plane = {vec3d{0, 0, 0}, vec3d{1, 1, 0}, vec3d{0, 0, 1}};  // the plane x = y, normal (1, -1, 0)
  EXPECT_EQ(exbsp::side_of_plane(n, {0.3, 0.3, 7}), 0);
  EXPECT_EQ(exbsp::plane_value(n, {0.3, 0.3, 7}), 0.0);
  // 0.1 + 0.2 rounds above 0.3: the point is off the plane by one ulp, on the positive side.
  EXPECT_EQ(exbsp::side_of_plane(n, {0.1 + 0.2, 0.3, -5}), 1);
  EXPECT_EQ(exbsp::side_of_plane(n, {0.3, 0.1 + 0.2, -5}), -1);
  // A plane through points a double orientation gets wrong: three nearly collinear points.
  n.plane = {vec3d{0.5, 0.5, 0}, vec3d{12, 12, 1e-30}, vec3d{24, 24, 0}};
  const vec3d on_line{0.5 + 0x1p-52, 0.5 + 0x1p-52, 0};  // on the segment's line, off the plane
  EXPECT_EQ(exbsp::side_of_plane(n, on_line), 0) << "exactly in the plane: the line lies in it";
  for (const vec3d& p : n.plane) EXPECT_EQ(exbsp::side_of_plane(n, p), 0);
}

TEST(Traversal, NodesAgreeWithAncestorsAndTheExactInput) {
  const exbsp::triangle_soup soup = grid_soup(60, 7);
  for (const std::string& heuristic : exbsp::heuristic_names()) {
    exbsp::build_options o;
    o.heuristic = heuristic;
    const bsp tree = bsp::build(soup, o);
    ASSERT_GT(tree.node_count(), 1u) << heuristic;
    std::size_t listed = 0;
    for (std::size_t k = 0; k < tree.node_count(); ++k) {
      const bsp_node n = tree.node(k);
      EXPECT_EQ(n.index, k);
      // The node's plane is its input triangle's, in its orientation.
      const exbsp::soup_triangle& t = soup.triangles[n.plane_face];
      for (int c = 0; c < 3; ++c) EXPECT_EQ(n.plane[c], soup.vertices[t.v[c]]);
      if (n.parent >= 0) {
        const bsp_node p = tree.node(static_cast<std::size_t>(n.parent));
        EXPECT_LT(p.index, n.index);
        EXPECT_EQ(n.side_in_parent > 0 ? p.positive : p.negative, static_cast<std::int32_t>(k));
      } else {
        EXPECT_EQ(k, 0u);
      }
      for (std::uint32_t i = n.first_fragment; i < n.first_fragment + n.fragment_count;
           ++i, ++listed) {
        // The path to the node is ancestors(i).
        std::vector<bsp::ancestor> path;
        for (bsp_node at = n; at.parent >= 0;) {
          const bsp_node p = tree.node(static_cast<std::size_t>(at.parent));
          path.insert(path.begin(), {p.plane_face, at.side_in_parent});
          at = p;
        }
        const std::vector<bsp::ancestor> anc = tree.ancestors(i);
        ASSERT_EQ(anc.size(), path.size());
        for (std::size_t a = 0; a < anc.size(); ++a) {
          EXPECT_EQ(anc[a].plane_face, path[a].plane_face);
          EXPECT_EQ(anc[a].side, path[a].side);
        }
        // Input vertices of the fragment (exact doubles) lie in its node's plane and on the
        // ancestors' sides it is stored under.
        const exbsp::exact_triangle exact = tree.fragment_exact(i);
        const exbsp::fragment_d d = tree.fragment(i);
        for (int c = 0; c < 3; ++c) {
          if (!std::all_of(exact[c].begin(), exact[c].end(), is_double))
            continue;  // rounded: no exact claim
          EXPECT_EQ(exbsp::side_of_plane(n, d.v[c]), 0);
          for (bsp_node at = n; at.parent >= 0;) {
            const bsp_node p = tree.node(static_cast<std::size_t>(at.parent));
            EXPECT_NE(exbsp::side_of_plane(p, d.v[c]), -at.side_in_parent);
            at = p;
          }
        }
      }
    }
    EXPECT_EQ(listed, tree.fragment_count());
  }
}

TEST(Traversal, WalkGivesTheOrderForEyesOnPlanesAndEveryKernel) {
  const exbsp::triangle_soup soup = grid_soup(40, 3);
  for (exbsp::kernel_id k :
       {exbsp::kernel_id::exact, exbsp::kernel_id::epeck, exbsp::kernel_id::double_}) {
    exbsp::build_options o;
    o.kernel = k;
    const bsp tree = bsp::build(soup, o);
    // Input vertices lie exactly on node planes (s = 0 there); the others are generic.
    std::vector<vec3d> eyes{
        soup.vertices[0], soup.vertices[5], soup.vertices[17], {0.3, -7, 11}, {-2.2, 3.1, -0.4}};
    for (const vec3d& eye : eyes) expect_walk_matches_order(tree, eye, false);
    for (const vec3d& d : {vec3d{0, 0, -1}, vec3d{1, 0, 0}, vec3d{0.3, -0.2, 0.9}})
      expect_walk_matches_order(tree, d, true);
  }
}

TEST(Traversal, EveryKernelShowsANodesPlaneAsItsInputTrianglesDoubles) {
  // The points come from the kernel's own copy of the input (no per-node table): each
  // kernel must give back exactly the input doubles, -0 included.
  exbsp::triangle_soup soup = grid_soup(30, 5);
  soup.vertices[0] = {-0.0, soup.vertices[0][1], soup.vertices[0][2]};
  for (const std::string& name : exbsp::kernel_names()) {
    exbsp::build_options o;
    o.kernel = exbsp::parse_kernel(name);
    const bsp tree = bsp::build(soup, o);
    for (std::size_t k = 0; k < tree.node_count(); ++k) {
      const bsp_node n = tree.node(k);
      const exbsp::soup_triangle& t = soup.triangles[n.plane_face];
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i) {
          const double want = soup.vertices[t.v[c]][i], got = n.plane[c][i];
          EXPECT_TRUE(want == got && std::signbit(want) == std::signbit(got))
              << name << " node " << k << " corner " << c << " coordinate " << i;
        }
    }
  }
}

}  // namespace
