// hpoint adapter of clip/homogeneous_segment.h (notation there).
#include "view/segment_clip.h"

namespace exbsp::view {

bool clip_segment_to_view_volume(const hpoint& a, const hpoint& b, hpoint& out_a, hpoint& out_b, double* t0_out,
                                 double* t1_out, segment_clipper clipper) {
  const clip::vec4 ca{a.x, a.y, a.z, a.w}, cb{b.x, b.y, b.z, b.w};
  clip::vec4 oa, ob;
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
