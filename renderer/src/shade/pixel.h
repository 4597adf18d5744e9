// Pixel operations: how one colour becomes bytes (rounding, clamping), how it is written (store,
// source-over, weighted source-over), and the per-tile passes that finish pixels (union compositing,
// multisample resolve). Templated on the framebuffer's channel count so per-pixel code has no format
// branches.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>

#include "framebuffer/surface.h"
#include "raster/image.h"
#include "raster/plan.h"

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

/// Composites the primitive accumulated in `surface.coverage` over `rect`: each pixel with a share takes the
/// share-weighted mean colour at opacity min(1, summed share) x alpha; the accumulation is cleared for the
/// next primitive.
template <int C>
void composite_union(const Surface& surface, Rect rect) {
  // Only the pixels accumulated into (Surface::expanded's bits): a thin diagonal line reaches few of its
  // box's pixels.
  for (int y0 = rect.y0 - (rect.y0 - surface.y0) % 8; y0 < rect.y1; y0 += 8)
    for (int x0 = rect.x0 - (rect.x0 - surface.x0) % 8; x0 < rect.x1; x0 += 8) {
      std::uint64_t& touched = surface.expanded_bits(x0, y0);
      for (std::uint64_t m = touched; m; m &= m - 1) {
        const int bit = std::countr_zero(m), x = x0 + (bit & 7), y = y0 + (bit >> 3);
        float* acc = surface.coverage + surface.index(x, y) * kUnionFloats;
        const float share = acc[0];
        auto channel = [&](int k) {
          return static_cast<std::uint8_t>(std::min(255.0f, acc[1 + k] / share + 0.5f));
        };
        const Rgba8 c{channel(0), channel(1), channel(2), channel(3)};
        blend_weighted<C>(surface.pixel(x, y), c, std::min(share, 1.0f) * (c.a / 255.0f));
        std::fill_n(acc, kUnionFloats, 0.0f);
      }
      touched = 0;
    }
}

/// Multisampling: each pixel of `rect` whose samples differ becomes their mean, rounded to nearest (for
/// formats with alpha, the mean of premultiplied values: a transparent sample adds no colour); the others
/// already hold their one colour. N is the sample count (a constant, so the loops unroll and the means
/// divide by shifting).
template <int C, int N>
void resolve_samples(const Surface& surface, Rect rect) {
  for (int y0 = rect.y0; y0 < rect.y1; y0 += 8)
    for (int x0 = rect.x0; x0 < rect.x1; x0 += 8) {
      std::uint64_t& bits = surface.expanded_bits(x0, y0);
      for (std::uint64_t m = bits; m; m &= m - 1) {
        const int bit = std::countr_zero(m);
        const std::size_t index = surface.index(x0 + (bit & 7), y0 + (bit >> 3));
        auto sample = [&](int s) { return surface.sample_pixel<C>(s, index); };
        std::uint8_t* out = surface.color + index * C;
        if constexpr (C == 1 || C == 3) {
          for (int k = 0; k < C; ++k) {
            std::uint32_t sum = 0;
            for (int s = 0; s < N; ++s) sum += sample(s)[k];
            out[k] = static_cast<std::uint8_t>((sum + N / 2) / N);
          }
        } else {
          std::uint32_t alpha = 0;
          for (int s = 0; s < N; ++s) alpha += sample(s)[C - 1];
          for (int k = 0; k + 1 < C; ++k) {
            std::uint32_t weighted = 0;
            for (int s = 0; s < N; ++s) weighted += std::uint32_t{sample(s)[k]} * sample(s)[C - 1];
            out[k] = alpha ? static_cast<std::uint8_t>((weighted + alpha / 2) / alpha) : 0;
          }
          out[C - 1] = static_cast<std::uint8_t>((alpha + N / 2) / N);
        }
      }
      bits = 0;
    }
}
template <int C>
void resolve_samples(const Surface& surface, Rect rect) {
  switch (surface.sample_count) {
    case 4:
      return resolve_samples<C, 4>(surface, rect);
    case 8:
      return resolve_samples<C, 8>(surface, rect);
    default:  // 16: the plan's counts are kSampleCounts (scene.h)
      return resolve_samples<C, 16>(surface, rect);
  }
}

/// floor(x) for |x| < 2^62, without a library call.
inline std::int64_t floor_to_int(double x) {
  const auto i = static_cast<std::int64_t>(x);  // toward zero
  return i - (x < static_cast<double>(i));
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
