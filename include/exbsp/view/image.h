// SPDX-License-Identifier: LGPL-3.0-or-later
// An 8-bit RGB image addressed in window coordinates (viewport.h): pixel (i, j) is column i,
// window row j counted from the BOTTOM; storage is top row first (PNG order), row r = height-1-j.
#pragma once
#include <cstdint>
#include <vector>
#include <exbsp/core/export.h>

namespace exbsp::view {

/// An 8-bit sRGB colour.
struct rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const rgb8& a, const rgb8& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  }
  friend bool operator!=(const rgb8& a, const rgb8& b) { return !(a == b); }
};

/// width x height RGB pixels, 3 bytes each, top row first.
class EXBSP_EXPORT image {
 public:
  image() = default;
  /// Throws usage_error unless 0 < width, height <= 65536.
  image(int width, int height, rgb8 fill);

  int width() const { return width_; }
  int height() const { return height_; }

  /// Pixel (i, j) in window coordinates (j = 0 is the bottom row). Precondition: in range.
  rgb8 pixel(int i, int j) const { return at_row(height_ - 1 - j, i); }
  void set_pixel(int i, int j, rgb8 c) { set_at_row(height_ - 1 - j, i, c); }

  /// Pixel in image coordinates: row 0 is the top. Precondition: in range.
  rgb8 at_row(int row, int col) const {
    const std::uint8_t* p = &data_[3 * (static_cast<std::size_t>(row) * width_ + col)];
    return {p[0], p[1], p[2]};
  }
  void set_at_row(int row, int col, rgb8 c) {
    std::uint8_t* p = &data_[3 * (static_cast<std::size_t>(row) * width_ + col)];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
  }

  /// RGB bytes, top row first, 3 * width bytes per row.
  const std::vector<std::uint8_t>& data() const { return data_; }
  std::vector<std::uint8_t>& data() { return data_; }

 private:
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> data_;
};

}  // namespace exbsp::view
