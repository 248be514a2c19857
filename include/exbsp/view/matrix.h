// SPDX-License-Identifier: LGPL-3.0-or-later
// Homogeneous 4x4 matrices, points and vectors in double precision.
//
// Notation (used by every file of the view module):
//   - mat4 stores 16 doubles ROW-MAJOR: m[4*r + c] is row r, column c.
//   - Points and vectors are COLUMN vectors multiplied on the right: p' = M p, and
//     A * B applies B first (OpenGL's convention; glLoadMatrixd would take the transpose
//     of this storage, i.e. this array read column by column).
//   - point3 is an affine point (w = 1), vector3 a direction (w = 0); they are distinct types
//     so that translations never move a vector. hpoint is a homogeneous point with explicit w
//     (clip coordinates).
#pragma once
#include <array>
#include <optional>
#include <cmath>

#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>

namespace exbsp::view {

/// A direction or displacement (homogeneous w = 0).
struct vector3 {
  double x = 0, y = 0, z = 0;
};

/// An affine point (homogeneous w = 1).
struct point3 {
  double x = 0, y = 0, z = 0;
};

/// A homogeneous point (x, y, z, w), e.g. in clip coordinates.
struct hpoint {
  double x = 0, y = 0, z = 0, w = 1;
};

inline vector3 operator-(const point3& a, const point3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline point3 operator+(const point3& p, const vector3& v) {
  return {p.x + v.x, p.y + v.y, p.z + v.z};
}
inline point3 operator-(const point3& p, const vector3& v) {
  return {p.x - v.x, p.y - v.y, p.z - v.z};
}
inline vector3 operator+(const vector3& a, const vector3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline vector3 operator-(const vector3& a, const vector3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline vector3 operator-(const vector3& a) { return {-a.x, -a.y, -a.z}; }
inline vector3 operator*(double s, const vector3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const vector3& a, const vector3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vector3 cross(const vector3& a, const vector3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const vector3& a) { return std::sqrt(dot(a, a)); }
inline bool is_finite(const vector3& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}
inline bool is_finite(const point3& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// a / |a|. Throws usage_error for a zero or non-finite vector.
EXBSP_EXPORT vector3 normalized(const vector3& a);

/// Conversions from the soup's coordinate triple.
inline point3 to_point(const vec3d& p) { return {p[0], p[1], p[2]}; }
inline vec3d to_vec3d(const point3& p) { return {p.x, p.y, p.z}; }

/// A 4x4 matrix of doubles, row-major (see the notation at the top of this file).
struct EXBSP_EXPORT mat4 {
  std::array<double, 16> m{};

  /// Element at row r, column c (0-based).
  double& operator()(int r, int c) { return m[4 * r + c]; }
  double operator()(int r, int c) const { return m[4 * r + c]; }

  static mat4 identity();
  /// Builds a matrix from 16 numbers given row by row.
  static mat4 from_rows(const std::array<double, 16>& rows);
};

/// Matrix product: (a * b) p = a (b p).
EXBSP_EXPORT mat4 operator*(const mat4& a, const mat4& b);
/// M (x, y, z, 1): the homogeneous image of a point.
EXBSP_EXPORT hpoint operator*(const mat4& m, const point3& p);
/// M (x, y, z, w).
EXBSP_EXPORT hpoint operator*(const mat4& m, const hpoint& p);
/// M (x, y, z, 0): the image of a vector (only the upper-left 3x3 block acts).
EXBSP_EXPORT vector3 transform_vector(const mat4& m, const vector3& v);
/// M (x, y, z, 1) divided by its w. Throws usage_error when w is 0 or the result is not finite.
EXBSP_EXPORT point3 transform_point(const mat4& m, const point3& p);
EXBSP_EXPORT mat4 transpose(const mat4& a);
/// Largest absolute difference between corresponding elements.
EXBSP_EXPORT double max_abs_difference(const mat4& a, const mat4& b);
/// True when every element is finite.
EXBSP_EXPORT bool is_finite(const mat4& a);
/// The solution x of M x = b (Gaussian elimination with partial pivoting), or nullopt when M
/// is singular (a pivot below 1e-12 times the largest element) or the result is not finite.
EXBSP_EXPORT std::optional<hpoint> solve(const mat4& m, const hpoint& b);

}  // namespace exbsp::view
