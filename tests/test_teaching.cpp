// SPDX-License-Identifier: LGPL-3.0-or-later
// Teaching views ("teaching": docs/contract.md "Scenes", scene/teaching.cpp): the observed
// camera's view volume and reference frame drawn as lines, the depth-sort painter, and dropping
// polygons at the near plane instead of cutting them. The view volume's corners are computed
// here from the observed camera's parameters and projected with this file's own gluLookAt and
// gluPerspective (not view/matrix.h); the near-plane test decides which polygons cross with
// its own eye-space depths. Mesa's z-buffer comparison of the depth sort is in
// test_oracle_gl.cpp.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/view/image.h>
#include <exbsp/view/stages.h>
#include <exbsp/view/standard_pipeline.h>
#include "scene/render.h"
#include "scene/scene.h"
#include "support/test_helpers.h"

using namespace exbsp;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

using v3 = std::array<double, 3>;
using exbsp_test::add;
using exbsp_test::cross;
using exbsp_test::dot;
using exbsp_test::scale;
using exbsp_test::sub;
using exbsp_test::unit;

v3 triple(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

std::string example_path(const std::string& name) {
  return std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json";
}

json example_json(const std::string& name) {
  std::ifstream in(example_path(name));
  return json::parse(in);
}

const std::string& temp_dir() {
  static const std::string dir = exbsp_test::make_temp_dir("test_teaching").string();
  return dir;
}

/// The PNG pipeline (build, then the per-view stages; no write) on the scene's frame.
view::frame rendered(const scene::scene& s) {
  view::frame f = scene::make_frame(s);
  view::standard_pipeline(s.effects, view::output_kind::png, !s.curves.empty()).run(f, nullptr);
  return f;
}

bool same_pixels(const view::image& a, const view::image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int r = 0; r < a.height(); ++r)
    for (int k = 0; k < a.width(); ++k)
      if (a.at_row(r, k) != b.at_row(r, k)) return false;
  return true;
}

/// A gluLookAt + gluPerspective camera of this file: world point -> window point (x, y).
struct test_camera {
  v3 eye, s, u, g;  // g: unit gaze; s = g x up; u = s x g
  double f, aspect;
  int width, height;
  test_camera(const json& cam, const json& proj, int w, int h)
      : eye(triple(cam["eye"])), width(w), height(h) {
    g = unit(sub(triple(cam["look_at"]), eye));
    s = unit(cross(g, triple(cam["up"])));
    u = cross(s, g);
    f = 1 / std::tan(proj["fovy_deg"].get<double>() * M_PI / 360);
    aspect = static_cast<double>(w) / h;
  }
  /// Window coordinates (OpenGL: y up, pixel (i, j) covers [i, i+1] x [j, j+1]).
  std::array<double, 2> window(const v3& p) const {
    const v3 d = sub(p, eye);
    const double x = dot(d, s), y = dot(d, u), depth = dot(d, g);
    return {(f / aspect * x / depth + 1) * width / 2, (f * y / depth + 1) * height / 2};
  }
  double depth(const v3& p) const { return dot(sub(p, eye), g); }
};

}  // namespace

// ---------------------------------------------------------------------------------------
// The view volume and reference frame of an observed camera

TEST(TeachingViewVolume, CornersAndAxesProjectedIndependentlyAreTheDrawnLinesEnds) {
  const json doc = example_json("teaching_view_volume");
  const json& vv = doc["teaching"]["view_volume"];
  const int width = doc["viewport"]["width"], height = doc["viewport"]["height"];
  const test_camera scene_camera(doc["camera"], doc["projection"], width, height);
  // The observed camera's frustum, from its parameters (gluPerspective with the scene's aspect).
  const test_camera observed(vv["camera"], vv["projection"], width, height);
  const double near_d = vv["projection"]["near"], far_d = vv["projection"]["far"];
  const double tan_half = std::tan(vv["projection"]["fovy_deg"].get<double>() * M_PI / 360);
  std::vector<v3> corners;
  for (const double d : {near_d, far_d}) {
    const v3 centre = add(observed.eye, scale(d, observed.g));
    const double h = d * tan_half, w = h * observed.aspect;
    for (const auto& [a, b] :
         {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}})
      corners.push_back(add(centre, add(scale(a * w, observed.s), scale(b * h, observed.u))));
  }
  const view::rgb8 frame_color{static_cast<std::uint8_t>(vv["color"][0].get<int>()),
                               static_cast<std::uint8_t>(vv["color"][1].get<int>()),
                               static_cast<std::uint8_t>(vv["color"][2].get<int>())};
  const double axis = vv["axis_length"];
  // Expected ends: the 8 corners and the eye (the pyramid's tip) in the frame colour, the axes'
  // tips x (red), y (green), z = -gaze (blue).
  struct expected {
    v3 p;
    view::rgb8 color;
    const char* what;
  };
  std::vector<expected> ends;
  for (std::size_t k = 0; k < corners.size(); ++k)
    ends.push_back({corners[k], frame_color, k < 4 ? "near corner" : "far corner"});
  ends.push_back({observed.eye, frame_color, "centre of projection"});
  ends.push_back({add(observed.eye, scale(axis, observed.s)), {220, 40, 40}, "x axis tip"});
  ends.push_back({add(observed.eye, scale(axis, observed.u)), {30, 150, 30}, "y axis tip"});
  ends.push_back({add(observed.eye, scale(-axis, observed.g)), {40, 80, 230}, "z axis tip"});
  ends.push_back({observed.eye, {220, 40, 40}, "x axis origin"});

  const scene::scene s = scene::load_scene(example_path("teaching_view_volume"));
  EXPECT_EQ(s.teaching.view_volume_lines, 2u + 4u + 4u + 3u);
  const view::frame f = rendered(s);
  ASSERT_FALSE(f.lines.empty());
  for (const expected& e : ends) {
    const auto w = scene_camera.window(e.p);
    ASSERT_GT(scene_camera.depth(e.p), 1.0) << e.what << " must be in front of the scene camera";
    ASSERT_TRUE(w[0] > 0 && w[0] < width && w[1] > 0 && w[1] < height)
        << e.what << " must be inside the picture";
    double best = 1e300;
    for (const view::screen_line& l : f.lines) {
      if (l.color != e.color) continue;
      for (const view::window_point& q : {l.a, l.b})
        best = std::min(best, std::hypot(q.x - w[0], q.y - w[1]));
    }
    EXPECT_LT(best, 1e-6) << e.what << " at (" << w[0] << ", " << w[1]
                          << ") is no drawn line's end";
  }
}

TEST(TeachingViewVolume, IsDrawnInPngSvgAndPdf) {
  const std::string in = example_path("teaching_view_volume");
  std::ostringstream log;
  for (const char* ext : {"png", "svg", "pdf"}) {
    const std::string out = temp_dir() + "/view_volume." + ext;
    render_command({in, out, false}, log);
    ASSERT_TRUE(fs::exists(out)) << out;
  }
  const std::string svg = exbsp_test::read_file(temp_dir() + "/view_volume.svg");
  for (const char* colour : {"#282828", "#dc2828", "#1e961e", "#2850e6"})
    EXPECT_NE(svg.find(colour), std::string::npos) << colour << " (a view-volume line colour)";
  // Without the key: none of those lines.
  json doc = example_json("teaching_view_volume");
  doc.erase("teaching");
  const scene::scene plain = scene::parse_scene(doc, in);
  const scene::scene with = scene::load_scene(in);
  EXPECT_EQ(with.curves.size(), plain.curves.size() + with.teaching.view_volume_lines);
}

// ---------------------------------------------------------------------------------------
// The depth-sort painter

namespace {

/// Writes an OFF square of side 2 centred at (x, y, z), facing +z, and returns its path.
std::string write_square(const std::string& name, double x, double y, double z) {
  const std::string path = temp_dir() + "/" + name + ".off";
  std::ofstream(path) << "OFF\n4 1 0\n"
                      << x - 1 << " " << y - 1 << " " << z << "\n"
                      << x + 1 << " " << y - 1 << " " << z << "\n"
                      << x + 1 << " " << y + 1 << " " << z << "\n"
                      << x - 1 << " " << y + 1 << " " << z << "\n4 0 1 2 3\n";
  return path;
}

/// Three overlapping squares stacked at three heights, seen from straight above: no cycles,
/// and each square lies wholly behind the next in depth (the case a depth sort gets right; seen
/// obliquely, a farthest-corner sort can already misorder two such squares).
json stacked_squares() {
  return json{{"meshes",
               {{{"file", write_square("low", 0, 0, 0)}, {"color", {200, 60, 50}}},
                {{"file", write_square("mid", 0.8, 0.5, 0.5)}, {"color", {60, 150, 80}}},
                {{"file", write_square("high", 0.2, 1.1, 1.0)}, {"color", {60, 90, 210}}}}},
              {"camera", {{"eye", {0.3, 0.4, 8}}, {"look_at", {0.3, 0.4, 0}}, {"up", {0, 1, 0}}}},
              {"projection", {{"type", "perspective"}, {"fovy_deg", 40}, {"near", 1}, {"far", 50}}},
              {"viewport", {{"width", 160}, {"height", 120}}}};
}

}  // namespace

TEST(TeachingDepthSort, AgreesWithTheBspWhereNothingOverlapsCyclically) {
  json doc = stacked_squares();
  const view::image by_tree = rendered(scene::parse_scene(doc, temp_dir() + "/s.json")).picture;
  EXPECT_GE(exbsp_test::colours_of(by_tree).size(), 4u);
  for (const char* key : {"farthest", "centroid"}) {
    doc["teaching"] = {{"painter", "depth_sort"}, {"depth_key", key}};
    const scene::scene s = scene::parse_scene(doc, temp_dir() + "/s.json");
    ASSERT_NE(s.teaching.painter, view::visibility_order::bsp);
    const view::frame f = rendered(s);
    EXPECT_FALSE(f.tree) << "a depth sort builds no tree";
    EXPECT_TRUE(same_pixels(f.picture, by_tree)) << key;
  }
  // Orthographic too (depth along the direction of projection).
  doc["projection"] = {{"type", "orthographic"},
                       {"left", -3},
                       {"right", 3},
                       {"bottom", -2.25},
                       {"top", 2.25},
                       {"near", 1},
                       {"far", 50}};
  doc.erase("teaching");
  const view::image ortho_tree = rendered(scene::parse_scene(doc, temp_dir() + "/s.json")).picture;
  doc["teaching"] = {{"painter", "depth_sort"}};
  EXPECT_TRUE(
      same_pixels(rendered(scene::parse_scene(doc, temp_dir() + "/s.json")).picture, ortho_tree));
}

TEST(TeachingDepthSort, PaintsFarthestFirstAndGetsTheCyclicPlanksWrong) {
  const scene::scene s = scene::load_scene(example_path("teaching_cyclic"));
  ASSERT_EQ(s.teaching.painter, view::visibility_order::depth_sort_farthest);
  const view::frame f = rendered(s);
  // The order: farthest corners (eye-space depth, computed here) never increase.
  const json doc = example_json("teaching_cyclic");
  const test_camera cam(doc["camera"], doc["projection"], 300, 300);
  ASSERT_EQ(f.order.size(), f.fragments.size());
  double previous = 1e300;
  for (std::uint32_t idx : f.order) {
    double farthest = -1e300;
    for (const vec3d& p : f.fragments[idx].v) farthest = std::max(farthest, cam.depth(p));
    EXPECT_LE(farthest, previous + 1e-12);
    previous = farthest;
  }
  scene::scene by_tree = s;
  by_tree.teaching.painter = view::visibility_order::bsp;
  const view::frame g = rendered(by_tree);
  EXPECT_FALSE(same_pixels(f.picture, g.picture));
  // The BSP's picture is the z-buffer's (the test support's software oracle).
  view::frame z = scene::make_frame(by_tree);
  view::standard_pipeline({}, view::output_kind::png).run(z, nullptr);
  const view::image oracle = exbsp_test::zbuffer_render(z);
  std::size_t bsp_wrong = 0, sort_wrong = 0;
  for (int r = 0; r < oracle.height(); ++r)
    for (int k = 0; k < oracle.width(); ++k) {
      bsp_wrong += g.picture.at_row(r, k) != oracle.at_row(r, k);
      sort_wrong += f.picture.at_row(r, k) != oracle.at_row(r, k);
    }
  EXPECT_LT(bsp_wrong, 300u);  // rounding along the planks' crossings only
  EXPECT_GT(sort_wrong, 10 * bsp_wrong + 900);
}

// ---------------------------------------------------------------------------------------
// Dropping polygons at the near plane

namespace {

const view::rgb8 crossing_red{255, 0, 0}, other_grey{128, 128, 128};

/// build, order, transform+clip and raster of scenes/teaching_near.json with `rule`; every
/// fragment with a corner in front of the near plane (by this file's depths) painted red, the
/// others grey. `crossing` receives those fragments, `crossing_meshes` their meshes.
view::frame near_run(view::near_plane_rule rule, std::vector<bool>* crossing = nullptr,
                     std::vector<bool>* crossing_meshes = nullptr) {
  const json doc = example_json("teaching_near");
  scene::scene s = scene::load_scene(example_path("teaching_near"));
  const test_camera cam(doc["camera"], doc["projection"], doc["viewport"]["width"],
                        doc["viewport"]["height"]);
  const double near_d = doc["projection"]["near"];
  view::frame f = scene::make_frame(s);
  f.near_plane = rule;
  view::build_stage(f);
  view::order_stage(f);
  std::vector<bool> cross(f.fragments.size(), false), meshes(s.meshes.size(), false);
  f.fragment_colors.assign(f.fragments.size(), other_grey);
  for (std::size_t i = 0; i < f.fragments.size(); ++i)
    for (const vec3d& p : f.fragments[i].v) {
      const double d = cam.depth(p);
      EXPECT_GT(std::abs(d - near_d), 1e-9) << "a corner on the near plane: rounding decides";
      if (d < near_d) cross[i] = true;
    }
  for (std::size_t i = 0; i < f.fragments.size(); ++i)
    if (cross[i]) {
      f.fragment_colors[i] = crossing_red;
      meshes[f.mesh_of(f.fragments[i].face)] = true;
    }
  view::transform_clip_stage(f);
  view::raster_stage(f);
  if (crossing) *crossing = cross;
  if (crossing_meshes) *crossing_meshes = meshes;
  return f;
}

std::size_t count_colour(const view::image& img, view::rgb8 c) {
  std::size_t n = 0;
  for (int r = 0; r < img.height(); ++r)
    for (int k = 0; k < img.width(); ++k) n += img.at_row(r, k) == c;
  return n;
}

bool same_polygon(const view::screen_polygon& a, const view::screen_polygon& b) {
  if (a.fragment != b.fragment || a.v.size() != b.v.size()) return false;
  for (std::size_t k = 0; k < a.v.size(); ++k)
    if (a.v[k].x != b.v[k].x || a.v[k].y != b.v[k].y || a.v[k].z != b.v[k].z) return false;
  return true;
}

}  // namespace

TEST(TeachingNearPlane, DropLeavesOutExactlyThePolygonsWithACornerInFrontOfIt) {
  std::vector<bool> crossing, crossing_meshes;
  const view::frame cut = near_run(view::near_plane_rule::clip, &crossing, &crossing_meshes);
  const view::frame dropped = near_run(view::near_plane_rule::drop_polygon);
  // The scene is one where the near plane matters: crossing polygons are seen when cut.
  EXPECT_GT(count_colour(cut.picture, crossing_red), 2000u);
  EXPECT_EQ(count_colour(dropped.picture, crossing_red), 0u);
  EXPECT_GT(count_colour(dropped.picture, other_grey), 2000u);
  // The others are unchanged: the same polygons, bit for bit, in the same order.
  std::vector<const view::screen_polygon*> kept;
  for (const view::screen_polygon& p : cut.polygons)
    if (!crossing[p.fragment]) kept.push_back(&p);
  ASSERT_EQ(dropped.polygons.size(), kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k)
    EXPECT_TRUE(same_polygon(dropped.polygons[k], *kept[k])) << "polygon " << k;
  EXPECT_GT(dropped.near_dropped, 0u);
  EXPECT_EQ(cut.near_dropped, 0u);

  // drop_mesh: every polygon of a mesh that has a crossing corner goes, the others stay.
  const view::frame whole = near_run(view::near_plane_rule::drop_mesh);
  std::vector<const view::screen_polygon*> kept_meshes;
  for (const view::screen_polygon& p : cut.polygons)
    if (!crossing_meshes[cut.mesh_of(p.face)]) kept_meshes.push_back(&p);
  ASSERT_EQ(whole.polygons.size(), kept_meshes.size());
  ASSERT_LT(kept_meshes.size(), kept.size());
  for (std::size_t k = 0; k < kept_meshes.size(); ++k)
    EXPECT_TRUE(same_polygon(whole.polygons[k], *kept_meshes[k])) << "polygon " << k;
}

TEST(Teaching, DepthSortAndDropAreDrawnInSvgAndPdfToo) {
  // The vector drawing takes the same polygons: the teaching views change it as they change
  // the PNG (the browser test of test_vector.cpp draws these scenes' BSP pictures).
  std::ostringstream log;
  for (const char* name : {"teaching_cyclic", "teaching_near"}) {
    const scene::scene s = scene::load_scene(example_path(name));
    scene::scene plain = s;
    plain.teaching = {};
    for (const char* ext : {"svg", "pdf"}) {
      const std::string a = temp_dir() + "/" + name + "_teaching." + ext,
                        b = temp_dir() + "/" + name + "_plain." + ext;
      render_request with_key({}, a), without_key({}, b);
      with_key.preloaded = s;
      without_key.preloaded = plain;
      render_command(with_key, log);
      render_command(without_key, log);
      EXPECT_NE(exbsp_test::read_file(a), exbsp_test::read_file(b)) << name << " " << ext;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Opt-in, validation

TEST(Teaching, TheDefaultsChangeNothing) {
  json doc = stacked_squares();
  const view::image plain = rendered(scene::parse_scene(doc, temp_dir() + "/s.json")).picture;
  doc["teaching"] = {{"painter", "bsp"}, {"near_plane", "clip"}};
  const scene::scene s = scene::parse_scene(doc, temp_dir() + "/s.json");
  EXPECT_EQ(s.teaching.painter, view::visibility_order::bsp);
  EXPECT_EQ(s.teaching.near_plane, view::near_plane_rule::clip);
  EXPECT_TRUE(same_pixels(rendered(s).picture, plain));
  view::frame f;
  EXPECT_EQ(f.visibility, view::visibility_order::bsp);
  EXPECT_EQ(f.near_plane, view::near_plane_rule::clip);
}

TEST(Teaching, BadValuesAreSceneErrorsNamingTheKey) {
  const json camera = {{"eye", {2, -6, 3}}, {"look_at", {0, 0, 0}}, {"up", {0, 0, 1}}};
  const json projection = {{"type", "perspective"}, {"fovy_deg", 30}, {"near", 1}, {"far", 5}};
  const json volume = {{"camera", camera}, {"projection", projection}};
  const auto with = [&](const json& key, const json& value) {
    json v = volume;
    v[key.get<std::string>()] = value;
    return v;
  };
  json up_parallel = camera;
  up_parallel["up"] = {2, -6, 3};
  json bad_near = projection;
  bad_near["near"] = -1;
  const std::vector<std::pair<json, std::string>> cases = {
      {3, "/teaching"},
      {{{"painter", "zbuffer"}}, "/teaching/painter"},
      {{{"painter", 1}}, "/teaching/painter"},
      {{{"depth_key", "centroid"}}, "/teaching/depth_key"},
      {{{"painter", "depth_sort"}, {"depth_key", "nearest"}}, "/teaching/depth_key"},
      {{{"near_plane", "cut"}}, "/teaching/near_plane"},
      {{{"view_frustum", true}}, "/teaching/view_frustum"},
      {{{"view_volume", 1}}, "/teaching/view_volume"},
      {{{"view_volume", json::object()}}, "/teaching/view_volume/camera"},
      {{{"view_volume", {{"camera", camera}}}}, "/teaching/view_volume/projection"},
      {{{"view_volume", with("camera", up_parallel)}}, "/teaching/view_volume/camera/up"},
      {{{"view_volume", with("projection", bad_near)}}, "/teaching/view_volume/projection/near"},
      {{{"view_volume", with("axis_length", -1)}}, "/teaching/view_volume/axis_length"},
      {{{"view_volume", with("axes", "yes")}}, "/teaching/view_volume/axes"},
      {{{"view_volume", with("colour", {1, 2, 3})}}, "/teaching/view_volume/colour"},
      {{{"painter", "depth_sort"}, {"view_volume", volume}}, "/teaching/painter"},
  };
  for (const auto& [teaching, key] : cases) {
    json doc = stacked_squares();
    doc["teaching"] = teaching;
    std::string message;
    EXPECT_EQ(
        exbsp_test::error_key([&] { scene::parse_scene(doc, temp_dir() + "/s.json"); }, &message),
        key)
        << teaching.dump() << ": " << message;
  }
  // A depth sort cannot place lines (their depth rule needs the tree).
  json doc = stacked_squares();
  doc["lines"] = {{{"points", {{0, 0, 0}, {1, 1, 1}}}}};
  doc["teaching"] = {{"painter", "depth_sort"}};
  EXPECT_EQ(exbsp_test::error_key([&] { scene::parse_scene(doc, temp_dir() + "/s.json"); }),
            "/teaching/painter");
}

TEST(Teaching, TheCommandLineExitsTwoAndWritesNothingForABadKey) {
  json doc = stacked_squares();
  doc["teaching"] = {{"near_plane", "cut"}};
  const std::string in = temp_dir() + "/bad_teaching.json", out = temp_dir() + "/bad.png",
                    err = temp_dir() + "/bad.err";
  std::ofstream(in) << doc.dump();
  const std::string command =
      std::string("'") + EXBSP_CLI + "' render '" + in + "' -o '" + out + "' 2>'" + err + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(exbsp_test::read_file(err).find("/teaching/near_plane"), std::string::npos);
}
