// SPDX-License-Identifier: LGPL-3.0-or-later
// The viewport's picture inside the image (notation in placement.h).
#include "view/placement.h"

#include <exbsp/core/errors.h>

namespace exbsp::view {

std::string place_stage(frame& f) {
  const view_setup& v = f.view;
  const int w = v.vp.width, h = v.vp.height;
  if (v.place_x < 0 || v.place_y < 0 || v.place_x + w > v.image_width ||
      v.place_y + h > v.image_height)
    throw usage_error("place: the viewport does not fit in the image");
  if (f.picture.width() == w && f.picture.height() == h) {
    image out(v.image_width, v.image_height, f.background);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        out.set_pixel(v.place_x + i, v.place_y + j, f.picture.pixel(i, j));
    f.picture = std::move(out);
  }
  return "viewport " + std::to_string(w) + "x" + std::to_string(h) + " at " +
         std::to_string(v.place_x) + "," + std::to_string(v.place_y) + " in a " +
         std::to_string(v.image_width) + "x" + std::to_string(v.image_height) + " image";
}

}  // namespace exbsp::view
