// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp clip INPUT.json [--algorithm A] [-o OUT.json|.svg] [-v]`: segments and polygons
// clipped against a region (the clip input format: scene/clip_input.h).
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
                    "clip input (JSON): {\"region\": ..., \"segments\": ..., \"polygons\": ...}")
        ->required();
    sub->add_option(
           "--algorithm", algorithm_,
           "segment clipper: cohen-sutherland (default) or liang-barsky (rect or box regions), "
           "cyrus-beck (any region; the default for convex and halfspaces); polygons are always "
           "clipped by sutherland-hodgman (any convex region)")
        ->check(CLI::IsMember(
            {"cohen-sutherland", "liang-barsky", "cyrus-beck", "sutherland-hodgman"}));
    sub->add_option("-o,--output", out_, "output .json or .svg (default: JSON on standard output)")
        ->check(non_empty_path());
    sub->add_flag("-v,--verbose", verbose_,
                  "print each segment endpoint's Cohen-Sutherland outcode");
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
