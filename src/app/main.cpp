// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp command line (docs/contract.md "Command line"): glue only. Library exceptions become
// messages "exbsp: error: ..." on stderr and exit codes: 2 bad input, bad usage or an output that
// cannot be written; 3 resource limit (--max-fragments, whose default comes from the available
// memory, or out of memory).
#include <CLI/CLI.hpp>
#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "app/cli_parse.h"
#include "bsp/engine.h"
#include "bsp/order_json.h"
#include "core/atomic_file.h"
#include "core/version.h"
#include "clip/section.h"
#include "clip/section_cap.h"
#include "core/errors.h"
#include "core/file_name.h"
#include "mesh/gmp_memory.h"
#include "mesh/mesh_io.h"
#include "scene/clip_input.h"
#include "scene/drawing_command.h"
#include "scene/mesh_scene.h"
#include "scene/render.h"

namespace {

using exbsp::vec3d;

// ---- resource defaults and limits (the library's defaults stay explicit: 0 = no limit) ----

/// Bytes one tree fragment costs in a build, tree nodes, lists and the process's slack
/// included, per kernel. Epeck and gmpq: about 1,000 measured (naive heuristic on 128 + 128
/// sticks: 2.1 M fragments in 2.1 GB), rounded up for the heavier gmpq numbers. exact (and the
/// double-based inexact kernels): the whole command's peak resident set per fragment on
/// refined_elephant (254,565 fragments), measured with /usr/bin/time (2026-11-24): build 218
/// bytes, order 358 (its document is streamed, not held), render 620. The budget is the
/// largest, rounded up.
std::uint64_t bytes_per_fragment(exbsp::kernel_id kernel) {
  return kernel == exbsp::kernel_id::epeck || kernel == exbsp::kernel_id::gmpq ? 1300 : 640;
}

using exbsp::cli::available_memory_bytes;

/// The default --max-fragments: half the available memory at bytes_per_fragment(kernel) each
/// (the other half for the input, the output and the allocator's slack), at least 10,000;
/// 0 (no limit) when the available memory is unknown.
std::size_t default_fragment_budget(exbsp::kernel_id kernel) {
  const std::uint64_t bytes = available_memory_bytes();
  if (bytes == 0) return 0;
  return static_cast<std::size_t>(
      std::max<std::uint64_t>(bytes / 2 / bytes_per_fragment(kernel), 10000));
}

/// The --max-fragments help text, shared by build, order and render.
std::string max_fragments_help() {
  return "stop with exit status 3 when the tree would need more fragments (0: no limit; default: "
         "half the "
         "available memory at " +
         std::to_string(bytes_per_fragment(exbsp::kernel_id::exact)) +
         " bytes per fragment for exact, double and epick, " +
         std::to_string(bytes_per_fragment(exbsp::kernel_id::epeck)) + " for epeck and gmpq)";
}

/// The most threads --threads accepts (the library's limit: 4 per hardware thread, at most
/// 1024; libgomp crashes or fails on team sizes in the tens of thousands).
unsigned max_threads() { return exbsp::max_build_threads(); }

/// OMP_NUM_THREADS is read by libgomp before main; a value it accepts but cannot honour
/// (100000) crashes the first parallel region. Anything but a number in 1..max_threads()
/// (first entry of a nesting list) is replaced by the hardware thread count, with a warning.
void sanitize_omp_num_threads() {
  const char* env = std::getenv("OMP_NUM_THREADS");
  if (!env) return;
  const std::string text(env);
  const std::string first = text.substr(0, text.find(','));
  unsigned long value = 0;
  const auto r = std::from_chars(first.data(), first.data() + first.size(), value);
  const bool ok = r.ec == std::errc() && r.ptr == first.data() + first.size() && value >= 1 &&
                  value <= max_threads();
  if (ok) return;
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  std::cerr << "exbsp: warning: OMP_NUM_THREADS='" << text.substr(0, 40)
            << "' ignored (expected 1.." << max_threads() << "); using " << hw << " threads\n";
  omp_set_num_threads(static_cast<int>(hw));
}

/// Starts OpenMP's thread pool now: libgomp cannot report an allocation failure (it prints
/// "Out of memory allocating N bytes" and exits 1), so the pool and its team are made while
/// memory is plentiful, and later parallel regions of the same size reuse them.
void start_thread_pool() {
#pragma omp parallel
  {}
}

struct build_cli {
  std::string mesh;
  std::string format;  ///< --format: the mesh format for '-' (standard input) or any file name
  std::string kernel = exbsp::to_string(exbsp::build_options{}.kernel);
  std::string heuristic = exbsp::default_heuristic();
  std::uint64_t seed = 0;
  std::optional<std::size_t> max_fragments;  ///< absent: default_fragment_budget(kernel)
  unsigned threads = 0;
  std::string save;                   ///< build --save: write the tree here
  const CLI::App* command = nullptr;  ///< to tell options given on the command line from defaults
};

/// Rejects an empty output name (`-o ""`): it would silently mean the default output.
const CLI::Validator non_empty_path(
    [](const std::string& s) { return s.empty() ? std::string("empty file name") : std::string(); },
    "FILE");

/// Rejects a negative integer for an unsigned option: CLI11 would wrap "-1" to 2^64 - 1.
const CLI::Validator not_negative(
    [](const std::string& s) {
      const std::size_t i = s.find_first_not_of(" \t");
      return i != std::string::npos && s[i] == '-' ? "must not be negative, got " + s
                                                   : std::string();
    },
    "");

void add_format_option(CLI::App* cmd, std::string& format) {
  cmd->add_option(
         "--format", format,
         "mesh format: off, obj, ply or stl (needed for '-', standard input; otherwise the "
         "file's extension decides)")
      ->check(CLI::IsMember({"off", "obj", "ply", "stl"}));
}

void add_build_options(CLI::App* cmd, build_cli& o) {
  o.command = cmd;
  cmd->add_option("MESH", o.mesh,
                  "mesh file: .off, .obj, .ply or .stl ('-': standard input, with --format), or a "
                  "saved tree "
                  "(.exbsp, from build --save)")
      ->required();
  add_format_option(cmd, o.format);
  cmd->add_option(
         "--kernel", o.kernel,
         "number type: exact (exbsp's own exact points, default), epeck (CGAL lazy exact), "
         "gmpq (plain exact rationals), epick (exact predicates, rounded splits), "
         "double (plain double)")
      ->check(CLI::IsMember(exbsp::kernel_names()))
      ->capture_default_str();
  cmd->add_option("--heuristic", o.heuristic,
                  "splitter choice: naive (first triangle), min-split (fewest straddlers), "
                  "sampled (16 seeded candidates, split/balance score), random (seeded)")
      ->check(CLI::IsMember(exbsp::heuristic_names()))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "seed of the randomised heuristics")
      ->check(not_negative)
      ->capture_default_str();
  cmd->add_option("--max-fragments", o.max_fragments, max_fragments_help())->check(not_negative);
  cmd->add_option("--threads", o.threads, "threads for candidate evaluation (0: all cores)")
      ->check(CLI::Range(0u, max_threads()));
}

/// Progress line on a terminal for builds that run longer than a second: the share of the
/// fragments already placed at nodes (the total grows as triangles are split, so the share can
/// step back a little), nodes and elapsed time.
struct progress_line {
  bool tty = ::isatty(2) != 0;
  bool shown = false;
  void operator()(const exbsp::build_progress& p) {
    if (!tty || p.seconds < 1.0) return;
    const double share =
        p.fragments_total ? 100.0 * static_cast<double>(p.fragments_placed) / p.fragments_total : 0;
    std::fprintf(
        stderr, "\r\033[Kexbsp: building: %3.0f%% (%zu of %zu fragments placed), %zu nodes, %.1f s",
        share, p.fragments_placed, p.fragments_total, p.nodes, p.seconds);
    std::fflush(stderr);
    shown = true;
  }
  void finish() {
    if (shown) std::fprintf(stderr, "\r\033[K");
    shown = false;
  }
};

/// A saved tree (docs/tree-file.md): --kernel, --heuristic and --seed may only repeat what the
/// tree was built with (they cannot change a built tree); --threads and --max-fragments, which
/// only steer a build, are ignored.
exbsp::bsp load_tree(const build_cli& o, double* load_seconds) {
  const auto start = std::chrono::steady_clock::now();
  exbsp::bsp tree = exbsp::bsp::load(o.mesh);
  if (load_seconds)
    *load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const exbsp::build_stats& s = tree.stats();
  const auto conflict = [&](const char* option, const std::string& given,
                            const std::string& saved) {
    if (o.command && o.command->count(option) && given != saved)
      throw exbsp::usage_error(o.mesh + " is a saved tree built with " + option + " " + saved +
                               "; " + option + " " + given +
                               " cannot change it (build from the mesh instead)");
  };
  conflict("--kernel", o.kernel, s.kernel);
  conflict("--heuristic", o.heuristic, s.heuristic);
  conflict("--seed", std::to_string(o.seed), std::to_string(s.seed));
  return tree;
}

exbsp::bsp build_tree(const build_cli& o, progress_line& progress, double* load_seconds = nullptr) {
  // A saved tree by its extension or magic; never standard input or a mesh given --format.
  if (o.format.empty() && o.mesh != "-" && exbsp::bsp::is_saved_tree(o.mesh))
    return load_tree(o, load_seconds);
  const exbsp::triangle_soup soup = exbsp::cli::read_mesh_input(o.mesh, o.format, std::cin);
  exbsp::build_options options;
  options.kernel = exbsp::parse_kernel(o.kernel);
  options.heuristic = o.heuristic;
  options.seed = o.seed;
  options.max_fragments =
      o.max_fragments ? *o.max_fragments : default_fragment_budget(options.kernel);
  options.threads = o.threads;
  options.progress = [&progress](const exbsp::build_progress& p) { progress(p); };
  try {
    exbsp::bsp tree = exbsp::bsp::build(soup, options);
    progress.finish();
    return tree;
  } catch (...) {
    progress.finish();
    throw;
  }
}

nlohmann::json stats_json(const exbsp::build_stats& s) {
  return {{"input_triangles", s.input_triangles},
          {"degenerate_input", s.degenerate_input},
          {"fragments", s.fragments},
          {"splits", s.splits},
          {"nodes", s.nodes},
          {"depth", s.depth},
          {"build_seconds", s.build_seconds},
          {"peak_rss_bytes", s.peak_rss_bytes},
          {"kernel", s.kernel},
          {"heuristic", s.heuristic}};
}

/// Flushes standard output and checks that every write to it went through: a full disk or a
/// closed pipe is an output error (exit 2), never a silent exit 0. Returns `status`.
int finish_standard_output(int status) {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (failed)
    throw exbsp::output_error(
        "(standard output)",
        std::string("cannot write output: write failed") +
            (errno ? std::string(": ") + std::strerror(errno) : std::string()));
  return status;
}

int run_build(const build_cli& o, bool json) {
  progress_line progress;
  double load_seconds = -1;
  const exbsp::bsp tree = build_tree(o, progress, &load_seconds);
  if (!o.save.empty()) tree.save(o.save);
  const auto& s = tree.stats();
  if (json) {
    nlohmann::json j = stats_json(s);
    j["mesh"] = o.mesh == "-" ? "<stdin>" : o.mesh;
    j["seed"] = s.seed;
    if (load_seconds >= 0)
      j["load_seconds"] = load_seconds;  // a saved tree: build_seconds is its build's
    // A file name need not be UTF-8 (Linux names are bytes): invalid bytes become U+FFFD in
    // the JSON instead of an exception from the writer (issue 28).
    std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else {
    if (load_seconds >= 0) std::cout << "saved tree loaded in " << load_seconds << " s; ";
    std::cout << (o.mesh == "-" ? "<stdin>" : o.mesh) << ": " << s.input_triangles
              << " input triangles (" << s.degenerate_input << " degenerate, skipped) -> "
              << s.fragments << " fragments, " << s.splits << " splits, " << s.nodes
              << " nodes, depth " << s.depth << "; " << s.kernel << ", " << s.heuristic << ", "
              << s.build_seconds << " s\n";
  }
  return 0;
}

int run_order(const build_cli& o, const std::string& eye, const std::string& direction,
              const std::string& out_path) {
  const bool use_eye = !eye.empty();
  const vec3d where = use_eye ? exbsp::cli::parse_triple(eye, "--eye")
                              : exbsp::cli::parse_triple(direction, "--direction");
  progress_line progress;
  const exbsp::bsp tree = build_tree(o, progress);
  const auto order = use_eye ? tree.order_from_eye(where) : tree.order_for_direction(where);
  // Streamed: the document is about 600 bytes per fragment, several times the tree.
  std::size_t non_finite = 0;
  exbsp::write_file_atomically(out_path.empty() ? "-" : out_path,
                               [&](const exbsp::output_sink& sink) {
                                 non_finite = exbsp::order_json(tree, order, where, use_eye, sink);
                               });
  if (non_finite > 0)
    std::cerr << "exbsp: warning: " << non_finite
              << " fragments with a NaN or infinite corner (the " << tree.stats().kernel
              << " kernel's rounded split points) were left out (\"non_finite_fragments\")\n";
  return 0;
}

/// `exbsp section`: JSON (default, to standard output), OFF or SVG by the output's extension.
int run_section(const std::string& mesh, const std::string& format, const std::string& plane_text,
                const std::string& out_path) {
  const exbsp::section_plane plane = exbsp::cli::parse_plane(plane_text);
  const bool off = exbsp::has_extension(out_path, ".off"),
             svg = exbsp::has_extension(out_path, ".svg");
  if (!out_path.empty() && out_path != "-" && !off && !svg &&
      !exbsp::has_extension(out_path, ".json"))
    throw exbsp::usage_error("-o/--output: section writes .json, .off or .svg, not '" + out_path +
                             "'");
  const exbsp::triangle_soup soup = exbsp::cli::read_mesh_input(mesh, format, std::cin);
  exbsp::section_options options;
  options.exact_text = !off && !svg;
  const exbsp::section_result r = exbsp::section_with_cap(soup, plane, options);
  const std::string text = off   ? exbsp::section_off(r)
                           : svg ? exbsp::section_svg(r)
                                 : exbsp::section_json(r);
  if (out_path.empty())
    std::cout << text;
  else
    exbsp::write_file_atomically(out_path, text);
  return 0;
}

/// `exbsp render` options.
struct render_cli {
  std::string input;  ///< scene (.json), mesh, '-' or empty (the demo)
  std::string output = "exbsp.png";
  std::string format, view = "iso", size = "800x600", edges = "visible";
  std::string orbit_drag, trackball, kernel;
  std::size_t frames = 0;
  std::optional<std::size_t> max_fragments;
  bool strict = false, verbose = false, quiet = false;
};

/// `exbsp render`: a scene file, a mesh (fitted view, scene::mesh_scene) or the demo; a
/// progress line during long builds and a one-line summary on standard error.
int run_render(const render_cli& r) {
  exbsp::render_request request{r.input, r.output, r.verbose};
  request.strict = r.strict;
  if (!r.orbit_drag.empty()) request.orbit_drag = exbsp::cli::parse_drag_path(r.orbit_drag);
  request.frames = r.frames;
  request.trackball = r.trackball;
  request.kernel = r.kernel;
  request.max_fragments =
      r.max_fragments ? *r.max_fragments
                      : default_fragment_budget(r.kernel.empty() ? exbsp::build_options{}.kernel
                                                                 : exbsp::parse_kernel(r.kernel));
  const bool mesh_input = !r.input.empty() && !exbsp::has_extension(r.input, ".json");
  if (!mesh_input && !r.format.empty())
    throw exbsp::usage_error(
        "--format applies to a mesh input, not to " +
        (r.input.empty() ? std::string("the demo scene") : "the scene " + r.input));
  if (mesh_input) {
    exbsp::scene::mesh_view_options options;
    const auto size = exbsp::cli::parse_size(r.size);
    options.width = size[0];
    options.height = size[1];
    options.view = r.view;
    options.edges = r.edges;
    const std::string name = r.input == "-" ? "<stdin>" : r.input;
    auto soup = std::make_shared<const exbsp::triangle_soup>(
        exbsp::cli::read_mesh_input(r.input, r.format, std::cin));
    request.preloaded = exbsp::scene::mesh_scene(std::move(soup), name, options);
  }
  progress_line progress;
  if (r.quiet) progress.tty = false;
  request.progress = [&progress](const exbsp::build_progress& p) { progress(p); };
  exbsp::render_summary summary;
  try {
    summary = exbsp::render_command(request, std::cerr);
  } catch (...) {
    progress.finish();
    throw;
  }
  progress.finish();
  if (summary.non_finite > 0)
    std::cerr << "exbsp: warning: " << summary.non_finite
              << " fragments with a NaN or infinite corner (the " << summary.kernel
              << " kernel's rounded split points) were left out of the picture\n";
  if (!r.quiet) {
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
              << ": " << summary.triangles << " triangles -> " << summary.fragments << " fragments"
              << (summary.kernel.empty() ? std::string() : " (" + summary.kernel + ")") << ", "
              << times << "\n";
  }
  return 0;
}

/// `exbsp drawing` options (strings parsed by the drawing library, which names the flag).
struct drawing_cli {
  std::string input, output, views = "front,top,left,iso", projection = "first-angle";
  std::string sheet = "A3", scale = "auto", units = "mm", up = "z", line_widths, title, number,
              date;
  std::string formats = "pdf", kernel;
  std::vector<std::string> sections;
  bool lines_only = false, force = false, strict = false, quiet = false;
  double crease_deg = 30;
};

/// `exbsp drawing`: a sheet of a mesh or scene, or a drawing set of a folder. `given`: the
/// drawing options given as flags (they override a scene's "drawing" block).
int run_drawing(const drawing_cli& d, std::vector<std::string> given) {
  namespace dr = exbsp::drawing;
  exbsp::scene::drawing_request request;
  request.input = d.input;
  request.output = d.output;
  request.force = d.force;
  request.strict = d.strict;
  request.given = std::move(given);
  request.formats.clear();
  {
    std::string f;
    for (char c : d.formats + ",") {
      if (c != ',') {
        f += c;
        continue;
      }
      request.formats.push_back(f);
      f.clear();
    }
  }
  dr::drawing_options& o = request.options;
  o.views = d.views.empty() ? std::vector<std::string>{} : dr::parse_views(d.views);
  o.projection = dr::parse_projection(d.projection);
  o.sheet = dr::parse_paper(d.sheet);
  if (d.scale != "auto") o.scale = dr::parse_scale(d.scale);
  dr::unit_mm(d.units);
  o.units = d.units;
  o.up = d.up;
  for (const std::string& s : d.sections) {
    o.sections.push_back(dr::parse_section(s));
    for (std::size_t i = 0; i + 1 < o.sections.size(); ++i)
      if (o.sections[i].letter == o.sections.back().letter)
        throw exbsp::usage_error("--section: letter " + o.sections.back().letter +
                                 " is used twice");
  }
  o.lines_only = d.lines_only;
  o.title = d.title;
  o.number = d.number;
  o.date = d.date;
  o.crease_deg = d.crease_deg;
  if (!(d.crease_deg > 0 && d.crease_deg <= 180))
    throw exbsp::usage_error("--crease-deg: must be in (0, 180]");
  if (!d.line_widths.empty()) {
    const auto comma = d.line_widths.find(',');
    char* end = nullptr;
    const std::string a = d.line_widths.substr(0, comma);
    const std::string b = comma == std::string::npos ? "" : d.line_widths.substr(comma + 1);
    o.visible_width = std::strtod(a.c_str(), &end);
    const bool ok_a = !a.empty() && *end == 0;
    o.hidden_width = std::strtod(b.c_str(), &end);
    const bool ok_b = !b.empty() && *end == 0;
    if (!ok_a || !ok_b || !(o.visible_width > 0 && o.visible_width <= 5) ||
        !(o.hidden_width > 0 && o.hidden_width <= 5))
      throw exbsp::usage_error(
          "--line-widths: expected VISIBLE,HIDDEN in mm (each in (0, 5]), "
          "e.g. 0.35,0.18; got '" +
          d.line_widths + "'");
  }
  if (!d.kernel.empty()) o.build.kernel = exbsp::parse_kernel(d.kernel);
  o.build.max_fragments = default_fragment_budget(o.build.kernel);
  progress_line progress;
  if (d.quiet) progress.tty = false;
  o.build.progress = [&progress](const exbsp::build_progress& p) { progress(p); };
  std::ostringstream quiet_log;
  exbsp::scene::drawing_summary summary;
  try {
    summary = exbsp::scene::drawing_command(
        request, d.quiet ? static_cast<std::ostream&>(quiet_log) : std::cerr);
  } catch (...) {
    progress.finish();
    throw;
  }
  progress.finish();
  if (!d.quiet) {
    char times[48];
    std::snprintf(times, sizeof times, "%.2f s", summary.seconds);
    std::cerr << "exbsp: wrote " << summary.written.size() << " file"
              << (summary.written.size() == 1 ? "" : "s")
              << (summary.written.size() == 1 ? " (" + summary.written[0] + ")" : std::string())
              << (summary.skipped.empty()
                      ? std::string()
                      : ", kept " + std::to_string(summary.skipped.size()) + " finished before")
              << ", " << summary.triangles << " triangles, " << times << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // First, before any GMP number exists: out of memory in GMP throws, never aborts.
  exbsp::install_gmp_memory_functions();
  sanitize_omp_num_threads();
  start_thread_pool();
  CLI::App app{
      "exbsp: exact-predicate BSP trees of triangle meshes, back-to-front orders and rendering.\n"
      "Classification and splitting are exact (exbsp's own exact kernel by default), so trees and "
      "orders are\n"
      "the same on every machine."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("exbsp ") + exbsp::version_string,
                       "print the version and exit");

  build_cli build_opts, order_opts;
  bool json = false;
  auto* build = app.add_subcommand("build", "build the BSP tree of MESH and print its statistics");
  add_build_options(build, build_opts);
  build
      ->add_option("--save", build_opts.save,
                   "write the tree to a saved-tree file T.exbsp, for order and build")
      ->check(non_empty_path);
  build->add_flag("--json", json,
                  "print one JSON object: input_triangles, degenerate_input, fragments, splits, "
                  "nodes, depth, build_seconds, kernel, heuristic, ...");

  std::string eye, direction, order_out;
  auto* order = app.add_subcommand(
      "order", "write the back-to-front fragment order of MESH for an eye point or a direction");
  add_build_options(order, order_opts);
  auto* eye_opt = order->add_option("--eye", eye, "eye point X,Y,Z (perspective view)");
  auto* dir_opt = order->add_option("--direction", direction,
                                    "direction of projection X,Y,Z, from the eye into the scene "
                                    "(parallel view)");
  eye_opt->excludes(dir_opt);
  order->add_option("-o,--output", order_out, "output JSON file ('-' or none: standard output)")
      ->check(non_empty_path);

  render_cli r;
  auto* render = app.add_subcommand("render",
                                    "render SCENE.json, a mesh with a view fitted to it, or the "
                                    "built-in demo scene to PNG, SVG or PDF");
  render->add_option(
      "INPUT", r.input,
      "scene file (.json), or a mesh (.off, .obj, .ply, .stl; '-': standard input with --format) "
      "drawn lit with a view fitted to its bounding box; omit for the built-in demo");
  render
      ->add_option("-o,--output", r.output,
                   "output .png, .svg or .pdf ('-': PNG on standard output)")
      ->check(non_empty_path)
      ->capture_default_str();
  add_format_option(render, r.format);
  render
      ->add_option("--view", r.view,
                   "a mesh's fitted view: iso, front, back, left, right, top or bottom")
      ->check(CLI::IsMember(exbsp::scene::mesh_view_names()))
      ->capture_default_str();
  render->add_option("--size", r.size, "a mesh's image size WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  render
      ->add_option("--edges", r.edges,
                   "a mesh's edges in SVG/PDF output: none, visible or visible+hidden")
      ->check(CLI::IsMember({"none", "visible", "visible+hidden"}))
      ->capture_default_str();
  render
      ->add_option("--kernel", r.kernel,
                   "BSP kernel (default exact); epeck, gmpq; epick and double only to see what "
                   "rounding does")
      ->check(CLI::IsMember(exbsp::kernel_names()));
  render->add_option("--max-fragments", r.max_fragments, max_fragments_help())->check(not_negative);
  render->add_flag("--strict", r.strict, "unknown scene keys are errors (exit 2), not warnings");
  render->add_flag("-v,--verbose", r.verbose,
                   "print the pipeline stages that ran and their timings");
  render->add_flag("-q,--quiet", r.quiet, "no progress line and no summary line");
  render->add_option("--orbit-drag", r.orbit_drag,
                     "trackball orbit: screen pixel path X0,Y0:X1,Y1:... (y down) dragged over an "
                     "arcball; writes OUT_0000.png, OUT_0001.png, ... from one BSP build");
  render
      ->add_option(
          "--trackball", r.trackball,
          "orbit rotation: arcball (Shoemake, twice the arc; default) or virtual (the classic "
          "virtual trackball: the point under the cursor follows it); overrides the scene's "
          "\"trackball\"")
      ->check(CLI::IsMember({"arcball", "virtual"}));
  render
      ->add_option(
          "--frames", r.frames,
          "number of orbit frames (the drag path resampled evenly; default: one per point)")
      ->check(not_negative);

  std::string section_mesh, section_format, section_plane_text, section_out;
  auto* section = app.add_subcommand(
      "section",
      "cut MESH exactly by a plane: kept part, outline loops and (closed meshes) the cap");
  section
      ->add_option("MESH", section_mesh,
                   "mesh file: .off, .obj, .ply or .stl ('-': standard input, with --format)")
      ->required();
  add_format_option(section, section_format);
  section
      ->add_option("--plane", section_plane_text,
                   "A,B,C,D: the plane A*x+B*y+C*z+D = 0; the side where it is >= 0 is kept")
      ->required();
  section
      ->add_option("-o,--output", section_out,
                   "OUT.json (kept, outline, cap with exact rationals; default: standard output), "
                   "OUT.off (kept and cap as one mesh) or OUT.svg (the outline in the cut plane)")
      ->check(non_empty_path);

  std::string clip_in, clip_out, clip_algorithm;
  bool clip_verbose = false;
  auto* clip = app.add_subcommand("clip",
                                  "clip the segments and polygons of INPUT.json against its region "
                                  "(rect, box, convex, halfspaces)");
  clip->add_option("INPUT", clip_in,
                   "clip input (JSON): {\"region\": ..., \"segments\": ..., \"polygons\": ...}")
      ->required();
  clip->add_option(
          "--algorithm", clip_algorithm,
          "segment clipper: cohen-sutherland (default) or liang-barsky (rect or box regions); "
          "polygons are always clipped by sutherland-hodgman (any convex region)")
      ->check(CLI::IsMember({"cohen-sutherland", "liang-barsky", "sutherland-hodgman"}));
  clip->add_option("-o,--output", clip_out,
                   "output .json or .svg (default: JSON on standard output)")
      ->check(non_empty_path);
  clip->add_flag("-v,--verbose", clip_verbose,
                 "print each segment endpoint's Cohen-Sutherland outcode");

  drawing_cli dc;
  auto* drawing = app.add_subcommand("drawing",
                                     "a drawing sheet (ISO views, sections, title block) of a "
                                     "mesh, a scene or a folder of meshes, "
                                     "as SVG, PDF or DXF");
  drawing
      ->add_option("INPUT", dc.input,
                   "mesh (.off, .obj, .ply, .stl), scene (.json: its meshes as one part) or a "
                   "folder (one sheet per mesh)")
      ->required();
  drawing
      ->add_option("-o,--output", dc.output,
                   "OUT.svg, OUT.pdf or OUT.dxf; for a folder input, an output folder")
      ->required()
      ->check(non_empty_path);
  drawing
      ->add_option("--views", dc.views,
                   "views: front, top, left, right, bottom, rear, iso (comma-separated)")
      ->capture_default_str();
  drawing->add_option("--projection", dc.projection, "first-angle (ISO E) or third-angle (ISO A)")
      ->capture_default_str();
  drawing->add_option("--sheet", dc.sheet, "A4, A3, A2, A1, A0 (landscape) or WxH in mm")
      ->capture_default_str();
  drawing
      ->add_option("--scale", dc.scale, "1:N, N:1, or auto (the largest ISO 5455 scale that fits)")
      ->capture_default_str();
  drawing->add_option("--units", dc.units, "model units: mm, cm, m or in")->capture_default_str();
  drawing
      ->add_option("--up", dc.up,
                   "the model's up axis: z (CAD: front looks from -y) or y (front looks from +z, "
                   "as render --view front)")
      ->check(CLI::IsMember({"z", "y"}))
      ->capture_default_str();
  drawing->add_option("--section", dc.sections,
                      "X=a,b,c,d: section view X-X, the cut by a*x+b*y+c*z+d = 0 seen from the "
                      "removed side (repeatable)");
  drawing->add_flag("--lines-only", dc.lines_only, "no shaded fills: the classic line drawing");
  drawing->add_option("--title", dc.title, "title block: title (default: the file name)");
  drawing->add_option("--number", dc.number, "title block: drawing number");
  drawing->add_option("--date", dc.date,
                      "title block: date of issue (default: today, or SOURCE_DATE_EPOCH)");
  drawing->add_option("--line-widths", dc.line_widths,
                      "VISIBLE,HIDDEN line widths in mm (default 0.5,0.25)");
  drawing->add_option("--crease-deg", dc.crease_deg, "feature edges: dihedral angle over this")
      ->capture_default_str();
  drawing
      ->add_option("--formats", dc.formats,
                   "folder input: the files of each sheet, e.g. pdf,svg,dxf")
      ->capture_default_str();
  drawing->add_flag("--force", dc.force, "folder input: redo sheets that are already finished");
  drawing->add_option("--kernel", dc.kernel, "BSP kernel (default exact)")
      ->check(CLI::IsMember(exbsp::kernel_names()));
  drawing->add_flag("--strict", dc.strict, "unknown scene keys are errors (exit 2), not warnings");
  drawing->add_flag("-q,--quiet", dc.quiet, "no progress lines and no summary line");

  {
    std::vector<std::string> args(argv + 1, argv + argc);
    const std::string typo = exbsp::cli::misspelling(app, args);
    if (!typo.empty()) {
      std::cerr << "exbsp: error: " << typo << "\n"
                << "run 'exbsp --help' for usage\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n"
              << "run 'exbsp --help' for usage\n";
    return 2;
  }

  if (app.get_subcommands().empty()) {
    std::cerr
        << "exbsp: error: a command is required: build, order, render, section, clip or drawing\n"
        << "run 'exbsp --help' for usage\n";
    return 2;
  }
  try {
    if (*build) return finish_standard_output(run_build(build_opts, json));
    if (*order) {
      if (eye.empty() && direction.empty())
        throw exbsp::usage_error("order needs --eye X,Y,Z or --direction X,Y,Z");
      return finish_standard_output(run_order(order_opts, eye, direction, order_out));
    }
    if (*section)
      return finish_standard_output(
          run_section(section_mesh, section_format, section_plane_text, section_out));
    if (*clip) {
      exbsp::scene::clip_command(clip_in, clip_out, clip_algorithm, clip_verbose, std::cout,
                                 std::cerr);
      return finish_standard_output(0);
    }
    if (*render) {
      return finish_standard_output(run_render(r));
    }
    if (*drawing) {
      std::vector<std::string> given;
      const std::pair<const char*, const char*> flags[] = {{"--title", "title"},
                                                           {"--number", "number"},
                                                           {"--date", "date"},
                                                           {"--views", "views"},
                                                           {"--projection", "projection"},
                                                           {"--sheet", "sheet"},
                                                           {"--scale", "scale"},
                                                           {"--units", "units"},
                                                           {"--section", "sections"},
                                                           {"--lines-only", "lines_only"},
                                                           {"--line-widths", "line_widths"},
                                                           {"--crease-deg", "crease_deg"}};
      for (const auto& [flag, name] : flags)
        if (drawing->count(flag) > 0) given.emplace_back(name);
      return run_drawing(dc, std::move(given));
    }
  } catch (const exbsp::limit_error& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n";
    if ((*build || *order || *render) &&
        std::string(e.what()).find("--max-fragments") != std::string::npos)
      std::cerr << "exbsp: the limit is --max-fragments (default: from the available memory); "
                   "raise it with "
                   "--max-fragments N, or 0 for no limit\n";
    return 3;
  } catch (const exbsp::error& e) {  // input, scene, usage and output errors
    std::cerr << "exbsp: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "exbsp: error: out of memory (lower --max-fragments, or use a smaller input)\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
