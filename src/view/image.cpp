// SPDX-License-Identifier: LGPL-3.0-or-later
// RGB image storage (top row first). See image.h.
#include <exbsp/view/image.h>

#include <exbsp/core/errors.h>

namespace exbsp::view {

image::image(int width, int height, rgb8 fill) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536)
    throw usage_error("image: width and height must be in 1..65536");
  data_.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t k = 0; k < data_.size(); k += 3) {
    data_[k] = fill.r;
    data_[k + 1] = fill.g;
    data_[k + 2] = fill.b;
  }
}

}  // namespace exbsp::view
