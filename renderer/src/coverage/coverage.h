// Coverage: one triangle (or line quad) record x one tile -> blocks of 8x8 pixels with a mask of the covered
// ones and the exact edge values shading needs. One block walker for every triangle (flat, smooth,
// depth-tested, lit; 2D and 3D), every line segment's quad, and every anti-aliasing mode, which are its
// policies (what a partial block yields: a centre mask, a mask per sample, area shares); templated on the
// edge count (3 or 4) and on the edge functions' integer type: int64 in the fast range, the 384-bit Wide
// beyond it.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "base/grid.h"
#include "base/masks.h"
#include "base/stop.h"
#include "coverage/area_share.h"
#include "setup/setup.h"

namespace raster::detail {

/// For 4 and 8 samples a pixel, the centroid of each set of a pixel's samples (entry m: the samples of m's
/// set bits) as {x, y} pixels from the pixel centre; nullptr for other counts (16 would take 65,536 entries).
/// Multisampling shades a pixel whose centre is not covered at the centroid of its covered samples: looked
/// up here once per pattern rather than summed and divided per pixel.
const std::array<double, 2>* centroid_offsets(int samples);

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

/// Every block of the fully covered `clip`, from `first` (the block at the clip's block-grid origin, exact
/// values) on: each with the mask of its pixels inside the clip and exactly the edge values it would have had
/// (whole multiples of a block's step), given to `visit(const Block&)` row by row.
template <class Visit>
[[gnu::always_inline]] inline void for_each_block(Rect clip, const Block& first, Visit&& visit) {
  Block b = first;
  for (int y0 = first.y0; y0 < clip.y1; y0 += kBlock) {
    const std::uint64_t rows = row_mask(std::max(0, clip.y0 - y0), std::min(kBlock, clip.y1 - y0));
    for (int x0 = first.x0; x0 < clip.x1; x0 += kBlock) {
      b.x0 = x0, b.y0 = y0;
      b.mask = rows & column_mask(std::max(0, clip.x0 - x0), std::min(kBlock, clip.x1 - x0));
      const double bx = (x0 - first.x0) / kBlock, by = (y0 - first.y0) / kBlock;  // exact steps
      for (int k = 0; k < 3; ++k)
        b.e[k] = first.e[k] + bx * (kBlock * first.dx[k]) + by * (kBlock * first.dy[k]);
      visit(b);
    }
  }
}

/// A multisampling shade policy restricted to the pixels `only` holds (a mask per block of the image): the
/// blocks, sample masks and rectangles the walker gives reach `shade` for those pixels alone, and a block
/// with none of them not at all. Edge sampling's second pass draws the edge pixels with it.
template <class Shade>
struct OnlyPixels {
  Shade& shade;
  BlockMasks only;
  int count;  ///< samples a pixel: cover_samples gives count + 1 masks (the last, the pixel centres)

  void operator()(const Block& b) {
    Block kept = b;
    kept.mask &= only.at(b.x0, b.y0);
    if (kept.mask) shade(kept);
  }
  void samples(const Block& b, const std::uint64_t* masks) {
    const std::uint64_t keep = only.at(b.x0, b.y0);
    Block kept = b;
    kept.mask &= keep;
    if (!kept.mask) return;
    std::uint64_t kept_masks[17];
    for (int s = 0; s <= count; ++s) kept_masks[s] = masks[s] & keep;
    shade.samples(kept, kept_masks);
  }
  void rect(Rect clip, const Block& first) {
    for_each_block(clip, first, [&](const Block& b) { (*this)(b); });
  }
};

/// How the partial blocks' masks are computed: eight lanes of a row at a time (SSE2 or AVX2, int32 lanes
/// relative to the block, only for the edges that cross it) or one pixel at a time in the edges' own integer
/// type. All give the same mask; tests hold them to it.
enum class Lanes : std::uint8_t {
  sse2,    ///< a row in two registers of four
  avx2,    ///< a row in one register of eight (RenderPlan::simd)
  scalar,  ///< one pixel at a time (test hook)
};

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

/// Whether edge values `at_origin` (at the sample point of pixel (bx, by), the clip's block-grid origin)
/// stay >= 0 over every pixel of `clip`: its nearest corner decides. Then the clip is accepted whole.
template <typename T, int N>
bool clip_inside(const T (&at_origin)[N], const T (&step_x)[N], const T (&step_y)[N], Rect clip, int bx,
                 int by) {
  for (int k = 0; k < N; ++k) {
    const T first = at_origin[k] + step_x[k] * T(clip.x0 - bx) + step_y[k] * T(clip.y0 - by);
    const T w = step_x[k] * T(clip.x1 - clip.x0 - 1), h = step_y[k] * T(clip.y1 - clip.y0 - 1);
    if (first + std::min(w, T(0)) + std::min(h, T(0)) < T(0)) return false;
  }
  return true;
}

/// A block's mask one pixel at a time, in T: the reference the lanes are tested against.
template <typename T, int N>
std::uint64_t partial_mask_scalar(const T (&e)[N], const T (&step_x)[N], const T (&step_y)[N], int r0 = 0,
                                  int r1 = kBlock) {
  std::uint64_t mask = 0;
  T row[N];
  for (int k = 0; k < N; ++k) {
    row[k] = e[k];
    for (int r = 0; r < r0; ++r) row[k] += step_y[k];
  }
  for (int r = r0; r < r1; ++r) {
    T v[N];
    for (int k = 0; k < N; ++k) v[k] = row[k];
    for (int i = 0; i < kBlock; ++i) {
      bool inside = true;
      for (int k = 0; k < N; ++k) inside = inside && !(v[k] < T(0));
      if (inside) mask |= 1ull << (8 * r + i);
      for (int k = 0; k < N; ++k) v[k] += step_x[k];
    }
    for (int k = 0; k < N; ++k) row[k] += step_y[k];
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

#if defined(__x86_64__)
/// edge_mask_lanes with a row in one AVX2 register: the row's eight sign bits in one movemask.
__attribute__((target("avx2"))) inline std::uint64_t edge_mask_avx2(std::int32_t e, std::int32_t dx,
                                                                    std::int32_t dy, int r0, int r1) {
  __m256i row =
      _mm256_add_epi32(_mm256_set1_epi32(e + r0 * dy),
                       _mm256_mullo_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), _mm256_set1_epi32(dx)));
  const __m256i down = _mm256_set1_epi32(dy);
  std::uint64_t mask = 0;
  for (int r = r0; r < r1; ++r, row = _mm256_add_epi32(row, down)) {
    const auto negative = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(row)));
    mask |= static_cast<std::uint64_t>(~negative & 0xffu) << (8 * r);
  }
  return mask;
}
#endif

#if defined(__x86_64__)
/// Multisampling: every sample's mask of a block in one pass, N samples. Each edge of `crossing` has its
/// row of values stepped once and compared at each sample's offset (`offset[k][s]`: E_k's change from the
/// pixel centre to sample s), where per-sample masks would set the edge up and step it once per sample.
/// Sample s's pixels of rows [r0, r1) go to masks[s], and the pixels whose centre is covered to masks[N].
/// Every value e + i dx + r dy + offset must fit int32.
template <int N, int kEdges>
__attribute__((target("avx2"))) inline void sample_masks_avx2(
    const std::int32_t (&e)[kEdges], const std::int32_t (&dx)[kEdges], const std::int32_t (&dy)[kEdges],
    unsigned crossing, const std::int32_t (&offset)[kEdges][16], int r0, int r1, std::uint64_t* masks) {
  // A byte a row: each row's eight bits are one store, not a shift and an and into a 64-bit word.
  alignas(8) std::uint8_t out[N + 1][8];
  const std::uint64_t rows = row_mask(r0, r1);
  for (int s = 0; s <= N; ++s) std::memcpy(out[s], &rows, 8);
  for (int k = 0; k < kEdges; ++k) {
    if (!(crossing & (1u << k))) continue;
    __m256i row = _mm256_add_epi32(
        _mm256_set1_epi32(e[k] + r0 * dy[k]),
        _mm256_mullo_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), _mm256_set1_epi32(dx[k])));
    const __m256i down = _mm256_set1_epi32(dy[k]);
    for (int r = r0; r < r1; ++r, row = _mm256_add_epi32(row, down)) {
      for (int s = 0; s < N; ++s) {
        const __m256i at = _mm256_add_epi32(row, _mm256_set1_epi32(offset[k][s]));
        out[s][r] &= static_cast<std::uint8_t>(~_mm256_movemask_ps(_mm256_castsi256_ps(at)));
      }
      out[N][r] &= static_cast<std::uint8_t>(~_mm256_movemask_ps(_mm256_castsi256_ps(row)));
    }
  }
  for (int s = 0; s <= N; ++s) std::memcpy(&masks[s], out[s], 8);
}
#endif

/// A partial block's mask from its crossing edges (bit k of `crossing`), in int32 lanes where the values
/// fit (an edge crossing a block has |e| <= 7 (|dx| + |dy|) there), else one pixel at a time in int64.
template <int N>
std::uint64_t partial_mask_lanes(const std::int64_t (&e)[N], const std::int64_t (&step_x)[N],
                                 const std::int64_t (&step_y)[N], unsigned crossing, int r0, int r1,
                                 Lanes lanes = Lanes::sse2) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 30;
  std::uint64_t mask = ~0ull;
  for (int k = 0; k < N; ++k) {
    if (!(crossing & (1u << k))) continue;
    const std::int64_t reach = 8 * (std::abs(step_x[k]) + std::abs(step_y[k]));
    if (std::abs(e[k]) + reach < kLimit) {
      const auto e32 = static_cast<std::int32_t>(e[k]), dx = static_cast<std::int32_t>(step_x[k]),
                 dy = static_cast<std::int32_t>(step_y[k]);
#if defined(__x86_64__)
      if (lanes == Lanes::avx2) {
        mask &= edge_mask_avx2(e32, dx, dy, r0, r1);
        continue;
      }
#endif
      mask &= edge_mask_lanes(e32, dx, dy, r0, r1);
    } else {
      const std::int64_t one[1] = {e[k]}, sx[1] = {step_x[k]}, sy[1] = {step_y[k]};
      mask &= partial_mask_scalar(one, sx, sy, r0, r1);
    }
  }
  return mask;
}

/// The top-left bias folded into c (1 for edges that are neither top nor left, see setup.h): area
/// coverage measures the triangle itself, so it adds the bias back.
template <typename C>
bool biased(const C& a, const C& b) {
  return !(a > C(0) || (a == C(0) && b > C(0)));
}

/// A clip's blocks and how the edge values step over them: E_k at a point `at` of each pixel (1/256 px from
/// its corner), exact in T.
template <typename T, int N = 3>
struct BlockGrid {
  int bx0 = 0, by0 = 0;      ///< the clip's first block, image pixels (multiples of kBlock)
  T origin[N];               ///< E_k at `at` of pixel (bx0, by0)
  T step_x[N], step_y[N];    ///< E_k's change a pixel right, a pixel down
  T block_x[N], block_y[N];  ///< ... a block right, a block down
  T low[N], high[N];         ///< the least and the most E_k changes across a block's 8x8 pixels

  BlockGrid(const EdgeFunctions<T, N>& edges, Rect clip, SamplePoint at)
      : bx0(clip.x0 - clip.x0 % kBlock), by0(clip.y0 - clip.y0 % kBlock) {  // clip >= 0
    const T sx(std::int64_t{bx0} * kSubpixelScale + at.x), sy(std::int64_t{by0} * kSubpixelScale + at.y);
    for (int k = 0; k < N; ++k) {
      step_x[k] = edges.a[k] * T(kSubpixelScale), step_y[k] = edges.b[k] * T(kSubpixelScale);
      block_x[k] = step_x[k] * T(kBlock), block_y[k] = step_y[k] * T(kBlock);
      origin[k] = edges.a[k] * sx + edges.b[k] * sy + edges.c[k];
      const T ex = step_x[k] * T(kBlock - 1), ey = step_y[k] * T(kBlock - 1);
      low[k] = std::min(ex, T(0)) + std::min(ey, T(0));
      high[k] = std::max(ex, T(0)) + std::max(ey, T(0));
    }
  }
};

/// The pixels of rows [r0, r1) of a block where every E_k >= 0, from its values `e` at the block's first
/// pixel: edges that stay >= 0 over the block are skipped, the others tested in lanes (or, `Lanes::scalar`
/// and wide edges, one pixel at a time).
template <typename T, int N>
std::uint64_t inside_mask(const T (&e)[N], const BlockGrid<T, N>& g, Lanes lanes, int r0, int r1) {
  if constexpr (std::is_same_v<T, std::int64_t>) {
    if (lanes != Lanes::scalar) {
      unsigned crossing = 0;
      // Not `crossing |= (cond ? 1u : 0u) << k`: GCC 12 with -fsanitize=bounds,shift miscompiles that
      // form (a wrong index at -O0, a wrong mask at -O2), which made make test-asan fail.
      for (int k = 0; k < N; ++k)
        if (e[k] + g.low[k] < T(0)) crossing |= 1u << k;
      return partial_mask_lanes(e, g.step_x, g.step_y, crossing, r0, r1, lanes);
    }
  }
  return partial_mask_scalar(e, g.step_x, g.step_y, r0, r1);
}

/// The one block walker. `g.origin` holds the values shading reads (E_k at the shading point); a block is
/// accepted whole when every E_k + accept[k] stays >= 0 over it, and skipped when some E_k + reject[k] stays
/// < 0 over it (accept <= reject: the policies' offsets for sample positions or pixel squares). Accepted
/// blocks side by side go to shade.rect(run, first block) as one rectangle, and a clip accepted whole goes
/// there at once; each other block to partial(block, e, clipped, r0, r1), with the block's values as doubles
/// and `e` exact. Rectangles need exact doubles, so only int64 edges make them; wide edges' accepted blocks
/// go one by one to shade(block). Returns early once `meter` says the render must stop (a block is kBlock^2
/// units of work).
template <typename T, int N, typename Shade, typename Partial>
void walk_blocks(const BlockGrid<T, N>& g, const T& area, Rect clip, const T (&accept)[N],
                 const T (&reject)[N], StopMeter& meter, Shade& shade, Partial&& partial) {
  constexpr bool kExact = std::is_same_v<T, std::int64_t>;
  constexpr int kShaded = 3;  // a Block carries the first three edges' values: a triangle's weights
  T accept_low[N], reject_high[N], row_start[N];
  Block block;
  block.area = to_double(area);
  for (int k = 0; k < N; ++k) {
    accept_low[k] = accept[k] + g.low[k], reject_high[k] = reject[k] + g.high[k];
    row_start[k] = g.origin[k];
  }
  for (int k = 0; k < kShaded; ++k)
    block.dx[k] = to_double(g.step_x[k]), block.dy[k] = to_double(g.step_y[k]);
  if constexpr (kExact) {
    T lowest[N];
    for (int k = 0; k < N; ++k) lowest[k] = g.origin[k] + accept[k];
    if (clip_inside(lowest, g.step_x, g.step_y, clip, g.bx0, g.by0)) {
      block.x0 = g.bx0, block.y0 = g.by0, block.mask = ~0ull;
      for (int k = 0; k < kShaded; ++k) block.e[k] = to_double(g.origin[k]);
      shade.rect(clip, block);
      meter.add(std::int64_t{clip.x1 - clip.x0} * (clip.y1 - clip.y0));
      return;
    }
  }
  Block run;  // accepted blocks of this block row not yet shaded: from run.x0, `run_blocks` of them
  int run_blocks = 0;
  for (int y0 = g.by0; y0 < clip.y1; y0 += kBlock) {
    const int r0 = std::max(0, clip.y0 - y0), r1 = std::min(kBlock, clip.y1 - y0);  // rows inside the clip
    const std::uint64_t rows = row_mask(r0, r1);
    auto flush = [&] {
      const Rect rect{std::max(clip.x0, run.x0), y0 + r0, std::min(clip.x1, run.x0 + run_blocks * kBlock),
                      y0 + r1};
      shade.rect(rect, run);
      run_blocks = 0;
    };
    T e[N];
    for (int k = 0; k < N; ++k) e[k] = row_start[k];
    for (int x0 = g.bx0; x0 < clip.x1; x0 += kBlock) {
      bool skip = false, whole = true;
      for (int k = 0; k < N; ++k) {
        skip = skip || e[k] + reject_high[k] < T(0);
        whole = whole && !(e[k] + accept_low[k] < T(0));
      }
      if (kExact && whole) {
        if (run_blocks++ == 0) {
          run.x0 = x0, run.y0 = y0, run.mask = ~0ull;
          for (int k = 0; k < kShaded; ++k) run.e[k] = to_double(e[k]);
          run.area = block.area;
          for (int k = 0; k < kShaded; ++k) run.dx[k] = block.dx[k], run.dy[k] = block.dy[k];
        }
        if (meter.add(kBlock * kBlock)) return;
      } else {
        if (run_blocks) flush();
        if (!skip) {
          const std::uint64_t clipped =
              rows & column_mask(std::max(0, clip.x0 - x0), std::min(kBlock, clip.x1 - x0));
          block.x0 = x0, block.y0 = y0;
          for (int k = 0; k < kShaded; ++k) block.e[k] = to_double(e[k]);
          if (whole) {
            block.mask = clipped;
            shade(block);
          } else {
            partial(block, e, clipped, r0, r1);
          }
          if (meter.add(kBlock * kBlock)) return;
        }
      }
      for (int k = 0; k < N; ++k) e[k] += g.block_x[k];
    }
    if (run_blocks) flush();
    for (int k = 0; k < N; ++k) row_start[k] += g.block_y[k];
  }
}

}  // namespace coverage_detail

/// Aliased coverage of `edges` over the pixels of `clip` (inside one tile, the record's box already
/// intersected): a pixel is covered when every E_k >= 0 at its `sample` point. Calls shade(block) for each
/// block with a covered pixel (the mask), shade.rect for rectangles wholly inside (see walk_blocks).
template <typename T, int N, typename Shade>
void cover(const EdgeFunctions<T, N>& edges, Rect clip, SamplePoint sample, Lanes lanes, StopMeter& meter,
           Shade&& shade) {
  using namespace coverage_detail;
  if (clip.empty()) return;
  const BlockGrid<T, N> g(edges, clip, sample);
  T zero[N];
  for (T& z : zero) z = T(0);
  walk_blocks(g, edges.area, clip, zero, zero, meter, shade,
              [&](Block& block, const T(&e)[N], std::uint64_t clipped, int r0, int r1) {
                block.mask = clipped & inside_mask(e, g, lanes, r0, r1);
                if (block.mask) shade(block);
              });
}

/// Area coverage of `edges` over the pixels of `clip`: the same blocks as cover(), tested against the
/// pixel squares instead of one sample point. Edge k's value at a pixel centre is t_k and it changes by
/// h_k = 128 (|a_k| + |b_k|) toward the square's farthest corner, so a pixel lies wholly inside when
/// t_k - h_k >= 0 for every k and touches the triangle's interior only when t_k + h_k > 0 for every k:
/// the walker's accept and reject offsets, and two masks from the same lanes as the aliased one. Whole
/// pixels go to shade(block) exactly as aliased coverage would send them (and rectangles to shade.rect);
/// cut pixels to shade.area(block, cover) with their exact share: one edge, or two that do not meet inside
/// the pixel, by a closed form; otherwise by clipping the square. The values shading reads are the aliased
/// ones (top-left bias included).
template <typename T, int N, typename Shade>
void cover_area(const EdgeFunctions<T, N>& edges, Rect clip, Lanes lanes, StopMeter& meter, Shade&& shade) {
  using namespace coverage_detail;
  if (clip.empty()) return;
  const BlockGrid<T, N> g(edges, clip, SamplePoint{});
  T inner[N], outer[N];  // offsets from the biased centre value: wholly inside, touching the interior
  double bias[N], dx[N], dy[N];
  HalfPlane half[N];
  for (int k = 0; k < N; ++k) {
    const T a(edges.a[k]), b(edges.b[k]);
    const T bias_k = biased(a, b) ? T(1) : T(0);  // the top-left rule's 1, given back: area is the triangle's
    const T h = ((a < T(0) ? -a : a) + (b < T(0) ? -b : b)) * T(kSubpixelScale / 2);
    inner[k] = bias_k - h;
    outer[k] = bias_k + h - T(1);  // >= 0 exactly when centre + h > 0
    bias[k] = biased(edges.a[k], edges.b[k]) ? 1 : 0;
    dx[k] = to_double(g.step_x[k]), dy[k] = to_double(g.step_y[k]);
    half[k] = HalfPlane(dx[k], dy[k]);
  }
  AreaCover cut;
  walk_blocks(g, edges.area, clip, inner, outer, meter, shade,
              [&](Block& block, const T(&e)[N], std::uint64_t clipped, int r0, int r1) {
                T in[N], out[N];
                double at[N];  // the edges' values at the block's first pixel centre, as doubles
                for (int k = 0; k < N; ++k)
                  in[k] = e[k] + inner[k], out[k] = e[k] + outer[k], at[k] = to_double(e[k]);
                const std::uint64_t whole = clipped & inside_mask(in, g, lanes, r0, r1);
                const std::uint64_t touched = clipped & inside_mask(out, g, lanes, r0, r1);
                if (whole) {
                  block.mask = whole;
                  shade(block);
                }
                cut.partial = 0;
                for (std::uint64_t m = touched & ~whole; m; m &= m - 1) {
                  const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
                  double t[N], A[N], B[N];
                  int n = 0, edge[N];
                  for (int k = 0; k < N; ++k) {
                    const double value = at[k] + bias[k] + i * dx[k] + r * dy[k];
                    if (value >= half[k].reach) continue;  // inside
                    t[n] = value, A[n] = dx[k], B[n] = dy[k], edge[n] = k, ++n;
                  }
                  const double share = n == 1   ? half[edge[0]].share(t[0])
                                       : n == 2 ? two_edge_share(t, A, B, half[edge[0]], half[edge[1]])
                                                : clipped_share(n, t, A, B);
                  if (!(share > 0)) continue;  // touches only where two edges meet outside the square
                  cut.share[bit] = static_cast<float>(std::min(share, 1.0));
                  cut.partial |= std::uint64_t{1} << bit;
                }
                if (cut.partial) {
                  block.mask = cut.partial;
                  shade.area(block, cut);
                }
              });
}

/// Multisampled coverage of `edges` over the pixels of `clip`: per block, a mask for each of the `count`
/// sample positions of `pattern`. Blocks whose every sample is inside go to shade(block) (all samples
/// covered) and rectangles to shade.rect; others to shade.samples(block, masks), block.mask being the pixels
/// with any sample covered and masks[count] those whose centre is covered. The values in a Block are at the
/// pixel centres (where shading is evaluated), whatever the pattern. With `only`, partial blocks are masked
/// to its pixels before their samples are (the shade policy, OnlyPixels, masks the rest).
template <typename T, int N, typename Shade>
void cover_samples(const EdgeFunctions<T, N>& edges, Rect clip, const SamplePoint* pattern, int count,
                   Lanes lanes, StopMeter& meter, Shade&& shade, const BlockMasks* only = nullptr) {
  using namespace coverage_detail;
  if (clip.empty()) return;
  const BlockGrid<T, N> g(edges, clip, SamplePoint{});
  T offset[16][N], least[N], most[N];  // E's change from the pixel centre to each sample, and its extremes
  for (int k = 0; k < N; ++k) {
    const T a(edges.a[k]), b(edges.b[k]);
    for (int s = 0; s < count; ++s) {
      offset[s][k] = a * T(pattern[s].x - kSubpixelScale / 2) + b * T(pattern[s].y - kSubpixelScale / 2);
      least[k] = s == 0 ? offset[s][k] : std::min(least[k], offset[s][k]);
      most[k] = s == 0 ? offset[s][k] : std::max(most[k], offset[s][k]);
    }
  }
  std::uint64_t masks[17];  // each sample's, then the pixel centres' (which shading's centroid asks for)
#if defined(__x86_64__)
  // AVX2 masks every sample in one pass (sample_masks_avx2) where the values fit int32: an edge crossing a
  // block has |E| below its reach over the block there, and the offsets add at most `spread`.
  constexpr std::int64_t kLimit = std::int64_t{1} << 30;
  std::int32_t offset32[N][16] = {}, dx32[N] = {}, dy32[N] = {};
  std::int64_t fits_below[N] = {};  // |E| at a block's first pixel below which its samples' values fit
  bool fused = false;
  if constexpr (std::is_same_v<T, std::int64_t>) {
    fused = lanes == Lanes::avx2 && (count == 4 || count == 8 || count == 16);
    for (int k = 0; k < N; ++k) {
      const std::int64_t reach = 8 * (std::abs(g.step_x[k]) + std::abs(g.step_y[k])),
                         spread = std::max(std::abs(least[k]), std::abs(most[k]));
      fits_below[k] = kLimit - reach - spread;
      fused = fused && fits_below[k] > 0;
      if (!fused) break;
      dx32[k] = static_cast<std::int32_t>(g.step_x[k]), dy32[k] = static_cast<std::int32_t>(g.step_y[k]);
      for (int s = 0; s < count; ++s) offset32[k][s] = static_cast<std::int32_t>(offset[s][k]);
    }
  }
#endif
  walk_blocks(g, edges.area, clip, least, most, meter, shade,
              [&](Block& block, const T(&e)[N], std::uint64_t clipped, int r0, int r1) {
                if (only && !(clipped &= only->at(block.x0, block.y0))) return;  // none of `only`'s
                std::uint64_t any = 0;
#if defined(__x86_64__)
                if constexpr (std::is_same_v<T, std::int64_t>) {
                  unsigned crossing = 0;
                  bool fits = fused;
                  for (int k = 0; k < N; ++k)
                    if (e[k] + std::min(least[k], T(0)) + g.low[k] < 0) {  // some sample or centre
                      crossing |= 1u << k;
                      fits = fits && std::abs(e[k]) < fits_below[k];
                    }
                  if (fits) {
                    std::int32_t e32[N];
                    for (int k = 0; k < N; ++k)
                      e32[k] = static_cast<std::int32_t>(crossing & (1u << k) ? e[k] : 0);
                    if (count == 4)
                      sample_masks_avx2<4>(e32, dx32, dy32, crossing, offset32, r0, r1, masks);
                    else if (count == 8)
                      sample_masks_avx2<8>(e32, dx32, dy32, crossing, offset32, r0, r1, masks);
                    else  // 16 (`fused` holds only for the three)
                      sample_masks_avx2<16>(e32, dx32, dy32, crossing, offset32, r0, r1, masks);
                    for (int s = 0; s < count; ++s) any |= masks[s] &= clipped;
                    masks[count] &= clipped;
                    if (any) {
                      block.mask = any;
                      shade.samples(block, masks);
                    }
                    return;
                  }
                }
#endif
                for (int s = 0; s < count; ++s) {
                  T es[N];
                  for (int k = 0; k < N; ++k) es[k] = e[k] + offset[s][k];
                  masks[s] = clipped & inside_mask(es, g, lanes, r0, r1);
                  any |= masks[s];
                }
                if (any) masks[count] = clipped & inside_mask(e, g, lanes, r0, r1);
                if (any) {
                  block.mask = any;
                  shade.samples(block, masks);
                }
              });
}

}  // namespace raster::detail
