// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of src/scene/: scene validation (every error names its key), defaults, relative mesh
// paths, geometry loading (transforms, face offsets, colours), view setup, the built-in demo,
// the example scenes in scenes/, `exbsp render` output (PNG read back, SVG parsed back) and
// atomic output on errors.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/scene/procedural.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/stages.h>
#include "scene/demo_scene.h"
#include "scene/render.h"
#include "scene/scene.h"
#include "view/effects.h"
#include "view/backface_culling.h"
#include "view/clip_stage.h"
#include "view/rasterizer.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp;
using nlohmann::json;
namespace fs = std::filesystem;

std::string temp_dir() {
  static const std::string dir = [] {
    const std::string d = exbsp_test::make_temp_dir("test_scene").string();
    fs::create_directories(d + "/meshes");
    std::ofstream(d + "/meshes/tri.off")
        << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n";
    return d;
  }();
  return dir;
}

std::string write_text(const std::string& name, const std::string& text) {
  const std::string path = temp_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

/// A valid scene; tests break one field at a time.
json valid_scene() {
  return json::parse(R"({
    "meshes": [{"file": "meshes/tri.off", "color": [200, 40, 40]}],
    "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0]},
    "projection": {"type": "perspective", "fovy_deg": 40, "near": 1, "far": 100},
    "viewport": {"width": 64, "height": 48}
  })");
}

scene::scene parse(const json& doc, std::ostream* warnings = nullptr) {
  return scene::parse_scene(doc, temp_dir() + "/scene.json", warnings);
}

/// The key named by the scene_error thrown for `doc`, or "(no error)".
std::string error_key(const json& doc, std::string* message = nullptr) {
  return exbsp_test::error_key([&] { parse(doc); }, message);
}

// ---------------------------------------------------------------------------------------
// Validation

TEST(SceneParse, ValidSceneAndDefaults) {
  const scene::scene s = parse(valid_scene());
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].color, (view::rgb8{200, 40, 40}));
  EXPECT_EQ(s.meshes[0].transform.m, view::mat4::identity().m);
  EXPECT_EQ(s.meshes[0].path, (fs::path(temp_dir()) / "meshes/tri.off").string());
  EXPECT_EQ(s.background, (view::rgb8{255, 255, 255}));
  EXPECT_TRUE(s.effects.empty());
  EXPECT_TRUE(s.curves.empty());
  EXPECT_EQ(s.width, 64);
  EXPECT_EQ(s.projection.kind, view::projection_kind::perspective);
  json d = valid_scene();
  d["meshes"][0].erase("color");
  EXPECT_EQ(parse(d).meshes[0].color, (view::rgb8{160, 160, 160}));  // grey
}

struct bad_case {
  const char* name;
  std::function<void(json&)> mutate;
  const char* key;
};

/// A mutation that sets the value at JSON pointer `at` to the JSON text `value`.
std::function<void(json&)> set(const char* at, const char* value) {
  return [at, value](json& d) { d[json::json_pointer(at)] = json::parse(value); };
}

/// A mutation that sets "projection" to {"type": type, "left": -1, "right": 1, "bottom": -1,
/// "top": 1, "near": 1, "far": 9} with `changes` merged in (RFC 7396: null removes a key).
std::function<void(json&)> projection(const char* type, const char* changes = "{}") {
  return [type, changes](json& d) {
    d["projection"] = json::parse(R"({"left": -1, "right": 1, "bottom": -1, "top": 1, "near": 1,
                                     "far": 9})");
    d["projection"]["type"] = type;
    d["projection"].merge_patch(json::parse(changes));
  };
}

TEST(SceneParse, EveryErrorNamesItsKey) {
  const std::vector<bad_case> cases = {
      {"meshes missing", [](json& d) { d.erase("meshes"); }, "/meshes"},
      {"meshes not an array", [](json& d) { d["meshes"] = 3; }, "/meshes"},
      {"mesh not an object", [](json& d) { d["meshes"][0] = "x.off"; }, "/meshes/0"},
      {"mesh file missing", [](json& d) { d["meshes"][0].erase("file"); }, "/meshes/0/file"},
      {"mesh file not a string", [](json& d) { d["meshes"][0]["file"] = 7; }, "/meshes/0/file"},
      {"color not an array", [](json& d) { d["meshes"][0]["color"] = "red"; }, "/meshes/0/color"},
      {"color two numbers", set("/meshes/0/color", R"([1, 2])"), "/meshes/0/color"},
      {"color above 255", set("/meshes/0/color", R"([1, 256, 3])"), "/meshes/0/color/1"},
      {"color negative", set("/meshes/0/color", R"([-1, 2, 3])"), "/meshes/0/color/0"},
      {"color fraction", set("/meshes/0/color", R"([1, 2, 3.5])"), "/meshes/0/color/2"},
      {"color string", set("/meshes/0/color", R"([1, "2", 3])"), "/meshes/0/color/1"},
      {"transform 15 numbers",
       [](json& d) { d["meshes"][0]["transform"] = std::vector<double>(15, 0.0); },
       "/meshes/0/transform"},
      {"transform not numbers",
       [](json& d) {
         json t = std::vector<double>(16, 0.0);
         t[5] = "one";
         d["meshes"][0]["transform"] = t;
       },
       "/meshes/0/transform/5"},
      {"camera missing", [](json& d) { d.erase("camera"); }, "/camera"},
      {"camera not an object", set("/camera", R"([1, 2, 3])"), "/camera"},
      {"eye missing", [](json& d) { d["camera"].erase("eye"); }, "/camera/eye"},
      {"eye two numbers", set("/camera/eye", R"([1, 2])"), "/camera/eye"},
      {"eye string", set("/camera/eye", R"([1, "2", 3])"), "/camera/eye/1"},
      {"look_at equals eye", set("/camera/look_at", R"([0, 0, 5])"), "/camera/look_at"},
      {"up parallel to gaze", set("/camera/up", R"([0, 0, 2])"), "/camera/up"},
      {"up zero", set("/camera/up", R"([0, 0, 0])"), "/camera/up"},
      {"projection missing", [](json& d) { d.erase("projection"); }, "/projection"},
      {"projection type missing", [](json& d) { d["projection"].erase("type"); },
       "/projection/type"},
      {"projection type unknown", [](json& d) { d["projection"]["type"] = "fisheye"; },
       "/projection/type"},
      {"fovy missing", [](json& d) { d["projection"].erase("fovy_deg"); }, "/projection/fovy_deg"},
      {"fovy zero", [](json& d) { d["projection"]["fovy_deg"] = 0; }, "/projection/fovy_deg"},
      {"fovy 180", [](json& d) { d["projection"]["fovy_deg"] = 180; }, "/projection/fovy_deg"},
      {"fovy string", [](json& d) { d["projection"]["fovy_deg"] = "40"; }, "/projection/fovy_deg"},
      {"near zero", [](json& d) { d["projection"]["near"] = 0; }, "/projection/near"},
      {"near negative", [](json& d) { d["projection"]["near"] = -1; }, "/projection/near"},
      {"near missing", [](json& d) { d["projection"].erase("near"); }, "/projection/near"},
      {"near equals far", [](json& d) { d["projection"]["far"] = 1; }, "/projection/far"},
      {"near beyond far", [](json& d) { d["projection"]["far"] = 0.5; }, "/projection/far"},
      {"ortho left missing", projection("orthographic", R"({"left": null})"), "/projection/left"},
      {"ortho left equals right", projection("orthographic", R"({"left": 1})"),
       "/projection/right"},
      {"frustum bottom above top", projection("frustum", R"({"bottom": 2})"), "/projection/top"},
      {"frustum near zero", projection("frustum", R"({"near": 0})"), "/projection/near"},
      {"oblique direction missing", projection("oblique"), "/projection/direction"},
      {"oblique direction away from the scene",
       projection("oblique", R"({"direction": [0.5, 0, 1]})"), "/projection/direction"},
      {"oblique direction zero", projection("oblique", R"({"direction": [0, 0, 0]})"),
       "/projection/direction"},
      {"viewport missing", [](json& d) { d.erase("viewport"); }, "/viewport"},
      {"viewport width zero", [](json& d) { d["viewport"]["width"] = 0; }, "/viewport/width"},
      {"viewport height huge", [](json& d) { d["viewport"]["height"] = 16385; },
       "/viewport/height"},
      {"viewport width fraction", [](json& d) { d["viewport"]["width"] = 64.5; },
       "/viewport/width"},
      {"viewport height missing", [](json& d) { d["viewport"].erase("height"); },
       "/viewport/height"},
      {"background out of range", set("/background", R"([0, 0, 300])"), "/background/2"},
      {"background wrong type", [](json& d) { d["background"] = "white"; }, "/background"},
      {"raster not an object", set("/raster", R"("edges")"), "/raster"},
      {"raster edges unknown", set("/raster", R"({"edges": "all"})"), "/raster/edges"},
      {"raster crease zero", set("/raster", R"({"crease_deg": 0})"), "/raster/crease_deg"},
      {"raster mode", set("/raster", R"({"mode": "painter"})"), "/raster/mode"},
      {"raster wireframe not a bool", set("/raster", R"({"wireframe": 1})"), "/raster/wireframe"},
      {"raster wireframe without edges", set("/raster", R"({"wireframe": true, "edges": "none"})"),
       "/raster/wireframe"},
      {"effects not an object", [](json& d) { d["effects"] = {"backface_culling"}; }, "/effects"},
      {"effect unknown",
       [](json& d) {
         d["effects"] = {{"sparkle", true}};
       },
       "/effects/sparkle"},
      {"effect lighting bad parameter",
       [](json& d) {
         d["effects"] = {{"lighting", {{"ambient", -1}}}};
       },
       "/effects/lighting/ambient"},
      {"effect fog unknown parameter",
       [](json& d) {
         d["effects"] = {{"fog", {{"far", 3}}}};
       },
       "/effects/fog/far"},
      {"effect wrong type",
       [](json& d) {
         d["effects"] = {{"backface_culling", 3}};
       },
       "/effects/backface_culling"},
      {"effect unknown parameter",
       [](json& d) {
         d["effects"] = {{"backface_culling", {{"mode", "front"}}}};
       },
       "/effects/backface_culling/mode"},
      {"curves not an array", [](json& d) { d["curves"] = 5; }, "/curves"},
      {"curve not an object", [](json& d) { d["curves"] = {3}; }, "/curves/0"},
      {"curve bezier missing",
       [](json& d) {
         d["curves"] = {{{"color", {0, 0, 0}}}};
       },
       "/curves/0/bezier"},
      {"curve bezier empty",
       [](json& d) {
         d["curves"] = {{{"bezier", json::array()}}};
       },
       "/curves/0/bezier"},
      {"curve bezier not an array",
       [](json& d) {
         d["curves"] = {{{"bezier", "arc"}}};
       },
       "/curves/0/bezier"},
      {"curve control point two numbers",
       [](json& d) {
         d["curves"] = {{{"bezier", {{0, 0, 0}, {1, 1, 1}, {2, 2}}}}};
       },
       "/curves/0/bezier/2"},
      {"curve coordinate not a number",
       [](json& d) {
         d["curves"] = {{{"bezier", {{0, 0, 0}, {1, 1, "z"}}}}};
       },
       "/curves/0/bezier/1/2"},
      {"curve coordinate infinite",
       [](json& d) {
         d["curves"] = {{{"bezier", {{0, 0, 0}, {1, 1, 1}}}}};
         d["curves"][0]["bezier"][0][2] = std::numeric_limits<double>::infinity();
       },
       "/curves/0/bezier/0/2"},
      {"curve with too many control points",
       [](json& d) {
         json pts = json::array();
         for (std::size_t k = 0; k <= scene::max_curve_control_points; ++k)
           pts.push_back({k, 0, 0});
         d["curves"] = {{{"bezier", pts}}};
       },
       "/curves/0/bezier"},
      {"second curve colour out of range",
       [](json& d) {
         d["curves"] = {{{"bezier", {{0, 0, 0}}}},
                        {{"bezier", {{0, 0, 0}, {1, 0, 0}}}, {"color", {0, 256, 0}}}};
       },
       "/curves/1/color/1"},
      {"root not an object", [](json& d) { d = json::array(); }, ""},
  };
  for (const bad_case& c : cases) {
    json d = valid_scene();
    c.mutate(d);
    std::string message;
    EXPECT_EQ(error_key(d, &message), c.key) << c.name;
    if (*c.key) {
      EXPECT_NE(message.find(c.key), std::string::npos) << c.name << ": " << message;
    }
    EXPECT_NE(message.find("scene.json"), std::string::npos) << c.name << ": " << message;
  }
}

TEST(SceneParse, EffectsSetToFalseAreNotAskedFor) {
  json d = valid_scene();
  d["effects"] = {{"depth_of_field", false}, {"antialias", false}, {"fog", false}};
  EXPECT_TRUE(parse(d).effects.empty());
  // Every effect of the catalogue is implemented now.
  for (const view::effect_description& e : view::effect_catalog())
    EXPECT_TRUE(e.available) << e.name;
}

TEST(SceneParse, EffectsAndCurves) {
  json d = valid_scene();
  d["effects"] = {{"backface_culling", true}};
  EXPECT_EQ(parse(d).effects, std::vector<std::string>{"backface_culling"});
  d["effects"] = {{"backface_culling", json::object()}};
  EXPECT_EQ(parse(d).effects, std::vector<std::string>{"backface_culling"});
  d["effects"] = {{"backface_culling", false}};
  EXPECT_TRUE(parse(d).effects.empty());
  // Curves: empty or absent accepted; non-empty parsed (colour default black), no warning.
  d["curves"] = json::array();
  EXPECT_TRUE(parse(d).curves.empty());
  d["curves"] = json::parse(
      R"([{"bezier": [[0,0,0],[1,1,0],[2,0,0]], "color": [10,20,30]}, {"bezier": [[1,2,3]]}])");
  std::ostringstream warnings;
  const scene::scene s = parse(d, &warnings);
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_EQ(s.curves[0].control_points.size(), 3u);
  EXPECT_EQ(s.curves[0].control_points[1], (vec3d{1, 1, 0}));
  EXPECT_EQ(s.curves[0].color, (view::rgb8{10, 20, 30}));
  EXPECT_EQ(s.curves[1].control_points.size(), 1u);
  EXPECT_EQ(s.curves[1].color, (view::rgb8{0, 0, 0}));
  EXPECT_TRUE(warnings.str().empty()) << warnings.str();
}

TEST(SceneParse, UnknownKeysAreWarnedAboutAndIgnored) {
  json d = valid_scene();
  d["title"] = "x";
  d["camera"]["roll"] = 3;
  std::ostringstream warnings;
  parse(d, &warnings);
  EXPECT_NE(warnings.str().find("/title"), std::string::npos);
  EXPECT_NE(warnings.str().find("/camera/roll"), std::string::npos);
}

TEST(SceneParse, SyntaxErrorsAndMissingFiles) {
  try {
    scene::parse_scene_text("{\"meshes\": [", "broken.json");
    FAIL() << "no error";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.key(), "");
    EXPECT_NE(std::string(e.what()).find("broken.json"), std::string::npos);
  }
  EXPECT_THROW(scene::load_scene(temp_dir() + "/no_such_scene.json"), input_error);
}

TEST(SceneParse, ObliqueAndOrthographicViews) {
  json d = valid_scene();
  d["projection"] = json::parse(
      R"({"type": "orthographic", "left": -2, "right": 2, "bottom": -1.5, "top": 1.5, "near": 1, "far": 9})");
  view::view_setup v = scene::make_view_setup(parse(d));
  EXPECT_TRUE(v.is_parallel());
  EXPECT_DOUBLE_EQ(v.direction.z, -1);  // the gaze
  d["projection"]["type"] = "oblique";
  d["projection"]["direction"] = {1, 0, -1};
  v = scene::make_view_setup(parse(d));
  EXPECT_EQ(v.kind, view::projection_kind::oblique);
  EXPECT_NEAR(v.direction.x, std::sqrt(0.5), 1e-15);
  // A point moved along the direction of projection keeps its image.
  const view::mat4 pm = v.projection * v.model_view;
  const view::hpoint a = pm * view::point3{0.2, 0.3, -1}, b = pm * view::point3{1.2, 0.3, -2};
  EXPECT_NEAR(a.x, b.x, 1e-14);
  EXPECT_NEAR(a.y, b.y, 1e-14);
  // The look-at point (on the view plane) projects to the window centre.
  const view::hpoint c = pm * view::point3{0, 0, 0};
  EXPECT_NEAR(c.x, 0, 1e-15);
  EXPECT_NEAR(c.y, 0, 1e-15);
}

// ---------------------------------------------------------------------------------------
// Geometry

TEST(SceneGeometry, TransformsFaceOffsetsAndColours) {
  json d = valid_scene();
  json second = {{"file", temp_dir() + "/meshes/tri.off"},  // absolute path
                 {"color", {1, 2, 3}},
                 {"transform", {1, 0, 0, 10, 0, 1, 0, 20, 0, 0, 1, 30, 0, 0, 0, 1}}};
  d["meshes"].push_back(second);
  const scene::scene s = parse(d);
  const scene::scene_geometry g = scene::load_geometry(s);
  EXPECT_EQ(g.soup.face_count, 4u);
  EXPECT_EQ(g.soup.triangles.size(), 4u);
  EXPECT_EQ(g.face_offsets, (std::vector<std::uint32_t>{0, 2, 4}));
  ASSERT_EQ(g.face_colors.size(), 4u);
  EXPECT_EQ(g.face_colors[1], (view::rgb8{200, 40, 40}));
  EXPECT_EQ(g.face_colors[2], (view::rgb8{1, 2, 3}));
  EXPECT_EQ(scene::mesh_of_face(g, 0), 0u);
  EXPECT_EQ(scene::mesh_of_face(g, 3), 1u);
  EXPECT_EQ(scene::mesh_of_face(g, 9), 2u);
  EXPECT_EQ(g.soup.vertices[4], (vec3d{10, 20, 30}));
  EXPECT_EQ(g.soup.vertices[5], (vec3d{11, 20, 30}));
}

TEST(SceneGeometry, MissingMeshFileNamesTheKey) {
  json d = valid_scene();
  d["meshes"].push_back({{"file", "meshes/absent.off"}});
  try {
    scene::load_geometry(parse(d));
    FAIL() << "no error";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.key(), "/meshes/1/file");
    EXPECT_NE(std::string(e.what()).find("absent.off"), std::string::npos);
  }
}

TEST(SceneGeometry, TransformToInfinityIsAnError) {
  json d = valid_scene();
  d["meshes"][0]["transform"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
  try {
    scene::load_geometry(parse(d));
    FAIL() << "no error";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.key(), "/meshes/0/transform");
  }
}

/// Signed volume sum over triangles of a . (b x c) / 6: positive for a closed mesh with
/// outward normals (divergence theorem).
double signed_volume(const triangle_soup& s) {
  double volume = 0;
  for (const soup_triangle& t : s.triangles) {
    const vec3d &a = s.vertices[t.v[0]], &b = s.vertices[t.v[1]], &c = s.vertices[t.v[2]];
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0])) /
              6;
  }
  return volume;
}

TEST(Procedural, ClosedSolidsHaveOutwardNormals) {
  EXPECT_NEAR(signed_volume(scene::make_box({0, 0, 0}, {1, 2, 3})), 6.0, 1e-12);
  EXPECT_NEAR(signed_volume(scene::make_prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, 2)), 2.0, 1e-12);
  EXPECT_GT(signed_volume(scene::make_gear(8, 1, 1.3, 0.4, 0.3)), 0);
  EXPECT_EQ(scene::make_cyclic_planks(1, 2, 0.5, 0.2).face_count, 3u);
  EXPECT_THROW(scene::make_box({0, 0, 0}, {0, 1, 1}), usage_error);
}

// ---------------------------------------------------------------------------------------
// Rendering

using exbsp_test::colours_of;

TEST(Render, BuiltInDemoScene) {
  const scene::scene demo = scene::demo_scene();
  EXPECT_EQ(demo.width, 800);
  EXPECT_EQ(demo.height, 600);
  const std::string out = temp_dir() + "/demo.png";
  std::ostringstream log;
  render_command({"", out, true}, log);
  const view::image img = view::read_png(out);
  EXPECT_EQ(img.width(), 800);
  EXPECT_EQ(img.height(), 600);
  EXPECT_GT(colours_of(img).size(), 10u);
  const std::string s = log.str();
  for (const char* stage :
       {"stage build:", "stage order:", "stage transform+clip:", "stage raster:", "stage write:"})
    EXPECT_NE(s.find(stage), std::string::npos) << stage;
  EXPECT_EQ(s.find("backface_culling"), std::string::npos);
  // The cyclic planks force at least one split.
  const std::size_t at = s.find(" splits");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NE(s.substr(at - 2, 2), " 0");
}

TEST(Render, DefaultOutputIsExbspPngInTheCurrentDirectory) {
  const std::string dir = temp_dir() + "/cwd";
  fs::create_directories(dir);
  const fs::path old = fs::current_path();
  fs::current_path(dir);
  std::ostringstream log;
  EXPECT_NO_THROW(render_command({"", "", false}, log));
  fs::current_path(old);
  EXPECT_TRUE(fs::exists(dir + "/exbsp.png"));
  EXPECT_TRUE(log.str().empty());
}

TEST(Render, UnknownOutputExtensionIsRejected) {
  std::ostringstream log;
  EXPECT_THROW(render_command({"", temp_dir() + "/out.jpg", false}, log), usage_error);
  EXPECT_FALSE(fs::exists(temp_dir() + "/out.jpg"));
}

TEST(Render, ErrorsLeaveNoPartialOutput) {
  const std::string out = temp_dir() + "/kept.png";
  std::ofstream(out) << "old";
  json d = valid_scene();
  d["projection"]["near"] = -1;
  const std::string bad = write_text("bad_scene.json", d.dump());
  std::ostringstream log;
  EXPECT_THROW(render_command({bad, out, false}, log), scene_error);
  std::ifstream in(out);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "old");
  const std::string missing_out = temp_dir() + "/never.svg";
  json m = valid_scene();
  m["meshes"][0]["file"] = "meshes/absent.off";
  EXPECT_THROW(render_command({write_text("missing_mesh.json", m.dump()), missing_out, false}, log),
               scene_error);
  EXPECT_FALSE(fs::exists(missing_out));
  for (const auto& e : fs::directory_iterator(temp_dir()))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST(Render, BackfaceCullingRunsOnlyWhenAskedFor) {
  json d = valid_scene();
  std::ostringstream log;
  const std::string out = temp_dir() + "/culled.png";
  render_command({write_text("plain.json", d.dump()), out, true}, log);
  EXPECT_EQ(log.str().find("backface_culling"), std::string::npos);
  d["effects"] = {{"backface_culling", true}};
  log.str("");
  render_command({write_text("culling.json", d.dump()), out, true}, log);
  EXPECT_NE(log.str().find("stage backface_culling:"), std::string::npos);
}

/// Renders a scene from scenes/ to PNG and SVG; returns the SVG's data-face sequence (one path
/// per visible region, view/vector_drawing.h).
std::vector<std::uint32_t> render_example(const std::string& name, view::image& png) {
  const std::string scene_path = std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json";
  const std::string png_path = temp_dir() + "/" + name + ".png",
                    svg_path = temp_dir() + "/" + name + ".svg";
  std::ostringstream log;
  render_command({scene_path, png_path, false}, log);
  render_command({scene_path, svg_path, false}, log);
  EXPECT_TRUE(log.str().empty()) << log.str();
  png = view::read_png(png_path);
  std::ifstream in(svg_path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  // (String scanning rather than <regex>: GCC 12's <regex> trips -Wmaybe-uninitialized in
  // the sanitizer build.)
  const std::string key = "data-face=\"";
  std::vector<std::uint32_t> frags;
  for (std::size_t at = svg.find(key); at != std::string::npos; at = svg.find(key, at + 1))
    frags.push_back(static_cast<std::uint32_t>(std::stoul(svg.substr(at + key.size()))));
  return frags;
}

TEST(Render, ExampleScenesRenderToPngAndSvg) {
  for (const char* name :
       {"perspective", "orthographic", "oblique", "frustum", "inside", "cyclic"}) {
    view::image png;
    const std::vector<std::uint32_t> frags = render_example(name, png);
    EXPECT_GT(frags.size(), 0u) << name;
    EXPECT_GT(colours_of(png).size(), 3u) << name;

    // Visible regions: each face at most once.
    EXPECT_EQ(std::set<std::uint32_t>(frags.begin(), frags.end()).size(), frags.size()) << name;
    // The painter's SVG: its paths are exactly the visible fragments in back-to-front order.
    const scene::scene s =
        scene::load_scene(std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json");
    scene::scene_geometry g = scene::load_geometry(s);
    view::frame f;
    f.view = scene::make_view_setup(s);
    f.soup = std::move(g.soup);
    f.face_colors = std::move(g.face_colors);
    f.vector.mode = view::vector_options::mode_kind::painter;
    view::standard_pipeline(s.effects, view::output_kind::svg).run(f, nullptr);
    std::vector<std::uint32_t> expected, painted;
    for (const view::screen_polygon& p : f.polygons) expected.push_back(p.fragment);
    const std::string fragment_key = "data-fragment=\"";
    for (std::size_t at = f.svg.find(fragment_key); at != std::string::npos;
         at = f.svg.find(fragment_key, at + 1))
      painted.push_back(
          static_cast<std::uint32_t>(std::stoul(f.svg.substr(at + fragment_key.size()))));
    EXPECT_EQ(painted, expected) << name;
    EXPECT_EQ(f.polygons.size() + f.fully_clipped + f.culled, f.fragments.size()) << name;
    if (std::string(name) == "inside") {
      EXPECT_GT(f.fully_clipped, 0u);  // the near plane cuts the room around the eye
      EXPECT_GT(f.culled, 0u);
    }
    if (std::string(name) == "cyclic") {
      EXPECT_GT(f.tree->stats().splits, 0u);
    }
  }
}

using exbsp_test::zbuffer_render;

TEST(Render, ExampleScenesMatchAZBufferOracle) {
  for (const char* name : {"demo", "perspective", "orthographic", "oblique", "frustum", "inside",
                           "cyclic", "groups", "camera_look", "camera_polar", "camera_pilot",
                           "phigs_perspective", "phigs_oblique", "viewport", "trackball"}) {
    const scene::scene s =
        std::string(name) == "demo"
            ? scene::demo_scene()
            : scene::load_scene(std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json");
    scene::scene_geometry g = scene::load_geometry(s);
    view::frame f;
    f.view = scene::make_view_setup(s);
    f.background = s.background;
    f.soup = std::move(g.soup);
    f.face_colors = std::move(g.face_colors);
    view::standard_pipeline(s.effects, view::output_kind::png).run(f, nullptr);
    const bool cull =
        std::find(s.effects.begin(), s.effects.end(), "backface_culling") != s.effects.end();
    const view::image oracle = zbuffer_render(f, cull);
    int differ = 0;
    for (int r = 0; r < oracle.height(); ++r)
      for (int c = 0; c < oracle.width(); ++c)
        differ += oracle.at_row(r, c) != f.picture.at_row(r, c);
    // Pixels may differ only where depths tie: along the intersection lines of interpenetrating
    // parts and on T-junctions of split fragments.
    std::cout << name << ": " << differ << " of " << oracle.width() * oracle.height()
              << " pixels differ\n";
    EXPECT_LE(differ, oracle.width() * oracle.height() / 10000) << name;
  }
}

TEST(Render, CommandLineExitCodes) {
  const std::string cli = EXBSP_CLI;
  json d = valid_scene();
  d["camera"]["up"] = {0, 0, 1};
  const std::string bad = write_text("cli_bad.json", d.dump());
  const std::string err = temp_dir() + "/cli_err.txt";
  const int rc =
      std::system((cli + " render " + bad + " -o " + temp_dir() + "/cli.png 2> " + err).c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("/camera/up"), std::string::npos) << text.str();
  EXPECT_FALSE(fs::exists(temp_dir() + "/cli.png"));
}

// ---------------------------------------------------------------------------------------
// Effect and curve scenes in scenes/, and the trackball orbit

TEST(Render, EffectScenesRunTheirEffectStages) {
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {"effects_lighting", "lighting"},
      {"effects_fog", "fog"},
      {"effects_dof", "depth_of_field"},
      {"effects_antialias", "antialias"},
      {"effects_smooth", "lighting"},
      {"effects_exposure", "exposure"},
      {"curves", "curves"}};
  for (const auto& [name, stage] : scenes) {
    const std::string scene_path = std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json";
    const std::string png = temp_dir() + "/" + name + ".png";
    std::ostringstream log;
    render_command({scene_path, png, true}, log);
    EXPECT_NE(log.str().find("stage " + stage + ":"), std::string::npos) << name << "\n"
                                                                         << log.str();
    EXPECT_EQ(log.str().find("warning"), std::string::npos) << log.str();
    const view::image img = view::read_png(png);
    EXPECT_EQ(img.width(), 400) << name;
    EXPECT_GT(colours_of(img).size(), 10u) << name;
    // SVG: PNG-only effects are skipped with a warning; the others have their stage.
    std::ostringstream svg_log;
    render_command({scene_path, temp_dir() + "/" + name + ".svg", true}, svg_log);
    const bool png_only = stage == "antialias" || stage == "depth_of_field" || stage == "exposure";
    EXPECT_EQ(svg_log.str().find("stage " + stage + ":") == std::string::npos, png_only) << name;
    EXPECT_EQ(svg_log.str().find("applies to PNG output only") != std::string::npos, png_only)
        << name;
  }
}

TEST(Orbit, FramePathsAndResampling) {
  EXPECT_EQ(frame_path("out/anim.png", 7), "out/anim_0007.png");
  EXPECT_EQ(frame_path("a.b/anim.svg", 12345), "a.b/anim_12345.svg");
  EXPECT_EQ(frame_path("noext", 1), "noext_0001");
  const auto r = resample_path({{0, 0}, {10, 0}, {10, 10}}, 5);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0], (std::array<double, 2>{0, 0}));
  EXPECT_EQ(r[1], (std::array<double, 2>{5, 0}));
  EXPECT_EQ(r[2], (std::array<double, 2>{10, 0}));
  EXPECT_EQ(r[3], (std::array<double, 2>{10, 5}));
  EXPECT_EQ(r[4], (std::array<double, 2>{10, 10}));
  EXPECT_EQ(resample_path({{3, 4}}, 3).size(), 3u);
  EXPECT_THROW(resample_path({}, 3), usage_error);
}

TEST(Orbit, CamerasTurnAboutTheLookAtPointStartingAtTheSceneCamera) {
  const scene::scene s = scene::demo_scene();
  const auto cams = orbit_cameras(s, {{400, 300}, {500, 300}, {500, 200}}, 6);
  ASSERT_EQ(cams.size(), 6u);
  const view::camera& c0 = cams[0].first;
  EXPECT_EQ(c0.look_at.x, s.camera.look_at.x);
  EXPECT_NEAR(view::length(c0.eye - s.camera.eye), 0, 1e-12);
  const double r = view::length(s.camera.eye - s.camera.look_at);
  for (const auto& [c, d] : cams) EXPECT_NEAR(view::length(c.eye - c.look_at), r, 1e-9 * r);
  EXPECT_GT(view::length(cams.back().first.eye - s.camera.eye), 0.5);
  // Dragging right turns the scene to the right: the eye moves to -x (the camera's left).
  const auto right = orbit_cameras(s, {{400, 300}, {450, 300}}, 0);
  EXPECT_LT(right.back().first.eye.x, s.camera.eye.x);
}

TEST(Orbit, WritesNFramesFromOneBuild) {
  const std::string out = temp_dir() + "/orbit/demo.png";
  fs::create_directories(temp_dir() + "/orbit");
  render_request request{"", out, true};
  request.orbit_drag = {{400, 300}, {520, 280}, {560, 180}};
  request.frames = 5;
  std::ostringstream log;
  render_command(request, log);
  const std::string text = log.str();
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(count("stage build:"), 1u) << text;
  EXPECT_EQ(count("stage order:"), 5u) << text;
  EXPECT_EQ(count("stage write:"), 5u) << text;
  for (std::size_t k = 0; k < 5; ++k) EXPECT_TRUE(fs::exists(frame_path(out, k))) << k;
  EXPECT_FALSE(fs::exists(frame_path(out, 5)));
  EXPECT_FALSE(fs::exists(out));
  // Frame 0 is the scene's own view; the last one differs.
  const std::string still = temp_dir() + "/orbit/still.png";
  std::ostringstream quiet;
  render_command({"", still, false}, quiet);
  EXPECT_EQ(view::read_png(frame_path(out, 0)).data(), view::read_png(still).data());
  EXPECT_NE(view::read_png(frame_path(out, 4)).data(), view::read_png(still).data());
  // --frames without a drag is an error.
  render_request bad{"", out, false};
  bad.frames = 3;
  EXPECT_THROW(render_command(bad, quiet), usage_error);
}

TEST(Orbit, CommandLine) {
  const std::string cli = EXBSP_CLI;
  const std::string dir = temp_dir() + "/orbit_cli";
  fs::create_directories(dir);
  const std::string scene_path = std::string(EXBSP_SOURCE_DIR) + "/scenes/effects_antialias.json";
  const int rc =
      std::system((cli + " render " + scene_path + " --orbit-drag 200,150:260,150 --frames 3 -o " +
                   dir + "/o.svg 2> " + dir + "/err.txt")
                      .c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(fs::exists(frame_path(dir + "/o.svg", k))) << k;
  const int bad = std::system(
      (cli + " render --orbit-drag 1,2:x -o " + dir + "/p.png 2> " + dir + "/err2.txt").c_str());
  ASSERT_TRUE(WIFEXITED(bad));
  EXPECT_EQ(WEXITSTATUS(bad), 2);
  std::ifstream in(dir + "/err2.txt");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("--orbit-drag"), std::string::npos) << text.str();
}

}  // namespace
