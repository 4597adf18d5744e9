// Shade: colour of a fragment (flat or interpolated) and how it is written (store or source-over blend).
// Templated on the framebuffer's channel count so the per-pixel code has no format branches.
#pragma once

#include <cstdint>

#include "raster/scene.h"

namespace raster::detail {

/// A channel value (0..255 scale) rounded to a byte; out-of-range values clamp and NaN becomes 0, so a
/// float never reaches an integer conversion it cannot survive.
inline std::uint8_t to_byte(double x) {
  if (!(x > 0)) return 0;  // also NaN
  return x >= 254.5 ? 255 : static_cast<std::uint8_t>(x + 0.5);
}

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

}  // namespace raster::detail
