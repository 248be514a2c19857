// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp render`: scene file (or the built-in demo) -> PNG or SVG, or an orbit animation.
//
// Still image: a "reject" stage first drops whole meshes whose bounding box is outside the view
// volume (view/mesh_reject.h; --verbose names them), then build and the per-view stages, then
// "place" when the viewport is smaller than the image (view/placement.h), then write.
//
// Orbit (trackball): a drag path of screen pixels (x right, y DOWN, origin at the top-left
// corner of the image, as mouse events) over Shoemake's arcball (or, with "trackball":
// "virtual" or --trackball virtual, the classic virtual trackball) of the viewport (ball centred
// in the viewport, radius min(width, height) / 2; view/trackball.h). The path is resampled to
// `frames` points evenly spaced along its length (its own points when frames is 0); frame k
// shows the camera orbit_camera(scene camera, drag_path(points)[k]): the eye turns about
// look_at so that the scene turns as the drag says, and frame 0 is the scene's own camera.
// For oblique projections the direction of projection turns with the camera. The BSP is
// built once; each frame only runs the per-view stages (a traversal, never a rebuild).
#pragma once
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "scene/scene.h"

namespace exbsp {

/// What to render. Constructible as {scene, output, verbose}; set the orbit members after.
struct render_request {
  render_request() = default;
  render_request(std::string scene, std::string output, bool verbose_log = false)
      : scene_path(std::move(scene)), output_path(std::move(output)), verbose(verbose_log) {}

  std::string scene_path;  ///< empty: the built-in demo scene (unless `preloaded` is set)
  /// A scene made by the caller (e.g. scene::mesh_scene for `render MESH`); used instead of
  /// reading scene_path.
  std::optional<scene::scene> preloaded;
  /// The BSP kernel (empty: the default, exact). An inexact one is for comparisons only.
  std::string kernel;
  /// Stop with limit_error when the BSP would need more fragments (0: no limit).
  std::size_t max_fragments = 0;
  /// Progress of the BSP build (build_options::progress); may be empty.
  std::function<void(const build_progress&)> progress;
  /// Called with each pipeline stage's name as it starts (frame::on_stage); may be empty.
  std::function<void(const std::string&)> on_stage;
  std::string output_path;  ///< .png, .svg or .pdf (by extension); "-": PNG on standard output
  bool verbose = false;     ///< print which pipeline stages ran, timings
  bool strict = false;      ///< unknown scene keys are errors (scene::load_scene), not warnings
  /// Orbit drag path in screen pixels (y down); empty: one still image.
  std::vector<std::array<double, 2>> orbit_drag;
  /// Orbit rotation rule: "arcball" or "virtual" (empty: the scene's "trackball", default arcball).
  std::string trackball;
  /// Orbit frames (0: one per drag point). Frame k is written to frame_path(output_path, k).
  std::size_t frames = 0;
  /// A built tree of the scene's soup (`render T.exbsp`: a saved tree and
  /// scene::mesh_scene(tree.input())): drawn as it is, not rebuilt ("adopt" replaces "reject"
  /// and "build"); `kernel` and `max_fragments` do not apply.
  std::optional<bsp> tree;
  /// The edges, overriding the scene's "svg" "edges" (SVG, PDF) or "raster" "edges" (PNG)
  /// (`--edges`): "none", "visible" or "visible+hidden"; empty: the scene's.
  std::string edges;
  /// PNG only: a wireframe (every feature edge solid on the background, no faces); edges
  /// default visible+hidden. Refused for SVG and PDF.
  bool wireframe = false;
};

/// What a render did, for the one-line summary the command line prints.
struct render_summary {
  std::size_t triangles = 0, fragments = 0, frames = 0;
  /// Most fragments with a NaN or infinite corner left out of one frame (inexact kernels).
  std::size_t non_finite = 0;
  double build_seconds = 0, total_seconds = 0;
  std::string kernel;
  /// Stop with limit_error when the BSP would need more fragments (0: no limit).
  std::size_t max_fragments = 0;
  std::vector<std::string> outputs;  ///< files written (or "-")
};

/// Loads the scene, builds one BSP of all its meshes, renders and writes output_path
/// atomically (no partial file on error). With an orbit, writes the frames OUT_0000.png ...
/// from one build; an error at any frame removes the frames this call wrote before it. Log lines go
/// to `log`. Returns what was done. Throws scene_error / input_error / output_error (exit 2),
/// limit_error (exit 3), usage_error for a bad output name or orbit request (exit 2).
render_summary render_command(const render_request& request, std::ostream& log);

/// OUT.png -> OUT_0000.png (k with at least 4 digits, before the extension).
std::string frame_path(const std::string& output, std::size_t k);

/// `path` resampled to `count` points evenly spaced along its length, first and last kept
/// (a path of zero length: `count` copies of its first point). Throws usage_error for an empty
/// path or count 0.
std::vector<std::array<double, 2>> resample_path(const std::vector<std::array<double, 2>>& path,
                                                 std::size_t count);

/// The cameras of an orbit over scene `s` (see the notation at the top): one per frame, with
/// the oblique direction of projection turned along (second of each pair).
/// Throws usage_error for an empty path.
std::vector<std::pair<view::camera, view::vector3>> orbit_cameras(
    const scene::scene& s, const std::vector<std::array<double, 2>>& path, std::size_t frames);

}  // namespace exbsp
