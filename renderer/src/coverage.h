// Coverage: one triangle record x one tile -> blocks of 8x8 pixels with a mask of the covered ones and the
// exact edge values shading needs. One routine for every triangle (flat, smooth, depth-tested, lit; 2D and
// 3D), templated on the edge functions' integer type: int64 in the fast range, the 384-bit Wide beyond it.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "setup.h"
#include "stop.h"

namespace raster::detail {

/// The standard (Direct3D) sample patterns for 1, 4, 8 and 16 samples, on the 1/256 px grid.
const std::vector<SamplePoint>& sample_pattern(int samples);

/// One block of coverage. Bit (8 r + i) of `mask` is set when pixel (x0 + i, y0 + r) is covered. The edge
/// values E_k at that pixel's sample point are e[k] + i dx[k] + r dy[k]: exact integers for int64 edges
/// (every term is below 2^53), the nearest doubles of the exact values for wide ones. x0 and y0 are
/// multiples of kBlock, so a pixel's values do not depend on the tile size.
struct Block {
  int x0 = 0, y0 = 0;
  std::uint64_t mask = 0;
  double e[3] = {}, dx[3] = {}, dy[3] = {};
  double area = 1;  ///< the triangle's doubled area in 1/256 px units: weights are E_k / area
};

/// How the partial blocks' masks are computed: eight lanes of a row at a time (SSE2, int32 lanes relative
/// to the block, only for the edges that cross it) or one pixel at a time in the edges' own integer type.
/// Both give the same mask; tests hold them to it.
enum class Lanes : std::uint8_t { simd, scalar };

namespace coverage_detail {

inline double to_double(std::int64_t v) {
  return static_cast<double>(v);
}
inline double to_double(const Wide& v) {
  return v.to_double();
}

inline std::int64_t floor_div(std::int64_t n, std::int64_t d) {
  return n / d - ((n % d != 0) && (n < 0));
}

/// Mask bits of the columns [c0, c1) of every row (0 <= c0 <= c1 <= 8).
inline std::uint64_t column_mask(int c0, int c1) {
  const std::uint64_t row = ((1u << c1) - 1) & ~((1u << c0) - 1);
  return row * 0x0101010101010101ull;
}
/// Mask bits of the rows [r0, r1).
inline std::uint64_t row_mask(int r0, int r1) {
  const std::uint64_t below = r1 >= 8 ? ~0ull : (1ull << (8 * r1)) - 1;
  return below & ~((1ull << (8 * r0)) - 1);
}

/// Whether edge values `at_origin` (at the sample point of pixel (bx, by), the clip's block-grid origin)
/// stay >= 0 over every pixel of `clip`: its nearest corner decides. Then the clip is accepted whole.
template <typename T>
bool clip_inside(const T (&at_origin)[3], const T (&step_x)[3], const T (&step_y)[3], Rect clip, int bx, int by) {
  for (int k = 0; k < 3; ++k) {
    const T first = at_origin[k] + step_x[k] * T(clip.x0 - bx) + step_y[k] * T(clip.y0 - by);
    const T w = step_x[k] * T(clip.x1 - clip.x0 - 1), h = step_y[k] * T(clip.y1 - clip.y0 - 1);
    if (first + std::min(w, T(0)) + std::min(h, T(0)) < T(0)) return false;
  }
  return true;
}

/// A block's mask one pixel at a time, in T: the reference the lanes are tested against.
template <typename T>
std::uint64_t partial_mask_scalar(const T (&e)[3], const T (&step_x)[3], const T (&step_y)[3], int r0 = 0,
                                  int r1 = kBlock) {
  std::uint64_t mask = 0;
  T row[3] = {e[0], e[1], e[2]};
  for (int k = 0; k < 3; ++k)
    for (int r = 0; r < r0; ++r) row[k] += step_y[k];
  for (int r = r0; r < r1; ++r) {
    T v[3] = {row[0], row[1], row[2]};
    for (int i = 0; i < kBlock; ++i) {
      if (!(v[0] < T(0)) && !(v[1] < T(0)) && !(v[2] < T(0))) mask |= 1ull << (8 * r + i);
      for (int k = 0; k < 3; ++k) v[k] += step_x[k];
    }
    for (int k = 0; k < 3; ++k) row[k] += step_y[k];
  }
  return mask;
}

/// One edge's mask over a block whose values e + i dx + r dy (i, r in 0..7) all fit in int32: eight lanes
/// a row, the sign bits read four at a time. A set bit is a sample with E >= 0.
inline std::uint64_t edge_mask_lanes(std::int32_t e, std::int32_t dx, std::int32_t dy, int r0, int r1) {
#if defined(__SSE2__)
  e += r0 * dy;
  __m128i left = _mm_setr_epi32(e, e + dx, e + 2 * dx, e + 3 * dx);
  __m128i right = _mm_add_epi32(left, _mm_set1_epi32(4 * dx));
  const __m128i down = _mm_set1_epi32(dy);
  std::uint64_t mask = 0;
  for (int r = r0; r < r1; ++r) {
    const unsigned negative = static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(left))) |
                              static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(right))) << 4;
    mask |= static_cast<std::uint64_t>(~negative & 0xffu) << (8 * r);
    left = _mm_add_epi32(left, down), right = _mm_add_epi32(right, down);
  }
  return mask;
#else
  using I8 = std::int32_t __attribute__((vector_size(32)));
  const I8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
  I8 row = e + r0 * dy + lane * dx;
  std::uint64_t mask = 0;
  for (int r = r0; r < r1; ++r, row += dy)
    for (int i = 0; i < 8; ++i) mask |= static_cast<std::uint64_t>(row[i] >= 0) << (8 * r + i);
  return mask;
#endif
}

/// A partial block's mask from its crossing edges (bit k of `crossing`), in int32 lanes where the values
/// fit (an edge crossing a block has |e| <= 7 (|dx| + |dy|) there), else one pixel at a time in int64.
inline std::uint64_t partial_mask_lanes(const std::int64_t (&e)[3], const std::int64_t (&step_x)[3],
                                        const std::int64_t (&step_y)[3], unsigned crossing, int r0, int r1) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 30;
  std::uint64_t mask = ~0ull;
  for (int k = 0; k < 3; ++k) {
    if (!(crossing & (1u << k))) continue;
    const std::int64_t reach = 8 * (std::abs(step_x[k]) + std::abs(step_y[k]));
    if (std::abs(e[k]) + reach < kLimit) {
      mask &= edge_mask_lanes(static_cast<std::int32_t>(e[k]), static_cast<std::int32_t>(step_x[k]),
                              static_cast<std::int32_t>(step_y[k]), r0, r1);
    } else {
      const std::int64_t one[3] = {e[k], 0, 0}, sx[3] = {step_x[k], 0, 0}, sy[3] = {step_y[k], 0, 0};
      mask &= partial_mask_scalar(one, sx, sy, r0, r1);
    }
  }
  return mask;
}

}  // namespace coverage_detail

/// Covers `edges` over the pixels of `clip` (inside one tile, the record's box already intersected), block
/// by block in rows, and calls shade(const Block&) for every block with a covered pixel. Whole blocks are
/// accepted or rejected from the edge values at their corners; only blocks an edge crosses are tested per
/// pixel. A clip inside the triangle altogether goes to shade.rect(clip, first block) instead. Returns early once `meter` says the render must stop (a block is kBlock^2 units of work).
template <typename T, typename Shade>
void cover(const Edges<T>& edges, Rect clip, SamplePoint sample, Lanes lanes, StopMeter& meter, Shade&& shade) {
  using namespace coverage_detail;
  if (clip.empty()) return;
  const int bx0 = clip.x0 - clip.x0 % kBlock, by0 = clip.y0 - clip.y0 % kBlock;  // clip >= 0
  T step_x[3], step_y[3], block_x[3], block_y[3], row_start[3];
  T low_extent[3], high_extent[3];  // the smallest and largest change of E_k across a block's samples
  const T sx(std::int64_t{bx0} * kSubpixelScale + sample.x), sy(std::int64_t{by0} * kSubpixelScale + sample.y);
  for (int k = 0; k < 3; ++k) {
    step_x[k] = edges.a[k] * T(kSubpixelScale), step_y[k] = edges.b[k] * T(kSubpixelScale);
    block_x[k] = step_x[k] * T(kBlock), block_y[k] = step_y[k] * T(kBlock);
    row_start[k] = edges.a[k] * sx + edges.b[k] * sy + edges.c[k];
    const T ex = step_x[k] * T(kBlock - 1), ey = step_y[k] * T(kBlock - 1);
    low_extent[k] = std::min(ex, T(0)) + std::min(ey, T(0));
    high_extent[k] = std::max(ex, T(0)) + std::max(ey, T(0));
  }
  Block block;
  block.area = to_double(edges.area);
  for (int k = 0; k < 3; ++k) block.dx[k] = to_double(step_x[k]), block.dy[k] = to_double(step_y[k]);
  if constexpr (std::is_same_v<T, std::int64_t>) {
    // The whole clip inside every edge (its corner samples are): accepted at once, and the shading covers
    // it as a rectangle. The first block's values are exact doubles; the shader steps them exactly.
    if (clip_inside(row_start, step_x, step_y, clip, bx0, by0)) {
      block.x0 = bx0, block.y0 = by0, block.mask = ~0ull;
      for (int k = 0; k < 3; ++k) block.e[k] = to_double(row_start[k]);
      shade.rect(clip, block);
      meter.add(std::int64_t{clip.x1 - clip.x0} * (clip.y1 - clip.y0));
      return;
    }
  }
  for (int y0 = by0; y0 < clip.y1; y0 += kBlock) {
    const int r0 = std::max(0, clip.y0 - y0), r1 = std::min(kBlock, clip.y1 - y0);  // rows inside the clip
    const std::uint64_t rows = row_mask(r0, r1);
    T e[3] = {row_start[0], row_start[1], row_start[2]};
    for (int x0 = bx0; x0 < clip.x1; x0 += kBlock) {
      bool reject = false, accept = true;
      for (int k = 0; k < 3; ++k) {
        reject = reject || e[k] + high_extent[k] < T(0);
        accept = accept && !(e[k] + low_extent[k] < T(0));
      }
      if (!reject) {
        std::uint64_t mask = rows & column_mask(std::max(0, clip.x0 - x0), std::min(kBlock, clip.x1 - x0));
        if (!accept) {
          if constexpr (std::is_same_v<T, std::int64_t>) {
            if (lanes == Lanes::simd) {
              unsigned crossing = 0;  // edges whose sign changes inside the block; the others cover it all
              for (int k = 0; k < 3; ++k) crossing |= (e[k] + low_extent[k] < T(0) ? 1u : 0u) << k;
              mask &= partial_mask_lanes(e, step_x, step_y, crossing, r0, r1);
            } else {
              mask &= partial_mask_scalar(e, step_x, step_y, r0, r1);
            }
          } else {
            mask &= partial_mask_scalar(e, step_x, step_y, r0, r1);
          }
        }
        if (mask) {
          block.x0 = x0, block.y0 = y0, block.mask = mask;
          for (int k = 0; k < 3; ++k) block.e[k] = to_double(e[k]);
          shade(block);
        }
        if (meter.add(kBlock * kBlock)) return;
      }
      for (int k = 0; k < 3; ++k) e[k] += block_x[k];
    }
    for (int k = 0; k < 3; ++k) row_start[k] += block_y[k];
  }
}

}  // namespace raster::detail

namespace raster::detail {

/// Area coverage: the share of a pixel's square inside a triangle, in (0, 1], for the pixels an edge cuts.
/// Entry 8 r + i is pixel (x0 + i, y0 + r) of the block; only the entries of `partial`'s set bits are
/// meaningful.
struct AreaCover {
  std::uint64_t partial = 0;  ///< pixels cut by an edge: some but not all of their square is inside
  float share[64];            ///< covered share of those pixels' squares
};

namespace coverage_detail {

/// The share of the unit square [0, 1]^2 where t + A (u - 1/2) + B (v - 1/2) >= 0, for a line that crosses
/// it (|t| < (|A| + |B|) / 2). It depends only on t, p = max(|A|, |B|) and q = min(|A|, |B|): a trapezoid
/// while the line crosses two opposite sides, a corner triangle (or its complement) beyond that.
inline double half_plane_share(double t, double A, double B) {
  const double p = std::max(std::fabs(A), std::fabs(B)), q = std::min(std::fabs(A), std::fabs(B));
  const double band = (p - q) / 2;
  if (std::fabs(t) <= band) return 0.5 + t / p;
  const double r = (p + q) / 2 - std::fabs(t);  // distance (in E) from the far corner, in (0, q)
  const double corner = r * r / (2 * p * q);
  return t > 0 ? 1 - corner : corner;
}

/// The share of the unit square inside several half-planes t_k + A_k (u - 1/2) + B_k (v - 1/2) >= 0: the
/// square clipped by each (Sutherland-Hodgman), then the shoelace area. Near a vertex, and in slivers.
inline double clipped_share(int n, const double* t, const double* A, const double* B) {
  double xs[2][8] = {{0, 1, 1, 0}}, ys[2][8] = {{0, 0, 1, 1}};
  int count = 4, from = 0;
  for (int k = 0; k < n && count > 0; ++k) {
    const double* x = xs[from];
    const double* y = ys[from];
    double* ox = xs[1 - from];
    double* oy = ys[1 - from];
    double f[8];
    for (int j = 0; j < count; ++j) f[j] = t[k] + A[k] * (x[j] - 0.5) + B[k] * (y[j] - 0.5);
    int out = 0;
    for (int j = 0; j < count; ++j) {
      const int next = j + 1 == count ? 0 : j + 1;
      if (f[j] >= 0) ox[out] = x[j], oy[out] = y[j], ++out;
      if ((f[j] >= 0) != (f[next] >= 0)) {
        const double s = f[j] / (f[j] - f[next]);
        ox[out] = x[j] + s * (x[next] - x[j]), oy[out] = y[j] + s * (y[next] - y[j]), ++out;
      }
    }
    count = out, from = 1 - from;
  }
  double twice = 0;
  for (int j = 0; j < count; ++j) {
    const int next = j + 1 == count ? 0 : j + 1;
    twice += xs[from][j] * ys[from][next] - xs[from][next] * ys[from][j];
  }
  return std::fabs(twice) / 2;
}

/// The top-left bias folded into c (1 for edges that are neither top nor left, see setup.cpp): area
/// coverage measures the triangle itself, so it adds the bias back.
template <typename C>
bool biased(const C& a, const C& b) {
  return !(a > C(0) || (a == C(0) && b > C(0)));
}

}  // namespace coverage_detail

/// Area coverage of `edges` over the pixels of `clip`: the same blocks as cover(), tested against the
/// pixel squares instead of one sample point. Edge k's value at a pixel centre is t_k and it changes by
/// h_k = 128 (|a_k| + |b_k|) toward the square's farthest corner, so a pixel lies wholly inside when
/// t_k - h_k >= 0 for every k and touches the triangle's interior only when t_k + h_k > 0 for every k:
/// two sets of edges offset by constants, whose masks come from the same block tests and lanes as the
/// aliased ones. Whole pixels go to shade(block) exactly as aliased coverage would send them (and a clip
/// wholly inside to shade.rect); cut pixels to shade.area(block, cover) with their exact share: one edge
/// by a closed form, several by clipping the square.
template <typename T, typename Shade>
void cover_area(const Edges<T>& edges, Rect clip, Lanes lanes, StopMeter& meter, Shade&& shade) {
  using namespace coverage_detail;
  if (clip.empty()) return;
  const int bx0 = clip.x0 - clip.x0 % kBlock, by0 = clip.y0 - clip.y0 % kBlock;
  const T half_px(kSubpixelScale / 2);
  T step_x[3], step_y[3], block_x[3], block_y[3], centre[3], inner[3], outer[3], low_extent[3], high_extent[3];
  const T sx(std::int64_t{bx0} * kSubpixelScale + kSubpixelScale / 2),
      sy(std::int64_t{by0} * kSubpixelScale + kSubpixelScale / 2);
  for (int k = 0; k < 3; ++k) {
    const T a(edges.a[k]), b(edges.b[k]);
    step_x[k] = a * T(kSubpixelScale), step_y[k] = b * T(kSubpixelScale);
    block_x[k] = step_x[k] * T(kBlock), block_y[k] = step_y[k] * T(kBlock);
    const T biased_c = a * sx + b * sy + edges.c[k];  // what aliased coverage tests, for shading
    centre[k] = biased_c + (biased(a, b) ? T(1) : T(0));
    const T a_abs = a < T(0) ? -a : a, b_abs = b < T(0) ? -b : b;
    const T h = (a_abs + b_abs) * half_px;
    inner[k] = centre[k] - h;
    outer[k] = centre[k] + h - T(1);  // >= 0 exactly when centre + h > 0
    const T ex = step_x[k] * T(kBlock - 1), ey = step_y[k] * T(kBlock - 1);
    low_extent[k] = std::min(ex, T(0)) + std::min(ey, T(0));
    high_extent[k] = std::max(ex, T(0)) + std::max(ey, T(0));
    centre[k] = biased_c;  // from here on: the biased values, stepped with the others
  }
  Block block;
  block.area = to_double(edges.area);
  double bias[3];
  for (int k = 0; k < 3; ++k) {
    block.dx[k] = to_double(step_x[k]), block.dy[k] = to_double(step_y[k]);
    bias[k] = biased(edges.a[k], edges.b[k]) ? 1 : 0;
  }
  {  // The whole clip wholly inside: a rectangle, as aliased coverage would draw it.
    if (clip_inside(inner, step_x, step_y, clip, bx0, by0)) {
      block.x0 = bx0, block.y0 = by0, block.mask = ~0ull;
      for (int k = 0; k < 3; ++k) block.e[k] = to_double(centre[k]);
      shade.rect(clip, block);
      meter.add(std::int64_t{clip.x1 - clip.x0} * (clip.y1 - clip.y0));
      return;
    }
  }
  AreaCover cut;
  for (int y0 = by0; y0 < clip.y1; y0 += kBlock) {
    const int r0 = std::max(0, clip.y0 - y0), r1 = std::min(kBlock, clip.y1 - y0);
    const std::uint64_t rows = row_mask(r0, r1);
    T in[3] = {inner[0], inner[1], inner[2]}, out[3] = {outer[0], outer[1], outer[2]};
    T e[3] = {centre[0], centre[1], centre[2]};
    for (int x0 = bx0; x0 < clip.x1; x0 += kBlock) {
      bool reject = false, accept = true;
      unsigned crossing_in = 0, crossing_out = 0;
      for (int k = 0; k < 3; ++k) {
        reject = reject || out[k] + high_extent[k] < T(0);
        accept = accept && !(in[k] + low_extent[k] < T(0));
        crossing_in |= (in[k] + low_extent[k] < T(0) ? 1u : 0u) << k;
        crossing_out |= (out[k] + low_extent[k] < T(0) ? 1u : 0u) << k;
      }
      if (!reject) {
        const std::uint64_t clipped =
            rows & column_mask(std::max(0, clip.x0 - x0), std::min(kBlock, clip.x1 - x0));
        std::uint64_t whole = clipped, touched = clipped;
        if (!accept) {
          if constexpr (std::is_same_v<T, std::int64_t>) {
            if (lanes == Lanes::simd) {
              whole &= partial_mask_lanes(in, step_x, step_y, crossing_in, r0, r1);
              touched &= partial_mask_lanes(out, step_x, step_y, crossing_out, r0, r1);
            } else {
              whole &= partial_mask_scalar(in, step_x, step_y, r0, r1);
              touched &= partial_mask_scalar(out, step_x, step_y, r0, r1);
            }
          } else {
            whole &= partial_mask_scalar(in, step_x, step_y, r0, r1);
            touched &= partial_mask_scalar(out, step_x, step_y, r0, r1);
          }
        }
        block.x0 = x0, block.y0 = y0;
        for (int k = 0; k < 3; ++k) block.e[k] = to_double(e[k]);
        if (whole) {
          block.mask = whole;
          shade(block);
        }
        cut.partial = 0;
        for (std::uint64_t m = touched & ~whole; m; m &= m - 1) {
          const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
          double t[3], A[3], B[3];
          int n = 0;
          for (int k = 0; k < 3; ++k) {
            const double value = block.e[k] + bias[k] + i * block.dx[k] + r * block.dy[k];
            if (value >= 0.5 * (std::fabs(block.dx[k]) + std::fabs(block.dy[k]))) continue;  // wholly inside
            t[n] = value, A[n] = block.dx[k], B[n] = block.dy[k], ++n;
          }
          const double share = n == 1 ? half_plane_share(t[0], A[0], B[0]) : clipped_share(n, t, A, B);
          if (!(share > 0)) continue;  // touches only where two edges meet outside the square
          cut.share[bit] = static_cast<float>(std::min(share, 1.0));
          cut.partial |= std::uint64_t{1} << bit;
        }
        if (cut.partial) {
          block.mask = cut.partial;
          shade.area(block, cut);
        }
        if (meter.add(kBlock * kBlock)) return;
      }
      for (int k = 0; k < 3; ++k) in[k] += block_x[k], out[k] += block_x[k], e[k] += block_x[k];
    }
    for (int k = 0; k < 3; ++k) inner[k] += block_y[k], outer[k] += block_y[k], centre[k] += block_y[k];
  }
}

}  // namespace raster::detail

namespace raster::detail {

/// Multisampled coverage of `edges` over the pixels of `clip`: per block, a mask for each of the
/// `count` sample positions of `pattern`, from the same corner tests and lanes as cover(). Blocks whose
/// every sample is inside go to shade(block) (all samples covered), a clip wholly inside to shade.rect;
/// others to shade.samples(block, masks), block.mask being the pixels with any sample covered. The edge
/// values in a Block are at the pixel centres (where shading is evaluated), whatever the pattern.
template <typename T, typename Shade>
void cover_samples(const Edges<T>& edges, Rect clip, const SamplePoint* pattern, int count, Lanes lanes,
                   StopMeter& meter, Shade&& shade) {
  using namespace coverage_detail;
  if (clip.empty()) return;
  const int bx0 = clip.x0 - clip.x0 % kBlock, by0 = clip.y0 - clip.y0 % kBlock;
  T step_x[3], step_y[3], block_x[3], block_y[3], corner[3], low_extent[3], high_extent[3];
  T offset[16][3], least[3], most[3], centre[3];  // E's change from a pixel's corner to each sample
  const T sx(std::int64_t{bx0} * kSubpixelScale), sy(std::int64_t{by0} * kSubpixelScale);
  for (int k = 0; k < 3; ++k) {
    const T a(edges.a[k]), b(edges.b[k]);
    step_x[k] = a * T(kSubpixelScale), step_y[k] = b * T(kSubpixelScale);
    block_x[k] = step_x[k] * T(kBlock), block_y[k] = step_y[k] * T(kBlock);
    corner[k] = a * sx + b * sy + edges.c[k];
    for (int s = 0; s < count; ++s) {
      offset[s][k] = a * T(pattern[s].x) + b * T(pattern[s].y);
      least[k] = s == 0 ? offset[s][k] : std::min(least[k], offset[s][k]);
      most[k] = s == 0 ? offset[s][k] : std::max(most[k], offset[s][k]);
    }
    centre[k] = (a + b) * T(kSubpixelScale / 2);
    const T ex = step_x[k] * T(kBlock - 1), ey = step_y[k] * T(kBlock - 1);
    low_extent[k] = std::min(ex, T(0)) + std::min(ey, T(0)) + least[k];
    high_extent[k] = std::max(ex, T(0)) + std::max(ey, T(0)) + most[k];
  }
  Block block;
  block.area = to_double(edges.area);
  for (int k = 0; k < 3; ++k) block.dx[k] = to_double(step_x[k]), block.dy[k] = to_double(step_y[k]);
  {  // every sample of the clip inside: a rectangle
    const T lowest[3] = {corner[0] + least[0], corner[1] + least[1], corner[2] + least[2]};
    if (clip_inside(lowest, step_x, step_y, clip, bx0, by0)) {
      block.x0 = bx0, block.y0 = by0, block.mask = ~0ull;
      for (int k = 0; k < 3; ++k) block.e[k] = to_double(corner[k] + centre[k]);
      shade.rect(clip, block);
      meter.add(std::int64_t{clip.x1 - clip.x0} * (clip.y1 - clip.y0));
      return;
    }
  }
  std::uint64_t masks[16];
  for (int y0 = by0; y0 < clip.y1; y0 += kBlock) {
    const int r0 = std::max(0, clip.y0 - y0), r1 = std::min(kBlock, clip.y1 - y0);
    const std::uint64_t rows = row_mask(r0, r1);
    T e[3] = {corner[0], corner[1], corner[2]};
    for (int x0 = bx0; x0 < clip.x1; x0 += kBlock) {
      bool reject = false, accept = true;
      for (int k = 0; k < 3; ++k) {
        reject = reject || e[k] + high_extent[k] < T(0);
        accept = accept && !(e[k] + low_extent[k] < T(0));
      }
      if (!reject) {
        const std::uint64_t clipped = rows & column_mask(std::max(0, clip.x0 - x0), std::min(kBlock, clip.x1 - x0));
        block.x0 = x0, block.y0 = y0;
        for (int k = 0; k < 3; ++k) block.e[k] = to_double(e[k] + centre[k]);
        if (accept) {
          block.mask = clipped;
          shade(block);
        } else {
          std::uint64_t any = 0;
          for (int s = 0; s < count; ++s) {
            T es[3], sample_low[3];
            unsigned crossing = 0;
            for (int k = 0; k < 3; ++k) {
              es[k] = e[k] + offset[s][k];
              sample_low[k] = low_extent[k] - least[k];
              crossing |= (es[k] + sample_low[k] < T(0) ? 1u : 0u) << k;
            }
            std::uint64_t m = clipped;
            if constexpr (std::is_same_v<T, std::int64_t>) {
              m &= lanes == Lanes::simd ? partial_mask_lanes(es, step_x, step_y, crossing, r0, r1)
                                        : partial_mask_scalar(es, step_x, step_y, r0, r1);
            } else {
              m &= partial_mask_scalar(es, step_x, step_y, r0, r1);
            }
            masks[s] = m, any |= m;
          }
          if (any) {
            block.mask = any;
            shade.samples(block, masks);
          }
        }
        if (meter.add(kBlock * kBlock)) return;
      }
      for (int k = 0; k < 3; ++k) e[k] += block_x[k];
    }
    for (int k = 0; k < 3; ++k) corner[k] += block_y[k];
  }
}

}  // namespace raster::detail
