// SPDX-License-Identifier: LGPL-3.0-or-later
// What several commands share: the mesh-or-saved-tree input with its build options (build,
// order), option validators, the progress line, and the final check of standard output.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

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
  std::string save;  ///< build --save: write the tree here
  /// `exbsp build` (set before add_build_options): the tree is only built and saved, so the
  /// default --max-fragments uses the build's own bytes per fragment (resources.h).
  bool build_only = false;
  const CLI::App* command = nullptr;  ///< to tell options given on the command line from defaults
};

/// An option a saved tree fixed when it was built: its name, the value the command line gave
/// and the tree's.
struct fixed_option {
  const char* name;
  std::string given, saved;
};

/// Refuses, for the saved tree `path` (docs/tree-file.md), the options of `cmd` that cannot act
/// on it: each of `steering` given at all (they steer a build; a flag acts or is refused), and
/// each of `fixed` given with another value than the tree's (usage_error ending "(`instead`)").
void refuse_for_saved_tree(const CLI::App& cmd, const std::string& path,
                           std::initializer_list<const char*> steering,
                           const std::vector<fixed_option>& fixed, const std::string& instead);

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

/// The progress line on a terminal (standard error) for work that runs over a second: the
/// stage running and its time, and during a build the share of fragments already placed at
/// nodes, nodes and time. The share never goes backwards (the total grows as triangles are
/// split, so the raw share can step back: the line shows the largest so far). A ticker thread
/// redraws it at most 10 times a second; the callbacks only record the state, from any thread.
class progress_line {
 public:
  /// `enabled`: false for --quiet; the line is drawn only when standard error is a terminal.
  explicit progress_line(bool enabled = true);
  ~progress_line();
  progress_line(const progress_line&) = delete;
  progress_line& operator=(const progress_line&) = delete;
  /// A build's progress (build_options::progress).
  void operator()(const build_progress& p);
  /// A stage starts (the render pipeline's stages: "build", "order", "svg", "write", ...).
  void stage(const std::string& name);
  /// Stops the ticker and clears the line; called again by the destructor.
  void finish();

 private:
  void tick();
  bool tty_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::string stage_ = "building";
  std::chrono::steady_clock::time_point stage_start_;
  bool have_build_ = false;
  build_progress build_{};
  double share_ = 0;  ///< the largest share placed so far, in percent
  bool shown_ = false;
  std::thread ticker_;
};

/// The tree of `o.mesh`: built from the mesh (standard input for "-"), or loaded when it is a
/// saved tree, whose --kernel, --heuristic and --seed may only repeat what it was built with.
/// `load_seconds` (when given) is set to the load time of a saved tree and left alone otherwise.
bsp build_tree(const build_cli& o, progress_line& progress, double* load_seconds = nullptr);

/// Flushes standard output and checks that every write to it went through: a full disk or a
/// closed pipe is an output error (exit 2), never a silent exit 0. Returns `status`.
int finish_standard_output(int status);

}  // namespace exbsp::cli
