// SPDX-License-Identifier: LGPL-3.0-or-later
// The tree walk of the public API (notation in traversal.h); the walk itself is
// basic_bsp_tree::walk, shared with order_from_eye.
#include <exbsp/bsp/traversal.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <exbsp/bsp/engine.h>
#include "bsp/bsp_impl.h"

namespace exbsp {

int side_of_plane(const bsp_node& n, const vec3d& p) {
  using K = CGAL::Epick;  // exact predicates on double input: the plane and p are doubles
  const auto point = [](const vec3d& v) { return K::Point_3(v[0], v[1], v[2]); };
  return static_cast<int>(K().orientation_3_object()(point(n.plane[0]), point(n.plane[1]),
                                                     point(n.plane[2]), point(p)));
}

double plane_value(const bsp_node& n, const vec3d& p) {
  const vec3d& a = n.plane[0];
  const vec3d e1{n.plane[1][0] - a[0], n.plane[1][1] - a[1], n.plane[1][2] - a[2]};
  const vec3d e2{n.plane[2][0] - a[0], n.plane[2][1] - a[1], n.plane[2][2] - a[2]};
  const vec3d normal{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                     e1[0] * e2[1] - e1[1] * e2[0]};
  return normal[0] * (p[0] - a[0]) + normal[1] * (p[1] - a[1]) + normal[2] * (p[2] - a[2]);
}

std::size_t bsp::node_count() const { return impl_->node_count(); }

bsp_node bsp::node(std::size_t k) const { return impl_->node(k); }

void bsp::traverse_from_eye(const vec3d& eye, bsp_visitor& visitor, bool back_to_front) const {
  detail::require_eye(eye, "traverse_from_eye");
  impl_->traverse(eye, false, visitor, back_to_front);
}

void bsp::traverse_for_direction(const vec3d& d, bsp_visitor& visitor, bool back_to_front) const {
  detail::require_direction(d, "traverse_for_direction");
  impl_->traverse(d, true, visitor, back_to_front);
}

}  // namespace exbsp
