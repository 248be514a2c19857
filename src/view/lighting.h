// SPDX-License-Identifier: LGPL-3.0-or-later
// The "lighting" effect: flat shading, Lambert's diffuse term and Blinn-Phong's specular one,
// from a directional light or a headlight and more directional, point or head lights (a
// world-space stage after "order"; settings and formula in effect_settings.h).
//
// Notation: fragment (a, b, c) with winding normal n = (b - a) x (c - a); N = n / |n|, flipped
// to face the viewer when two_sided (V = eye - a for perspective and frustum views, V = -d for
// parallel views with direction of projection d; N . V < 0 flips); L = direction / |direction|
// points from the surface towards the light. The fragment's colour is
//   base * (ambient + intensity * max(0, N . L)),
// per channel, clamped to [0, 255] and rounded to nearest, plus the specular terms and the
// other lights of effect_settings.h. One colour per fragment (flat): pieces of one face share
// their plane, so they share their colour; a point light, a headlight and the highlights use
// the centroid of the source face (the mean of its input triangles' centroids), so pieces of a
// face share that colour too and the picture never shows where the tree split a face.
#pragma once
#include <string>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// base * (ambient + intensity * max(0, N . L)) for a unit normal N (notation above).
rgb8 lambert_color(rgb8 base, const vector3& unit_normal, const lighting_settings& s);

/// The colour of a fragment with unit normal N and centroid `centroid` seen in `view`
/// (effect_settings.h's formula); lambert_color's exactly when there is no headlight, no
/// specular term and no other light.
rgb8 lit_color(rgb8 base, const vector3& unit_normal, const point3& centroid,
               const view_setup& view, const lighting_settings& s);

/// The unit shading normal of a fragment in `view` (two-sided or as given). A fragment with
/// no normal (zero area after rounding) gets the zero vector, hence ambient light only.
vector3 shading_normal(const fragment_d& fr, const view_setup& view, bool two_sided);

/// "lighting": f.fragment_colors[i] = lit colour of fragment i for every i in f.order
/// (sized like f.fragments; transform+clip reads it). Throws usage_error for a zero or
/// non-finite light direction.
std::string lighting_stage(frame& f);

}  // namespace exbsp::view
