// SPDX-License-Identifier: LGPL-3.0-or-later
// Segment clipping in clip space: Liang–Barsky and Cohen–Sutherland (notation in
// homogeneous_segment.h).
#include <exbsp/clip/homogeneous_segment.h>

#include <cmath>

#include <exbsp/clip/homogeneous.h>
#include <exbsp/clip/liang_barsky.h>

namespace exbsp::clip {

namespace {

/// d_k(p) for the six planes, in the order of homogeneous_segment.h.
double plane_distance(int k, const vec4d& p) {
  switch (k) {
    case 0:
      return p[3] + p[0];
    case 1:
      return p[3] - p[0];
    case 2:
      return p[3] + p[1];
    case 3:
      return p[3] - p[1];
    case 4:
      return p[3] + p[2];
    default:
      return p[3] - p[2];
  }
}

/// Puts p exactly on plane k (the coordinate the plane constrains becomes +-w).
void snap_to_plane(int k, vec4d& p) {
  const std::size_t axis = static_cast<std::size_t>(k / 2);
  p[axis] = k % 2 == 0 ? -p[3] : p[3];
}

vec4d lerp(const vec4d& a, const vec4d& b, double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]),
          a[3] + t * (b[3] - a[3])};
}

bool finite(const vec4d& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(p[3]);
}

}  // namespace

bool homogeneous_liang_barsky(const vec4d& a, const vec4d& b, vec4d& out_a, vec4d& out_b,
                              double* t0_out, double* t1_out) {
  if (!finite(a) || !finite(b)) return false;
  // d_k(P(t)) = da + t (db - da) >= 0 is (da - db) t <= da.
  detail::parametric_interval kept;
  for (int k = 0; k < 6; ++k) {
    const double da = plane_distance(k, a), db = plane_distance(k, b);
    if (da < 0 && db < 0) return false;
    kept.add(da - db, da, k);
  }
  if (kept.empty()) return false;
  out_a = kept.entry < 0 ? a : lerp(a, b, kept.t0);
  out_b = kept.exit < 0 ? b : lerp(a, b, kept.t1);
  if (kept.entry >= 0) snap_to_plane(kept.entry, out_a);
  if (kept.exit >= 0) snap_to_plane(kept.exit, out_b);
  if (t0_out) *t0_out = kept.t0;
  if (t1_out) *t1_out = kept.t1;
  return true;
}

bool homogeneous_cohen_sutherland(const vec4d& a, const vec4d& b, vec4d& out_a, vec4d& out_b,
                                  double* t0_out, double* t1_out) {
  if (!finite(a) || !finite(b)) return false;
  double t0 = 0, t1 = 1;
  int enter_plane = -1, leave_plane = -1;
  vec4d pa = a, pb = b;
  for (int moves = 0; moves < 12; ++moves) {
    const unsigned ca = homogeneous_outcode(pa), cb = homogeneous_outcode(pb);
    if ((ca | cb) == 0) break;
    if ((ca & cb) != 0) return false;
    const bool move_a = ca != 0;
    const unsigned code = move_a ? ca : cb;
    int k = 0;
    while (!((code >> k) & 1u)) ++k;
    const double da = plane_distance(k, a), db = plane_distance(k, b);
    if (!(da != db)) return false;  // parallel to the plane and outside it: rounding noise only
    const double t = da / (da - db);
    if (move_a) {
      if (t > t0) t0 = t;
      enter_plane = k;
      pa = lerp(a, b, t0);
      snap_to_plane(k, pa);
    } else {
      if (t < t1) t1 = t;
      leave_plane = k;
      pb = lerp(a, b, t1);
      snap_to_plane(k, pb);
    }
    if (t0 > t1) return false;
  }
  // After 12 moves only rounding can leave a bit set (each move snaps its end onto a plane).
  if ((homogeneous_outcode(pa) & homogeneous_outcode(pb)) != 0) return false;
  if (t0_out) *t0_out = t0;
  if (t1_out) *t1_out = t1;
  out_a = enter_plane < 0 ? a : pa;
  out_b = leave_plane < 0 ? b : pb;
  return true;
}

}  // namespace exbsp::clip
