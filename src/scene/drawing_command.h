// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp drawing`: a mesh, a scene or a folder of meshes -> drawing sheets (drawing/drawing.h)
// in SVG, PDF or DXF.
//
// Inputs: a mesh file (.off, .obj, .ply, .stl); a scene (.json: all its meshes with their
// transforms as one part; its camera and effects do not apply to a drawing); a saved tree
// (.exbsp, `build --save`: its views use the tree without a build); a folder: one
// sheet per mesh file in it (sorted by name, not recursive), written to OUTDIR/NAME.EXT for each
// of `formats`. Sections are cut exactly (section_with_cap, exbsp::gpl) before the views.
//
// Output: each file is written atomically (no partial file on error). A folder run is
// resumable: a sheet whose file exists and is newer than its mesh is not redone (a finished
// sheet was renamed into place whole); --force redoes it.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "drawing/drawing.h"

namespace exbsp::scene {

/// What to draw.
struct drawing_request {
  std::string input;   ///< mesh, scene (.json) or folder
  std::string output;  ///< OUT.svg / OUT.pdf / OUT.dxf, or a folder for a folder input
  std::vector<std::string> formats{"pdf"};  ///< folder input: the files of each sheet
  drawing::drawing_options options;
  /// The options given explicitly (names of drawing_option_names()): for a scene input they
  /// override its "drawing" block, the others come from the block (or options' defaults).
  std::vector<std::string> given;
  bool force = false;   ///< folder input: redo finished sheets
  bool strict = false;  ///< scenes: unknown keys are errors
};

/// What was done.
struct drawing_summary {
  std::vector<std::string> written, skipped;  ///< files
  std::size_t triangles = 0;
  double seconds = 0;
};

/// "title", "number", "date", "views", "projection", "sheet", "scale", "units", "up", "sections",
/// "lines_only", "line_widths", "crease_deg": the options a scene's "drawing" block may set.
const std::vector<std::string>& drawing_option_names();

/// The sheet of one mesh or scene file (sections cut), without writing it. For a scene, the
/// options are its "drawing" block with the `given` ones of `options` over it (`given` null:
/// all of them); the date is today's when none is given. `used` (may be null) receives the
/// options the sheet was made with.
drawing::sheet make_drawing_sheet(const std::string& input, const drawing::drawing_options& options,
                                  bool strict, std::ostream* log, std::size_t* triangles = nullptr,
                                  const std::vector<std::string>* given = nullptr,
                                  drawing::drawing_options* used = nullptr);

/// `o`, with lines_only set when `only_dxf`: a DXF holds the line drawing only (fills stay in
/// SVG and PDF), so a sheet made only for DXF skips the visible regions; its edges, and so the
/// DXF's bytes, are the same either way.
drawing::drawing_options lines_only_if(drawing::drawing_options o, bool only_dxf);

/// The bytes of `sheet` in `format` ("svg", "pdf" or "dxf") with the options' date.
std::string drawing_bytes(const drawing::sheet& sheet, const std::string& format,
                          const drawing::drawing_options& options);

/// Runs the command. Log lines (progress, one per step) go to `log`. Throws input_error /
/// scene_error / usage_error (exit 2), output_error (exit 2), limit_error (exit 3).
drawing_summary drawing_command(const drawing_request& request, std::ostream& log);

}  // namespace exbsp::scene
