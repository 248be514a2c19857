// SPDX-License-Identifier: LGPL-3.0-or-later
// Smooth (Gouraud) shading for the "lighting" stage (lighting_settings::smooth): the normals at
// the corners of the input triangles, the lit colour at each corner of every fragment, and the
// perspective-correct interpolation the raster uses between them.
//
// Notation: input triangle t = (a, b, c) with area vector m_t = (b - a) x (c - a) / 2 and unit
// normal n_t. Its vertices are welded by exact position (a soup read from STL repeats them).
// The normal at corner v of t is N(t, v) = normalised sum of m_u over the triangles u at v with
// angle(n_u, n_t) <= crease_deg (t itself included): a crease sharper than crease_deg stays
// sharp. A fragment's corner p lies in its source triangle t; with barycentric coordinates
// (l_a, l_b, l_c) of p in t, its normal is the normalised l_a N(t, a) + l_b N(t, b) +
// l_c N(t, c). With two-sided lighting the three normals are flipped together when the
// fragment faces away from the viewer (lighting.h's rule for its flat normal). The corner's
// colour is lit_color at p with that normal (per-vertex lighting, as OpenGL computes it).
#pragma once
#include <array>
#include <vector>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// f.corner_colors[i] for every fragment i of f.order (the others left black); needs
/// f.tree (for the fragments' source triangles) and f.soup.
void smooth_corner_colors(frame& f);

/// Perspective-correct weights over one fragment's projection (window coordinates): made from
/// the fragment's world corners and the view, it gives at window point (x, y) the barycentric
/// coordinates (k0, k1, k2) of the fragment's point seen there, the weights of its corners'
/// attributes (colours; texture coordinates, texture_uvs.h). Corners behind the eye are fine
/// (the homogeneous form never divides by their w).
class perspective_weights {
 public:
  perspective_weights(const fragment_d& fragment, const view_setup& view);
  /// The weights at window point (x, y); false where the projection is degenerate.
  bool at(double x, double y, std::array<double, 3>& k) const;

 private:
  std::array<double, 3> xw_{}, yw_{}, w_{};  ///< homogeneous window corners (x w, y w, w)
};

/// The corner colours interpolated with perspective_weights.
class corner_interpolator {
 public:
  corner_interpolator(const fragment_d& fragment, const std::array<rgb8, 3>& colors,
                      const view_setup& view);
  /// The colour at window point (x, y); `fallback` where the projection is degenerate.
  rgb8 at(double x, double y, rgb8 fallback) const;

 private:
  perspective_weights weights_;
  std::array<rgb8, 3> colors_;
};

}  // namespace exbsp::view
