// SPDX-License-Identifier: LGPL-3.0-or-later
// The backface_culling effect (a world-space stage after "order").
//
// Notation: a fragment (a, b, c) keeps its source face's orientation; its normal is
// N = (b - a) x (c - a). V points from the surface towards the viewer: V = eye - a for
// perspective and frustum views, V = -d for parallel views with direction of projection d.
// The fragment is culled when N . V <= 0 (it faces away from the viewer, or is seen edge-on).
#pragma once
#include <string>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// True when fragment (a, b, c) faces away from the viewer of `view` (N . V <= 0).
bool is_back_facing(const fragment_d& fr, const view_setup& view);

/// "backface_culling": removes back-facing fragments from f.order (order kept); counts them
/// in f.culled.
std::string backface_culling_stage(frame& f);

}  // namespace exbsp::view
