// bench_render: per-frame times of exbsp's viewing pipeline next to Mesa's off-screen
// OpenGL z-buffer (OSMesa, llvmpipe), on the same triangles in the same process.
//
// Per input: one BSP build (kernel and heuristic as given), then `frames` frames of the
// standard stages (view/stages.h) for a fixed perspective camera: "order" (back-to-front
// traversal for the eye), "transform+clip" (modelview, projection, homogeneous clipping,
// divide, viewport), "raster" (painter's algorithm at width x height, no z-buffer), "svg"
// (the SVG document as a string) and "svg write" (atomic file write). Each stage's median
// over the frames is reported. OSMesa draws the INPUT triangles (what a z-buffer viewer
// draws; it needs no BSP) with the same matrices and flat face colours from a vertex buffer:
// glClear + glDrawArrays + glFinish per frame, median over the frames, and the first frame
// (upload and pipeline compilation) separately. "pixel_agreement" is the fraction of pixels
// with the same colour in both images.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "bench_view.h"
#include "generators.h"
#include "view/atomic_file.h"
#include "view/camera.h"
#include "view/projection.h"
#include "view/stages.h"

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

#if EXBSP_HAVE_OSMESA
/// OSMesa z-buffer rendering of the input triangles; fills `out` and returns the image.
std::vector<unsigned char> render_osmesa(const view::frame& f, std::size_t frames, json& out) {
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
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(xyz.size() * sizeof(float)), xyz.data(), GL_STATIC_DRAW);
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
  out["triangles_drawn"] = f.soup.triangles.size();
  out["status"] = "ok";
  glDeleteBuffers(2, vbo);
  OSMesaDestroyContext(ctx);
  return buffer;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_render: per-frame times of the exbsp pipeline and of an OSMesa z-buffer"};
  std::string mesh, kernel = "epeck", heuristic = "sampled", out_path, svg_path = "bench/out/render.svg";
  std::size_t soup_n = 0, frames = 5;
  int width = 1024, height = 768;
  app.add_option("--mesh", mesh, "mesh file");
  app.add_option("--soup", soup_n, "random soup of N triangles instead of a mesh");
  app.add_option("--kernel", kernel, "BSP kernel");
  app.add_option("--heuristic", heuristic, "BSP heuristic");
  app.add_option("--frames", frames, "timed frames (median reported)");
  app.add_option("--width", width);
  app.add_option("--height", height);
  app.add_option("--svg", svg_path, "where the svg write stage writes");
  app.add_option("--out", out_path, "append the JSON line here (default: stdout)");
  CLI11_PARSE(app, argc, argv);
  try {
    const bench::input_spec in = bench::parse_input_spec(mesh.empty() ? "soup:" + std::to_string(soup_n) : "mesh:" + mesh);
    view::frame f;
    f.soup = bench::load_input(in);
    f.build.kernel = parse_kernel(kernel);
    f.build.heuristic = heuristic;
    f.face_colors.resize(f.soup.face_count);
    for (std::uint32_t i = 0; i < f.soup.face_count; ++i) f.face_colors[i] = face_color(i);
    bench::set_bench_view(f, width, height);

    json line = {{"input", in.name}, {"triangles", f.soup.triangles.size()}, {"kernel", kernel},
                 {"heuristic", heuristic}, {"width", width}, {"height", height}, {"frames", frames}};
    auto t0 = clock_type::now();
    view::build_stage(f);
    line["build_seconds"] = seconds_since(t0);
    line["fragments"] = f.fragments.size();
    std::map<std::string, std::vector<double>> stage_times;
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
      t0 = clock_type::now();
      view::svg_stage(f);
      stage_times["svg"].push_back(seconds_since(t0));
      t0 = clock_type::now();
      view::write_file_atomically(svg_path, f.svg);
      stage_times["svg write"].push_back(seconds_since(t0));
    }
    json stages = json::object();
    double frame_total = 0;
    for (const auto& [name, times] : stage_times) {
      stages[name] = median(times);
      if (name != "svg" && name != "svg write") frame_total += median(times);
    }
    line["stage_seconds_median"] = stages;
    line["png_frame_seconds"] = frame_total;  // order + transform+clip + raster
    line["polygons"] = f.polygons.size();
    line["fully_clipped"] = f.fully_clipped;
    line["svg_bytes"] = f.svg.size();
    json gl = json::object();
#if EXBSP_HAVE_OSMESA
    const std::vector<unsigned char> gl_image = render_osmesa(f, frames, gl);
    if (!gl_image.empty()) {
      std::size_t same = 0;
      for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
          const unsigned char* g = &gl_image[4 * (static_cast<std::size_t>(j) * width + i)];  // row 0 = bottom
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
              << frame_total << " s, osmesa " << gl.value("frame_seconds_median", 0.0) << " s\n";
  } catch (const std::exception& e) {
    std::cerr << "bench_render: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
