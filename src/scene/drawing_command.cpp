// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp drawing` (notation in drawing_command.h).
#include "scene/drawing_command.h"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

#include <exbsp/bsp/engine.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include "core/atomic_file.h"
#include "core/file_name.h"
#include "drawing/sheet_dxf.h"
#include "drawing/sheet_writers.h"
#include "scene/scene.h"

namespace exbsp::scene {

namespace {

namespace fs = std::filesystem;

const char* const mesh_extensions[] = {".off", ".obj", ".ply", ".stl"};

bool is_mesh_file(const std::string& path) {
  for (const char* e : mesh_extensions)
    if (has_extension(path, e)) return true;
  return false;
}

/// The format of an output file name, or "" when it has none of ours.
std::string format_of(const std::string& path) {
  for (const char* f : {"svg", "pdf", "dxf"})
    if (has_extension(path, std::string(".") + f)) return f;
  return "";
}

/// The cut of `part` by one section (exact, with its cap) as the drawing needs it.
drawing::section_cut cut_of(const triangle_soup& part, const drawing::section_spec& spec) {
  section_options opt;
  opt.exact_text = false;
  const section_result r = section_with_cap(part, spec.plane, opt);
  drawing::section_cut c;
  c.spec = spec;
  c.cap_face = r.cap_face;
  c.solid.face_count = part.face_count + 1;
  c.solid.source = part.source;
  c.solid.vertices.reserve(r.points.size());
  for (const section_point& p : r.points) c.solid.vertices.push_back(p.v);
  for (const section_triangle& t : r.kept) c.solid.triangles.push_back({t.p, t.face});
  for (const section_triangle& t : r.cap) c.solid.triangles.push_back({t.p, t.face});
  for (const section_chain& ch : r.outline) {
    if (!ch.closed) continue;
    std::vector<std::array<double, 3>> loop;
    for (std::uint32_t i : ch.p) loop.push_back(r.points[i].v);
    c.loops.push_back(std::move(loop));
  }
  if (r.cap.empty())
    throw usage_error("--section " + spec.letter +
                      ": the plane does not cut a closed part of the "
                      "mesh (no cut face to hatch)");
  return c;
}

/// Modification time of a file (0 when it does not exist).
long long mtime_ns(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return 0;
  return static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
}

/// `base` with the options named in `given` taken from `over`.
drawing::drawing_options overridden(drawing::drawing_options base,
                                    const drawing::drawing_options& over,
                                    const std::vector<std::string>& given) {
  const auto has = [&](const char* n) {
    return std::find(given.begin(), given.end(), n) != given.end();
  };
  if (has("title")) base.title = over.title;
  if (has("number")) base.number = over.number;
  if (has("date")) base.date = over.date;
  if (has("views")) base.views = over.views;
  if (has("projection")) base.projection = over.projection;
  if (has("sheet")) base.sheet = over.sheet;
  if (has("scale")) base.scale = over.scale;
  if (has("units")) base.units = over.units;
  if (has("up")) base.up = over.up;
  if (has("sections")) base.sections = over.sections;
  if (has("lines_only")) base.lines_only = over.lines_only;
  if (has("line_widths")) {
    base.visible_width = over.visible_width;
    base.hidden_width = over.hidden_width;
  }
  if (has("crease_deg")) base.crease_deg = over.crease_deg;
  base.color = over.color;
  base.build = over.build;
  return base;
}

}  // namespace

drawing::drawing_options lines_only_if(drawing::drawing_options o, bool only_dxf) {
  if (only_dxf) o.lines_only = true;
  return o;
}

const std::vector<std::string>& drawing_option_names() {
  static const std::vector<std::string> names{
      "title", "number", "date",     "views",      "projection",  "sheet",     "scale",
      "units", "up",     "sections", "lines_only", "line_widths", "crease_deg"};
  return names;
}

drawing::sheet make_drawing_sheet(const std::string& input, const drawing::drawing_options& flags,
                                  bool strict, std::ostream* log, std::size_t* triangles,
                                  const std::vector<std::string>* given,
                                  drawing::drawing_options* used) {
  triangle_soup part;
  std::optional<bsp> tree;  // a saved tree: the part's views use it without a build
  std::string name = fs::path(input).filename().string();
  drawing::drawing_options options = flags;
  if (has_extension(input, ".json")) {
    // A drawing sets its own views: a scene need not have a camera, projection or viewport
    // (the picture's keys); absent ones get harmless defaults so the scene validates as usual.
    nlohmann::json doc = parse_scene_json(read_input_file(input), input);
    if (doc.is_object()) {
      const bool has_camera = doc.contains("camera") && !doc["camera"].is_null();
      if (!has_camera)
        doc["camera"] = {{"eye", {0, 0, 1}}, {"look_at", {0, 0, 0}}, {"up", {0, 1, 0}}};
      if (!has_camera && !doc.contains("projection"))
        doc["projection"] = {{"type", "perspective"}, {"fovy_deg", 40}, {"near", 0.1}, {"far", 10}};
      if (!doc.contains("viewport")) doc["viewport"] = {{"width", 64}, {"height", 64}};
    }
    const scene s = parse_scene(doc, input, log, strict);
    part = load_geometry(s).soup;
    if (given) options = overridden(s.drawing, flags, *given);
  } else if (bsp::is_saved_tree(input)) {
    tree.emplace(bsp::load(input));
    part = tree->input();
  } else {
    part = read_mesh(input);
  }
  if (options.date.empty()) options.date = drawing::today_date();
  if (used) *used = options;
  if (triangles) *triangles = part.triangles.size();
  std::vector<drawing::section_cut> cuts;
  for (const drawing::section_spec& spec : options.sections) {
    if (log) *log << "exbsp: section " << spec.letter << ": cutting " << name << "\n";
    cuts.push_back(cut_of(part, spec));
  }
  const auto progress = [log](const std::string& m) {
    if (log) *log << "exbsp: " << m << "\n";
  };
  if (tree) return drawing::make_sheet(std::move(*tree), name, cuts, options, progress);
  return drawing::make_sheet(part, name, cuts, options, progress);
}

std::string drawing_bytes(const drawing::sheet& sheet, const std::string& format,
                          const drawing::drawing_options& options) {
  if (format == "svg") return drawing::sheet_svg(sheet);
  if (format == "pdf")
    return drawing::sheet_pdf(sheet, options.date.empty() ? drawing::today_date() : options.date);
  if (format == "dxf") return drawing::sheet_dxf(sheet);
  throw usage_error("drawing: unknown output format '" + format + "' (expected svg, pdf or dxf)");
}

drawing_summary drawing_command(const drawing_request& request, std::ostream& log) {
  const auto t0 = std::chrono::steady_clock::now();
  drawing_summary summary;
  drawing::drawing_options options = request.options;
  if (options.date.empty()) options.date = drawing::today_date();  // one date for every file
  const std::vector<std::string>& given = request.given;
  std::error_code ec;
  if (fs::is_directory(request.input, ec)) {
    if (request.formats.empty()) throw usage_error("--formats: at least one of svg, pdf, dxf");
    for (const std::string& f : request.formats)
      if (f != "svg" && f != "pdf" && f != "dxf")
        throw usage_error("--formats: unknown format '" + f + "' (expected svg, pdf or dxf)");
    if (!format_of(request.output).empty())
      throw usage_error("-o: a folder input makes one sheet per mesh: give an output folder, not " +
                        request.output);
    std::vector<std::string> meshes;
    for (const auto& e : fs::directory_iterator(request.input, ec))
      if (e.is_regular_file() && is_mesh_file(e.path().string()))
        meshes.push_back(e.path().string());
    if (ec) throw input_error(request.input, 0, "cannot list the folder: " + ec.message());
    std::sort(meshes.begin(), meshes.end());
    if (meshes.empty())
      throw input_error(request.input, 0, "no mesh file (.off, .obj, .ply, .stl) in the folder");
    fs::create_directories(request.output, ec);
    if (ec) throw output_error(request.output, "cannot make the output folder: " + ec.message());
    std::size_t k = 0;
    // An error stops the set; the sheets finished before it stay (each was renamed into place
    // whole) and are listed, and a rerun resumes after them.
    struct report_on_error {
      const std::vector<std::string>& written;
      std::ostream& log;
      bool done = false;
      ~report_on_error() {
        if (done || written.empty()) return;
        log << "exbsp: the set stopped at an error; " << written.size()
            << " file(s) finished before it are kept (a rerun skips them):";
        for (const std::string& w : written) log << " " << w;
        log << "\n";
      }
    } report{summary.written, log};
    for (const std::string& mesh : meshes) {
      ++k;
      const std::string stem = fs::path(mesh).stem().string();
      std::vector<std::string> todo;
      for (const std::string& f : request.formats) {
        const std::string out = (fs::path(request.output) / (stem + "." + f)).string();
        if (!request.force && mtime_ns(out) > 0 && mtime_ns(out) >= mtime_ns(mesh))
          summary.skipped.push_back(out);
        else
          todo.push_back(f);
      }
      log << "exbsp: sheet " << k << "/" << meshes.size() << ": " << stem
          << (todo.empty() ? " (done before; skipped)" : "") << "\n";
      if (todo.empty()) continue;
      drawing::drawing_options o = options;
      if (o.title.empty()) o.title = stem;
      std::size_t tris = 0;
      drawing::drawing_options used;
      const bool dxf_only =
          std::all_of(todo.begin(), todo.end(), [](const std::string& f) { return f == "dxf"; });
      const drawing::sheet s = make_drawing_sheet(mesh, lines_only_if(o, dxf_only), request.strict,
                                                  nullptr, &tris, &given, &used);
      summary.triangles += tris;
      for (const std::string& f : todo) {
        const std::string out = (fs::path(request.output) / (stem + "." + f)).string();
        write_file_atomically(out, drawing_bytes(s, f, used));
        summary.written.push_back(out);
      }
    }
    report.done = true;
  } else {
    const std::string format = format_of(request.output);
    if (format.empty())
      throw usage_error(
          "-o: the output must end in .svg, .pdf or .dxf (a folder only for a "
          "folder input), got '" +
          request.output + "'");
    if (!has_extension(request.input, ".json") && !is_mesh_file(request.input) &&
        !bsp::is_saved_tree(request.input))
      throw usage_error(
          "drawing: the input must be a mesh (.off, .obj, .ply, .stl), a scene (.json), a saved "
          "tree (.exbsp, from build --save) or a folder, got '" +
          request.input + "'");
    drawing::drawing_options used;
    std::vector<std::string> g = given;
    if (format == "dxf") g.push_back("lines_only");
    const drawing::sheet s =
        make_drawing_sheet(request.input, lines_only_if(request.options, format == "dxf"),
                           request.strict, &log, &summary.triangles, &g, &used);
    write_file_atomically(request.output, drawing_bytes(s, format, used));
    summary.written.push_back(request.output);
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace exbsp::scene
