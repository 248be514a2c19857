// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of include/exbsp/view/trackball.h: unit quaternions, Shoemake's arcball, camera orbit.
// Notation: q = (w, x, y, z); rotation v' = q v q*; arcball drag p -> q is (p.q, p x q), which
// turns by twice the arc from p to q, so it maps p to 2 (p.q) q - p. Eye coordinates: x right,
// y up, z towards the viewer. q and -q are the same rotation: "same_rotation" compares up to sign.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/view/trackball.h>
#include "support/test_helpers.h"

namespace {

using exbsp::arcball;
using exbsp::quaternion;
using exbsp::screen_y;
using exbsp::vec2d;
using exbsp::vec3d;

using exbsp_test::cross;
using exbsp_test::dist;
using exbsp_test::dot;
using exbsp_test::norm;
using exbsp_test::scale;
using exbsp_test::sub;
using exbsp_test::unit;

[[maybe_unused]] const bool fixed_seed = exbsp_test::fixed_rc_seed();

const double pi = 3.14159265358979323846;

double qdist(const quaternion& a, const quaternion& b) {
  return std::sqrt((a.w - b.w) * (a.w - b.w) + (a.x - b.x) * (a.x - b.x) +
                   (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}
/// Distance between rotations: quaternions compared up to sign.
double rotation_distance(const quaternion& a, const quaternion& b) {
  return std::min(qdist(a, b), qdist(a, quaternion{-b.w, -b.x, -b.y, -b.z}));
}

// --- generators (called inside properties) ---
double random_unit_interval() { return *rc::gen::inRange(0, 1000001) / 1e6; }
/// A screen point in a 640 x 480 viewport, sometimes outside the ball or the viewport.
vec2d random_screen_point() {
  return {*rc::gen::inRange(-100000, 740001) / 1000.0, *rc::gen::inRange(-100000, 580001) / 1000.0};
}
vec3d random_nonzero_vector() {
  vec3d v;
  do {
    v = {*rc::gen::inRange(-1000, 1001) / 100.0, *rc::gen::inRange(-1000, 1001) / 100.0,
         *rc::gen::inRange(-1000, 1001) / 100.0};
  } while (norm(v) < 1e-3);
  return v;
}
quaternion random_rotation() {
  return exbsp::from_axis_angle(random_nonzero_vector(), *rc::gen::inRange(-7000, 7001) / 1000.0);
}

// --- quaternion algebra ---

RC_GTEST_PROP(Quaternion, ProductComposesRotationsRightToLeft, ()) {
  const quaternion a = random_rotation(), b = random_rotation();
  const vec3d v = random_nonzero_vector();
  const vec3d once = exbsp::rotate(a * b, v);
  const vec3d twice = exbsp::rotate(a, exbsp::rotate(b, v));
  RC_ASSERT(dist(once, twice) <= 1e-13 * norm(v));
  RC_ASSERT(std::fabs(norm(once) - norm(v)) <= 1e-13 * norm(v));
}

RC_GTEST_PROP(Quaternion, MatrixAgreesWithRotationAndIsOrthonormal, ()) {
  const quaternion q = random_rotation();
  const std::array<double, 9> m = exbsp::to_matrix3(q);
  const vec3d v = random_nonzero_vector();
  const vec3d mv{m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
                 m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
  RC_ASSERT(dist(mv, exbsp::rotate(q, v)) <= 1e-13 * norm(v));
  const vec3d r0{m[0], m[1], m[2]}, r1{m[3], m[4], m[5]}, r2{m[6], m[7], m[8]};
  RC_ASSERT(std::fabs(dot(r0, r0) - 1.0) <= 1e-14);
  RC_ASSERT(std::fabs(dot(r1, r1) - 1.0) <= 1e-14);
  RC_ASSERT(std::fabs(dot(r0, r1)) <= 1e-14);
  RC_ASSERT(std::fabs(dot(cross(r0, r1), r2) - 1.0) <= 1e-14);  // det = +1
  const std::array<double, 16> h = exbsp::to_matrix4(q);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) RC_ASSERT(h[4 * i + j] == m[3 * i + j]);
    RC_ASSERT(h[4 * i + 3] == 0.0);
    RC_ASSERT(h[12 + i] == 0.0);
  }
  RC_ASSERT(h[15] == 1.0);
}

TEST(TrackballName, OnlyTheTwoNamesAreKnown) {
  EXPECT_FALSE(exbsp::trackball_named(""));
  EXPECT_FALSE(exbsp::trackball_named("Arcball"));  // names are case-sensitive, as JSON keys
  EXPECT_FALSE(exbsp::trackball_named("virtual_"));
  EXPECT_EQ(exbsp::trackball_named("arcball"), exbsp::trackball_kind::arcball);
  EXPECT_EQ(exbsp::trackball_named("virtual"), exbsp::trackball_kind::virtual_);
}

TEST(Quaternion, QuarterTurnAboutZMapsXToY) {
  const quaternion q = exbsp::from_axis_angle({0, 0, 2}, pi / 2);
  const vec3d r = exbsp::rotate(q, {1, 0, 0});
  EXPECT_NEAR(r[0], 0.0, 1e-15);
  EXPECT_NEAR(r[1], 1.0, 1e-15);
  EXPECT_NEAR(r[2], 0.0, 1e-15);
}

RC_GTEST_PROP(Quaternion, AxisAngleRoundTripsAndAngleIsInZeroToPi, ()) {
  const quaternion q = random_rotation();
  const exbsp::axis_angle aa = exbsp::to_axis_angle(q);
  RC_ASSERT(aa.angle >= 0.0);
  RC_ASSERT(aa.angle <= pi);
  RC_ASSERT(std::fabs(norm(aa.axis) - 1.0) <= 1e-14);
  RC_ASSERT(rotation_distance(exbsp::from_axis_angle(aa.axis, aa.angle), q) <= 1e-13);
}

TEST(Quaternion, IdentityHasZeroAngleAndDefaultAxis) {
  const exbsp::axis_angle aa = exbsp::to_axis_angle(quaternion{});
  EXPECT_EQ(aa.angle, 0.0);
  EXPECT_EQ(aa.axis, (vec3d{0, 0, 1}));
  const exbsp::axis_angle negated = exbsp::to_axis_angle(quaternion{-1, 0, 0, 0});
  EXPECT_EQ(negated.angle, 0.0);
}

RC_GTEST_PROP(Quaternion, SlerpHitsEndPointsWithConstantAngularSpeed, ()) {
  const quaternion a = random_rotation(), b = random_rotation();
  const double t = random_unit_interval();
  RC_ASSERT(rotation_distance(exbsp::slerp(a, b, 0.0), a) <= 1e-14);
  RC_ASSERT(rotation_distance(exbsp::slerp(a, b, 1.0), b) <= 1e-14);
  const quaternion s = exbsp::slerp(a, b, t);
  RC_ASSERT(std::fabs(exbsp::norm(s) - 1.0) <= 1e-15);
  // Rotation angle from a to s is t times the angle from a to b.
  const double total = exbsp::to_axis_angle(exbsp::conjugate(a) * b).angle;
  const double part = exbsp::to_axis_angle(exbsp::conjugate(a) * s).angle;
  RC_ASSERT(std::fabs(part - t * total) <= 1e-9);
}

TEST(Quaternion, SlerpOfNearlyEqualRotationsIsFinite) {
  const quaternion a = exbsp::from_axis_angle({1, 2, 3}, 0.5);
  const quaternion b = exbsp::from_axis_angle({1, 2, 3}, 0.5 + 1e-12);
  const quaternion s = exbsp::slerp(a, b, 0.5);
  EXPECT_NEAR(exbsp::norm(s), 1.0, 1e-15);
  EXPECT_LE(rotation_distance(s, a), 1e-12);
  EXPECT_LE(rotation_distance(exbsp::slerp(a, a, 0.3), a), 1e-15);
}

TEST(Quaternion, InvalidInputThrowsUsageError) {
  const double nan = std::nan("");
  EXPECT_THROW(exbsp::normalize(quaternion{0, 0, 0, 0}), exbsp::usage_error);
  EXPECT_THROW(exbsp::normalize(quaternion{nan, 0, 0, 0}), exbsp::usage_error);
  EXPECT_THROW(exbsp::from_axis_angle({0, 0, 0}, 1.0), exbsp::usage_error);
  EXPECT_THROW(exbsp::from_axis_angle({1, 0, 0}, nan), exbsp::usage_error);
  EXPECT_THROW(exbsp::rotate(quaternion{}, {nan, 0, 0}), exbsp::usage_error);
  EXPECT_THROW(exbsp::slerp(quaternion{}, quaternion{}, nan), exbsp::usage_error);
  EXPECT_THROW(exbsp::arcball_rotation({0, 0, 0}, {1, 0, 0}), exbsp::usage_error);
}

TEST(Quaternion, NormIsOverflowSafe) {
  const double big = 1e300;
  EXPECT_DOUBLE_EQ(exbsp::norm(quaternion{big, big, big, big}), 2e300);
  const quaternion n = exbsp::normalize(quaternion{big, big, big, big});
  EXPECT_DOUBLE_EQ(n.w, 0.5);
}

// --- arcball ---

RC_GTEST_PROP(Arcball, SpherePointIsOnUnitSphereFacingTheViewer, ()) {
  const arcball ball(640, 480);
  const vec2d s = random_screen_point();
  const vec3d p = ball.sphere_point(s);
  RC_ASSERT(std::fabs(norm(p) - 1.0) <= 1e-15);
  RC_ASSERT(p[2] >= 0.0);
  const double r = std::hypot(s[0] - 320.0, s[1] - 240.0) / 240.0;
  if (r >= 1.0) RC_ASSERT(p[2] == 0.0);  // outside the ball: on the rim
  if (r < 1.0) RC_ASSERT(std::fabs(p[0] - (s[0] - 320.0) / 240.0) <= 1e-15);
}

TEST(Arcball, ScreenYConventionsDescribeTheSamePhysicalPoint) {
  const arcball down(640, 480, screen_y::down), up(640, 480, screen_y::up);
  EXPECT_EQ(down.sphere_point({320, 240}), (vec3d{0, 0, 1}));
  // 100 px above the centre: y = 140 from the top, y = 340 from the bottom; sphere y > 0.
  const vec3d a = down.sphere_point({400, 140}), b = up.sphere_point({400, 340});
  EXPECT_EQ(a, b);
  EXPECT_GT(a[1], 0.0);
  EXPECT_GT(a[0], 0.0);
  // Far outside: onto the rim in the direction of the point.
  const vec3d rim = down.sphere_point({320 + 1e6, 240});
  EXPECT_EQ(rim, (vec3d{1, 0, 0}));
}

RC_GTEST_PROP(Arcball, IdenticalPointsGiveExactlyTheIdentity, ()) {
  const arcball ball(640, 480);
  const vec2d s = random_screen_point();
  const quaternion q = ball.drag(s, s);
  RC_ASSERT(q.w == 1.0);
  RC_ASSERT(q.x == 0.0);
  RC_ASSERT(q.y == 0.0);
  RC_ASSERT(q.z == 0.0);
}

RC_GTEST_PROP(Arcball, RotationMapsStartPointToMirrorOfEndPointAndItsSquareRootToEndPoint, ()) {
  // The documented doubling: angle 2 * angle(p, q) about p x q, so p -> 2 (p.q) q - p;
  // the rotation by the arc itself about the same axis (a square root) maps p -> q.
  const arcball ball(640, 480);
  const vec2d a = random_screen_point(), b = random_screen_point();
  const vec3d p = ball.sphere_point(a), q = ball.sphere_point(b);
  const quaternion r = ball.drag(a, b);
  RC_ASSERT(std::fabs(exbsp::norm(r) - 1.0) <= 1e-15);
  const vec3d mirror = sub(scale(2.0 * dot(p, q), q), p);
  RC_ASSERT(dist(exbsp::rotate(r, p), mirror) <= 1e-14);
  const double arc = std::atan2(norm(cross(p, q)), dot(p, q));
  if (norm(cross(p, q)) > 1e-9) {
    // The undoubled rotation h (same axis, angle = the arc) maps p to q, and h h = r.
    const quaternion h = exbsp::from_axis_angle(cross(p, q), arc);
    RC_ASSERT(dist(exbsp::rotate(h, p), q) <= 1e-12);
    RC_ASSERT(rotation_distance(h * h, r) <= 1e-12);
  }
  RC_ASSERT(std::fabs(exbsp::to_axis_angle(r).angle - std::min(2.0 * arc, 2.0 * pi - 2.0 * arc)) <=
            1e-12);
}

TEST(Arcball, DraggingRightTurnsTheFrontOfTheSceneRightAboutScreenUp) {
  const arcball ball(640, 480);
  const quaternion r = ball.drag({320, 240}, {400, 240});
  const exbsp::axis_angle aa = exbsp::to_axis_angle(r);
  EXPECT_NEAR(aa.axis[1], 1.0, 1e-15);
  EXPECT_GT(exbsp::rotate(r, {0, 0, 1})[0], 0.0);
  // Dragging up (towards y = 0 in screen_y::down) turns the front up, about screen left.
  const quaternion u = ball.drag({320, 240}, {320, 160});
  EXPECT_NEAR(exbsp::to_axis_angle(u).axis[0], -1.0, 1e-15);  // z x y = -x
  EXPECT_GT(exbsp::rotate(u, {0, 0, 1})[1], 0.0);
}

RC_GTEST_PROP(Arcball, SuccessiveDragsComposeToTheDragBetweenTheEnds, ()) {
  const arcball ball(640, 480);
  const vec2d a = random_screen_point(), b = random_screen_point(), c = random_screen_point();
  const quaternion composed = ball.drag(b, c) * ball.drag(a, b);
  RC_ASSERT(rotation_distance(composed, ball.drag(a, c)) <= 1e-14);
  const std::vector<quaternion> path = ball.drag_path({a, b, c});
  RC_ASSERT(path.size() == 3u);
  RC_ASSERT(rotation_distance(path[0], quaternion{}) == 0.0);
  RC_ASSERT(rotation_distance(path[1], ball.drag(a, b)) <= 1e-15);
  RC_ASSERT(rotation_distance(path[2], composed) <= 1e-15);
}

RC_GTEST_PROP(Arcball, InverseDragReturnsToIdentity, ()) {
  const arcball ball(640, 480, screen_y::up);
  const vec2d a = random_screen_point(), b = random_screen_point();
  RC_ASSERT(rotation_distance(ball.drag(b, a) * ball.drag(a, b), quaternion{}) <= 1e-14);
  const quaternion start = random_rotation();
  const std::vector<quaternion> path = ball.drag_path({a, b, a}, start);
  RC_ASSERT(rotation_distance(path.back(), start) <= 1e-14);
}

TEST(Arcball, QuaternionStaysUnitAfter100000ComposedDrags) {
  const arcball ball(640, 480);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> step(-3.0, 3.0), where(0.0, 640.0);
  std::vector<vec2d> path{{320, 240}};
  for (int i = 0; i < 100000; ++i) {
    vec2d next{path.back()[0] + step(rng), path.back()[1] + step(rng)};
    if (next[0] < 0 || next[0] > 640 || next[1] < 0 || next[1] > 480) next = {where(rng), 240};
    path.push_back(next);
  }
  const std::vector<quaternion> rotations = ball.drag_path(path);
  ASSERT_EQ(rotations.size(), path.size());
  double worst = 0.0;
  for (const quaternion& q : rotations) worst = std::max(worst, std::fabs(exbsp::norm(q) - 1.0));
  EXPECT_LE(worst, 1e-15);
  // Arcball drags are path independent: the whole path equals the drag from first to last.
  EXPECT_LE(rotation_distance(rotations.back(), ball.drag(path.front(), path.back())), 1e-9);
  // Without renormalisation the raw product drifts only slowly, but compose() must not.
  quaternion raw{};
  for (std::size_t k = 1; k < path.size(); ++k) raw = ball.drag(path[k - 1], path[k]) * raw;
  EXPECT_LE(std::fabs(exbsp::norm(raw) - 1.0), 1e-9);
}

TEST(Arcball, EmptyAndSinglePointPaths) {
  const arcball ball(100, 100);
  EXPECT_TRUE(ball.drag_path({}).empty());
  const quaternion start = exbsp::from_axis_angle({0, 1, 0}, 0.3);
  const std::vector<quaternion> one = ball.drag_path({{10, 10}}, start);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_LE(rotation_distance(one[0], start), 1e-16);
}

TEST(Arcball, InvalidInputThrowsUsageError) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(arcball(0, 480), exbsp::usage_error);
  EXPECT_THROW(arcball(640, -1), exbsp::usage_error);
  EXPECT_THROW(arcball(inf, 480), exbsp::usage_error);
  EXPECT_THROW(arcball(vec2d{0, 0}, 0.0, screen_y::up), exbsp::usage_error);
  EXPECT_THROW(arcball(vec2d{nan, 0}, 1.0, screen_y::up), exbsp::usage_error);
  const arcball ball(640, 480);
  EXPECT_THROW(ball.sphere_point({nan, 0}), exbsp::usage_error);
  EXPECT_THROW(ball.drag({0, 0}, {inf, 0}), exbsp::usage_error);
  EXPECT_THROW(ball.drag_path({{0, 0}, {0, nan}}), exbsp::usage_error);
}

// --- camera orbit ---

/// Eye coordinates of world point w for gluLookAt(eye, look_at, up).
vec3d eye_coordinates(const exbsp::orbit_view& c, const vec3d& w) {
  const vec3d f = unit(sub(c.look_at, c.eye));
  const vec3d s = unit(cross(f, c.up));
  const vec3d u = cross(s, f);
  const vec3d d = sub(w, c.eye);
  return {dot(s, d), dot(u, d), -dot(f, d)};
}

RC_GTEST_PROP(OrbitCamera, SceneAppearsRotatedAboutTheLookAtPoint, ()) {
  exbsp::orbit_view camera{random_nonzero_vector(), random_nonzero_vector(),
                           random_nonzero_vector()};
  const vec3d view = sub(camera.look_at, camera.eye);
  RC_PRE(norm(view) > 0.1);
  RC_PRE(norm(cross(unit(view), unit(camera.up))) > 0.1);
  const quaternion r = random_rotation();
  const exbsp::orbit_view moved = exbsp::orbit_camera(camera, r);
  RC_ASSERT(moved.look_at == camera.look_at);
  RC_ASSERT(std::fabs(dist(moved.eye, moved.look_at) - norm(view)) <= 1e-12 * norm(view) + 1e-12);
  RC_ASSERT(std::fabs(norm(moved.up) - 1.0) <= 1e-14);
  RC_ASSERT(std::fabs(dot(moved.up, unit(sub(moved.look_at, moved.eye)))) <= 1e-12);
  // e' + (0, 0, d) = R (e + (0, 0, d)): the look-at point (0, 0, -d) is the centre of rotation.
  const vec3d world = random_nonzero_vector();
  const vec3d centre{0.0, 0.0, -norm(view)};
  const vec3d before = sub(eye_coordinates(camera, world), centre);
  const vec3d after = sub(eye_coordinates(moved, world), centre);
  RC_ASSERT(dist(after, exbsp::rotate(r, before)) <= 1e-10 * (norm(before) + 1.0));
}

TEST(OrbitCamera, IdentityKeepsTheCamera) {
  const exbsp::orbit_view camera{{0, 0, 10}, {0, 0, 0}, {0, 2, 0}};
  const exbsp::orbit_view same = exbsp::orbit_camera(camera, quaternion{});
  EXPECT_EQ(same.eye, camera.eye);
  EXPECT_EQ(same.up, (vec3d{0, 1, 0}));
}

TEST(OrbitCamera, DragRightMovesTheEyeLeftAroundTheTarget) {
  // Turning the scene to the right (about screen up) = moving the camera to its left.
  const exbsp::orbit_view camera{{0, 0, 10}, {0, 0, 0}, {0, 1, 0}};
  const arcball ball(640, 480);
  const exbsp::orbit_view moved = exbsp::orbit_camera(camera, ball.drag({320, 240}, {400, 240}));
  EXPECT_LT(moved.eye[0], 0.0);
  EXPECT_NEAR(moved.eye[1], 0.0, 1e-12);
}

TEST(OrbitCamera, DegenerateCameraThrowsUsageError) {
  EXPECT_THROW(exbsp::orbit_camera({{1, 1, 1}, {1, 1, 1}, {0, 1, 0}}, quaternion{}),
               exbsp::usage_error);
  EXPECT_THROW(exbsp::orbit_camera({{0, 5, 0}, {0, 0, 0}, {0, 1, 0}}, quaternion{}),
               exbsp::usage_error);
  EXPECT_THROW(exbsp::orbit_camera({{0, 0, 5}, {0, 0, 0}, {0, 0, 0}}, quaternion{}),
               exbsp::usage_error);
  EXPECT_THROW(exbsp::orbit_camera({{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, quaternion{0, 0, 0, 0}),
               exbsp::usage_error);
}

}  // namespace
