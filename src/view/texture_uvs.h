// SPDX-License-Identifier: LGPL-3.0-or-later
// Texture coordinates of fragments and their per-pixel interpolation (texture.h, pipeline.h
// frame::mesh_textures).
//
// A fragment lies in the plane of its source triangle (a, b, c) (bsp::fragment_source), so its
// corner p has barycentric coordinates (l_a, l_b, l_c) in it, and its texture coordinates are
// l_a uv_a + l_b uv_b + l_c uv_c: exactly the interpolation at the exact split parameter of every
// split that made it (texture coordinates are affine in the plane). texture_uvs computes them in
// GMP rationals from the EXACT fragment corner (bsp::fragment_exact) and the source triangle's
// double corners and UVs, and rounds each once to the nearest double. Inexact kernels (epick,
// double) have no exact corners: their double fragment corners are used (the same exact
// arithmetic on the rounded points). A depth sort (no tree) draws the soup's own triangles: their
// UVs as read.
//
// The raster interpolates the corner UVs perspective-correctly (perspective_weights in
// smooth_shading.h: u / w, v / w and 1 / w interpolated in the window, equivalently) and
// samples the mesh's texture there; the texel times the fragment's colour (white unless lit:
// GL_MODULATE) is the pixel.
#pragma once
#include <array>

#include <exbsp/view/pipeline.h>
#include "view/smooth_shading.h"

namespace exbsp::view {

/// f.fragment_uvs for f.fragments (from f.tree and f.soup.triangle_uvs; f.tree absent: fragment i
/// is soup triangle i) when f.textured(), else cleared: at zero cost. Only fragments of textured
/// meshes are computed (the others keep (0, 0)). Throws usage_error when a textured mesh's
/// triangles have no UVs or a fragment's source is not in f.soup (a saved tree of another soup).
void texture_uvs(frame& f);

/// The texture coordinates of one fragment at window points (perspective-correct).
class uv_interpolator {
 public:
  uv_interpolator(const fragment_d& fragment, const std::array<vec2d, 3>& uvs,
                  const view_setup& view)
      : weights_(fragment, view), uvs_(uvs) {}
  /// (u, v) at window point (x, y); corner 0's where the projection is degenerate.
  vec2d at(double x, double y) const {
    std::array<double, 3> k;
    if (!weights_.at(x, y, k)) return uvs_[0];
    return {k[0] * uvs_[0][0] + k[1] * uvs_[1][0] + k[2] * uvs_[2][0],
            k[0] * uvs_[0][1] + k[1] * uvs_[1][1] + k[2] * uvs_[2][1]};
  }

 private:
  perspective_weights weights_;
  std::array<vec2d, 3> uvs_;
};

/// GL_MODULATE: texel times colour, per channel, (t c + 127) / 255 (a white colour leaves the
/// texel unchanged).
inline rgb8 modulate(rgb8 texel, rgb8 color) {
  const auto ch = [](unsigned t, unsigned c) {
    return static_cast<std::uint8_t>((t * c + 127) / 255);
  };
  return {ch(texel.r, color.r), ch(texel.g, color.g), ch(texel.b, color.b)};
}

}  // namespace exbsp::view
