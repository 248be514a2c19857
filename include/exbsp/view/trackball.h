// SPDX-License-Identifier: LGPL-3.0-or-later
// Virtual trackball: Shoemake's arcball ("ARCBALL: a user interface for specifying
// three-dimensional orientation using a mouse", Graphics Interface 1992) and unit quaternions.
//
// Notation and conventions:
// - A quaternion is w + x i + y j + z k (Hamilton: i^2 = j^2 = k^2 = ijk = -1). A unit
//   quaternion q rotates a vector v as v' = q v q*; q and -q are the same rotation.
//   Products compose right to left: (a * b) rotates by b first, then by a.
//   The rotation by angle a about unit axis u (right-hand rule) is (cos a/2, sin a/2 u).
// - Matrices are row-major (as the scene "transform"), acting on column vectors: v' = M v.
// - The ball lives in eye coordinates (as OpenGL): x to the right, y up, z towards the viewer.
//   Screen points are pixels; screen_y::down (mouse events, PNG rows: y = 0 at the top) or
//   screen_y::up (OpenGL window coordinates: y = 0 at the bottom). By default the ball is
//   centred in the viewport [0, width] x [0, height] with radius min(width, height) / 2.
// - Screen to sphere: (x, y) = (screen - centre) / radius (y flipped for screen_y::down); inside
//   the ball z = sqrt(1 - x^2 - y^2); outside it the point is projected onto the rim (x, y, 0)
//   / |(x, y)|.
// - Arcball rotation of a drag from sphere point p to sphere point q: the quaternion
//   (p.q, p x q), i.e. axis p x q and angle 2 * angle(p, q): the arc is doubled, so the
//   rotation maps p to 2 (p.q) q - p (the mirror image of p in q), not to q; the rotation by
//   the arc itself about the same axis (whose square it is) maps p to q. Doubling makes the
//   rotation of a whole drag depend only on its end points: drag(b, c) * drag(a, b) =
//   drag(a, c) (up to sign), and dragging back gives the identity. The angle can exceed pi
//   (rim points up to 180 degrees apart): then to_axis_angle reports 2 pi - angle about -axis.
// - Classic virtual trackball (Chen, Mountford and Sellen 1988; the "trackball.c" of SGI's GLUT
//   examples, on a sphere without their hyperbolic sheet): the drag from p to q rotates by the
//   angle between p and q itself, about p x q, so p goes exactly to q: the point under the
//   cursor stays under the cursor. As a quaternion it is the square root of the arcball's,
//   normalize(1 + p.q, p x q). It is not path independent: a closed drag can leave a net
//   rotation (which the arcball's doubling avoids), and a full turn needs twice the drag.
//   The rotation turns the scene as seen from the camera (in eye coordinates); orbit_camera()
//   turns the camera the other way about the look-at point to get the same picture.
// Precondition failures throw exbsp::usage_error (include/exbsp/core/errors.h); nothing aborts.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>
#include <exbsp/core/export.h>
#include <exbsp/core/vec.h>

namespace exbsp {

// vec2d (e.g. a point in pixels) and vec3d: <exbsp/core/vec.h>.

/// A quaternion w + x i + y j + z k; rotations use unit quaternions. Default: identity.
struct quaternion {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

/// Hamilton product: (a * b) is the rotation b followed by a.
EXBSP_EXPORT quaternion operator*(const quaternion& a, const quaternion& b);
/// w - x i - y j - z k; the inverse rotation of a unit quaternion.
EXBSP_EXPORT quaternion conjugate(const quaternion& q);
/// Euclidean norm sqrt(w^2 + x^2 + y^2 + z^2) (overflow-safe).
EXBSP_EXPORT double norm(const quaternion& q);
/// q / |q|. Throws usage_error when q is zero or has a non-finite component.
EXBSP_EXPORT quaternion normalize(const quaternion& q);
/// normalize(a * b): composing many rotations this way stays a unit quaternion.
/// Throws usage_error as normalize().
EXBSP_EXPORT quaternion compose(const quaternion& a, const quaternion& b);
/// 4D dot product; |dot(a, b)| = 1 for unit quaternions of the same rotation.
EXBSP_EXPORT double dot(const quaternion& a, const quaternion& b);

/// Rotation by `angle` radians about `axis` (any length > 0, right-hand rule).
/// Throws usage_error for a zero or non-finite axis or a non-finite angle.
EXBSP_EXPORT quaternion from_axis_angle(const vec3d& axis, double angle);

/// A rotation as a unit axis and an angle in [0, pi].
struct axis_angle {
  vec3d axis;
  double angle;
};
/// The axis and angle of the rotation q (normalised first; q and -q give the same answer).
/// For the identity (angle 0) the axis is (0, 0, 1). Throws usage_error as normalize().
EXBSP_EXPORT axis_angle to_axis_angle(const quaternion& q);

/// v rotated by q (normalised first). Throws usage_error as normalize() or for non-finite v.
EXBSP_EXPORT vec3d rotate(const quaternion& q, const vec3d& v);
/// The 3x3 rotation matrix of q (normalised first), row-major: rotate(q, v) = M v.
/// Throws usage_error as normalize().
EXBSP_EXPORT std::array<double, 9> to_matrix3(const quaternion& q);
/// The 4x4 homogeneous matrix (rotation, no translation), row-major, last row (0, 0, 0, 1).
/// Throws usage_error as normalize().
EXBSP_EXPORT std::array<double, 16> to_matrix4(const quaternion& q);

/// Spherical linear interpolation along the shorter arc: slerp(a, b, 0) = a, slerp(a, b, 1) =
/// +-b (b's sign is flipped when dot(a, b) < 0), constant angular speed, unit result.
/// Falls back to normalised linear interpolation when a and b are nearly equal.
/// Throws usage_error as normalize() or for a non-finite t (any finite t extrapolates).
EXBSP_EXPORT quaternion slerp(const quaternion& a, const quaternion& b, double t);

/// Arcball rotation between two points on the unit sphere (normalised first): the quaternion
/// (p.q, p x q) — axis p x q, angle twice the angle between p and q (see the file comment).
/// Equal points give exactly the identity. Throws usage_error for zero or non-finite points.
EXBSP_EXPORT quaternion arcball_rotation(const vec3d& p, const vec3d& q);

/// Virtual-trackball rotation between two points on the unit sphere (normalised first): axis
/// p x q, angle = the angle between p and q (p goes to q). Equal points give exactly the
/// identity; opposite points (rim points 180 degrees apart) the half turn about an axis
/// perpendicular to p in the screen plane. Throws usage_error for zero or non-finite points.
EXBSP_EXPORT quaternion virtual_trackball_rotation(const vec3d& p, const vec3d& q);

/// Which rotation a drag gives.
enum class trackball_kind {
  arcball,  ///< Shoemake: twice the arc (path independent; the default)
  virtual_  ///< classic virtual trackball: the arc itself (follows the cursor)
};

/// The trackball a scene's "trackball" or --trackball names: "arcball" or "virtual";
/// nothing for any other name.
EXBSP_EXPORT std::optional<trackball_kind> trackball_named(const std::string& name);

/// Direction of the screen y axis.
enum class screen_y {
  down,  ///< y = 0 at the top edge (mouse events, PNG rows)
  up     ///< y = 0 at the bottom edge (OpenGL window coordinates)
};

/// Shoemake's arcball over a viewport.
class EXBSP_EXPORT arcball {
 public:
  /// Ball centred in the viewport [0, width] x [0, height], radius min(width, height) / 2.
  /// Throws usage_error unless width and height are finite and > 0.
  arcball(double width, double height, screen_y y_axis = screen_y::down);
  /// The same ball with the rotation rule `kind` (virtual trackball or arcball).
  arcball(double width, double height, screen_y y_axis, trackball_kind kind);
  /// Ball with the given centre and radius in pixels (both in the screen convention y_axis).
  /// Throws usage_error unless centre is finite and radius finite and > 0.
  arcball(const vec2d& centre, double radius, screen_y y_axis);

  const vec2d& centre() const { return centre_; }
  double radius() const { return radius_; }
  screen_y y_axis() const { return y_axis_; }
  trackball_kind kind() const { return kind_; }

  /// The unit-sphere point under a screen point (eye coordinates; rim point when outside the
  /// ball). Throws usage_error for a non-finite screen point.
  vec3d sphere_point(const vec2d& screen) const;
  /// The rotation (arcball or virtual trackball, by kind()) of a drag from screen point `from` to
  /// `to`. Throws usage_error for non-finite screen points.
  quaternion drag(const vec2d& from, const vec2d& to) const;
  /// Cumulative rotations along a drag path: result[0] = start and
  /// result[k] = compose(drag(path[k-1], path[k]), result[k-1]) (renormalised every step).
  /// Same size as path (empty for an empty path). Throws usage_error for a non-finite point.
  std::vector<quaternion> drag_path(const std::vector<vec2d>& path,
                                    const quaternion& start = quaternion{}) const;

 private:
  vec2d centre_;
  double radius_;
  screen_y y_axis_;
  trackball_kind kind_ = trackball_kind::arcball;
};

/// A gluLookAt camera.
struct orbit_view {
  vec3d eye, look_at, up;
};
/// The camera that shows the scene turned by `rotation` (in the camera's eye coordinates, as
/// arcball rotations are) about `look_at`: the eye moves on the sphere around look_at by the
/// inverse rotation, R_world^-1 = B R^-1 B^T with B = (right, true up, back) of the camera.
/// The returned up is the camera's new true up (unit, orthogonal to the view direction).
/// Throws usage_error for non-finite input, eye == look_at, or up parallel to eye - look_at.
EXBSP_EXPORT orbit_view orbit_camera(const orbit_view& camera, const quaternion& rotation);

}  // namespace exbsp
