// SPDX-License-Identifier: LGPL-3.0-or-later
// Mesa's off-screen OpenGL (OSMesa, llvmpipe; Debian libosmesa6-dev, cmake/osmesa.cmake) as an
// independent z-buffer renderer: the context of tests/test_oracle_gl.cpp, and a flat-colour
// triangle renderer shared by tests/test_vector.cpp and bench/zbuffer_render.cpp.
//
// Notation: matrices are given row by row (as view::mat4) and loaded into OpenGL column-major;
// window coordinates as OpenGL (y up); images as view::image (row 0 = top).
// Tie rule: Mesa (llvmpipe) owns left and BOTTOM edges in GL window coordinates, exbsp
// (docs/contract.md "Pixels") left and TOP edges; zbuffer_scene::mirror_y draws the scene upside
// down (y_ndc negated, the winding of culled faces reversed) and flips the buffer back, which turns
// Mesa's rule into exbsp's (test_oracle_gl.cpp checks this on edges through pixel centres).
//
// Include in ONE translation unit per program: it defines LeakSanitizer's default suppressions.
#pragma once

#if EXBSP_HAVE_OSMESA
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <exbsp/view/image.h>

// LeakSanitizer: OSMesaMakeCurrent allocates per-context buffers that libOSMesa keeps in a
// global list and never frees, even after OSMesaDestroyContext (Mesa 22.3); those are Mesa's
// own leaks, suppressed here so that no LSAN_OPTIONS are needed.
#if defined(__SANITIZE_ADDRESS__)
#define EXBSP_OSMESA_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EXBSP_OSMESA_LSAN 1
#endif
#endif
#ifdef EXBSP_OSMESA_LSAN
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
#endif

namespace exbsp::osmesa {

/// Mesa 22.3 dereferences a null screen inside OSMesaCreateContextExt when it has no usable
/// gallium driver (e.g. GALLIUM_DRIVER names a missing one): while a context is being
/// created, a SIGSEGV prints what happened and ends the program with a failure.
inline void crashed(int) {
  static const char msg[] =
      "\nOSMesa: FAILED: Mesa crashed (SIGSEGV) creating an OSMesa context: its off-screen OpenGL "
      "is "
      "not usable on this machine (Debian: libosmesa6, libosmesa6-dev; check GALLIUM_DRIVER)\n";
  if (::write(2, msg, sizeof msg - 1) < 0) {
  }
  std::_Exit(1);
}

/// Installs `crashed` as the SIGSEGV handler while it lives.
class crash_guard {
 public:
  crash_guard() {
    struct sigaction sa {};
    sa.sa_handler = crashed;
    sigemptyset(&sa.sa_mask);
    ::sigaction(SIGSEGV, &sa, &old_);
  }
  ~crash_guard() { ::sigaction(SIGSEGV, &old_, nullptr); }
  crash_guard(const crash_guard&) = delete;
  crash_guard& operator=(const crash_guard&) = delete;

 private:
  struct sigaction old_ {};
};

/// An OSMesa RGBA context with a 24-bit depth buffer, current on this thread while it lives.
/// Throws std::runtime_error when Mesa cannot create or bind it.
class context {
 public:
  context(int width, int height) : width_(width), height_(height) {
    const crash_guard guard;
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx_)
      throw std::runtime_error(
          "OSMesaCreateContextExt(OSMESA_RGBA, 24 depth bits) failed: Mesa's off-screen "
          "OpenGL is not usable on this machine (Debian: libosmesa6, libosmesa6-dev)");
    buffer_.assign(static_cast<std::size_t>(width) * height * 4, 0);
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
      OSMesaDestroyContext(ctx_);
      throw std::runtime_error("OSMesaMakeCurrent failed for a " + std::to_string(width) + "x" +
                               std::to_string(height) + " RGBA buffer");
    }
    OSMesaPixelStore(OSMESA_Y_UP, 1);  // buffer row 0 = window row 0 = BOTTOM of the image
  }
  ~context() { OSMesaDestroyContext(ctx_); }
  context(const context&) = delete;
  context& operator=(const context&) = delete;

  /// The finished buffer as an image (row 0 = top, as PNG). `mirrored_y`: the scene was drawn
  /// upside down, so buffer row 0 holds the image's top row.
  view::image picture(bool mirrored_y = false) const {
    view::image img(width_, height_, {0, 0, 0});
    for (int j = 0; j < height_; ++j)
      for (int i = 0; i < width_; ++i) {
        const std::uint8_t* p = &buffer_[4 * (static_cast<std::size_t>(j) * width_ + i)];
        if (mirrored_y)
          img.set_at_row(j, i, {p[0], p[1], p[2]});
        else
          img.set_pixel(i, j, {p[0], p[1], p[2]});  // window row j from the bottom
      }
    return img;
  }

 private:
  OSMesaContext ctx_ = nullptr;
  int width_, height_;
  std::vector<GLubyte> buffer_;
};

/// A row-major 4x4 matrix as OpenGL wants it: column-major.
inline std::array<double, 16> column_major(const std::array<double, 16>& rows) {
  std::array<double, 16> c{};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) c[4 * k + r] = rows[4 * r + k];
  return c;
}

/// Flat-coloured triangles with the matrices and viewport that place them in an image.
struct zbuffer_scene {
  int image_width = 0, image_height = 0;
  /// glViewport (window coordinates of its lower-left corner) and glDepthRange.
  int vp_x = 0, vp_y = 0, vp_width = 0, vp_height = 0;
  double depth_near = 0, depth_far = 1;
  view::rgb8 background{255, 255, 255};
  std::array<double, 16> projection{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  ///< row-major
  std::array<double, 16> model_view{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  ///< row-major
  std::vector<std::array<std::array<double, 3>, 3>> triangles;  ///< world (object) coordinates
  std::vector<view::rgb8> colors;                               ///< one per triangle
  /// When not empty: a colour per corner of each triangle, interpolated (GL_SMOOTH: Gouraud,
  /// perspective-correct in Mesa) instead of `colors`.
  std::vector<std::array<view::rgb8, 3>> corner_colors;
  /// When not empty: texture coordinates (s, t) per corner of each triangle and `texture`
  /// (row 0 = top, uploaded bottom row first: t = 0 at the image's bottom), GL_MODULATE with the
  /// triangles' colours, GL_PERSPECTIVE_CORRECTION_HINT GL_NICEST, no mipmaps.
  std::vector<std::array<std::array<double, 2>, 3>> corner_uvs;
  view::image texture;
  bool texture_linear = false;  ///< GL_LINEAR (else GL_NEAREST), both filters
  bool texture_clamp = false;   ///< GL_CLAMP_TO_EDGE (else GL_REPEAT), both directions
  /// Cull triangles whose (b - a) x (c - a) faces away from the viewer (counter-clockwise in
  /// window coordinates = front).
  bool cull_back = false;
  bool mirror_y = false;  ///< Mesa's tie rule turned into exbsp's (notation above)
  /// GL_LESS (nearer = smaller window z, OpenGL's convention) or GL_GREATER.
  bool nearer_is_smaller = true;
};

/// The state of a z-buffer oracle frame in the current context: unlit flat colours, no
/// blending, dithering, multisampling or polygon smoothing, depth test (GL_LESS, or GL_GREATER
/// when nearer points have greater window depth), back faces culled when asked (front =
/// counter-clockwise in window coordinates, clockwise when the scene is drawn mirrored), and
/// the colour and depth buffers cleared.
inline void begin_zbuffer_frame(view::rgb8 background, bool cull_back, bool mirror_y,
                                bool nearer_is_smaller = true) {
  glDisable(GL_LIGHTING);
  glDisable(GL_BLEND);
  glDisable(GL_DITHER);
  glDisable(GL_MULTISAMPLE);
  glDisable(GL_POLYGON_SMOOTH);
  glShadeModel(GL_FLAT);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(nearer_is_smaller ? GL_LESS : GL_GREATER);
  glDepthMask(GL_TRUE);
  if (cull_back) {
    glEnable(GL_CULL_FACE);
    glFrontFace(mirror_y ? GL_CW : GL_CCW);  // a mirror reverses the window-space winding
    glCullFace(GL_BACK);
  } else {
    glDisable(GL_CULL_FACE);
  }
  glClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  glClearDepth(nearer_is_smaller ? 1.0 : 0.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/// Mesa's image of `s`: one pass, 24-bit z-buffer, unlit, flat colours, no blending, no
/// dithering, no multisampling. Throws std::runtime_error when OSMesa cannot render.
inline view::image render_zbuffer(const zbuffer_scene& s) {
  context ctx(s.image_width, s.image_height);
  GLint depth_bits = 0;
  glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
  if (depth_bits < 24)
    throw std::runtime_error("OSMesa context has " + std::to_string(depth_bits) + " depth bits");
  const int vp_y = s.mirror_y ? s.image_height - s.vp_y - s.vp_height : s.vp_y;
  glViewport(s.vp_x, vp_y, s.vp_width, s.vp_height);
  glDepthRange(s.depth_near, s.depth_far);
  begin_zbuffer_frame(s.background, s.cull_back, s.mirror_y, s.nearer_is_smaller);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (s.mirror_y) glScaled(1, -1, 1);
  const std::array<double, 16> p = column_major(s.projection), mv = column_major(s.model_view);
  glMultMatrixd(p.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(mv.data());
  if (!s.corner_colors.empty()) glShadeModel(GL_SMOOTH);
  GLuint texture_name = 0;
  if (!s.corner_uvs.empty()) {
    std::vector<GLubyte> texels;  // bottom row first
    for (int j = 0; j < s.texture.height(); ++j)
      for (int i = 0; i < s.texture.width(); ++i) {
        const view::rgb8 c = s.texture.pixel(i, j);
        texels.insert(texels.end(), {c.r, c.g, c.b});
      }
    glGenTextures(1, &texture_name);
    glBindTexture(GL_TEXTURE_2D, texture_name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, s.texture.width(), s.texture.height(), 0, GL_RGB,
                 GL_UNSIGNED_BYTE, texels.data());
    const GLint filter = s.texture_linear ? GL_LINEAR : GL_NEAREST;
    const GLint wrap = s.texture_clamp ? GL_CLAMP_TO_EDGE : GL_REPEAT;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glEnable(GL_TEXTURE_2D);
  }
  glBegin(GL_TRIANGLES);
  for (std::size_t k = 0; k < s.triangles.size(); ++k) {
    if (s.corner_colors.empty()) {
      const view::rgb8 c = s.colors.at(k);
      glColor3ub(c.r, c.g, c.b);
    }
    for (int i = 0; i < 3; ++i) {
      if (!s.corner_colors.empty()) {
        const view::rgb8 c = s.corner_colors.at(k)[i];
        glColor3ub(c.r, c.g, c.b);
      }
      if (!s.corner_uvs.empty()) glTexCoord2d(s.corner_uvs.at(k)[i][0], s.corner_uvs.at(k)[i][1]);
      const auto& v = s.triangles[k][i];
      glVertex3d(v[0], v[1], v[2]);
    }
  }
  glEnd();
  glFinish();
  if (texture_name != 0) glDeleteTextures(1, &texture_name);
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR)
    throw std::runtime_error("OpenGL error " + std::to_string(err) + " while rendering");
  return ctx.picture(s.mirror_y);
}

}  // namespace exbsp::osmesa

#endif  // EXBSP_HAVE_OSMESA
