// The catalogue of effects a scene may name under "effects" (DESIGN.md section 5), and where
// each plugs into the stage list (pipeline.h). An effect runs only when the scene names it:
// a scene that names none gets exactly the stages build, order, transform+clip, raster (or
// svg), and pays for nothing else.
//
// Hooks (stage list order):
//   after_order      world-space fragments in back-to-front order (f.order, f.fragments):
//                    backface_culling, lighting (per-fragment colour).
//   after_transform  window-space polygons (f.polygons), after the curves stage when there
//                    are curves: fog (prepares per-pixel fog for the painters).
//   raster           replaces the "raster" stage (PNG only): antialias.
//   after_raster     the finished image (PNG only); such a stage may re-run the per-view
//                    stages for other views: depth_of_field.
// The parameters of each effect are in frame::settings (effect_settings.h). Effects designed
// but not implemented yet would be listed with available = false; the scene parser rejects
// those with a "not supported yet" error.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "pipeline.h"

namespace exbsp::view {

/// Where an effect's stage is inserted.
enum class effect_hook { after_order, after_transform, raster, after_raster };

/// One known effect.
struct effect_description {
  std::string name;
  effect_hook hook;
  bool available;                          ///< false: known name, not implemented yet
  std::function<std::string(frame&)> run;  ///< the stage (hooks after_order, after_transform, raster)
  /// after_raster stages: also given the per-view stages ("order" up to raster/antialias) to
  /// render other views of the same BSP.
  std::function<std::string(frame&, const pipeline&)> run_with_views;
  bool png_only = false;                   ///< no stage in SVG output
};

/// All known effects, implemented or not, in stage order within each hook.
const std::vector<effect_description>& effect_catalog();

/// The effect called `name`, or nullptr.
const effect_description* find_effect(const std::string& name);

/// Output of the pipeline.
enum class output_kind { png, svg, pdf };

/// The stages that depend on the view, for `output` with the named effects (each must be
/// available; throws usage_error otherwise), in this order:
///   order, [after_order effects], transform+clip, [curves when `curves`],
///   [after_transform effects], then for PNG: raster (or the raster effect, antialias),
///   [after_raster effects]; for SVG: svg, for PDF: pdf (png_only effects have no stage).
/// Re-running these stages on a frame whose "build" ran renders another view of the same BSP.
pipeline per_view_pipeline(const std::vector<std::string>& effects, output_kind output, bool curves = false);

/// "build" followed by per_view_pipeline(effects, output, curves). The caller appends the
/// "write" stage.
pipeline standard_pipeline(const std::vector<std::string>& effects, output_kind output, bool curves = false);

/// The effects among `effects` that have no stage in `output` (png_only effects for SVG and PDF).
std::vector<std::string> effects_without_stage(const std::vector<std::string>& effects, output_kind output);

}  // namespace exbsp::view
