// The "fog" effect (a screen-space stage after transform+clip; the painters apply it).
//
// Notation: a window point (x, y, z) (viewport.h: z is the depth in [depth_near, depth_far])
// goes back to normalized device coordinates ndc = (2 (x - vp.x) / width - 1,
// 2 (y - vp.y) / height - 1, 2 (z - depth_near) / (depth_far - depth_near) - 1) and to eye
// space by the inverse projection: p_eye = P^-1 (ndc, 1), divided by its w. The eye distance
// is d = |p_eye| for perspective and frustum views (radial fog: the same for every pixel at
// the same distance, so the far plane's corners fade as its centre does) and d = -z_eye for
// parallel views. Visibility v(d) (effect_settings.h): linear clamp((end - d)/(end - start),
// 0, 1) or exponential exp(-density d); colour = v surface + (1 - v) fog colour, rounded.
//
// Over a planar polygon the window depth z is an affine function of (x, y) (a projective map
// sends planes to planes), so each polygon's depth at a pixel centre comes from its plane
// z = zx x + zy y + z0 through its window vertices: per-pixel fog without a depth buffer.
#pragma once
#include <string>
#include <vector>

#include "view/effect_settings.h"
#include "view/pipeline.h"

namespace exbsp::view {

/// v(d) in [0, 1] (1: no fog) for eye distance d >= 0.
double fog_visibility(const fog_settings& s, double d);

/// Fog state for a view: settings, inverse projection, radial or planar distance.
/// Throws usage_error when the projection matrix is singular.
fog_shading make_fog_shading(const fog_settings& s, const view_setup& view);

/// Eye distance of the window point (x, y, z) (notation above).
double eye_distance(const fog_shading& fog, double x, double y, double z);

/// `base` fogged at eye distance d.
rgb8 fog_color(const fog_shading& fog, rgb8 base, double d);

/// The depth plane z = zx x + zy y + z0 of a window-space polygon; for a polygon seen
/// edge-on (no stable plane) zx = zy = 0 and z0 is the mean depth.
struct depth_plane {
  double zx = 0, zy = 0, z0 = 0;
  double at(double x, double y) const { return zx * x + zy * y + z0; }
};
/// The plane through the polygon's widest fan triangle.
depth_plane polygon_depth_plane(const std::vector<window_point>& v);

/// "fog": f.fog = make_fog_shading(f.settings.fog, f.view). Colours are applied by the
/// painters: per pixel in raster/antialias, per path (at the centroid) in svg, and the
/// background takes the fog colour.
std::string fog_stage(frame& f);

}  // namespace exbsp::view
