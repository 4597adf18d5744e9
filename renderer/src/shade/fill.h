// Fill: the 2D colour kernels of shading. One colour (FlatFill) or per-vertex colours interpolated in
// screen space (ColorPlanes), written over a block's covered pixels, over a run of whole block rows, or as a
// rectangle's rows. Everything else a triangle's pixels need (depth, lighting, textures, samples, area
// shares) is TriangleShader's (shade.h), which hands 2D blocks to these.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "base/srgb.h"
#include "coverage/coverage.h"
#include "framebuffer/pixel.h"

namespace raster::detail {

/// floor(x) for |x| < 2^62, without a library call.
inline std::int64_t floor_to_int(double x) {
  const auto i = static_cast<std::int64_t>(x);  // toward zero
  return i - (x < static_cast<double>(i));
}

/// One colour over a tile's pixels (the surface's colour storage), stored or blended.
template <int C>
class FlatFill {
 public:
  FlatFill() = default;
  FlatFill(const Surface& surface, Rgba8 color, bool blend)
      : surface_(&surface),
        flat_(color),
        blend_(blend),
        wide_(surface.simd == Simd::avx2 && (C == 3 || C == 4) && !blend) {
    for (int i = 0; i < kBlock; ++i) store<C>(row_bytes_ + i * C, flat_);
#if defined(__SSE2__)
    pattern_[0] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row_bytes_));
    pattern_[1] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row_bytes_ + 16));
#endif
  }

  // One colour: a whole row of a block is one copy of eight pixels' bytes.
  void block(const Block& b) const {
#if defined(__x86_64__)
    if (wide_) return block_avx2(b);
#endif
    const std::uint8_t* row_bytes = row_bytes_;
    const Rgba8 flat = flat_;  // locals: pixel stores (through uint8_t*) could alias the members
#if defined(__SSE2__)
    const __m128i pattern[2] = {pattern_[0], pattern_[1]};
#else
    const int pattern[2] = {};
#endif
    for (int r = 0; r < kBlock; ++r) {
      unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      std::uint8_t* row = surface_->pixel<C>(b.x0, b.y0 + r);
      if (!blend_) {
#if defined(__SSE2__)
        if constexpr (C == 3 || C == 4) {
          // Whole block rows, the covered bytes chosen by a mask: no branch per row shape to mispredict.
          // The tile storage is whole blocks wide, so the row's other bytes are this tile's own.
          const __m128i* m = reinterpret_cast<const __m128i*>(kByteMasks<C>[bits]);
          __m128i* out = reinterpret_cast<__m128i*>(row);
          const __m128i lo = _mm_loadu_si128(out), lo_m = _mm_load_si128(m);
          _mm_storeu_si128(out, _mm_or_si128(_mm_and_si128(pattern[0], lo_m), _mm_andnot_si128(lo_m, lo)));
          if constexpr (C == 4) {
            const __m128i hi = _mm_loadu_si128(out + 1), hi_m = _mm_load_si128(m + 1);
            _mm_storeu_si128(out + 1,
                             _mm_or_si128(_mm_and_si128(pattern[1], hi_m), _mm_andnot_si128(hi_m, hi)));
          } else {
            const __m128i hi = _mm_loadl_epi64(out + 1), hi_m = _mm_load_si128(m + 1);
            _mm_storel_epi64(out + 1,
                             _mm_or_si128(_mm_and_si128(pattern[1], hi_m), _mm_andnot_si128(hi_m, hi)));
          }
          continue;
        }
#endif
        if (bits == 0xff) {
          store_row_pattern(row, pattern);
          continue;
        }
        const int first = std::countr_zero(bits), last = 31 - std::countl_zero(bits);
        if ((bits >> first) + 1 == 1u << (last - first + 1)) {  // one run: a prefix of the row's bytes
          copy_run(row + first * C, row_bytes, (last - first + 1) * C);
          continue;
        }
      }
      for (; bits; bits &= bits - 1) put<C>(row + std::countr_zero(bits) * C, flat, blend_);
    }
  }

#if defined(__x86_64__)
  // block()'s opaque RGB(A) rows with AVX2 byte blends: a row is the pattern where its mask's bytes are set
  // and what was there elsewhere (this block's other pixels, so this tile's).
  __attribute__((target("avx2"))) void block_avx2(const Block& b) const {
    const std::size_t stride = static_cast<std::size_t>(surface_->width) * C;
    std::uint8_t* row = surface_->pixel<C>(b.x0, b.y0);
    if constexpr (C == 4) {
      const __m256i pattern = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(row_bytes_));
      for (int r = 0; r < kBlock; ++r, row += stride) {
        const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
        if (!bits) continue;
        __m256i* out = reinterpret_cast<__m256i*>(row);
        const __m256i m = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kByteMasks<C>[bits]));
        _mm256_storeu_si256(out, _mm256_blendv_epi8(_mm256_loadu_si256(out), pattern, m));
      }
    } else {
      const __m128i lo = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row_bytes_));
      const __m128i hi = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row_bytes_ + 16));
      for (int r = 0; r < kBlock; ++r, row += stride) {
        const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
        if (!bits) continue;
        const __m128i* m = reinterpret_cast<const __m128i*>(kByteMasks<C>[bits]);
        __m128i* out = reinterpret_cast<__m128i*>(row);
        _mm_storeu_si128(out, _mm_blendv_epi8(_mm_loadu_si128(out), lo, _mm_load_si128(m)));
        _mm_storel_epi64(out + 1, _mm_blendv_epi8(_mm_loadl_epi64(out + 1), hi, _mm_load_si128(m + 1)));
      }
    }
  }
#endif

  // `n` pixels of the flat colour from `p` on: whole block rows from registers, the rest as a run.
  void run(std::uint8_t* p, int n) const {
#if defined(__SSE2__)
    const __m128i pattern[2] = {pattern_[0], pattern_[1]};
#else
    const int pattern[2] = {};
#endif
    for (; n >= kBlock; n -= kBlock, p += kBlock * C) store_row_pattern(p, pattern);
    if (n > 0) copy_run(p, row_bytes_, n * C);
  }

 private:
  // A full block row of the flat colour. From registers: loading the pattern after each store would make
  // the load wait on the store whenever their addresses agree modulo 4 KiB.
  template <typename Pattern>
  void store_row_pattern(std::uint8_t* row, const Pattern (&pattern)[2]) const {
#if defined(__SSE2__)
    if constexpr (C == 3 || C == 4) {
      const __m128i a = pattern[0], b = pattern[1];
      _mm_storeu_si128(reinterpret_cast<__m128i*>(row), a);
      if constexpr (C == 4)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(row + 16), b);
      else
        _mm_storel_epi64(reinterpret_cast<__m128i*>(row + 16), b);
      return;
    }
#endif
    std::memcpy(row, row_bytes_, kBlock * C);
  }

  // Copies the first `n` bytes (1 <= n <= 32) of `src` (which `dst` does not overlap) with two fixed-size
  // moves that may overlap each other (the same bytes go to the same places twice), instead of a call for a
  // variable length.
  static void copy_run(std::uint8_t* dst, const std::uint8_t* src, int n) {
    auto move = [&](int at, auto size) { std::memcpy(dst + at, src + at, decltype(size)::value); };
    using S1 = std::integral_constant<int, 1>;
    using S4 = std::integral_constant<int, 4>;
    using S8 = std::integral_constant<int, 8>;
    using S16 = std::integral_constant<int, 16>;
    if (n >= 16) {
      move(0, S16{}), move(n - 16, S16{});
    } else if (n >= 8) {
      move(0, S8{}), move(n - 8, S8{});
    } else if (n >= 4) {
      move(0, S4{}), move(n - 4, S4{});
    } else {
      for (int i = 0; i < n; ++i) move(i, S1{});
    }
  }

  const Surface* surface_ = nullptr;
  Rgba8 flat_;
  bool blend_ = false;
  bool wide_ = false;                // the plan chose AVX2 and this is opaque RGB(A)
  std::uint8_t row_bytes_[32] = {};  // a block row of the colour, stored (kBlock * C bytes used)
#if defined(__SSE2__)
  __m128i pattern_[2] = {};  // the same 32 bytes in registers' form
#endif
};

/// Per-vertex colours of a 2D triangle (attributes: 3 x RGBA, 0..255 scale) interpolated in screen space
/// over a tile's pixels, stored or blended.
template <int C>
class ColorPlanes {
 public:
  ColorPlanes() = default;
  /// `color[k]`: vertex k's RGBA in the record; `step_x` and `step_y` are the record's edge-value steps per
  /// pixel right and down and `area` its doubled area, as doubles (exact for the fast range).
  ColorPlanes(const Surface& surface, const float* const (&color)[3], const double (&step_x)[3],
              const double (&step_y)[3], double area, bool blend)
      : surface_(&surface), color_{color[0], color[1], color[2]}, blend_(blend) {
    for (int ch = 0; ch < 4; ++ch) {
      lo_[ch] = std::min({color_[0][ch], color_[1][ch], color_[2][ch]});
      hi_[ch] = std::max({color_[0][ch], color_[1][ch], color_[2][ch]});
    }
    // 16.16 change per pixel right and down, from the exact edge steps; steep ones take the exact path.
    const double scale = 65536.0 / area;
    for (int ch = 0; ch < 4; ++ch) {
      const double v[3] = {color_[0][ch], color_[1][ch], color_[2][ch]};
      const double sx = (step_x[0] * v[0] + step_x[1] * v[1] + step_x[2] * v[2]) * scale;
      const double sy = (step_y[0] * v[0] + step_y[1] * v[1] + step_y[2] * v[2]) * scale;
      steep_ = steep_ || !(std::fabs(sx) < 0x1p40 && std::fabs(sy) < 0x1p40);
      slope_x_[ch] = steep_ ? 0 : floor_to_int(sx + 0.5);
      slope_y_[ch] = steep_ ? 0 : floor_to_int(sy + 0.5);
    }
#if defined(__x86_64__)
    wide_ = surface.simd == Simd::avx2 && (C == 3 || C == 4) && !blend && !steep_;
    for (int k = 0; k < 3; ++k)
      for (int ch = 0; ch < 4; ++ch) vertex_[k][ch] = color_[k][ch];
    for (int ch = 0; ch < 4; ++ch)
      reach_[ch] = static_cast<double>(8 * (std::abs(slope_x_[ch]) + std::abs(slope_y_[ch])));
#endif
  }

  /// The colour at barycentrics `l`, each channel clamped to the vertices' range (a cut pixel's centre may
  /// lie outside the triangle): the exact value for single pixels (area shares, samples, unions).
  Rgba8 at(const double (&l)[3]) const {
    std::uint8_t out[4];
    for (int ch = 0; ch < 4; ++ch) {
      const double v = l[0] * color_[0][ch] + l[1] * color_[1][ch] + l[2] * color_[2][ch];
      out[ch] = to_byte(std::clamp(v, lo_[ch], hi_[ch]));
    }
    return {out[0], out[1], out[2], out[3]};
  }

  // Colours interpolated in screen space (2D): channel = sum_k E_k v_k / area, rounded to nearest. Per
  // block, the value at its first pixel comes from the exact edge values and steps in 16.16 fixed point
  // across the block's rows and columns (at most 14 steps: an error below 10^-3 of a level, so a covered
  // pixel, whose exact value lies in the vertices' range, rounds into it). The block grid does not depend on
  // the tile, so neither does any pixel's value.
  void block(const Block& b) const {
#if defined(__x86_64__)
    if (wide_) return block_avx2(b);
#endif
    block_sse2(b);
  }

  /// Every pixel of `clip` covered; `first` is the block at the clip's block-grid origin (exact values):
  /// block by block, each with exactly the values it would have had.
  void rect(Rect clip, const Block& first) const {
    for_each_block(clip, first, [&](const Block& b) { block(b); });
  }

 private:
  void block_sse2(const Block& b) const {
    if (steep_) return shade_smooth_exact(b);
    const double scale = 65536.0 / b.area;
    std::int64_t start[4];
    for (int ch = 0; ch < 4; ++ch) {
      const double n0 = b.e[0] * color_[0][ch] + b.e[1] * color_[1][ch] + b.e[2] * color_[2][ch];
      start[ch] = floor_to_int(n0 * scale + 0.5) + 0x8000;
    }
#if defined(__SSE2__)
    if (fits_int32(start)) {
      if constexpr (C == 3 || C == 4)
        if (!blend_) return shade_smooth_rows(b, start);
      return shade_smooth_lanes(b, start);
    }
#endif
    for (int r = 0; r < kBlock; ++r) {
      unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      std::uint8_t* row = surface_->pixel<C>(b.x0, b.y0 + r);
      for (; bits; bits &= bits - 1) {
        const int i = std::countr_zero(bits);
        std::uint8_t out[4];
        for (int ch = 0; ch < 4; ++ch) {
          const std::int64_t v = (start[ch] + i * slope_x_[ch] + r * slope_y_[ch]) >> 16;
          out[ch] = static_cast<std::uint8_t>(std::clamp<std::int64_t>(v, 0, 255));
        }
        put<C>(row + i * C, Rgba8{out[0], out[1], out[2], out[3]}, blend_);
      }
    }
  }

 private:
#if defined(__x86_64__)
  // block_sse2's opaque RGB(A) path in AVX2: the four channels' starting values side by side in doubles
  // (the same operations in the same order, so the same bits), then a block row in one register per
  // channel; a pixel's word is its channels' bytes side by side, RGB drops each word's spare byte with one
  // shuffle per half, and a row is stored whole (the tile storage is whole blocks wide). Anything else
  // (steep, blending, grey, values beyond int32) goes to block_sse2.
  __attribute__((target("avx2"))) void block_avx2(const Block& b) const {
    const __m256d scale = _mm256_set1_pd(65536.0 / b.area);
    __m256d n = _mm256_mul_pd(_mm256_set1_pd(b.e[0]), _mm256_loadu_pd(vertex_[0]));
    n = _mm256_add_pd(n, _mm256_mul_pd(_mm256_set1_pd(b.e[1]), _mm256_loadu_pd(vertex_[1])));
    n = _mm256_add_pd(n, _mm256_mul_pd(_mm256_set1_pd(b.e[2]), _mm256_loadu_pd(vertex_[2])));
    n = _mm256_floor_pd(_mm256_add_pd(_mm256_mul_pd(n, scale), _mm256_set1_pd(0.5)));
    n = _mm256_add_pd(n, _mm256_set1_pd(0x8000));
    // fits_int32: |start| + reach < 2^31 in every channel (all exact in doubles)
    const __m256d magnitude = _mm256_andnot_pd(_mm256_set1_pd(-0.0), n);
    const __m256d far = _mm256_add_pd(magnitude, _mm256_loadu_pd(reach_));
    if (_mm256_movemask_pd(_mm256_cmp_pd(far, _mm256_set1_pd(0x1p31), _CMP_LT_OQ)) != 0xf)
      return block_sse2(b);
    const __m128i start = _mm256_cvtpd_epi32(n);
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    __m256i v[C], down[C];
    const std::int32_t starts[4] = {_mm_extract_epi32(start, 0), _mm_extract_epi32(start, 1),
                                    _mm_extract_epi32(start, 2), _mm_extract_epi32(start, 3)};
    for (int ch = 0; ch < C; ++ch) {
      v[ch] = _mm256_add_epi32(
          _mm256_set1_epi32(starts[ch]),
          _mm256_mullo_epi32(lane, _mm256_set1_epi32(static_cast<std::int32_t>(slope_x_[ch]))));
      down[ch] = _mm256_set1_epi32(static_cast<std::int32_t>(slope_y_[ch]));
    }
    const __m256i pack = _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1, 0, 1, 2, 4,
                                          5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
    const std::size_t stride = static_cast<std::size_t>(surface_->width) * C;
    std::uint8_t* p = surface_->pixel<C>(b.x0, b.y0);
    for (int r = 0; r < kBlock; ++r, p += stride) {
      const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (bits) {
        __m256i w = _mm256_srli_epi32(v[0], 16);
        for (int ch = 1; ch < C; ++ch)
          w = _mm256_or_si256(w, _mm256_slli_epi32(_mm256_srli_epi32(v[ch], 16), 8 * ch));
        // Partial rows keep the other pixels' bytes with a byte blend: they are this block's, so this tile's.
        const std::uint8_t* keep = kByteMasks<C>[bits];
        if constexpr (C == 4) {
          if (bits == 0xff) {
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), w);
          } else {
            __m256i* out = reinterpret_cast<__m256i*>(p);
            const __m256i m = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(keep));
            _mm256_storeu_si256(out, _mm256_blendv_epi8(_mm256_loadu_si256(out), w, m));
          }
        } else {
          const __m256i packed = _mm256_shuffle_epi8(w, pack);  // 12 bytes at the start of each half
          const __m128i a = _mm256_castsi256_si128(packed), b = _mm256_extracti128_si256(packed, 1);
          const __m128i lo = _mm_or_si128(a, _mm_slli_si128(b, 12)), hi = _mm_srli_si128(b, 4);
          __m128i* out = reinterpret_cast<__m128i*>(p);
          if (bits == 0xff) {
            _mm_storeu_si128(out, lo);
            _mm_storel_epi64(out + 1, hi);
          } else {
            const __m128i m_lo = _mm_load_si128(reinterpret_cast<const __m128i*>(keep));
            const __m128i m_hi = _mm_load_si128(reinterpret_cast<const __m128i*>(keep + 16));
            _mm_storeu_si128(out, _mm_blendv_epi8(_mm_loadu_si128(out), lo, m_lo));
            _mm_storel_epi64(out + 1, _mm_blendv_epi8(_mm_loadl_epi64(out + 1), hi, m_hi));
          }
        }
      }
      for (int ch = 0; ch < C; ++ch) v[ch] = _mm256_add_epi32(v[ch], down[ch]);
    }
  }
#endif

  // Every value the block can reach fits an int32 lane.
  bool fits_int32(const std::int64_t (&start)[4]) const {
    for (int ch = 0; ch < 4; ++ch)
      if (std::abs(start[ch]) + 8 * (std::abs(slope_x_[ch]) + std::abs(slope_y_[ch])) >=
          (std::int64_t{1} << 31))
        return false;
    return true;
  }

#if defined(__SSE2__)
  // The four channels of a pixel in the four lanes of one register: a pixel is an add, a shift and two
  // saturating packs. A row's covered pixels are one run (a triangle is convex, and so is the clip), so an
  // opaque run stores whole words: each pixel's spare byte is overwritten by the next pixel, the run's last
  // pixel is stored exactly.
  // Opaque RGB(A): the pixels of a row in the lanes, one register of four per channel and half row, stepped
  // down the block; a row's words are the channels' bytes side by side (a covered pixel's values lie in
  // 0..255, see shade_smooth, so its bytes cannot spill into each other; other lanes are not stored).
  void shade_smooth_rows(const Block& b, const std::int64_t (&start)[4]) const {
    __m128i left[C], four[C], down[C];
    for (int ch = 0; ch < C; ++ch) {
      const auto v = static_cast<std::int32_t>(start[ch]), d = static_cast<std::int32_t>(slope_x_[ch]);
      left[ch] = _mm_setr_epi32(v, v + d, v + 2 * d, v + 3 * d);
      four[ch] = _mm_set1_epi32(4 * d);
      down[ch] = _mm_set1_epi32(static_cast<std::int32_t>(slope_y_[ch]));
    }
    for (int r = 0; r < kBlock; ++r) {
      const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (bits) {
        __m128i lo = _mm_setzero_si128(), hi = _mm_setzero_si128();
        for (int ch = 0; ch < C; ++ch) {
          const __m128i right = _mm_add_epi32(left[ch], four[ch]);
          lo = _mm_or_si128(lo, _mm_slli_epi32(_mm_srli_epi32(left[ch], 16), 8 * ch));
          hi = _mm_or_si128(hi, _mm_slli_epi32(_mm_srli_epi32(right, 16), 8 * ch));
        }
        std::uint8_t* p = surface_->pixel<C>(b.x0, b.y0 + r);
        if (bits == 0xff) {
          store_full_row(p, lo, hi);
        } else {
          // Words straight from the registers (a trip through memory stalls store forwarding).
          const std::uint64_t q[4] = {static_cast<std::uint64_t>(_mm_cvtsi128_si64(lo)),
                                      static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_srli_si128(lo, 8))),
                                      static_cast<std::uint64_t>(_mm_cvtsi128_si64(hi)),
                                      static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_srli_si128(hi, 8)))};
          for (unsigned m = bits; m; m &= m - 1) {
            const int i = std::countr_zero(m);
            const auto word = static_cast<std::uint32_t>(q[i >> 1] >> (32 * (i & 1)));
            std::memcpy(p + C * i, &word, C);
          }
        }
      }
      for (int ch = 0; ch < C; ++ch) left[ch] = _mm_add_epi32(left[ch], down[ch]);
    }
  }

  // Eight pixels' words (four in each register) stored as a block row of C bytes a pixel. RGB: each 64-bit
  // half becomes two pixels' six bytes side by side; nothing past the row is written.
  static void store_full_row(std::uint8_t* p, __m128i lo, __m128i hi) {
    if constexpr (C == 4) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(p), lo);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(p + 16), hi);
    } else {
      const __m128i even = _mm_set_epi32(0, 0xffffff, 0, 0xffffff),
                    odd = _mm_set_epi32(0xffffff, 0, 0xffffff, 0);
      auto six = [&](__m128i w) {
        return _mm_or_si128(_mm_and_si128(w, even), _mm_srli_epi64(_mm_and_si128(w, odd), 8));
      };
      const __m128i a = six(lo), b = six(hi);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(p), a);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(p + 6), _mm_srli_si128(a, 8));
      _mm_storel_epi64(reinterpret_cast<__m128i*>(p + 12), b);
      const auto last = static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_srli_si128(b, 8)));
      std::memcpy(p + 18, &last, 6);
    }
  }

  void shade_smooth_lanes(const Block& b, const std::int64_t (&start)[4]) const {
    __m128i row_value = _mm_setr_epi32(static_cast<int>(start[0]), static_cast<int>(start[1]),
                                       static_cast<int>(start[2]), static_cast<int>(start[3]));
    const __m128i step_x = _mm_setr_epi32(static_cast<int>(slope_x_[0]), static_cast<int>(slope_x_[1]),
                                          static_cast<int>(slope_x_[2]), static_cast<int>(slope_x_[3]));
    const __m128i step_y = _mm_setr_epi32(static_cast<int>(slope_y_[0]), static_cast<int>(slope_y_[1]),
                                          static_cast<int>(slope_y_[2]), static_cast<int>(slope_y_[3]));
    auto bytes = [](__m128i v) {
      const __m128i words = _mm_packs_epi32(_mm_srai_epi32(v, 16), _mm_setzero_si128());
      return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_packus_epi16(words, words)));
    };
    auto color = [](std::uint32_t rgba) {
      return Rgba8{static_cast<std::uint8_t>(rgba), static_cast<std::uint8_t>(rgba >> 8),
                   static_cast<std::uint8_t>(rgba >> 16), static_cast<std::uint8_t>(rgba >> 24)};
    };
    for (int r = 0; r < kBlock; ++r, row_value = _mm_add_epi32(row_value, step_y)) {
      const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      const int lo = std::countr_zero(bits), hi = 31 - std::countl_zero(bits);
      std::uint8_t* p = surface_->pixel<C>(b.x0 + lo, b.y0 + r);
      __m128i v = row_value;
      for (int i = 0; i < lo; ++i) v = _mm_add_epi32(v, step_x);
      const bool run = (bits >> lo) + 1 == 1u << (hi - lo + 1);
      if ((C == 3 || C == 4) && run && !blend_) {
        for (int i = lo; i < hi; ++i, p += C, v = _mm_add_epi32(v, step_x)) {
          const std::uint32_t rgba = bytes(v);
          std::memcpy(p, &rgba, 4);
        }
        store<C>(p, color(bytes(v)));
        continue;
      }
      for (int i = lo; i <= hi; ++i, p += C, v = _mm_add_epi32(v, step_x))
        if (bits & (1u << i)) put<C>(p, color(bytes(v)), blend_);
    }
  }
#endif

  // The same value without stepping, for triangles whose colour changes by more than 2^24 levels a pixel
  // (slivers): eight lanes of exact doubles per row.
  void shade_smooth_exact(const Block& b) const {
    using D8 = double __attribute__((vector_size(64)));
    const D8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
    const double inv_area = 1.0 / b.area;
    for (int r = 0; r < kBlock; ++r) {
      unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      double e[3];
      for (int k = 0; k < 3; ++k) e[k] = b.e[k] + r * b.dy[k];
      std::uint8_t out[4][8] = {};
      for (int ch = 0; ch < 4; ++ch) {
        if (!stores(ch)) continue;
        const double v0 = color_[0][ch], v1 = color_[1][ch], v2 = color_[2][ch];
        const double n0 = e[0] * v0 + e[1] * v1 + e[2] * v2;
        const double dn = b.dx[0] * v0 + b.dx[1] * v1 + b.dx[2] * v2;
        D8 value = (n0 + lane * dn) * inv_area + 0.5;
        value = value < lo_[ch] ? lo_[ch] : value;
        value = value > hi_[ch] + 0.5 ? hi_[ch] + 0.5 : value;  // stays below hi + 1 after flooring
        for (int i = 0; i < 8; ++i) out[ch][i] = static_cast<std::uint8_t>(static_cast<int>(value[i]));
      }
      std::uint8_t* row = surface_->pixel<C>(b.x0, b.y0 + r);
      for (; bits; bits &= bits - 1) {
        const int i = std::countr_zero(bits);
        put<C>(row + i * C, Rgba8{out[0][i], out[1][i], out[2][i], out[3][i]}, blend_);
      }
    }
  }

  // The channels a format of C channels stores (grey r, grey+alpha r and a, RGB, RGBA), and alpha when
  // it weighs a blend.
  bool stores(int ch) const {
    if (ch == 3) return C == 2 || C == 4 || blend_;
    if (ch == 0) return true;
    return C >= 3;
  }

  const Surface* surface_ = nullptr;
  const float* color_[3] = {};  // vertex k's RGBA in the record (VaryingLayout::record_at)
  bool blend_ = false;
  double lo_[4] = {}, hi_[4] = {};                  // each channel's range over the vertices
  std::int64_t slope_x_[4] = {}, slope_y_[4] = {};  // 16.16 per pixel right and down
  bool steep_ = false;  // some slope beyond 2^24 levels a pixel: no fixed-point stepping
#if defined(__x86_64__)
  bool wide_ = false;         // the plan chose AVX2 and this is opaque RGB(A) with fixed-point slopes
  double vertex_[3][4] = {};  // the vertices' channels, as doubles, for four lanes at once
  double reach_[4] = {};      // 8 (|slope_x| + |slope_y|): a block's farthest step from its start
#endif
};

}  // namespace raster::detail
