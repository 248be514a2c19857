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
#include <string>
#include <vector>

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

/// One step of the PHIGS normalisation: its name in the course's notation, what it does, its
/// matrix, and the name of the space the scene is in after it ("" between named spaces).
struct EXBSP_EXPORT phigs_step {
  std::string name, meaning;
  mat4 m = mat4::identity();
  std::string space;
};

/// The course's normalisation of a PHIGS view, step by step (seed 004, "VRC - NDC"): world to
/// the normalised view volume, the cube [-1,1]^3 with the front plane at z = +1 and the back
/// plane at z = -1 (right-handed like VRC: OpenGL's NDC with z negated), after the division
/// by w. dop = CW - PRP, CW = ((umin+umax)/2, (vmin+vmax)/2, 0), pn = PRP's n.
///   perspective: N = Mpp * Sfar * Sper * SHper * T(-PRP) * R * T(-VRP)
///     T(-VRP), R (rows u, v, n; space "vrc"), T(-PRP) (the centre of projection at the
///     origin), SHper = [[1,0,-dop_u/dop_n,0],[0,1,-dop_v/dop_n,0],[0,0,1,0],[0,0,0,1]] (the
///     centre line onto the -z axis; space "sheared"), Sper = diag(2 pn / (umax-umin),
///     2 pn / (vmax-vmin), 1, 1) (the side planes at 45 degrees, x = +-z, y = +-z; space
///     "opening_45"), Sfar = uniform scale by 1 / (pn - B) (the back plane at z = -1, the
///     front plane at z_min = -(pn - F) / (pn - B)), Mpp = [[1,0,0,0],[0,1,0,0],
///     [0,0,(1-z_min)/(1+z_min),-2 z_min/(1+z_min)],[0,0,-1,0]] (the truncated pyramid to the
///     cube; the centre of projection goes to infinity; space "normalised").
///   parallel: N = Spar * Tpar * SHpar * T(-PRP) * R * T(-VRP)
///     the same first steps and shear (DOP onto -z; space "sheared"), Tpar = T(0, 0,
///     pn - (F + B) / 2) (the volume's centre to the origin), Spar = diag(2 / (umax-umin),
///     2 / (vmax-vmin), 2 / (F-B), 1) (space "normalised").
/// The product equals the view mapping times the orientation (phigs_view_matrices) up to the
/// sign of z and a positive factor. Throws usage_error as phigs_view_matrices does, and
/// ("prp") when PRP lies on the view plane (pn = 0: the steps have no 45 degree opening).
EXBSP_EXPORT std::vector<phigs_step> phigs_normalisation(const phigs_view& p);

}  // namespace exbsp::view
