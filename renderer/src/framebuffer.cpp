#include "framebuffer.h"

#include <algorithm>
#include <cstring>

namespace raster::detail {

Image make_color_buffer(const RenderPlan& plan, Rgba8 background) {
  Image image;
  image.width = plan.width;
  image.height = plan.height;
  image.format = plan.format;
  // One byte per row more than the pixels: room for the PNG filter bytes, so encode_png(Image&&) filters
  // in place instead of allocating a second image.
  image.pixels.reserve(static_cast<std::size_t>(plan.memory.color_bytes) +
                       static_cast<std::size_t>(plan.height));
  image.pixels.resize(static_cast<std::size_t>(plan.memory.color_bytes));
  const std::uint8_t all[4] = {background.r, background.g, background.b, background.a};
  std::uint8_t texel[4];
  switch (plan.format) {
    case PixelFormat::grey8:
      texel[0] = background.r;
      break;
    case PixelFormat::grey_alpha8:
      texel[0] = background.r, texel[1] = background.a;
      break;
    case PixelFormat::rgb8:
      std::memcpy(texel, all, 3);
      break;
    case PixelFormat::rgba8:
      std::memcpy(texel, all, 4);
      break;
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
  if (!plan.depth_buffer) return {};
  return std::vector<float>(static_cast<std::size_t>(plan.width) * plan.height, 0.0f);
}

void resolve(const std::vector<Image>& planes, Image& out, Rect band) {
  const int c = out.channels();
  const auto n = static_cast<std::uint32_t>(planes.size());
  const bool alpha = out.format == PixelFormat::grey_alpha8 || out.format == PixelFormat::rgba8;
  const std::size_t begin = static_cast<std::size_t>(band.y0) * out.width * c,
                    end = static_cast<std::size_t>(band.y1) * out.width * c;
  for (std::size_t i = begin; i < end; i += c) {
    if (!alpha) {
      for (int k = 0; k < c; ++k) {
        std::uint32_t sum = 0;
        for (const Image& p : planes) sum += p.pixels[i + k];
        out.pixels[i + k] = static_cast<std::uint8_t>((sum + n / 2) / n);
      }
      continue;
    }
    std::uint32_t alpha_sum = 0;
    for (const Image& p : planes) alpha_sum += p.pixels[i + c - 1];
    for (int k = 0; k + 1 < c; ++k) {
      std::uint32_t weighted = 0;
      for (const Image& p : planes)
        weighted += static_cast<std::uint32_t>(p.pixels[i + k]) * p.pixels[i + c - 1];
      out.pixels[i + k] = alpha_sum ? static_cast<std::uint8_t>((weighted + alpha_sum / 2) / alpha_sum) : 0;
    }
    out.pixels[i + c - 1] = static_cast<std::uint8_t>((alpha_sum + n / 2) / n);
  }
}

Rect band(const RenderPlan& plan, int index, int count) {
  const int rows = plan.height / count;
  const int y0 = index * rows;
  const int y1 = index + 1 == count ? plan.height : y0 + rows;
  return {0, y0, plan.width, y1};
}

}  // namespace raster::detail
