// SPDX-License-Identifier: LGPL-3.0-or-later
// The clipping stage: delegates to exbsp_clip's homogeneous (4D) Sutherland–Hodgman clipper
// (include/exbsp/clip/homogeneous.h), which clips against w+x, w-x, w+y, w-y, w+z, w-z >= 0 before
// the divide, interpolates each crossing from the lexicographically smaller end point (shared edges
// give bit-identical vertices) and puts the crossing exactly on its plane. Segments (curves,
// lines): clip/homogeneous_segment.h, Liang–Barsky or Cohen–Sutherland. This file is the only place
// that knows which clipper the pipeline uses.
#include "view/clip_stage.h"

#include <exbsp/clip/homogeneous.h>
#include <exbsp/clip/homogeneous_segment.h>

namespace exbsp::view {

void clip_to_view_volume(const std::vector<hpoint>& in, std::vector<hpoint>& out) {
  out.clear();
  if (in.size() < 3) return;
  clip::homogeneous_polygon poly;
  poly.positions.reserve(in.size());
  for (const hpoint& p : in) poly.positions.push_back({p.x, p.y, p.z, p.w});
  const clip::homogeneous_polygon clipped = clip::homogeneous_clip(poly);
  out.reserve(clipped.positions.size());
  for (const clip::vec4d& p : clipped.positions) out.push_back({p[0], p[1], p[2], p[3]});
}

unsigned view_volume_outcode(const hpoint& p) {
  return clip::homogeneous_outcode({p.x, p.y, p.z, p.w});
}

bool clip_segment_to_view_volume(const hpoint& a, const hpoint& b, hpoint& out_a, hpoint& out_b,
                                 double* t0_out, double* t1_out, segment_clipper clipper) {
  const clip::vec4d ca{a.x, a.y, a.z, a.w}, cb{b.x, b.y, b.z, b.w};
  clip::vec4d oa, ob;
  const bool kept = clipper == segment_clipper::cohen_sutherland
                        ? clip::homogeneous_cohen_sutherland(ca, cb, oa, ob, t0_out, t1_out)
                        : clip::homogeneous_liang_barsky(ca, cb, oa, ob, t0_out, t1_out);
  if (kept) {
    out_a = {oa[0], oa[1], oa[2], oa[3]};
    out_b = {ob[0], ob[1], ob[2], ob[3]};
  }
  return kept;
}

}  // namespace exbsp::view
