// Resolve: the per-tile passes that finish pixels once a tile's records are drawn: union compositing (area
// coverage of a primitive that adds up its own triangles) and the multisample resolve.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

#include "framebuffer/pixel.h"
#include "framebuffer/surface.h"
#include "raster/image.h"

namespace raster::detail {

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

}  // namespace raster::detail
