#include "setup/batch.h"

#include <algorithm>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace raster::detail {
namespace {

// Whether some position of the pattern lies in the box [lo, hi] (1/256 px) in a pixel of the image: for
// sample s at p in each pixel, the pixels k with lo <= 256 k + p <= hi are those from (lo - p + 255) >> 8 to
// (hi - p) >> 8, on each axis, within [0, size).
bool holds_a_sample(const std::int32_t (&lo)[2], const std::int32_t (&hi)[2], const SamplePoint* pattern,
                    int count, const int (&size)[2]) {
  for (int s = 0; s < count; ++s) {
    const std::int32_t p[2] = {pattern[s].x, pattern[s].y};
    bool in = true;
    for (int d = 0; d < 2; ++d) {
      const std::int32_t first = std::max((lo[d] - p[d] + 255) >> 8, 0);
      const std::int32_t last = std::min((hi[d] - p[d]) >> 8, size[d] - 1);
      in = in && first <= last;
    }
    if (in) return true;
  }
  return false;
}

std::uint32_t candidates_scalar(const std::array<std::uint32_t, 3>* triangles, int n,
                                const ScreenVertex* screen, const SamplePoint* pattern, int count,
                                const int (&size)[2]) {
  std::uint32_t mask = 0;
  for (int i = 0; i < n; ++i) {
    const ScreenVertex& a = screen[triangles[i][0]];
    const ScreenVertex& b = screen[triangles[i][1]];
    const ScreenVertex& c = screen[triangles[i][2]];
    const bool unprojected = a.x == kNoScreen || b.x == kNoScreen || c.x == kNoScreen;
    const std::int32_t lo[2] = {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})};
    const std::int32_t hi[2] = {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})};
    mask |= static_cast<std::uint32_t>(unprojected || holds_a_sample(lo, hi, pattern, count, size)) << i;
  }
  return mask;
}

#if defined(__x86_64__)
// The screen positions (x, y) of the eight vertices at `index`, as two vectors of x and of y.
__attribute__((target("avx2"))) inline void gather_xy(const ScreenVertex* screen, __m256i index, __m256i& x,
                                                      __m256i& y) {
  const auto* base = reinterpret_cast<const long long*>(screen);  // (x, y) is a ScreenVertex's first 8 bytes
  const __m256i twice = _mm256_add_epi32(index, index);           // 16 bytes a vertex: 2 x 8
  const __m256i lo = _mm256_i32gather_epi64(base, _mm256_castsi256_si128(twice), 8);
  const __m256i hi = _mm256_i32gather_epi64(base, _mm256_extracti128_si256(twice, 1), 8);
  const __m256i split = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);  // x x x x y y y y in each
  const __m256i l = _mm256_permutevar8x32_epi32(lo, split), h = _mm256_permutevar8x32_epi32(hi, split);
  x = _mm256_permute2x128_si256(l, h, 0x20);
  y = _mm256_permute2x128_si256(l, h, 0x31);
}

// holds_a_sample's rule for one axis and one position p, in eight lanes.
__attribute__((target("avx2"))) inline __m256i axis_holds(__m256i lo, __m256i hi, std::int32_t p, int size) {
  const __m256i first = _mm256_max_epi32(
      _mm256_srai_epi32(_mm256_add_epi32(lo, _mm256_set1_epi32(255 - p)), 8), _mm256_setzero_si256());
  const __m256i last = _mm256_min_epi32(_mm256_srai_epi32(_mm256_sub_epi32(hi, _mm256_set1_epi32(p)), 8),
                                        _mm256_set1_epi32(size - 1));
  return _mm256_cmpgt_epi32(_mm256_add_epi32(last, _mm256_set1_epi32(1)), first);  // first <= last
}

__attribute__((target("avx2"))) std::uint32_t candidates_avx2(const std::array<std::uint32_t, 3>* triangles,
                                                              const ScreenVertex* screen,
                                                              const SamplePoint* pattern, int count,
                                                              const int (&size)[2]) {
  const auto* index = reinterpret_cast<const int*>(triangles);
  const __m256i stride = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
  __m256i x[3], y[3], keep = _mm256_setzero_si256();
  for (int k = 0; k < 3; ++k) {
    gather_xy(screen, _mm256_i32gather_epi32(index + k, stride, 4), x[k], y[k]);
    keep = _mm256_or_si256(keep, _mm256_cmpeq_epi32(x[k], _mm256_set1_epi32(kNoScreen)));
  }
  const __m256i lo_x = _mm256_min_epi32(x[0], _mm256_min_epi32(x[1], x[2]));
  const __m256i hi_x = _mm256_max_epi32(x[0], _mm256_max_epi32(x[1], x[2]));
  const __m256i lo_y = _mm256_min_epi32(y[0], _mm256_min_epi32(y[1], y[2]));
  const __m256i hi_y = _mm256_max_epi32(y[0], _mm256_max_epi32(y[1], y[2]));
  for (int s = 0; s < count; ++s)
    keep = _mm256_or_si256(keep, _mm256_and_si256(axis_holds(lo_x, hi_x, pattern[s].x, size[0]),
                                                  axis_holds(lo_y, hi_y, pattern[s].y, size[1])));
  return static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_castsi256_ps(keep)));
}
#endif

}  // namespace

std::uint32_t sample_candidates(const std::array<std::uint32_t, 3>* triangles, int n,
                                const ScreenVertex* screen, const SamplePoint* pattern, int count, int width,
                                int height, Simd simd) {
  const int size[2] = {width, height};
#if defined(__x86_64__)
  if (simd == Simd::avx2 && n == 8) return candidates_avx2(triangles, screen, pattern, count, size);
#endif
  (void)simd;
  return candidates_scalar(triangles, n, screen, pattern, count, size);
}

}  // namespace raster::detail
