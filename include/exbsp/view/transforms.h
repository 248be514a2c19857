// SPDX-License-Identifier: LGPL-3.0-or-later
// Modelling transforms (glTranslate / glRotate / glScale equivalents) and a matrix stack
// (glPushMatrix / glPopMatrix). Matrices are row-major and act on column vectors (matrix.h);
// multiply() post-multiplies like OpenGL: the last transform given is applied first.
#pragma once
#include <cstddef>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/view/matrix.h>

namespace exbsp::view {

/// Translation by t (glTranslated).
EXBSP_EXPORT mat4 translate(const vector3& t);
/// Non-uniform scale (glScaled).
EXBSP_EXPORT mat4 scale(double sx, double sy, double sz);
/// Rotation by angle_deg degrees counter-clockwise about `axis` through the origin
/// (right-hand rule, glRotated). Throws usage_error for a zero or non-finite axis.
EXBSP_EXPORT mat4 rotate(double angle_deg, const vector3& axis);

/// A stack of matrices; the top is the current transform. Never empty.
class EXBSP_EXPORT matrix_stack {
 public:
  /// Starts with one identity matrix.
  matrix_stack();
  /// The current matrix.
  const mat4& top() const { return stack_.back(); }
  /// Duplicates the top (glPushMatrix).
  void push();
  /// Removes the top (glPopMatrix). Throws usage_error when only one matrix is left.
  void pop();
  /// Replaces the top.
  void load(const mat4& m);
  void load_identity() { load(mat4::identity()); }
  /// top = top * m (glMultMatrix): m acts first on points.
  void multiply(const mat4& m);
  /// Number of matrices on the stack (1 after construction).
  std::size_t depth() const { return stack_.size(); }

 private:
  std::vector<mat4> stack_;
};

}  // namespace exbsp::view
