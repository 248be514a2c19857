// SPDX-License-Identifier: LGPL-3.0-or-later
// Limits checked on JSON text before a JSON library parses it. nlohmann::json parses
// iteratively but copies, compares and (in older releases) destroys values recursively, so
// a document nested 100,000 levels deep overflows the stack; the depth is therefore bounded
// on the raw text first. Used by scene files (scene/scene.cpp) and meant for every JSON
// input (the `clip` input and saved trees will call it too). No JSON library is needed here,
// which is why it lives in exbsp_mesh, the lowest module.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace exbsp {

/// The deepest nesting of arrays and objects accepted in a JSON input (the outermost value
/// counts as level 1). Real scenes nest a handful of levels.
constexpr std::size_t max_json_depth = 256;

/// Throws input_error(file, line, ...) naming the line, column and byte offset of the first
/// '[' or '{' that opens level max_depth + 1. Brackets inside strings (with \" escapes) do not
/// count. Linear in text.size(), no recursion; says nothing about the text's other syntax.
void check_json_nesting(std::string_view text, const std::string& file,
                        std::size_t max_depth = max_json_depth);

}  // namespace exbsp
