// SPDX-License-Identifier: LGPL-3.0-or-later
// The "fog" effect: a screen-space stage after transform+clip that installs its colour
// change as the frame's sample_shader (sample_shader.h); the painters apply it without
// knowing it is fog.
//
// Notation: a window point (x, y, z) (viewport.h: z is the depth in [depth_near, depth_far])
// goes back to normalized device coordinates ndc = (2 (x - vp.x) / width - 1,
// 2 (y - vp.y) / height - 1, 2 (z - depth_near) / (depth_far - depth_near) - 1) and to eye
// space by the inverse projection: p_eye = P^-1 (ndc, 1), divided by its w. The eye distance
// is d = |p_eye| for perspective and frustum views (radial fog: the same for every pixel at
// the same distance, so the far plane's corners fade as its centre does) and d = -z_eye for
// parallel views. Visibility v(d) (effect_settings.h): linear clamp((end - d)/(end - start),
// 0, 1) or exponential exp(-density d); colour = v surface + (1 - v) fog colour, rounded.
// The painters give each sample's window point, so fog is per pixel in PNG (polygon depths
// from their depth planes, sample_shader.h) and per path in SVG and PDF.
#pragma once
#include <string>
#include <vector>

#include <exbsp/view/effect_settings.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/sample_shader.h>

namespace exbsp::view {

/// v(d) in [0, 1] (1: no fog) for eye distance d >= 0.
double fog_visibility(const fog_settings& s, double d);

/// Fog state for a view: settings, inverse projection, radial or planar distance.
/// Throws usage_error when the projection matrix is singular.
fog_shading make_fog_shading(const fog_settings& s, const view_setup& view);

/// Eye distance of the window point (x, y, z) (notation above).
double eye_distance(const fog_shading& fog, double x, double y, double z);

/// `base` fogged at eye distance d.
rgb8 fog_color(const fog_shading& fog, rgb8 base, double d);

/// "fog": f.fog = make_fog_shading(f.settings.fog, f.view) and f.shader = its sample
/// shader: fog_color at each sample's eye distance; the background takes the fog colour.
std::string fog_stage(frame& f);

}  // namespace exbsp::view
