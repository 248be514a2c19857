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

void parse_antialias_parameters(const reader& r, const json& p, const std::string& key,
                                const effect_scene& scene, effect_settings& out) {
  antialias_settings& a = out.antialias;
  r.reject_unknown(p, key, "antialias", {"samples"});
  if (const json* v = r.optional(p, "samples")) {
    const long long n = r.integer(*v, key + "/samples");
    if (n < 1 || n > 8) r.fail(key + "/samples", "must be in 1..8 (got " + std::to_string(n) + ")");
    a.samples = static_cast<int>(n);
  }
  if (static_cast<long long>(std::max(scene.width, scene.height)) * a.samples > scene.max_side)
    r.fail(key + "/samples", "the supersampled image would exceed " +
                                 std::to_string(scene.max_side) + " pixels a side (viewport " +
                                 std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                                 ")");
}

}  // namespace exbsp::view
