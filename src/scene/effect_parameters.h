// SPDX-License-Identifier: LGPL-3.0-or-later
// The effects' parameters as a scene gives them (docs/contract.md "Scenes", "effects"): one
// reader per effect of view's catalogue (view/effects.h), from a JSON object to the effect's
// typed member of effect_settings, with defaults and checks; every failure is a scene_error
// naming the parameter's key. JSON stops at scene: view sees the typed settings only.
// Adding an effect: its reader here and one row in effect_parameter_readers(), beside its
// row in view's catalogue (tests/test_effects.cpp checks that every effect has a reader).
#pragma once
#include <string>
#include <vector>

#include <exbsp/view/effect_settings.h>
#include "scene/json_reader.h"

namespace exbsp::scene {

/// Reads an effect's parameters `params` (a JSON object; {} for `true`) at JSON pointer `key`
/// into its member of `out`; throws scene_error naming the bad or unknown parameter's key.
using effect_parameters_reader = void (*)(const reader& r, const json& params,
                                          const std::string& key, const view::effect_scene& scene,
                                          view::effect_settings& out);

/// The parameter reader of the effect called `name`, or nullptr.
effect_parameters_reader effect_parameters(const std::string& name);

/// The effects that have a parameter reader, for the test that every catalogue effect has one.
std::vector<std::string> effects_with_parameters();

}  // namespace exbsp::scene
