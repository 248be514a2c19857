// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp section MESH --plane A,B,C,D [-o OUT.json|.off|.svg]`: the exact cut of a mesh by a
// plane, with its outline and cap.
#include <CLI/CLI.hpp>

#include <iostream>

#include <exbsp/clip/section.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/core/errors.h>
#include "app/cli_parse.h"
#include "app/commands/command.h"
#include "app/commands/common.h"
#include "core/atomic_file.h"
#include "core/file_name.h"

namespace exbsp::cli {

namespace {

class section_subcommand final : public command {
 public:
  explicit section_subcommand(CLI::App& subcommand) : command(subcommand) {
    sub->add_option("MESH", mesh_,
                    "mesh file: .off, .obj, .ply or .stl ('-': standard input, with --format)")
        ->required();
    add_format_option(sub, format_);
    sub->add_option("--plane", plane_text_,
                    "A,B,C,D: the plane A*x+B*y+C*z+D = 0; the side where it is >= 0 is kept")
        ->required();
    sub->add_option("-o,--output", out_,
                    "OUT.json (kept, outline, cap with exact rationals; default: standard output), "
                    "OUT.off (kept and cap as one mesh) or OUT.svg (the outline in the cut plane)")
        ->check(non_empty_path());
  }

  /// JSON (default, to standard output), OFF or SVG by the output's extension.
  int run() override {
    const section_plane plane = parse_plane(plane_text_);
    const bool off = has_extension(out_, ".off"), svg = has_extension(out_, ".svg");
    if (!out_.empty() && out_ != "-" && !off && !svg && !has_extension(out_, ".json"))
      throw usage_error("-o/--output: section writes .json, .off or .svg, not '" + out_ + "'");
    const triangle_soup soup = read_mesh_input(mesh_, format_, std::cin);
    section_options options;
    options.exact_text = !off && !svg;
    const section_result r = section_with_cap(soup, plane, options);
    const std::string text = off ? section_off(r) : svg ? section_svg(r) : section_json(r);
    if (out_.empty())
      std::cout << text;
    else
      write_file_atomically(out_, text);
    return finish_standard_output(0);
  }

 private:
  std::string mesh_, format_, plane_text_, out_;
};

}  // namespace

std::unique_ptr<command> make_section_command(CLI::App& subcommand) {
  return std::make_unique<section_subcommand>(subcommand);
}

}  // namespace exbsp::cli
