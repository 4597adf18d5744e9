// Surface: where a tile draws, as the kernels see it. A tile's storage (framebuffer/tiles.h) or, when tiles
// draw in place, the image itself -> pointers, strides and the plan's coverage mode; the per-pixel code of
// coverage and shading addresses pixels, depth and samples only through it.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "base/grid.h"
#include "raster/plan.h"

namespace raster::detail {

/// Where a tile draws: a tile's own colour (and depth) storage, row-major, holding the pixels of image
/// rectangle [x0, x0 + width) x [y0, ...). Small and contiguous, so a tile's pixels stay in the nearest
/// cache however wide the image is (rows of a 1024-px RGB image are 3 KiB apart and alias in the L1).
struct Surface {
  std::uint8_t* color = nullptr;  ///< channels per pixel as the image's format
  float* depth = nullptr;         ///< z / w (reversed: larger is nearer) per sample, or nullptr without 3D;
                                  ///< multisampled: `sample_count` planes of `plane` values, sample-major
  float* coverage = nullptr;      ///< area coverage of union primitives: kUnionFloats (plan.h) a pixel
  int width = 0;                  ///< pixels per row of all of them (whole blocks)
  int x0 = 0, y0 = 0;             ///< image coordinates of the first pixel
  int channels = 3;
  /// The plan's coverage: which storage below is in use (samples: `samples` and `expanded`; area, for union
  /// primitives: `coverage` and `expanded`). Shading reads the mode here; it never infers it.
  Coverage coverage_mode = Coverage::centre;
  // Multisampling (sample_count > 1). A pixel whose samples all hold one colour keeps it in `color` alone;
  // its bit in `expanded` says when they differ, and then `samples` holds one colour per sample.
  int sample_count = 1;
  const SamplePoint* pattern = nullptr;  ///< the sample positions, sample_count of them
  /// The centroid of each set of samples (bit s: sample s), {x, y} pixels from the pixel centre, for 4 and
  /// 8 samples (coverage.h's centroid_offsets); nullptr otherwise.
  const std::array<double, 2>* centroids = nullptr;
  std::size_t plane = 0;            ///< pixels per sample plane (width x the tile's rows in blocks)
  std::uint8_t* samples = nullptr;  ///< sample_count planes of colour, each laid out like `color`
  /// One word per 8x8 block, row-major, bit 8 r + i per pixel: multisampling, the pixels whose samples
  /// differ; area coverage, the pixels a union primitive has accumulated coverage in.
  std::uint64_t* expanded = nullptr;
  /// Multisampling test hook (RenderPlan::keep_samples): every pixel keeps a colour per sample from the
  /// start, never one colour alone; the resolved bytes must be those of the compressed storage.
  bool keep_samples = false;
  std::int64_t* shaded = nullptr;  ///< counts pixels shaded (once per pixel per triangle)
  Simd simd = Simd::sse2;          ///< the plan's choice of kernels
  std::uint64_t& expanded_bits(int bx, int by) const {  // the word of the block at image pixel (bx, by)
    return expanded[static_cast<std::size_t>((by - y0) / 8) * static_cast<std::size_t>(width / 8) +
                    static_cast<std::size_t>((bx - x0) / 8)];
  }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x - x0);
  }
  std::uint8_t* pixel(int x, int y) const { return color + index(x, y) * static_cast<std::size_t>(channels); }
  template <int C>  ///< the same, for kernels compiled for C channels (== channels)
  std::uint8_t* pixel(int x, int y) const {
    return color + index(x, y) * C;
  }

  // The multisample storage steps, for every kernel that writes samples (triangles, points).
  template <int C>  ///< sample s of the pixel at `index`
  std::uint8_t* sample_pixel(int s, std::size_t at) const {
    return samples + (static_cast<std::size_t>(s) * plane + at) * C;
  }
  template <int C>  ///< the pixel at `index` is about to hold different colours: each sample takes its one
  void expand(std::size_t at) const {
    for (int s = 0; s < sample_count; ++s) std::memcpy(sample_pixel<C>(s, at), color + at * C, C);
  }
  /// The pixels of `bits` in the block at image pixel (bx, by), whose word of `expanded` is `word`, have
  /// just had one colour written to `color` for all their samples: it is stored once again (their bits
  /// cleared), or, keeping samples, written through to each sample.
  template <int C>
  [[gnu::always_inline]] inline void one_colour(std::uint64_t& word, int bx, int by,
                                                std::uint64_t bits) const {
    if (!keep_samples) [[likely]] {
      word &= ~bits;
      return;
    }
    for (std::uint64_t m = bits; m; m &= m - 1)
      expand<C>(index(bx + (std::countr_zero(m) & 7), by + (std::countr_zero(m) >> 3)));
  }
  template <int C>  ///< the same, finding the block's word
  void one_colour(int bx, int by, std::uint64_t bits) const {
    one_colour<C>(expanded_bits(bx, by), bx, by, bits);
  }
};

}  // namespace raster::detail
