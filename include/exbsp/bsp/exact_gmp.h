// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact fragment coordinates as GMP rationals (optional part of the public API: it includes
// gmpxx.h, so a consumer needs GMP's C++ headers; exbsp::exbsp links gmpxx for it).
//
// bsp::fragment_exact gives the same values as reduced "p/q" strings; this header gives them
// as mpq_class, copied straight from the kernel's exact representation (no text round trip).
// Every value is canonical (reduced, positive denominator), so == on mpq_class is exact
// equality of points. Section points (clip/section.h) come as text; mpq_class(text) reads them.
#pragma once
#include <gmpxx.h>

#include <array>
#include <cstddef>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/export.h>

namespace exbsp {

/// Exact coordinates of a fragment: [vertex][axis].
using exact_triangle_mpq = std::array<std::array<mpq_class, 3>, 3>;

/// The exact coordinates of fragment i of `tree` (i < tree.fragment_count()). Throws
/// usage_error for an index out of range or an inexact kernel (epick, double). Thread-safe
/// for concurrent calls on one tree, like the other const members of bsp.
EXBSP_EXPORT exact_triangle_mpq fragment_exact_mpq(const bsp& tree, std::size_t i);

}  // namespace exbsp
