// SPDX-License-Identifier: LGPL-3.0-or-later
// bench_vector: vector output per frame (SVG and PDF) for the painter's stack and the
// visible-region drawing (include/exbsp/view/vector_drawing.h), with and without edges.
//
// Per input: one BSP build, then for each mode `frames` frames of order + transform+clip +
// the vector stage ("svg" or "pdf") for a fixed perspective camera (the view of bench_render:
// eye along (1, 0.6, 0.4) from the centre, one diagonal away, fovy 40, lighting on so faces
// differ). Reported per mode: median seconds of the vector stage alone and of the whole frame
// (order + transform+clip + vector), the vector stage's process CPU time (single-threaded: the
// wall time it would take on an idle machine), document bytes, and paths (<path> elements).
// One JSON line per input and mode on stdout (and --out). Never a timed test.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <exbsp/view/camera.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
#include "bench_view.h"
#include "generators.h"
#include "view/effects.h"
#include "view/lighting.h"

namespace {

using namespace exbsp;
using json = nlohmann::json;
using clock_type = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "bench_vector: SVG/PDF bytes, paths and time per frame, painter's stack vs visible regions");
  std::vector<std::string> inputs;
  std::size_t frames = 5;
  int width = 800, height = 600;
  std::string out_path, keep_dir;
  app.add_option("inputs", inputs, "mesh:PATH or soup:N (see bench/generators.h)")->required();
  app.add_option("--frames", frames, "frames per mode (median reported)")->capture_default_str();
  app.add_option("--width", width)->capture_default_str();
  app.add_option("--height", height)->capture_default_str();
  app.add_option("--out", out_path, "append the JSON lines to this file");
  app.add_option("--keep", keep_dir, "write each mode's last document into this directory");
  std::string only;
  app.add_option("--mode", only, "run only the modes whose name contains this text");
  CLI11_PARSE(app, argc, argv);

  std::ofstream out;
  if (!out_path.empty()) out.open(out_path, std::ios::app);
  struct mode {
    const char* name;
    view::output_kind kind;
    view::vector_options options;
  };
  using vo = view::vector_options;
  const std::vector<mode> modes = {
      {"painter svg", view::output_kind::svg, {vo::mode_kind::painter, vo::edges_kind::none, 30}},
      {"visible svg", view::output_kind::svg, {vo::mode_kind::visible, vo::edges_kind::none, 30}},
      {"visible svg, edges",
       view::output_kind::svg,
       {vo::mode_kind::visible, vo::edges_kind::visible, 30}},
      {"visible svg, edges+hidden",
       view::output_kind::svg,
       {vo::mode_kind::visible, vo::edges_kind::visible_hidden, 30}},
      {"painter pdf", view::output_kind::pdf, {vo::mode_kind::painter, vo::edges_kind::none, 30}},
      {"visible pdf, edges",
       view::output_kind::pdf,
       {vo::mode_kind::visible, vo::edges_kind::visible, 30}},
  };
  for (const std::string& spec : inputs) {
    const bench::input_spec in = bench::parse_input_spec(spec);
    view::frame f;
    f.soup = bench::load_input(in);
    f.face_colors.assign(f.soup.face_count, view::rgb8{200, 200, 210});
    bench::set_bench_view(f, width, height);
    view::build_stage(f);
    for (const mode& m : modes) {
      if (std::string(m.name).find(only) == std::string::npos) continue;
      f.vector = m.options;
      std::vector<double> stage, total, stage_cpu;
      for (std::size_t i = 0; i < frames; ++i) {
        const auto t0 = clock_type::now();
        view::order_stage(f);
        view::lighting_stage(f);
        view::transform_clip_stage(f);
        const auto t1 = clock_type::now();
        const std::clock_t c1 = std::clock();
        if (m.kind == view::output_kind::svg)
          view::svg_stage(f);
        else
          view::pdf_stage(f);
        const auto t2 = clock_type::now();
        stage_cpu.push_back(static_cast<double>(std::clock() - c1) / CLOCKS_PER_SEC);
        stage.push_back(std::chrono::duration<double>(t2 - t1).count());
        total.push_back(std::chrono::duration<double>(t2 - t0).count());
      }
      const std::string& doc = m.kind == view::output_kind::svg ? f.svg : f.pdf;
      json line = {{"input", in.name},
                   {"triangles", f.soup.triangles.size()},
                   {"fragments", f.fragments.size()},
                   {"mode", m.name},
                   {"width", width},
                   {"height", height},
                   {"bytes", doc.size()},
                   {"vector_stage_seconds", median(stage)},
                   {"vector_stage_cpu_seconds", median(stage_cpu)},
                   {"frame_seconds", median(total)}};
      if (m.kind == view::output_kind::svg) line["paths"] = count_of(doc, "<path");
      std::cout << line.dump() << std::endl;
      if (out) out << line.dump() << "\n";
      if (!keep_dir.empty()) {
        std::string file =
            in.name + "_" + m.name + (m.kind == view::output_kind::svg ? ".svg" : ".pdf");
        std::replace(file.begin(), file.end(), ' ', '_');
        std::replace(file.begin(), file.end(), ',', '_');
        std::ofstream(keep_dir + "/" + file, std::ios::binary) << doc;
      }
    }
  }
  return 0;
}
