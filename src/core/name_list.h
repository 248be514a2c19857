// SPDX-License-Identifier: LGPL-3.0-or-later
// "a, b and c" / "a, b or c": a list of names for a message (unknown kernel, output
// extensions, the commands, the kernels' memory groups). One joiner for every message.
#pragma once
#include <string>
#include <vector>

namespace exbsp {

/// The names joined by ", ", the last two by " `last` " ("and" or "or").
inline std::string name_list(const std::vector<std::string>& names, const char* last) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? std::string(" ") + last + " " : ", ") + names[i];
  return out;
}

}  // namespace exbsp
