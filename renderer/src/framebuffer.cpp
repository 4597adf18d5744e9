#include "framebuffer.h"

#include <algorithm>
#include <cstring>

namespace raster::detail {

Image make_color_buffer(const RenderPlan& plan, Rgba8 background) {
  Image image;
  image.width = plan.width;
  image.height = plan.height;
  image.format = plan.format;
  image.pixels.resize(static_cast<std::size_t>(plan.memory.color_bytes));
  const std::uint8_t all[4] = {background.r, background.g, background.b, background.a};
  std::uint8_t texel[4];
  switch (plan.format) {
    case PixelFormat::grey8: texel[0] = background.r; break;
    case PixelFormat::grey_alpha8: texel[0] = background.r, texel[1] = background.a; break;
    case PixelFormat::rgb8: std::memcpy(texel, all, 3); break;
    case PixelFormat::rgba8: std::memcpy(texel, all, 4); break;
  }
  const int c = image.channels();
  if (std::all_of(texel, texel + c, [&](std::uint8_t v) { return v == texel[0]; })) {
    std::memset(image.pixels.data(), texel[0], image.pixels.size());
  } else {
    for (std::size_t i = 0; i < image.pixels.size(); i += c) std::memcpy(&image.pixels[i], texel, c);
  }
  return image;
}

std::vector<float> make_depth_buffer(const RenderPlan& plan) {
  return std::vector<float>(static_cast<std::size_t>(plan.memory.depth_bytes) / sizeof(float), 0.0f);
}

Rect band(const RenderPlan& plan, int index, int count) {
  const int rows = plan.height / count;
  const int y0 = index * rows;
  const int y1 = index + 1 == count ? plan.height : y0 + rows;
  return {0, y0, plan.width, y1};
}

}  // namespace raster::detail
