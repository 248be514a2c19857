// SPDX-License-Identifier: LGPL-3.0-or-later
// File names: the one place that decides a file's kind by its extension (mesh input, scene
// input, and the outputs of render, section and clip).
//
// Notation: the extension of a path is its text from the last '.' after the last '/'
// (".png" in "out/a.b/x.png"; none in "out/a.b/x"); comparisons ignore ASCII case.
#pragma once
#include <cstddef>
#include <string>

namespace exbsp {

/// The extension of `path` as written, with its dot ("" when it has none).
inline std::string file_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return path.substr(dot);
}

/// Whether the extension of `path` is `ext` (with its dot, lower case), ignoring ASCII case.
inline bool has_extension(const std::string& path, const std::string& ext) {
  const std::string e = file_extension(path);
  if (e.size() != ext.size()) return false;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const char c = e[i] >= 'A' && e[i] <= 'Z' ? static_cast<char>(e[i] - 'A' + 'a') : e[i];
    if (c != ext[i]) return false;
  }
  return true;
}

}  // namespace exbsp
