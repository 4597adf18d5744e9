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

Image make_color_buffer(const RenderPlan& plan, Rgba8 background, StopMeter& meter) {
  Image image;
  image.width = plan.width;
  image.height = plan.height;
  image.format = plan.format;
  const auto bytes = static_cast<std::size_t>(plan.memory.color_bytes);
  // The output gets one byte per row more than the pixels: room for the PNG filter bytes, so
  // encode_png(Image&&) filters in place instead of allocating a second image.
  image.pixels.reserve(bytes + static_cast<std::size_t>(plan.height));
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

}  // namespace raster::detail
