// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp build MESH|T.exbsp [--save T.exbsp] [--json]`: builds (or loads) a tree and prints its
// statistics.
#include <CLI/CLI.hpp>

#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands/command.h"
#include "app/commands/common.h"

namespace exbsp::cli {

namespace {

class build_subcommand final : public command {
 public:
  explicit build_subcommand(CLI::App& subcommand) : command(subcommand) {
    o_.build_only = true;  // no frame or document: the build's own memory per fragment
    add_build_options(sub, o_);
    sub->add_option("--save", o_.save,
                    "write the tree to a saved-tree file T.exbsp, for order and build")
        ->check(non_empty_path());
    sub->add_flag("--json", json_,
                  "print one JSON object: input_triangles, degenerate_input, fragments, splits, "
                  "nodes, depth, build_seconds, kernel, heuristic, ...");
  }

  bool builds_tree() const override { return true; }

  int run() override {
    progress_line progress;
    double load_seconds = -1;
    const bsp tree = build_tree(o_, progress, &load_seconds);
    if (!o_.save.empty()) tree.save(o_.save);
    const auto& s = tree.stats();
    if (json_) {
      nlohmann::json j;
      for_each_stat(s, [&j](const char* name, const auto& value) { j[name] = value; });
      j["mesh"] = o_.mesh == "-" ? "<stdin>" : o_.mesh;
      if (load_seconds >= 0)
        j["load_seconds"] = load_seconds;  // a saved tree: build_seconds is its build's
      // A file name need not be UTF-8 (Linux names are bytes): invalid bytes become U+FFFD in
      // the JSON instead of an exception from the writer (issue 28).
      std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
      if (load_seconds >= 0) std::cout << "saved tree loaded in " << load_seconds << " s; ";
      std::cout << (o_.mesh == "-" ? "<stdin>" : o_.mesh) << ": " << s.input_triangles
                << " input triangles (" << s.degenerate_input << " degenerate, skipped) -> "
                << s.fragments << " fragments, " << s.splits << " splits, " << s.nodes
                << " nodes, depth " << s.depth << "; " << s.kernel << ", " << s.heuristic << ", "
                << s.build_seconds << " s\n";
    }
    return finish_standard_output(0);
  }

 private:
  build_cli o_;
  bool json_ = false;
};

}  // namespace

std::unique_ptr<command> make_build_command(CLI::App& subcommand) {
  return std::make_unique<build_subcommand>(subcommand);
}

}  // namespace exbsp::cli
