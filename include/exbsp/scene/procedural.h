// SPDX-License-Identifier: LGPL-3.0-or-later
// Procedural meshes for the built-in demo scene and tests (no files needed).
//
// Notation: every mesh is a triangle_soup whose faces are polygons (fan-triangulated by
// triangle_soup::add_polygon) with face ids 0, 1, ... in construction order; closed solids
// have outward normals n = (b - a) x (c - a). Lengths are in scene units; z is the axis of
// extrusion where there is one.
#pragma once
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>

namespace exbsp::scene {

/// Axis-aligned box [lo, hi]: 6 quad faces, outward. Precondition: lo < hi componentwise.
EXBSP_EXPORT triangle_soup make_box(const vec3d& lo, const vec3d& hi);

/// Right prism over a convex polygon `outline` (x, y, counter-clockwise) from z0 to z1 > z0:
/// bottom cap, top cap, then one quad per side; outward.
EXBSP_EXPORT triangle_soup make_prism(const std::vector<std::array<double, 2>>& outline, double z0,
                                      double z1);

/// A spur-gear-like CAD part: `teeth` trapezoid teeth between root_radius and tip_radius, a
/// round bore of bore_radius (sampled at the profile's angles), extruded from -thickness/2 to
/// +thickness/2 along z, centred on the z axis; outward. Preconditions: teeth >= 3,
/// 0 < bore_radius < root_radius < tip_radius, thickness > 0.
EXBSP_EXPORT triangle_soup make_gear(int teeth, double root_radius, double tip_radius,
                                     double bore_radius, double thickness);

/// Three long flat planks (one quad face each) in cyclic overlap as seen from +z: plank i
/// runs along direction angle 120 i degrees, at distance `offset` from the origin, from
/// parameter -half_length to +half_length, `width` wide, rising with `slope` along its length,
/// so that plank i passes over plank i+1 (mod 3) where they cross. No depth order of the three
/// exists; a BSP must split one of them. Normals point up (+z side).
EXBSP_EXPORT triangle_soup make_cyclic_planks(double offset, double half_length, double width,
                                              double slope);

}  // namespace exbsp::scene
