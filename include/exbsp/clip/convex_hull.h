// SPDX-License-Identifier: GPL-3.0-or-later
// The convex hull of a 3D point set as half-spaces, for Sutherland–Hodgman (notation in
// convex_region.h). In the GPL component exbsp::gpl (libexbsp_gpl; find_package(exbsp
// COMPONENTS gpl), target exbsp::gpl): CGAL's convex_hull_3 is GPL-3.0-or-later
// (docs/licence.md). convex_region.h (LGPL core) has the convex polygon and polyhedron given
// by their faces.
#pragma once
#include <vector>

#include <exbsp/core/export.h>

#include <exbsp/clip/clip_types.h>
#include <exbsp/clip/sutherland_hodgman.h>

namespace exbsp::clip {

/// The half-spaces of the convex hull of `points`. Throws usage_error for NaN/infinite input
/// or points that do not span 3D (fewer than 4, or all coplanar).
EXBSP_EXPORT std::vector<half_space3> convex_hull_half_spaces(const std::vector<vec3d>& points);

}  // namespace exbsp::clip
