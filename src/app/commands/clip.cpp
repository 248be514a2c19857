// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp clip INPUT.json [--algorithm A] [-o OUT.json|.svg] [-v]`: segments and polygons
// (with holes, for a polygon region) clipped against a region, or 4D points in clip space
// (the clip input format: scene/clip_input.h).
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/commands/command.h"
#include "app/commands/common.h"
#include "scene/clip_input.h"

namespace exbsp::cli {

namespace {

class clip_subcommand final : public command {
 public:
  explicit clip_subcommand(CLI::App& subcommand) : command(subcommand) {
    sub->add_option("INPUT", in_,
                    "clip input (JSON): {\"region\": ..., \"segments\": ..., \"polygons\": ..., "
                    "\"polygons_with_holes\": ...}; regions rect, box, convex, halfspaces, "
                    "frustum, polygon ({\"outer\": [[x,y],...], \"holes\": [...]}, concave) and "
                    "clip_space (true: points [x,y,z,w], -w <= x,y,z <= w)")
        ->required();
    sub->add_option(
           "--algorithm", algorithm_,
           "segment clipper: cohen-sutherland (default) or liang-barsky (rect, box and "
           "clip_space regions), cyrus-beck (the convex regions; the default for convex, "
           "halfspaces and frustum); polygons are clipped by sutherland-hodgman (the convex "
           "regions and clip_space); weiler-atherton (the polygon region's only clipper, its "
           "default: CGAL's exact Boolean operations) clips polygons with holes and segments")
        ->check(CLI::IsMember({"cohen-sutherland", "liang-barsky", "cyrus-beck",
                               "sutherland-hodgman", "weiler-atherton"}));
    sub->add_option("-o,--output", out_, "output .json or .svg (default: JSON on standard output)")
        ->check(non_empty_path());
    sub->add_flag("-v,--verbose", verbose_,
                  "print each segment endpoint's Cohen-Sutherland outcode (or what happened "
                  "to each segment and polygon)");
  }

  int run() override {
    scene::clip_command(in_, out_, algorithm_, verbose_, std::cout, std::cerr);
    return finish_standard_output(0);
  }

 private:
  std::string in_, out_, algorithm_;
  bool verbose_ = false;
};

}  // namespace

std::unique_ptr<command> make_clip_command(CLI::App& subcommand) {
  return std::make_unique<clip_subcommand>(subcommand);
}

}  // namespace exbsp::cli
