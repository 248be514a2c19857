// SPDX-License-Identifier: LGPL-3.0-or-later
// Nesting depth of JSON text (json_limits.h): one pass that tracks whether it is inside a
// string (a '"' not escaped by a backslash toggles it) and counts unclosed '[' and '{'
// outside strings. Lines are counted at '\n', and at a '\r' not followed by '\n'.
#include "mesh/json_limits.h"

#include <exbsp/core/errors.h>

namespace exbsp {

void check_json_nesting(std::string_view text, const std::string& file, std::size_t max_depth) {
  std::size_t depth = 0, line = 1, line_start = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n' || (c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) {
      ++line;
      line_start = i + 1;
      continue;
    }
    if (in_string) {
      if (c == '\\')
        ++i;  // the escaped character cannot end the string
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth)
        throw input_error(file, line,
                          "JSON nested too deeply: more than " + std::to_string(max_depth) +
                              " levels of arrays and objects (column " +
                              std::to_string(i - line_start + 1) + ", byte offset " +
                              std::to_string(i) + ")");
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace exbsp
