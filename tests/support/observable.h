// SPDX-License-Identifier: LGPL-3.0-or-later
// What a user can observe of a built tree, as one string, for tests that compare trees across
// kernels, thread counts and saved files (test_exact_kernel, test_heuristics, test_parallel):
// statistics without timings, each fragment's face with its exact and double coordinates and
// its ancestors, and the orders for a set of eyes and directions.
#pragma once
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/mesh/soup.h>

namespace exbsp_test {

/// Stats, fragments (face, exact (exact kernels only) and %.17g double coordinates, ancestors) and,
/// for each eye, order_from_eye and (for a nonzero eye) order_for_direction of the same vector.
std::string observable(const exbsp::bsp& t, const std::vector<exbsp::vec3d>& eyes);

/// Eyes for a soup: fixed far points, and some input vertices (eyes exactly on node planes).
std::vector<exbsp::vec3d> eyes_for(const exbsp::triangle_soup& soup);

}  // namespace exbsp_test
