// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp matrices [SCENE.json] [--json] [-o OUT]`: every matrix of a scene's view, in OpenGL's
// terms and in the course material's (scene/matrices_command.h).
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/commands/command.h"
#include "app/commands/common.h"
#include "core/atomic_file.h"
#include "scene/demo_scene.h"
#include "scene/matrices_command.h"

namespace exbsp::cli {

namespace {

class matrices_subcommand final : public command {
 public:
  explicit matrices_subcommand(CLI::App& subcommand) : command(subcommand) {
    sub->add_option("SCENE", scene_, "scene file (.json); omit for the built-in demo scene");
    sub->add_flag("--json", json_, "one JSON object instead of text");
    sub->add_option("-o,--output", out_, "output file (default: standard output)")
        ->check(non_empty_path());
    sub->add_flag("--strict", strict_, "unknown scene keys are errors (exit 2), not warnings");
  }

  int run() override {
    const scene::scene s =
        scene_.empty() ? scene::demo_scene() : scene::load_scene(scene_, &std::cerr, strict_);
    const scene::scene_matrices m = scene::matrices_of(s);
    const std::string text = json_ ? scene::matrices_json(m) : scene::matrices_text(m);
    if (out_.empty() || out_ == "-") {
      std::cout << text;
      return finish_standard_output(0);
    }
    write_file_atomically(out_, text);
    return 0;
  }

 private:
  std::string scene_, out_;
  bool json_ = false, strict_ = false;
};

}  // namespace

std::unique_ptr<command> make_matrices_command(CLI::App& subcommand) {
  return std::make_unique<matrices_subcommand>(subcommand);
}

}  // namespace exbsp::cli
