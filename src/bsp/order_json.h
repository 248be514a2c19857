// SPDX-License-Identifier: LGPL-3.0-or-later
// The `exbsp order` document (docs/contract.md "Command line"): {"eye" | "direction": [x, y, z],
// "kernel", "heuristic", "fragments": [{"face", "v", "exact"}, ...], "non_finite_fragments"}
// back to front, "v" with 17 significant digits, "exact" (exact kernels only) as reduced
// rationals; fragments with a NaN or infinite corner (inexact kernels only) are left out and
// counted in "non_finite_fragments".
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "core/atomic_file.h"

namespace exbsp {

/// The order document of `tree` for the fragment indices `order` (back to front), seen from
/// the eye point `where` (use_eye) or along the direction of projection `where`, passed to
/// `sink` in pieces of about a megabyte: the document (about 600 bytes per fragment with
/// exact coordinates) is never held whole. Returns the number of fragments left out for a NaN
/// or infinite corner.
std::size_t order_json(const bsp& tree, const std::vector<std::uint32_t>& order, const vec3d& where,
                       bool use_eye, const output_sink& sink);

}  // namespace exbsp
