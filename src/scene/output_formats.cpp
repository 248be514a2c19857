// SPDX-License-Identifier: LGPL-3.0-or-later
// The render output formats (output_formats.h): one row per format.
#include "scene/output_formats.h"

#include <exbsp/core/errors.h>
#include <exbsp/view/png_io.h>
#include "core/atomic_file.h"
#include "core/file_name.h"
#include "core/name_list.h"

namespace exbsp {

namespace {

void write_png_file(const view::frame& f, const std::string& path) {
  view::write_png(f.picture, path);
}
void write_svg_file(const view::frame& f, const std::string& path) {
  write_file_atomically(path, f.svg);
}
void write_pdf_file(const view::frame& f, const std::string& path) {
  write_file_atomically(path, f.pdf);
}

std::vector<output_format_row>& table() {
  static std::vector<output_format_row> rows{
      {".png", "the shaded picture", view::output_kind::png, write_png_file},
      {".svg", "the visible regions and edges as vector paths", view::output_kind::svg,
       write_svg_file},
      {".pdf", "the same drawing as PDF", view::output_kind::pdf, write_pdf_file},
  };
  return rows;
}

}  // namespace

const std::vector<output_format_row>& output_format_table() { return table(); }

std::string output_extensions() {
  std::vector<std::string> extensions;
  for (const output_format_row& r : table()) extensions.push_back(r.extension);
  return name_list(extensions, "or");
}

const output_format_row& output_format_for(const std::string& path) {
  if (path == "-") return table().front();
  for (const output_format_row& r : table())
    if (has_extension(path, r.extension)) return r;
  throw usage_error("render: the output file must end in " + output_extensions() + ": " + path);
}

void add_output_format(output_format_row row) {
  if (row.extension.size() < 2 || row.extension[0] != '.' || !row.write)
    throw usage_error("add_output_format: a format needs an extension '.x' and a writer");
  for (const output_format_row& r : table())
    if (r.extension == row.extension)
      throw usage_error("add_output_format: " + row.extension + " is taken");
  table().push_back(std::move(row));
}

}  // namespace exbsp
