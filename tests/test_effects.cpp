// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of the opt-in effects (src/view/{lighting,fog,antialias,depth_of_field}.*), their
// parameters in scene files, the stage lists ("a scene that names no effect pays nothing"),
// and Bézier curves in the painter's sequence (src/view/curves.*, clip_stage.*,
// line_raster.h): the depth rule against a brute-force per-pixel depth oracle, SVG order,
// curves behind the eye, the line pixel rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/view/bezier.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
#include "scene/effect_parameters.h"
#include "scene/render.h"
#include "scene/scene.h"
#include "view/antialias.h"
#include "view/clip_stage.h"
#include "view/curves.h"
#include "view/depth_of_field.h"
#include "view/effects.h"
#include "view/fog.h"
#include "view/lighting.h"
#include "view/smooth_shading.h"
#include "view/line_raster.h"
#include "view/paint.h"
#include "view/rasterizer.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp;
using namespace exbsp::view;
using nlohmann::json;

// ---------------------------------------------------------------------------------------
// Helpers

using exbsp_test::add_quad;
using exbsp_test::perspective_frame;

void run(frame& f, const std::vector<std::string>& effects, output_kind out = output_kind::png) {
  standard_pipeline(effects, out, !f.curves.empty()).run(f, nullptr);
}

json valid_scene() {
  return json::parse(R"({
    "meshes": [{"file": "meshes/tri.off", "color": [200, 40, 40]}],
    "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0]},
    "projection": {"type": "perspective", "fovy_deg": 40, "near": 1, "far": 100},
    "viewport": {"width": 64, "height": 48},
    "background": [10, 20, 30]
  })");
}

scene::scene parse(const json& doc, std::ostream* warnings = nullptr) {
  return scene::parse_scene(doc, "/nowhere/scene.json", warnings);
}

/// The key of the scene_error for `doc` ("(no error)" when it parses).
std::string error_key(const json& doc, std::string* message = nullptr) {
  return exbsp_test::error_key([&] { parse(doc); }, message);
}

int count_color(const image& img, rgb8 c) {
  int n = 0;
  for (int j = 0; j < img.height(); ++j)
    for (int i = 0; i < img.width(); ++i) n += img.pixel(i, j) == c;
  return n;
}

int color_distance(rgb8 a, rgb8 b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

// ---------------------------------------------------------------------------------------
// Effect parameters in scene files

struct bad_effect {
  const char* name;
  json effects;
  const char* key;
};

TEST(EffectParsing, EveryErrorNamesTheEffectOrParameterKey) {
  const std::vector<bad_effect> cases = {
      {"unknown effect", {{"bloom", true}}, "/effects/bloom"},
      {"effect not an object", {{"fog", "thick"}}, "/effects/fog"},
      {"backface_culling takes no parameter",
       {{"backface_culling", {{"front", true}}}},
       "/effects/backface_culling/front"},
      {"lighting unknown parameter", {{"lighting", {{"colour", 3}}}}, "/effects/lighting/colour"},
      {"lighting direction zero",
       {{"lighting", {{"direction", {0, 0, 0}}}}},
       "/effects/lighting/direction"},
      {"lighting direction two numbers",
       {{"lighting", {{"direction", {0, 1}}}}},
       "/effects/lighting/direction"},
      {"lighting direction not a number",
       {{"lighting", {{"direction", {0, "up", 1}}}}},
       "/effects/lighting/direction/1"},
      {"lighting intensity negative",
       {{"lighting", {{"intensity", -0.5}}}},
       "/effects/lighting/intensity"},
      {"lighting ambient a string",
       {{"lighting", {{"ambient", "dim"}}}},
       "/effects/lighting/ambient"},
      {"lighting two_sided a number",
       {{"lighting", {{"two_sided", 1}}}},
       "/effects/lighting/two_sided"},
      {"lighting smooth a string", {{"lighting", {{"smooth", "yes"}}}}, "/effects/lighting/smooth"},
      {"lighting crease_deg zero",
       {{"lighting", {{"crease_deg", 0}}}},
       "/effects/lighting/crease_deg"},
      {"lighting crease_deg beyond 180",
       {{"lighting", {{"crease_deg", 200}}}},
       "/effects/lighting/crease_deg"},
      {"lighting headlight and direction",
       {{"lighting", {{"headlight", true}, {"direction", {0, 0, 1}}}}},
       "/effects/lighting/direction"},
      {"lighting direction overflows",
       {{"lighting", {{"direction", {1e200, 0, 0}}}}},
       "/effects/lighting/direction"},
      {"lighting specular negative",
       {{"lighting", {{"specular", -1}}}},
       "/effects/lighting/specular"},
      {"lighting lights not an array", {{"lighting", {{"lights", 3}}}}, "/effects/lighting/lights"},
      {"lighting light with two kinds",
       {{"lighting", {{"lights", {{{"direction", {0, 0, 1}}, {"position", {0, 0, 1}}}}}}}},
       "/effects/lighting/lights/0"},
      {"lighting light of no kind",
       {{"lighting", {{"lights", {{{"intensity", 1}}}}}}},
       "/effects/lighting/lights/0"},
      {"lighting light unknown key",
       {{"lighting", {{"lights", {{{"position", {0, 0, 1}}, {"colour", 1}}}}}}},
       "/effects/lighting/lights/0/colour"},
      {"lighting nine lights",
       {{"lighting", {{"lights", std::vector<json>(8, {{"headlight", true}})}}}},
       "/effects/lighting/lights"},
      {"fog unknown mode", {{"fog", {{"mode", "exp2"}}}}, "/effects/fog/mode"},
      {"fog end before start", {{"fog", {{"start", 10}, {"end", 5}}}}, "/effects/fog/end"},
      {"fog start negative", {{"fog", {{"start", -1}, {"end", 5}}}}, "/effects/fog/start"},
      {"fog density for linear",
       {{"fog", {{"mode", "linear"}, {"density", 0.1}}}},
       "/effects/fog/density"},
      {"fog exp density zero",
       {{"fog", {{"mode", "exp"}, {"density", 0}}}},
       "/effects/fog/density"},
      {"fog exp with start", {{"fog", {{"mode", "exp"}, {"start", 1}}}}, "/effects/fog/start"},
      {"fog colour out of range", {{"fog", {{"color", {0, 0, 256}}}}}, "/effects/fog/color/2"},
      {"fog unknown parameter", {{"fog", {{"height", 2}}}}, "/effects/fog/height"},
      {"dof without parameters",
       {{"depth_of_field", true}},
       "/effects/depth_of_field/focal_length"},
      {"dof focal length negative",
       {{"depth_of_field", {{"focal_length", -1}, {"aperture", 0.1}, {"focus_distance", 5}}}},
       "/effects/depth_of_field/focal_length"},
      {"dof aperture and f_number",
       {{"depth_of_field",
         {{"focal_length", 0.05}, {"aperture", 0.1}, {"f_number", 2}, {"focus_distance", 5}}}},
       "/effects/depth_of_field/f_number"},
      {"dof neither aperture nor f_number",
       {{"depth_of_field", {{"focal_length", 0.05}, {"focus_distance", 5}}}},
       "/effects/depth_of_field/aperture"},
      {"dof f_number zero",
       {{"depth_of_field", {{"focal_length", 0.05}, {"f_number", 0}, {"focus_distance", 5}}}},
       "/effects/depth_of_field/f_number"},
      {"dof focus inside the focal length",
       {{"depth_of_field", {{"focal_length", 2}, {"aperture", 0.1}, {"focus_distance", 1.5}}}},
       "/effects/depth_of_field/focus_distance"},
      {"dof focus missing",
       {{"depth_of_field", {{"focal_length", 0.05}, {"aperture", 0.1}}}},
       "/effects/depth_of_field/focus_distance"},
      {"dof one sample",
       {{"depth_of_field",
         {{"focal_length", 0.05}, {"aperture", 0.1}, {"focus_distance", 5}, {"samples", 1}}}},
       "/effects/depth_of_field/samples"},
      {"dof fractional samples",
       {{"depth_of_field",
         {{"focal_length", 0.05}, {"aperture", 0.1}, {"focus_distance", 5}, {"samples", 8.5}}}},
       "/effects/depth_of_field/samples"},
      {"antialias zero samples", {{"antialias", {{"samples", 0}}}}, "/effects/antialias/samples"},
      {"antialias too many samples",
       {{"antialias", {{"samples", 9}}}},
       "/effects/antialias/samples"},
      {"antialias unknown parameter",
       {{"antialias", {{"filter", "gauss"}}}},
       "/effects/antialias/filter"},
  };
  for (const bad_effect& c : cases) {
    json d = valid_scene();
    d["effects"] = c.effects;
    std::string message;
    EXPECT_EQ(error_key(d, &message), c.key) << c.name;
    EXPECT_NE(message.find(c.key), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find("scene.json"), std::string::npos) << c.name << ": " << message;
  }
}

TEST(EffectParsing, DepthOfFieldNeedsALens) {
  json d = valid_scene();
  d["projection"] = json::parse(
      R"({"type": "orthographic", "left": -1, "right": 1, "bottom": -1, "top": 1, "near": 1, "far": 9})");
  d["effects"] = {
      {"depth_of_field", {{"focal_length", 0.05}, {"aperture", 0.1}, {"focus_distance", 5}}}};
  std::string message;
  EXPECT_EQ(error_key(d, &message), "/effects/depth_of_field");
  EXPECT_NE(message.find("perspective or frustum"), std::string::npos) << message;
}

TEST(EffectParsing, DefaultsAndGivenValues) {
  json d = valid_scene();
  d["effects"] = {{"lighting", true}, {"fog", true}, {"antialias", json::object()}};
  scene::scene s = parse(d);
  EXPECT_EQ(std::set<std::string>(s.effects.begin(), s.effects.end()),
            (std::set<std::string>{"lighting", "fog", "antialias"}));
  const effect_settings& e = s.effect_settings;
  EXPECT_EQ(e.lighting.intensity, 0.8);
  EXPECT_EQ(e.lighting.ambient, 0.2);
  EXPECT_TRUE(e.lighting.two_sided);
  EXPECT_FALSE(e.lighting.smooth);
  EXPECT_EQ(e.lighting.crease_deg, 30);
  EXPECT_EQ(e.fog.mode, fog_mode::linear);
  EXPECT_EQ(e.fog.start, 1);                   // near
  EXPECT_EQ(e.fog.end, 100);                   // far
  EXPECT_EQ(e.fog.color, (rgb8{10, 20, 30}));  // the background
  EXPECT_EQ(e.antialias.samples, 4);

  d["effects"] = {
      {"fog", {{"mode", "exp"}}},
      {"depth_of_field", {{"focal_length", 0.05}, {"f_number", 2}, {"focus_distance", 5}}},
      {"lighting",
       {{"direction", {1, 2, 3}},
        {"intensity", 0.5},
        {"ambient", 0},
        {"two_sided", false},
        {"smooth", true},
        {"crease_deg", 180}}}};
  s = parse(d);
  EXPECT_EQ(s.effect_settings.fog.mode, fog_mode::exponential);
  EXPECT_NEAR(s.effect_settings.fog.density * 100, std::log(255.0),
              1e-12);                                                  // 1/255 at the far plane
  EXPECT_DOUBLE_EQ(s.effect_settings.depth_of_field.aperture, 0.025);  // f / N
  EXPECT_EQ(s.effect_settings.depth_of_field.samples, 32);
  EXPECT_EQ(s.effect_settings.lighting.direction.z, 3);
  EXPECT_FALSE(s.effect_settings.lighting.two_sided);
  EXPECT_TRUE(s.effect_settings.lighting.smooth);
  EXPECT_EQ(s.effect_settings.lighting.crease_deg, 180);
}

TEST(EffectParsing, FogEndingBeyondTheFarPlaneIsWarnedAbout) {
  json d = valid_scene();
  d["effects"] = {{"fog", {{"start", 10}, {"end", 150}}}};
  std::ostringstream warnings;
  parse(d, &warnings);
  EXPECT_NE(warnings.str().find("/effects/fog/end"), std::string::npos) << warnings.str();
  d["effects"] = {{"fog", {{"start", 10}, {"end", 90}}}};
  std::ostringstream none;
  parse(d, &none);
  EXPECT_TRUE(none.str().empty()) << none.str();
}

// ---------------------------------------------------------------------------------------
// A scene that names no effect pays nothing

TEST(NoEffects, StageListContainsNoEffectStage) {
  const scene::scene s = parse(valid_scene());
  ASSERT_TRUE(s.effects.empty());
  ASSERT_TRUE(s.curves.empty());
  for (output_kind out : {output_kind::png, output_kind::svg}) {
    const std::vector<std::string> names =
        standard_pipeline(s.effects, out, !s.curves.empty()).names();
    EXPECT_EQ(names, (std::vector<std::string>{"build", "order", "transform+clip",
                                               out == output_kind::png ? "raster" : "svg"}));
    for (const effect_description& e : effect_catalog())
      EXPECT_EQ(std::find(names.begin(), names.end(), e.name), names.end()) << e.name;
    EXPECT_EQ(std::find(names.begin(), names.end(), "curves"), names.end());
  }
  // Each effect adds exactly its own stage.
  for (const effect_description& e : effect_catalog()) {
    const std::vector<std::string> names = standard_pipeline({e.name}, output_kind::png).names();
    EXPECT_NE(std::find(names.begin(), names.end(), e.name), names.end()) << e.name;
    EXPECT_EQ(names.size(), e.hook == effect_hook::raster ? 4u : 5u) << e.name;
  }
}

TEST(NoEffects, RenderCommandRunsOnlyThePlainStages) {
  const std::string out =
      (std::filesystem::temp_directory_path() / "exbsp_test_effects_plain.png").string();
  std::ostringstream log;
  render_command({"", out, true}, log);  // the built-in demo names no effect
  EXPECT_NE(log.str().find("stages: reject, build, order, transform+clip, raster, write\n"),
            std::string::npos)
      << log.str();
  for (const effect_description& e : effect_catalog())
    EXPECT_EQ(log.str().find("stage " + e.name), std::string::npos) << e.name;
  std::filesystem::remove(out);
}

TEST(NoEffects, FrameProductsOfEffectsStayEmpty) {
  triangle_soup s;
  add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
  frame f =
      perspective_frame(std::move(s), {{200, 10, 10}}, {{0, 0, 4}, {0, 0, 0}, {0, 1, 0}}, 32, 32);
  run(f, {});
  EXPECT_TRUE(f.fragment_colors.empty());
  EXPECT_TRUE(f.lines.empty());
  EXPECT_FALSE(f.fog.has_value());
  EXPECT_EQ(f.picture.pixel(16, 16), (rgb8{200, 10, 10}));
}

// ---------------------------------------------------------------------------------------
// Lighting

/// A unit square in the plane z = 0, wound so that its normal is +z (or -z), seen from +z.
/// The main light only: direction, intensity, ambient, two_sided (the other members default).
lighting_settings lighting(const vector3& direction, double intensity, double ambient,
                           bool two_sided) {
  lighting_settings s;
  s.direction = direction;
  s.intensity = intensity;
  s.ambient = ambient;
  s.two_sided = two_sided;
  return s;
}

frame lit_square_frame(bool normal_up) {
  triangle_soup s;
  if (normal_up)
    add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
  else
    add_quad(s, {-1, -1, 0}, {-1, 1, 0}, {1, 1, 0}, {1, -1, 0});
  return perspective_frame(std::move(s), {{200, 100, 50}}, {{0, 0, 4}, {0, 0, 0}, {0, 1, 0}}, 40,
                           40);
}

TEST(Lighting, FaceTowardsTheLightGetsAmbientPlusIntensityAndAwayGetsAmbient) {
  frame f = lit_square_frame(true);
  f.settings.lighting = lighting({0, 0, 5}, 0.6, 0.3, true);  // any length: normalised
  run(f, {"lighting"});
  EXPECT_EQ(f.picture.pixel(20, 20), (rgb8{180, 90, 45}));  // 200 * 0.9, 100 * 0.9, 50 * 0.9

  frame g = lit_square_frame(true);
  g.settings.lighting = lighting({0, 0, -1}, 0.6, 0.3, true);  // the light is behind the square
  run(g, {"lighting"});
  EXPECT_EQ(g.picture.pixel(20, 20), (rgb8{60, 30, 15}));  // ambient only

  // At 60 degrees: N . L = 1/2.
  frame h = lit_square_frame(true);
  h.settings.lighting = lighting({std::sqrt(3.0), 0, 1}, 0.6, 0.3, true);
  run(h, {"lighting"});
  EXPECT_EQ(h.picture.pixel(20, 20), (rgb8{120, 60, 30}));  // * (0.3 + 0.3)
}

TEST(Lighting, TwoSidedFacesTheViewerAndOneSidedKeepsTheWinding) {
  // The square's winding normal points away from the viewer (-z); the light is at +z.
  frame two = lit_square_frame(false);
  two.settings.lighting = lighting({0, 0, 1}, 0.6, 0.3, true);
  run(two, {"lighting"});
  EXPECT_EQ(two.picture.pixel(20, 20), (rgb8{180, 90, 45}));
  frame one = lit_square_frame(false);
  one.settings.lighting = lighting({0, 0, 1}, 0.6, 0.3, false);
  run(one, {"lighting"});
  EXPECT_EQ(one.picture.pixel(20, 20), (rgb8{60, 30, 15}));
}

/// Three tilted planks in a cycle (each above the next somewhere), one quad face each: the
/// tree must split them.
triangle_soup tilted_cyclic_planks() {
  triangle_soup s;
  for (int i = 0; i < 3; ++i) {
    const double a = i * 2.0943951023931953, ux = std::cos(a), uy = std::sin(a), nx = -uy, ny = ux;
    const double cx = -0.75 * nx, cy = -0.75 * ny;
    std::vector<vec3d> v;
    for (auto [t, w] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
      v.push_back(
          {cx + 2.1 * t * ux + 0.3 * w * nx, cy + 2.1 * t * uy + 0.3 * w * ny, 0.25 * 2.1 * t});
    add_quad(s, v[0], v[1], v[2], v[3]);
  }
  return s;
}

TEST(Lighting, ColoursClampAt255AndSplitPiecesShareTheirColour) {
  EXPECT_EQ(lambert_color({200, 100, 0}, {0, 0, 1}, lighting({0, 0, 1}, 1.0, 0.5, true)),
            (rgb8{255, 150, 0}));
  // The cyclic planks force a split: every piece of a face gets the same colour.
  const triangle_soup s = tilted_cyclic_planks();
  // Also with a headlight, a point light and highlights, which depend on the face's place.
  lighting_settings placed = lighting({0.3, -0.2, 1}, 0.5, 0.2, true);
  placed.headlight = true;
  placed.specular = 0.5;
  placed.lights.push_back({light_source::kind_type::point, {1, -1, 3}, 0.4});
  for (const lighting_settings& light : {lighting({0.3, -0.2, 1}, 0.7, 0.2, true), placed}) {
    frame f = perspective_frame(s, {{250, 0, 0}, {0, 250, 0}, {0, 0, 250}},
                                {{0.3, -2, 8}, {0, 0, 0}, {0, 1, 0}}, 100, 100);
    f.settings.lighting = light;
    run(f, {"lighting"});
    ASSERT_GT(f.tree->stats().splits, 0u);
    std::vector<std::set<std::tuple<int, int, int>>> by_face(3);
    for (const screen_polygon& p : f.polygons)
      by_face[p.face].insert({p.color.r, p.color.g, p.color.b});
    for (const auto& colours : by_face) EXPECT_EQ(colours.size(), 1u) << light.headlight;
  }
}

/// lit_color for a face with normal +z at the origin seen from (0, 0, 4) (view_setup of a
/// lit_square_frame).
rgb8 lit_at_origin(const lighting_settings& s, rgb8 base = {100, 50, 0}) {
  const frame f = lit_square_frame(true);
  return lit_color(base, {0, 0, 1}, {0, 0, 0}, f.view, s);
}

TEST(Lighting, WithoutExtrasTheColourIsLambertsExactly) {
  const frame f = lit_square_frame(true);
  const lighting_settings s = lighting({0.3, -0.2, 1}, 0.7, 0.2, true);
  for (const vector3& n : {vector3{0, 0, 1}, vector3{0.6, 0, 0.8}, vector3{0, -1, 0}})
    EXPECT_EQ(lit_color({200, 100, 50}, n, {0.5, 0.25, 0}, f.view, s),
              lambert_color({200, 100, 50}, n, s));
}

TEST(Lighting, BlinnPhongHighlightsFollowTheHalfVector) {
  lighting_settings s = lighting({0, 0, 1}, 0.5, 0.2, true);
  s.specular = 0.4;
  s.shininess = 4;
  // L = V = N: N . H = 1, so 100 * (0.2 + 0.5) + 255 * 0.5 * 0.4 = 121 (and 86, 51).
  EXPECT_EQ(lit_at_origin(s), (rgb8{121, 86, 51}));
  // L at 45 degrees from N in the xz plane, V = N: H lies at 22.5 degrees.
  s.direction = {1, 0, 1};
  const double diffuse = 0.2 + 0.5 * std::cos(M_PI / 4);
  const double highlight = 255 * 0.5 * 0.4 * std::pow(std::cos(M_PI / 8), 4);
  EXPECT_EQ(lit_at_origin(s),
            (rgb8{static_cast<std::uint8_t>(std::lround(100 * diffuse + highlight)),
                  static_cast<std::uint8_t>(std::lround(50 * diffuse + highlight)),
                  static_cast<std::uint8_t>(std::lround(highlight))}));
  // A light behind the face gives no highlight: ambient only.
  s.direction = {0, 0, -1};
  EXPECT_EQ(lit_at_origin(s), (rgb8{20, 10, 0}));
}

TEST(Lighting, HeadlightsAndPointLightsTakeTheirDirectionFromTheFragment) {
  lighting_settings s =
      lighting({0, 0, -1}, 0.6, 0.3, true);  // a main light behind the face: ambient
  EXPECT_EQ(lit_at_origin(s), (rgb8{30, 15, 0}));
  s.headlight = true;  // from the eye at (0, 0, 4): N . L = 1
  EXPECT_EQ(lit_at_origin(s), (rgb8{90, 45, 0}));
  s.headlight = false;
  // A point light at (2, 0, 2) seen from the origin: N . L = cos 45 degrees.
  s.lights.push_back({light_source::kind_type::point, {2, 0, 2}, 0.5});
  const double k = 0.3 + 0.5 * std::cos(M_PI / 4);
  EXPECT_EQ(lit_at_origin(s), (rgb8{static_cast<std::uint8_t>(std::lround(100 * k)),
                                    static_cast<std::uint8_t>(std::lround(50 * k)), 0}));
  // A second, directional one adds its term; a point light in the face's plane adds nothing.
  s.lights.push_back({light_source::kind_type::directional, {0, 0, 3}, 0.1});
  s.lights.push_back({light_source::kind_type::point, {0, 0, 0}, 0.9});
  const double k2 = k + 0.1;
  EXPECT_EQ(lit_at_origin(s), (rgb8{static_cast<std::uint8_t>(std::lround(100 * k2)),
                                    static_cast<std::uint8_t>(std::lround(50 * k2)), 0}));
}

TEST(Lighting, AHeadlightLightsTheSideTheViewerSees) {
  // The eye is at +z; a directional light from -z leaves the (two-sided) face in its ambient
  // light, as an orbit to the unlit side does; a headlight lights it.
  frame dark = lit_square_frame(false);
  dark.settings.lighting = lighting({0, 0, -1}, 0.6, 0.3, true);
  run(dark, {"lighting"});
  EXPECT_EQ(dark.picture.pixel(20, 20), (rgb8{60, 30, 15}));
  frame lit = lit_square_frame(false);
  lit.settings.lighting = lighting({0, 0, 1}, 0.6, 0.3, true);
  lit.settings.lighting.headlight = true;
  run(lit, {"lighting"});
  // The face's centroid (the mean of its two triangles' centroids) is the origin: N . V = 1,
  // and both triangles of the square get 200 * (0.3 + 0.6) = 180, the same colour.
  EXPECT_EQ(lit.picture.pixel(20, 20), (rgb8{180, 90, 45}));
  EXPECT_EQ(lit.picture.pixel(12, 27), (rgb8{180, 90, 45}));
  EXPECT_EQ(lit.picture.pixel(27, 12), (rgb8{180, 90, 45}));
}

// ---------------------------------------------------------------------------------------
// Smooth shading (view/smooth_shading.h)

lighting_settings smooth_lighting(double crease_deg) {
  lighting_settings s = lighting({0.2, -0.4, 1}, 0.7, 0.25, true);
  s.smooth = true;
  s.crease_deg = crease_deg;
  return s;
}

TEST(SmoothShading, AFlatMeshIsPaintedExactlyAsFlatShadingPaintsIt) {
  frame flat = lit_square_frame(true), smooth = lit_square_frame(true);
  flat.settings.lighting = lighting({0.2, -0.4, 1}, 0.7, 0.25, true);
  smooth.settings.lighting = smooth_lighting(30);
  run(flat, {"lighting"});
  run(smooth, {"lighting"});
  ASSERT_FALSE(smooth.corner_colors.empty());
  EXPECT_TRUE(flat.picture.data() == smooth.picture.data());
}

/// A roof: two triangles sharing the edge (0,-1,0)-(0,1,0), each sloping down by `slope_deg`.
frame roof_frame(double slope_deg) {
  const double t = std::tan(slope_deg * 3.14159265358979323846 / 180);
  triangle_soup s;
  s.vertices = {{0, -1, 0}, {0, 1, 0}, {-1, 0, -t}, {1, 0, -t}};
  s.triangles = {{{0, 1, 2}, 0}, {{1, 0, 3}, 1}};
  s.face_count = 2;
  return perspective_frame(std::move(s), {{200, 180, 160}, {200, 180, 160}},
                           {{0.3, -0.2, 5}, {0, 0, 0}, {0, 1, 0}}, 60, 60);
}

TEST(SmoothShading, SharedCornersAgreeBelowTheCreaseAngleAndDifferAboveIt) {
  // Dihedral deviation 2 x 10 = 20 degrees: smooth under crease_deg = 30, a crease under 15.
  for (const double crease : {30.0, 15.0}) {
    frame f = roof_frame(10);
    f.settings.lighting = smooth_lighting(crease);
    run(f, {"lighting"});
    ASSERT_EQ(f.fragments.size(), 2u);
    // The corners on the shared edge, found by position in each fragment.
    std::map<std::pair<double, double>, std::set<std::tuple<int, int, int>>> at;
    for (std::size_t i = 0; i < 2; ++i)
      for (int k = 0; k < 3; ++k) {
        const vec3d& p = f.fragments[i].v[k];
        const rgb8 c = f.corner_colors[i][k];
        if (p[0] == 0) at[{p[0], p[1]}].insert({c.r, c.g, c.b});
      }
    ASSERT_EQ(at.size(), 2u);
    for (const auto& [where, colours] : at) EXPECT_EQ(colours.size(), crease > 20 ? 1u : 2u);
    if (crease > 20) {
      // The shared normal is the mean of the two: (0, 0, 1), lit as a flat face facing up.
      const rgb8 up = lambert_color({200, 180, 160}, {0, 0, 1}, f.settings.lighting);
      for (const auto& [where, colours] : at)
        EXPECT_EQ(*colours.begin(), std::make_tuple(int(up.r), int(up.g), int(up.b)));
    }
  }
}

TEST(SmoothShading, InterpolationIsPerspectiveCorrect) {
  // A triangle receding from the eye, corner colours far apart: the colour seen at the image
  // of the world point sum b_k P_k is sum b_k c_k (to rounding), not the screen-space mix.
  const frame f = perspective_frame({}, {}, {{0, -3, 1}, {0, 10, 0}, {0, 0, 1}}, 200, 200, 50);
  const fragment_d tri{0, {{{-2, 0, 0}, {2, 0, 0}, {0, 30, 0}}}};
  const std::array<rgb8, 3> colors{{{250, 0, 0}, {0, 250, 0}, {0, 0, 250}}};
  const corner_interpolator smooth(tri, colors, f.view);
  const mat4 m = f.view.projection * f.view.model_view;
  for (const std::array<double, 3>& b :
       {std::array<double, 3>{0.2, 0.3, 0.5}, {0.45, 0.45, 0.1}, {0.1, 0.1, 0.8}}) {
    point3 p{0, 0, 0};
    for (int k = 0; k < 3; ++k)
      p = {p.x + b[k] * tri.v[k][0], p.y + b[k] * tri.v[k][1], p.z + b[k] * tri.v[k][2]};
    const hpoint c = m * p;
    const window_point w = to_window(f.view.vp, c.x / c.w, c.y / c.w, c.z / c.w);
    const rgb8 got = smooth.at(w.x, w.y, {1, 2, 3});
    EXPECT_NEAR(got.r, 250 * b[0], 1.0);
    EXPECT_NEAR(got.g, 250 * b[1], 1.0);
    EXPECT_NEAR(got.b, 250 * b[2], 1.0);
  }
  // Screen-space (affine) interpolation would be far off at the far corner's side: the image
  // of the world centroid is much nearer the far corner's image than the centroid of the images.
  point3 centroid{0, 10, 0};
  const hpoint c = m * centroid;
  const window_point w = to_window(f.view.vp, c.x / c.w, c.y / c.w, c.z / c.w);
  std::array<window_point, 3> img;
  for (int k = 0; k < 3; ++k) {
    const hpoint q = m * point3{tri.v[k][0], tri.v[k][1], tri.v[k][2]};
    img[k] = to_window(f.view.vp, q.x / q.w, q.y / q.w, q.z / q.w);
  }
  const double screen_centroid_y = (img[0].y + img[1].y + img[2].y) / 3;
  EXPECT_GT(std::abs(w.y - screen_centroid_y), 10.0);
}

TEST(SmoothShading, SplitPiecesJoinWithoutASeam) {
  // The cyclic planks force splits; along each split line the pieces' colours agree (they
  // interpolate one triangle's corners): no pixel in a plank's interior differs from its
  // neighbours by more than the smooth gradient does elsewhere.
  const triangle_soup s = tilted_cyclic_planks();
  frame f = perspective_frame(s, {{250, 200, 150}, {250, 200, 150}, {250, 200, 150}},
                              {{0.3, -2, 8}, {0, 0, 0}, {0, 1, 0}}, 160, 160);
  f.settings.lighting = smooth_lighting(30);
  run(f, {"lighting"});
  ASSERT_GT(f.tree->stats().splits, 0u);
  // Flat planks: smooth shading equals the flat colour on each (every corner normal is the
  // plank's), so a split line would show as a jump: there is none.
  frame g = perspective_frame(s, {{250, 200, 150}, {250, 200, 150}, {250, 200, 150}},
                              {{0.3, -2, 8}, {0, 0, 0}, {0, 1, 0}}, 160, 160);
  g.settings.lighting = smooth_lighting(30);
  g.settings.lighting.smooth = false;
  run(g, {"lighting"});
  EXPECT_TRUE(f.picture.data() == g.picture.data());
}

// ---------------------------------------------------------------------------------------
// Fog

/// A long floor (z = 0, y from -2 to 200) seen from a low eye looking along +y.
frame floor_frame(double far_dist) {
  triangle_soup s;
  add_quad(s, {-20, -2, 0}, {20, -2, 0}, {20, 200, 0}, {-20, 200, 0});
  return perspective_frame(std::move(s), {{40, 160, 40}}, {{0, -3, 1.5}, {0, 30, 0.2}, {0, 0, 1}},
                           60, 80, 50, 0.5, far_dist);
}

TEST(Fog, FarPixelsApproachTheFogColourMonotonically) {
  for (fog_mode mode : {fog_mode::linear, fog_mode::exponential}) {
    frame f = floor_frame(60);
    f.background = {255, 255, 255};
    f.settings.fog.mode = mode;
    f.settings.fog.start = 4;
    f.settings.fog.end = 40;
    f.settings.fog.density = 0.08;
    f.settings.fog.color = {200, 200, 220};
    run(f, {"fog"});
    // Up the middle column the floor recedes: the distance to the fog colour never grows.
    int previous = std::numeric_limits<int>::max(), floor_pixels = 0;
    for (int j = 0; j < f.picture.height(); ++j) {
      const rgb8 c = f.picture.pixel(30, j);
      const int d = color_distance(c, f.settings.fog.color);
      EXPECT_LE(d, previous) << "row " << j;
      previous = d;
      floor_pixels += d > 0;
    }
    EXPECT_GT(floor_pixels, 5);
    // The background takes the fog colour (it is infinitely far away).
    EXPECT_EQ(f.picture.pixel(30, f.picture.height() - 1), f.settings.fog.color);
    if (mode == fog_mode::linear) {
      // Bottom rows are nearer than `start`: unfogged.
      EXPECT_EQ(f.picture.pixel(30, 0), (rgb8{40, 160, 40}));
    }
  }
}

TEST(Fog, LinearFogEndingAtTheFarPlaneHidesTheFarPlanePop) {
  // A wall facing the camera moves back across the far plane (30): just inside it is drawn,
  // just beyond it is clipped. Without fog that is a jump from the wall's colour to the
  // background (the "pop"); with linear fog ending at the far plane the wall has already
  // faded into the background, so the picture barely changes.
  auto wall_at = [](double depth, bool fog) {
    triangle_soup s;
    add_quad(s, {-30, -30, -depth}, {30, -30, -depth}, {30, 30, -depth}, {-30, 30, -depth});
    frame f = perspective_frame(std::move(s), {{40, 160, 40}}, {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}},
                                60, 40, 50, 0.5, 30);
    f.background = {230, 235, 240};
    f.settings.fog = {fog_mode::linear, 2, 30, 1, f.background};
    run(f, fog ? std::vector<std::string>{"fog"} : std::vector<std::string>{});
    return f.picture;
  };
  const image plain_in = wall_at(29.9, false), plain_out = wall_at(30.1, false);
  const image fog_in = wall_at(29.9, true), fog_out = wall_at(30.1, true);
  EXPECT_EQ(plain_in.pixel(30, 20), (rgb8{40, 160, 40}));  // the pop: wall, then background
  EXPECT_EQ(plain_out.pixel(30, 20), (rgb8{230, 235, 240}));
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 60; ++i) {
      EXPECT_EQ(fog_out.pixel(i, j), (rgb8{230, 235, 240}));
      EXPECT_LE(color_distance(fog_in.pixel(i, j), fog_out.pixel(i, j)), 3) << i << "," << j;
    }
}

TEST(Fog, EyeDistanceInvertsTheProjection) {
  frame f = floor_frame(60);
  const fog_shading fog = make_fog_shading(f.settings.fog, f.view);
  const point3 p{3, 20, 0};
  const hpoint c = f.view.projection * f.view.model_view * p;
  const window_point w = to_window(f.view.vp, c.x / c.w, c.y / c.w, c.z / c.w);
  EXPECT_NEAR(eye_distance(fog, w.x, w.y, w.z), length(p - f.view.cam.eye), 1e-6);
  EXPECT_EQ(fog_visibility({fog_mode::linear, 10, 20, 1, {}}, 5), 1.0);
  EXPECT_EQ(fog_visibility({fog_mode::linear, 10, 20, 1, {}}, 15), 0.5);
  EXPECT_EQ(fog_visibility({fog_mode::linear, 10, 20, 1, {}}, 25), 0.0);
  EXPECT_NEAR(fog_visibility({fog_mode::exponential, 0, 1, 0.5, {}}, 2), std::exp(-1.0), 1e-15);
}

// ---------------------------------------------------------------------------------------
// Antialias

/// Two triangles sharing the diagonal of a tilted quad (or the quad as one polygon), in a
/// frame whose projection maps world x, y directly to the window (orthographic, 1 unit = 1 px).
frame quad_frame(bool split, int width = 48, int height = 40) {
  const vec3d a{5.3, 4.1, 0}, b{40.7, 9.6, 0}, c{37.2, 35.9, 0}, d{8.1, 30.3, 0};
  triangle_soup s;
  if (split) {
    s.vertices = {a, b, c, d};
    s.add_polygon({0, 1, 2}, 0);
    s.add_polygon({0, 2, 3}, 1);
  } else {
    s.vertices = {a, b, c, d};
    s.add_polygon({1, 2, 3, 0}, 0);  // fan from b: the other diagonal
  }
  frame f;
  f.soup = std::move(s);
  f.face_colors = {{30, 90, 200}, {30, 90, 200}};
  f.background = {250, 250, 250};
  f.view.kind = projection_kind::orthographic;
  f.view.cam = {{0, 0, 10}, {0, 0, 0}, {0, 1, 0}};
  f.view.model_view = look_at(f.view.cam);
  f.view.projection = ortho(0, width, 0, height, 1, 20);
  f.view.direction = {0, 0, -1};
  f.view.vp = {0, 0, width, height, 0, 1};
  return f;
}

TEST(Antialias, TwoTrianglesSharingAnEdgeShowNoSeam) {
  const rgb8 blue{30, 90, 200};
  const point2 q[4] = {{5.3, 4.1}, {40.7, 9.6}, {37.2, 35.9}, {8.1, 30.3}};
  for (int n : {2, 3, 4, 8}) {
    frame f = quad_frame(true);
    f.settings.antialias.samples = n;
    run(f, {"antialias"});
    int interior = 0, edge = 0;
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 48; ++i) {
        // Is every sub-pixel centre strictly inside the quad (the union of the triangles)?
        bool all = true, any = false;
        for (int k = 0; k < n; ++k)
          for (int l = 0; l < n; ++l) {
            const double x = i + (k + 0.5) / n, y = j + (l + 0.5) / n;
            bool in = true;
            for (int e = 0; e < 4; ++e)
              in = in && orient2d(q[e].x, q[e].y, q[(e + 1) % 4].x, q[(e + 1) % 4].y, x, y) > 0;
            all = all && in;
            any = any || in;
          }
        const rgb8 c = f.picture.pixel(i, j);
        if (all) {
          ++interior;
          ASSERT_EQ(c, blue) << "seam at pixel " << i << "," << j << " with " << n << "x" << n
                             << " samples";
        } else if (any) {
          ++edge;
          EXPECT_NE(c, blue);  // a blend with the background
        } else {
          EXPECT_EQ(c, f.background);
        }
      }
    EXPECT_GT(interior, 600);
    EXPECT_GT(edge, 60);
    // The same quad drawn as one polygon fanned along the other diagonal: identical image.
    frame g = quad_frame(false);
    g.settings.antialias.samples = n;
    run(g, {"antialias"});
    EXPECT_EQ(f.picture.data(), g.picture.data()) << n;
  }
}

TEST(Antialias, OneSampleIsThePlainRasterAndBoxDownsampleAverages) {
  frame f = quad_frame(true), g = quad_frame(true);
  f.settings.antialias.samples = 1;
  run(f, {"antialias"});
  run(g, {});
  EXPECT_EQ(f.picture.data(), g.picture.data());
  image hi(4, 2, {0, 0, 0});
  hi.set_pixel(0, 0, {255, 255, 255});
  hi.set_pixel(1, 1, {255, 3, 0});
  hi.set_pixel(3, 1, {100, 100, 100});
  const image lo = box_downsample(hi, 2);
  EXPECT_EQ(lo.pixel(0, 0),
            (rgb8{128, 65, 64}));  // (255 + 255) / 4, (255 + 3) / 4, 255 / 4, rounded
  EXPECT_EQ(lo.pixel(1, 0), (rgb8{25, 25, 25}));
  EXPECT_THROW(box_downsample(hi, 3), usage_error);
}

// ---------------------------------------------------------------------------------------
// Depth of field

/// Width in pixels of the edge of a red square (left of x = edge_x, world) at depth u, seen
/// from the origin looking down -z, with the given aperture: pixels in the middle row that are
/// neither pure red nor pure background.
int edge_width(double u, double aperture, double focus, int samples = 48) {
  triangle_soup s;
  const double e = 0.0137 * u;  // the edge lands between pixel centres
  add_quad(s, {-10 * u, -10 * u, -u}, {e, -10 * u, -u}, {e, 10 * u, -u}, {-10 * u, 10 * u, -u});
  frame f = perspective_frame(std::move(s), {{220, 0, 0}}, {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, 120,
                              60, 40, 0.1, 1000);
  f.settings.depth_of_field = {0.05, aperture, focus, samples};
  run(f, aperture > 0 ? std::vector<std::string>{"depth_of_field"} : std::vector<std::string>{});
  int width = 0;
  for (int i = 0; i < 120; ++i) {
    const rgb8 c = f.picture.pixel(i, 30);
    width += c != rgb8{220, 0, 0} && c != rgb8{255, 255, 255};
  }
  return width;
}

TEST(DepthOfField, InFocusPlaneStaysSharpAndOutOfFocusPlaneBlursWithAperture) {
  const double focus = 10;
  EXPECT_LE(edge_width(focus, 0.4, focus), 1);
  EXPECT_LE(edge_width(focus, 2.0, focus), 1);
  // Out of focus (twice as far, and nearer): the blur grows with the aperture, and matches
  // the circle of confusion in pixels.
  for (double u : {20.0, 6.0}) {
    int previous = edge_width(u, 0, focus);
    EXPECT_LE(previous, 1);
    for (double aperture : {0.2, 0.5, 1.0, 2.0}) {
      const int w = edge_width(u, aperture, focus);
      EXPECT_GT(w, previous) << "u " << u << " aperture " << aperture;
      previous = w;
      triangle_soup none;
      frame f =
          perspective_frame(none, {}, {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, 120, 60, 40, 0.1, 1000);
      const double c = circle_of_confusion_pixels({0.05, aperture, focus, 48}, f.view, u);
      EXPECT_NEAR(w, c, 0.15 * c + 2) << "u " << u << " aperture " << aperture;
    }
  }
}

TEST(DepthOfField, ThinLensCircleOfConfusionAndTheShearedLensViews) {
  const depth_of_field_settings s{0.05, 0.025, 4.0, 32};
  // c = A |v - v_f| / v with the lens law v = f u / (u - f): the closed form agrees.
  for (double u : {0.5, 2.0, 4.0, 9.0, 100.0}) {
    const double v = s.focal_length * u / (u - s.focal_length);
    const double vf = s.focal_length * s.focus_distance / (s.focus_distance - s.focal_length);
    EXPECT_NEAR(circle_of_confusion(s, u), s.aperture * std::fabs(v - vf) / v, 1e-15);
  }
  EXPECT_EQ(circle_of_confusion(s, s.focus_distance), 0);
  // From opposite rim points of the lens a point at depth u lands c_px apart, a point on the
  // focus plane at the same pixel.
  triangle_soup none;
  frame f =
      perspective_frame(none, {}, {{1, 2, 3}, {1.5, 2.2, -5}, {0, 1, 0}}, 200, 150, 50, 0.2, 100);
  const camera_basis b = look_at_basis(f.view.cam.eye, f.view.cam.look_at, f.view.cam.up);
  const depth_of_field_settings big{0.05, 0.4, 4.0, 32};
  const view_setup left = lens_view(f.view, {-0.2, 0}, big.focus_distance);
  const view_setup right = lens_view(f.view, {0.2, 0}, big.focus_distance);
  auto window_of = [](const view_setup& v, const point3& p) {
    const hpoint c = v.projection * v.model_view * p;
    return to_window(v.vp, c.x / c.w, c.y / c.w, c.z / c.w);
  };
  const vector3 gaze = -1.0 * b.w;
  for (double u : {1.0, 4.0, 12.0}) {
    const point3 p = f.view.cam.eye + (u * gaze + 0.3 * b.u + 0.2 * b.v);
    const window_point l = window_of(left, p), r = window_of(right, p);
    EXPECT_NEAR(std::hypot(l.x - r.x, l.y - r.y), circle_of_confusion_pixels(big, f.view, u), 1e-6)
        << u;
  }
  // The lens samples: the centre first, all within the disk, spread around it.
  const std::vector<lens_offset> lens = lens_samples(32, 0.4);
  EXPECT_EQ(lens[0].dx, 0);
  EXPECT_EQ(lens[0].dy, 0);
  double mx = 0, my = 0;
  for (const lens_offset& o : lens) {
    EXPECT_LE(std::hypot(o.dx, o.dy), 0.2 + 1e-15);
    mx += o.dx;
    my += o.dy;
  }
  EXPECT_LT(std::hypot(mx, my) / 32, 0.02);
}

TEST(DepthOfField, ReusesTheBspAndRestoresTheCentreView) {
  triangle_soup s;
  add_quad(s, {-1, -1, -5}, {1, -1, -5}, {1, 1, -5}, {-1, 1, -5});
  add_quad(s, {-3, -3, -12}, {3, -3, -12}, {3, 3, -12}, {-3, 3, -12});
  frame f = perspective_frame(std::move(s), {{200, 0, 0}, {0, 0, 200}},
                              {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, 64, 48);
  f.settings.depth_of_field = {0.05, 0.3, 5, 8};
  const view_setup centre = f.view;
  std::ostringstream log;
  standard_pipeline({"depth_of_field"}, output_kind::png).run(f, &log);
  const std::string text = log.str();
  EXPECT_EQ(text.find("stage build:"), text.rfind("stage build:"));  // one build
  EXPECT_NE(text.find("8 lens samples"), std::string::npos) << text;
  EXPECT_EQ(f.view.cam.eye.x, centre.cam.eye.x);
  EXPECT_EQ(f.view.projection.m, centre.projection.m);
  EXPECT_EQ(f.order, f.tree->order_from_eye({0, 0, 0}));
}

// ---------------------------------------------------------------------------------------
// Exposure (view/exposure.h)

/// Two quads at different depths, seen from (0, 0, 0) down -z: the nearer one sweeps farther
/// across the image when the camera moves sideways (parallax).
frame parallax_frame(view::projection_kind kind = view::projection_kind::perspective) {
  triangle_soup s;
  add_quad(s, {-0.4, -1, -4}, {0.4, -1, -4}, {0.4, 1, -4}, {-0.4, 1, -4});
  add_quad(s, {-3, -3, -12}, {3, -3, -12}, {3, 3, -12}, {-3, 3, -12});
  frame f = perspective_frame(std::move(s), {{220, 40, 30}, {40, 60, 210}},
                              {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, 80, 60);
  if (kind == view::projection_kind::orthographic) {
    f.view.kind = kind;
    f.view.projection = ortho(-4, 4, -3, 3, 1, 30);
    f.view.direction = {0, 0, -1};
  }
  return f;
}

TEST(Exposure, AStillCameraGivesTheStillPictureAndAMovingOneTheMeanOfItsViews) {
  for (const auto kind :
       {view::projection_kind::perspective, view::projection_kind::orthographic}) {
    frame still = parallax_frame(kind);
    run(still, {});
    frame same = parallax_frame(kind);
    same.settings.exposure = {0.5, 6, same.view.cam};
    run(same, {"exposure"});
    EXPECT_TRUE(same.picture.data() == still.picture.data());

    // Moving right by 1.2 over a frame, shutter open for 3/4 of it, 4 samples: the mean of
    // the four pictures taken from t = 0, 0.25, 0.5, 0.75, each rendered on its own.
    frame moving = parallax_frame(kind);
    const camera end{{1.2, 0, 0}, {1.2, 0, -1}, {0, 1, 0}};
    moving.settings.exposure = {0.75, 4, end};
    run(moving, {"exposure"});
    std::vector<unsigned> sum(moving.picture.data().size(), 0);
    for (int k = 0; k < 4; ++k) {
      frame g = parallax_frame(kind);
      const double x = 1.2 * 0.25 * k;
      g.view.cam = {{x, 0, 0}, {x, 0, -1}, {0, 1, 0}};
      g.view.model_view = look_at(g.view.cam);
      run(g, {});
      for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += g.picture.data()[i];
    }
    std::size_t differ = 0;
    for (std::size_t i = 0; i < sum.size(); ++i)
      differ += moving.picture.data()[i] != static_cast<std::uint8_t>((sum[i] + 2) / 4);
    EXPECT_EQ(differ, 0u);
    // Blurred: colours between the two quads' appear (at least a few distinct mixtures).
    EXPECT_GT(exbsp_test::colours_of(moving.picture).size(),
              exbsp_test::colours_of(still.picture).size() + 2);
    // The frame's other products are the start view's.
    EXPECT_EQ(moving.view.cam.eye.x, 0);
  }
}

TEST(Exposure, ParametersAreCheckedAndNamed) {
  json d = valid_scene();
  const json end = {{"eye", {1, 0, 5}}, {"look_at", {1, 0, 0}}, {"up", {0, 1, 0}}};
  d["effects"] = {{"exposure", {{"shutter", 0.25}, {"samples", 5}, {"camera_end", end}}}};
  const scene::scene s = parse(d);
  EXPECT_EQ(s.effect_settings.exposure.samples, 5);
  EXPECT_EQ(s.effect_settings.exposure.shutter, 0.25);
  EXPECT_EQ(s.effect_settings.exposure.camera_end.eye.x, 1);
  const std::vector<std::pair<json, std::string>> bad = {
      {{{"exposure", {{"shutter", 0}, {"camera_end", end}}}}, "/effects/exposure/shutter"},
      {{{"exposure", {{"shutter", 1.5}, {"camera_end", end}}}}, "/effects/exposure/shutter"},
      {{{"exposure", {{"samples", 1}, {"camera_end", end}}}}, "/effects/exposure/samples"},
      {{{"exposure", json::object()}}, "/effects/exposure/camera_end"},
      {{{"exposure",
         {{"camera_end", {{"eye", {1, 0, 0}}, {"look_at", {1, 0, 0}}, {"up", {0, 1, 0}}}}}}},
       "/effects/exposure/camera_end"},
      {{{"exposure", {{"camera_end", end}}},
        {"depth_of_field", {{"focal_length", 0.05}, {"f_number", 2}, {"focus_distance", 5}}}},
       "/effects/exposure"},
  };
  for (const auto& [effects, key] : bad) {
    json e = valid_scene();
    e["effects"] = effects;
    EXPECT_EQ(error_key(e), key) << effects.dump();
  }
}

// ---------------------------------------------------------------------------------------
// Curves: clipping, the line pixel rule

TEST(SegmentClip, KeepsInsideCutsBehindTheEyeAndRejectsOutside) {
  hpoint a, b;
  double t0, t1;
  ASSERT_TRUE(
      clip_segment_to_view_volume({0.1, 0.2, 0.3, 1}, {-0.5, 0.4, -0.2, 2}, a, b, &t0, &t1));
  EXPECT_EQ(t0, 0);
  EXPECT_EQ(t1, 1);
  EXPECT_EQ(a.x, 0.1);
  EXPECT_EQ(b.w, 2);
  // From in front of the eye (w = 2) to behind it (w = -2): cut at the near plane w + z = 0.
  ASSERT_TRUE(clip_segment_to_view_volume({0, 0, 0, 2}, {0, 0, -6, -2}, a, b, &t0, &t1));
  EXPECT_EQ(a.w, 2);
  EXPECT_EQ(b.z, -b.w);  // exactly on the plane
  EXPECT_GT(b.w, 0);
  // Entirely behind the eye, entirely left of the volume: nothing.
  EXPECT_FALSE(clip_segment_to_view_volume({0, 0, 1, -1}, {0.3, 0, 2, -3}, a, b));
  EXPECT_FALSE(clip_segment_to_view_volume({-3, 0, 0, 1}, {-2, 1, 0, 1}, a, b));
  // A zero-length segment survives iff inside; non-finite input never does.
  EXPECT_TRUE(clip_segment_to_view_volume({0.5, 0, 0, 1}, {0.5, 0, 0, 1}, a, b));
  EXPECT_FALSE(clip_segment_to_view_volume({1.5, 0, 0, 1}, {1.5, 0, 0, 1}, a, b));
  EXPECT_FALSE(clip_segment_to_view_volume({0, 0, 0, 1}, {std::nan(""), 0, 0, 1}, a, b));
}

TEST(LinePixels, ColumnCentreRuleOnePixelPerColumnNoGapsAtJoints) {
  std::vector<int> count(20 * 10, 0);
  auto add = [&](double x0, double y0, double x1, double y1) {
    for_each_line_pixel(x0, y0, x1, y1, 1, 20, 10,
                        [&](int i, int j, double) { ++count[j * 20 + i]; });
  };
  // Two segments of one polyline, x-major, sharing the vertex (7.5, 3.2) on a column centre.
  add(0.2, 1.1, 7.5, 3.2);
  add(7.5, 3.2, 18.9, 6.7);
  for (int i = 0; i < 20; ++i) {
    int in_column = 0;
    for (int j = 0; j < 10; ++j) in_column += count[j * 20 + i];
    EXPECT_EQ(in_column, i <= 18 ? 1 : 0)
        << "column " << i;  // centres 0.5 .. 18.5 lie in [0.2, 18.9)
  }
  // The pixel painted in column 7 contains the joint: floor(3.2) = row 3.
  EXPECT_EQ(count[3 * 20 + 7], 1);
  // Reversed direction: start included, end excluded.
  std::set<std::pair<int, int>> px;
  for_each_line_pixel(9.5, 2.0, 2.5, 2.0, 1, 20, 10, [&](int i, int j, double) {
    px.insert({i, j});
  });
  EXPECT_EQ(px.size(), 7u);  // centres 9.5 down to 3.5
  EXPECT_TRUE(px.count({9, 2}));
  EXPECT_FALSE(px.count({2, 2}));
  // y-major, and width 3: three pixels across per row.
  int n = 0;
  for_each_line_pixel(5.2, 0.1, 6.0, 8.9, 3, 20, 10, [&](int, int, double) { ++n; });
  EXPECT_EQ(n, 9 * 3);
  // Degenerate, off-screen and non-finite segments paint nothing.
  n = 0;
  for_each_line_pixel(3, 3, 3, 3, 1, 20, 10, [&](int, int, double) { ++n; });
  for_each_line_pixel(-50, -50, -10, -30, 1, 20, 10, [&](int, int, double) { ++n; });
  for_each_line_pixel(0, 0, std::numeric_limits<double>::infinity(), 1, 1, 20, 10,
                      [&](int, int, double) { ++n; });
  EXPECT_EQ(n, 0);
}

// ---------------------------------------------------------------------------------------
// Curves: the depth rule

/// Brute-force per-pixel depth oracle: polygons by a z-buffer over the unsplit soup (depth at
/// the pixel centre), then every pixel of the curves' flattened polylines (same flattening,
/// same clipping, same pixel rule) painted where the curve is nearer than the polygon plane
/// seen at that pixel, both evaluated at the line's sample point.
image depth_oracle(const frame& f) {
  const int w = f.view.vp.width, h = f.view.vp.height;
  image img(w, h, f.background);
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<double> depth(n, std::numeric_limits<double>::infinity());
  std::vector<depth_plane> plane(n);
  const mat4 pm = f.view.projection * f.view.model_view;
  std::vector<hpoint> in(3), out;
  for (const soup_triangle& t : f.soup.triangles) {
    for (int k = 0; k < 3; ++k) in[k] = pm * to_point(f.soup.vertices[t.v[k]]);
    clip_to_view_volume(in, out);
    std::vector<window_point> p;
    for (const hpoint& c : out) p.push_back(to_window(f.view.vp, c.x / c.w, c.y / c.w, c.z / c.w));
    if (p.size() < 3) continue;
    const depth_plane dp = polygon_depth_plane(p);
    std::vector<point2> poly;
    for (const window_point& q : p) poly.push_back({q.x, q.y});
    for_each_covered_pixel_polygon(poly, w, h, [&](int i, int j) {
      const double z = dp.at(i + 0.5, j + 0.5);
      const std::size_t k = static_cast<std::size_t>(j) * w + i;
      if (z < depth[k]) {
        depth[k] = z;
        plane[k] = dp;
        img.set_pixel(i, j, f.color_of(t.face));
      }
    });
  }
  auto project = [&](const vec3d& p) -> vec2d {
    const hpoint c = pm * to_point(p);
    if (!(c.w > 0) || c.z < -2 * c.w) return {std::nan(""), 0.0};
    const window_point q = to_window(f.view.vp, c.x / c.w, c.y / c.w, c.z / c.w);
    return {q.x, q.y};
  };
  for (const curve_spec& cs : f.curves) {
    const flattened_curve poly =
        flatten(bezier_curve(cs.control_points), project, curve_tolerance_px);
    for (std::size_t s = 0; s + 1 < poly.points.size(); ++s) {
      hpoint a, b;
      if (!clip_segment_to_view_volume(pm * to_point(poly.points[s]),
                                       pm * to_point(poly.points[s + 1]), a, b))
        continue;
      const window_point wa = to_window(f.view.vp, a.x / a.w, a.y / a.w, a.z / a.w);
      const window_point wb = to_window(f.view.vp, b.x / b.w, b.y / b.w, b.z / b.w);
      for_each_line_pixel(wa.x, wa.y, wb.x, wb.y, 1, w, h, [&](int i, int j, double t) {
        const std::size_t k = static_cast<std::size_t>(j) * w + i;
        const double x = wa.x + t * (wb.x - wa.x), y = wa.y + t * (wb.y - wa.y),
                     z = wa.z + t * (wb.z - wa.z);
        if (depth[k] == std::numeric_limits<double>::infinity() || z < plane[k].at(x, y))
          img.set_pixel(i, j, cs.color);
      });
    }
  }
  return img;
}

/// Back quad A (red, y = 2), front quad B (blue, y = -2) and a tilted quad C (green) that the
/// curve pierces; the black curve runs at y ~ 0: in front of A, behind B, through C.
frame weaving_frame(int width, int height) {
  triangle_soup s;
  add_quad(s, {-3, 2, -2}, {0.5, 2, -2}, {0.5, 2, 2}, {-3, 2, 2});    // A
  add_quad(s, {0.9, -2, -2}, {3, -2, -2}, {3, -2, 2}, {0.9, -2, 2});  // B
  add_quad(s, {-0.8, -0.4, -1.5}, {0.4, 0.2, -1.5}, {0.4, 0.2, 1.5},
           {-0.8, -0.4, 1.5});  // C: y = x/2
  frame f = perspective_frame(std::move(s), {{220, 40, 40}, {40, 60, 220}, {40, 180, 60}},
                              {{0.4, -7, 1.8}, {0, 0, 0}, {0, 0, 1}}, width, height, 50, 0.5, 50);
  f.curves.push_back(
      {{{-3.2, 0.1, 0.6}, {-1, -0.7, -1.4}, {1, 0.8, 1.2}, {3.3, -0.1, -0.5}}, {0, 0, 0}});
  f.curves.push_back({{{-2.5, 0.3, -1.2}, {0, -0.3, 2.6}, {2.6, 0.3, -1.0}}, {250, 200, 0}});
  return f;
}

TEST(CurveDepth, CurveInFrontOfOneFaceBehindAnotherAndThroughAThirdMatchesAPerPixelOracle) {
  for (const auto& [w, h] : {std::pair{240, 180}, {720, 540}}) {
    frame f = weaving_frame(w, h);
    run(f, {});
    ASSERT_FALSE(f.lines.empty());
    const image oracle = depth_oracle(f);
    int differ = 0, curve_pixels = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        differ += f.picture.pixel(i, j) != oracle.pixel(i, j);
        const rgb8 c = oracle.pixel(i, j);
        curve_pixels += c == rgb8{0, 0, 0} || c == rgb8{250, 200, 0};
      }
    // Pixels may differ only where the curve crosses a face's plane within the pixel (its
    // sample point and the split point round differently) or grazes a face's outline.
    EXPECT_LE(differ, 6) << w << "x" << h << ": of " << curve_pixels << " curve pixels";
    EXPECT_GT(curve_pixels, w / 2);
  }

  // The same with a parallel (orthographic) view: cells ordered by the direction of projection.
  frame o = weaving_frame(240, 180);
  o.view.kind = projection_kind::orthographic;
  o.view.projection = ortho(-4, 4, -3, 3, 1, 30);
  o.view.direction = gaze_direction(o.view.cam);
  run(o, {});
  int differ = 0;
  const image ortho_oracle = depth_oracle(o);
  for (int j = 0; j < 180; ++j)
    for (int i = 0; i < 240; ++i) differ += o.picture.pixel(i, j) != ortho_oracle.pixel(i, j);
  EXPECT_LE(differ, 6) << "orthographic";
  EXPECT_GT(count_color(o.picture, {0, 0, 0}), 100);

  // The test is meaningful: the curve is seen over A and over C, and hidden by B and by C.
  frame f = weaving_frame(240, 180);
  run(f, {});
  triangle_soup only_curves;
  frame bare = weaving_frame(240, 180);
  bare.soup = only_curves;
  run(bare, {});
  int over_a = 0, hidden_by_b = 0, hidden_by_c = 0, over_c = 0;
  frame polys = weaving_frame(240, 180);
  polys.curves.clear();
  run(polys, {});
  for (int j = 0; j < 180; ++j)
    for (int i = 0; i < 240; ++i) {
      if (bare.picture.pixel(i, j) != rgb8{0, 0, 0}) continue;  // the black curve's pixels
      const rgb8 under = polys.picture.pixel(i, j), shown = f.picture.pixel(i, j);
      if (under == rgb8{220, 40, 40} && shown == rgb8{0, 0, 0}) ++over_a;
      if (under == rgb8{40, 60, 220} && shown == under) ++hidden_by_b;
      if (under == rgb8{40, 180, 60} && shown == under) ++hidden_by_c;
      if (under == rgb8{40, 180, 60} && shown == rgb8{0, 0, 0}) ++over_c;
    }
  EXPECT_GT(over_a, 10);
  EXPECT_GT(hidden_by_b, 10);
  EXPECT_GT(hidden_by_c, 0);
  EXPECT_GT(over_c, 0);
}

TEST(CurveDepth, SvgPlacesTheCurveBetweenTheFacesBehindAndInFrontOfIt) {
  triangle_soup s;
  add_quad(s, {-2, 2, -1}, {2, 2, -1}, {2, 2, 1}, {-2, 2, 1});      // face 0 behind the curve
  add_quad(s, {-1, -2, -2}, {1, -2, -2}, {1, -2, 2}, {-1, -2, 2});  // face 1 in front of it
  frame f = perspective_frame(std::move(s), {{200, 0, 0}, {0, 0, 200}},
                              {{0, -8, 0.5}, {0, 0, 0}, {0, 0, 1}}, 120, 90);
  f.curves.push_back({{{-3, 0, 0}, {0, 0.5, 1}, {3, 0, 0}}, {0, 0, 0}});
  f.vector.mode = vector_options::mode_kind::painter;  // the painter's stack keeps every fragment
  run(f, {}, output_kind::svg);
  std::vector<std::string> sequence;  // "face0", "face1", "curve", in document order
  for (std::size_t at = f.svg.find("data-"); at != std::string::npos;
       at = f.svg.find("data-", at + 1)) {
    if (f.svg.compare(at, 12, "data-curve=\"") == 0) {
      sequence.push_back("curve");
    } else if (f.svg.compare(at, 15, "data-fragment=\"") == 0) {
      const std::uint32_t fragment = static_cast<std::uint32_t>(std::stoul(f.svg.substr(at + 15)));
      sequence.push_back("face" + std::to_string(f.fragments.at(fragment).face));
    }
  }
  ASSERT_FALSE(sequence.empty());
  const auto first_curve = std::find(sequence.begin(), sequence.end(), "curve");
  ASSERT_NE(first_curve, sequence.end());
  EXPECT_EQ(std::find(first_curve, sequence.end(), "face0"),
            sequence.end());  // all of face 0 before
  EXPECT_EQ(std::find(sequence.begin(), first_curve, "face1"), first_curve);  // all of face 1 after
  // One polyline path: the pieces of the curve in that slot are joined.
  EXPECT_EQ(std::count(sequence.begin(), sequence.end(), "curve"), 1);
  EXPECT_NE(f.svg.find("fill=\"none\" stroke=\"#000000\" stroke-width=\"1\""), std::string::npos);
}

TEST(CurveDepth, ACurveDrawnOnAFaceIsDrawnOverIt) {
  triangle_soup s;
  add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
  for (double eye_z : {6.0, -6.0}) {  // from the front and from behind
    frame f = perspective_frame(s, {{200, 200, 200}}, {{0.2, -0.3, eye_z}, {0, 0, 0}, {0, 1, 0}},
                                100, 100);
    f.curves.push_back({{{-1.5, -1, 0}, {0, 3, 0}, {1.5, -1, 0}}, {0, 0, 0}});
    run(f, {});
    frame bare = perspective_frame(triangle_soup{}, {}, f.view.cam, 100, 100);
    bare.curves = f.curves;
    run(bare, {});
    const int drawn = count_color(bare.picture, {0, 0, 0});
    EXPECT_GT(drawn, 50);
    EXPECT_EQ(count_color(f.picture, {0, 0, 0}), drawn) << eye_z;
  }
}

TEST(CurveDepth, PointsBehindTheEyeAreClippedBeforeTheDivide) {
  triangle_soup s;
  add_quad(s, {-2, -2, -10}, {2, -2, -10}, {2, 2, -10}, {-2, 2, -10});
  frame f = perspective_frame(std::move(s), {{200, 200, 200}}, {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}},
                              80, 60, 60, 0.5, 50);
  // From far behind the eye, past its side, to far in front; and one curve entirely behind.
  f.curves.push_back({{{0.5, 0.2, 30}, {3, -1, 0.1}, {-4, 1, -0.2}, {-0.5, -0.4, -20}}, {0, 0, 0}});
  f.curves.push_back({{{0, 0, 1}, {1, 1, 5}, {-1, 2, 3}}, {255, 0, 0}});
  f.curves.push_back({{{0.3, 0.3, -4}}, {0, 0, 255}});  // degree 0: one pixel
  run(f, {});
  ASSERT_FALSE(f.lines.empty());
  for (const screen_line& l : f.lines) {
    EXPECT_NE(l.curve, 1u) << "the curve behind the eye is drawn";
    for (const window_point& p : {l.a, l.b}) {
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
      EXPECT_GE(p.x, -1e-9);
      EXPECT_LE(p.x, 80 + 1e-9);
      EXPECT_GE(p.y, -1e-9);
      EXPECT_LE(p.y, 60 + 1e-9);
      EXPECT_GE(p.z, -1e-12);
      EXPECT_LE(p.z, 1 + 1e-12);
    }
  }
  EXPECT_GT(count_color(f.picture, {0, 0, 0}), 20);
  EXPECT_EQ(count_color(f.picture, {255, 0, 0}), 0);
  EXPECT_EQ(count_color(f.picture, {0, 0, 255}), 1);
}

TEST(CurveDepth, CurvesWorkWithEveryEffectAndCullingShiftsTheirSlots) {
  for (const std::vector<std::string>& effects : {std::vector<std::string>{"backface_culling"},
                                                  {"lighting", "fog"},
                                                  {"antialias"},
                                                  {"depth_of_field"}}) {
    frame f = weaving_frame(120, 90);
    f.settings.depth_of_field = {0.05, 0.1, 7, 4};
    f.settings.fog = {fog_mode::linear, 5, 12, 1, {255, 255, 255}};
    run(f, effects);
    EXPECT_FALSE(f.lines.empty());
    for (const screen_line& l : f.lines) EXPECT_LE(l.slot, f.polygons.size());
    EXPECT_LT(count_color(f.picture, f.background), 120 * 90);
  }
}

// Degenerate placements: points and whole curves exactly on a node plane.

/// Pixels of colour c in f's picture and in the picture of its curves alone.
std::pair<int, int> drawn_and_bare(frame& f, rgb8 c) {
  run(f, {});
  frame bare =
      perspective_frame(triangle_soup{}, {}, f.view.cam, f.view.vp.width, f.view.vp.height);
  bare.view = f.view;
  bare.curves = f.curves;
  run(bare, {});
  return {count_color(f.picture, c), count_color(bare.picture, c)};
}

TEST(CurveDepth, ACurveEndExactlyOnAFacePlaneGoesWithItsOtherEnd) {
  triangle_soup s;
  add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
  for (double eye_z : {6.0, -6.0}) {
    frame f = perspective_frame(s, {{200, 200, 200}}, {{0.2, -0.3, eye_z}, {0, 0, 0}, {0, 1, 0}},
                                100, 100);
    // Rises from a point of the face (exactly on its plane) to z = 1.5, and a curve touching
    // the plane at t = 1/2 only (control points z = 1, -1, 1: B(1/2) has z = 0 exactly).
    f.curves.push_back({{{-1.5, -1, 0}, {0, 0, 1}, {1.5, 1, 1.5}}, {0, 0, 0}});
    f.curves.push_back({{{-1, 1.2, 1}, {0, 1.2, -1}, {1, 1.2, 1}}, {255, 0, 0}});
    const auto [black, bare_black] = drawn_and_bare(f, {0, 0, 0});
    const auto [red, bare_red] = drawn_and_bare(f, {255, 0, 0});
    EXPECT_GT(bare_black, 40);
    EXPECT_GT(bare_red, 20);
    if (eye_z > 0) {  // in front of the face: all of both curves
      EXPECT_EQ(black, bare_black);
      EXPECT_EQ(red, bare_red);
    } else {  // behind it: hidden where the face covers them
      EXPECT_LT(black, bare_black / 2);
      EXPECT_LT(red, bare_red / 2);
    }
  }
}

TEST(CurveDepth, ALineLyingInAFacePlaneIsDrawnOverItFromBothSides) {
  triangle_soup s;
  add_quad(s, {-2, -2, -2}, {2, -2, -2}, {2, 2, 2}, {-2, 2, 2});  // the plane z = y
  for (double side : {1.0, -1.0}) {
    frame f = perspective_frame(s, {{200, 200, 200}},
                                {{0.3, -5 * side, 5 * side}, {0, 0, 0}, {0, 0, 1}}, 100, 100);
    curve_spec line;
    line.control_points = {
        {-1.3, 0.7, 0.7}, {1.1, -0.3, -0.3}, {0.9, 1.7, 1.7}, {-1.9, -1.1, -1.1}};
    line.polyline = true;
    f.curves.push_back(line);
    const auto [drawn, bare] = drawn_and_bare(f, {0, 0, 0});
    EXPECT_GT(bare, 60);
    EXPECT_EQ(drawn, bare) << side;
  }
}

TEST(CurveDepth, ACurveInTheTiltedPlaneOfAFaceIsDrawnOverItDespiteRounding) {
  // A quadratic curve lies in the plane of its control points; the face is their triangle.
  // Flattened points round off that plane by an ulp to either side; the control points'
  // signs (all 0) put every chord on the plane, so the curve is a decal on the face.
  const vec3d p0{-1.3, -0.7, 0.2}, p1{0.1, 2.9, -0.45}, p2{1.7, -0.9, 0.35};
  triangle_soup s;
  s.vertices = {p0, p1, p2};
  s.add_polygon({0, 1, 2}, 0);
  for (double side : {1.0, -1.0}) {
    frame f =
        perspective_frame(s, {{200, 200, 200}},
                          {{0.4 * side, -0.5 * side, 6 * side}, {0, 0.4, 0}, {0, 1, 0}}, 120, 120);
    f.curves.push_back({{p0, p1, p2}, {0, 0, 0}});
    const auto [drawn, bare] = drawn_and_bare(f, {0, 0, 0});
    EXPECT_GT(bare, 60);
    EXPECT_EQ(drawn, bare) << side;
  }
}

/// The cell of point p (sides clamped into [lo, hi] per node as the depth rule does for a
/// piece of a curve with those hull signs), or {-1, 0} when p lies on a node plane.
std::pair<std::int32_t, int> cell_of(const bsp& tree, const vec3d& p,
                                     const std::vector<vec3d>& hull) {
  std::int32_t at = 0;
  for (;;) {
    const bsp_node n = tree.node(static_cast<std::size_t>(at));
    int lo = 1, hi = -1;
    for (const vec3d& h : hull)
      lo = std::min(lo, side_of_plane(n, h)), hi = std::max(hi, side_of_plane(n, h));
    const int s = std::min(hi, std::max(lo, side_of_plane(n, p)));
    if (s == 0) return {-1, 0};
    const std::int32_t next = s > 0 ? n.positive : n.negative;
    if (next < 0) return {at, s};
    at = next;
  }
}

TEST(CurveDepth, EveryPieceIsDrawnAtThePositionOfTheCellHoldingIt) {
  // Point location of each piece's midpoint, node by node with the exact side test, against
  // the chord pushing of place_chord: same cell, same position in the painter's sequence.
  std::vector<frame> frames;
  for (const char* name : {"curves", "lines"}) {
    const scene::scene sc =
        scene::load_scene(std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json");
    scene::scene_geometry g = scene::load_geometry(sc);
    frame f;
    f.view = scene::make_view_setup(sc);
    f.soup = std::move(g.soup);
    f.face_colors = std::move(g.face_colors);
    f.curves = sc.curves;
    frames.push_back(std::move(f));
  }
  frames.push_back(weaving_frame(240, 180));
  frame o = weaving_frame(240, 180);
  o.view.kind = projection_kind::orthographic;
  o.view.projection = ortho(-4, 4, -3, 3, 1, 30);
  o.view.direction = gaze_direction(o.view.cam);
  frames.push_back(std::move(o));
  for (frame& f : frames) {
    run(f, {});
    const curve_cells cells = make_curve_cells(*f.tree, f.view, f.order);
    const placed_curves placed = place_curves(f);
    ASSERT_GT(placed.pieces.size(), 10u);
    std::size_t checked = 0;
    for (const curve_piece& piece : placed.pieces) {
      const vec3d m{0.5 * (piece.a[0] + piece.b[0]), 0.5 * (piece.a[1] + piece.b[1]),
                    0.5 * (piece.a[2] + piece.b[2])};
      const curve_spec& c = f.curves[piece.curve];
      const std::vector<vec3d> hull = c.polyline
                                          ? std::vector<vec3d>{c.control_points[piece.segment],
                                                               c.control_points[piece.segment + 1]}
                                          : c.control_points;
      const auto [node, side] = cell_of(*f.tree, m, hull);
      if (node < 0) continue;  // on a plane: the eye's side decides (ACurveDrawnOnAFace...)
      ++checked;
      EXPECT_EQ(piece.order_position, cells.position[static_cast<std::size_t>(node)][side > 0])
          << "curve " << piece.curve << " segment " << piece.segment << " at t " << piece.t_begin;
    }
    EXPECT_GT(checked, placed.pieces.size() / 2);
  }
}

}  // namespace

namespace {

// JSON stops at scene: each effect of view's catalogue has its parameter reader in
// scene/effect_parameters.cpp, and every reader belongs to an effect of the catalogue.
TEST(EffectCatalog, every_effect_has_a_scene_parameter_reader_and_no_reader_is_orphaned) {
  std::set<std::string> catalogue;
  for (const exbsp::view::effect_description& d : exbsp::view::effect_catalog()) {
    catalogue.insert(d.name);
    EXPECT_NE(exbsp::scene::effect_parameters(d.name), nullptr) << d.name;
  }
  for (const std::string& name : exbsp::scene::effects_with_parameters())
    EXPECT_TRUE(catalogue.count(name)) << name << " has a reader but no catalogue entry";
  EXPECT_EQ(exbsp::scene::effect_parameters("no_such_effect"), nullptr);
}

}  // namespace
