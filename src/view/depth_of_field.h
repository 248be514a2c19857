// SPDX-License-Identifier: LGPL-3.0-or-later
// The "depth_of_field" effect: a thin-lens camera rendered by accumulating jittered-aperture
// painter's renders. Its stage runs after the raster stage (PNG only).
//
// Notation: focal length f, aperture (lens diameter) A, focus distance u_f > f, depth u of a
// point along the gaze (u = -z_eye), image height H pixels, P the projection matrix
// (glFrustum / gluPerspective: P11 = 2 near / (top - bottom) = cot(fovy / 2)).
// Lens law 1/f = 1/u + 1/v: the plane at u_f is imaged at v_f = f u_f / (u_f - f), and a point
// at depth u spreads into a disk of diameter
//   c = A f |u - u_f| / (u (u_f - f))                       (sensor units, circle of confusion).
// The sensor's height is h_s = 2 v_f / P11, so in pixels
//   c_px = c H / h_s = A |u - u_f| H P11 / (2 u u_f)        (f cancels: it only turns an
//                                                             f-number into A = f / N).
// Rendering: the eye moves to e + dx u + dy v for lens points (dx, dy) on the disk of radius
// A/2 (u, v: the camera's right and up), keeps its orientation, and the frustum is sheared so
// that the window on the focus plane stays put: P02 -= dx P00 / u_f, P12 -= dy P11 / u_f.
// A point at depth u then moves by P00 dx (1/u_f - 1/u) in ndc: the points of the focus plane
// stay fixed (sharp), and over the lens disk a point at depth u sweeps a disk of exactly c_px
// pixels. Sample 0 is the lens centre (the ordinary pinhole render the raster stage already
// made); samples k = 1..S-1 lie at radius (A/2) sqrt((k - 1/2)/(S - 1)) and angle k times the
// golden angle (a deterministic, evenly spread Vogel spiral). The frame's picture becomes the
// rounded mean of the S renders. The BSP is reused: each sample is a traversal for its own
// eye point and the per-view stages, never a rebuild. No depth buffer is used.
// Parallel projections have no lens: the scene parser rejects depth_of_field for them.
#pragma once
#include <string>
#include <vector>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// c = A f |u - u_f| / (u (u_f - f)) in the units of the scene (sensor side of the lens).
double circle_of_confusion(const depth_of_field_settings& s, double u);

/// c_px = A |u - u_f| H P11 / (2 u u_f): the circle of confusion in pixels of `view`.
double circle_of_confusion_pixels(const depth_of_field_settings& s, const view_setup& view,
                                  double u);

/// A point on the lens disk in the camera's (right, up) frame, world units.
struct lens_offset {
  double dx = 0, dy = 0;
};
/// The S lens samples of the notation above (sample 0 at the centre). Throws usage_error
/// unless count >= 1 and aperture >= 0 is finite.
std::vector<lens_offset> lens_samples(int count, double aperture);

/// The view from lens point (dx, dy) with the focus plane at focus_distance held fixed.
/// Throws usage_error for a parallel view or focus_distance <= 0.
view_setup lens_view(const view_setup& view, const lens_offset& lens, double focus_distance);

/// "depth_of_field": renders samples 1..S-1 with `per_view` (the stages from "order" up to
/// the raster or antialias stage) and averages them with f.picture (sample 0). Everything
/// but f.picture is restored to the centre view afterwards. Throws usage_error for a parallel
/// view or bad settings.
std::string depth_of_field_stage(frame& f, const pipeline& per_view);

}  // namespace exbsp::view
