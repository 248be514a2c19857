// `exbsp render`: scene (or the built-in demo) -> one soup -> the stage list of
// view/effects.h -> atomic PNG or SVG write.
#include "scene/render.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <string_view>

#include "mesh/errors.h"
#include "scene/demo_scene.h"
#include "scene/scene.h"
#include "view/effects.h"
#include "view/atomic_file.h"
#include "view/png_io.h"

namespace exbsp {

namespace {

bool ends_with_ci(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

}  // namespace

void render_command(const render_request& request, std::ostream& log) {
  const std::string out = request.output_path.empty() ? std::string("exbsp.png") : request.output_path;
  view::output_kind kind;
  if (ends_with_ci(out, ".png")) {
    kind = view::output_kind::png;
  } else if (ends_with_ci(out, ".svg")) {
    kind = view::output_kind::svg;
  } else {
    throw usage_error("render: the output file must end in .png or .svg: " + out);
  }

  const auto t0 = std::chrono::steady_clock::now();
  const scene::scene s = request.scene_path.empty() ? scene::demo_scene() : scene::load_scene(request.scene_path, &log);
  scene::scene_geometry geometry = scene::load_geometry(s);
  const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  view::frame f;
  f.view = scene::make_view_setup(s);
  f.background = s.background;
  f.face_colors = std::move(geometry.face_colors);
  f.soup = std::move(geometry.soup);

  view::pipeline p = view::standard_pipeline(s.effects, kind);
  p.add("write", [&out, kind](view::frame& fr) {
    if (kind == view::output_kind::png)
      view::write_png(fr.picture, out);
    else
      view::write_file_atomically(out, fr.svg);
    return out;
  });

  if (request.verbose) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", load_seconds);
    log << "scene: " << s.path << ": " << s.meshes.size() << " meshes, " << f.soup.triangles.size() << " triangles, "
        << view::to_string(s.projection.kind) << " " << s.width << "x" << s.height << "\n";
    log << "stage load: " << buf << " s (meshes read, transformed, appended into one soup)\n";
    if (!s.curves.empty()) log << "curves: " << s.curves.size() << " ignored (not drawn yet)\n";
    std::string names;
    for (const std::string& n : p.names()) names += (names.empty() ? "" : ", ") + n;
    log << "stages: " << names << "\n";
  }
  p.run(f, request.verbose ? &log : nullptr);
}

}  // namespace exbsp
