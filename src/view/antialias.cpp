// SPDX-License-Identifier: LGPL-3.0-or-later
// N x N supersampling (notation in antialias.h).
#include "view/antialias.h"

#include <algorithm>
#include <string>

#include <exbsp/core/errors.h>
#include "view/paint.h"

namespace exbsp::view {

std::string antialias_stage(frame& f) {
  const int n = f.settings.antialias.samples;
  if (n < 1 || n > 8)
    throw usage_error("antialias: samples must be in 1..8, got " + std::to_string(n));
  f.picture = box_downsample(paint_frame(f, n), n);
  const viewport& vp = f.view.vp;
  return std::to_string(vp.width) + "x" + std::to_string(vp.height) + " at " + std::to_string(n) +
         "x" + std::to_string(n) + " samples, " + std::to_string(f.polygons.size()) +
         " polygons, " + std::to_string(f.lines.size()) + " lines";
}

}  // namespace exbsp::view
