// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp's one vector vocabulary for plain coordinates: vec2d, vec3d and vec4d are std::array of
// doubles (2D points, 3D points and directions, homogeneous clip-space points). Meshes, clipping,
// curves and the trackball take and give these. Two other families have their own job and
// name: view's point3, vector3 and hpoint (<exbsp/view/matrix.h>) are the course's affine and
// projective points and vectors, which a matrix maps differently; geom::hpoint is a row of an
// exact determinant (w exactly 0 or 1).
#pragma once
#include <array>

namespace exbsp {

using vec2d = std::array<double, 2>;
using vec3d = std::array<double, 3>;
using vec4d = std::array<double, 4>;  ///< a homogeneous point (x, y, z, w)

}  // namespace exbsp
