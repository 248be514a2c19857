// SPDX-License-Identifier: LGPL-3.0-or-later
// The "exposure" effect: motion blur of a camera moving while the shutter is open (settings
// in effect_settings.h). Its stage runs after the raster stage (PNG only).
//
// Notation: the camera at time t is the linear blend c(t) = (1 - t) c0 + t c1 of the scene's
// camera c0 and camera_end c1 (eye, look_at and up each blended); the shutter is open for
// t in [0, s]; sample k = 0..n-1 is the view at t_k = s k / (n - 1) with Mv = gluLookAt(c(t_k))
// and the scene's projection. The tree is ordered from each view's centre of projection: the
// point (or, parallel, the direction) that view 0's has in eye coordinates, carried along with
// the camera (for the usual projections, the camera's own eye or gaze). Sample 0 is the frame
// the raster stage already made; the picture becomes the rounded mean of the n renders. The
// BSP is reused (the scene does not move: only the camera does).
#pragma once
#include <string>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// The view of sample `k` of `count` for the view `start` at time 0 (notation above). Throws
/// usage_error when a blended camera is degenerate (eye on look_at, up along the gaze).
view_setup exposure_view(const view_setup& start, const exposure_settings& s, int k, int count);

/// "exposure": renders samples 1..n-1 with `per_view` and averages them with f.picture.
std::string exposure_stage(frame& f, const pipeline& per_view);

}  // namespace exbsp::view
