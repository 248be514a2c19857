// SPDX-License-Identifier: LGPL-3.0-or-later
// PHIGS view orientation and view mapping (notation in phigs.h).
#include <exbsp/view/phigs.h>

#include <cmath>
#include <string>

#include <exbsp/core/errors.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/transforms.h>

namespace exbsp::view {

phigs_matrices phigs_view_matrices(const phigs_view& p) {
  if (!is_finite(p.vrp)) throw usage_error("vrp: must be finite");
  if (!is_finite(p.prp)) throw usage_error("prp: must be finite");
  for (double x : {p.umin, p.umax, p.vmin, p.vmax})
    if (!std::isfinite(x)) throw usage_error("window: must be finite");
  if (!std::isfinite(p.front) || !std::isfinite(p.back)) throw usage_error("front: must be finite");
  if (!is_finite(p.vpn) || !(length(p.vpn) > 0))
    throw usage_error("vpn: must be a finite nonzero vector");
  if (!is_finite(p.vup) || !(length(p.vup) > 0))
    throw usage_error("vup: must be a finite nonzero vector");
  if (!(p.umin < p.umax) || !(p.vmin < p.vmax))
    throw usage_error("window: needs umin < umax and vmin < vmax");
  if (!(p.front > p.back))
    throw usage_error("front: must be greater than back (both along n, n towards the viewer)");
  phigs_matrices r;
  try {
    r.basis = look_direction_basis(-p.vpn, p.vup);  // w = n
  } catch (const usage_error&) {
    throw usage_error("vup: is parallel to vpn (the view direction)");
  }
  r.orientation = look_along(p.vrp, -p.vpn, p.vup);
  const camera_basis& b = r.basis;
  const vector3 prp_world = p.prp.x * b.u + p.prp.y * b.v + p.prp.z * b.w;
  r.eye = p.vrp + prp_world;
  if (p.perspective) {
    if (!(p.prp.z > p.front))
      throw usage_error(
          "prp: the centre of projection must lie in front of the front plane (prp n > front)");
    const double d = p.prp.z, near_dist = p.prp.z - p.front, far_dist = p.prp.z - p.back;
    const double k = near_dist / d;
    const mat4 shift = translate({-p.prp.x, -p.prp.y, -p.prp.z});
    r.projection = frustum((p.umin - p.prp.x) * k, (p.umax - p.prp.x) * k, (p.vmin - p.prp.y) * k,
                           (p.vmax - p.prp.y) * k, near_dist, far_dist);
    r.mapping = r.projection * shift;
    r.model_view = shift * r.orientation;
  } else {
    if (!(p.prp.z > 0))
      throw usage_error("prp: must lie on the viewer's side of the view plane (prp n > 0)");
    const vector3 dop{(p.umin + p.umax) / 2 - p.prp.x, (p.vmin + p.vmax) / 2 - p.prp.y, -p.prp.z};
    r.oblique = dop.x != 0 || dop.y != 0;
    r.mapping = r.oblique ? oblique(p.umin, p.umax, p.vmin, p.vmax, -p.front, -p.back, dop, 0.0)
                          : ortho(p.umin, p.umax, p.vmin, p.vmax, -p.front, -p.back);
    r.projection = r.mapping;
    r.model_view = r.orientation;
    r.direction = normalized(dop.x * b.u + dop.y * b.v + dop.z * b.w);
  }
  return r;
}

}  // namespace exbsp::view
