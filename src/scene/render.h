// `exbsp render`: scene file (or the built-in demo) -> PNG or SVG.
#pragma once
#include <ostream>
#include <string>

namespace exbsp {

struct render_request {
  std::string scene_path;   ///< empty: the built-in demo scene
  std::string output_path;  ///< .png or .svg (by extension)
  bool verbose = false;     ///< print which pipeline stages ran, timings
};

/// Loads the scene, builds one BSP of all its meshes, renders and writes output_path
/// atomically (no partial file on error). Log lines go to `log`.
/// Throws scene_error / input_error (exit 2), limit_error (exit 3).
void render_command(const render_request& request, std::ostream& log);

}  // namespace exbsp
