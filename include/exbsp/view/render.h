// SPDX-License-Identifier: LGPL-3.0-or-later
// Rendering a soup in one call, and the helpers a viewer needs around it: the view fitted to a
// mesh's bounding box (the one `exbsp render MESH` uses), its light, and a headlight.
//
// Notation: world axes as the file gives them, +y up. A named view gives the direction from
// the centre c of the bounding box of the vertices the triangles use towards the eye (front:
// +z, back: -z, right: +x, left: -x, top: +y with up -z, bottom: -y with up +z, iso: (1, 1, 1)
// with up +y); r is the radius of the box's bounding sphere. The perspective camera has a
// vertical field of view of 30 degrees at distance d = 1.08 r / sin(fov / 2) from c, fov the
// smaller of the vertical and horizontal fields of view, so it sees the whole sphere with a
// margin; near = d - 1.01 r and far = d + 1.01 r enclose it. Its light comes from over the
// viewer's left shoulder: w + 0.6 up - 0.4 right (w from c towards the eye, unit).
//
//   exbsp::view::render_result r = exbsp::view::render_soup(soup, {});
//   exbsp::view::write_png(r.picture, "out.png");
//
// render_soup gives the same pixels as `exbsp render MESH --view V --size WxH` (PNG).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/image.h>
#include <exbsp/view/view_setup.h>

namespace exbsp::view {

/// A perspective camera fitted to a soup (notation above).
struct fitted_view {
  camera cam;  ///< eye at distance d from the centre c, looking at c
  double fovy_deg = 30;
  double near_dist = 1, far_dist = 2;
  vector3 light;  ///< towards the light (not unit): over the viewer's left shoulder
};

/// "iso", "front", "back", "left", "right", "top", "bottom".
EXBSP_EXPORT const std::vector<std::string>& fitted_view_names();

/// The fitted view `name` of `soup` for a width x height viewport. Throws usage_error for an
/// unknown name or a size outside 1..16384, input_error naming `soup.source` when the soup has
/// no triangle or its coordinates are too large to fit a view in double.
EXBSP_EXPORT fitted_view fit_view(const triangle_soup& soup, int width, int height,
                                  const std::string& name = "iso");

/// A perspective view from `cam` (with `fovy_deg`) that sees all of `tree`: near and far
/// enclose the bounding sphere of its fragments (near at least 1e-4 of far when the eye is
/// inside it), light over the viewer's left shoulder as fit_view's. usage_error for a camera
/// gluLookAt refuses or an empty tree.
EXBSP_EXPORT fitted_view view_of_tree(const bsp& tree, const camera& cam, double fovy_deg = 30);

/// The view_setup of a fitted view: look_at(cam), perspective(fovy, width / height, near,
/// far), the viewport (0, 0, width, height).
EXBSP_EXPORT view_setup to_view_setup(const fitted_view& v, int width, int height);

/// Face colours lit by a headlight (a light at the eye, so every face seen is lit): base *
/// (0.25 + 0.75 |N . L|) per channel, L towards the eye from the look-at point, by face id of
/// `soup` (a face's first non-degenerate triangle decides; a face with none keeps base * 0.25).
EXBSP_EXPORT std::vector<rgb8> headlight_colors(const triangle_soup& soup, const camera& cam,
                                                rgb8 base = {200, 200, 200});

/// How a tree is painted: every face in one colour, flat Lambert light (ambient 0.3, intensity
/// 0.7, two-sided) from the view's `light`, on a background.
struct render_style {
  rgb8 color{176, 190, 214};
  rgb8 background{250, 250, 252};
};

/// The picture of a built tree seen by `view` (a fitted view, or any perspective camera with
/// its field of view, near and far distances and light) in a width x height image. The tree
/// is shared, not copied (bsp copies share it). usage_error for a size outside 1..16384 or a
/// camera gluLookAt refuses. `edges` "visible" or "visible+hidden" draws the feature edges of
/// render_tree_svg over the picture (they need bsp::input(), as there); default "none".
EXBSP_EXPORT image render_tree(const bsp& tree, const fitted_view& view, int width, int height,
                               const render_style& style = {}, const std::string& edges = "none");

/// The same view as an SVG document: visible regions and visible feature edges
/// (docs/contract.md's exact edge visibility), `edges` "none", "visible" or "visible+hidden";
/// edges need the tree's input (bsp::input(): usage_error for a tree built without
/// keep_input). The document `exbsp render MESH -o X.svg` writes for a fitted view.
EXBSP_EXPORT std::string render_tree_svg(const bsp& tree, const fitted_view& view, int width,
                                         int height, const render_style& style = {},
                                         const std::string& edges = "visible");

/// What render_soup draws.
struct render_options {
  int width = 800, height = 600;  ///< the image, each in 1..16384
  std::string view = "iso";       ///< one of fitted_view_names()
  rgb8 color{176, 190, 214};      ///< every face's colour, lit by the fitted light
  rgb8 background{250, 250, 252};
  build_options build;  ///< the BSP (default: the exact kernel)
};

/// The picture, and the tree and back-to-front order it was painted from.
struct render_result {
  image picture;
  bsp tree;
  std::vector<std::uint32_t> order;  ///< fragment indices of `tree`, back to front
  fitted_view view;
};

/// Builds the tree of `soup`, orders it for the fitted view and paints it (painter's
/// algorithm, flat Lambert light as `exbsp render MESH`). Throws like fit_view and bsp::build.
EXBSP_EXPORT render_result render_soup(const triangle_soup& soup,
                                       const render_options& options = {});

}  // namespace exbsp::view
