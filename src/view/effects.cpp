// SPDX-License-Identifier: LGPL-3.0-or-later
// Effect catalogue and the standard stage list (see effects.h for the hooks).
#include "view/effects.h"

#include <algorithm>

#include <exbsp/core/errors.h>
#include <exbsp/view/stages.h>
#include "view/antialias.h"
#include "view/backface_culling.h"
#include "view/curves.h"
#include "view/depth_of_field.h"
#include "view/exposure.h"
#include "view/fog.h"
#include "view/lighting.h"

namespace exbsp::view {

const std::vector<effect_description>& effect_catalog() {
  static const std::vector<effect_description> catalog = {
      {"backface_culling", effect_hook::after_order, true, backface_culling_stage, {}, false},
      {"lighting", effect_hook::after_order, true, lighting_stage, {}, false},
      {"fog", effect_hook::after_transform, true, fog_stage, {}, false},
      {"antialias", effect_hook::raster, true, antialias_stage, {}, true},
      {"depth_of_field", effect_hook::after_raster, true, {}, depth_of_field_stage, true},
      {"exposure", effect_hook::after_raster, true, {}, exposure_stage, true},
  };
  return catalog;
}

const effect_description* find_effect(const std::string& name) {
  for (const effect_description& e : effect_catalog())
    if (e.name == name) return &e;
  return nullptr;
}

namespace {

/// The catalogue entries named in `effects`, in catalogue order; throws usage_error for
/// unknown or unavailable names.
std::vector<const effect_description*> chosen_effects(const std::vector<std::string>& effects) {
  for (const std::string& name : effects) {
    const effect_description* e = find_effect(name);
    if (!e) throw usage_error("unknown effect: " + name);
    if (!e->available) throw usage_error("effect not supported yet: " + name);
  }
  std::vector<const effect_description*> chosen;
  for (const effect_description& e : effect_catalog())
    if (std::find(effects.begin(), effects.end(), e.name) != effects.end()) chosen.push_back(&e);
  return chosen;
}

}  // namespace

pipeline per_view_pipeline(const std::vector<std::string>& effects, output_kind output,
                           bool curves) {
  const std::vector<const effect_description*> chosen = chosen_effects(effects);
  auto has_hook = [&](effect_hook hook) {
    return std::any_of(chosen.begin(), chosen.end(), [&](const effect_description* e) {
      return e->hook == hook && !(e->png_only && output != output_kind::png);
    });
  };
  auto add_hook = [&](pipeline& p, effect_hook hook) {
    for (const effect_description* e : chosen)
      if (e->hook == hook && !(e->png_only && output != output_kind::png)) p.add(e->name, e->run);
  };
  pipeline p;
  p.add("order", order_stage);
  add_hook(p, effect_hook::after_order);
  p.add("transform+clip", transform_clip_stage);
  if (curves) p.add("curves", curves_stage);
  add_hook(p, effect_hook::after_transform);
  if (output != output_kind::png) {
    p.add(output == output_kind::svg ? "svg" : "pdf",
          output == output_kind::svg ? svg_stage : pdf_stage);
    return p;
  }
  if (has_hook(effect_hook::raster))
    add_hook(p, effect_hook::raster);
  else
    p.add("raster", raster_stage);
  if (has_hook(effect_hook::after_raster)) {
    // Each after_raster stage may re-render other views with the stages before it.
    const pipeline views = p;
    for (const effect_description* e : chosen)
      if (e->hook == effect_hook::after_raster) {
        auto run = e->run_with_views;
        p.add(e->name, [run, views](frame& f) { return run(f, views); });
      }
  }
  return p;
}

pipeline standard_pipeline(const std::vector<std::string>& effects, output_kind output,
                           bool curves) {
  pipeline p;
  p.add("build", build_stage);
  const pipeline views = per_view_pipeline(effects, output, curves);
  for (const stage& s : views.stages()) p.add(s.name, s.run);
  return p;
}

std::vector<std::string> effects_without_stage(const std::vector<std::string>& effects,
                                               output_kind output) {
  std::vector<std::string> out;
  if (output == output_kind::png) return out;
  for (const effect_description* e : chosen_effects(effects))
    if (e->png_only) out.push_back(e->name);
  return out;
}

}  // namespace exbsp::view
