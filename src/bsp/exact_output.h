// SPDX-License-Identifier: LGPL-3.0-or-later
// The tree's exact output: exact coordinates visited per fragment and written as text (the
// rationals themselves, their text and their rounding are geom/rational.h's), and the peak
// memory a build reports.
#pragma once
#include <gmp.h>

#include <array>
#include <cstddef>
#include <functional>
#include <string>

#include "geom/rational.h"

namespace exbsp {

/// Receives exact coordinates: vertex k (0..2), axis (0..2) and the canonical rational, valid
/// during the call.
using exact_visitor = std::function<void(int k, int axis, mpq_srcptr value)>;

/// The exact coordinates that visit_exact(visitor) reports, as text [vertex][axis].
template <class VisitExact>
std::array<std::array<std::string, 3>, 3> exact_text(VisitExact&& visit_exact) {
  std::array<std::array<std::string, 3>, 3> out;
  visit_exact(exact_visitor(
      [&](int k, int axis, mpq_srcptr q) { out[k][axis] = geom::rational_to_string(q); }));
  return out;
}

/// Peak resident set size of this process in bytes (Linux VmHWM), 0 when unknown.
std::size_t peak_rss_bytes();

}  // namespace exbsp
