// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact fallback of orient2d (orient2d.h): CGAL's filtered exact Orientation_2 on doubles.
#include "view/orient2d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace exbsp::view {

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const CGAL::Orientation o =
      CGAL::orientation(K::Point_2(ax, ay), K::Point_2(bx, by), K::Point_2(cx, cy));
  return o == CGAL::LEFT_TURN ? 1 : (o == CGAL::RIGHT_TURN ? -1 : 0);
}

}  // namespace exbsp::view
