// SPDX-License-Identifier: LGPL-3.0-or-later
// Arcball and unit quaternions. Notation as in trackball.h: q = (w, x, y, z) = w + v with
// v = (x, y, z); rotation v' = q v q*; products compose right to left; eye coordinates x right,
// y up, z towards the viewer. For pure unit quaternions p, q the arcball quaternion
// (p.q, p x q) equals q p* (because q p = -q.p + q x p), which is why drags compose:
// (c b*)(b a*) = c a*.
#include <exbsp/view/trackball.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <exbsp/core/errors.h>

namespace exbsp {
namespace {

bool is_finite(const vec3d& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

bool is_finite(const quaternion& q) {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

vec3d cross(const vec3d& a, const vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot3(const vec3d& a, const vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// |v| without overflow or premature underflow.
double length(const vec3d& v) {
  const double m = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
  if (m == 0.0 || !std::isfinite(m)) return m;
  const double a = v[0] / m, b = v[1] / m, c = v[2] / m;
  return m * std::sqrt(a * a + b * b + c * c);
}

/// v / |v|; throws usage_error (naming `what`) for a zero or non-finite v.
vec3d unit(const vec3d& v, const char* what) {
  if (!is_finite(v)) throw usage_error(std::string(what) + " has a non-finite coordinate");
  const double l = length(v);
  if (l == 0.0) throw usage_error(std::string(what) + " is the zero vector");
  return {v[0] / l, v[1] / l, v[2] / l};
}

/// Column-major basis times vector: b0 * v[0] + b1 * v[1] + b2 * v[2].
vec3d combine(const vec3d& b0, const vec3d& b1, const vec3d& b2, const vec3d& v) {
  return {b0[0] * v[0] + b1[0] * v[1] + b2[0] * v[2], b0[1] * v[0] + b1[1] * v[1] + b2[1] * v[2],
          b0[2] * v[0] + b1[2] * v[1] + b2[2] * v[2]};
}

void check_screen(const vec2d& s) {
  if (!(std::isfinite(s[0]) && std::isfinite(s[1])))
    throw usage_error("arcball: screen point has a non-finite coordinate");
}

}  // namespace

quaternion operator*(const quaternion& a, const quaternion& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

quaternion conjugate(const quaternion& q) { return {q.w, -q.x, -q.y, -q.z}; }

double dot(const quaternion& a, const quaternion& b) {
  return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

double norm(const quaternion& q) {
  const double m = std::max({std::fabs(q.w), std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
  if (m == 0.0 || !std::isfinite(m)) return m;
  const double w = q.w / m, x = q.x / m, y = q.y / m, z = q.z / m;
  return m * std::sqrt(w * w + x * x + y * y + z * z);
}

quaternion normalize(const quaternion& q) {
  if (!is_finite(q)) throw usage_error("quaternion: non-finite component");
  const double n = norm(q);
  if (n == 0.0) throw usage_error("quaternion: cannot normalise the zero quaternion");
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

quaternion compose(const quaternion& a, const quaternion& b) { return normalize(a * b); }

quaternion from_axis_angle(const vec3d& axis, double angle) {
  if (!std::isfinite(angle)) throw usage_error("from_axis_angle: non-finite angle");
  const vec3d u = unit(axis, "from_axis_angle: axis");
  const double s = std::sin(0.5 * angle);
  return {std::cos(0.5 * angle), s * u[0], s * u[1], s * u[2]};
}

axis_angle to_axis_angle(const quaternion& q) {
  quaternion n = normalize(q);
  if (n.w < 0.0) n = {-n.w, -n.x, -n.y, -n.z};
  const vec3d v{n.x, n.y, n.z};
  const double s = length(v);
  if (s == 0.0) return {{0.0, 0.0, 1.0}, 0.0};
  return {{v[0] / s, v[1] / s, v[2] / s}, 2.0 * std::atan2(s, n.w)};
}

vec3d rotate(const quaternion& q, const vec3d& v) {
  if (!is_finite(v)) throw usage_error("rotate: vector has a non-finite coordinate");
  const quaternion n = normalize(q);
  // v' = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z).
  const vec3d u{n.x, n.y, n.z};
  const vec3d t = cross(u, v);
  const vec3d t2{2.0 * t[0], 2.0 * t[1], 2.0 * t[2]};
  const vec3d c = cross(u, t2);
  return {v[0] + n.w * t2[0] + c[0], v[1] + n.w * t2[1] + c[1], v[2] + n.w * t2[2] + c[2]};
}

std::array<double, 9> to_matrix3(const quaternion& q) {
  const quaternion n = normalize(q);
  const double w = n.w, x = n.x, y = n.y, z = n.z;
  return {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z),       2.0 * (x * z + w * y),
          2.0 * (x * y + w * z),       1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),
          2.0 * (x * z - w * y),       2.0 * (y * z + w * x),       1.0 - 2.0 * (x * x + y * y)};
}

std::array<double, 16> to_matrix4(const quaternion& q) {
  const std::array<double, 9> r = to_matrix3(q);
  return {r[0], r[1], r[2], 0.0, r[3], r[4], r[5], 0.0, r[6], r[7], r[8], 0.0, 0.0, 0.0, 0.0, 1.0};
}

quaternion slerp(const quaternion& a, const quaternion& b, double t) {
  if (!std::isfinite(t)) throw usage_error("slerp: non-finite parameter");
  const quaternion p = normalize(a);
  quaternion q = normalize(b);
  if (dot(p, q) < 0.0) q = {-q.w, -q.x, -q.y, -q.z};
  // Angle between p and q on the 3-sphere, accurate also when it is tiny:
  // theta = 2 atan2(|q - p|, |q + p|).
  const quaternion diff{q.w - p.w, q.x - p.x, q.y - p.y, q.z - p.z};
  const quaternion sum{q.w + p.w, q.x + p.x, q.y + p.y, q.z + p.z};
  const double theta = 2.0 * std::atan2(norm(diff), norm(sum));
  double wp, wq;
  if (theta < 1e-8) {  // sin(theta) ~ theta: plain linear interpolation is as accurate
    wp = 1.0 - t;
    wq = t;
  } else {
    const double s = std::sin(theta);
    wp = std::sin((1.0 - t) * theta) / s;
    wq = std::sin(t * theta) / s;
  }
  return normalize(
      {wp * p.w + wq * q.w, wp * p.x + wq * q.x, wp * p.y + wq * q.y, wp * p.z + wq * q.z});
}

quaternion arcball_rotation(const vec3d& p, const vec3d& q) {
  const vec3d a = unit(p, "arcball_rotation: first point");
  const vec3d b = unit(q, "arcball_rotation: second point");
  const vec3d axis = cross(a, b);
  return normalize({dot3(a, b), axis[0], axis[1], axis[2]});
}

quaternion virtual_trackball_rotation(const vec3d& p, const vec3d& q) {
  const vec3d a = unit(p, "virtual_trackball_rotation: first point");
  const vec3d b = unit(q, "virtual_trackball_rotation: second point");
  const vec3d axis = cross(a, b);
  const double c = dot3(a, b);
  if (a == b) return quaternion{};
  if (1.0 + c < 1e-12 && std::hypot(axis[0], axis[1], axis[2]) < 1e-6) {
    // Opposite points: half turn about the screen-plane axis perpendicular to p (or x).
    const double r = std::hypot(a[0], a[1]);
    return r > 0 ? quaternion{0.0, -a[1] / r, a[0] / r, 0.0} : quaternion{0.0, 1.0, 0.0, 0.0};
  }
  return normalize({1.0 + c, axis[0], axis[1], axis[2]});
}

std::optional<trackball_kind> trackball_named(const std::string& name) {
  if (name == "arcball") return trackball_kind::arcball;
  if (name == "virtual") return trackball_kind::virtual_;
  return std::nullopt;
}

arcball::arcball(double width, double height, screen_y y_axis, trackball_kind kind)
    : arcball(width, height, y_axis) {
  kind_ = kind;
}

arcball::arcball(double width, double height, screen_y y_axis)
    : centre_{0.5 * width, 0.5 * height}, radius_(0.5 * std::min(width, height)), y_axis_(y_axis) {
  if (!(std::isfinite(width) && std::isfinite(height) && width > 0.0 && height > 0.0))
    throw usage_error("arcball: viewport width and height must be finite and > 0");
}

arcball::arcball(const vec2d& centre, double radius, screen_y y_axis)
    : centre_(centre), radius_(radius), y_axis_(y_axis) {
  if (!(std::isfinite(centre[0]) && std::isfinite(centre[1])))
    throw usage_error("arcball: centre has a non-finite coordinate");
  if (!(std::isfinite(radius) && radius > 0.0))
    throw usage_error("arcball: radius must be finite and > 0");
}

vec3d arcball::sphere_point(const vec2d& screen) const {
  check_screen(screen);
  const double x = (screen[0] - centre_[0]) / radius_;
  double y = (screen[1] - centre_[1]) / radius_;
  if (y_axis_ == screen_y::down) y = -y;
  const double r = std::hypot(x, y);
  if (r > 1.0) return {x / r, y / r, 0.0};  // outside the ball: onto its rim
  return {x, y, std::sqrt(std::max(0.0, 1.0 - (x * x + y * y)))};
}

quaternion arcball::drag(const vec2d& from, const vec2d& to) const {
  return kind_ == trackball_kind::virtual_
             ? virtual_trackball_rotation(sphere_point(from), sphere_point(to))
             : arcball_rotation(sphere_point(from), sphere_point(to));
}

std::vector<quaternion> arcball::drag_path(const std::vector<vec2d>& path,
                                           const quaternion& start) const {
  std::vector<quaternion> out;
  if (path.empty()) return out;
  out.reserve(path.size());
  for (const vec2d& s : path) check_screen(s);
  out.push_back(normalize(start));
  for (std::size_t k = 1; k < path.size(); ++k)
    out.push_back(compose(drag(path[k - 1], path[k]), out.back()));
  return out;
}

orbit_view orbit_camera(const orbit_view& camera, const quaternion& rotation) {
  if (!(is_finite(camera.eye) && is_finite(camera.look_at) && is_finite(camera.up)))
    throw usage_error("orbit_camera: camera has a non-finite coordinate");
  const vec3d to_eye{camera.eye[0] - camera.look_at[0], camera.eye[1] - camera.look_at[1],
                     camera.eye[2] - camera.look_at[2]};
  const double distance = length(to_eye);
  if (distance == 0.0) throw usage_error("orbit_camera: eye equals look_at");
  const vec3d back = unit(to_eye, "orbit_camera: eye - look_at");
  const vec3d up = unit(camera.up, "orbit_camera: up");
  const vec3d side = cross(up, back);  // = forward x up, gluLookAt's s
  if (length(side) == 0.0) throw usage_error("orbit_camera: up is parallel to the view direction");
  const vec3d right = unit(side, "orbit_camera: right");
  const vec3d true_up = cross(back, right);
  // New camera basis B R^-1: the eye-space axes of the camera rotated by the inverse rotation.
  const quaternion inverse = conjugate(normalize(rotation));
  const vec3d new_back = combine(right, true_up, back, rotate(inverse, {0.0, 0.0, 1.0}));
  const vec3d new_up = combine(right, true_up, back, rotate(inverse, {0.0, 1.0, 0.0}));
  orbit_view out;
  out.look_at = camera.look_at;
  out.eye = {camera.look_at[0] + distance * new_back[0], camera.look_at[1] + distance * new_back[1],
             camera.look_at[2] + distance * new_back[2]};
  out.up = unit(new_up, "orbit_camera: new up");
  return out;
}

}  // namespace exbsp
