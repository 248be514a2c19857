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
#include <exbsp/view/png_io.h>
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

// ---------------------------------------------------------------------------------------
// The scene drawn in the spaces of the PHIGS normalisation ("view_volume" "space"). The step
// matrices themselves are checked against the model's geometry in test_viewing.cpp
// (PhigsNormalisation); here: that meshes, lines and the volume are moved by them, and the cut
// before the projective step.

namespace {

json phigs_observer(bool perspective) {
  return {{"phigs",
           {{"vrp", {0.3, 0.4, 0}},
            {"vpn", {0, 0, 1}},
            {"vup", {0, 1, 0}},
            {"prp", {0.2, -0.1, 6}},
            {"window", {-2, 2.5, -2, 2.5}},
            {"front", 1.5},
            {"back", -1},
            {"projection", perspective ? "perspective" : "parallel"}}}};
}

/// The stacked squares seen from outside the normalised cube, drawn in `space`.
json in_space(const std::string& space, bool perspective = true) {
  json doc = stacked_squares();
  doc["camera"] = {{"eye", {3, -4, 3}}, {"look_at", {0, 0, 0}}, {"up", {0, 0, 1}}};
  doc["teaching"] = {
      {"view_volume",
       {{"camera", phigs_observer(perspective)}, {"space", space}, {"axis_length", 0.5}}}};
  return doc;
}

view::mat4 steps_up_to(bool perspective, const std::string& space) {
  const json o = phigs_observer(perspective)["phigs"];
  view::phigs_view p;
  p.vrp = {0.3, 0.4, 0};
  p.prp = {0.2, -0.1, 6};
  p.umin = p.vmin = -2;
  p.umax = p.vmax = 2.5;
  p.front = o["front"];
  p.back = o["back"];
  p.perspective = perspective;
  view::mat4 m = view::mat4::identity();
  for (const view::phigs_step& step : view::phigs_normalisation(p)) {
    m = step.m * m;
    if (step.space == space) break;
  }
  return m;
}

}  // namespace

TEST(TeachingSpace, MeshesAndLinesMoveByTheNormalisationAndTheVolumeBecomesTheCube) {
  for (const bool perspective : {true, false}) {
    SCOPED_TRACE(perspective ? "perspective" : "parallel");
    const json doc = in_space("normalised", perspective);
    const scene::scene s = scene::parse_scene(doc, temp_dir() + "/s.json");
    ASSERT_TRUE(s.teaching.space_matrix.has_value());
    EXPECT_EQ(s.teaching.space_keep.has_value(), perspective);
    const view::mat4 m = steps_up_to(perspective, "normalised");
    // Every vertex of the squares (all in front of the cut) is the step product's image.
    const scene::scene plain =
        scene::parse_scene(stacked_squares(), temp_dir() + "/s.json");  // same meshes, world
    const triangle_soup world = scene::load_geometry(plain).soup;
    const triangle_soup moved = scene::load_geometry(s).soup;
    ASSERT_EQ(moved.vertices.size(), world.vertices.size());
    ASSERT_EQ(moved.triangles.size(), world.triangles.size());
    for (std::size_t k = 0; k < world.vertices.size(); ++k) {
      const view::point3 q = view::transform_point(
          m, {world.vertices[k][0], world.vertices[k][1], world.vertices[k][2]});
      EXPECT_NEAR(moved.vertices[k][0], q.x, 1e-12);
      EXPECT_NEAR(moved.vertices[k][1], q.y, 1e-12);
      EXPECT_NEAR(moved.vertices[k][2], q.z, 1e-12);
    }
    // The view volume's lines end at the cube's corners, seen by the scene's camera; a
    // perspective volume has no tip left (its centre of projection went to infinity).
    const test_camera scene_camera(doc["camera"], doc["projection"], 160, 120);
    const view::frame f = rendered(s);
    std::size_t volume_ends = 0;
    for (const double x : {-1.0, 1.0})
      for (const double y : {-1.0, 1.0})
        for (const double z : {-1.0, 1.0}) {
          const auto w = scene_camera.window({x, y, z});
          double best = 1e300;
          for (const view::screen_line& l : f.lines)
            if (l.color == view::rgb8{60, 60, 60})
              for (const view::window_point& q : {l.a, l.b})
                best = std::min(best, std::hypot(q.x - w[0], q.y - w[1]));
          EXPECT_LT(best, 1e-6) << "corner (" << x << ", " << y << ", " << z << ")";
          ++volume_ends;
        }
    EXPECT_EQ(volume_ends, 8u);
    // 2 rectangles + 4 side edges, no tip edges, and two frames (VRC, world) of 3 axes.
    EXPECT_EQ(s.teaching.view_volume_lines, 2u + 4u + 3u + 3u);
  }
}

TEST(TeachingSpace, AffineSpacesMoveCurvesByTheirControlPoints) {
  json doc = in_space("sheared");
  doc["curves"] = {{{"bezier", {{0, 0, 0}, {1, 2, 0.5}, {2, 0, 1}}}, {"color", {10, 20, 30}}}};
  doc["lines"] = {{{"points", {{0, 0, 0}, {1, 1, 1}}}}};
  const scene::scene s = scene::parse_scene(doc, temp_dir() + "/s.json");
  const view::mat4 m = steps_up_to(true, "sheared");
  ASSERT_GE(s.curves.size(), 2u);
  const std::vector<std::array<double, 3>> bezier = {{0, 0, 0}, {1, 2, 0.5}, {2, 0, 1}};
  ASSERT_EQ(s.curves[0].control_points.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const view::point3 q = view::transform_point(m, {bezier[k][0], bezier[k][1], bezier[k][2]});
    EXPECT_NEAR(s.curves[0].control_points[k][0], q.x, 1e-12);
    EXPECT_NEAR(s.curves[0].control_points[k][1], q.y, 1e-12);
    EXPECT_NEAR(s.curves[0].control_points[k][2], q.z, 1e-12);
  }
  const view::point3 end = view::transform_point(m, {1, 1, 1});
  EXPECT_NEAR(s.curves[1].control_points[1][2], end.z, 1e-12);
  EXPECT_EQ(s.line_count, s.curves.size() - 1);
}

TEST(TeachingSpace, TheProjectiveStepCutsWhatWouldWrapThroughInfinity) {
  // A quad from n = -1 to n = 9 crosses PRP's plane (n = 6): kept up to the plane halfway
  // between PRP and the front plane (n = 3.75), whose image is z = -1 + 2 (1/2.25 - 1/7) /
  // (1/4.5 - 1/7).
  const std::string quad = temp_dir() + "/long_quad.off";
  std::ofstream(quad) << "OFF\n4 1 0\n-1 -1 -1\n1 -1 -1\n1 1 9\n-1 1 9\n4 0 1 2 3\n";
  json doc = in_space("normalised");
  doc["meshes"] = {{{"file", quad}}};
  doc["lines"] = {{{"points", {{0, 0, -1}, {0, 0, 9}}}}};
  const scene::scene s = scene::parse_scene(doc, temp_dir() + "/s.json");
  const triangle_soup moved = scene::load_geometry(s).soup;
  const double z_cut = -1 + 2 * (1 / 2.25 - 1 / 7.0) / (1 / 4.5 - 1 / 7.0);
  ASSERT_GT(moved.triangles.size(), 0u);
  double highest = -1e300;
  for (const auto& p : moved.vertices) {
    ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    highest = std::max(highest, p[2]);
  }
  EXPECT_NEAR(highest, z_cut, 1e-9);
  // The line is cut there too: one run, ending at the cut's image.
  ASSERT_EQ(s.line_count, 1u + s.teaching.view_volume_lines);
  const std::vector<vec3d>& line = s.curves[s.curves.size() - s.line_count].control_points;
  ASSERT_EQ(line.size(), 2u);
  EXPECT_NEAR(std::max(line[0][2], line[1][2]), z_cut, 1e-9);
  // And it renders.
  EXPECT_FALSE(rendered(s).polygons.empty());
}

TEST(TeachingSpace, WorldIsTheDefaultAndBadSpacesNameTheKey) {
  json doc = stacked_squares();
  doc["teaching"] = {{"view_volume", {{"camera", phigs_observer(true)}}}};
  const view::image plain = rendered(scene::parse_scene(doc, temp_dir() + "/s.json")).picture;
  doc["teaching"]["view_volume"]["space"] = "world";
  const scene::scene world = scene::parse_scene(doc, temp_dir() + "/s.json");
  EXPECT_FALSE(world.teaching.space_matrix.has_value());
  EXPECT_TRUE(same_pixels(rendered(world).picture, plain));

  const json look_at = {{"eye", {2, -6, 3}}, {"look_at", {0, 0, 0}}, {"up", {0, 0, 1}}};
  const json lens = {{"type", "perspective"}, {"fovy_deg", 30}, {"near", 1}, {"far", 5}};
  const std::string key = "/teaching/view_volume/space";
  const auto error_of = [&](json d) {
    std::string message;
    const std::string k =
        exbsp_test::error_key([&] { scene::parse_scene(d, temp_dir() + "/s.json"); }, &message);
    const std::size_t at = message.find(k + ": ");
    return k + " | " + (at == std::string::npos ? message : message.substr(at + k.size() + 2));
  };
  json d = in_space("normalised");
  d["teaching"]["view_volume"]["space"] = "ndc";
  EXPECT_EQ(error_of(d).rfind(key, 0), 0u) << error_of(d);
  d["teaching"]["view_volume"]["space"] = 3;
  EXPECT_EQ(error_of(d).rfind(key, 0), 0u) << error_of(d);
  d = in_space("sheared");
  d["teaching"]["view_volume"]["camera"] = look_at;
  d["teaching"]["view_volume"]["projection"] = lens;
  EXPECT_NE(error_of(d).find(key + " | the normalisation steps are those of the PHIGS"),
            std::string::npos)
      << error_of(d);
  d = in_space("opening_45", false);
  EXPECT_NE(error_of(d).find("no 45 degree opening"), std::string::npos) << error_of(d);
  d = in_space("normalised");
  d["curves"] = {{{"bezier", {{0, 0, 0}, {1, 2, 0.5}, {2, 0, 1}}}}};
  EXPECT_NE(error_of(d).find(key + " | the perspective normalised space is a projective"),
            std::string::npos)
      << error_of(d);
  // A textured mesh: its coordinates would not interpolate linearly after a projective map.
  const std::string obj = temp_dir() + "/textured.obj", png = temp_dir() + "/texture.png";
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
  view::write_png(view::image(2, 2, {200, 30, 30}), png);
  d = in_space("normalised");
  d["meshes"] = {{{"file", obj}, {"texture", {{"png", png}}}}};
  EXPECT_NE(error_of(d).find(key + " | the perspective normalised space is a projective map, "
                                   "under which a texture"),
            std::string::npos)
      << error_of(d);
  d["teaching"]["view_volume"]["space"] = "opening_45";
  EXPECT_NO_THROW(scene::parse_scene(d, temp_dir() + "/s.json"));
  // A Bezier curve in the parallel normalised space (affine) is fine.
  d = in_space("normalised", false);
  d["curves"] = {{{"bezier", {{0, 0, 0}, {1, 2, 0.5}, {2, 0, 1}}}}};
  EXPECT_NO_THROW(scene::parse_scene(d, temp_dir() + "/s.json"));
}
