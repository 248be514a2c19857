// SPDX-License-Identifier: LGPL-3.0-or-later
// bench_tree_file: saved trees (docs/tree-file.md) against builds. For each mesh: one build,
// then save and load `repeats` times (median wall time), the file's size per fragment, and
// the time until a viewer can draw (tree + fragments in doubles + one order) from the mesh
// and from the file. Checks on the way that the loaded tree has the same order and saves to
// the same bytes. One JSON line per mesh on stdout, a table on stderr.
//
//   build/bench/bench_tree_file data/meshes/fandisk.off data/meshes/refined_elephant.off
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/gmp_memory.h>
#include <exbsp/mesh/mesh_io.h>

namespace {

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t) {
  return std::chrono::duration<double>(clock_type::now() - t).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

/// Seconds until a viewer can draw: fragments in doubles and one back-to-front order.
double ready_to_draw(const exbsp::bsp& tree) {
  const auto t = clock_type::now();
  const auto frags = tree.fragments_double();
  const auto order = tree.order_from_eye({1e3, 2e3, 3e3});
  if (frags.size() != order.size()) throw std::runtime_error("order and fragments disagree");
  return seconds_since(t);
}

}  // namespace

int main(int argc, char** argv) {
  exbsp::install_gmp_memory_functions();
  CLI::App app{"bench_tree_file: load time and size of saved trees against build time"};
  std::vector<std::string> meshes;
  std::string kernel = "exact", heuristic = exbsp::default_heuristic(),
              dir = std::filesystem::temp_directory_path();
  int repeats = 5;
  app.add_option("MESH", meshes, "mesh files")->required();
  app.add_option("--kernel", kernel, "kernel")->capture_default_str();
  app.add_option("--heuristic", heuristic, "heuristic")->capture_default_str();
  app.add_option("--repeats", repeats, "saves and loads per mesh (median)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  app.add_option("--dir", dir, "directory for the temporary tree files")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::fprintf(stderr, "%-22s %9s %9s %9s %8s %9s %9s %8s %8s %10s %10s\n", "mesh", "triangles",
               "fragments", "build s", "save s", "load s", "build/ld", "file MB", "B/frag",
               "draw(mesh)", "draw(file)");
  try {
    for (const std::string& mesh : meshes) {
      const exbsp::triangle_soup soup = exbsp::read_mesh(mesh);
      exbsp::build_options options;
      options.kernel = exbsp::parse_kernel(kernel);
      options.heuristic = heuristic;
      auto t = clock_type::now();
      const exbsp::bsp tree = exbsp::bsp::build(soup, options);
      const double build_seconds = seconds_since(t);
      const double draw_built = ready_to_draw(tree);

      const std::string path = (std::filesystem::path(dir) / "bench_tree_file.exbsp").string();
      std::vector<double> saves, loads;
      std::uintmax_t bytes = 0;
      double draw_loaded = 0;
      for (int r = 0; r < repeats; ++r) {
        t = clock_type::now();
        tree.save(path);
        saves.push_back(seconds_since(t));
        bytes = std::filesystem::file_size(path);
        t = clock_type::now();
        const exbsp::bsp loaded = exbsp::bsp::load(path);
        loads.push_back(seconds_since(t));
        if (r == 0) {
          draw_loaded = ready_to_draw(loaded);
          if (loaded.order_from_eye({3, -4, 5}) != tree.order_from_eye({3, -4, 5}) ||
              loaded.serialize() != tree.serialize())
            throw std::runtime_error(mesh + ": the loaded tree differs from the built one");
        }
      }
      std::filesystem::remove(path);
      const double load = median(loads), save = median(saves);
      const std::size_t fragments = tree.fragment_count();
      const double per_fragment =
          fragments ? static_cast<double>(bytes) / static_cast<double>(fragments) : 0;
      nlohmann::json j{{"mesh", mesh},
                       {"kernel", kernel},
                       {"heuristic", heuristic},
                       {"input_triangles", tree.stats().input_triangles},
                       {"fragments", fragments},
                       {"nodes", tree.stats().nodes},
                       {"build_seconds", build_seconds},
                       {"save_seconds", save},
                       {"load_seconds", load},
                       {"build_over_load", load > 0 ? build_seconds / load : 0},
                       {"file_bytes", bytes},
                       {"bytes_per_fragment", per_fragment},
                       {"ready_to_draw_from_mesh_seconds", build_seconds + draw_built},
                       {"ready_to_draw_from_file_seconds", load + draw_loaded},
                       {"repeats", repeats}};
      std::cout << j.dump() << std::endl;
      std::fprintf(stderr, "%-22s %9zu %9zu %9.3f %8.3f %9.3f %8.1fx %8.2f %8.1f %10.3f %10.3f\n",
                   std::filesystem::path(mesh).filename().string().c_str(),
                   tree.stats().input_triangles, fragments, build_seconds, save, load,
                   load > 0 ? build_seconds / load : 0, static_cast<double>(bytes) / 1e6,
                   per_fragment, build_seconds + draw_built, load + draw_loaded);
    }
  } catch (const std::exception& e) {
    std::cerr << "bench_tree_file: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
