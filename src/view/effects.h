// The catalogue of effects a scene may name under "effects" (DESIGN.md section 5), and where
// each plugs into the stage list (pipeline.h). An effect runs only when the scene names it.
//
// Hooks:
//   after_order      world-space fragments in back-to-front order (f.order, f.fragments):
//                    backface_culling; later lighting (per-fragment colour).
//   after_transform  window-space polygons (f.polygons): later fog (colour by depth).
//   after_raster     the finished image (f.picture, PNG output only): later antialias,
//                    depth_of_field.
// Effects that are designed but not implemented yet are listed with available = false; the
// scene parser rejects them with a "not supported yet" error.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "view/pipeline.h"

namespace exbsp::view {

/// Where an effect's stage is inserted.
enum class effect_hook { after_order, after_transform, after_raster };

/// One known effect.
struct effect_description {
  std::string name;
  effect_hook hook;
  bool available;                          ///< false: known name, not implemented yet
  std::function<std::string(frame&)> run;  ///< the stage; empty when not available
};

/// All known effects, implemented or not.
const std::vector<effect_description>& effect_catalog();

/// The effect called `name`, or nullptr.
const effect_description* find_effect(const std::string& name);

/// Output of the pipeline.
enum class output_kind { png, svg };

/// The standard stage list for `output` with the named effects (each must be available;
/// throws usage_error otherwise) at their hooks:
///   build, order, [after_order effects], transform+clip, [after_transform effects],
///   then raster, [after_raster effects] for PNG, or svg for SVG.
/// The caller appends the "write" stage.
pipeline standard_pipeline(const std::vector<std::string>& effects, output_kind output);

}  // namespace exbsp::view
