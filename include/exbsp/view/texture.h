// SPDX-License-Identifier: LGPL-3.0-or-later
// Textures (GL_TEXTURE_2D of the course notes): a PNG image per mesh, sampled per pixel at
// perspective-correct texture coordinates (docs/contract.md "Scenes", "texture").
//
// Notation (OpenGL's): texture coordinates (u, v) = (s, t); the image is W x H texels, texel
// (i, j) is column i and row j counted from the BOTTOM of the PNG (v = 0 is the PNG's last row,
// as glTexImage2D with the PNG's rows uploaded bottom first, and as OBJ's vt). Texel (i, j)
// covers [i / W, (i + 1) / W) x [j / H, (j + 1) / H).
//   nearest (GL_NEAREST): texel (wrap(floor(u W)), wrap(floor(v H))).
//   linear (GL_LINEAR): with a = u W - 1/2, b = v H - 1/2, i0 = floor(a), j0 = floor(b),
//     alpha = a - i0, beta = b - j0: (1 - alpha)(1 - beta) T(i0, j0) + alpha (1 - beta)
//     T(i0 + 1, j0) + (1 - alpha) beta T(i0, j0 + 1) + alpha beta T(i0 + 1, j0 + 1), each index
//     wrapped, each channel rounded to the nearest integer.
//   wrap: repeat (GL_REPEAT): i mod W (into 0..W-1); clamp (GL_CLAMP_TO_EDGE): min(max(i, 0), W-1).
// A non-finite (u, v) samples texel (0, 0).
#pragma once
#include <exbsp/core/export.h>
#include <exbsp/view/image.h>

namespace exbsp::view {

/// One mesh's texture: its texels, filter and wrap mode, and their mean colour.
struct EXBSP_EXPORT texture {
  enum class filter_kind { nearest, linear };
  enum class wrap_kind { repeat, clamp };

  image texels;  ///< the PNG as read (row 0 = top = v near 1)
  filter_kind filter = filter_kind::nearest;
  wrap_kind wrap = wrap_kind::repeat;
  rgb8 mean;  ///< the rounded mean of every texel (SVG / PDF fill textured regions with it)

  /// A texture of `texels` (nonempty) with its mean computed.
  texture(image texels, filter_kind filter, wrap_kind wrap);

  /// The filtered colour at texture coordinates (u, v) (notation above).
  rgb8 sample(double u, double v) const;
};

/// "nearest" / "linear", "repeat" / "clamp".
EXBSP_EXPORT const char* to_string(texture::filter_kind f);
EXBSP_EXPORT const char* to_string(texture::wrap_kind w);

}  // namespace exbsp::view
