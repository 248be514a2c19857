// SPDX-License-Identifier: LGPL-3.0-or-later
// The effects' parameter readers (effect_parameters.h).
#include "scene/effect_parameters.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <exbsp/core/errors.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/matrix.h>

namespace exbsp::scene {

namespace {

using view::antialias_settings;
using view::depth_of_field_settings;
using view::effect_scene;
using view::effect_settings;
using view::fog_mode;
using view::fog_settings;
using view::lighting_settings;

/// The parameters reader of an effect that takes none.
void no_parameters(const reader& r, const json& params, const std::string& key, const effect_scene&,
                   effect_settings&) {
  r.reject_unknown(params, key, key.substr(key.rfind('/') + 1), {});
}

/// "lighting" parameters into out.lighting; scene_error names the bad key. Parameters and
/// defaults: direction [0,0,1] (towards the light, not zero), intensity 0.8 (>= 0), ambient
/// 0.2 (>= 0), two_sided true, headlight false, specular 0 (>= 0), shininess 32 (>= 0), lights
/// [] (at most max_lights - 1 objects, each one of "direction" (not zero), "position" or
/// "headlight": true, and "intensity", default 0.8), smooth false, crease_deg 30 (in (0, 180]).
void parse_lighting_parameters(const reader& r, const json& p, const std::string& key,
                               const effect_scene&, effect_settings& out) {
  lighting_settings& l = out.lighting;
  r.reject_unknown(p, key, "lighting",
                   {"direction", "intensity", "ambient", "two_sided", "headlight", "specular",
                    "shininess", "lights", "smooth", "crease_deg"});
  // A direction or position whose length is zero or overflows cannot be normalised.
  const auto vector_at = [&](const json& v, const std::string& at, bool zero_ok) {
    const view::vector3 d = r.triple(v, at);
    const double length = view::length(d);
    if (!std::isfinite(length)) r.fail(at, "too large: its length overflows a double");
    if (!zero_ok && !(length > 0)) r.fail(at, "must not be the zero vector");
    return d;
  };
  if (const json* v = r.optional(p, "direction"))
    l.direction = vector_at(*v, key + "/direction", false);
  if (const json* v = r.optional(p, "intensity"))
    l.intensity = r.positive(*v, key + "/intensity", true);
  if (const json* v = r.optional(p, "ambient")) l.ambient = r.positive(*v, key + "/ambient", true);
  const auto flag = [&](const json& obj, const std::string& at, const char* name, bool& out) {
    if (const json* v = r.optional(obj, name)) {
      if (!v->is_boolean()) r.fail(at + "/" + name, "must be true or false");
      out = v->get<bool>();
    }
  };
  flag(p, key, "two_sided", l.two_sided);
  flag(p, key, "headlight", l.headlight);
  if (l.headlight && p.contains("direction"))
    r.fail(key + "/direction", "a headlight comes from the eye: give direction or headlight");
  if (const json* v = r.optional(p, "specular"))
    l.specular = r.positive(*v, key + "/specular", true);
  if (const json* v = r.optional(p, "shininess"))
    l.shininess = r.positive(*v, key + "/shininess", true);
  flag(p, key, "smooth", l.smooth);
  if (const json* v = r.optional(p, "crease_deg")) {
    l.crease_deg = r.positive(*v, key + "/crease_deg", false);
    if (l.crease_deg > 180) r.fail(key + "/crease_deg", "must be in (0, 180]");
  }
  r.for_each_entry(p, key, "lights", [&](const json& e, const std::string& at) {
    if (l.lights.size() + 1 >= view::max_lights)
      r.fail(key + "/lights", "at most " + std::to_string(view::max_lights - 1) + " more lights (" +
                                  std::to_string(view::max_lights) +
                                  " in all, as OpenGL's GL_MAX_LIGHTS)");
    const json& entry = r.object(e, at);
    r.reject_unknown(entry, at, "light", {"direction", "position", "headlight", "intensity"});
    view::light_source light;
    bool head = false;
    flag(entry, at, "headlight", head);
    const int given = entry.contains("direction") + entry.contains("position") + head;
    if (given != 1)
      r.fail(at, "give exactly one of \"direction\", \"position\" or \"headlight\": true");
    if (const json* v = r.optional(entry, "direction")) {
      light.where = vector_at(*v, at + "/direction", false);
    } else if (const json* v = r.optional(entry, "position")) {
      light.kind = view::light_source::kind_type::point;
      light.where = vector_at(*v, at + "/position", true);
    } else {
      light.kind = view::light_source::kind_type::headlight;
    }
    if (const json* v = r.optional(entry, "intensity"))
      light.intensity = r.positive(*v, at + "/intensity", true);
    l.lights.push_back(light);
  });
}

/// "fog" parameters into out.fog; scene_error names the bad key. Parameters and defaults:
/// mode "linear" (start = near, end = far; 0 <= start < end) or "exp" (density > 0, default
/// ln(255)/far: 1/255 visibility at the far plane); color = the scene's background. A linear
/// end beyond the far plane is warned about.
void parse_fog_parameters(const reader& r, const json& p, const std::string& key,
                          const effect_scene& scene, effect_settings& out) {
  fog_settings& f = out.fog;
  r.reject_unknown(p, key, "fog", {"mode", "start", "end", "density", "color"});
  f.mode = fog_mode::linear;
  if (const json* v = r.optional(p, "mode")) {
    const std::string m = v->is_string() ? v->get<std::string>() : std::string();
    if (m == "exp")
      f.mode = fog_mode::exponential;
    else if (m != "linear")
      r.fail(key + "/mode", "must be \"linear\" or \"exp\"");
  }
  const double near_dist = scene.near_dist, far_dist = scene.far_dist;
  if (f.mode == fog_mode::linear) {
    if (p.contains("density"))
      r.fail(key + "/density", "only for mode \"exp\" (linear fog takes start and end)");
    f.start = near_dist;
    f.end = far_dist;
    if (const json* v = r.optional(p, "start")) f.start = r.positive(*v, key + "/start", true);
    if (const json* v = r.optional(p, "end")) f.end = r.positive(*v, key + "/end");
    if (!(f.end > f.start))
      r.fail(key + "/end", "must be greater than start (start " + number_text(f.start) + ", end " +
                               number_text(f.end) + ")");
    if (f.end > far_dist)
      r.warn(key + "/end", "fog ends beyond the far plane (" + number_text(far_dist) +
                               "): geometry cut by the far plane will pop instead of fading");
  } else {
    if (p.contains("start"))
      r.fail(key + "/start", "only for mode \"linear\" (exp fog takes density)");
    if (p.contains("end")) r.fail(key + "/end", "only for mode \"linear\" (exp fog takes density)");
    f.density = std::log(255.0) / far_dist;
    if (const json* v = r.optional(p, "density")) f.density = r.positive(*v, key + "/density");
  }
  f.color = scene.background;
  if (const json* v = r.optional(p, "color")) f.color = r.color(*v, key + "/color");
}

/// The optional integer p["samples"] into `out` when present; scene_error unless it is in
/// [lo, hi].
void read_samples(const reader& r, const json& p, const std::string& key, long long lo,
                  long long hi, int& out) {
  const json* v = r.optional(p, "samples");
  if (!v) return;
  const long long n = r.integer(*v, key + "/samples");
  if (n < lo || n > hi)
    r.fail(key + "/samples", "must be in " + std::to_string(lo) + ".." + std::to_string(hi) +
                                 " (got " + std::to_string(n) + ")");
  out = static_cast<int>(n);
}

/// "antialias" parameters into out.antialias; scene_error names the bad key. Parameter:
/// samples 4 (N in 1..8: N x N sub-pixels; N times the viewport must stay within
/// scene.max_side).
void parse_antialias_parameters(const reader& r, const json& p, const std::string& key,
                                const effect_scene& scene, effect_settings& out) {
  antialias_settings& a = out.antialias;
  r.reject_unknown(p, key, "antialias", {"samples"});
  read_samples(r, p, key, 1, 8, a.samples);
  if (static_cast<long long>(std::max(scene.width, scene.height)) * a.samples > scene.max_side)
    r.fail(key + "/samples", "the supersampled image would exceed " +
                                 std::to_string(scene.max_side) + " pixels a side (viewport " +
                                 std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                                 ")");
}

/// "depth_of_field" parameters into out.depth_of_field; scene_error names the bad key (also
/// for a parallel projection: perspective and frustum only, a parallel view has no lens).
/// Parameters: focal_length (> 0, required), aperture (lens diameter > 0) or f_number (> 0;
/// aperture = focal_length / f_number), exactly one of them, focus_distance (> focal_length,
/// required), samples 32 (2..1024).
void parse_depth_of_field_parameters(const reader& r, const json& p, const std::string& key,
                                     const effect_scene& scene, effect_settings& out) {
  depth_of_field_settings& d = out.depth_of_field;
  r.reject_unknown(p, key, "depth_of_field",
                   {"focal_length", "aperture", "f_number", "focus_distance", "samples"});
  if (scene.parallel)
    r.fail(key, "needs a perspective or frustum projection (a parallel projection has no lens)");
  d.focal_length = r.positive(r.require(p, key, "focal_length"), key + "/focal_length");
  const json* aperture = r.optional(p, "aperture");
  const json* f_number = r.optional(p, "f_number");
  if (aperture && f_number) r.fail(key + "/f_number", "give aperture or f_number, not both");
  if (!aperture && !f_number)
    r.fail(key + "/aperture", "missing key (the lens diameter; or give f_number)");
  d.aperture = aperture ? r.positive(*aperture, key + "/aperture")
                        : d.focal_length / r.positive(*f_number, key + "/f_number");
  if (!(std::isfinite(d.aperture) && d.aperture > 0))
    r.fail(key + "/f_number", "gives an impossible aperture");
  d.focus_distance = r.positive(r.require(p, key, "focus_distance"), key + "/focus_distance");
  // The lens samples shift the eye by up to half the aperture: a lens a thousand times wider
  // than the distance it focuses at is no lens, and wider still the shifted cameras are lost
  // to rounding (checked here, before any build).
  if (!(d.aperture <= 1000 * d.focus_distance))
    r.fail(aperture ? key + "/aperture" : key + "/f_number",
           "gives an aperture of " + number_text(d.aperture) +
               ", more than 1000 times focus_distance");
  if (!(d.focus_distance > d.focal_length))
    r.fail(key + "/focus_distance",
           "must be greater than focal_length (a thin lens cannot focus closer than f)");
  read_samples(r, p, key, 2, 1024, d.samples);
}

/// "exposure" parameters into out.exposure; scene_error names the bad key. Parameters:
/// shutter 0.5 (in (0, 1]), samples 8 (2..1024), camera_end {"eye", "look_at", "up"}
/// (required: the camera at the next frame; eye and look_at distinct, up not along the gaze).
void parse_exposure_parameters(const reader& r, const json& p, const std::string& key,
                               const effect_scene&, effect_settings& out) {
  view::exposure_settings& e = out.exposure;
  r.reject_unknown(p, key, "exposure", {"shutter", "samples", "camera_end"});
  if (const json* v = r.optional(p, "shutter")) {
    e.shutter = r.positive(*v, key + "/shutter");
    if (e.shutter > 1)
      r.fail(key + "/shutter", "must be in (0, 1]: the fraction of the frame the shutter is open");
  }
  read_samples(r, p, key, 2, 1024, e.samples);
  const std::string at = key + "/camera_end";
  const json& c = r.object(r.require(p, key, "camera_end"), at);
  r.reject_unknown(c, at, "camera_end", {"eye", "look_at", "up"});
  const view::vector3 eye = r.triple(r.require(c, at, "eye"), at + "/eye");
  const view::vector3 look = r.triple(r.require(c, at, "look_at"), at + "/look_at");
  e.camera_end = {{eye.x, eye.y, eye.z},
                  {look.x, look.y, look.z},
                  r.triple(r.require(c, at, "up"), at + "/up")};
  try {
    view::look_at(e.camera_end);
  } catch (const usage_error& err) {
    r.fail(at, err.what());
  }
}

const std::pair<const char*, effect_parameters_reader> readers[] = {
    {"backface_culling", no_parameters},
    {"lighting", parse_lighting_parameters},
    {"fog", parse_fog_parameters},
    {"antialias", parse_antialias_parameters},
    {"depth_of_field", parse_depth_of_field_parameters},
    {"exposure", parse_exposure_parameters},
};

}  // namespace

effect_parameters_reader effect_parameters(const std::string& name) {
  for (const auto& [effect, read] : readers)
    if (name == effect) return read;
  return nullptr;
}

std::vector<std::string> effects_with_parameters() {
  std::vector<std::string> out;
  for (const auto& row : readers) out.emplace_back(row.first);
  return out;
}

}  // namespace exbsp::scene
