// SPDX-License-Identifier: LGPL-3.0-or-later
// The views of the hidden-line suite (tests/test_hidden_lines.cpp) and of bench/hlr_judge: the
// standard views (front, back, top, bottom, left, right, two isometric corners) and two general
// ones, and the frame of a soup seen along one of them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/mesh/soup.h>
#include <exbsp/view/pipeline.h>

namespace exbsp_test {

struct view_spec {
  std::string name;
  exbsp::vec3d direction;  ///< into the scene
  exbsp::vec3d up;
};

/// Front (0,0,-1), Back, Top (0,-1,0), Bottom, Left (1,0,0), Right, Isometric (-1,-1,-1) and
/// IsometricBackLeft (1,-1,1), with their view-up vectors.
const std::vector<view_spec>& standard_views();
/// Two views along no axis or diagonal.
const std::vector<view_spec>& general_views();

/// The frame of `soup` (meshes from `offsets`, mesh_face_offsets) seen along `v`: the camera
/// looks at the bounding box's centre from 4 radii away; perspective (fovy fitting 1.3 radii)
/// or orthographic (a window of 1.3 radii), through the scene parser (make_view_setup), svg
/// edges "visible+hidden" with `crease_deg`.
exbsp::view::frame make_view(const exbsp::triangle_soup& soup,
                             const std::vector<std::uint32_t>& offsets, const view_spec& v,
                             bool parallel, int width = 320, int height = 240,
                             double crease_deg = 30);

}  // namespace exbsp_test
