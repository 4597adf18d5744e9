// Image: the finished pixels a render produces and the PNG encoder consumes.
#pragma once

#include <cstdint>
#include <vector>

namespace raster {

/// Pixel layout of an Image; the value is the number of interleaved 8-bit channels.
enum class PixelFormat : std::uint8_t {
  grey8 = 1,        ///< Y
  grey_alpha8 = 2,  ///< Y, A (straight alpha)
  rgb8 = 3,         ///< R, G, B
  rgba8 = 4,        ///< R, G, B, A (straight alpha)
};

inline int channel_count(PixelFormat f) {
  return static_cast<int>(f);
}

/// Pixels row-major, top row first, channels interleaved as PixelFormat says, no row padding.
struct Image {
  int width = 0;   ///< pixels
  int height = 0;  ///< pixels
  PixelFormat format = PixelFormat::rgb8;
  std::vector<std::uint8_t> pixels;  ///< width * height * channel_count(format) bytes

  int channels() const { return channel_count(format); }
  const std::uint8_t* at(int x, int y) const {
    return pixels.data() + (static_cast<std::size_t>(y) * width + x) * channels();
  }
};

}  // namespace raster
