// SPDX-License-Identifier: LGPL-3.0-or-later
// bench_section: time of exbsp::section_with_cap (what `exbsp section` runs: the cut and its
// exact cap) on one mesh (default data/meshes/fandisk.off) through its bounding-box centre,
// with the default exact kernel (Epeck). Prints one JSON line per
// plane: median, min and max wall seconds over --repeats runs, with the section's counters.
// The goal of issue 12 is fandisk (12,946 triangles) under 0.2 s, exact text included.
// Never a timed test: bench_smoke_section only checks that it runs.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <exbsp/clip/section.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/mesh/mesh_io.h>

int main(int argc, char** argv) {
  CLI::App app{"bench_section: wall time of exact sections (clip/section.h)"};
  std::string mesh = std::string(EXBSP_SOURCE_DIR) + "/data/meshes/fandisk.off";
  int repeats = 5;
  bool exact_text = true;
  app.add_option("MESH", mesh, "mesh file")->capture_default_str();
  app.add_option("--repeats", repeats, "runs per plane (median reported)")->capture_default_str();
  app.add_option("--exact-text", exact_text,
                 "also write the exact rationals as text (as `exbsp section` JSON)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  const exbsp::triangle_soup soup = exbsp::read_mesh(mesh);
  exbsp::vec3d lo = soup.vertices.at(0), hi = lo;
  for (const auto& v : soup.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  const exbsp::vec3d c{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const std::vector<std::pair<const char*, exbsp::section_plane>> planes{
      {"z-mid", {0, 0, 1, -c[2]}},
      {"slanted", {0.3, -0.5, 0.8, -(0.3 * c[0] - 0.5 * c[1] + 0.8 * c[2])}}};
  exbsp::section_options options;
  options.exact_text = exact_text;
  for (const auto& [name, plane] : planes) {
    std::vector<double> times;
    exbsp::section_result r;
    for (int i = 0; i < std::max(1, repeats); ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      r = exbsp::section_with_cap(soup, plane, options);
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(times.begin(), times.end());
    std::printf(
        "{\"mesh\": \"%s\", \"plane\": \"%s\", \"triangles\": %zu, \"closed\": %s, \"split\": %zu, "
        "\"kept\": %zu, \"cap_triangles\": %zu, \"loops\": %zu, \"exact_text\": %s, "
        "\"median_seconds\": %.4f, "
        "\"min_seconds\": %.4f, \"max_seconds\": %.4f}\n",
        mesh.c_str(), name, soup.triangles.size(), r.closed ? "true" : "false", r.stats.split,
        r.kept.size(), r.cap.size(), r.outline.size(), exact_text ? "true" : "false",
        times[times.size() / 2], times.front(), times.back());
  }
  return 0;
}
