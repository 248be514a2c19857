// SPDX-License-Identifier: LGPL-3.0-or-later
// The fitted view of <exbsp/view/render.h> with the file name its messages give, for
// `exbsp render MESH` (scene/mesh_scene.cpp), whose soup may come from standard input.
#pragma once
#include <string>

#include <exbsp/view/render.h>

namespace exbsp::view {

/// fit_view, with `file` (not soup.source) named by its input_errors and its usage_errors
/// beginning with `view_what` (an unknown view) or `size_what` (a size outside 1..16384): the
/// command line names its options there, fit_view itself.
fitted_view fit_view_of(const triangle_soup& soup, int width, int height, const std::string& name,
                        const std::string& file, const std::string& view_what = "fit_view",
                        const std::string& size_what = "fit_view");

}  // namespace exbsp::view
