// SPDX-License-Identifier: LGPL-3.0-or-later
// The PHIGS view reference model (docs/contract.md "Scenes", seed 004) as OpenGL-style matrices.
//
// Notation: world points p; the view reference coordinates (VRC) have origin VRP and axes
//   n = VPN / |VPN|,   u = (VUP x n) / |VUP x n|,   v = n x u
// (right-handed; n points towards the viewer, like gluLookAt's w). The view orientation matrix
// maps world to VRC: O = R_uvn * T(-VRP), R_uvn with rows u, v, n. PRP = (pu, pv, pn), the
// window [umin, umax] x [vmin, vmax] (on the view plane n = 0) and the front and back planes
// n = F, n = B are given in VRC. The view mapping matrix M maps VRC to OpenGL clip
// coordinates (the view volume becomes -w <= x, y, z <= w, z_ndc = -1 on the front plane):
//   perspective (centre of projection at PRP; needs pn > F > B): eye coordinates are
//     VRC - PRP, the window lies at distance d = pn in front of the eye and the front and back
//     planes at near = pn - F and far = pn - B, so
//     M = frustum((umin - pu) near/d, (umax - pu) near/d, (vmin - pv) near/d, (vmax - pv) near/d,
//                 near, far) * T(-PRP);
//     an off-centre PRP (pu, pv not the window's centre) gives an off-axis frustum.
//   parallel (direction of projection DOP = CW - PRP, CW = ((umin+umax)/2, (vmin+vmax)/2, 0);
//     needs pn > 0 and F > B): M = ortho(umin, umax, vmin, vmax, -F, -B) * shear, the shear of
//     projection.h fixing the view plane n = 0 and mapping DOP onto -n; oblique when DOP is
//     not along -n.
// The product M * O is the whole viewing transform. For the pipeline it is split into a rigid
// model_view (perspective: T(-PRP) * O, eye at the origin; parallel: O) and a projection.
#pragma once
#include <exbsp/core/export.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/matrix.h>

namespace exbsp::view {

/// PHIGS viewing parameters (notation above).
struct phigs_view {
  point3 vrp;
  vector3 vpn{0, 0, 1}, vup{0, 1, 0};
  point3 prp{0, 0, 1};
  double umin = -1, umax = 1, vmin = -1, vmax = 1;
  double front = 0, back = -1;
  bool perspective = true;
};

/// The matrices of a PHIGS view.
struct EXBSP_EXPORT phigs_matrices {
  camera_basis basis;                   ///< u, v, n (n in the w slot)
  mat4 orientation = mat4::identity();  ///< O: world -> VRC
  mat4 mapping = mat4::identity();      ///< M: VRC -> clip coordinates
  mat4 model_view = mat4::identity();   ///< rigid part for the pipeline
  mat4 projection = mat4::identity();   ///< projection * model_view = mapping * orientation
  point3 eye;                           ///< world position of PRP (the centre of projection)
  vector3 direction;                    ///< parallel: unit world DOP (eye into the scene)
  bool oblique = false;                 ///< parallel with DOP not along -n
};

/// Builds the matrices. Throws usage_error naming the parameter ("vup", "prp", "window",
/// "front", "back", "vpn") for non-finite input, a zero VPN, VUP parallel to VPN, an empty
/// window, F <= B, or a PRP on the wrong side (pn <= F for perspective, pn <= 0 for parallel).
EXBSP_EXPORT phigs_matrices phigs_view_matrices(const phigs_view& p);

}  // namespace exbsp::view
