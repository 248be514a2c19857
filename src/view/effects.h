// SPDX-License-Identifier: LGPL-3.0-or-later
// The catalogue of effects a scene may name under "effects" (docs/contract.md "Scenes"), and where
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
// One entry per effect describes its stage: its name, its hook and its stage. The parameters of
// each effect travel in frame::settings (effect_settings.h), typed; a scene's JSON parameters
// are read into them by the scene module (scene/effect_parameters.h: JSON stops at scene).
// Adding an effect: its settings struct, its file (view/<effect>.{h,cpp}: its stage), one line
// in effect_catalog() and its parameter reader in scene/effect_parameters.cpp.
// Effects designed but not implemented yet would be listed with available = false; the scene
// parser rejects those with a "not supported yet" error. The stage lists built from this
// catalogue are declared in standard_pipeline.h (public, free of JSON types).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <exbsp/view/pipeline.h>
#include <exbsp/view/standard_pipeline.h>

namespace exbsp::view {

/// Where an effect's stage is inserted.
enum class effect_hook { after_order, after_transform, raster, after_raster };

/// One known effect.
struct effect_description {
  std::string name;
  effect_hook hook;
  bool available;  ///< false: known name, not implemented yet
  std::function<std::string(frame&)>
      run;  ///< the stage (hooks after_order, after_transform, raster)
  /// after_raster stages: also given the per-view stages ("order" up to raster/antialias) to
  /// render other views of the same BSP.
  std::function<std::string(frame&, const pipeline&)> run_with_views;
  bool png_only = false;  ///< no stage in SVG output
};

/// All known effects, implemented or not, in stage order within each hook.
const std::vector<effect_description>& effect_catalog();

/// The effect called `name`, or nullptr.
const effect_description* find_effect(const std::string& name);

}  // namespace exbsp::view
