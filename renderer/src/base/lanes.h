// Lanes: the value types shading computes in, one pixel (float, double) or eight side by side (GCC vector
// types), and the few operations that need an instruction set. The shading code is written once over a lane
// type; inlined into a target("avx2") function, eight lanes become AVX2 code (a register a value),
// elsewhere SSE2 (two registers a value); one lane is scalar code. IEEE float operations round the same
// in every lane width, and nothing here is approximate (no rcp/rsqrt, whose results differ between CPUs, and
// the library is built with -ffp-contract=off), so every width gives the same bytes.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace raster::detail {

// Eight float lanes are 32 bytes, which a function compiled without AVX could not pass by value the way an
// AVX one does (GCC warns): the functions here take and give them by reference.
inline constexpr int kLanes = 8;  ///< pixels a step: one block row
using FloatLanes = float __attribute__((vector_size(4 * kLanes)));
using IntLanes = std::int32_t __attribute__((vector_size(4 * kLanes)));
using FloatHalf = float __attribute__((vector_size(2 * kLanes)));    ///< four lanes of FloatLanes
using DoubleHalf = double __attribute__((vector_size(4 * kLanes)));  ///< four lanes, in doubles

/// sqrt in each lane, in place, exactly rounded (IEEE), for one lane or eight. Eight lanes take two SSE
/// square roots on every instruction set: an intrinsic of a wider one could not be inlined into this generic
/// code, and where AVX2 runs, the core splits a 256-bit square root in two anyway.
[[gnu::always_inline]] inline void sqrt_lanes(float& x) {
  x = std::sqrt(x);
}
[[gnu::always_inline]] inline void sqrt_lanes(FloatLanes& x) {
#if defined(__SSE2__)
  // Halves and back by shuffles, not through memory: two 16-byte stores read as one 32-byte load stall.
  const FloatHalf lo = _mm_sqrt_ps(__builtin_shufflevector(x, x, 0, 1, 2, 3));
  const FloatHalf hi = _mm_sqrt_ps(__builtin_shufflevector(x, x, 4, 5, 6, 7));
  x = __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7);
#else
  for (int i = 0; i < kLanes; ++i) x[i] = std::sqrt(x[i]);
#endif
}

/// Bit i set where lane i of a comparison's result is true (all ones).
[[gnu::always_inline]] inline unsigned lane_bits(const IntLanes& m) {
#if defined(__SSE2__)
  const FloatHalf lo = reinterpret_cast<FloatHalf>(__builtin_shufflevector(m, m, 0, 1, 2, 3));
  const FloatHalf hi = reinterpret_cast<FloatHalf>(__builtin_shufflevector(m, m, 4, 5, 6, 7));
  return static_cast<unsigned>(_mm_movemask_ps(lo) | _mm_movemask_ps(hi) << 4);
#else
  unsigned bits = 0;
  for (int i = 0; i < kLanes; ++i) bits |= static_cast<unsigned>(m[i] & 1) << i;
  return bits;
#endif
}

/// Lane i holds bit i: (kLaneBit & bits) != 0 is all ones in the lanes whose bit is set in `bits`.
inline constexpr IntLanes kLaneBit = {1, 2, 4, 8, 16, 32, 64, 128};

/// A channel value (0..255 scale) on its way to a byte, in place, the same in every lane width: x + 0.5,
/// with out-of-range values clamped and NaN made 0, so that lane_byte's truncation rounds it to nearest.
[[gnu::always_inline]] inline void byte_lanes(FloatLanes& x) {
  FloatLanes r = x + 0.5f;
  r = x >= 254.5f ? FloatLanes{} + 255.0f : r;
  x = x > 0.0f ? r : FloatLanes{};  // also NaN
}
[[gnu::always_inline]] inline void byte_lanes(float& x) {
  x = !(x > 0.0f) ? 0.0f : x >= 254.5f ? 255.0f : x + 0.5f;
}
/// Lane i of byte_lanes's result as a byte (truncated: in 0..255.5, so no conversion can overflow).
[[gnu::always_inline]] inline std::uint8_t lane_byte(float v, int) {
  return static_cast<std::uint8_t>(static_cast<int>(v));
}
[[gnu::always_inline]] inline std::uint8_t lane_byte(const FloatLanes& v, int i) {
  return static_cast<std::uint8_t>(static_cast<int>(v[i]));
}

/// byte_lanes's eight values as bytes of a word, lane i in byte i (truncated, as lane_byte does).
[[gnu::always_inline]] inline std::uint64_t lane_bytes(const FloatLanes& v) {
  const IntLanes whole = __builtin_convertvector(v, IntLanes);
#if defined(__SSE2__)
  // Packed by saturating halves (GCC's generic narrowing extracts lane by lane); values are 0..255.
  using Int4 = std::int32_t __attribute__((vector_size(16)));
  const __m128i lo = reinterpret_cast<__m128i>(Int4(__builtin_shufflevector(whole, whole, 0, 1, 2, 3)));
  const __m128i hi = reinterpret_cast<__m128i>(Int4(__builtin_shufflevector(whole, whole, 4, 5, 6, 7)));
  const __m128i words = _mm_packs_epi32(lo, hi);
  return static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_packus_epi16(words, words)));
#else
  using ByteLanes = std::uint8_t __attribute__((vector_size(kLanes)));
  const ByteLanes b = __builtin_convertvector(whole, ByteLanes);
  std::uint64_t word;
  std::memcpy(&word, &b, sizeof word);
  return word;
#endif
}

/// Lane i of a value (the value itself for one lane).
[[gnu::always_inline]] inline float lane(float v, int) {
  return v;
}
[[gnu::always_inline]] inline float lane(const FloatLanes& v, int i) {
  return v[i];
}

}  // namespace raster::detail
