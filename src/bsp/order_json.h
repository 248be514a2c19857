// The `exbsp order` document (DESIGN.md section 4): {"eye" | "direction": [x, y, z],
// "kernel", "heuristic", "fragments": [{"face", "v", "exact"}, ...]} back to front, "v" with
// 17 significant digits, "exact" (exact kernels only) as reduced rationals.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bsp/engine.h"
#include "core/atomic_file.h"

namespace exbsp {

/// The order document of `tree` for the fragment indices `order` (back to front), seen from
/// the eye point `where` (use_eye) or along the direction of projection `where`, passed to
/// `sink` in pieces of about a megabyte: the document (about 600 bytes per fragment with
/// exact coordinates) is never held whole.
void order_json(const bsp& tree, const std::vector<std::uint32_t>& order, const vec3d& where,
                bool use_eye, const output_sink& sink);

}  // namespace exbsp
