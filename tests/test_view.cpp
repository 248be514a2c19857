// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of src/view/: matrices and camera against closed forms and GLM, oblique projection,
// viewport, clip stage, the top-left rule (coverage counted through the rasterizer's coverage
// callback), painter's order on a cyclic overlap against a z-buffer oracle, backface culling,
// PNG round trip (read back with libpng's own API), SVG output, atomic writes, stage lists.
//
// RapidCheck runs with a fixed seed unless RC_PARAMS is set in the environment.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <png.h>
#include <rapidcheck/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/soup.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
#include <exbsp/view/transforms.h>
#include <exbsp/view/viewport.h>
#include "core/atomic_file.h"
#include "view/backface_culling.h"
#include "view/clip_stage.h"
#include "view/effects.h"
#include "view/orient2d.h"
#include "view/rasterizer.h"
#include "view/svg_writer.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp;
using namespace exbsp::view;

[[maybe_unused]] const bool fixed_seed = exbsp_test::fixed_rc_seed();

constexpr double pi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------
// Helpers

using exbsp_test::relative_difference;
mat4 from_glm(const glm::dmat4& g) { return exbsp_test::from_column_major(g); }

std::string temp_dir() {
  static const std::string dir = exbsp_test::make_temp_dir("test_view").string();
  return dir;
}

/// Per-pixel coverage counts of a set of triangles (the coverage callback of the rasterizer).
struct coverage {
  int width, height;
  std::vector<int> count;
  coverage(int w, int h) : width(w), height(h), count(static_cast<std::size_t>(w) * h, 0) {}
  void add(const point2& a, const point2& b, const point2& c) {
    for_each_covered_pixel(a, b, c, width, height,
                           [&](int i, int j) { ++count[static_cast<std::size_t>(j) * width + i]; });
  }
  int at(int i, int j) const { return count[static_cast<std::size_t>(j) * width + i]; }
  int total() const {
    int t = 0;
    for (int c : count) t += c;
    return t;
  }
};

point2 centre(int i, int j) { return {i + 0.5, j + 0.5}; }

int orient(const point2& a, const point2& b, const point2& c) {
  return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// Uniform integer in [lo, hi] independent of RapidCheck's size.
int uniform_int(int lo, int hi) {
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi + 1));
}

/// A coordinate on the half-pixel grid in [0, n]: often exactly on pixel centres.
double half_grid(int n) { return uniform_int(0, 2 * n) / 2.0; }

// ---------------------------------------------------------------------------------------
// Matrices, points and vectors

TEST(Matrix, RowMajorStorageAndColumnVectors) {
  const mat4 t = translate({1, 2, 3});
  EXPECT_EQ(t.m[3], 1);  // row 0, column 3
  EXPECT_EQ(t.m[7], 2);
  EXPECT_EQ(t.m[11], 3);
  const hpoint p = t * point3{1, 1, 1};
  EXPECT_EQ(p.x, 2);
  EXPECT_EQ(p.y, 3);
  EXPECT_EQ(p.z, 4);
  EXPECT_EQ(p.w, 1);
}

TEST(Matrix, TranslationMovesPointsButNotVectors) {
  const mat4 t = translate({5, -7, 9});
  const vector3 v = transform_vector(t, {1, 2, 3});
  EXPECT_EQ(v.x, 1);
  EXPECT_EQ(v.y, 2);
  EXPECT_EQ(v.z, 3);
  const point3 q = transform_point(t, {1, 2, 3});
  EXPECT_EQ(q.x, 6);
  EXPECT_EQ(q.y, -5);
  EXPECT_EQ(q.z, 12);
}

TEST(Matrix, ProductAppliesTheRightFactorFirst) {
  const mat4 m = translate({1, 0, 0}) * scale(2, 2, 2);  // scale, then translate
  const point3 q = transform_point(m, {1, 1, 1});
  EXPECT_EQ(q.x, 3);
  EXPECT_EQ(q.y, 2);
}

TEST(Matrix, TransformPointDividesByWAndRejectsWZero) {
  mat4 m = mat4::identity();
  m(3, 3) = 2;
  const point3 q = transform_point(m, {2, 4, 6});
  EXPECT_EQ(q.x, 1);
  EXPECT_EQ(q.z, 3);
  m(3, 3) = 0;
  EXPECT_THROW(transform_point(m, {1, 1, 1}), usage_error);
}

TEST(Transforms, RotateFollowsTheRightHandRule) {
  const mat4 r = rotate(90, {0, 0, 1});
  const vector3 v = transform_vector(r, {1, 0, 0});
  EXPECT_NEAR(v.x, 0, 1e-15);
  EXPECT_NEAR(v.y, 1, 1e-15);
  EXPECT_NEAR(v.z, 0, 1e-15);
  EXPECT_THROW(rotate(10, {0, 0, 0}), usage_error);
}

TEST(Transforms, AgreeWithGlm) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int k = 0; k < 200; ++k) {
    const double angle = u(rng) * 36;
    const vector3 axis{u(rng), u(rng), u(rng)};
    const glm::dmat4 g =
        glm::rotate(glm::dmat4(1.0), angle * pi / 180, glm::dvec3(axis.x, axis.y, axis.z));
    EXPECT_LT(relative_difference(rotate(angle, axis), from_glm(g)), 1e-12);
    const vector3 t{u(rng), u(rng), u(rng)};
    EXPECT_LT(relative_difference(translate(t), from_glm(glm::translate(
                                                    glm::dmat4(1.0), glm::dvec3(t.x, t.y, t.z)))),
              1e-15);
    EXPECT_LT(relative_difference(scale(t.x, t.y, t.z),
                                  from_glm(glm::scale(glm::dmat4(1.0), glm::dvec3(t.x, t.y, t.z)))),
              1e-15);
  }
}

TEST(MatrixStack, PushPopAndMultiplyLikeOpenGl) {
  matrix_stack s;
  EXPECT_EQ(s.depth(), 1u);
  s.multiply(translate({1, 0, 0}));
  s.push();
  s.multiply(scale(2, 2, 2));
  EXPECT_EQ(s.depth(), 2u);
  point3 q = transform_point(s.top(), {1, 1, 1});  // scale first, then translate
  EXPECT_EQ(q.x, 3);
  EXPECT_EQ(q.y, 2);
  s.pop();
  q = transform_point(s.top(), {1, 1, 1});
  EXPECT_EQ(q.x, 2);
  EXPECT_EQ(q.y, 1);
  EXPECT_THROW(s.pop(), usage_error);
  s.load_identity();
  EXPECT_EQ(s.top().m, mat4::identity().m);
}

// ---------------------------------------------------------------------------------------
// Camera

TEST(LookAt, EyeOnThePositiveZAxisIsATranslation) {
  const mat4 m = look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
  mat4 expected = mat4::identity();
  expected(2, 3) = -5;
  EXPECT_EQ(m.m, expected.m);
}

TEST(LookAt, ClosedFormBasisForAGazeAlongX) {
  // g = +x, up = +z: w = -x, u = t x w = -y, v = w x u = +z.
  const camera_basis b = look_at_basis({0, 0, 0}, {1, 0, 0}, {0, 0, 1});
  EXPECT_EQ(b.u.x, 0);
  EXPECT_EQ(b.u.y, -1);
  EXPECT_EQ(b.v.z, 1);
  EXPECT_EQ(b.w.x, -1);
  const mat4 m = look_at({0, 0, 0}, {1, 0, 0}, {0, 0, 1});
  const point3 c = transform_point(m, {1, 0, 0});  // the look-at point is straight ahead: -z
  EXPECT_EQ(c.x, 0);
  EXPECT_EQ(c.y, 0);
  EXPECT_EQ(c.z, -1);
}

TEST(LookAt, MapsTheEyeToTheOriginAndTheTargetOntoMinusZ) {
  const point3 eye{3, -4, 2}, target{-1, 2, 0.5};
  const mat4 m = look_at(eye, target, {0.2, 0.1, 1});
  const point3 e = transform_point(m, eye);
  EXPECT_NEAR(e.x, 0, 1e-14);
  EXPECT_NEAR(e.y, 0, 1e-14);
  EXPECT_NEAR(e.z, 0, 1e-14);
  const point3 t = transform_point(m, target);
  EXPECT_NEAR(t.x, 0, 1e-14);
  EXPECT_NEAR(t.y, 0, 1e-14);
  EXPECT_NEAR(t.z, -length(target - eye), 1e-14);
}

TEST(LookAt, UpParallelToTheGazeIsAnError) {
  EXPECT_THROW(look_at({0, 0, 0}, {0, 0, -3}, {0, 0, 1}), usage_error);
  EXPECT_THROW(look_at({0, 0, 0}, {0, 0, -3}, {0, 0, -2}), usage_error);
  EXPECT_THROW(look_at({1, 1, 1}, {1, 1, 1}, {0, 1, 0}), usage_error);
  EXPECT_THROW(look_at({0, 0, 0}, {0, 0, -1}, {0, 0, 0}), usage_error);
}

TEST(LookAt, AgreesWithGlmOnRandomCameras) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-100, 100);
  for (int k = 0; k < 500; ++k) {
    const point3 eye{u(rng), u(rng), u(rng)}, target{u(rng), u(rng), u(rng)};
    const vector3 up{u(rng), u(rng), u(rng)};
    const glm::dmat4 g =
        glm::lookAt(glm::dvec3(eye.x, eye.y, eye.z), glm::dvec3(target.x, target.y, target.z),
                    glm::dvec3(up.x, up.y, up.z));
    EXPECT_LT(relative_difference(look_at(eye, target, up), from_glm(g)), 1e-12);
  }
}

// ---------------------------------------------------------------------------------------
// Projections

TEST(Perspective, ClosedForm) {
  const double f = 1 / std::tan(pi / 8);  // fovy 45
  const mat4 m = perspective(45, 2, 1, 11);
  EXPECT_NEAR(m(0, 0), f / 2, 1e-15);
  EXPECT_NEAR(m(1, 1), f, 1e-15);
  EXPECT_NEAR(m(2, 2), -12.0 / 10, 1e-15);
  EXPECT_NEAR(m(2, 3), -22.0 / 10, 1e-15);
  EXPECT_EQ(m(3, 2), -1);
  EXPECT_EQ(m(3, 3), 0);
}

TEST(Perspective, MapsNearAndFarToMinusOneAndOne) {
  const mat4 m = perspective(60, 1.5, 2, 50);
  const hpoint n = m * point3{0, 0, -2}, f = m * point3{0, 0, -50};
  EXPECT_NEAR(n.z / n.w, -1, 1e-15);
  EXPECT_NEAR(f.z / f.w, 1, 1e-14);
  // The top of the view volume on the near plane: y = near tan(fovy/2) -> y_ndc = 1.
  const hpoint t = m * point3{0, 2 * std::tan(pi / 6), -2};
  EXPECT_NEAR(t.y / t.w, 1, 1e-15);
}

TEST(Perspective, EqualsTheSymmetricFrustum) {
  const double n = 0.5, f = 30, aspect = 4.0 / 3, top = n * std::tan(40 * pi / 360);
  EXPECT_LT(relative_difference(perspective(40, aspect, n, f),
                                frustum(-top * aspect, top * aspect, -top, top, n, f)),
            1e-14);
}

TEST(Perspective, BadParametersThrow) {
  EXPECT_THROW(perspective(0, 1, 1, 2), usage_error);
  EXPECT_THROW(perspective(180, 1, 1, 2), usage_error);
  EXPECT_THROW(perspective(60, 0, 1, 2), usage_error);
  EXPECT_THROW(perspective(60, 1, 0, 2), usage_error);
  EXPECT_THROW(perspective(60, 1, 2, 2), usage_error);
  EXPECT_THROW(frustum(-1, 1, -1, 1, -1, 2), usage_error);
  EXPECT_THROW(ortho(1, 1, -1, 1, 1, 2), usage_error);
}

TEST(Frustum, ClosedForm) {
  const mat4 m = frustum(-1, 3, -2, 2, 2, 6);
  EXPECT_DOUBLE_EQ(m(0, 0), 1.0);  // 2n/(r-l)
  EXPECT_DOUBLE_EQ(m(0, 2), 0.5);  // (r+l)/(r-l)
  EXPECT_DOUBLE_EQ(m(1, 1), 1.0);  // 2n/(t-b)
  EXPECT_DOUBLE_EQ(m(1, 2), 0.0);
  EXPECT_DOUBLE_EQ(m(2, 2), -2.0);  // -(f+n)/(f-n)
  EXPECT_DOUBLE_EQ(m(2, 3), -6.0);  // -2fn/(f-n)
  EXPECT_EQ(m(3, 2), -1);
  // The window corner (r, t) on the near plane maps to ndc (1, 1, -1).
  const hpoint c = m * point3{3, 2, -2};
  EXPECT_NEAR(c.x / c.w, 1, 1e-15);
  EXPECT_NEAR(c.y / c.w, 1, 1e-15);
  EXPECT_NEAR(c.z / c.w, -1, 1e-15);
}

TEST(Ortho, ClosedForm) {
  const mat4 m = ortho(-2, 6, -1, 3, 1, 9);
  EXPECT_DOUBLE_EQ(m(0, 0), 0.25);
  EXPECT_DOUBLE_EQ(m(0, 3), -0.5);
  EXPECT_DOUBLE_EQ(m(1, 1), 0.5);
  EXPECT_DOUBLE_EQ(m(1, 3), -0.5);
  EXPECT_DOUBLE_EQ(m(2, 2), -0.25);
  EXPECT_DOUBLE_EQ(m(2, 3), -1.25);
  EXPECT_EQ(m(3, 3), 1);
  const hpoint n = m * point3{-2, -1, -1}, f = m * point3{6, 3, -9};
  EXPECT_DOUBLE_EQ(n.x, -1);
  EXPECT_DOUBLE_EQ(n.z, -1);
  EXPECT_DOUBLE_EQ(f.y, 1);
  EXPECT_DOUBLE_EQ(f.z, 1);
}

TEST(Projections, AgreeWithGlmOnRandomInput) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-50, 50), pos(0.01, 20), fov(1, 179), asp(0.1, 10);
  for (int k = 0; k < 500; ++k) {
    double l = u(rng), r = u(rng), b = u(rng), t = u(rng);
    if (l == r || b == t) continue;
    const double n = pos(rng), f = n + pos(rng) * 10;
    EXPECT_LT(relative_difference(ortho(l, r, b, t, n, f), from_glm(glm::ortho(l, r, b, t, n, f))),
              1e-12);
    EXPECT_LT(
        relative_difference(frustum(l, r, b, t, n, f), from_glm(glm::frustum(l, r, b, t, n, f))),
        1e-12);
    const double fovy = fov(rng), aspect = asp(rng);
    EXPECT_LT(relative_difference(perspective(fovy, aspect, n, f),
                                  from_glm(glm::perspective(fovy * pi / 180, aspect, n, f))),
              1e-12);
  }
}

TEST(Oblique, IsAShearComposedWithOrthographic) {
  const vector3 dop{0.3, -0.2, -1};
  const double zp = -7;
  mat4 shear = mat4::identity();
  shear(0, 2) = 0.3;  // -dop.x / dop.z
  shear(1, 2) = -0.2;
  shear(0, 3) = -0.3 * zp;
  shear(1, 3) = 0.2 * zp;
  EXPECT_LT(relative_difference(oblique_shear(dop, zp), shear), 1e-15);
  const mat4 o = ortho(-4, 4, -3, 3, 1, 20);
  EXPECT_LT(relative_difference(oblique(-4, 4, -3, 3, 1, 20, dop, zp), o * shear), 1e-15);
}

TEST(Oblique, ProjectsAlongTheDirectionOfProjection) {
  const vector3 dop{0.5, 0.25, -1};
  const mat4 m = oblique(-4, 4, -3, 3, 1, 20, dop, -5);
  const point3 p{0.7, -0.4, -3};
  const hpoint a = m * p, b = m * (p + 4.0 * dop);
  EXPECT_NEAR(a.x, b.x, 1e-14);  // same image point, different depth
  EXPECT_NEAR(a.y, b.y, 1e-14);
  EXPECT_GT(b.z, a.z);
  // The view plane z = -5 is not sheared: there oblique equals orthographic.
  const hpoint c = m * point3{1, 2, -5}, d = ortho(-4, 4, -3, 3, 1, 20) * point3{1, 2, -5};
  EXPECT_NEAR(c.x, d.x, 1e-15);
  EXPECT_NEAR(c.y, d.y, 1e-15);
  // The view-plane normal as direction of projection gives orthographic.
  EXPECT_LT(
      relative_difference(oblique(-4, 4, -3, 3, 1, 20, {0, 0, -2}, -5), ortho(-4, 4, -3, 3, 1, 20)),
      1e-15);
  EXPECT_THROW(oblique_shear({0, 0, 1}), usage_error);
  EXPECT_THROW(oblique_shear({1, 0, 0}), usage_error);
}

// ---------------------------------------------------------------------------------------
// Viewport

TEST(Viewport, NdcCornersMapToTheWindowCornersLikeOpenGl) {
  const viewport vp{0, 0, 640, 480, 0, 1};
  const window_point lo = to_window(vp, -1, -1, -1), hi = to_window(vp, 1, 1, 1),
                     mid = to_window(vp, 0, 0, 0);
  EXPECT_EQ(lo.x, 0);
  EXPECT_EQ(lo.y, 0);
  EXPECT_EQ(lo.z, 0);
  EXPECT_EQ(hi.x, 640);
  EXPECT_EQ(hi.y, 480);
  EXPECT_EQ(hi.z, 1);
  EXPECT_EQ(mid.x, 320);
  EXPECT_EQ(mid.z, 0.5);
  const viewport off{10, 20, 100, 50, 0, 1};
  const hpoint m = viewport_matrix(off) * hpoint{0.5, -0.5, 0.2, 1};
  const window_point w = to_window(off, 0.5, -0.5, 0.2);
  EXPECT_DOUBLE_EQ(m.x, w.x);
  EXPECT_DOUBLE_EQ(m.y, w.y);
  EXPECT_DOUBLE_EQ(m.z, w.z);
  EXPECT_EQ(w.x, 85);
  EXPECT_EQ(w.y, 32.5);
}

TEST(Viewport, ImageRowZeroIsTheTopWindowRow) {
  EXPECT_EQ(image_row(0, 480), 479);
  EXPECT_EQ(image_row(479, 480), 0);
  image img(4, 3, {0, 0, 0});
  img.set_pixel(1, 2, {9, 8, 7});  // top window row
  EXPECT_EQ(img.at_row(0, 1), (rgb8{9, 8, 7}));
  EXPECT_EQ(img.data()[3 * 1], 9);
}

// ---------------------------------------------------------------------------------------
// Clip stage

TEST(ClipStage, InsideIsUnchangedOutsideIsEmpty) {
  std::vector<hpoint> in{{0, 0, 0, 1}, {0.5, 0, 0, 1}, {0, 0.5, 0.2, 1}}, out;
  clip_to_view_volume(in, out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].x, 0.5);
  in = {{2, 0, 0, 1}, {3, 0, 0, 1}, {2, 1, 0, 1}};
  clip_to_view_volume(in, out);
  EXPECT_TRUE(out.empty());
}

TEST(ClipStage, NearPlaneCutPutsVerticesExactlyOnThePlane) {
  // A perspective triangle reaching behind the eye: clipped before the divide.
  const mat4 p = perspective(60, 1, 1, 10);
  std::vector<hpoint> in{p * point3{0, 0, -5}, p * point3{0.5, 0, 2}, p * point3{0, 0.5, 2}}, out;
  clip_to_view_volume(in, out);
  ASSERT_GE(out.size(), 3u);
  int on_near = 0;
  for (const hpoint& c : out) {
    EXPECT_GT(c.w, 0);
    EXPECT_GE(c.z, -c.w);
    if (c.z == -c.w) ++on_near;
  }
  EXPECT_EQ(on_near, 2);
}

TEST(ClipStage, SharedEdgesGetIdenticalVertices) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int k = 0; k < 300; ++k) {
    const hpoint a{u(rng), u(rng), u(rng), 1}, b{u(rng), u(rng), u(rng), 1},
        c{u(rng), u(rng), u(rng), 1}, d{u(rng), u(rng), u(rng), 1};
    std::vector<hpoint> t1{a, b, c}, t2{b, a, d}, o1, o2;  // share edge ab, opposite directions
    clip_to_view_volume(t1, o1);
    clip_to_view_volume(t2, o2);
    // Every vertex of o1 lying on segment ab (exactly collinear in 4D is hard to test, so use
    // the new vertices created on the edge: both results must contain the same ones).
    auto on_ab = [&](const hpoint& p) {
      const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
      const double t =
          ((p.x - a.x) * dx + (p.y - a.y) * dy + (p.z - a.z) * dz) / (dx * dx + dy * dy + dz * dz);
      if (t < -1e-12 || t > 1 + 1e-12) return false;
      return std::fabs(a.x + t * dx - p.x) < 1e-9 && std::fabs(a.y + t * dy - p.y) < 1e-9 &&
             std::fabs(a.z + t * dz - p.z) < 1e-9;
    };
    std::vector<std::array<double, 4>> e1, e2;
    for (const hpoint& p : o1)
      if (on_ab(p)) e1.push_back({p.x, p.y, p.z, p.w});
    for (const hpoint& p : o2)
      if (on_ab(p)) e2.push_back({p.x, p.y, p.z, p.w});
    std::sort(e1.begin(), e1.end());
    std::sort(e2.begin(), e2.end());
    EXPECT_EQ(e1, e2);
  }
}

// ---------------------------------------------------------------------------------------
// Rasterizer: the top-left rule

TEST(TopLeftRule, SquareSplitAlongADiagonalThroughPixelCentres) {
  // The diagonal x + y = 4 passes through the centres (0.5, 3.5), (1.5, 2.5), ...
  coverage lower(4, 4), upper(4, 4), both(4, 4);
  lower.add({0, 0}, {4, 0}, {0, 4});
  upper.add({4, 0}, {4, 4}, {0, 4});
  both.add({0, 0}, {4, 0}, {0, 4});
  both.add({4, 0}, {4, 4}, {0, 4});
  EXPECT_EQ(lower.total(), 6);   // the diagonal is a right edge of the lower triangle
  EXPECT_EQ(upper.total(), 10);  // and a left edge of the upper one: it owns the centres
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(both.at(i, j), 1) << i << "," << j;
}

TEST(TopLeftRule, HorizontalEdgeThroughCentresBelongsToTheTriangleBelow) {
  coverage above(6, 6), below(6, 6);
  above.add({0, 0.5}, {4, 0.5}, {2, 3});   // edge y = 0.5 is its bottom edge
  below.add({0, 0.5}, {2, -2}, {4, 0.5});  // ... and the top edge of this one
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(above.at(i, 0), 0);
    EXPECT_EQ(below.at(i, 0), 1);
  }
}

TEST(TopLeftRule, VerticalEdgeThroughCentresBelongsToTheTriangleOnTheRight) {
  coverage left(6, 6), right(6, 6);
  left.add({2.5, 0}, {2.5, 6}, {0, 3});
  right.add({2.5, 0}, {5, 3}, {2.5, 6});
  for (int j = 1; j < 5; ++j) {
    EXPECT_EQ(left.at(2, j), 0);
    EXPECT_EQ(right.at(2, j), 1);
  }
}

TEST(TopLeftRule, EitherWindingCoversTheSamePixels) {
  coverage ccw(8, 8), cw(8, 8);
  ccw.add({0.5, 0.5}, {7, 1.5}, {3.5, 6.5});
  cw.add({0.5, 0.5}, {3.5, 6.5}, {7, 1.5});
  EXPECT_EQ(ccw.count, cw.count);
  EXPECT_GT(ccw.total(), 0);
}

TEST(TopLeftRule, DegenerateAndOffscreenTriangles) {
  coverage c(8, 8);
  c.add({0.5, 0.5}, {3.5, 3.5}, {7.5, 7.5});  // collinear through centres: zero area
  EXPECT_EQ(c.total(), 0);
  c.add({-100, -100}, {-50, -100}, {-100, -50});
  EXPECT_EQ(c.total(), 0);
  c.add({-1e300, -1e300}, {1e300, -1e300}, {0, 1e300});  // covers everything
  EXPECT_EQ(c.total(), 64);
  c.add({0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}, {0, 1});
  EXPECT_EQ(c.total(), 64);
}

TEST(TopLeftRule, ExactOrientationIsAntisymmetric) {
  // Nearly collinear points where the naive determinant is unreliable.
  const double a = 0.5 + 0x1p-52, b = 12.0, c = 24.0 - 0x1p-49;
  EXPECT_EQ(orient2d(0.5, 0.5, b, b, c, c + 0x1p-49), -orient2d(b, b, 0.5, 0.5, c, c + 0x1p-49));
  EXPECT_EQ(orient2d_exact(a, a, b, b, c, c), -orient2d_exact(b, b, a, a, c, c));
  EXPECT_EQ(orient2d(0, 0, 1, 1, 3, 3), 0);
  EXPECT_EQ(orient2d(0, 0, 1, 0, 0, 1), 1);
}

// A convex quad on the half-pixel grid, split along either diagonal: no pixel is painted twice,
// every pixel centre strictly inside the quad is painted exactly once, and centres on the
// quad's boundary follow the boundary edge's own top-left rule, whichever the split.
RC_GTEST_PROP(TopLeftRule, QuadSplitEitherWayPaintsEachInteriorPixelOnce, ()) {
  const int n = 10;
  std::array<point2, 4> q;
  for (auto& p : q) p = {half_grid(n), half_grid(n)};
  // Order the points counter-clockwise around their centroid; keep strictly convex quads.
  const double cx = (q[0].x + q[1].x + q[2].x + q[3].x) / 4,
               cy = (q[0].y + q[1].y + q[2].y + q[3].y) / 4;
  std::sort(q.begin(), q.end(), [&](const point2& a, const point2& b) {
    return std::atan2(a.y - cy, a.x - cx) < std::atan2(b.y - cy, b.x - cx);
  });
  for (int k = 0; k < 4; ++k) RC_PRE(orient(q[k], q[(k + 1) % 4], q[(k + 2) % 4]) > 0);
  coverage s1(n, n), s2(n, n);
  s1.add(q[0], q[1], q[2]);
  s1.add(q[0], q[2], q[3]);
  s2.add(q[1], q[2], q[3]);
  s2.add(q[1], q[3], q[0]);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      RC_ASSERT(s1.at(i, j) <= 1);
      RC_ASSERT(s2.at(i, j) <= 1);
      const point2 p = centre(i, j);
      bool strictly_inside = true, on_boundary_owned = true, on_vertex = false;
      int on_edges = 0;
      for (int k = 0; k < 4; ++k) {
        const point2 &s = q[k], &t = q[(k + 1) % 4];
        const int o = orient(s, t, p);
        if (o < 0) strictly_inside = on_boundary_owned = false;
        if (o == 0) {
          strictly_inside = false;
          ++on_edges;
          if (!(t.y < s.y || (t.y == s.y && t.x < s.x))) on_boundary_owned = false;
        }
        if (p.x == s.x && p.y == s.y) on_vertex = true;
      }
      if (strictly_inside) {
        RC_ASSERT(s1.at(i, j) == 1);
        RC_ASSERT(s2.at(i, j) == 1);
      } else if (on_edges == 1 && !on_vertex) {
        const int expected = on_boundary_owned ? 1 : 0;
        RC_ASSERT(s1.at(i, j) == expected);
        RC_ASSERT(s2.at(i, j) == expected);
      } else if (on_edges == 0) {
        RC_ASSERT(s1.at(i, j) == 0);
        RC_ASSERT(s2.at(i, j) == 0);
      }
    }
}

// Two triangles sharing an edge, on opposite sides of it, with random windings: no pixel is
// painted twice and every centre on the shared edge strictly between its end points is
// painted exactly once.
RC_GTEST_PROP(TopLeftRule, SharedEdgeIsPaintedExactlyOnce, ()) {
  const int n = 12;
  const point2 a{half_grid(n), half_grid(n)}, b{half_grid(n), half_grid(n)};
  const point2 c{half_grid(n), half_grid(n)}, d{half_grid(n), half_grid(n)};
  RC_PRE(orient(a, b, c) * orient(a, b, d) < 0);
  coverage cov(n, n);
  if (*rc::gen::arbitrary<bool>())
    cov.add(a, b, c);
  else
    cov.add(b, a, c);
  if (*rc::gen::arbitrary<bool>())
    cov.add(b, a, d);
  else
    cov.add(a, b, d);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      RC_ASSERT(cov.at(i, j) <= 1);
      const point2 p = centre(i, j);
      const bool on_open_edge = orient(a, b, p) == 0 &&
                                (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y) > 0 &&
                                (p.x - b.x) * (a.x - b.x) + (p.y - b.y) * (a.y - b.y) > 0;
      // Strictly inside the union near the edge: the other edges must not pass through p.
      if (on_open_edge && orient(a, c, p) != 0 && orient(b, c, p) != 0 && orient(a, d, p) != 0 &&
          orient(b, d, p) != 0) {
        // p is inside the union iff it is inside the quad a-c-b-d; it is on ab, so inside.
        RC_ASSERT(cov.at(i, j) == 1);
      }
    }
}

// A closed fan of triangles around a vertex that sits exactly on a pixel centre: every pixel
// strictly inside the fan's outline, including the centre vertex's pixel and pixels on the
// spokes, is painted exactly once.
RC_GTEST_PROP(TopLeftRule, FanAroundAVertexPaintsEachPixelOnce, ()) {
  const int n = 16;
  const point2 v{8.5, 7.5};
  const int k = uniform_int(3, 9);
  // Outer vertices at increasing angles (gaps < 180 degrees), radius 3..7, on the half grid.
  std::vector<double> angles;
  for (int t = 0; t < k; ++t) angles.push_back((t + uniform_int(0, 60) / 100.0) * (2 * pi / k));
  std::vector<point2> outer;
  for (double ang : angles) {
    const double r = uniform_int(6, 14) / 2.0;
    outer.push_back({std::round(2 * (v.x + r * std::cos(ang))) / 2,
                     std::round(2 * (v.y + r * std::sin(ang))) / 2});
  }
  for (int t = 0; t < k; ++t) RC_PRE(orient(v, outer[t], outer[(t + 1) % k]) > 0);
  coverage cov(n, n);
  for (int t = 0; t < k; ++t) {
    if (*rc::gen::arbitrary<bool>())
      cov.add(v, outer[t], outer[(t + 1) % k]);
    else
      cov.add(v, outer[(t + 1) % k], outer[t]);
  }
  RC_ASSERT(cov.at(8, 7) == 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      RC_ASSERT(cov.at(i, j) <= 1);
      const point2 p = centre(i, j);
      // Strictly inside the outline: inside or on a spoke of some triangle, never on an
      // outer edge.
      bool on_outer = false, inside = false;
      for (int t = 0; t < k; ++t) {
        const point2 &s = outer[t], &e = outer[(t + 1) % k];
        const int o_outer = orient(s, e, p);
        if (o_outer == 0 && (p.x - s.x) * (e.x - s.x) + (p.y - s.y) * (e.y - s.y) >= 0 &&
            (p.x - e.x) * (s.x - e.x) + (p.y - e.y) * (s.y - e.y) >= 0)
          on_outer = true;
        if (orient(v, s, p) >= 0 && orient(s, e, p) > 0 && orient(e, v, p) >= 0) inside = true;
      }
      if (inside && !on_outer) RC_ASSERT(cov.at(i, j) == 1);
    }
}

// ---------------------------------------------------------------------------------------
// Painter's algorithm on a cyclic overlap: the BSP order against a z-buffer oracle

/// Three planks in cyclic overlap seen from +z (the demo's construction).
triangle_soup cyclic_planks() {
  triangle_soup s;
  for (int i = 0; i < 3; ++i) {
    const double a = i * (2 * pi / 3), ux = std::cos(a), uy = std::sin(a), nx = -uy, ny = ux;
    const double cx = -0.75 * nx, cy = -0.75 * ny;
    std::vector<std::uint32_t> quad;
    for (auto [t, w] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
      quad.push_back(static_cast<std::uint32_t>(s.vertices.size()));
      s.vertices.push_back(
          {cx + 2.1 * t * ux + 0.3 * w * nx, cy + 2.1 * t * uy + 0.3 * w * ny, 0.25 * 2.1 * t});
    }
    s.add_polygon(quad, static_cast<std::uint32_t>(i));
  }
  return s;
}

frame cyclic_frame(int width, int height) {
  frame f;
  f.soup = cyclic_planks();
  f.face_colors = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  f.background = {255, 255, 255};
  f.view.kind = projection_kind::perspective;
  f.view.cam = {{0.3, -2.0, 8.0}, {0, 0, 0}, {0, 1, 0}};
  f.view.model_view = look_at(f.view.cam);
  f.view.projection = perspective(45, static_cast<double>(width) / height, 1, 30);
  f.view.vp = {0, 0, width, height, 0, 1};
  return f;
}

using exbsp_test::zbuffer_render;

int mismatches(const image& a, const image& b) {
  int n = 0;
  for (int r = 0; r < a.height(); ++r)
    for (int c = 0; c < a.width(); ++c)
      if (a.at_row(r, c) != b.at_row(r, c)) ++n;
  return n;
}

TEST(Painter, CyclicOverlapMatchesAZBufferOracle) {
  frame f = cyclic_frame(300, 300);
  pipeline p = standard_pipeline({}, output_kind::png);
  p.run(f, nullptr);
  ASSERT_TRUE(f.tree.has_value());
  EXPECT_GT(f.tree->stats().splits, 0u);  // no order of the three planks exists: one is split
  const image oracle = zbuffer_render(f);
  // All three colours visible, and at most a handful of pixels differ (T-junctions of split
  // fragments land on rounded points; pixels with centres exactly there may differ).
  EXPECT_EQ(exbsp_test::colours_of(f.picture).size(), 4u);
  EXPECT_LE(mismatches(f.picture, oracle), 3);

  // A depth sort by centroid (what a BSP replaces) cannot get a cyclic overlap right.
  frame g = cyclic_frame(300, 300);
  g.fragments.clear();
  for (const soup_triangle& t : g.soup.triangles)
    g.fragments.push_back(
        {t.face, {g.soup.vertices[t.v[0]], g.soup.vertices[t.v[1]], g.soup.vertices[t.v[2]]}});
  g.order.clear();
  for (std::uint32_t k = 0; k < g.fragments.size(); ++k) g.order.push_back(k);
  auto eye_distance = [&](std::uint32_t k) {
    point3 c{0, 0, 0};
    for (const vec3d& v : g.fragments[k].v) c = c + (1.0 / 3) * vector3{v[0], v[1], v[2]};
    return length(c - g.view.cam.eye);
  };
  std::sort(g.order.begin(), g.order.end(),
            [&](auto a, auto b) { return eye_distance(a) > eye_distance(b); });
  transform_clip_stage(g);
  raster_stage(g);
  EXPECT_GT(mismatches(g.picture, oracle), 100);
}

TEST(Painter, OrderFollowsTheBspForParallelViews) {
  frame f = cyclic_frame(200, 200);
  f.view.kind = projection_kind::orthographic;
  f.view.projection = ortho(-3, 3, -3, 3, 1, 30);
  f.view.direction = gaze_direction(f.view.cam);
  build_stage(f);
  order_stage(f);
  EXPECT_EQ(f.order, f.tree->order_for_direction(
                         {f.view.direction.x, f.view.direction.y, f.view.direction.z}));
  transform_clip_stage(f);
  raster_stage(f);
  EXPECT_LE(mismatches(f.picture, zbuffer_render(f)), 3);
}

// ---------------------------------------------------------------------------------------
// Backface culling

triangle_soup unit_cube() {
  triangle_soup s;
  for (int k = 0; k < 8; ++k)
    s.vertices.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
  const std::vector<std::vector<std::uint32_t>> faces{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                      {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (std::uint32_t f = 0; f < faces.size(); ++f) s.add_polygon(faces[f], f);
  return s;
}

TEST(BackfaceCulling, KeepsOnlyFacesTowardsTheViewer) {
  frame f;
  f.soup = unit_cube();
  f.view.kind = projection_kind::perspective;
  f.view.cam = {{5, 4, 3}, {0, 0, 0}, {0, 0, 1}};  // sees the +x, +y and +z faces
  build_stage(f);
  order_stage(f);
  ASSERT_EQ(f.order.size(), 12u);
  backface_culling_stage(f);
  EXPECT_EQ(f.culled, 6u);
  std::set<std::uint32_t> faces;
  for (std::uint32_t k : f.order) faces.insert(f.fragments[k].face);
  EXPECT_EQ(faces, (std::set<std::uint32_t>{1, 3, 5}));

  // Parallel view along -z (from above): only the top face (+z) is kept.
  f.view.kind = projection_kind::orthographic;
  f.view.direction = {0, 0, -1};
  order_stage(f);
  backface_culling_stage(f);
  faces.clear();
  for (std::uint32_t k : f.order) faces.insert(f.fragments[k].face);
  EXPECT_EQ(faces, (std::set<std::uint32_t>{1}));
  // Edge-on faces (N . V = 0) are culled too.
  EXPECT_EQ(f.culled, 10u);
}

// ---------------------------------------------------------------------------------------
// PNG and SVG output

/// Reads a PNG with libpng's simplified API (independent of view::read_png).
bool libpng_read(const std::string& path, int& w, int& h, std::vector<std::uint8_t>& rgb) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str())) return false;
  img.format = PNG_FORMAT_RGB;
  rgb.assign(PNG_IMAGE_SIZE(img), 0);
  if (!png_image_finish_read(&img, nullptr, rgb.data(), 0, nullptr)) return false;
  w = static_cast<int>(img.width);
  h = static_cast<int>(img.height);
  return true;
}

TEST(Png, RoundTripThroughLibpng) {
  image img(37, 23, {10, 20, 30});
  std::mt19937 rng(3);
  for (int r = 0; r < 23; ++r)
    for (int c = 0; c < 37; ++c)
      img.set_at_row(r, c,
                     {static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                      static_cast<std::uint8_t>(rng())});
  img.set_pixel(0, 22, {1, 2, 3});  // window (0, 22) = top-left = PNG row 0
  const std::string path = temp_dir() + "/round_trip.png";
  write_png(img, path);
  int w = 0, h = 0;
  std::vector<std::uint8_t> rgb;
  ASSERT_TRUE(libpng_read(path, w, h, rgb));
  EXPECT_EQ(w, 37);
  EXPECT_EQ(h, 23);
  EXPECT_EQ(rgb, img.data());
  EXPECT_EQ(rgb[0], 1);
  EXPECT_EQ(rgb[2], 3);
  const image back = read_png(path);
  EXPECT_EQ(back.data(), img.data());
}

TEST(Png, ReadingAnInvalidFileThrowsInputError) {
  const std::string path = temp_dir() + "/not_a_png.png";
  std::ofstream(path) << "hello";
  EXPECT_THROW(read_png(path), input_error);
  EXPECT_THROW(read_png(temp_dir() + "/missing.png"), input_error);
}

TEST(AtomicWrite, FailureLeavesNoFileAndKeepsTheOldOne) {
  const std::string dir = temp_dir() + "/atomic";
  std::filesystem::create_directories(dir);
  EXPECT_THROW(write_file_atomically(dir + "/no/such/dir/out.png", "x"), exbsp::output_error);
  const std::string path = dir + "/out.txt";
  write_file_atomically(path, "first");
  write_file_atomically(path, "second");
  std::ifstream in(path);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "second");
  // A directory in the way: rename fails, the temporary file is removed.
  std::filesystem::create_directories(dir + "/blocked");
  EXPECT_THROW(write_file_atomically(dir + "/blocked", "x"), exbsp::output_error);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(Svg, OnePathPerVisibleFragmentInBackToFrontOrder) {
  frame f = cyclic_frame(320, 240);
  f.view.vp = {0, 0, 320, 240, 0, 1};
  // Move the camera so that some fragments are fully clipped (outside the view).
  f.view.projection = perspective(20, 320.0 / 240, 1, 30);
  f.vector.mode =
      vector_options::mode_kind::painter;  // the painter's stack (the default is visible regions)
  pipeline p = standard_pipeline({}, output_kind::svg);
  p.run(f, nullptr);
  ASSERT_FALSE(f.polygons.empty());
  const std::string& svg = f.svg;
  EXPECT_NE(svg.find("viewBox=\"0 0 320 240\""), std::string::npos);
  // Each polygon is <path data-face="F" data-fragment="K" fill="#rrggbb" stroke="#rrggbb" d="..."/>
  // with the stroke equal to the fill. (Parsed by hand: GCC 12's <regex> trips
  // -Wmaybe-uninitialized in the sanitizer build.)
  auto attribute = [](const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const std::size_t at = tag.find(key);
    if (at == std::string::npos) return std::string("(missing)");
    const std::size_t begin = at + key.size();
    return tag.substr(begin, tag.find('"', begin) - begin);
  };
  std::vector<std::uint32_t> fragments;
  std::vector<std::string> ds;
  for (std::size_t at = svg.find("<path data-face=\""); at != std::string::npos;
       at = svg.find("<path data-face=\"", at + 1)) {
    const std::string tag = svg.substr(at, svg.find("/>", at) + 2 - at);
    const std::string fill = attribute(tag, "fill");
    ASSERT_EQ(fill.size(), 7u) << tag;
    EXPECT_EQ(fill[0], '#');
    EXPECT_EQ(fill.find_first_not_of("0123456789abcdef", 1), std::string::npos) << tag;
    EXPECT_EQ(attribute(tag, "stroke"), fill) << tag;
    std::stoul(attribute(tag, "data-face"));
    fragments.push_back(static_cast<std::uint32_t>(std::stoul(attribute(tag, "data-fragment"))));
    ds.push_back(attribute(tag, "d"));
  }
  std::vector<std::uint32_t> expected;
  for (const screen_polygon& poly : f.polygons) expected.push_back(poly.fragment);
  EXPECT_EQ(fragments, expected);
  // Visible fragments keep the back-to-front order of the BSP (a subsequence of it).
  const auto full = f.tree->order_from_eye(to_vec3d(f.view.cam.eye));
  std::size_t pos = 0;
  for (std::uint32_t k : fragments) {
    while (pos < full.size() && full[pos] != k) ++pos;
    ASSERT_LT(pos, full.size()) << "fragment " << k << " out of order";
  }
  EXPECT_EQ(full.size(), f.polygons.size() + f.fully_clipped);
  // The first path's points are the window coordinates with y flipped.
  std::istringstream d(ds.front());
  std::string cmd;
  double x, y;
  d >> cmd;
  ASSERT_EQ(cmd.substr(0, 1), "M");
  x = std::stod(cmd.substr(1));
  d >> y;
  EXPECT_DOUBLE_EQ(x, f.polygons.front().v[0].x);
  EXPECT_DOUBLE_EQ(y, 240 - f.polygons.front().v[0].y);
}

TEST(Svg, EmptySceneHasOnlyTheBackground) {
  const std::string svg = svg_document({0, 0, 10, 20, 0, 1}, {1, 2, 3}, {});
  EXPECT_NE(svg.find("fill=\"#010203\""), std::string::npos);
  EXPECT_EQ(svg.find("<path"), std::string::npos);
}

// ---------------------------------------------------------------------------------------
// Stage lists and effects

TEST(Pipeline, OnlyTheRequestedStagesRun) {
  EXPECT_EQ(standard_pipeline({}, output_kind::png).names(),
            (std::vector<std::string>{"build", "order", "transform+clip", "raster"}));
  EXPECT_EQ(standard_pipeline({}, output_kind::svg).names(),
            (std::vector<std::string>{"build", "order", "transform+clip", "svg"}));
  EXPECT_EQ(
      standard_pipeline({"backface_culling"}, output_kind::png).names(),
      (std::vector<std::string>{"build", "order", "backface_culling", "transform+clip", "raster"}));
  EXPECT_THROW(standard_pipeline({"sparkle"}, output_kind::png), usage_error);
  ASSERT_NE(find_effect("antialias"), nullptr);
  EXPECT_TRUE(find_effect("antialias")->available);
  // Each effect at its hook; antialias replaces raster; PNG-only effects have no SVG stage.
  EXPECT_EQ(
      standard_pipeline({"depth_of_field", "fog", "antialias", "lighting", "backface_culling"},
                        output_kind::png, true)
          .names(),
      (std::vector<std::string>{"build", "order", "backface_culling", "lighting", "transform+clip",
                                "curves", "fog", "antialias", "depth_of_field"}));
  EXPECT_EQ(standard_pipeline({"depth_of_field", "fog", "antialias"}, output_kind::svg).names(),
            (std::vector<std::string>{"build", "order", "transform+clip", "fog", "svg"}));
}

TEST(Pipeline, VerboseLogNamesEveryStage) {
  frame f = cyclic_frame(50, 50);
  pipeline p = standard_pipeline({}, output_kind::png);
  p.insert_after("order", "probe",
                 [](frame& fr) { return std::to_string(fr.order.size()) + " seen"; });
  std::ostringstream log;
  p.run(f, &log);
  const std::string s = log.str();
  for (const char* name :
       {"stage build:", "stage order:", "stage probe:", "stage transform+clip:", "stage raster:"})
    EXPECT_NE(s.find(name), std::string::npos) << name;
  EXPECT_LT(s.find("stage order:"), s.find("stage probe:"));
  EXPECT_THROW(p.insert_after("nothing", "x", [](frame&) { return std::string(); }), usage_error);
}

TEST(Pipeline, EmptySceneRendersTheBackground) {
  frame f = cyclic_frame(20, 10);
  f.soup = triangle_soup{};
  f.background = {7, 8, 9};
  standard_pipeline({}, output_kind::png).run(f, nullptr);
  EXPECT_EQ(f.picture.width(), 20);
  EXPECT_EQ(f.picture.at_row(3, 3), (rgb8{7, 8, 9}));
}

TEST(Pipeline, CameraInsideTheModelIsCutByTheNearPlane) {
  frame f;
  f.soup = unit_cube();
  f.face_colors.assign(6, {200, 0, 0});
  f.view.kind = projection_kind::perspective;
  f.view.cam = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}};  // at the cube's centre
  f.view.model_view = look_at(f.view.cam);
  f.view.projection = perspective(90, 1, 0.1, 10);
  f.view.vp = {0, 0, 64, 64, 0, 1};
  standard_pipeline({}, output_kind::png).run(f, nullptr);
  // The walls around and behind the eye are clipped, the image is full of wall.
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < 64; ++c) ASSERT_EQ(f.picture.at_row(r, c), (rgb8{200, 0, 0}));
  EXPECT_GT(f.fully_clipped, 0u);
  for (const screen_polygon& p : f.polygons)
    for (const window_point& w : p.v) {
      EXPECT_GE(w.z, 0);
      EXPECT_LE(w.z, 1);
    }
}

}  // namespace

// ---- <exbsp/view/render.h>: the one-call render and the fitted view ----

#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/render.h>
#include "support/cli_support.h"

namespace {

class RenderSoup : public exbsp_test::cli_fixture {};

// render_soup is `exbsp render MESH --view V --size WxH` as a library call: the same pixels.
TEST_F(RenderSoup, paints_the_pixels_of_exbsp_render_for_every_fitted_view) {
  const std::string mesh = std::string(EXBSP_TEST_DATA) + "/cube.off";
  const exbsp::triangle_soup soup = exbsp::read_mesh(mesh);
  for (const std::string& name : exbsp::view::fitted_view_names()) {
    SCOPED_TRACE(name);
    const auto r = run("render " + exbsp_test::quoted(mesh) + " --view " + name +
                       " --size 160x120 -q -o cli.png");
    ASSERT_EQ(r.status, 0) << r.err;
    exbsp::view::render_options o;
    o.width = 160;
    o.height = 120;
    o.view = name;
    const exbsp::view::render_result got = exbsp::view::render_soup(soup, o);
    const exbsp::view::image want = exbsp::view::read_png((dir / "cli.png").string());
    ASSERT_EQ(got.picture.width(), want.width());
    ASSERT_EQ(got.picture.height(), want.height());
    EXPECT_TRUE(got.picture.data() == want.data());
    EXPECT_EQ(got.order.size(), got.tree.fragment_count());
    EXPECT_EQ(got.view.cam.up.y, name == "top" || name == "bottom" ? 0.0 : 1.0);
    // The tree's SVG: the document `exbsp render MESH -o X.svg` writes, byte for byte.
    const auto svg = run("render " + exbsp_test::quoted(mesh) + " --view " + name +
                         " --size 160x120 -q -o cli.svg");
    ASSERT_EQ(svg.status, 0) << svg.err;
    EXPECT_EQ(exbsp::view::render_tree_svg(got.tree, got.view, 160, 120),
              exbsp_test::read_file(dir / "cli.svg"));
  }
}

TEST(FittedView, sees_the_whole_bounding_sphere_and_refuses_what_it_cannot_fit) {
  exbsp::triangle_soup soup;
  soup.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 4, 0}, {0, 0, 6}};
  soup.triangles = {{{0, 1, 2}, 0}, {{0, 1, 3}, 1}};
  soup.face_count = 2;
  soup.source = "tetra.off";
  const exbsp::view::fitted_view v = exbsp::view::fit_view(soup, 400, 300, "front");
  // The centre of the box, and the eye on +z from it (front), beyond the far side of the sphere.
  EXPECT_EQ(v.cam.look_at.x, 1);
  EXPECT_EQ(v.cam.look_at.y, 2);
  EXPECT_EQ(v.cam.look_at.z, 3);
  EXPECT_EQ(v.cam.eye.x, 1);
  EXPECT_EQ(v.cam.eye.y, 2);
  const double r = std::sqrt(1.0 + 4.0 + 9.0);
  EXPECT_GT(v.near_dist, 0);
  EXPECT_NEAR(v.far_dist - v.near_dist, 2.02 * r, 1e-9);
  EXPECT_NEAR((v.cam.eye.z - 3) * std::sin(15 * std::acos(-1.0) / 180), 1.08 * r, 1e-9);
  EXPECT_THROW(exbsp::view::fit_view(soup, 400, 300, "sideways"), exbsp::usage_error);
  EXPECT_THROW(exbsp::view::fit_view(soup, 0, 300), exbsp::usage_error);
  exbsp::triangle_soup empty;
  empty.source = "empty.off";
  try {
    exbsp::view::fit_view(empty, 10, 10);
    ADD_FAILURE() << "no error";
  } catch (const exbsp::input_error& e) {
    EXPECT_NE(std::string(e.what()).find("empty.off"), std::string::npos) << e.what();
  }
  soup.vertices = {{-1e308, 0, 0}, {1e308, 0, 0}, {0, 1e308, 0}};
  soup.triangles = {{{0, 1, 2}, 0}};
  EXPECT_THROW(exbsp::view::fit_view(soup, 10, 10), exbsp::input_error);
}

TEST(Headlight, lights_faces_facing_the_eye_fully_and_edge_on_faces_by_the_ambient_quarter) {
  exbsp::triangle_soup soup;
  // Face 0 faces +z (towards the eye), face 1 lies in a plane containing the gaze, face 2 is
  // degenerate.
  soup.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 2, 2}};
  soup.triangles = {{{0, 1, 2}, 0}, {{0, 1, 3}, 1}, {{0, 4, 4}, 2}};
  soup.face_count = 3;
  const exbsp::view::camera cam{{0, 0, 10}, {0, 0, 0}, {0, 1, 0}};
  const auto colors = exbsp::view::headlight_colors(soup, cam, {200, 100, 40});
  ASSERT_EQ(colors.size(), 3u);
  EXPECT_EQ(colors[0], (exbsp::view::rgb8{200, 100, 40}));
  EXPECT_EQ(colors[1], (exbsp::view::rgb8{50, 25, 10}));
  EXPECT_EQ(colors[2], (exbsp::view::rgb8{50, 25, 10}));
}

}  // namespace
