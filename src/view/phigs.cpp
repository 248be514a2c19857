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

std::vector<phigs_step> phigs_normalisation(const phigs_view& p) {
  const phigs_matrices checked = phigs_view_matrices(p);  // the same validation and basis
  if (p.prp.z == 0)
    throw usage_error("prp: the centre of projection lies on the view plane (prp n = 0)");
  const camera_basis& b = checked.basis;
  const double pn = p.prp.z;
  const double du = (p.umin + p.umax) / 2 - p.prp.x, dv = (p.vmin + p.vmax) / 2 - p.prp.y;
  const double wu = p.umax - p.umin, wv = p.vmax - p.vmin;
  std::vector<phigs_step> steps;
  steps.push_back({"T(-VRP)", "translate the view reference point to the origin",
                   translate({-p.vrp.x, -p.vrp.y, -p.vrp.z}), ""});
  steps.push_back({"R", "rotate u, v, n onto x, y, z: world to VRC",
                   mat4::from_rows({b.u.x, b.u.y, b.u.z, 0, b.v.x, b.v.y, b.v.z, 0,  //
                                    b.w.x, b.w.y, b.w.z, 0, 0, 0, 0, 1}),
                   "vrc"});
  steps.push_back({"T(-PRP)", "translate the projection reference point to the origin",
                   translate({-p.prp.x, -p.prp.y, -p.prp.z}), ""});
  // dop = (du, dv, -pn): -dop_u / dop_n = du / pn.
  const char* shear_meaning = p.perspective
                                  ? "shear the centre line (PRP to the window's centre) onto the "
                                    "-z axis, fixing the plane z = 0"
                                  : "shear the direction of projection onto -z, fixing the plane "
                                    "z = 0";
  steps.push_back({p.perspective ? "SHper" : "SHpar", shear_meaning,
                   mat4::from_rows({1, 0, du / pn, 0, 0, 1, dv / pn, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
                   "sheared"});
  if (p.perspective) {
    steps.push_back({"Sper", "scale x, y: the side planes at 45 degrees (x = +-z, y = +-z)",
                     scale(2 * pn / wu, 2 * pn / wv, 1), "opening_45"});
    const double far_dist = pn - p.back, z_min = -(pn - p.front) / far_dist;
    steps.push_back({"Sfar", "scale by 1 / (pn - B): the back plane at z = -1",
                     scale(1 / far_dist, 1 / far_dist, 1 / far_dist), ""});
    steps.push_back({"Mpp",
                     "the truncated pyramid between z_min and -1 to the cube [-1,1]^3 (front at "
                     "+1): the centre of projection goes to infinity",
                     mat4::from_rows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, (1 - z_min) / (1 + z_min),
                                      -2 * z_min / (1 + z_min), 0, 0, -1, 0}),
                     "normalised"});
  } else {
    steps.push_back({"Tpar", "translate the view volume's centre to the origin",
                     translate({0, 0, pn - (p.front + p.back) / 2}), ""});
    steps.push_back({"Spar", "scale the view volume to the cube [-1,1]^3 (front at +1)",
                     scale(2 / wu, 2 / wv, 2 / (p.front - p.back)), "normalised"});
  }
  return steps;
}

}  // namespace exbsp::view
