// SPDX-License-Identifier: LGPL-3.0-or-later
// The standard stage lists of the viewing pipeline (pipeline.h): "build", then the per-view
// stages with the effects a scene names (effects.h holds the effect catalogue they come
// from). Kept apart from effects.h so that the installed API needs no JSON types.
#pragma once
#include <string>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// Output of the pipeline.
enum class output_kind { png, svg, pdf };

/// The stages that depend on the view, for `output` with the named effects (each must be
/// available; throws usage_error otherwise), in this order:
///   order, [after_order effects], transform+clip, [curves when `curves`],
///   [after_transform effects], then for PNG: raster (or the raster effect, antialias),
///   [after_raster effects]; for SVG: svg, for PDF: pdf (png_only effects have no stage).
/// Re-running these stages on a frame whose "build" ran renders another view of the same BSP.
EXBSP_EXPORT pipeline per_view_pipeline(const std::vector<std::string>& effects, output_kind output,
                                        bool curves = false);

/// "build" followed by per_view_pipeline(effects, output, curves). The caller appends the
/// "write" stage.
EXBSP_EXPORT pipeline standard_pipeline(const std::vector<std::string>& effects, output_kind output,
                                        bool curves = false);

/// The effects among `effects` that have no stage in `output` (png_only effects for SVG and PDF).
EXBSP_EXPORT std::vector<std::string> effects_without_stage(const std::vector<std::string>& effects,
                                                            output_kind output);

}  // namespace exbsp::view
