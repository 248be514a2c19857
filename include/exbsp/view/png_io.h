// SPDX-License-Identifier: LGPL-3.0-or-later
// PNG encoding and decoding with libpng: 8-bit RGB, no interlace, row 0 = top of the image.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/core/export.h>
#include <exbsp/view/image.h>

namespace exbsp::view {

/// Encodes `img` as an 8-bit RGB PNG in memory. Throws usage_error if libpng fails.
EXBSP_EXPORT std::vector<std::uint8_t> encode_png(const image& img);

/// Encodes and writes `img` to `path` atomically (write_file_atomically).
/// Throws output_error naming `path` when it cannot be written.
EXBSP_EXPORT void write_png(const image& img, const std::string& path);

/// Reads a PNG file into an 8-bit RGB image (palette, grey, 16-bit and alpha are converted;
/// alpha is dropped). Throws input_error naming `path` for unreadable or invalid files.
EXBSP_EXPORT image read_png(const std::string& path);

}  // namespace exbsp::view
