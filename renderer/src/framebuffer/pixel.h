// Pixel storage: how one colour is written into a framebuffer's bytes (store, source-over, weighted
// source-over) and which bytes of a row of pixels a mask covers. Templated on the framebuffer's channel
// count so per-pixel code has no format branches. A colour becomes bytes through base/srgb.h's to_byte.
#pragma once

#include <cstdint>

#include "raster/image.h"

namespace raster::detail {

/// round(x / 255) for 0 <= x <= 255 * 255 * 2, exact.
inline std::uint32_t div255(std::uint32_t x) {
  return (x + 127) / 255;
}

/// Writes an opaque-or-replacing colour. Grey formats use r (the plan chose grey only if r == g == b).
template <int C>
inline void store(std::uint8_t* px, Rgba8 c) {
  if constexpr (C == 1) {
    px[0] = c.r;
  } else if constexpr (C == 2) {
    px[0] = c.r, px[1] = c.a;
  } else if constexpr (C == 3) {
    px[0] = c.r, px[1] = c.g, px[2] = c.b;
  } else {
    px[0] = c.r, px[1] = c.g, px[2] = c.b, px[3] = c.a;
  }
}

/// Source-over with straight alpha. Formats without alpha hold an opaque destination, which keeps the
/// simple form; formats with alpha use the general one.
template <int C>
inline void blend(std::uint8_t* px, Rgba8 c) {
  const std::uint32_t sa = c.a, ia = 255 - sa;
  if constexpr (C == 1 || C == 3) {
    px[0] = static_cast<std::uint8_t>(div255(c.r * sa + px[0] * ia));
    if constexpr (C == 3) {
      px[1] = static_cast<std::uint8_t>(div255(c.g * sa + px[1] * ia));
      px[2] = static_cast<std::uint8_t>(div255(c.b * sa + px[2] * ia));
    }
  } else {
    constexpr int alpha_index = C - 1;
    const std::uint32_t da = px[alpha_index];
    // Output alpha and colours scaled by 255 * 255 to stay in integers: oa = sa + da (1 - sa).
    const std::uint32_t oa = sa * 255 + da * ia;
    if (oa == 0) {
      store<C>(px, Rgba8{0, 0, 0, 0});
      return;
    }
    auto mix = [&](std::uint32_t s, std::uint32_t d) {
      return static_cast<std::uint8_t>((s * sa * 255 + d * da * ia + oa / 2) / oa);
    };
    px[0] = mix(c.r, px[0]);
    if constexpr (C == 4) {
      px[1] = mix(c.g, px[1]);
      px[2] = mix(c.b, px[2]);
    }
    px[alpha_index] = static_cast<std::uint8_t>(div255(oa));
  }
}

/// How a primitive writes a colour: source-over when its plan says it blends, else a plain store.
template <int C>
inline void put(std::uint8_t* px, Rgba8 c, bool blending) {
  if (blending)
    blend<C>(px, c);
  else
    store<C>(px, c);
}

/// Source-over of `c` at opacity `w` in [0, 1] (a covered share times the colour's own alpha / 255), rounded
/// to nearest: how area coverage composites a cut pixel.
template <int C>
inline void blend_weighted(std::uint8_t* px, Rgba8 c, float w) {
  if constexpr (C == 1 || C == 3) {
    // d + (s - d) w lies between s and d, so adding 0.5 and truncating rounds without leaving 0..255.
    auto mix = [&](std::uint8_t s, std::uint8_t d) {
      return static_cast<std::uint8_t>(static_cast<float>(d) + static_cast<float>(s - d) * w + 0.5f);
    };
    px[0] = mix(c.r, px[0]);
    if constexpr (C == 3) px[1] = mix(c.g, px[1]), px[2] = mix(c.b, px[2]);
  } else {
    constexpr int alpha_index = C - 1;
    const float da = px[alpha_index] / 255.0f, keep = da * (1 - w), oa = w + keep;
    if (!(oa > 0)) {
      store<C>(px, Rgba8{0, 0, 0, 0});
      return;
    }
    auto mix = [&](std::uint8_t s, std::uint8_t d) {
      return static_cast<std::uint8_t>((static_cast<float>(s) * w + static_cast<float>(d) * keep) / oa +
                                       0.5f);
    };
    px[0] = mix(c.r, px[0]);
    if constexpr (C == 4) px[1] = mix(c.g, px[1]), px[2] = mix(c.b, px[2]);
    px[alpha_index] = static_cast<std::uint8_t>(oa * 255 + 0.5f);
  }
}

/// For each 8-bit row mask, the bytes of an 8-pixel row of C channels that belong to covered pixels (0xff),
/// padded to 32 bytes.
template <int C>
struct ByteMasks {
  alignas(16) std::uint8_t mask[256][32];
  constexpr ByteMasks() : mask{} {
    for (int bits = 0; bits < 256; ++bits)
      for (int i = 0; i < 8; ++i)
        for (int c = 0; c < C; ++c) mask[bits][i * C + c] = (bits >> i) & 1 ? 0xff : 0;
  }
  const std::uint8_t* operator[](unsigned bits) const { return mask[bits]; }
};
template <int C>
inline constexpr ByteMasks<C> kByteMasks{};

}  // namespace raster::detail
