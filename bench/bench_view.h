// SPDX-License-Identifier: LGPL-3.0-or-later
// The fixed view of the rendering benchmarks (bench_render, bench_vector): a perspective camera
// looking at the centre of the soup's bounding box from one diagonal away along (1, 0.6, 0.4),
// z up, fovy 40 degrees, near 0.05 and far 3 diagonals, viewport width x height.
#pragma once
#include <cmath>

#include <exbsp/view/camera.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/projection.h>
#include "generators.h"

namespace exbsp::bench {

/// Sets f.view to the benchmark view of f.soup (notation above).
inline void set_bench_view(view::frame& f, int width, int height) {
  const bounds b = soup_bounds(f.soup);
  const vec3d c = b.centre();
  const double d = b.diagonal();
  const double n = std::sqrt(1 + 0.36 + 0.16);
  f.view.kind = view::projection_kind::perspective;
  f.view.cam.look_at = {c[0], c[1], c[2]};
  f.view.cam.eye = {c[0] + d * 1.0 / n, c[1] + d * 0.6 / n, c[2] + d * 0.4 / n};
  f.view.cam.up = {0, 0, 1};
  f.view.model_view = view::look_at(f.view.cam);
  f.view.projection = view::perspective(40, static_cast<double>(width) / height, 0.05 * d, 3 * d);
  f.view.vp = view::viewport{0, 0, width, height, 0.0, 1.0};
}

}  // namespace exbsp::bench
