// SPDX-License-Identifier: LGPL-3.0-or-later
// Liang–Barsky clipping (see liang_barsky.h for the p/q notation).
// Boundaries are numbered 2k: min[k], 2k+1: max[k] (parametric_interval's entry / exit).
#include <exbsp/clip/liang_barsky.h>

#include <cstddef>

#include "clip/clip_checks.h"

namespace exbsp::clip {
namespace {

template <std::size_t N>
std::array<double, N> clamped(std::array<double, N> p, const box<N>& b) {
  for (std::size_t k = 0; k < N; ++k) p[k] = detail::clamp_to(p[k], b.min[k], b.max[k]);
  return p;
}

template <std::size_t N>
std::array<double, N> point_at(const segment<N>& s, double t, int boundary, const box<N>& b) {
  std::array<double, N> p;
  for (std::size_t k = 0; k < N; ++k)
    p[k] = detail::clamp_to(detail::lerp_within(s.p0[k], s.p1[k], t), b.min[k], b.max[k]);
  const std::size_t axis = static_cast<std::size_t>(boundary / 2);
  p[axis] = (boundary % 2) ? b.max[axis] : b.min[axis];
  return p;
}

template <std::size_t N>
std::optional<liang_barsky_result<N>> clip_n(const segment<N>& s, const box<N>& b,
                                             const char* function) {
  detail::require_finite(s.p0, function, "segment start");
  detail::require_finite(s.p1, function, "segment end");
  detail::require_valid_box(b, function);

  detail::parametric_interval kept;
  for (std::size_t k = 0; k < N; ++k) {
    const double d = s.p1[k] - s.p0[k];
    if (!kept.add(-d, s.p0[k] - b.min[k], static_cast<int>(2 * k)) ||
        !kept.add(d, b.max[k] - s.p0[k], static_cast<int>(2 * k + 1)))
      return std::nullopt;
  }
  if (kept.empty()) return std::nullopt;
  const double t0 = kept.t0, t1 = kept.t1;
  const int entry = kept.entry, exit = kept.exit;

  // An end kept by its own parameter (t0 == 0 or t1 == 1) can still be a few ulps outside
  // when the ratio rounded onto the end; clamping is the identity for points inside.
  liang_barsky_result<N> result{t0, t1, {clamped(s.p0, b), clamped(s.p1, b)}};
  if (entry >= 0) result.clipped.p0 = point_at(s, t0, entry, b);
  if (exit >= 0) result.clipped.p1 = point_at(s, t1, exit, b);
  return result;
}

}  // namespace

std::optional<liang_barsky_result2> liang_barsky_clip(const segment2& s, const window2& window) {
  return clip_n(s, window, "liang_barsky_clip");
}

std::optional<liang_barsky_result3> liang_barsky_clip(const segment3& s, const box3& box) {
  return clip_n(s, box, "liang_barsky_clip");
}

}  // namespace exbsp::clip
