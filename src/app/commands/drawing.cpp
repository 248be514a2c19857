// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp drawing INPUT -o OUT`: a drawing sheet of a mesh or scene, or a drawing set of a
// folder (scene/drawing_command.h does the work; the option strings are parsed by the drawing
// library, which names the flag).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <utility>
#include <vector>

#include <exbsp/core/errors.h>
#include "app/commands/command.h"
#include "app/commands/common.h"
#include "app/resources.h"
#include "scene/drawing_command.h"

namespace exbsp::cli {

namespace {

class drawing_subcommand final : public command {
 public:
  explicit drawing_subcommand(CLI::App& subcommand) : command(subcommand) {
    sub->add_option("INPUT", input_,
                    "mesh (.off, .obj, .ply, .stl), scene (.json: its meshes as one part) or a "
                    "folder (one sheet per mesh)")
        ->required();
    sub->add_option("-o,--output", output_,
                    "OUT.svg, OUT.pdf or OUT.dxf; for a folder input, an output folder")
        ->required()
        ->check(non_empty_path());
    sub->add_option("--views", views_,
                    "views: front, top, left, right, bottom, rear, iso (comma-separated)")
        ->capture_default_str();
    sub->add_option("--projection", projection_, "first-angle (ISO E) or third-angle (ISO A)")
        ->capture_default_str();
    sub->add_option("--sheet", sheet_, "A4, A3, A2, A1, A0 (landscape) or WxH in mm")
        ->capture_default_str();
    sub->add_option("--scale", scale_, "1:N, N:1, or auto (the largest ISO 5455 scale that fits)")
        ->capture_default_str();
    sub->add_option("--units", units_, "model units: mm, cm, m or in")->capture_default_str();
    sub->add_option("--up", up_,
                    "the model's up axis: z (CAD: front looks from -y) or y (front looks from "
                    "+z, as render --view front)")
        ->check(CLI::IsMember({"z", "y"}))
        ->capture_default_str();
    sub->add_option("--section", sections_,
                    "X=a,b,c,d: section view X-X, the cut by a*x+b*y+c*z+d = 0 seen from the "
                    "removed side (repeatable)");
    sub->add_flag("--lines-only", lines_only_, "no shaded fills: the classic line drawing");
    sub->add_option("--title", title_, "title block: title (default: the file name)");
    sub->add_option("--number", number_, "title block: drawing number");
    sub->add_option("--date", date_,
                    "title block: date of issue (default: today, or SOURCE_DATE_EPOCH)");
    sub->add_option("--line-widths", line_widths_,
                    "VISIBLE,HIDDEN line widths in mm (default 0.5,0.25)");
    sub->add_option("--crease-deg", crease_deg_, "feature edges: dihedral angle over this")
        ->capture_default_str();
    sub->add_option("--formats", formats_,
                    "folder input: the files of each sheet, e.g. pdf,svg,dxf")
        ->capture_default_str();
    sub->add_flag("--force", force_, "folder input: redo sheets that are already finished");
    sub->add_option("--kernel", kernel_, "BSP kernel (default exact)")
        ->check(CLI::IsMember(kernel_names()));
    sub->add_flag("--strict", strict_, "unknown scene keys are errors (exit 2), not warnings");
    sub->add_flag("-q,--quiet", quiet_, "no progress lines and no summary line");
  }

  int run() override {
    namespace dr = exbsp::drawing;
    scene::drawing_request request;
    request.input = input_;
    request.output = output_;
    request.force = force_;
    request.strict = strict_;
    request.given = given();
    request.formats.clear();
    {
      std::string f;
      for (char c : formats_ + ",") {
        if (c != ',') {
          f += c;
          continue;
        }
        request.formats.push_back(f);
        f.clear();
      }
    }
    dr::drawing_options& o = request.options;
    o.views = views_.empty() ? std::vector<std::string>{} : dr::parse_views(views_);
    o.projection = dr::parse_projection(projection_);
    o.sheet = dr::parse_paper(sheet_);
    if (scale_ != "auto") o.scale = dr::parse_scale(scale_);
    dr::unit_mm(units_);
    o.units = units_;
    o.up = up_;
    for (const std::string& s : sections_) {
      o.sections.push_back(dr::parse_section(s));
      for (std::size_t i = 0; i + 1 < o.sections.size(); ++i)
        if (o.sections[i].letter == o.sections.back().letter)
          throw usage_error("--section: letter " + o.sections.back().letter + " is used twice");
    }
    o.lines_only = lines_only_;
    o.title = title_;
    o.number = number_;
    o.date = date_;
    o.crease_deg = crease_deg_;
    if (!(crease_deg_ > 0 && crease_deg_ <= 180))
      throw usage_error("--crease-deg: must be in (0, 180]");
    if (!line_widths_.empty()) parse_line_widths(o);
    if (!kernel_.empty()) o.build.kernel = parse_kernel(kernel_);
    o.build.max_fragments = default_fragment_budget(o.build.kernel);
    progress_line progress(!quiet_);
    o.build.progress = [&progress](const build_progress& p) { progress(p); };
    std::ostringstream quiet_log;
    scene::drawing_summary summary;
    try {
      summary = scene::drawing_command(request,
                                       quiet_ ? static_cast<std::ostream&>(quiet_log) : std::cerr);
    } catch (...) {
      progress.finish();
      throw;
    }
    progress.finish();
    if (!quiet_) {
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

 private:
  /// The drawing options given as flags (they override a scene's "drawing" block).
  std::vector<std::string> given() const {
    std::vector<std::string> out;
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
      if (sub->count(flag) > 0) out.emplace_back(name);
    return out;
  }

  /// --line-widths VISIBLE,HIDDEN in mm, each in (0, 5].
  void parse_line_widths(exbsp::drawing::drawing_options& o) const {
    const auto comma = line_widths_.find(',');
    char* end = nullptr;
    const std::string a = line_widths_.substr(0, comma);
    const std::string b = comma == std::string::npos ? "" : line_widths_.substr(comma + 1);
    o.visible_width = std::strtod(a.c_str(), &end);
    const bool ok_a = !a.empty() && *end == 0;
    o.hidden_width = std::strtod(b.c_str(), &end);
    const bool ok_b = !b.empty() && *end == 0;
    if (!ok_a || !ok_b || !(o.visible_width > 0 && o.visible_width <= 5) ||
        !(o.hidden_width > 0 && o.hidden_width <= 5))
      throw usage_error(
          "--line-widths: expected VISIBLE,HIDDEN in mm (each in (0, 5]), "
          "e.g. 0.35,0.18; got '" +
          line_widths_ + "'");
  }

  std::string input_, output_, views_ = "front,top,left,iso", projection_ = "first-angle";
  std::string sheet_ = "A3", scale_ = "auto", units_ = "mm", up_ = "z", line_widths_, title_,
              number_, date_;
  std::string formats_ = "pdf", kernel_;
  std::vector<std::string> sections_;
  bool lines_only_ = false, force_ = false, strict_ = false, quiet_ = false;
  double crease_deg_ = 30;
};

}  // namespace

std::unique_ptr<command> make_drawing_command(CLI::App& subcommand) {
  return std::make_unique<drawing_subcommand>(subcommand);
}

}  // namespace exbsp::cli
