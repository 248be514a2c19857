// SPDX-License-Identifier: LGPL-3.0-or-later
// Modelling and viewing from scene files (docs/contract.md "Scenes", issue 12): "transforms" lists
// and nested "groups" on the matrix stack, the camera forms (position/look/up, polar, pilot, PHIGS)
// checked against GLM and against the formulas' defining properties, viewport x/y inside an
// image, aspect stretch/fit, glOrtho with a negative near, ortho2d, "lines" with both clippers,
// the bounding-box mesh reject, and the virtual trackball. Bad input: exit 2, key named,
// nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include <exbsp/clip/homogeneous_segment.h>
#include <exbsp/core/errors.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/phigs.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/trackball.h>
#include <exbsp/view/transforms.h>
#include "scene/matrices_command.h"
#include "scene/render.h"
#include "scene/scene.h"
#include "view/effects.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp;
using nlohmann::json;
using view::mat4;
namespace fs = std::filesystem;
constexpr double pi = 3.14159265358979323846;

mat4 from_glm(const glm::dmat4& g) { return exbsp_test::from_column_major(g); }
using exbsp_test::relative_difference;
glm::dvec3 g3(double x, double y, double z) { return glm::dvec3(x, y, z); }
glm::dmat4 grot(double deg, double x, double y, double z) {
  return glm::rotate(glm::dmat4(1.0), deg * pi / 180, g3(x, y, z));
}
glm::dmat4 gtr(double x, double y, double z) {
  return glm::translate(glm::dmat4(1.0), g3(x, y, z));
}

std::string dir() {
  static const std::string d = [] {
    const std::string tmpl = exbsp_test::make_temp_dir("test_viewing").string();
    fs::create_directories(tmpl + "/meshes");
    std::ofstream(tmpl + "/meshes/tri.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    std::ofstream(tmpl + "/meshes/quad.off")
        << "OFF\n4 1 0\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n4 0 1 2 3\n";
    return tmpl;
  }();
  return d;
}

json base_scene() {
  return json::parse(R"({
    "meshes": [{"file": "meshes/tri.off"}],
    "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0]},
    "projection": {"type": "perspective", "fovy_deg": 40, "near": 1, "far": 100},
    "viewport": {"width": 64, "height": 48}
  })");
}

scene::scene parse(const json& doc) { return scene::parse_scene(doc, dir() + "/scene.json"); }

std::string error_key(const json& doc) {
  return exbsp_test::error_key([&] { parse(doc); });
}

// --- transforms and groups ---------------------------------------------------------------------

TEST(Transforms, ListPostMultipliesLikeOpenGL) {
  json d = base_scene();
  d["meshes"][0]["transforms"] = json::parse(
      R"([{"translate": [1, 2, 3]}, {"rotate": [30, 1, 1, 0]}, {"scale": [2, 3, 4]},
          {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1], "order": "column-major"},
          {"matrix": [1,0,0,-1, 0,1,0,0, 0,0,1,0, 0,0,0,1], "order": "row-major"}])");
  const scene::scene s = parse(d);
  const glm::dmat4 g = gtr(1, 2, 3) * grot(30, 1, 1, 0) * glm::scale(glm::dmat4(1.0), g3(2, 3, 4)) *
                       gtr(5, 6, 7) * gtr(-1, 0, 0);
  EXPECT_LT(relative_difference(s.meshes[0].transform, from_glm(g)), 1e-14);
}

TEST(Transforms, OldSixteenNumberTransformStaysValid) {
  json d = base_scene();
  d["meshes"][0]["transform"] = {1, 0, 0, 4, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(parse(d).meshes[0].transform.m, view::translate({4, 0, 0}).m);
}

TEST(Groups, NestLikePushAndPopMatrix) {
  json d = base_scene();
  d["groups"] = json::parse(R"([
    {"transforms": [{"translate": [10, 0, 0]}],
     "meshes": [{"file": "meshes/tri.off"}],
     "groups": [{"transforms": [{"rotate": [90, 0, 0, 1]}], "meshes": [{"file": "meshes/tri.off",
                 "transforms": [{"scale": [2, 2, 2]}]}]},
                {"meshes": [{"file": "meshes/tri.off"}]}]},
    {"meshes": [{"file": "meshes/tri.off"}]}])");
  const scene::scene s = parse(d);
  ASSERT_EQ(s.meshes.size(), 5u);
  EXPECT_EQ(s.meshes[0].key, "/meshes/0");
  EXPECT_EQ(s.meshes[1].key, "/groups/0/meshes/0");
  EXPECT_EQ(s.meshes[2].key, "/groups/0/groups/0/meshes/0");
  EXPECT_EQ(s.meshes[3].key, "/groups/0/groups/1/meshes/0");
  EXPECT_EQ(s.meshes[4].key, "/groups/1/meshes/0");
  EXPECT_EQ(s.meshes[0].transform.m, mat4::identity().m);
  EXPECT_EQ(s.meshes[1].transform.m, view::translate({10, 0, 0}).m);
  const mat4 nested =
      view::translate({10, 0, 0}) * view::rotate(90, {0, 0, 1}) * view::scale(2, 2, 2);
  EXPECT_LT(relative_difference(s.meshes[2].transform, nested), 1e-15);
  EXPECT_EQ(s.meshes[3].transform.m,
            view::translate({10, 0, 0}).m);                // the sibling's rotation was popped
  EXPECT_EQ(s.meshes[4].transform.m, mat4::identity().m);  // and the first group's translation
  const scene::scene_geometry g = scene::load_geometry(s);
  EXPECT_EQ(g.face_offsets, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  // Vertex 1 of the nested mesh, (1, 0, 0), scaled by 2, turned by 90 degrees, moved by 10: (10, 2,
  // 0).
  EXPECT_NEAR(g.soup.vertices[7][0], 10, 1e-15);
  EXPECT_NEAR(g.soup.vertices[7][1], 2, 1e-15);
}

TEST(Groups, OnlyGroupsIsAValidScene) {
  json d = base_scene();
  d.erase("meshes");
  d["groups"] = json::parse(R"([{"meshes": [{"file": "meshes/tri.off"}]}])");
  EXPECT_EQ(parse(d).meshes.size(), 1u);
  d.erase("groups");
  EXPECT_EQ(error_key(d), "/meshes");
}

TEST(Groups, NestingIsBoundedWithoutRecursion) {
  auto nested = [](std::size_t depth) {
    json d = base_scene();
    json g = json::parse(R"({"meshes": [{"file": "meshes/tri.off"}]})");
    for (std::size_t k = 1; k < depth; ++k) g = json{{"groups", json::array({g})}};
    d["groups"] = json::array({g});
    return d;
  };
  EXPECT_EQ(parse(nested(scene::max_group_depth)).meshes.size(), 2u);
  const std::string key = error_key(nested(scene::max_group_depth + 1));
  std::string expected;
  for (std::size_t k = 0; k <= scene::max_group_depth; ++k)
    expected += (k ? "/groups/0" : "/groups/0");
  EXPECT_EQ(key, expected);
  // Far deeper documents fail at the same bound (the parser never recurses per level). 400, not
  // thousands: this test builds its document with nlohmann's recursive copies, which would
  // overflow the stack under AddressSanitizer (the scene parser itself is iterative).
  EXPECT_EQ(error_key(nested(400)).size(), expected.size());
}

TEST(Transforms, BadInputNamesTheKey) {
  struct bad {
    const char* json_text;
    const char* key;
  };
  const bad cases[] = {
      {R"({"transforms": 5})", "/meshes/0/transforms"},
      {R"({"transforms": [{"spin": [1, 2, 3]}]})", "/meshes/0/transforms/0"},
      {R"({"transforms": [{"translate": [1, 2, 3], "scale": [1, 1, 1]}]})",
       "/meshes/0/transforms/0"},
      {R"({"transforms": [{"translate": [1, 2]}]})", "/meshes/0/transforms/0/translate"},
      {R"({"transforms": [{"rotate": [30, 0, 0, 0]}]})", "/meshes/0/transforms/0/rotate"},
      {R"({"transforms": [{"rotate": [30, 0, "z", 1]}]})", "/meshes/0/transforms/0/rotate/2"},
      {R"({"transforms": [{"scale": [1, 1, 1]}, {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})",
       "/meshes/0/transforms/1/order"},
      {R"({"transforms": [{"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "order": "gl"}]})",
       "/meshes/0/transforms/0/order"},
      {R"({"transforms": [{"matrix": [1, 2, 3]], "order": "row-major"}]})", ""},
      {R"({"transforms": [{"translate": [1, 2, 3], "order": "row-major"}]})",
       "/meshes/0/transforms/0/order"},
      {R"({"transform": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "transforms": []})",
       "/meshes/0/transforms"},
  };
  for (const bad& c : cases) {
    json d = base_scene();
    json extra;
    try {
      extra = json::parse(c.json_text);
    } catch (const json::exception&) {
      continue;  // (the malformed matrix case above is not JSON: skip it)
    }
    d["meshes"][0].update(extra);
    EXPECT_EQ(error_key(d), c.key) << c.json_text;
  }
  json d = base_scene();
  d["groups"] = json::parse(R"([{"transforms": [{"scale": "big"}]}])");
  EXPECT_EQ(error_key(d), "/groups/0/transforms/0/scale");
  d["groups"] = json::parse(R"([{"groups": 3}])");
  EXPECT_EQ(error_key(d), "/groups/0/groups");
  d["groups"] = json::parse(R"([7])");
  EXPECT_EQ(error_key(d), "/groups/0");
}

TEST(Transforms, ASingularTransformNamesItsKey) {
  json d = base_scene();
  d["groups"] = json::parse(R"([{"meshes": [{"file": "meshes/tri.off",
      "transforms": [{"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,0], "order": "row-major"}]}]}])");
  const scene::scene s = parse(d);
  try {
    scene::load_geometry(s);
    FAIL();
  } catch (const scene_error& e) {
    EXPECT_EQ(e.key(), "/groups/0/meshes/0/transforms");
  }
}

// --- cameras ---------------------------------------------------------------------------------

TEST(Cameras, PositionLookUpIsGluLookAtAlongTheLookDirection) {
  json d = base_scene();
  d["camera"] = json::parse(R"({"position": [1, -4, 3], "look": [-0.5, 2, -1], "up": [0, 0, 1]})");
  const scene::scene s = parse(d);
  EXPECT_EQ(s.form, scene::camera_form::look);
  const glm::dmat4 g = glm::lookAt(g3(1, -4, 3), g3(0.5, -2, 2), g3(0, 0, 1));
  EXPECT_LT(relative_difference(scene::make_view_setup(s).model_view, from_glm(g)), 1e-14);
  d["camera"]["up"] = {1, -4, 2};  // parallel to look
  EXPECT_EQ(error_key(d), "/camera/up");
  d["camera"]["up"] = {0, 0, 1};
  d["camera"]["look"] = {0, 0, 0};
  EXPECT_EQ(error_key(d), "/camera/look");
}

TEST(Cameras, PolarViewAsDesignWritesIt) {
  json d = base_scene();
  d["camera"] = json::parse(
      R"({"polar": {"distance": 7, "twist_deg": 10, "elevation_deg": -65, "azimuth_deg": 30, "look_at": [1, 2, 0.5]}})");
  const scene::scene s = parse(d);
  const glm::dmat4 g = gtr(0, 0, -7) * grot(-10, 0, 0, 1) * grot(-65, 1, 0, 0) * grot(30, 0, 0, 1) *
                       gtr(-1, -2, -0.5);
  const mat4 mv = scene::make_view_setup(s).model_view;
  EXPECT_LT(relative_difference(mv, from_glm(g)), 1e-14);
  // The equivalent gluLookAt camera (it orders the BSP): at distance 7 from look_at, same matrix.
  EXPECT_NEAR(view::length(s.camera.eye - view::point3{1, 2, 0.5}), 7, 1e-12);
  EXPECT_LT(relative_difference(view::look_at(s.camera), mv), 1e-12);
  d["camera"]["polar"].erase("look_at");  // defaults to the origin
  EXPECT_LT(relative_difference(scene::make_view_setup(parse(d)).model_view,
                                from_glm(gtr(0, 0, -7) * grot(-10, 0, 0, 1) * grot(-65, 1, 0, 0) *
                                         grot(30, 0, 0, 1))),
            1e-14);
  d["camera"]["polar"]["distance"] = 0;
  EXPECT_EQ(error_key(d), "/camera/polar/distance");
  d["camera"]["polar"]["distance"] = 7;
  d["camera"]["polar"].erase("twist_deg");
  EXPECT_EQ(error_key(d), "/camera/polar/twist_deg");
}

TEST(Cameras, PilotViewAsDesignWritesIt) {
  json d = base_scene();
  d["camera"] = json::parse(
      R"({"pilot": {"position": [-3, -4, 2], "roll_deg": 5, "pitch_deg": -80, "heading_deg": 40}})");
  const scene::scene s = parse(d);
  const glm::dmat4 g = grot(5, 0, 1, 0) * grot(-80, 1, 0, 0) * grot(40, 0, 0, 1) * gtr(3, 4, -2);
  EXPECT_LT(relative_difference(scene::make_view_setup(s).model_view, from_glm(g)), 1e-14);
  EXPECT_NEAR(view::length(s.camera.eye - view::point3{-3, -4, 2}), 0, 1e-12);
  d["camera"]["pilot"]["position"] = {1, 2};
  EXPECT_EQ(error_key(d), "/camera/pilot/position");
}

TEST(Cameras, OneFormOnly) {
  json d = base_scene();
  d["camera"]["polar"] = {{"distance", 1}};
  EXPECT_EQ(error_key(d), "/camera/polar");
  d = base_scene();
  d["camera"].erase("eye");
  EXPECT_EQ(error_key(d), "/camera/eye");
}

view::phigs_view sample_phigs(bool perspective) {
  view::phigs_view p;
  p.vrp = {1, 2, 0.5};
  p.vpn = {0.3, -1, 0.8};
  p.vup = {0, 0, 1};
  p.prp = {1.5, -0.5, 9};
  p.umin = -3;
  p.umax = 4;
  p.vmin = -2;
  p.vmax = 2.5;
  p.front = 2;
  p.back = -6;
  p.perspective = perspective;
  return p;
}

/// NDC of a VRC point (u, v, n) through the whole PHIGS transform.
view::point3 ndc_of_vrc(const view::phigs_matrices& m, const view::camera_basis& b,
                        const view::point3& vrp, double u, double v, double n) {
  const view::point3 world = vrp + (u * b.u + v * b.v + n * b.w);
  return view::transform_point(m.projection * m.model_view, world);
}

TEST(Phigs, OrientationIsGluLookAtAndMappingIsAnOffAxisFrustum) {
  const view::phigs_view p = sample_phigs(true);
  const view::phigs_matrices m = view::phigs_view_matrices(p);
  const glm::dmat4 orient = glm::lookAt(g3(1, 2, 0.5), g3(1 - 0.3, 2 + 1, 0.5 - 0.8), g3(0, 0, 1));
  EXPECT_LT(relative_difference(m.orientation, from_glm(orient)), 1e-14);
  const double near_d = 9 - 2, far_d = 9 + 6, k = near_d / 9;
  const glm::dmat4 map =
      glm::frustum((-3 - 1.5) * k, (4 - 1.5) * k, (-2 + 0.5) * k, (2.5 + 0.5) * k, near_d, far_d) *
      gtr(-1.5, 0.5, -9);
  EXPECT_LT(relative_difference(m.mapping, from_glm(map)), 1e-14);
  EXPECT_LT(relative_difference(m.projection * m.model_view, m.mapping * m.orientation), 1e-14);
  // Defining properties: the window's corners on the view plane go to the NDC square's
  // corners; the front plane to z = -1, the back plane to z = +1; PRP is the eye.
  const double corners[4][2] = {{-3, -2}, {4, -2}, {4, 2.5}, {-3, 2.5}};
  for (const auto& c : corners) {
    const view::point3 q = ndc_of_vrc(m, m.basis, p.vrp, c[0], c[1], 0);
    EXPECT_NEAR(std::fabs(q.x), 1, 1e-12);
    EXPECT_NEAR(std::fabs(q.y), 1, 1e-12);
  }
  EXPECT_NEAR(ndc_of_vrc(m, m.basis, p.vrp, 0, 0, 2).z, -1, 1e-12);
  EXPECT_NEAR(ndc_of_vrc(m, m.basis, p.vrp, 0.3, 0.1, -6).z, 1, 1e-12);
  const view::point3 eye = p.vrp + (1.5 * m.basis.u + -0.5 * m.basis.v + 9 * m.basis.w);
  EXPECT_NEAR(view::length(m.eye - eye), 0, 1e-12);
}

TEST(Phigs, ParallelWithOffCentrePrpIsOblique) {
  view::phigs_view p = sample_phigs(false);
  const view::phigs_matrices m = view::phigs_view_matrices(p);
  EXPECT_TRUE(m.oblique);
  // Points along the direction of projection land on the same NDC x, y.
  const view::vector3 dop_vrc{(p.umin + p.umax) / 2 - p.prp.x, (p.vmin + p.vmax) / 2 - p.prp.y,
                              -p.prp.z};
  const view::point3 a = ndc_of_vrc(m, m.basis, p.vrp, 0.5, 0.25, 0);
  const view::point3 b =
      ndc_of_vrc(m, m.basis, p.vrp, 0.5 + 0.3 * dop_vrc.x, 0.25 + 0.3 * dop_vrc.y, 0.3 * dop_vrc.z);
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(ndc_of_vrc(m, m.basis, p.vrp, -3, -2, 0).x, -1, 1e-12);
  EXPECT_NEAR(ndc_of_vrc(m, m.basis, p.vrp, 4, 2.5, 0).y, 1, 1e-12);
  EXPECT_NEAR(ndc_of_vrc(m, m.basis, p.vrp, 0, 0, 2).z, -1, 1e-12);
  EXPECT_NEAR(ndc_of_vrc(m, m.basis, p.vrp, 0, 0, -6).z, 1, 1e-12);
  // A PRP over the window's centre: plain glOrtho.
  p.prp = {0.5, 0.25, 3};
  const view::phigs_matrices o = view::phigs_view_matrices(p);
  EXPECT_FALSE(o.oblique);
  EXPECT_LT(relative_difference(o.mapping, from_glm(glm::ortho(-3.0, 4.0, -2.0, 2.5, -2.0, 6.0))),
            1e-14);
}

/// The course's normalised coordinates of a VRC point (u, v, n), from the PHIGS model's own
/// geometry rather than the step matrices: project it onto the view plane (through PRP, or
/// along DOP = CW - PRP), place the projection in the window ([-1, 1] across it), and map its
/// depth so that the front plane is +1 and the back plane -1 (linear in n for a parallel
/// view, in 1 / (pn - n), the distance to the centre of projection, for a perspective one).
std::array<double, 3> normalised_of_vrc(const view::phigs_view& p, double u, double v, double n) {
  const double pu = p.prp.x, pv = p.prp.y, pn = p.prp.z;
  const double cu = (p.umin + p.umax) / 2, cv = (p.vmin + p.vmax) / 2;
  double uu, vv, z;
  if (p.perspective) {
    const double t = pn / (pn - n);  // from PRP towards the point, to the plane n = 0
    uu = pu + t * (u - pu);
    vv = pv + t * (v - pv);
    const double a = 1 / (pn - p.front), b = 1 / (pn - p.back);  // z linear in 1 / (pn - n)
    z = -1 + 2 * (1 / (pn - n) - b) / (a - b);
  } else {
    const double t = n / pn;  // along DOP = (cu - pu, cv - pv, -pn) to the plane n = 0
    uu = u + t * (cu - pu);
    vv = v + t * (cv - pv);
    z = -1 + 2 * (n - p.back) / (p.front - p.back);
  }
  return {2 * (uu - cu) / (p.umax - p.umin), 2 * (vv - cv) / (p.vmax - p.vmin), z};
}

TEST(PhigsNormalisation, EachStepHasTheNotesPropertyAndTheWholeIsTheViewMapping) {
  for (const bool perspective : {true, false}) {
    SCOPED_TRACE(perspective ? "perspective" : "parallel");
    const view::phigs_view p = sample_phigs(perspective);
    const std::vector<view::phigs_step> steps = view::phigs_normalisation(p);
    std::vector<std::string> names, spaces;
    for (const view::phigs_step& s : steps) {
      names.push_back(s.name);
      if (!s.space.empty()) spaces.push_back(s.space);
    }
    const std::vector<std::string> perspective_names = {"T(-VRP)", "R",    "T(-PRP)", "SHper",
                                                        "Sper",    "Sfar", "Mpp"};
    const std::vector<std::string> parallel_names = {"T(-VRP)", "R",    "T(-PRP)",
                                                     "SHpar",   "Tpar", "Spar"};
    const std::vector<std::string> perspective_spaces = {"vrc", "sheared", "opening_45",
                                                         "normalised"};
    const std::vector<std::string> parallel_spaces = {"vrc", "sheared", "normalised"};
    EXPECT_EQ(names, perspective ? perspective_names : parallel_names);
    EXPECT_EQ(spaces, perspective ? perspective_spaces : parallel_spaces);
    // The product up to each named space, and points given in VRC.
    const auto up_to = [&](const std::string& space) {
      mat4 m = mat4::identity();
      for (const view::phigs_step& s : steps) {
        m = s.m * m;
        if (s.space == space) return m;
      }
      ADD_FAILURE() << "no space " << space;
      return m;
    };
    // VRC axes from VPN and VUP, the notes' formulas: n = VPN / |VPN|, u = VUP x n / |..|.
    const auto unit3 = [](view::vector3 a) { return (1 / view::length(a)) * a; };
    const view::vector3 n_hat = unit3(p.vpn), u_hat = unit3(view::cross(p.vup, n_hat));
    const view::vector3 v_hat = view::cross(n_hat, u_hat);
    const auto world = [&](double u, double v, double n) {
      return p.vrp + (u * u_hat + v * v_hat + n * n_hat);
    };
    const auto in = [&](const std::string& space, double u, double v, double n) {
      return view::transform_point(up_to(space), world(u, v, n));
    };
    const auto expect_at = [](const view::point3& q, double x, double y, double z,
                              const char* what) {
      EXPECT_NEAR(q.x, x, 1e-12) << what;
      EXPECT_NEAR(q.y, y, 1e-12) << what;
      EXPECT_NEAR(q.z, z, 1e-12) << what;
    };
    // VRC: the point (u, v, n) has coordinates (u, v, n).
    expect_at(in("vrc", 0.7, -1.2, 2.5), 0.7, -1.2, 2.5, "VRC point");
    // Sheared: PRP at the origin, the window's centre on the -z axis at depth pn.
    const double pn = p.prp.z, cu = (p.umin + p.umax) / 2, cv = (p.vmin + p.vmax) / 2;
    expect_at(in("sheared", p.prp.x, p.prp.y, p.prp.z), 0, 0, 0, "PRP");
    expect_at(in("sheared", cu, cv, 0), 0, 0, -pn, "window centre");
    if (perspective) {
      // 45 degrees: the window's corners on x = +-z, y = +-z.
      for (const double u : {p.umin, p.umax})
        for (const double v : {p.vmin, p.vmax}) {
          const view::point3 q = in("opening_45", u, v, 0);
          EXPECT_NEAR(std::fabs(q.x), -q.z, 1e-12);
          EXPECT_NEAR(std::fabs(q.y), -q.z, 1e-12);
        }
    }
    // Normalised: the view volume's corners at (+-1, +-1, +-1), and every point where the
    // model's own geometry puts it.
    const double dop_u = cu - p.prp.x, dop_v = cv - p.prp.y;
    for (const double plane : {p.front, p.back})
      for (const double u : {p.umin, p.umax})
        for (const double v : {p.vmin, p.vmax}) {
          // The corner on that plane: on the projector through the window's corner.
          const double t = perspective ? (pn - plane) / pn : -plane / pn;
          const double cu_ = perspective ? p.prp.x + t * (u - p.prp.x) : u + t * dop_u;
          const double cv_ = perspective ? p.prp.y + t * (v - p.prp.y) : v + t * dop_v;
          const view::point3 q = in("normalised", cu_, cv_, plane);
          expect_at(q, u == p.umin ? -1 : 1, v == p.vmin ? -1 : 1, plane == p.front ? 1 : -1,
                    "view volume corner");
        }
    const view::phigs_matrices pm = view::phigs_view_matrices(p);
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> coord(-5, 5), depth(p.back - 3, p.front + 0.5);
    for (int i = 0; i < 200; ++i) {
      const double u = coord(rng), v = coord(rng), n = depth(rng);
      const view::point3 q = in("normalised", u, v, n);
      const std::array<double, 3> e = normalised_of_vrc(p, u, v, n);
      EXPECT_NEAR(q.x, e[0], 1e-9 * (1 + std::fabs(e[0])));
      EXPECT_NEAR(q.y, e[1], 1e-9 * (1 + std::fabs(e[1])));
      EXPECT_NEAR(q.z, e[2], 1e-9 * (1 + std::fabs(e[2])));
      // The pipeline's OpenGL NDC: the same x and y, z turned round.
      const view::point3 gl = view::transform_point(pm.mapping * pm.orientation, world(u, v, n));
      EXPECT_NEAR(gl.x, q.x, 1e-9 * (1 + std::fabs(q.x)));
      EXPECT_NEAR(gl.y, q.y, 1e-9 * (1 + std::fabs(q.y)));
      EXPECT_NEAR(gl.z, -q.z, 1e-9 * (1 + std::fabs(q.z)));
    }
  }
  view::phigs_view flat = sample_phigs(true);
  flat.front = -1;
  flat.prp.z = 0;
  EXPECT_THROW(view::phigs_normalisation(flat), usage_error);
}

TEST(PhigsNormalisation, TheMatricesCommandPrintsEveryStep) {
  json d = base_scene();
  d.erase("projection");
  d["camera"] = json::parse(
      R"({"phigs": {"vrp": [1, 2, 0.5], "vpn": [0.3, -1, 0.8], "vup": [0, 0, 1],
          "prp": [1.5, -0.5, 9], "window": [-3, 4, -2, 2.5], "front": 2, "back": -6,
          "projection": "perspective"}})");
  const scene::scene_matrices m = scene::matrices_of(parse(d));
  const scene::matrix_chain* chain = nullptr;
  for (const scene::matrix_chain& c : m.chains)
    if (c.name == "phigs_normalisation") chain = &c;
  ASSERT_NE(chain, nullptr);
  EXPECT_EQ(chain->formula, "N = Mpp * Sfar * Sper * SHper * T(-PRP) * R * T(-VRP) * p");
  ASSERT_EQ(chain->factors.size(), 7u);
  EXPECT_EQ(chain->factors.front().name, "Mpp");
  // Sper's diagonal: 2 pn / (umax - umin), 2 pn / (vmax - vmin).
  EXPECT_DOUBLE_EQ(chain->factors[2].m.m[0], 2 * 9 / 7.0);
  EXPECT_DOUBLE_EQ(chain->factors[2].m.m[5], 2 * 9 / 4.5);
  const std::string text = scene::matrices_text(m);
  for (const char* name : {"Mpp (", "Sfar (", "Sper (", "SHper (", "T(-PRP) (", "R (", "T(-VRP) ("})
    EXPECT_NE(text.find(name), std::string::npos) << name;
  EXPECT_NE(text.find("now in the opening_45 space"), std::string::npos);
  const json doc = json::parse(scene::matrices_json(m));
  bool found = false;
  for (const json& c : doc["chains"]) found = found || c["name"] == "phigs_normalisation";
  EXPECT_TRUE(found);
}

TEST(Phigs, SceneFormAndBadInput) {
  json d = base_scene();
  d.erase("projection");
  d["camera"] = json::parse(
      R"({"phigs": {"vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0], "prp": [0, 0, 10],
      "window": [-2, 2, -1.5, 1.5], "front": 5, "back": -5, "projection": "perspective"}})");
  const scene::scene s = parse(d);
  EXPECT_EQ(s.form, scene::camera_form::phigs);
  const view::view_setup v = scene::make_view_setup(s);
  EXPECT_EQ(v.kind, view::projection_kind::frustum);
  EXPECT_NEAR(v.cam.eye.z, 10, 1e-12);
  struct bad {
    const char* field;
    json value;
    const char* key;
  };
  const bad cases[] = {
      {"vup", {0, 0, 2}, "/camera/phigs/vup"},
      {"vpn", {0, 0, 0}, "/camera/phigs/vpn"},
      {"prp", {0, 0, 4}, "/camera/phigs/prp"},  // behind the front plane
      {"window", {2, -2, -1, 1}, "/camera/phigs/window"},
      {"window", {-2, 2, -1}, "/camera/phigs/window"},
      {"front", -6, "/camera/phigs/front"},
      {"projection", "isometric", "/camera/phigs/projection"},
      {"vrp", {0, "x", 0}, "/camera/phigs/vrp/1"},
  };
  for (const bad& c : cases) {
    json e = d;
    e["camera"]["phigs"][c.field] = c.value;
    EXPECT_EQ(error_key(e), c.key) << c.field;
  }
  json e = d;
  e["projection"] = base_scene()["projection"];
  EXPECT_EQ(error_key(e), "/projection");
  e = d;
  e["camera"]["phigs"]["projection"] = "parallel";
  e["camera"]["phigs"]["prp"] = {0, 0, -1};
  EXPECT_EQ(error_key(e), "/camera/phigs/prp");
}

// --- viewport, image, aspect, glOrtho, ortho2d ---------------------------------------------------

TEST(Viewport, OrthoAcceptsAnyDistinctNearAndFar) {
  json d = base_scene();
  d["projection"] =
      json::parse(R"({"type": "orthographic", "left": -2, "right": 2, "bottom": -1, "top": 1.5,
                                    "near": -3, "far": 4})");
  const view::view_setup v = scene::make_view_setup(parse(d));
  EXPECT_LT(
      relative_difference(v.projection, from_glm(glm::ortho(-2.0, 2.0, -1.0, 1.5, -3.0, 4.0))),
      1e-15);
  d["projection"]["far"] = -3;
  EXPECT_EQ(error_key(d), "/projection/far");
  d["projection"]["far"] = -5;  // far < near: glOrtho mirrors depth, still a view volume
  EXPECT_EQ(error_key(d), "(no error)");
}

TEST(Viewport, Ortho2dIsGluOrtho2DAndNeedsNoCamera) {
  json d = base_scene();
  d.erase("camera");
  d["projection"] =
      json::parse(R"({"type": "ortho2d", "left": -4, "right": 4, "bottom": -3, "top": 3})");
  const scene::scene s = parse(d);
  const view::view_setup v = scene::make_view_setup(s);
  EXPECT_LT(relative_difference(v.projection, from_glm(glm::ortho(-4.0, 4.0, -3.0, 3.0))),
            1e-15);  // 4 arguments: gluOrtho2D
  EXPECT_EQ(v.model_view.m, mat4::identity().m);
  d["projection"].erase("top");
  EXPECT_EQ(error_key(d), "/projection/top");
  d = base_scene();
  d.erase("camera");
  EXPECT_EQ(error_key(d), "/camera");
}

TEST(Viewport, FitLetterboxesTheWindowAndStretchDoesNot) {
  json d = base_scene();
  d["viewport"] = {{"width", 100}, {"height", 100}};
  d["projection"] =
      json::parse(R"({"type": "orthographic", "left": -2, "right": 2, "bottom": -1, "top": 1,
                                    "near": 1, "far": 9})");
  view::view_setup v = scene::make_view_setup(parse(d));
  EXPECT_EQ(v.vp.width, 100);
  EXPECT_EQ(v.vp.height, 100);
  EXPECT_FALSE(v.needs_placement());
  d["aspect"] = "fit";
  v = scene::make_view_setup(parse(d));
  EXPECT_EQ(v.vp.width, 100);
  EXPECT_EQ(v.vp.height, 50);
  EXPECT_EQ(v.place_y, 25);
  EXPECT_TRUE(v.needs_placement());
  d["aspect"] = "squash";
  EXPECT_EQ(error_key(d), "/aspect");
}

TEST(Viewport, OffsetInsideALargerImage) {
  json d = base_scene();
  d["meshes"][0]["file"] = "meshes/quad.off";
  d["meshes"][0]["color"] = {200, 40, 40};
  d["camera"] = json::parse(R"({"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0]})");
  d["projection"] =
      json::parse(R"({"type": "orthographic", "left": -2, "right": 2, "bottom": -2, "top": 2,
                                    "near": 1, "far": 9})");
  d["viewport"] = {{"width", 40}, {"height", 40}, {"x", 10}, {"y", 5}};
  d["image"] = {{"width", 60}, {"height", 50}};
  const std::string path = dir() + "/offset.json";
  std::ofstream(path) << d.dump();
  std::ostringstream log;
  render_command({path, dir() + "/offset.png", false}, log);
  const view::image img = view::read_png(dir() + "/offset.png");
  ASSERT_EQ(img.width(), 60);
  ASSERT_EQ(img.height(), 50);
  // The quad covers the middle half of the viewport: window pixels x 20..39, y 15..34.
  const view::rgb8 red{200, 40, 40}, white{255, 255, 255};
  EXPECT_EQ(img.pixel(20, 15), red);
  EXPECT_EQ(img.pixel(39, 34), red);
  EXPECT_EQ(img.pixel(19, 15), white);
  EXPECT_EQ(img.pixel(40, 34), white);
  EXPECT_EQ(img.pixel(20, 14), white);
  EXPECT_EQ(img.pixel(39, 35), white);
  int reds = 0;
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 60; ++i) reds += img.pixel(i, j) == red;
  EXPECT_EQ(reds, 400);
  render_command({path, dir() + "/offset.svg", false}, log);
  std::ifstream in(dir() + "/offset.svg");
  std::stringstream svg;
  svg << in.rdbuf();
  EXPECT_NE(svg.str().find("<svg x=\"10\" y=\"5\""), std::string::npos) << svg.str().substr(0, 400);
  // Bad placements name the key.
  d["viewport"]["x"] = 30;
  EXPECT_EQ(error_key(d), "/viewport/x");
  d["viewport"]["x"] = -1;
  EXPECT_EQ(error_key(d), "/viewport/x");
  d["viewport"]["x"] = 0;
  d["image"]["height"] = 0;
  EXPECT_EQ(error_key(d), "/image/height");
}

// --- lines --------------------------------------------------------------------------------------

TEST(Lines, HomogeneousCohenSutherlandAgreesWithLiangBarsky) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-3, 3), w(-0.5, 3);
  int kept = 0;
  for (int k = 0; k < 20000; ++k) {
    const clip::vec4d a{u(rng), u(rng), u(rng), w(rng)}, b{u(rng), u(rng), u(rng), w(rng)};
    clip::vec4d la, lb, ca, cb;
    double lt0, lt1, ct0, ct1;
    const bool l = clip::homogeneous_liang_barsky(a, b, la, lb, &lt0, &lt1);
    const bool c = clip::homogeneous_cohen_sutherland(a, b, ca, cb, &ct0, &ct1);
    if (l != c) {  // only a segment grazing the volume may differ, by rounding
      EXPECT_LT(std::fabs(l ? lt1 - lt0 : ct1 - ct0), 1e-9) << k;
      continue;
    }
    if (!l) continue;
    ++kept;
    EXPECT_NEAR(lt0, ct0, 1e-12) << k;
    EXPECT_NEAR(lt1, ct1, 1e-12) << k;
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(la[i], ca[i], 1e-9) << k;
      EXPECT_NEAR(lb[i], cb[i], 1e-9) << k;
    }
  }
  EXPECT_GT(kept, 1000);
  // Degenerate cases first-hand: inside point, outside point, behind the eye.
  clip::vec4d oa, ob;
  EXPECT_TRUE(clip::homogeneous_cohen_sutherland({0.5, 0, 0, 1}, {0.5, 0, 0, 1}, oa, ob));
  EXPECT_FALSE(clip::homogeneous_cohen_sutherland({1.5, 0, 0, 1}, {1.5, 0, 0, 1}, oa, ob));
  EXPECT_FALSE(clip::homogeneous_cohen_sutherland({0, 0, 1, -1}, {0.3, 0, 2, -3}, oa, ob));
  EXPECT_FALSE(clip::homogeneous_cohen_sutherland({0, 0, 0, 1}, {NAN, 0, 0, 1}, oa, ob));
  ASSERT_TRUE(clip::homogeneous_cohen_sutherland({0, 0, 0, 2}, {0, 0, -6, -2}, oa, ob));
  EXPECT_EQ(oa, (clip::vec4d{0, 0, 0, 2}));
  EXPECT_EQ(ob[2], -ob[3]);  // snapped onto the near plane w + z = 0
}

TEST(Lines, SceneLinesAreDrawnInBspOrderByEitherClipper) {
  json d = base_scene();
  d["meshes"][0] = json::parse(R"({"file": "meshes/quad.off", "color": [200, 40, 40]})");
  d["camera"] = json::parse(R"({"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0]})");
  // One line in front of the quad (visible), one behind it (hidden where the quad covers it),
  // both running out of the view volume on both sides (clipped).
  d["lines"] = json::parse(R"([
    {"points": [[-9, 0.5, 1], [9, 0.5, 1]], "color": [0, 0, 255], "clipper": "cohen-sutherland"},
    {"points": [[-9, -0.5, -1], [9, -0.5, -1]], "color": [0, 160, 0], "clipper": "liang-barsky"}])");
  const scene::scene s = parse(d);
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_EQ(s.line_count, 2u);
  EXPECT_TRUE(s.curves[0].polyline);
  EXPECT_EQ(s.curves[0].clipper, view::segment_clipper::cohen_sutherland);
  const std::string path = dir() + "/lines.json";
  std::ofstream(path) << d.dump();
  std::ostringstream log;
  render_command({path, dir() + "/lines.png", true}, log);
  EXPECT_NE(log.str().find("stage curves:"), std::string::npos);
  const view::image img = view::read_png(dir() + "/lines.png");
  int blue_over_quad = 0, green_over_quad = 0, green_outside = 0;
  for (int j = 0; j < img.height(); ++j)
    for (int i = 0; i < img.width(); ++i) {
      const bool over_quad = std::fabs(i + 0.5 - 32) < 11 &&
                             std::fabs(j + 0.5 - 24) < 11;  // inside the quad (half-size 13 px)
      const view::rgb8 c = img.pixel(i, j);
      blue_over_quad += over_quad && c == view::rgb8{0, 0, 255};
      green_over_quad += over_quad && c == view::rgb8{0, 160, 0};
      green_outside += !over_quad && c == view::rgb8{0, 160, 0};
    }
  EXPECT_GT(blue_over_quad, 0);
  EXPECT_EQ(green_over_quad, 0);
  EXPECT_GT(green_outside, 0);
  json e = d;
  e["lines"][0]["clipper"] = "bresenham";
  EXPECT_EQ(error_key(e), "/lines/0/clipper");
  e = d;
  e["lines"][1]["points"] = {{0, 0, 0}};
  EXPECT_EQ(error_key(e), "/lines/1/points");
  e["lines"][1]["points"] = {{0, 0, 0}, {1, 1}};
  EXPECT_EQ(error_key(e), "/lines/1/points/1");
}

// --- bounding-box reject
// ---------------------------------------------------------------------------

TEST(Reject, MeshOutsideTheViewVolumeIsDroppedBeforeTheBuildAndSaidSo) {
  json d = base_scene();
  d["meshes"] = json::parse(R"([{"file": "meshes/quad.off", "color": [200, 40, 40]},
      {"file": "meshes/quad.off", "color": [0, 0, 200], "transforms": [{"translate": [0, 0, 20]}]},
      {"file": "meshes/quad.off", "color": [0, 200, 0], "transforms": [{"translate": [50, 0, 0]}]}])");
  const std::string path = dir() + "/reject.json";
  std::ofstream(path) << d.dump();
  std::ostringstream log;
  render_command({path, dir() + "/reject.png", true}, log);
  const std::string text = log.str();
  EXPECT_NE(text.find("2 of 3 meshes outside the view volume"), std::string::npos) << text;
  EXPECT_NE(text.find("reject: /meshes/1 "), std::string::npos) << text;
  EXPECT_NE(text.find("reject: /meshes/2 "), std::string::npos) << text;
  EXPECT_EQ(text.find("reject: /meshes/0 "), std::string::npos) << text;
  // The picture is that of the visible mesh alone.
  json only = d;
  only["meshes"] = json::array({d["meshes"][0]});
  std::ofstream(dir() + "/reject_only.json") << only.dump();
  render_command({dir() + "/reject_only.json", dir() + "/reject_only.png", false}, log);
  const view::image a = view::read_png(dir() + "/reject.png"),
                    b = view::read_png(dir() + "/reject_only.png");
  ASSERT_EQ(a.width(), b.width());
  for (int j = 0; j < a.height(); ++j)
    for (int i = 0; i < a.width(); ++i) ASSERT_EQ(a.pixel(i, j), b.pixel(i, j));
}

// --- trackball
// ------------------------------------------------------------------------------------

TEST(Trackball, VirtualTrackballTurnsByTheArcItself) {
  const vec3d p{0.6, 0, 0.8}, q{0, 0.6, 0.8};
  const quaternion v = virtual_trackball_rotation(p, q);
  const vec3d r = rotate(v, p);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r[k], q[k], 1e-15);  // p goes exactly to q
  const quaternion twice = v * v, a = arcball_rotation(p, q);
  EXPECT_NEAR(std::fabs(dot(twice, a)), 1, 1e-15);  // the arcball is its square
  EXPECT_NEAR(to_axis_angle(a).angle, 2 * to_axis_angle(v).angle, 1e-12);
  const quaternion same = virtual_trackball_rotation(p, p);
  EXPECT_EQ(same.w, 1.0);
  const quaternion half = virtual_trackball_rotation({1, 0, 0}, {-1, 0, 0});  // opposite rim points
  const vec3d h = rotate(half, {1, 0, 0});
  EXPECT_NEAR(h[0], -1, 1e-15);
  EXPECT_THROW(virtual_trackball_rotation({0, 0, 0}, q), usage_error);
  const arcball ball(100, 100, screen_y::down, trackball_kind::virtual_);
  EXPECT_NEAR(std::fabs(dot(ball.drag({50, 50}, {70, 50}),
                            virtual_trackball_rotation(ball.sphere_point({50, 50}),
                                                       ball.sphere_point({70, 50})))),
              1, 1e-15);
}

TEST(Trackball, SelectablePerSceneAndByFlag) {
  json d = base_scene();
  d["trackball"] = "virtual";
  scene::scene s = parse(d);
  EXPECT_EQ(s.trackball, "virtual");
  const auto virt = orbit_cameras(s, {{32, 24}, {44, 24}}, 0);
  s.trackball = "arcball";
  const auto arc = orbit_cameras(s, {{32, 24}, {44, 24}}, 0);
  const view::point3 look = s.camera.look_at;
  auto angle = [&](const view::camera& c) {
    const view::vector3 a = view::normalized(s.camera.eye - look),
                        b = view::normalized(c.eye - look);
    return std::acos(std::min(1.0, view::dot(a, b)));
  };
  EXPECT_NEAR(angle(arc.back().first), 2 * angle(virt.back().first), 1e-9);
  d["trackball"] = "spaceball";
  EXPECT_EQ(error_key(d), "/trackball");
}

// --- the command line: bad input exits 2, names the key, writes nothing
// ------------------------------

int run(const std::string& args, std::string& err) {
  const std::string e = dir() + "/.err";
  const int raw = std::system(
      ("'" + std::string(EXBSP_CLI) + "' " + args + " 2>'" + e + "' >/dev/null").c_str());
  std::ifstream in(e);
  std::stringstream s;
  s << in.rdbuf();
  err = s.str();
  return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

TEST(CommandLine, BadNewKeysExit2NamingTheKeyWithNoOutput) {
  struct bad {
    const char* name;
    std::function<void(json&)> mutate;
    const char* key;
  };
  const bad cases[] = {
      {"rotate axis",
       [](json& d) { d["meshes"][0]["transforms"] = json::parse(R"([{"rotate": [9, 0, 0, 0]}])"); },
       "/meshes/0/transforms/0/rotate"},
      {"polar distance",
       [](json& d) {
         d["camera"] = json::parse(R"({"polar": {"distance": -1, "twist_deg": 0,
           "elevation_deg": 0, "azimuth_deg": 0}})");
       },
       "/camera/polar/distance"},
      {"phigs vup",
       [](json& d) {
         d.erase("projection");
         d["camera"] = json::parse(
             R"({"phigs": {"vrp": [0,0,0], "vpn": [0,0,1], "vup": [0,0,-3], "prp": [0,0,9],
           "window": [-1,1,-1,1], "front": 1, "back": -1, "projection": "parallel"}})");
       },
       "/camera/phigs/vup"},
      {"line clipper",
       [](json& d) {
         d["lines"] = json::parse(R"([{"points": [[0,0,0],[1,1,1]], "clipper": 3}])");
       },
       "/lines/0/clipper"},
      {"viewport y", [](json& d) { d["viewport"]["y"] = 1; }, "/viewport/y"},
      {"trackball", [](json& d) { d["trackball"] = true; }, "/trackball"},
  };
  for (const bad& c : cases) {
    json d = base_scene();
    c.mutate(d);
    const std::string path = dir() + "/bad.json", out = dir() + "/bad_out.png";
    std::ofstream(path) << d.dump();
    std::string err;
    EXPECT_EQ(run("render '" + path + "' -o '" + out + "'", err), 2) << c.name;
    EXPECT_NE(err.find(std::string("bad.json: ") + c.key + ":"), std::string::npos)
        << c.name << ": " << err;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
  std::string err;
  EXPECT_EQ(run("render --trackball spaceball -o '" + dir() + "/x.png'", err), 2);
  EXPECT_FALSE(fs::exists(dir() + "/x.png"));
}

// ---- the lens, the depth range and a curve's control polygon ----------------------------------

TEST(Lens, AWidthAngleAndAnAspectGiveGluPerspectivesMatrix) {
  json d = base_scene();
  d["projection"] = {
      {"type", "perspective"}, {"fovx_deg", 90}, {"aspect", 2}, {"near", 1}, {"far", 100}};
  // tan(fovy / 2) = tan(45 degrees) / 2: fovy = 2 atan(1/2), GLM's gluPerspective as the oracle.
  const mat4 expected = from_glm(glm::perspective(2 * std::atan(0.5), 2.0, 1.0, 100.0));
  EXPECT_LT(view::max_abs_difference(scene::make_view_setup(parse(d)).projection, expected), 1e-12);
  // The height angle with the viewport's aspect (64 x 48) is the default, as before.
  const mat4 plain = from_glm(glm::perspective(40 * pi / 180, 64.0 / 48.0, 1.0, 100.0));
  EXPECT_LT(view::max_abs_difference(scene::make_view_setup(parse(base_scene())).projection, plain),
            1e-12);
  // With "aspect": "fit", a perspective window of its own aspect is letterboxed: 64 x 32.
  d["aspect"] = "fit";
  const view::view_setup fitted = scene::make_view_setup(parse(d));
  EXPECT_EQ(fitted.vp.width, 64);
  EXPECT_EQ(fitted.vp.height, 32);
  EXPECT_EQ(fitted.place_y, 8);
  json both = base_scene();
  both["projection"]["fovx_deg"] = 50;
  EXPECT_EQ(error_key(both), "/projection/fovx_deg");
  json none = base_scene();
  none["projection"].erase("fovy_deg");
  EXPECT_EQ(error_key(none), "/projection/fovy_deg");
  json wide = base_scene();
  wide["projection"].erase("fovy_deg");
  wide["projection"]["fovx_deg"] = 180;
  EXPECT_EQ(error_key(wide), "/projection/fovx_deg");
  json flat = base_scene();
  flat["projection"]["aspect"] = 0;
  EXPECT_EQ(error_key(flat), "/projection/aspect");
}

TEST(RawMatrix, AFrustumsOrAnOrthosMatrixIsThatViewAndRendersTheSamePixels) {
  // glFrustum(-0.5, 0.4, -0.3, 0.35, 1, 100) as a matrix: the same view as "frustum".
  json frustum = base_scene();
  frustum["projection"] = {{"type", "frustum"}, {"left", -0.5}, {"right", 0.4}, {"bottom", -0.3},
                           {"top", 0.35},       {"near", 1},    {"far", 100}};
  const view::view_setup fv = scene::make_view_setup(parse(frustum));
  json raw = base_scene();
  raw["projection"] = {{"type", "matrix"}, {"matrix", fv.projection.m}};
  const scene::scene rs = parse(raw);
  const view::view_setup rv = scene::make_view_setup(rs);
  EXPECT_EQ(rs.projection.kind, view::projection_kind::frustum);
  EXPECT_NEAR(rs.projection.left, -0.5, 1e-12);
  EXPECT_NEAR(rs.projection.top, 0.35, 1e-12);
  EXPECT_NEAR(rs.projection.near_dist, 1, 1e-9);
  EXPECT_NEAR(rs.projection.far_dist, 100, 1e-9);
  EXPECT_LT(view::length(rv.cam.eye - fv.cam.eye), 1e-12);  // the centre of projection
  EXPECT_EQ(rv.projection.m, fv.projection.m);
  // glOrtho as a matrix: a parallel view along the gaze.
  json ortho = base_scene();
  ortho["projection"] = {{"type", "orthographic"},
                         {"left", -2},
                         {"right", 2},
                         {"bottom", -1.5},
                         {"top", 1.5},
                         {"near", 1},
                         {"far", 20}};
  const view::view_setup ov = scene::make_view_setup(parse(ortho));
  json raw_ortho = base_scene();
  raw_ortho["projection"] = {{"type", "matrix"}, {"matrix", ov.projection.m}};
  const scene::scene ros = parse(raw_ortho);
  const view::view_setup rov = scene::make_view_setup(ros);
  EXPECT_EQ(ros.projection.kind, view::projection_kind::orthographic);
  EXPECT_TRUE(rov.is_parallel());
  EXPECT_LT(view::length(rov.direction - ov.direction), 1e-12);
  EXPECT_NEAR(ros.projection.near_dist, 1, 1e-12);
  EXPECT_NEAR(ros.projection.far_dist, 20, 1e-12);
  // The same pixels: the command renders both scenes of each pair to identical PNGs.
  for (const auto& [a, b] : {std::pair{frustum, raw}, std::pair{ortho, raw_ortho}}) {
    std::ofstream(dir() + "/a.json") << a.dump();
    std::ofstream(dir() + "/b.json") << b.dump();
    std::string err;
    ASSERT_EQ(run("render " + dir() + "/a.json -o " + dir() + "/a.png", err), 0) << err;
    ASSERT_EQ(run("render " + dir() + "/b.json -o " + dir() + "/b.png", err), 0) << err;
    EXPECT_TRUE(view::read_png(dir() + "/a.png").data() == view::read_png(dir() + "/b.png").data());
  }
}

TEST(RawMatrix, BadMatricesNameTheKey) {
  json short_one = base_scene();
  short_one["projection"] = {{"type", "matrix"}, {"matrix", std::vector<double>(15, 1.0)}};
  EXPECT_EQ(error_key(short_one), "/projection/matrix");
  json word = base_scene();
  std::vector<json> entries(16, 0.0);
  entries[5] = "one";
  word["projection"] = {{"type", "matrix"}, {"matrix", entries}};
  EXPECT_EQ(error_key(word), "/projection/matrix/5");
  json singular = base_scene();
  singular["projection"] = {{"type", "matrix"}, {"matrix", std::vector<double>(16, 1.0)}};
  EXPECT_EQ(error_key(singular), "/projection/matrix");
  json mirrored = base_scene();
  mirrored["projection"] = {{"type", "matrix"},
                            {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1}}};
  EXPECT_EQ(error_key(mirrored), "/projection/matrix");
  json missing = base_scene();
  missing["projection"] = {{"type", "matrix"}};
  EXPECT_EQ(error_key(missing), "/projection/matrix");
}

TEST(DepthRange, GlDepthRangeMapsTheWindowDepthAndLeavesThePictureAlone) {
  json d = base_scene();
  d["viewport"]["depth_range"] = {0.25, 0.75};
  const view::view_setup v = scene::make_view_setup(parse(d));
  EXPECT_EQ(v.vp.depth_near, 0.25);
  EXPECT_EQ(v.vp.depth_far, 0.75);
  // z_w = n + (z_ndc + 1) (f - n) / 2: the near plane at 0.25, the far one at 0.75.
  EXPECT_DOUBLE_EQ(view::to_window(v.vp, 0, 0, -1).z, 0.25);
  EXPECT_DOUBLE_EQ(view::to_window(v.vp, 0, 0, 1).z, 0.75);
  // The painter needs no depth: the PNG is the default range's, with fog too (fog reads the
  // eye's distance back through the range).
  for (const bool fog : {false, true}) {
    json plain = base_scene(), ranged = d;
    if (fog) plain["effects"] = ranged["effects"] = {{"fog", {{"start", 1}, {"end", 8}}}};
    const std::string a = dir() + "/plain.png", b = dir() + "/ranged.png";
    std::ofstream(dir() + "/plain.json") << plain.dump();
    std::ofstream(dir() + "/ranged.json") << ranged.dump();
    std::ostringstream log;
    exbsp::render_command({dir() + "/plain.json", a}, log);
    exbsp::render_command({dir() + "/ranged.json", b}, log);
    EXPECT_EQ(exbsp_test::read_file(a), exbsp_test::read_file(b)) << "fog " << fog;
  }
  json empty = base_scene();
  empty["viewport"]["depth_range"] = {0.5, 0.5};
  EXPECT_EQ(error_key(empty), "/viewport/depth_range");
  json outside = base_scene();
  outside["viewport"]["depth_range"] = {0, 2};
  EXPECT_EQ(error_key(outside), "/viewport/depth_range/1");
}

TEST(ControlPolygon, ACurveMayShowItsControlPolygonAsALine) {
  json d = base_scene();
  d["curves"] = {{{"bezier", {{-1, 0, 0}, {0, 2, 0}, {1, 0, 0}}}, {"control_polygon", true}}};
  const scene::scene s = parse(d);
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_TRUE(s.curves[0].polyline);
  EXPECT_EQ(s.curves[0].control_points, s.curves[1].control_points);
  EXPECT_EQ(s.curves[0].color, (view::rgb8{150, 150, 150}));
  EXPECT_FALSE(s.curves[1].polyline);
  EXPECT_EQ(s.line_count, 1u);
  d["curves"][0]["control_polygon"] = {{"color", {0, 0, 255}}};
  EXPECT_EQ(parse(d).curves[0].color, (view::rgb8{0, 0, 255}));
  d["curves"][0]["control_polygon"] = false;
  EXPECT_EQ(parse(d).curves.size(), 1u);
  d["curves"][0]["control_polygon"] = 3;
  EXPECT_EQ(error_key(d), "/curves/0/control_polygon");
}

// ---- exbsp matrices: the course's chains beside OpenGL's -------------------------------------

/// The matrices of scenes/NAME.json.
scene::scene_matrices scene_matrices_of(const std::string& name) {
  return scene::matrices_of(
      scene::load_scene(std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json"));
}

const scene::matrix_chain* chain_named(const scene::scene_matrices& m, const std::string& name) {
  for (const scene::matrix_chain& c : m.chains)
    if (c.name == name) return &c;
  return nullptr;
}

/// m * p divided by w.
view::point3 divided(const mat4& m, const view::point3& p) {
  const view::hpoint h = m * p;
  return {h.x / h.w, h.y / h.w, h.z / h.w};
}

TEST(CourseMatrices, TheViewingChainIsOpenGLsWindowMinusHalfAPixelWithZTurned) {
  for (const std::string name : {"perspective", "frustum", "orthographic"}) {
    SCOPED_TRACE(name);
    const scene::scene_matrices m = scene_matrices_of(name);
    const scene::matrix_chain* gl = chain_named(m, "opengl");
    const scene::matrix_chain* course = chain_named(m, "viewing");
    ASSERT_TRUE(gl && course);
    EXPECT_EQ(course->factors.size(), name == "orthographic" ? 3u : 4u);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coordinate(-3, 3);
    for (int i = 0; i < 50; ++i) {
      const view::point3 p{coordinate(rng), coordinate(rng), coordinate(rng)};
      const view::point3 w = divided(gl->product, p), s = divided(course->product, p);
      const double tolerance = 1e-9 * (1 + std::abs(w.x) + std::abs(w.y));
      EXPECT_NEAR(s.x, w.x - 0.5, tolerance);
      EXPECT_NEAR(s.y, w.y - 0.5, tolerance);
      EXPECT_NEAR(s.z, -(2 * w.z - 1), 1e-9 * (1 + std::abs(s.z)));  // depth [0,1] -> ndc, turned
    }
  }
  EXPECT_EQ(chain_named(scene_matrices_of("oblique"), "viewing"), nullptr);
}

TEST(CourseMatrices, NormalisationTakesTheFrustumsCornersToTheCanonicalParallelVolume) {
  // perspective.json: the camera and lens written out here from the scene file, not from the
  // code under test.
  const std::string path = std::string(EXBSP_SOURCE_DIR) + "/scenes/perspective.json";
  const nlohmann::json doc = nlohmann::json::parse(exbsp_test::read_file(path));
  const auto triple = [](const nlohmann::json& a) {
    return view::vector3{a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
  };
  const view::vector3 eye = triple(doc["camera"]["eye"]), at = triple(doc["camera"]["look_at"]);
  const view::vector3 up = triple(doc["camera"]["up"]);
  const double fovy = doc["projection"]["fovy_deg"].get<double>();
  const double near_dist = doc["projection"]["near"].get<double>();
  const double far_dist = doc["projection"]["far"].get<double>();
  const double aspect =
      doc["viewport"]["width"].get<double>() / doc["viewport"]["height"].get<double>();
  const view::vector3 gaze = view::normalized(at - eye);
  const view::vector3 right = view::normalized(view::cross(gaze, up)),
                      true_up = view::cross(right, gaze);
  const scene::scene_matrices m = scene::matrices_of(scene::load_scene(path));
  const scene::matrix_chain* chain = chain_named(m, "normalisation");
  ASSERT_NE(chain, nullptr);
  ASSERT_EQ(chain->factors.size(), 5u);
  EXPECT_EQ(chain->factors[0].name, "Dpersp");
  for (const double distance : {near_dist, far_dist}) {
    const double half_h = distance * std::tan(fovy * M_PI / 360), half_w = half_h * aspect;
    for (const double sx : {-1.0, 1.0})
      for (const double sy : {-1.0, 1.0}) {
        const view::vector3 corner =
            eye + distance * gaze + (sx * half_w) * right + (sy * half_h) * true_up;
        const view::point3 q = divided(chain->product, {corner.x, corner.y, corner.z});
        EXPECT_NEAR(q.x, sx, 1e-9);
        EXPECT_NEAR(q.y, sy, 1e-9);
        EXPECT_NEAR(q.z, distance == near_dist ? 0.0 : 1.0, 1e-9);  // near at 0, far at 1
      }
  }
  // In between, the depth is OpenGL's window depth (glDepthRange 0, 1).
  const scene::matrix_chain* gl = chain_named(m, "opengl");
  const view::vector3 inside = eye + (0.5 * (near_dist + far_dist)) * gaze + 0.3 * right;
  const view::point3 p{inside.x, inside.y, inside.z};
  EXPECT_NEAR(divided(chain->product, p).z, divided(gl->product, p).z, 1e-12);
  // The product of the factors is the product shown.
  mat4 product = mat4::identity();
  for (const scene::named_matrix& f : chain->factors) product = product * f.m;
  EXPECT_EQ(view::max_abs_difference(product, chain->product), 0.0);
}

TEST(CourseMatrices, TheCommandPrintsTextOrJsonAndNamesWhatItLeavesOut) {
  const auto run = [&](const std::string& args) {
    const std::string out = dir() + "/matrices.out";
    const int raw = std::system(
        ("'" + std::string(EXBSP_CLI) + "' matrices " + args + " >'" + out + "' 2>/dev/null")
            .c_str());
    return std::pair<int, std::string>{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1,
                                       exbsp_test::read_file(out)};
  };
  const std::string scenes = std::string(EXBSP_SOURCE_DIR) + "/scenes/";
  const auto [status, text] = run("'" + scenes + "perspective.json'");
  EXPECT_EQ(status, 0);
  for (const char* name : {"Mviewport", "Mprojection", "Mmodelview", "Mvp", "Morth", "Mp (", "Mv (",
                           "Dpersp", "Sfar", "Sxy", "Mrot", "Ttrans"})
    EXPECT_NE(text.find(name), std::string::npos) << name;
  const auto [json_status, json_text] = run("'" + scenes + "orthographic.json' --json");
  EXPECT_EQ(json_status, 0);
  const nlohmann::json doc = nlohmann::json::parse(json_text);
  EXPECT_EQ(doc["projection"], "orthographic");
  EXPECT_EQ(doc["chains"].size(), 2u);
  EXPECT_EQ(doc["chains"][1]["factors"].size(), 3u);  // Mvp, Morth, Mv: no Mp
  EXPECT_EQ(doc["notes"].size(), 1u);
  EXPECT_EQ(doc["chains"][0]["product"].size(), 4u);
  EXPECT_EQ(run("'" + scenes + "no_such_scene.json'").first, 2);
  EXPECT_EQ(run("").first, 0);  // the demo scene
}

}  // namespace
