// SPDX-License-Identifier: LGPL-3.0-or-later
// Mesh input: OFF, OBJ, PLY and STL into a triangle soup (docs/contract.md "Input").
// The readers are exbsp's own (not OpenMesh's): a coordinate is the IEEE double nearest to
// its decimal text, no face is dropped, and bad input throws input_error naming file and line.
#pragma once
#include <string>
#include <string_view>

#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>

namespace exbsp {

/// The mesh file formats read_mesh understands.
enum class mesh_format { off, obj, ply, stl };

/// The format for `path`'s extension (.off, .obj, .ply, .stl, case-insensitive).
/// Throws input_error (line 0) for any other or no extension, listing the supported ones.
EXBSP_EXPORT mesh_format mesh_format_for_path(const std::string& path);

/// Reads a mesh file by extension (.off, .obj, .ply, .stl, case-insensitive) into a soup.
/// Every face is kept (fan-triangulated, face id = 0-based face index in the file).
/// Throws input_error naming the file and line for unreadable files, syntax errors,
/// NaN/Inf coordinates, out-of-range indices, faces with < 3 vertices and count mismatches,
/// and for files that are not regular files (read_input_file).
EXBSP_EXPORT triangle_soup read_mesh(const std::string& path);

/// The whole contents of the regular file `path`. Throws input_error (line 0) naming the file
/// when it cannot be opened or read, or is not a regular file (a directory, device such as
/// /dev/zero, FIFO or socket: refused without reading, and without waiting for a FIFO writer).
/// Shared by every file input (meshes, scenes).
EXBSP_EXPORT std::string read_input_file(const std::string& path);

/// Parses the complete contents `data` of a mesh file in `format`; `name` is the file name
/// used in messages and stored in triangle_soup::source. Same rules and errors as read_mesh
/// (an empty `data` is an error: "empty file").
EXBSP_EXPORT triangle_soup read_mesh_data(std::string_view data, mesh_format format,
                                          const std::string& name);

}  // namespace exbsp
