// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp render MESH`: a scene for one bare mesh, with a view fitted to its bounding box.
//
// The view, its camera, light and margins are view::fit_view's (<exbsp/view/render.h>, which
// gives the notation); the mesh is lit (the "lighting" effect) from over the viewer's left
// shoulder, so its shape reads without a hand-written scene; SVG and PDF get visible regions
// and edges.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <exbsp/mesh/soup.h>
#include "scene/scene.h"

namespace exbsp::scene {

/// What `exbsp render MESH` may choose.
struct mesh_view_options {
  std::string view = "iso";       ///< one of mesh_view_names()
  int width = 800, height = 600;  ///< viewport (= image) in pixels, each in 1..16384
  std::string edges = "visible";  ///< SVG/PDF edges: "none", "visible" or "visible+hidden"
};

/// "iso", "front", "back", "left", "right", "top", "bottom".
const std::vector<std::string>& mesh_view_names();

/// The scene that draws `soup` (named `name` in messages) as `options` say: one mesh, the
/// fitted perspective camera above, lighting, a light background. The scene goes through the
/// same validation as a scene file (parse_scene). Throws usage_error for an unknown view or
/// a bad size, input_error naming `name` when the mesh has no triangle or its coordinates are
/// too large to fit a view in double.
scene mesh_scene(std::shared_ptr<const triangle_soup> soup, const std::string& name,
                 const mesh_view_options& options = {});

}  // namespace exbsp::scene
