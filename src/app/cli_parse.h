// SPDX-License-Identifier: LGPL-3.0-or-later
// Command-line parsing for `exbsp` (docs/contract.md "Command line"): the text formats of its
// option values, mesh input from a file or standard input, and suggestions for misspelled commands
// and options. Kept apart from main.cpp so the tests can call it; every function throws
// usage_error (exit 2) with a message naming the option.
#pragma once
#include <array>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

#include <exbsp/clip/section.h>
#include <exbsp/mesh/soup.h>

namespace CLI {
class App;
}

namespace exbsp::cli {

/// "X,Y,Z" as three finite doubles (nearest to the decimal text).
vec3d parse_triple(const std::string& text, const std::string& option);

/// "A,B,C,D" as a section plane A*x+B*y+C*z+D = 0 (finite, (A,B,C) not zero).
section_plane parse_plane(const std::string& text, const std::string& option = "--plane");

/// "X0,Y0:X1,Y1:..." (at least one point, finite numbers).
std::vector<std::array<double, 2>> parse_drag_path(const std::string& text,
                                                   const std::string& option = "--orbit-drag");

/// "WxH" (e.g. 800x600), each in 1..16384.
std::array<int, 2> parse_size(const std::string& text, const std::string& option = "--size");

/// Reads a mesh: `path` "-" reads standard input (`in`) and needs `format` (off, obj, ply or
/// stl); otherwise the file, in `format` when given (whatever its extension), else by its
/// extension. Throws input_error naming the file ("<stdin>" for "-") and line.
/// Standard input is bounded like a named file: when `in` is std::cin, a device that is not a
/// terminal (/dev/zero, /dev/urandom) is refused as a named device is, and at most
/// `max_stdin_bytes` are read (limit_error beyond; 0: available_memory_bytes() / 4 (resources.h),
/// the text of a mesh being a fraction of what its soup and tree then take).
triangle_soup read_mesh_input(const std::string& path, const std::string& format, std::istream& in,
                              std::uint64_t max_stdin_bytes = 0);

/// Levenshtein distance (insertions, deletions, substitutions; each costs 1). Written here
/// because neither CLI11 nor the standard library offer one, and it is ten lines.
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The candidate closest to `word` when it is close enough to be a likely typo (distance at
/// most 2, or at most a third of the word's length for long words), else "".
std::string closest(const std::string& word, const std::vector<std::string>& candidates);

/// Checks argv before CLI11 sees it, so that a misspelled command or option gets a message that
/// names it and suggests the closest valid one ("unknown command 'bild'; did you mean
/// 'build'?", "unknown option '--kernal' for 'build'; did you mean '--kernel'?"). Returns ""
/// when nothing is wrong (CLI11 then reports anything else), else the message.
std::string misspelling(const CLI::App& app, const std::vector<std::string>& args);

}  // namespace exbsp::cli
