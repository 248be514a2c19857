// SPDX-License-Identifier: LGPL-3.0-or-later
// Internal precondition checks of the floating-point clippers (not installed API).
// Every check throws exbsp::usage_error naming the function that was misused.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include <exbsp/clip/clip_types.h>
#include <exbsp/core/errors.h>

namespace exbsp::clip::detail {

template <std::size_t N>
bool all_finite(const std::array<double, N>& p) {
  for (double v : p)
    if (!std::isfinite(v)) return false;
  return true;
}

template <std::size_t N>
void require_finite(const std::array<double, N>& p, const char* function, const char* what) {
  if (!all_finite(p))
    throw usage_error(std::string(function) + ": " + what + " has a NaN or infinite coordinate");
}

template <std::size_t N>
void require_valid_box(const box<N>& b, const char* function) {
  require_finite(b.min, function, "box minimum");
  require_finite(b.max, function, "box maximum");
  for (std::size_t k = 0; k < N; ++k)
    if (b.min[k] > b.max[k])
      throw usage_error(std::string(function) + ": box minimum exceeds maximum on axis " +
                        std::to_string(k));
}

/// p[k] clamped into [lo, hi] (lo <= hi).
inline double clamp_to(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

/// a + t * (b - a) with t in [0, 1], kept within [min(a, b), max(a, b)] despite rounding.
inline double lerp_within(double a, double b, double t) {
  const double v = a + t * (b - a);
  return a <= b ? clamp_to(v, a, b) : clamp_to(v, b, a);
}

}  // namespace exbsp::clip::detail
