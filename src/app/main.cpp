// exbsp command line (DESIGN.md section 4): glue only. Library exceptions become messages
// "exbsp: error: ..." on stderr and exit codes: 2 bad input, bad usage or an output that cannot
// be written; 3 resource limit (--max-fragments, whose default comes from the available
// memory, or out of memory).
#include <CLI/CLI.hpp>
#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "bsp/engine.h"
#include "core/atomic_file.h"
#include "core/version.h"
#include "clip/section.h"
#include "core/errors.h"
#include "mesh/gmp_memory.h"
#include "mesh/mesh_io.h"
#include "scene/clip_input.h"
#include "scene/render.h"

namespace {

using exbsp::vec3d;

/// Parses "X,Y,Z" into three finite doubles (nearest to the decimal text).
vec3d parse_triple(const std::string& text, const std::string& option) {
  vec3d v{};
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int k = 0; k < 3; ++k) {
    const auto r = std::from_chars(p, end, v[k]);
    if (r.ec != std::errc() || !std::isfinite(v[k]))
      throw exbsp::usage_error(option + " expects three finite numbers X,Y,Z, got '" + text + "'");
    p = r.ptr;
    if (k < 2) {
      if (p == end || *p != ',')
        throw exbsp::usage_error(option + " expects three numbers separated by commas, got '" + text + "'");
      ++p;
    }
  }
  if (p != end) throw exbsp::usage_error(option + " expects exactly three numbers, got '" + text + "'");
  return v;
}

/// Parses "A,B,C,D" into four finite doubles; throws usage_error naming --plane otherwise.
exbsp::section_plane parse_plane(const std::string& text) {
  exbsp::section_plane p{};
  const char* s = text.data();
  const char* end = text.data() + text.size();
  for (int k = 0; k < 4; ++k) {
    const auto r = std::from_chars(s, end, p[k]);
    if (r.ec != std::errc() || !std::isfinite(p[k]) || (k < 3 && (r.ptr == end || *r.ptr != ',')) ||
        (k == 3 && r.ptr != end))
      throw exbsp::usage_error("--plane expects four finite numbers A,B,C,D (the plane A*x+B*y+C*z+D = 0), got '" +
                               text + "'");
    s = r.ptr + (k < 3 ? 1 : 0);
  }
  exbsp::check_section_plane(p, "--plane");
  return p;
}

std::string format_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// ---- resource defaults and limits (the library's defaults stay explicit: 0 = no limit) ----

/// Bytes one tree fragment costs in a build, tree nodes and lists included: about 1,000
/// measured (naive heuristic on 128 + 128 sticks: 2.1 M fragments in 2.1 GB; 121 k fragments
/// in 108 MB resident), rounded up for the heavier gmpq numbers.
constexpr std::uint64_t bytes_per_fragment = 1300;

/// Bytes this process may still use: MemAvailable (/proc/meminfo), and no more than the
/// address-space limit (RLIMIT_AS) when there is one. 0 when unknown.
std::uint64_t available_memory_bytes() {
  std::uint64_t available = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") {
      available = kib * 1024;
      break;
    }
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    const auto cap = static_cast<std::uint64_t>(as.rlim_cur);
    available = available ? std::min(available, cap) : cap;
  }
  return available;
}

/// The default --max-fragments: half the available memory at bytes_per_fragment each (the
/// other half for the input, the output and the allocator's slack), at least 10,000;
/// 0 (no limit) when the available memory is unknown.
std::size_t default_fragment_budget() {
  const std::uint64_t bytes = available_memory_bytes();
  if (bytes == 0) return 0;
  return static_cast<std::size_t>(std::max<std::uint64_t>(bytes / 2 / bytes_per_fragment, 10000));
}

/// The most threads --threads accepts: 4 per hardware thread, at most 1024 (libgomp crashes
/// or fails on team sizes in the tens of thousands).
unsigned max_threads() {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  return std::min(1024u, 4 * hw);
}

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
  const bool ok = r.ec == std::errc() && r.ptr == first.data() + first.size() && value >= 1 && value <= max_threads();
  if (ok) return;
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  std::cerr << "exbsp: warning: OMP_NUM_THREADS='" << text.substr(0, 40) << "' ignored (expected 1.."
            << max_threads() << "); using " << hw << " threads\n";
  omp_set_num_threads(static_cast<int>(hw));
}

/// Starts OpenMP's thread pool now: libgomp cannot report an allocation failure (it prints
/// "Out of memory allocating N bytes" and exits 1), so the pool and its team are made while
/// memory is plentiful, and later parallel regions of the same size reuse them.
void start_thread_pool() {
#pragma omp parallel
  {
  }
}

struct build_cli {
  std::string mesh;
  std::string kernel = exbsp::to_string(exbsp::build_options{}.kernel);
  std::string heuristic = exbsp::default_heuristic();
  std::uint64_t seed = 0;
  std::size_t max_fragments = 0;
  unsigned threads = 0;
  std::string save;                  ///< build --save: write the tree here
  const CLI::App* command = nullptr;  ///< to tell options given on the command line from defaults
};

/// Rejects an empty output name (`-o ""`): it would silently mean the default output.
const CLI::Validator non_empty_path(
    [](const std::string& s) { return s.empty() ? std::string("empty file name") : std::string(); }, "FILE");

/// Rejects a negative integer for an unsigned option: CLI11 would wrap "-1" to 2^64 - 1.
const CLI::Validator not_negative(
    [](const std::string& s) {
      const std::size_t i = s.find_first_not_of(" \t");
      return i != std::string::npos && s[i] == '-' ? "must not be negative, got " + s : std::string();
    },
    "");

void add_build_options(CLI::App* cmd, build_cli& o) {
  o.command = cmd;
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply or .stl) or a saved tree (.exbsp, build --save)")
      ->required();
  cmd->add_option("--kernel", o.kernel,
                  "number type: exact (exbsp's own exact points, default), epeck (CGAL lazy exact), "
                  "gmpq (plain exact rationals), epick (exact predicates, rounded splits), "
                  "double (plain double)")
      ->check(CLI::IsMember({"exact", "epeck", "gmpq", "epick", "double"}))
      ->capture_default_str();
  cmd->add_option("--heuristic", o.heuristic,
                  "splitter choice: naive (first triangle), min-split (fewest straddlers), "
                  "sampled (16 seeded candidates, split/balance score), random (seeded)")
      ->check(CLI::IsMember(exbsp::heuristic_names()))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "seed of the randomised heuristics")
      ->check(not_negative)
      ->capture_default_str();
  cmd->add_option("--max-fragments", o.max_fragments,
                  "stop with exit status 3 when the tree would need more fragments (0: no limit; "
                  "default: half the available memory at " + std::to_string(bytes_per_fragment) +
                      " bytes per fragment)")
      ->check(not_negative)
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "threads for candidate evaluation (0: all cores)")
      ->check(CLI::Range(0u, max_threads()));
}

/// Progress line on a terminal for builds that run longer than a second.
struct progress_line {
  bool tty = ::isatty(2) != 0;
  bool shown = false;
  void operator()(const exbsp::build_progress& p) {
    if (!tty || p.seconds < 1.0) return;
    std::fprintf(stderr, "\r\033[Kexbsp: building: %zu of %zu fragments placed, %zu nodes, %.1f s",
                 p.fragments_placed, p.fragments_total, p.nodes, p.seconds);
    std::fflush(stderr);
    shown = true;
  }
  void finish() {
    if (shown) std::fprintf(stderr, "\r\033[K");
  }
};

/// A saved tree (docs/tree-file.md): --kernel, --heuristic and --seed may only repeat what the
/// tree was built with (they cannot change a built tree); --threads and --max-fragments, which
/// only steer a build, are ignored.
exbsp::bsp load_tree(const build_cli& o, double* load_seconds) {
  const auto start = std::chrono::steady_clock::now();
  exbsp::bsp tree = exbsp::bsp::load(o.mesh);
  if (load_seconds) *load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const exbsp::build_stats& s = tree.stats();
  const auto conflict = [&](const char* option, const std::string& given, const std::string& saved) {
    if (o.command && o.command->count(option) && given != saved)
      throw exbsp::usage_error(o.mesh + " is a saved tree built with " + option + " " + saved + "; " + option + " " +
                               given + " cannot change it (build from the mesh instead)");
  };
  conflict("--kernel", o.kernel, s.kernel);
  conflict("--heuristic", o.heuristic, s.heuristic);
  conflict("--seed", std::to_string(o.seed), std::to_string(s.seed));
  return tree;
}

exbsp::bsp build_tree(const build_cli& o, progress_line& progress, double* load_seconds = nullptr) {
  if (exbsp::bsp::is_saved_tree(o.mesh)) return load_tree(o, load_seconds);
  const exbsp::triangle_soup soup = exbsp::read_mesh(o.mesh);
  exbsp::build_options options;
  options.kernel = exbsp::parse_kernel(o.kernel);
  options.heuristic = o.heuristic;
  options.seed = o.seed;
  options.max_fragments = o.max_fragments;
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
  return {{"input_triangles", s.input_triangles}, {"degenerate_input", s.degenerate_input},
          {"fragments", s.fragments},             {"splits", s.splits},
          {"nodes", s.nodes},                     {"depth", s.depth},
          {"build_seconds", s.build_seconds},     {"peak_rss_bytes", s.peak_rss_bytes},
          {"kernel", s.kernel},                   {"heuristic", s.heuristic}};
}

int run_build(const build_cli& o, bool json) {
  progress_line progress;
  double load_seconds = -1;
  const exbsp::bsp tree = build_tree(o, progress, &load_seconds);
  if (!o.save.empty()) tree.save(o.save);
  const auto& s = tree.stats();
  if (json) {
    nlohmann::json j = stats_json(s);
    j["mesh"] = o.mesh;
    j["seed"] = s.seed;
    if (load_seconds >= 0) j["load_seconds"] = load_seconds;  // a saved tree: build_seconds is its build's
    std::cout << j.dump() << "\n";
  } else {
    if (load_seconds >= 0) std::cout << "saved tree loaded in " << load_seconds << " s; ";
    std::cout << o.mesh << ": " << s.input_triangles << " input triangles (" << s.degenerate_input
              << " degenerate, skipped) -> " << s.fragments << " fragments, " << s.splits
              << " splits, " << s.nodes << " nodes, depth " << s.depth << "; " << s.kernel << ", "
              << s.heuristic << ", " << s.build_seconds << " s\n";
  }
  return 0;
}

int run_order(const build_cli& o, const std::string& eye, const std::string& direction,
              const std::string& out_path) {
  const bool use_eye = !eye.empty();
  const vec3d where = use_eye ? parse_triple(eye, "--eye") : parse_triple(direction, "--direction");
  progress_line progress;
  const exbsp::bsp tree = build_tree(o, progress);
  const auto order = use_eye ? tree.order_from_eye(where) : tree.order_for_direction(where);
  const bool exact = exbsp::is_exact(tree.kernel());

  std::string out;
  out.reserve(order.size() * (exact ? 400 : 200) + 64);
  out += use_eye ? "{\"eye\": [" : "{\"direction\": [";
  for (int k = 0; k < 3; ++k) out += (k ? ", " : "") + format_double(where[k]);
  out += "],\n \"kernel\": \"" + exbsp::to_string(tree.kernel()) + "\", \"heuristic\": \"" +
         tree.stats().heuristic + "\",\n \"fragments\": [";
  for (std::size_t n = 0; n < order.size(); ++n) {
    const exbsp::fragment_d f = tree.fragment(order[n]);
    out += n ? ",\n  {\"face\": " : "\n  {\"face\": ";
    out += std::to_string(f.face) + ", \"v\": [";
    for (int i = 0; i < 3; ++i) {
      out += i ? ", [" : "[";
      for (int k = 0; k < 3; ++k) out += (k ? ", " : "") + format_double(f.v[i][k]);
      out += "]";
    }
    out += "]";
    if (exact) {
      const exbsp::exact_triangle e = tree.fragment_exact(order[n]);
      out += ", \"exact\": [";
      for (int i = 0; i < 3; ++i) {
        out += i ? ", [" : "[";
        for (int k = 0; k < 3; ++k) out += std::string(k ? ", \"" : "\"") + e[i][k] + "\"";
        out += "]";
      }
      out += "]";
    }
    out += "}";
  }
  out += "\n ]}\n";
  if (out_path.empty())
    std::cout << out;
  else
    exbsp::write_file_atomically(out_path, out);
  return 0;
}

/// `exbsp section`: JSON (default, to standard output), OFF or SVG by the output's extension.
int run_section(const std::string& mesh, const std::string& plane_text, const std::string& out_path) {
  const exbsp::section_plane plane = parse_plane(plane_text);
  const auto ends_with = [&](const char* ext) {
    const std::size_t n = std::strlen(ext);
    return out_path.size() >= n && out_path.compare(out_path.size() - n, n, ext) == 0;
  };
  const bool off = ends_with(".off"), svg = ends_with(".svg");
  if (!out_path.empty() && out_path != "-" && !off && !svg && !ends_with(".json"))
    throw exbsp::usage_error("-o/--output: section writes .json, .off or .svg, not '" + out_path + "'");
  const exbsp::triangle_soup soup = exbsp::read_mesh(mesh);
  exbsp::section_options options;
  options.exact_text = !off && !svg;
  const exbsp::section_result r = exbsp::section(soup, plane, options);
  const std::string text = off ? exbsp::section_off(r) : svg ? exbsp::section_svg(r) : exbsp::section_json(r);
  if (out_path.empty())
    std::cout << text;
  else
    exbsp::write_file_atomically(out_path, text);
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
      "Classification and splitting are exact (exbsp's own exact kernel by default), so trees and orders are\n"
      "the same on every machine."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("exbsp ") + exbsp::version_string,
                       "print the version and exit");

  build_cli build_opts, order_opts;
  build_opts.max_fragments = order_opts.max_fragments = default_fragment_budget();
  bool json = false;
  auto* build = app.add_subcommand("build", "build the BSP tree of MESH and print its statistics");
  add_build_options(build, build_opts);
  build->add_option("--save", build_opts.save, "write the tree to a saved-tree file T.exbsp, for order and build")
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

  std::string scene_path, render_out = "exbsp.png";
  bool verbose = false;
  auto* render = app.add_subcommand(
      "render", "render SCENE.json (or the built-in demo scene) to PNG, SVG or PDF");
  render->add_option("SCENE", scene_path, "scene file (JSON); omit for the built-in demo");
  render->add_option("-o,--output", render_out, "output .png, .svg or .pdf ('-': PNG on standard output)")
      ->check(non_empty_path)
      ->capture_default_str();
  bool strict = false;
  render->add_flag("--strict", strict, "unknown scene keys are errors (exit 2), not warnings");
  render->add_flag("-v,--verbose", verbose, "print the pipeline stages that ran and their timings");
  std::string orbit_drag;
  std::size_t orbit_frames = 0;
  render->add_option("--orbit-drag", orbit_drag,
                     "trackball orbit: screen pixel path X0,Y0:X1,Y1:... (y down) dragged over an "
                     "arcball; writes OUT_0000.png, OUT_0001.png, ... from one BSP build");
  std::string trackball;
  render->add_option("--trackball", trackball,
                     "orbit rotation: arcball (Shoemake, twice the arc; default) or virtual (the classic "
                     "virtual trackball: the point under the cursor follows it); overrides the scene's \"trackball\"")
      ->check(CLI::IsMember({"arcball", "virtual"}));
  render->add_option("--frames", orbit_frames,
                     "number of orbit frames (the drag path resampled evenly; default: one per point)");

  std::string section_mesh, section_plane_text, section_out;
  auto* section = app.add_subcommand(
      "section", "cut MESH exactly by a plane: kept part, outline loops and (closed meshes) the cap");
  section->add_option("MESH", section_mesh, "mesh file: .off, .obj, .ply or .stl")->required();
  section->add_option("--plane", section_plane_text,
                      "A,B,C,D: the plane A*x+B*y+C*z+D = 0; the side where it is >= 0 is kept")
      ->required();
  section->add_option("-o,--output", section_out,
                      "OUT.json (kept, outline, cap with exact rationals; default: standard output), "
                      "OUT.off (kept and cap as one mesh) or OUT.svg (the outline in the cut plane)")
      ->check(non_empty_path);

  std::string clip_in, clip_out, clip_algorithm;
  bool clip_verbose = false;
  auto* clip = app.add_subcommand(
      "clip", "clip the segments and polygons of INPUT.json against its region (rect, box, convex, halfspaces)");
  clip->add_option("INPUT", clip_in, "clip input (JSON): {\"region\": ..., \"segments\": ..., \"polygons\": ...}")
      ->required();
  clip->add_option("--algorithm", clip_algorithm,
                   "segment clipper: cohen-sutherland (default) or liang-barsky (rect or box regions); "
                   "polygons are always clipped by sutherland-hodgman (any convex region)")
      ->check(CLI::IsMember({"cohen-sutherland", "liang-barsky", "sutherland-hodgman"}));
  clip->add_option("-o,--output", clip_out, "output .json or .svg (default: JSON on standard output)")
      ->check(non_empty_path);
  clip->add_flag("-v,--verbose", clip_verbose, "print each segment endpoint's Cohen-Sutherland outcode");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n" << "run 'exbsp --help' for usage\n";
    return 2;
  }

  if (app.get_subcommands().empty()) {
    std::cerr << "exbsp: error: a command is required: build, order, render, section or clip\n"
              << "run 'exbsp --help' for usage\n";
    return 2;
  }
  try {
    if (*build) return run_build(build_opts, json);
    if (*order) {
      if (eye.empty() && direction.empty())
        throw exbsp::usage_error("order needs --eye X,Y,Z or --direction X,Y,Z");
      return run_order(order_opts, eye, direction, order_out);
    }
    if (*section) return run_section(section_mesh, section_plane_text, section_out);
    if (*clip) {
      exbsp::scene::clip_command(clip_in, clip_out, clip_algorithm, clip_verbose, std::cout, std::cerr);
      return 0;
    }
    if (*render) {
      exbsp::render_request request{scene_path, render_out, verbose};
      request.strict = strict;
      if (!orbit_drag.empty()) request.orbit_drag = exbsp::parse_drag_path(orbit_drag);
      request.frames = orbit_frames;
      request.trackball = trackball;
      exbsp::render_command(request, std::cerr);
      return 0;
    }
  } catch (const exbsp::limit_error& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n";
    if (*build || *order)
      std::cerr << "exbsp: the limit is --max-fragments (default: from the available memory); raise it with "
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
