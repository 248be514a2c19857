// Liang–Barsky in homogeneous coordinates (notation in segment_clip.h).
#include "view/segment_clip.h"

#include <cmath>

namespace exbsp::view {

namespace {

/// d_k(p) for the six planes, in the order of segment_clip.h.
double plane_distance(int k, const hpoint& p) {
  switch (k) {
    case 0: return p.w + p.x;
    case 1: return p.w - p.x;
    case 2: return p.w + p.y;
    case 3: return p.w - p.y;
    case 4: return p.w + p.z;
    default: return p.w - p.z;
  }
}

/// Puts p exactly on plane k (the coordinate the plane constrains becomes +-w).
void snap_to_plane(int k, hpoint& p) {
  switch (k) {
    case 0: p.x = -p.w; break;
    case 1: p.x = p.w; break;
    case 2: p.y = -p.w; break;
    case 3: p.y = p.w; break;
    case 4: p.z = -p.w; break;
    default: p.z = p.w; break;
  }
}

hpoint lerp(const hpoint& a, const hpoint& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z), a.w + t * (b.w - a.w)};
}

bool finite(const hpoint& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w); }

}  // namespace

bool clip_segment_to_view_volume(const hpoint& a, const hpoint& b, hpoint& out_a, hpoint& out_b, double* t0_out,
                                 double* t1_out) {
  if (!finite(a) || !finite(b)) return false;
  double t0 = 0, t1 = 1;
  int enter_plane = -1, leave_plane = -1;
  for (int k = 0; k < 6; ++k) {
    const double da = plane_distance(k, a), db = plane_distance(k, b);
    if (da < 0 && db < 0) return false;
    if (da < 0) {  // enters through plane k
      const double t = da / (da - db);
      if (t > t0) {
        t0 = t;
        enter_plane = k;
      }
    } else if (db < 0) {  // leaves through plane k
      const double t = da / (da - db);
      if (t < t1) {
        t1 = t;
        leave_plane = k;
      }
    }
  }
  if (t0 > t1) return false;
  out_a = enter_plane < 0 ? a : lerp(a, b, t0);
  out_b = leave_plane < 0 ? b : lerp(a, b, t1);
  if (enter_plane >= 0) snap_to_plane(enter_plane, out_a);
  if (leave_plane >= 0) snap_to_plane(leave_plane, out_b);
  if (t0_out) *t0_out = t0;
  if (t1_out) *t1_out = t1;
  return true;
}

}  // namespace exbsp::view
