// SPDX-License-Identifier: LGPL-3.0-or-later
// What several commands share: the mesh-or-saved-tree input with its build options (build,
// order), option validators, the progress line, and the final check of standard output.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include <exbsp/bsp/engine.h>

namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace exbsp::cli {

/// The input and build options of build and order.
struct build_cli {
  std::string mesh;
  std::string format;  ///< --format: the mesh format for '-' (standard input) or any file name
  std::string kernel = to_string(build_options{}.kernel);
  std::string heuristic = default_heuristic();
  std::uint64_t seed = 0;
  std::optional<std::size_t> max_fragments;  ///< absent: default_fragment_budget(kernel)
  unsigned threads = 0;
  std::string save;                   ///< build --save: write the tree here
  const CLI::App* command = nullptr;  ///< to tell options given on the command line from defaults
};

/// Rejects an empty output name (`-o ""`): it would silently mean the default output.
const CLI::Validator& non_empty_path();
/// Rejects a negative integer for an unsigned option: CLI11 would wrap "-1" to 2^64 - 1.
const CLI::Validator& not_negative();

/// The --kernel help of build and order: every kernel with its description (kernels.h).
std::string kernel_help();
/// The --kernel help of render: the default, the other exact kernels, the inexact ones.
std::string render_kernel_help();
/// The --heuristic help: every heuristic with its description (heuristic_table.h).
std::string heuristic_help();

/// --format: off, obj, ply or stl.
void add_format_option(CLI::App* cmd, std::string& format);
/// MESH, --format, --kernel, --heuristic, --seed, --max-fragments, --threads.
void add_build_options(CLI::App* cmd, build_cli& o);

/// Progress line on a terminal for builds that run longer than a second: the share of the
/// fragments already placed at nodes (the total grows as triangles are split, so the share can
/// step back a little), nodes and elapsed time.
struct progress_line {
  bool tty;
  bool shown = false;
  progress_line();
  void operator()(const build_progress& p);
  void finish();
};

/// The tree of `o.mesh`: built from the mesh (standard input for "-"), or loaded when it is a
/// saved tree, whose --kernel, --heuristic and --seed may only repeat what it was built with.
/// `load_seconds` (when given) is set to the load time of a saved tree and left alone otherwise.
bsp build_tree(const build_cli& o, progress_line& progress, double* load_seconds = nullptr);

/// Flushes standard output and checks that every write to it went through: a full disk or a
/// closed pipe is an output error (exit 2), never a silent exit 0. Returns `status`.
int finish_standard_output(int status);

}  // namespace exbsp::cli
