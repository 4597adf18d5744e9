#include "base/mip_chain.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "base/srgb.h"

namespace raster::detail {

std::int64_t mip_bytes(int width, int height) {
  std::int64_t bytes = 0;
  while (width > 1 || height > 1) {
    width = std::max(1, width / 2), height = std::max(1, height / 2);
    bytes += std::int64_t{width} * height * 4;
  }
  return bytes;
}

MipChain build_mips(const Texture& texture, StopMeter* meter) {
  MipChain chain;
  chain.texture = &texture;
  chain.levels.push_back({texture.width, texture.height, texture.rgba.data()});
  while (chain.levels.back().width > 1 || chain.levels.back().height > 1) {
    const MipLevel from = chain.levels.back();
    const int w = std::max(1, from.width / 2), h = std::max(1, from.height / 2);
    // Not zeroed: every byte is written below (a 4096^2 chain is 21 MB).
    std::uint8_t* const out =
        chain.storage
            .emplace_back(std::make_unique_for_overwrite<std::uint8_t[]>(std::size_t(w) * std::size_t(h) * 4))
            .get();
    // Texel 2x + 1 (row 2y + 1) exists unless that side of `from` is 1 (an odd side's last one is dropped).
    const std::size_t dx = from.width > 1 ? 4 : 0, dy = from.height > 1 ? std::size_t(from.width) * 4 : 0;
    for (int y = 0; y < h; ++y) {
      // A 4096^2 texture's chain is 5.6M texels: the render's deadline is asked as for a row of pixels.
      if (meter && meter->add(w)) return chain;
      const std::uint8_t* row = from.rgba + std::size_t(2 * y) * std::size_t(from.width) * 4;
      std::uint8_t* o = out + std::size_t(y) * std::size_t(w) * 4;
      for (int x = 0; x < w; ++x, o += 4) {
        const std::uint8_t* q = row + std::size_t(8 * x);
        const std::uint8_t* taps[4] = {q, q + dx, q + dy, q + dy + dx};
        float acc[4] = {};  // premultiplied linear colour, alpha (0..255)
        if ((taps[0][3] & taps[1][3] & taps[2][3] & taps[3][3]) == 255) {  // opaque: a plain average
          for (const std::uint8_t* t : taps)
            for (int c = 0; c < 3; ++c) acc[c] += srgb_to_linear(t[c]);
          for (int c = 0; c < 3; ++c) o[c] = linear_to_srgb(acc[c] * 0.25f);
          o[3] = 255;
          continue;
        }
        for (const std::uint8_t* t : taps) {
          const float a = t[3];
          for (int c = 0; c < 3; ++c) acc[c] += a * srgb_to_linear(t[c]);
          acc[3] += a;
        }
        for (int c = 0; c < 3; ++c) o[c] = acc[3] > 0 ? linear_to_srgb(acc[c] / acc[3]) : 0;
        o[3] = static_cast<std::uint8_t>(std::lround(acc[3] * 0.25f));
      }
    }
    chain.levels.push_back({w, h, out});
  }
  return chain;
}

// Bytes as stored, each level the 2x2 average of the one below rounded to nearest (GL's glGenerateMipmap
// for an RGBA8 texture): what a shader's channels sample.
MipChain build_raw_mips(const Texture& texture, StopMeter* meter) {
  MipChain chain;
  chain.texture = &texture;
  chain.levels.push_back({texture.width, texture.height, texture.rgba.data()});
  while (chain.levels.back().width > 1 || chain.levels.back().height > 1) {
    const MipLevel from = chain.levels.back();
    const int w = std::max(1, from.width / 2), h = std::max(1, from.height / 2);
    std::uint8_t* const out =
        chain.storage
            .emplace_back(std::make_unique_for_overwrite<std::uint8_t[]>(std::size_t(w) * std::size_t(h) * 4))
            .get();
    const std::size_t dx = from.width > 1 ? 4 : 0, dy = from.height > 1 ? std::size_t(from.width) * 4 : 0;
    for (int y = 0; y < h; ++y) {
      if (meter && meter->add(w)) return chain;
      const std::uint8_t* row = from.rgba + std::size_t(2 * y) * std::size_t(from.width) * 4;
      std::uint8_t* o = out + std::size_t(y) * std::size_t(w) * 4;
      for (int x = 0; x < w; ++x, o += 4) {
        const std::uint8_t* q = row + std::size_t(8 * x);
        for (int c = 0; c < 4; ++c)
          o[c] = static_cast<std::uint8_t>((q[c] + q[dx + c] + q[dy + c] + q[dy + dx + c] + 2) / 4);
      }
    }
    chain.levels.push_back({w, h, out});
  }
  return chain;
}

}  // namespace raster::detail
