// SPDX-License-Identifier: LGPL-3.0-or-later
// What several commands share (common.h).
#include "app/commands/common.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <vector>

#include <exbsp/core/errors.h>
#include "app/cli_parse.h"
#include "app/resources.h"
#include "bsp/heuristic_table.h"
#include "bsp/kernels.h"
#include "core/name_list.h"

namespace exbsp::cli {

const CLI::Validator& non_empty_path() {
  static const CLI::Validator v(
      [](const std::string& s) {
        return s.empty() ? std::string("empty file name") : std::string();
      },
      "FILE");
  return v;
}

const CLI::Validator& not_negative() {
  static const CLI::Validator v(
      [](const std::string& s) {
        const std::size_t i = s.find_first_not_of(" \t");
        return i != std::string::npos && s[i] == '-' ? "must not be negative, got " + s
                                                     : std::string();
      },
      "");
  return v;
}

namespace {

/// "PREFIX a (what a is), b (what b is), ...": a table's rows with their descriptions.
template <class Row>
std::string described_rows(const std::string& prefix, const std::vector<Row>& rows) {
  std::string text = prefix;
  for (std::size_t i = 0; i < rows.size(); ++i)
    text += (i == 0 ? "" : ", ") + rows[i].name + " (" + rows[i].description + ")";
  return text;
}

}  // namespace

std::string kernel_help() { return described_rows("number type: ", kernel_table()); }

std::string heuristic_help() { return described_rows("splitter choice: ", heuristic_table()); }

std::string render_kernel_help() {
  std::vector<std::string> exact, inexact;
  for (const kernel_row& r : kernel_table())
    if (r.name != to_string(build_options{}.kernel)) (r.exact ? exact : inexact).push_back(r.name);
  return "BSP kernel (default " + to_string(build_options{}.kernel) + "); " +
         name_list(exact, "and") + "; " + name_list(inexact, "and") +
         " only to see what rounding does";
}

void add_format_option(CLI::App* cmd, std::string& format) {
  cmd->add_option(
         "--format", format,
         "mesh format: off, obj, ply or stl (needed for '-', standard input; otherwise the "
         "file's extension decides)")
      ->check(CLI::IsMember({"off", "obj", "ply", "stl"}));
}

namespace {
fragment_use use_of(const build_cli& o) {
  return o.build_only ? fragment_use::build : fragment_use::command;
}
}  // namespace

void add_build_options(CLI::App* cmd, build_cli& o) {
  o.command = cmd;
  cmd->add_option("MESH", o.mesh,
                  "mesh file: .off, .obj, .ply or .stl ('-': standard input, with --format), or a "
                  "saved tree "
                  "(.exbsp, from build --save)")
      ->required();
  add_format_option(cmd, o.format);
  cmd->add_option("--kernel", o.kernel, kernel_help())
      ->check(CLI::IsMember(kernel_names()))
      ->capture_default_str();
  cmd->add_option("--heuristic", o.heuristic, heuristic_help())
      ->check(CLI::IsMember(heuristic_names()))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "seed of the randomised heuristics")
      ->check(not_negative())
      ->capture_default_str();
  cmd->add_option("--max-fragments", o.max_fragments, max_fragments_help(use_of(o)))
      ->check(not_negative());
  cmd->add_option("--threads", o.threads, "threads for candidate evaluation (0: all cores)")
      ->check(CLI::Range(0u, max_threads()));
}

progress_line::progress_line(bool enabled)
    : tty_(enabled && ::isatty(2) != 0), stage_start_(std::chrono::steady_clock::now()) {
  if (tty_) ticker_ = std::thread([this] { tick(); });
}

progress_line::~progress_line() { finish(); }

void progress_line::operator()(const build_progress& p) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!have_build_) stage_ = "building";
  have_build_ = true;
  build_ = p;
  if (p.fragments_total)
    share_ = std::max(share_, 100.0 * static_cast<double>(p.fragments_placed) /
                                  static_cast<double>(p.fragments_total));
}

void progress_line::stage(const std::string& name) {
  const std::lock_guard<std::mutex> lock(mutex_);
  stage_ = name == "build" ? "building" : name;
  stage_start_ = std::chrono::steady_clock::now();
  have_build_ = false;
}

void progress_line::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; })) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - stage_start_).count();
    if (seconds < 1.0) continue;
    if (have_build_ && stage_ == "building")
      std::fprintf(stderr,
                   "\r\033[Kexbsp: building: %3.0f%% (%zu of %zu fragments placed), %zu nodes, "
                   "%.1f s",
                   share_, build_.fragments_placed, build_.fragments_total, build_.nodes, seconds);
    else
      std::fprintf(stderr, "\r\033[Kexbsp: %s: %.1f s", stage_.c_str(), seconds);
    std::fflush(stderr);
    shown_ = true;
  }
}

void progress_line::finish() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  if (shown_) std::fprintf(stderr, "\r\033[K");
  shown_ = false;
}

namespace {

/// A saved tree (docs/tree-file.md): --kernel, --heuristic and --seed may only repeat what the
/// tree was built with (they cannot change a built tree); --threads and --max-fragments, which
/// only steer a build, are refused (a flag acts or is refused, never ignored).
bsp load_tree(const build_cli& o, double* load_seconds) {
  const auto start = std::chrono::steady_clock::now();
  bsp tree = bsp::load(o.mesh);
  if (load_seconds)
    *load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const build_stats& s = tree.stats();
  if (o.command)
    refuse_for_saved_tree(*o.command, o.mesh, {"--threads", "--max-fragments"},
                          {{"--kernel", o.kernel, s.kernel},
                           {"--heuristic", o.heuristic, s.heuristic},
                           {"--seed", std::to_string(o.seed), std::to_string(s.seed)}},
                          "build from the mesh instead");
  return tree;
}

}  // namespace

void refuse_for_saved_tree(const CLI::App& cmd, const std::string& path,
                           std::initializer_list<const char*> steering,
                           const std::vector<fixed_option>& fixed, const std::string& instead) {
  for (const char* option : steering)
    if (cmd.count(option))
      throw usage_error(std::string(option) + " steers a build; " + path +
                        " is a saved tree, loaded, not rebuilt");
  for (const fixed_option& f : fixed)
    if (cmd.count(f.name) && f.given != f.saved)
      throw usage_error(path + " is a saved tree built with " + f.name + " " + f.saved + "; " +
                        f.name + " " + f.given + " cannot change it (" + instead + ")");
}

bsp build_tree(const build_cli& o, progress_line& progress, double* load_seconds) {
  // A saved tree by its extension or magic; never standard input or a mesh given --format.
  if (o.format.empty() && o.mesh != "-" && bsp::is_saved_tree(o.mesh))
    return load_tree(o, load_seconds);
  const triangle_soup soup = read_mesh_input(o.mesh, o.format, std::cin);
  build_options options;
  options.kernel = parse_kernel(o.kernel);
  options.heuristic = o.heuristic;
  options.seed = o.seed;
  options.max_fragments =
      o.max_fragments ? *o.max_fragments : default_fragment_budget(options.kernel, use_of(o));
  options.threads = o.threads;
  options.keep_input = !o.save.empty();  // the copy of the input serves saving only
  options.progress = [&progress](const build_progress& p) { progress(p); };
  try {
    bsp tree = bsp::build(soup, options);
    progress.finish();
    return tree;
  } catch (...) {
    progress.finish();
    throw;
  }
}

int finish_standard_output(int status) {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (failed)
    throw output_error("(standard output)",
                       std::string("cannot write output: write failed") +
                           (errno ? std::string(": ") + std::strerror(errno) : std::string()));
  return status;
}

}  // namespace exbsp::cli
