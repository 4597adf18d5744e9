#include "framebuffer.h"

#include <algorithm>
#include <cstring>

namespace raster::detail {

namespace {

// Buffers grow to their size one chunk at a time inside capacity reserved up front (so nothing moves), and
// the deadline is looked at between chunks. The first touch of fresh pages is most of what a clear costs
// (~0.9 ms per MB on the 2-core test machine): in one step, a 40 MP buffer would be ~110 ms that no
// deadline could interrupt.
constexpr std::size_t kClearChunkBytes = 1u << 20;

// Grows `v` to `count` copies of `value`; false when `meter` stopped it first (then `v` is incomplete).
template <typename T>
bool grow_filled(std::vector<T>& v, std::size_t count, T value, StopMeter& meter) {
  const std::size_t step = std::max<std::size_t>(1, kClearChunkBytes / sizeof(T));
  while (v.size() < count) {
    if (meter.check()) return false;
    v.resize(std::min(count, v.size() + step), value);
  }
  return true;
}

}  // namespace

Image make_color_buffer(const RenderPlan& plan, Rgba8 background, StopMeter& meter, bool output) {
  Image image;
  image.width = plan.width;
  image.height = plan.height;
  image.format = plan.format;
  const auto bytes = static_cast<std::size_t>(plan.memory.color_bytes);
  // The output gets one byte per row more than the pixels: room for the PNG filter bytes, so
  // encode_png(Image&&) filters in place instead of allocating a second image.
  image.pixels.reserve(bytes + (output ? static_cast<std::size_t>(plan.height) : 0));
  const std::uint8_t all[4] = {background.r, background.g, background.b, background.a};
  std::uint8_t texel[4] = {};
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
    grow_filled(image.pixels, bytes, texel[0], meter);  // one pass: every byte is the same
    return image;
  }
  if (!grow_filled(image.pixels, bytes, std::uint8_t{0}, meter)) return image;
  for (std::size_t i = 0; i < image.pixels.size(); i += c) std::memcpy(&image.pixels[i], texel, c);
  return image;
}

void resolve(const std::vector<Image>& planes, Image& out, Rect rect) {
  const int c = out.channels();
  const auto n = static_cast<std::uint32_t>(planes.size());
  const bool alpha = out.format == PixelFormat::grey_alpha8 || out.format == PixelFormat::rgba8;
  for (int y = rect.y0; y < rect.y1; ++y) {
    const std::size_t begin = (static_cast<std::size_t>(y) * out.width + rect.x0) * c,
                      end = (static_cast<std::size_t>(y) * out.width + rect.x1) * c;
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
}

}  // namespace raster::detail
