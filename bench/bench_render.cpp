// SPDX-License-Identifier: LGPL-3.0-or-later
// bench_render: per-frame times of exbsp's viewing pipeline next to Mesa's off-screen
// OpenGL z-buffer (OSMesa, llvmpipe), on the same triangles in the same process.
//
// Per input: one BSP build (kernel and heuristic as given), then `frames` frames of the
// standard stages (view/stages.h) for a fixed perspective camera: "order" (back-to-front
// traversal for the eye), "transform+clip" (modelview, projection, homogeneous clipping,
// divide, viewport), "raster" (painter's algorithm at width x height, no z-buffer), "svg"
// (the SVG document as a string: visible regions, visible and hidden edges) and "svg write" (atomic
// file write). Each stage's median over the frames is reported, and the svg stage's phases
// ("svg_phase_seconds_median": snap, coverage, regions, underlays, the edges on their own
// thread and the time the regions waited for them). OSMesa draws the INPUT triangles
// (what a z-buffer viewer draws; it needs no BSP) with the same matrices and flat face colours from
// a vertex buffer: glClear + glDrawArrays + glFinish per frame, median over the frames, and the
// first frame (upload and pipeline compilation) separately. "pixel_agreement" is the fraction of
// pixels with the same colour in both images.
//
// The raster stage paints front to back with a coverage mask (the default, paint.h); two
// more timings of the same stage, not part of the frame, compare: "raster all cores" (front
// to back in one band of rows per core) and "raster back to front" (the reference walk).
// Every frame checks that all three give the same bytes. Orbit: `orbit`
// frames (default 36) with the eye turned about the look-at point by 360 / orbit degrees each
// (the same BSP, order + transform+clip + raster per frame) give "orbit_fps", and OSMesa draws
// the same cameras for its own frames per second.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <exbsp/view/camera.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/stages.h>
#include "bench_view.h"
#include "generators.h"
#include "core/atomic_file.h"
#include "view/paint.h"

#if EXBSP_HAVE_OSMESA
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#endif

namespace {

using namespace exbsp;
using json = nlohmann::json;
using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t0) {
  return std::chrono::duration<double>(clock_type::now() - t0).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

view::rgb8 face_color(std::uint32_t face) {
  bench::split_mix rng(face);
  const std::uint64_t x = rng.next();
  return {static_cast<std::uint8_t>(40 + x % 200), static_cast<std::uint8_t>(40 + (x >> 8) % 200),
          static_cast<std::uint8_t>(40 + (x >> 16) % 200)};
}

/// The camera of orbit frame k of n: the eye turned about the look-at point by 360 k / n
/// degrees around the up axis.
view::view_setup orbit_view(const view::view_setup& v, std::size_t k, std::size_t n) {
  view::view_setup o = v;
  const double a = 2 * 3.14159265358979323846 * static_cast<double>(k) / static_cast<double>(n);
  const view::vector3 d = v.cam.eye - v.cam.look_at;
  o.cam.eye = v.cam.look_at + view::vector3{d.x * std::cos(a) - d.y * std::sin(a),
                                            d.x * std::sin(a) + d.y * std::cos(a), d.z};
  o.model_view = view::look_at(o.cam);
  return o;
}

/// CPU seconds of every thread of this process so far (user + system).
double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
  return seconds(u.ru_utime) + seconds(u.ru_stime);
}

#if EXBSP_HAVE_OSMESA
/// OSMesa z-buffer rendering of the input triangles; fills `out` and returns the image.
/// With orbit > 0, also draws the orbit's cameras and reports "orbit_fps".
std::vector<unsigned char> render_osmesa(const view::frame& f, std::size_t frames,
                                         std::size_t orbit, json& out) {
  const int w = f.view.vp.width, h = f.view.vp.height;
  std::vector<unsigned char> buffer(static_cast<std::size_t>(w) * h * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h)) {
    out["status"] = "no OSMesa context";
    if (ctx) OSMesaDestroyContext(ctx);
    return {};
  }
  out["renderer"] = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::vector<float> xyz;
  std::vector<unsigned char> rgb;
  xyz.reserve(f.soup.triangles.size() * 9);
  rgb.reserve(f.soup.triangles.size() * 9);
  for (const soup_triangle& t : f.soup.triangles) {
    const view::rgb8 c = f.color_of(t.face);
    for (std::uint32_t v : t.v) {
      for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(f.soup.vertices[v][k]));
      rgb.insert(rgb.end(), {c.r, c.g, c.b});
    }
  }
  const auto t_first = clock_type::now();
  GLuint vbo[2];
  glGenBuffers(2, vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(xyz.size() * sizeof(float)), xyz.data(),
               GL_STATIC_DRAW);
  glVertexPointer(3, GL_FLOAT, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[1]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(rgb.size()), rgb.data(), GL_STATIC_DRAW);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glViewport(0, 0, w, h);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glShadeModel(GL_FLAT);
  glDisable(GL_LIGHTING);
  glDisable(GL_DITHER);
  // view::mat4 is row-major; OpenGL reads column-major: pass the transpose.
  const view::mat4 p = view::transpose(f.view.projection), mv = view::transpose(f.view.model_view);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(p.m.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(mv.m.data());
  glClearColor(f.background.r / 255.0f, f.background.g / 255.0f, f.background.b / 255.0f, 1.0f);
  const auto draw = [&] {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xyz.size() / 3));
    glFinish();
  };
  draw();
  out["first_frame_seconds"] = seconds_since(t_first);
  std::vector<double> times;
  for (std::size_t i = 0; i < frames; ++i) {
    const auto t0 = clock_type::now();
    draw();
    times.push_back(seconds_since(t0));
  }
  out["frame_seconds"] = times;
  out["frame_seconds_median"] = median(times);
  out["frame_seconds_min"] = *std::min_element(times.begin(), times.end());
  std::vector<unsigned char> image = buffer;
  if (orbit > 0) {
    const auto t_orbit = clock_type::now();
    for (std::size_t k = 0; k < orbit; ++k) {
      glMatrixMode(GL_MODELVIEW);
      glLoadMatrixd(view::transpose(orbit_view(f.view, k, orbit).model_view).m.data());
      draw();
    }
    out["orbit_fps"] = static_cast<double>(orbit) / seconds_since(t_orbit);
  }
  out["triangles_drawn"] = f.soup.triangles.size();
  out["status"] = "ok";
  glDeleteBuffers(2, vbo);
  OSMesaDestroyContext(ctx);
  return image;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_render: per-frame times of the exbsp pipeline and of an OSMesa z-buffer"};
  std::string mesh, kernel = "epeck", heuristic = "sampled", out_path,
                    svg_path = "bench/out/render.svg";
  std::size_t soup_n = 0, frames = 5, orbit = 36;
  int width = 1024, height = 768;
  // --mesh, --soup and --kernel are declared again in bench_sweep.cpp: one CLI11 line each,
  // different types there (repeatable lists).
  app.add_option("--mesh", mesh, "mesh file");
  app.add_option("--soup", soup_n, "random soup of N triangles instead of a mesh");
  app.add_option("--kernel", kernel, "BSP kernel");
  app.add_option("--heuristic", heuristic, "BSP heuristic");
  app.add_option("--frames", frames, "timed frames (median reported)");
  app.add_option("--orbit", orbit, "orbit frames for frames per second (0: none)");
  app.add_option("--width", width);
  app.add_option("--height", height);
  app.add_option("--svg", svg_path, "where the svg write stage writes");
  app.add_option("--out", out_path, "append the JSON line here (default: stdout)");
  CLI11_PARSE(app, argc, argv);
  try {
    const bench::input_spec in =
        bench::parse_input_spec(mesh.empty() ? "soup:" + std::to_string(soup_n) : "mesh:" + mesh);
    view::frame f;
    f.soup = bench::load_input(in);
    f.build.kernel = parse_kernel(kernel);
    f.build.heuristic = heuristic;
    f.face_colors.resize(f.soup.face_count);
    for (std::uint32_t i = 0; i < f.soup.face_count; ++i) f.face_colors[i] = face_color(i);
    bench::set_bench_view(f, width, height);
    // The SVG frame is the hidden-line drawing a CAD user ships: visible regions, visible and
    // hidden edges.
    f.vector.edges = view::vector_options::edges_kind::visible_hidden;

    json line = {{"input", in.name}, {"triangles", f.soup.triangles.size()},
                 {"kernel", kernel}, {"heuristic", heuristic},
                 {"width", width},   {"height", height},
                 {"frames", frames}};
    auto t0 = clock_type::now();
    view::build_stage(f);
    line["build_seconds"] = seconds_since(t0);
    line["fragments"] = f.fragments.size();
    std::map<std::string, std::vector<double>> stage_times;
    std::map<std::string, std::vector<double>> svg_phase_times;  ///< visible_drawing's phases
    for (std::size_t i = 0; i < frames; ++i) {
      t0 = clock_type::now();
      view::order_stage(f);
      stage_times["order"].push_back(seconds_since(t0));
      t0 = clock_type::now();
      view::transform_clip_stage(f);
      stage_times["transform+clip"].push_back(seconds_since(t0));
      t0 = clock_type::now();
      view::raster_stage(f);
      stage_times["raster"].push_back(seconds_since(t0));
      const view::image fast = f.picture;
      const unsigned threads = f.raster_threads;
      f.raster_threads = 0;
      t0 = clock_type::now();
      view::raster_stage(f);
      stage_times["raster all cores"].push_back(seconds_since(t0));
      f.raster_threads = threads;
      if (f.picture.data() != fast.data())
        throw std::runtime_error("raster: one band and all bands differ");
      f.painter = view::paint_order::back_to_front;
      t0 = clock_type::now();
      view::raster_stage(f);
      stage_times["raster back to front"].push_back(seconds_since(t0));
      f.painter = view::paint_order::front_to_back;
      if (f.picture.data() != fast.data())
        throw std::runtime_error("raster: front to back and back to front differ");
      t0 = clock_type::now();
      const double cpu0 = process_cpu_seconds();
      view::svg_stage(f);
      stage_times["svg"].push_back(seconds_since(t0));
      stage_times["svg cpu"].push_back(process_cpu_seconds() - cpu0);
      const view::vector_phase_seconds& v = f.vector_seconds;
      for (const auto& [name, s] : {std::pair<const char*, double>{"snap", v.snap},
                                    {"coverage", v.coverage},
                                    {"regions", v.regions},
                                    {"underlays", v.underlays},
                                    {"edges (own thread)", v.edges},
                                    {"edges wait", v.edges_wait}})
        svg_phase_times[name].push_back(s);
      t0 = clock_type::now();
      write_file_atomically(svg_path, f.svg);
      stage_times["svg write"].push_back(seconds_since(t0));
    }
    // First: the first frame's times, which include what later views keep (the soup's edge
    // graph and outward-closed meshes, frame::soup_products).
    json stages = json::object(), stages_min = json::object(), stages_first = json::object();
    double frame_total = 0;
    for (const auto& [name, times] : stage_times) {
      stages[name] = median(times);
      stages_min[name] = *std::min_element(times.begin(), times.end());
      stages_first[name] = times.front();
      if (name == "order" || name == "transform+clip" || name == "raster")
        frame_total += median(times);
    }
    line["stage_seconds_median"] = stages;
    line["stage_seconds_min"] = stages_min;
    line["stage_seconds_first"] = stages_first;
    json phases = json::object();
    for (const auto& [name, times] : svg_phase_times) phases[name] = median(times);
    line["svg_phase_seconds_median"] = phases;
    line["png_frame_seconds"] = frame_total;  // order + transform+clip + raster
    line["polygons"] = f.polygons.size();
    line["fully_clipped"] = f.fully_clipped;
    const view::view_setup centre = f.view;
    const view::image centre_picture = f.picture;
    if (orbit > 0) {
      t0 = clock_type::now();
      for (std::size_t k = 0; k < orbit; ++k) {
        f.view = orbit_view(centre, k, orbit);
        view::order_stage(f);
        view::transform_clip_stage(f);
        view::raster_stage(f);
      }
      line["orbit_frames"] = orbit;
      line["orbit_fps"] = static_cast<double>(orbit) / seconds_since(t0);
      f.view = centre;
      view::order_stage(f);
      view::transform_clip_stage(f);
      f.picture = centre_picture;
    }
    line["svg_bytes"] = f.svg.size();
    json gl = json::object();
#if EXBSP_HAVE_OSMESA
    const std::vector<unsigned char> gl_image = render_osmesa(f, frames, orbit, gl);
    if (!gl_image.empty()) {
      std::size_t same = 0;
      for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
          const unsigned char* g =
              &gl_image[4 * (static_cast<std::size_t>(j) * width + i)];  // row 0 = bottom
          const view::rgb8 p = f.picture.pixel(i, j);
          same += p.r == g[0] && p.g == g[1] && p.b == g[2];
        }
      gl["pixel_agreement"] = static_cast<double>(same) / (static_cast<double>(width) * height);
    }
#else
    gl["status"] = "not built: OSMesa (libosmesa6-dev) not found at configure time";
#endif
    line["osmesa"] = gl;
    std::ofstream file;
    if (!out_path.empty()) file.open(out_path, std::ios::app);
    (out_path.empty() ? std::cout : file) << line.dump() << "\n";
    std::cerr << "bench_render: " << in.name << ": " << line["fragments"] << " fragments, frame "
              << frame_total << " s, osmesa " << gl.value("frame_seconds_median", 0.0)
              << " s; orbit " << line.value("orbit_fps", 0.0) << " fps, osmesa "
              << gl.value("orbit_fps", 0.0) << " fps\n";
  } catch (const std::exception& e) {
    std::cerr << "bench_render: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
