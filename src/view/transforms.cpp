// SPDX-License-Identifier: LGPL-3.0-or-later
// Modelling transforms and the matrix stack. Notation: row-major mat4, p' = M p (matrix.h).
// rotate() is the Rodrigues matrix c I + (1 - c) a a^T + s [a]x for the unit axis a.
#include <exbsp/view/transforms.h>

#include <exbsp/core/errors.h>

namespace exbsp::view {

namespace {
constexpr double pi = 3.14159265358979323846;
}

mat4 translate(const vector3& t) {
  mat4 r = mat4::identity();
  r(0, 3) = t.x;
  r(1, 3) = t.y;
  r(2, 3) = t.z;
  return r;
}

mat4 scale(double sx, double sy, double sz) {
  mat4 r = mat4::identity();
  r(0, 0) = sx;
  r(1, 1) = sy;
  r(2, 2) = sz;
  return r;
}

mat4 rotate(double angle_deg, const vector3& axis) {
  if (!is_finite(axis) || length(axis) == 0) throw usage_error("rotate: zero or non-finite axis");
  const vector3 a = normalized(axis);
  const double t = angle_deg * (pi / 180.0);
  const double c = std::cos(t), s = std::sin(t), k = 1 - c;
  mat4 r = mat4::identity();
  r(0, 0) = a.x * a.x * k + c;
  r(0, 1) = a.x * a.y * k - a.z * s;
  r(0, 2) = a.x * a.z * k + a.y * s;
  r(1, 0) = a.y * a.x * k + a.z * s;
  r(1, 1) = a.y * a.y * k + c;
  r(1, 2) = a.y * a.z * k - a.x * s;
  r(2, 0) = a.z * a.x * k - a.y * s;
  r(2, 1) = a.z * a.y * k + a.x * s;
  r(2, 2) = a.z * a.z * k + c;
  return r;
}

matrix_stack::matrix_stack() : stack_{mat4::identity()} {}

void matrix_stack::push() { stack_.push_back(stack_.back()); }

void matrix_stack::pop() {
  if (stack_.size() <= 1) throw usage_error("matrix_stack::pop: stack underflow");
  stack_.pop_back();
}

void matrix_stack::load(const mat4& m) { stack_.back() = m; }

void matrix_stack::multiply(const mat4& m) { stack_.back() = stack_.back() * m; }

}  // namespace exbsp::view
