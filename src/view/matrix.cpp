// SPDX-License-Identifier: LGPL-3.0-or-later
// Homogeneous 4x4 matrices (row-major storage, column vectors: p' = M p). See matrix.h.
#include <exbsp/view/matrix.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <exbsp/core/errors.h>

namespace exbsp::view {

vector3 normalized(const vector3& a) {
  const double len = length(a);
  if (len > 1e-150 && len < 1e150) return {a.x / len, a.y / len, a.z / len};
  // |a|^2 would overflow or underflow (an axis of 1e200, a direction of 1e-200): scale by the
  // largest component first, which is exact in direction.
  const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
  if (!(m > 0) || !std::isfinite(m) || !is_finite(a))
    throw usage_error("normalized: zero or non-finite vector");
  const vector3 s{a.x / m, a.y / m, a.z / m};
  const double l = length(s);
  return {s.x / l, s.y / l, s.z / l};
}

mat4 mat4::identity() {
  mat4 r;
  r(0, 0) = r(1, 1) = r(2, 2) = r(3, 3) = 1;
  return r;
}

mat4 mat4::from_rows(const std::array<double, 16>& rows) {
  mat4 r;
  r.m = rows;
  return r;
}

mat4 operator*(const mat4& a, const mat4& b) {
  mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a(i, k) * b(k, j);
      r(i, j) = s;
    }
  return r;
}

hpoint operator*(const mat4& m, const point3& p) {
  return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.z + m(0, 3),
          m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.z + m(1, 3),
          m(2, 0) * p.x + m(2, 1) * p.y + m(2, 2) * p.z + m(2, 3),
          m(3, 0) * p.x + m(3, 1) * p.y + m(3, 2) * p.z + m(3, 3)};
}

hpoint operator*(const mat4& m, const hpoint& p) {
  return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.z + m(0, 3) * p.w,
          m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.z + m(1, 3) * p.w,
          m(2, 0) * p.x + m(2, 1) * p.y + m(2, 2) * p.z + m(2, 3) * p.w,
          m(3, 0) * p.x + m(3, 1) * p.y + m(3, 2) * p.z + m(3, 3) * p.w};
}

vector3 transform_vector(const mat4& m, const vector3& v) {
  return {m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z,
          m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z,
          m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z};
}

point3 transform_point(const mat4& m, const point3& p) {
  const hpoint h = m * p;
  if (h.w == 0) throw usage_error("transform_point: the transformed point has w = 0");
  point3 r = h.w == 1 ? point3{h.x, h.y, h.z} : point3{h.x / h.w, h.y / h.w, h.z / h.w};
  if (!is_finite(r)) throw usage_error("transform_point: the transformed point is not finite");
  return r;
}

mat4 transpose(const mat4& a) {
  mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = a(j, i);
  return r;
}

double max_abs_difference(const mat4& a, const mat4& b) {
  double d = 0;
  for (int i = 0; i < 16; ++i) d = std::max(d, std::fabs(a.m[i] - b.m[i]));
  return d;
}

bool is_finite(const mat4& a) {
  return std::all_of(a.m.begin(), a.m.end(), [](double x) { return std::isfinite(x); });
}

std::optional<hpoint> solve(const mat4& m, const hpoint& b) {
  // Four unknowns: elimination by hand rather than a linear-algebra library for one system.
  double a[4][5];
  const double rhs[4] = {b.x, b.y, b.z, b.w};
  double largest = 0;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m(r, c);
      largest = std::max(largest, std::abs(m(r, c)));
    }
    a[r][4] = rhs[r];
  }
  if (!(largest > 0) || !std::isfinite(largest)) return std::nullopt;
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (!(std::abs(a[pivot][c]) > 1e-12 * largest)) return std::nullopt;
    for (int k = 0; k < 5; ++k) std::swap(a[c][k], a[pivot][k]);
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < 5; ++k) a[r][k] -= f * a[c][k];
    }
  }
  const hpoint x{a[0][4] / a[0][0], a[1][4] / a[1][1], a[2][4] / a[2][2], a[3][4] / a[3][3]};
  if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z) || !std::isfinite(x.w))
    return std::nullopt;
  return x;
}

}  // namespace exbsp::view
