// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp render [SCENE.json|MESH]`: a scene, a mesh with a view fitted to it (scene::mesh_scene)
// or the built-in demo to PNG, SVG or PDF; a progress line during long builds and a one-line
// summary on standard error.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include "app/cli_parse.h"
#include "app/commands/command.h"
#include "app/commands/common.h"
#include "app/resources.h"
#include "core/file_name.h"
#include "scene/mesh_scene.h"
#include "scene/output_formats.h"
#include "scene/render.h"

namespace exbsp::cli {

namespace {

class render_subcommand final : public command {
 public:
  explicit render_subcommand(CLI::App& subcommand) : command(subcommand) {
    sub->add_option(
        "INPUT", input_,
        "scene file (.json), or a mesh (.off, .obj, .ply, .stl; '-': standard input with "
        "--format) or a saved tree (.exbsp, from build --save: not rebuilt) drawn lit with a view "
        "fitted to its bounding box; omit for the built-in demo");
    sub->add_option("-o,--output", output_,
                    "output " + output_extensions() + " ('-': PNG on standard output)")
        ->check(non_empty_path())
        ->capture_default_str();
    add_format_option(sub, format_);
    sub->add_option("--view", view_,
                    "a mesh's fitted view: iso, front, back, left, right, top or bottom")
        ->check(CLI::IsMember(scene::mesh_view_names()))
        ->capture_default_str();
    sub->add_option("--size", size_, "a mesh's image size WIDTHxHEIGHT in pixels")
        ->capture_default_str();
    sub->add_option("--edges", edges_,
                    "feature edges: none, visible or visible+hidden (hidden ones dashed); SVG/PDF: "
                    "a mesh's default is visible, on a scene it overrides \"svg\" \"edges\"; "
                    "PNG: drawn over the shaded picture (default none; on a scene it overrides "
                    "\"raster\" \"edges\")")
        ->check(CLI::IsMember({"none", "visible", "visible+hidden"}))
        ->capture_default_str();
    sub->add_option("--kernel", kernel_, render_kernel_help())
        ->check(CLI::IsMember(kernel_names()));
    sub->add_option("--max-fragments", max_fragments_, max_fragments_help())->check(not_negative());
    sub->add_flag("--wireframe", wireframe_,
                  "PNG: every feature edge drawn solid on the background, no faces (CAD's "
                  "wireframe; --edges visible keeps only the visible ones)");
    sub->add_flag("--strict", strict_, "unknown scene keys are errors (exit 2), not warnings");
    sub->add_flag("-v,--verbose", verbose_, "print the pipeline stages that ran and their timings");
    sub->add_flag("-q,--quiet", quiet_, "no progress line and no summary line");
    sub->add_option("--orbit-drag", orbit_drag_,
                    "trackball orbit: screen pixel path X0,Y0:X1,Y1:... (y down) dragged over an "
                    "arcball; writes OUT_0000.png, OUT_0001.png, ... from one BSP build");
    sub->add_option(
           "--trackball", trackball_,
           "orbit rotation: arcball (Shoemake, twice the arc; default) or virtual (the classic "
           "virtual trackball: the point under the cursor follows it); overrides the scene's "
           "\"trackball\"")
        ->check(CLI::IsMember({"arcball", "virtual"}));
    sub->add_option(
           "--frames", frames_,
           "number of orbit frames (the drag path resampled evenly; default: one per point)")
        ->check(not_negative());
  }

  bool builds_tree() const override { return true; }

  int run() override {
    render_request request{input_, output_, verbose_};
    request.strict = strict_;
    if (!orbit_drag_.empty()) request.orbit_drag = parse_drag_path(orbit_drag_);
    // Every flag acts or is refused (issue 25): --frames only shapes an orbit, and 0 would
    // mean nothing.
    if (sub->count("--frames") > 0 && orbit_drag_.empty())
      throw usage_error("--frames shapes an orbit: it needs --orbit-drag");
    if (sub->count("--frames") > 0 && frames_ == 0)
      throw usage_error("--frames must be at least 1 (omit it for one frame per drag point)");
    request.frames = frames_;
    request.trackball = trackball_;
    request.kernel = kernel_;
    request.max_fragments = max_fragments_
                                ? *max_fragments_
                                : default_fragment_budget(kernel_.empty() ? build_options{}.kernel
                                                                          : parse_kernel(kernel_));
    const bool scene_input = input_.empty() || has_extension(input_, ".json");
    const std::string what = input_.empty() ? std::string("the demo scene") : "the scene " + input_;
    if (sub->count("--edges") > 0) request.edges = edges_;  // SVG/PDF: "svg"; PNG: "raster"
    request.wireframe = wireframe_;
    if (scene_input) {
      // A scene sets its own camera and viewport: --view and --size are a mesh's. --edges
      // overrides the scene's "svg" or "raster" "edges" (docs/contract.md "Command line").
      if (!format_.empty()) throw usage_error("--format applies to a mesh input, not to " + what);
      if (sub->count("--view") > 0)
        throw usage_error("--view chooses a mesh's fitted view; " + what +
                          " has its own \"camera\"");
      if (sub->count("--size") > 0)
        throw usage_error("--size sets a mesh's image size; " + what +
                          " sets it in \"viewport\" (and \"image\")");
    } else {
      scene::mesh_view_options options;
      const auto size = parse_size(size_);
      options.width = size[0];
      options.height = size[1];
      options.view = view_;
      options.edges = edges_;
      const std::string name = input_ == "-" ? "<stdin>" : input_;
      std::shared_ptr<const triangle_soup> soup;
      if (format_.empty() && input_ != "-" && bsp::is_saved_tree(input_)) {
        // A saved tree: drawn as it was built (docs/tree-file.md), never rebuilt.
        refuse_for_saved_tree(*sub, input_, {"--max-fragments"}, {}, "");  // before loading
        bsp tree = bsp::load(input_);
        refuse_for_saved_tree(*sub, input_, {}, {{"--kernel", kernel_, to_string(tree.kernel())}},
                              "render the mesh instead");
        soup = std::make_shared<const triangle_soup>(tree.input());
        request.tree = std::move(tree);
      } else {
        soup = std::make_shared<const triangle_soup>(read_mesh_input(input_, format_, std::cin));
      }
      request.preloaded = scene::mesh_scene(std::move(soup), name, options);
    }
    progress_line progress(!quiet_);
    request.progress = [&progress](const build_progress& p) { progress(p); };
    request.on_stage = [&progress](const std::string& stage) { progress.stage(stage); };
    render_summary summary;
    try {
      summary = render_command(request, std::cerr);
    } catch (...) {
      progress.finish();
      throw;
    }
    progress.finish();
    if (summary.non_finite > 0)
      std::cerr << "exbsp: warning: " << summary.non_finite
                << " fragments with a NaN or infinite corner (the " << summary.kernel
                << " kernel's rounded split points) were left out of the picture\n";
    if (!quiet_) {
      char times[96];
      std::snprintf(times, sizeof times, "build %.2f s, total %.2f s", summary.build_seconds,
                    summary.total_seconds);
      const auto shown = [](const std::string& path) {
        return path == "-" ? std::string("standard output") : path;
      };
      std::cerr << "exbsp: wrote "
                << (summary.outputs.size() == 1
                        ? shown(summary.outputs[0])
                        : std::to_string(summary.frames) + " frames (" + summary.outputs.front() +
                              " ... " + summary.outputs.back() + ")")
                << ": " << summary.triangles << " triangles -> " << summary.fragments
                << " fragments"
                << (summary.kernel.empty() ? std::string() : " (" + summary.kernel + ")") << ", "
                << times << "\n";
    }
    return finish_standard_output(0);
  }

 private:
  std::string input_;  ///< scene (.json), mesh, '-' or empty (the demo)
  std::string output_ = "exbsp.png";
  bool wireframe_ = false;
  std::string format_, view_ = "iso", size_ = "800x600", edges_ = "visible";
  std::string orbit_drag_, trackball_, kernel_;
  std::size_t frames_ = 0;
  std::optional<std::size_t> max_fragments_;
  bool strict_ = false, verbose_ = false, quiet_ = false;
};

}  // namespace

std::unique_ptr<command> make_render_command(CLI::App& subcommand) {
  return std::make_unique<render_subcommand>(subcommand);
}

}  // namespace exbsp::cli
