// SPDX-License-Identifier: LGPL-3.0-or-later
// Accumulation of views for the effects that average renders (depth of field over a lens,
// exposure over a camera path): view 0 is the frame's own picture, views 1..n-1 are rendered
// with the per-view stages, the picture becomes their rounded mean, and every other product
// of the frame is restored to view 0's.
#pragma once
#include <cstddef>
#include <functional>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// Renders view_of(k) for k = 1..count-1 with `per_view` and sets f.picture to the rounded
/// mean of the count pictures (f.picture is view 0's on entry). `effect` names the effect in
/// errors (usage_error when a view changes the image size).
void accumulate_views(frame& f, const pipeline& per_view, std::size_t count,
                      const std::function<view_setup(std::size_t)>& view_of, const char* effect);

}  // namespace exbsp::view
