// SPDX-License-Identifier: LGPL-3.0-or-later
// Cyrus–Beck clipping (notation in cyrus_beck.h); its parametric interval is Liang–Barsky's.
#include <exbsp/clip/cyrus_beck.h>

#include <cmath>
#include <string>

#include <exbsp/clip/liang_barsky.h>
#include "clip/clip_checks.h"

namespace exbsp::clip {
namespace {

/// n·v and f(p) of a half-plane or half-space.
double normal_dot(const half_plane2& h, const vec2d& v) { return h.a * v[0] + h.b * v[1]; }
double normal_dot(const half_space3& h, const vec3d& v) {
  return h.n[0] * v[0] + h.n[1] * v[1] + h.n[2] * v[2];
}

template <std::size_t N, class H>
std::optional<cyrus_beck_result<N>> clip_n(const segment<N>& s, const std::vector<H>& region) {
  const char* function = "cyrus_beck_clip";
  detail::require_finite(s.p0, function, "segment start");
  detail::require_finite(s.p1, function, "segment end");
  std::array<double, N> d;
  for (std::size_t k = 0; k < N; ++k) d[k] = s.p1[k] - s.p0[k];
  detail::parametric_interval kept;
  for (std::size_t i = 0; i < region.size(); ++i) {
    const double nd = normal_dot(region[i], d), f0 = region[i].value(s.p0);
    if (!std::isfinite(nd) || !std::isfinite(f0))
      throw usage_error(std::string(function) + ": half-plane " + std::to_string(i) +
                        " has a NaN or infinite coefficient, or its values on the segment "
                        "overflow");
    if (!kept.add(-nd, f0, static_cast<int>(i))) return std::nullopt;
  }
  if (kept.empty()) return std::nullopt;
  const auto point_at = [&](double t) {
    std::array<double, N> p;
    for (std::size_t k = 0; k < N; ++k) p[k] = detail::lerp_within(s.p0[k], s.p1[k], t);
    return p;
  };
  cyrus_beck_result<N> result{kept.t0, kept.t1, s, kept.entry, kept.exit};
  if (kept.entry >= 0) result.clipped.p0 = point_at(kept.t0);
  if (kept.exit >= 0) result.clipped.p1 = point_at(kept.t1);
  return result;
}

}  // namespace

std::optional<cyrus_beck_result2> cyrus_beck_clip(const segment2& s,
                                                  const std::vector<half_plane2>& region) {
  return clip_n(s, region);
}

std::optional<cyrus_beck_result3> cyrus_beck_clip(const segment3& s,
                                                  const std::vector<half_space3>& region) {
  return clip_n(s, region);
}

}  // namespace exbsp::clip
