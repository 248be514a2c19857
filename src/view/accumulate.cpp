// SPDX-License-Identifier: LGPL-3.0-or-later
// Accumulated views (notation in accumulate.h).
#include "view/accumulate.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <exbsp/core/errors.h>

namespace exbsp::view {

void accumulate_views(frame& f, const pipeline& per_view, std::size_t count,
                      const std::function<view_setup(std::size_t)>& view_of, const char* effect) {
  std::vector<std::uint32_t> sum(f.picture.data().begin(), f.picture.data().end());
  // View 0's products, restored afterwards.
  const view_setup centre = f.view;
  std::vector<std::uint32_t> order = std::move(f.order);
  std::vector<screen_polygon> polygons = std::move(f.polygons);
  std::vector<std::uint8_t> meshes_whole = std::move(f.meshes_whole);
  std::vector<screen_line> lines = std::move(f.lines);
  std::vector<rgb8> colors = std::move(f.fragment_colors);
  std::vector<std::array<rgb8, 3>> corner_colors = std::move(f.corner_colors);
  std::optional<fog_shading> fog = std::move(f.fog);
  std::optional<sample_shader> shader = std::move(f.shader);
  const std::size_t culled = f.culled, fully_clipped = f.fully_clipped;
  const image centre_picture = f.picture;

  for (std::size_t k = 1; k < count; ++k) {
    f.view = view_of(k);
    per_view.run(f, nullptr);
    const std::vector<std::uint8_t>& px = f.picture.data();
    if (px.size() != sum.size())
      throw usage_error(std::string(effect) + ": a view changed the image size");
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += px[i];
  }

  f.view = centre;
  f.order = std::move(order);
  f.polygons = std::move(polygons);
  f.meshes_whole = std::move(meshes_whole);
  f.lines = std::move(lines);
  f.fragment_colors = std::move(colors);
  f.corner_colors = std::move(corner_colors);
  f.fog = std::move(fog);
  f.shader = std::move(shader);
  f.culled = culled;
  f.fully_clipped = fully_clipped;
  f.picture = centre_picture;
  const auto n = static_cast<std::uint32_t>(count);
  std::vector<std::uint8_t>& out = f.picture.data();
  for (std::size_t i = 0; i < sum.size(); ++i)
    out[i] = static_cast<std::uint8_t>((sum[i] + n / 2) / n);
}

}  // namespace exbsp::view
