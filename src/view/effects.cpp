// Effect catalogue and the standard stage list (see effects.h for the hooks).
#include "view/effects.h"

#include "mesh/errors.h"
#include "view/backface_culling.h"
#include "view/stages.h"

namespace exbsp::view {

const std::vector<effect_description>& effect_catalog() {
  static const std::vector<effect_description> catalog = {
      {"backface_culling", effect_hook::after_order, true, backface_culling_stage},
      {"lighting", effect_hook::after_order, false, {}},
      {"fog", effect_hook::after_transform, false, {}},
      {"depth_of_field", effect_hook::after_raster, false, {}},
      {"antialias", effect_hook::after_raster, false, {}},
  };
  return catalog;
}

const effect_description* find_effect(const std::string& name) {
  for (const effect_description& e : effect_catalog())
    if (e.name == name) return &e;
  return nullptr;
}

pipeline standard_pipeline(const std::vector<std::string>& effects, output_kind output) {
  std::vector<const effect_description*> chosen;
  for (const std::string& name : effects) {
    const effect_description* e = find_effect(name);
    if (!e) throw usage_error("unknown effect: " + name);
    if (!e->available) throw usage_error("effect not supported yet: " + name);
    chosen.push_back(e);
  }
  auto add_hook = [&](pipeline& p, effect_hook hook) {
    for (const effect_description* e : chosen)
      if (e->hook == hook) p.add(e->name, e->run);
  };
  pipeline p;
  p.add("build", build_stage);
  p.add("order", order_stage);
  add_hook(p, effect_hook::after_order);
  p.add("transform+clip", transform_clip_stage);
  add_hook(p, effect_hook::after_transform);
  if (output == output_kind::png) {
    p.add("raster", raster_stage);
    add_hook(p, effect_hook::after_raster);
  } else {
    p.add("svg", svg_stage);
  }
  return p;
}

}  // namespace exbsp::view
