// The viewport's picture inside the image (notation in placement.h).
#include "view/placement.h"

#include "core/errors.h"

namespace exbsp::view {

namespace {

std::string hex(rgb8 c) {
  static const char* digits = "0123456789abcdef";
  std::string s = "#";
  for (std::uint8_t v : {c.r, c.g, c.b}) {
    s += digits[v >> 4];
    s += digits[v & 15];
  }
  return s;
}

}  // namespace

std::string place_stage(frame& f) {
  const view_setup& v = f.view;
  const int w = v.vp.width, h = v.vp.height;
  if (v.place_x < 0 || v.place_y < 0 || v.place_x + w > v.image_width || v.place_y + h > v.image_height)
    throw usage_error("place: the viewport does not fit in the image");
  if (!f.svg.empty()) {
    std::string inner = f.svg;
    if (inner.compare(0, 5, "<?xml") == 0) inner.erase(0, inner.find('\n') + 1);
    const std::string x = std::to_string(v.place_x), y = std::to_string(v.image_height - v.place_y - h);
    inner.replace(inner.find("<svg "), 5, "<svg x=\"" + x + "\" y=\"" + y + "\" ");
    const std::string iw = std::to_string(v.image_width), ih = std::to_string(v.image_height);
    f.svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
            iw + "\" height=\"" + ih + "\" viewBox=\"0 0 " + iw + " " + ih + "\">\n<rect x=\"0\" y=\"0\" width=\"" + iw +
            "\" height=\"" + ih + "\" fill=\"" + hex(f.background) + "\"/>\n" + inner + "</svg>\n";
  }
  if (f.picture.width() == w && f.picture.height() == h) {
    image out(v.image_width, v.image_height, f.background);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) out.set_pixel(v.place_x + i, v.place_y + j, f.picture.pixel(i, j));
    f.picture = std::move(out);
  }
  return "viewport " + std::to_string(w) + "x" + std::to_string(h) + " at " + std::to_string(v.place_x) + "," +
         std::to_string(v.place_y) + " in a " + std::to_string(v.image_width) + "x" + std::to_string(v.image_height) +
         " image";
}

}  // namespace exbsp::view
