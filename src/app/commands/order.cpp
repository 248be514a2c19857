// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp order MESH|T.exbsp --eye X,Y,Z | --direction X,Y,Z [-o OUT.json]`: the back-to-front
// fragment order as JSON (docs/contract.md "Command line").
#include <CLI/CLI.hpp>

#include <iostream>

#include <exbsp/core/errors.h>
#include "app/cli_parse.h"
#include "app/commands/command.h"
#include "app/commands/common.h"
#include "bsp/order_json.h"
#include "core/atomic_file.h"

namespace exbsp::cli {

namespace {

class order_subcommand final : public command {
 public:
  explicit order_subcommand(CLI::App& subcommand) : command(subcommand) {
    add_build_options(sub, o_);
    auto* eye_opt = sub->add_option("--eye", eye_, "eye point X,Y,Z (perspective view)");
    auto* dir_opt = sub->add_option("--direction", direction_,
                                    "direction of projection X,Y,Z, from the eye into the scene "
                                    "(parallel view)");
    eye_opt->excludes(dir_opt);
    sub->add_option("-o,--output", out_, "output JSON file ('-' or none: standard output)")
        ->check(non_empty_path());
  }

  bool builds_tree() const override { return true; }

  int run() override {
    if (eye_.empty() && direction_.empty())
      throw usage_error("order needs --eye X,Y,Z or --direction X,Y,Z");
    const bool use_eye = !eye_.empty();
    const vec3d where =
        use_eye ? parse_triple(eye_, "--eye") : parse_triple(direction_, "--direction");
    progress_line progress;
    const bsp tree = build_tree(o_, progress);
    const auto order = use_eye ? tree.order_from_eye(where) : tree.order_for_direction(where);
    // Streamed: the document is about 600 bytes per fragment, several times the tree.
    std::size_t non_finite = 0;
    write_file_atomically(out_.empty() ? "-" : out_, [&](const output_sink& sink) {
      non_finite = order_json(tree, order, where, use_eye, sink);
    });
    if (non_finite > 0)
      std::cerr << "exbsp: warning: " << non_finite
                << " fragments with a NaN or infinite corner (the " << tree.stats().kernel
                << " kernel's rounded split points) were left out (\"non_finite_fragments\")\n";
    return finish_standard_output(0);
  }

 private:
  build_cli o_;
  std::string eye_, direction_, out_;
};

}  // namespace

std::unique_ptr<command> make_order_command(CLI::App& subcommand) {
  return std::make_unique<order_subcommand>(subcommand);
}

}  // namespace exbsp::cli
