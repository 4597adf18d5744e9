#include "framebuffer/framebuffer.h"

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
  // A chunk of whole pixels made once and appended over and over: each byte is written once, with no zero
  // fill before it (a pixel at a time, the clear was most of a thumbnail's render).
  constexpr std::size_t kChunk = 3 * 4 * 1024;  // a multiple of every pixel size
  std::uint8_t chunk[kChunk];
  for (std::size_t i = 0; i < kChunk; i += static_cast<std::size_t>(c)) std::memcpy(chunk + i, texel, c);
  std::size_t unchecked = 0;
  while (image.pixels.size() < bytes) {
    if (unchecked >= kClearChunkBytes) {
      if (meter.check()) return image;
      unchecked = 0;
    }
    const std::size_t n = std::min(kChunk, bytes - image.pixels.size());
    image.pixels.insert(image.pixels.end(), chunk, chunk + n);
    unchecked += n;
  }
  return image;
}

}  // namespace raster::detail
