// Atomic output: the bytes go to a temporary file next to the destination, which is then
// renamed over it, so a failed run never leaves a partial (or truncated old) output file.
#pragma once
#include <string>
#include <string_view>

namespace exbsp::view {

/// Writes `bytes` to `path` atomically (temporary file in the same directory + rename).
/// Throws input_error naming `path` when the file cannot be written; the temporary file is
/// removed and any existing file at `path` is left untouched.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace exbsp::view
