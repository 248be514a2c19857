// SPDX-License-Identifier: LGPL-3.0-or-later
// Parameters of the effects a scene may name under "effects" (docs/contract.md "Scenes"), as plain
// data carried by the frame (pipeline.h). The scene parser (src/scene/scene.cpp) validates
// them and fills in the documented defaults; an effect's stage reads only its own struct, and
// only when the scene named the effect. README.md "## Effects" describes each one.
//
// Notation: world units are the units of the scene's coordinates; "eye distance" is measured
// from the camera's eye point; colours are 0..255 per channel.
#pragma once
#include <cstddef>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/viewport.h>

namespace exbsp::view {

/// One more light of "lighting" ("lights"): directional (towards the light, as OpenGL's
/// GL_POSITION (x, y, z, 0)), a point at `where` (GL_POSITION (x, y, z, 1), world space: L
/// points from the face's centroid to it, no attenuation) or a headlight (L = V).
struct light_source {
  enum class kind_type { directional, point, headlight };
  kind_type kind = kind_type::directional;
  vector3 where{0, 0, 1};  ///< the direction, or the point's position (as a vector from 0)
  double intensity = 0.8;  ///< >= 0
};

/// "lighting": flat shading, one colour per fragment,
///   colour = base * (ambient + sum_i intensity_i * max(0, N . L_i))
///            + 255 * sum_i [N . L_i > 0] intensity_i * specular * max(0, N . H_i)^shininess,
/// per channel, clamped to 255 and rounded. N is the unit face normal, V the unit vector from
/// the face's centroid toward the eye (parallel views: toward the viewer), H_i = the unit
/// half vector of L_i and V (Blinn-Phong; white highlights). The lights: the main one,
/// L = direction / |direction| (pointing from the surface TOWARDS the light, as OpenGL's
/// GL_POSITION (x, y, z, 0)), or L = V with `headlight`, then those of `lights`. With no
/// headlight, no specular term and no more lights this is flat Lambert shading.
struct lighting_settings {
  vector3 direction{0, 0, 1};  ///< towards the light, any length > 0
  double intensity = 0.8;      ///< >= 0
  double ambient = 0.2;        ///< >= 0
  /// true: N is flipped to face the viewer (a sheet is lit the same from both sides);
  /// false: N = (b - a) x (c - a) as given by the winding, so a face seen from behind is lit
  /// as its front would be.
  bool two_sided = true;
  bool headlight = false;            ///< the main light comes from the eye (L = V)
  double specular = 0;               ///< >= 0: the highlights' weight (0: none)
  double shininess = 32;             ///< >= 0: the highlights' exponent
  std::vector<light_source> lights;  ///< more lights, at most max_lights - 1
  /// Smooth (Gouraud) shading: the colour is computed at each corner of a fragment from the
  /// normal there (the normals of the input triangles around the vertex, area-weighted, that
  /// lie within crease_deg of the triangle's own; between the input corners, interpolated
  /// linearly and renormalised) and interpolated across the fragment, perspective-correct, as
  /// OpenGL's GL_SMOOTH does. PNG only: SVG and PDF regions stay flat (the flat colour).
  bool smooth = false;
  double crease_deg = 30;  ///< (0, 180]: sharper edges stay creases
};

/// Lights a scene may have in all: the main one and "lights" (OpenGL's GL_MAX_LIGHTS).
constexpr std::size_t max_lights = 8;

/// How fog grows with eye distance d.
enum class fog_mode {
  linear,      ///< visibility v = clamp((end - d) / (end - start), 0, 1)
  exponential  ///< v = exp(-density * d)
};

/// "fog": colour = v * surface + (1 - v) * fog colour, per pixel. The background counts as
/// infinitely far away (v = 0) and is painted in the fog colour, so with end <= far (linear)
/// or a density that makes v tiny at the far plane (exp), geometry fades into the background
/// before the far plane can cut it: the far-plane "pop" is hidden.
struct fog_settings {
  fog_mode mode = fog_mode::linear;
  double start = 0, end = 1;  ///< linear: 0 <= start < end (world units of eye distance)
  double density = 1;         ///< exponential: > 0, per world unit
  rgb8 color{255, 255, 255};  ///< the scene's background unless given
};

/// "depth_of_field": a thin lens of focal length f and aperture (diameter) A focused at
/// distance u_f > f. A point at depth u (along the gaze) is imaged as a disk, the circle of
/// confusion, of diameter c = A f |u - u_f| / (u (u_f - f)) on the sensor (lens law
/// 1/f = 1/u + 1/v). Rendered by accumulating `samples` painter's renders with the eye moved
/// over the lens disk (depth_of_field.h).
struct depth_of_field_settings {
  double focal_length = 0.05;  ///< f > 0, world units
  double aperture = 0.01;      ///< A > 0, lens diameter in world units (f / f_number)
  double focus_distance = 1;   ///< u_f > f, world units along the gaze
  int samples = 32;            ///< lens samples, 2..1024
};

/// "exposure": motion blur of a moving camera. The camera runs linearly from the scene's
/// camera (time 0) to `camera_end` (time 1, the next frame); the shutter is open from time 0
/// to `shutter`, and the picture is the mean of `samples` renders at times
/// shutter * k / (samples - 1), k = 0..samples-1 (exposure.h). One tree for every sample.
struct exposure_settings {
  double shutter = 0.5;  ///< (0, 1]
  int samples = 8;       ///< 2..1024
  camera camera_end;     ///< gluLookAt's camera at time 1 (required)
};

/// "antialias": samples x samples supersampling with a box filter.
struct antialias_settings {
  int samples = 4;  ///< N in 1..8: N x N sub-pixels per pixel
};

/// Parameters of every effect (only the named ones are used).
struct effect_settings {
  lighting_settings lighting;
  fog_settings fog;
  depth_of_field_settings depth_of_field;
  antialias_settings antialias;
  exposure_settings exposure;
};

/// What the defaults and checks of effect parameters depend on in a scene.
struct effect_scene {
  bool parallel = false;  ///< orthographic or oblique projection (no lens, planar fog distance)
  double near_dist = 1, far_dist = 100;
  rgb8 background{255, 255, 255};
  int width = 1, height = 1;  ///< the viewport
  int max_side = 16384;       ///< the largest image side a scene may ask for
};

/// What the "fog" stage computes for a view (its sample shader reads it): the settings and
/// the inverse of the projection, to turn a window point (x, y, depth) back into eye space.
struct EXBSP_EXPORT fog_shading {
  fog_settings settings;
  mat4 inverse_projection = mat4::identity();
  viewport vp;
  /// true: d = |p_eye| (perspective and frustum views); false: d = -z_eye, the distance from
  /// the eye plane (orthographic and oblique views, whose eye is at infinity).
  bool radial = true;
};

}  // namespace exbsp::view
