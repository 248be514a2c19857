// SPDX-License-Identifier: LGPL-3.0-or-later
// The output formats of `exbsp render`, one row each (issue 26): the file extension, which
// product of the view pipeline it writes (the raster picture, the SVG text or the PDF bytes:
// standard_pipeline's output_kind picks the stages that make it) and the writer. The render
// command, its --help and its error messages read this table, so adding a format over an
// existing product is one writer and one row (or add_output_format); tests/test_tables.cpp
// walks the table and adds one.
#pragma once
#include <string>
#include <vector>

#include <exbsp/view/pipeline.h>
#include <exbsp/view/standard_pipeline.h>

namespace exbsp {

struct output_format_row {
  std::string extension;      ///< ".png": lower case, matched in any case (has_extension)
  std::string description;    ///< one phrase for --help
  view::output_kind product;  ///< what the pipeline makes for it
  /// Writes the frame's product to `path` atomically (no partial file on failure); "-" is
  /// standard output, for the first row only.
  void (*write)(const view::frame& f, const std::string& path);
};

/// Every render output format, PNG (also standard output, "-") first.
const std::vector<output_format_row>& output_format_table();

/// The row for an output path (by its extension; "-": the first row). usage_error naming the
/// extensions otherwise.
const output_format_row& output_format_for(const std::string& path);

/// ".png, .svg or .pdf": the extensions, for messages and help.
std::string output_extensions();

/// Adds a format (usage_error for an extension that is taken or does not start with '.', or
/// a row without a writer). Call it before a render runs on another thread: the table is not
/// locked.
void add_output_format(output_format_row row);

}  // namespace exbsp
