// The shader engine's maths over lanes, part one: the plumbing (lane types, splats, bit casts, masks,
// selects, conversions) and GLSL ES 3.00's common functions (chapter 8.3). F is one lane (float) or eight
// (raster::detail::FloatLanes); each function is written once, with IEEE operations, integer operations,
// comparisons and selects only, so one lane, SSE2 and AVX2 (eight lanes inlined into a target("avx2")
// function) give the same bits. No libm. The formulas are llvmpipe's (Mesa 22.3, see
// /work/notes/mesa-numerics.md), so a program made of these gives llvmpipe's pixels; lane_transcendental.h
// has the rest. Build with -ffp-contract=off (the library is): a contracted a * b + c changes the bits.
//
// Every function is always_inline and takes and returns lanes by value. A caller compiled without AVX gets
// one -Wpsabi warning per translation unit for that (nothing crosses a call boundary): silence it there with
// #pragma GCC diagnostic ignored "-Wpsabi". Call them qualified (shader::floor(x)): where <cmath> is seen,
// an unqualified call on a float would pick libm's overload over these templates.
#pragma once

#include <bit>
#include <cstdint>
#include <type_traits>

#include "base/lanes.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace raster::shader {

using detail::FloatLanes;
using detail::IntLanes;
using detail::kLanes;
using UIntLanes = std::uint32_t __attribute__((vector_size(4 * kLanes)));

namespace lane_types {
template <class T>
struct Of;
template <>
struct Of<float> {
  using Float = float;
  using Int = std::int32_t;
  using UInt = std::uint32_t;
  using Element = float;
};
template <>
struct Of<FloatLanes> {
  using Float = FloatLanes;
  using Int = IntLanes;
  using UInt = UIntLanes;
  using Element = float;
};
// A width's int and unsigned types know the others (an int lane type's Float is its width's float type).
template <>
struct Of<std::int32_t> : Of<float> {
  using Element = std::int32_t;
};
template <>
struct Of<std::uint32_t> : Of<float> {
  using Element = std::uint32_t;
};
template <>
struct Of<IntLanes> : Of<FloatLanes> {
  using Element = std::int32_t;
};
template <>
struct Of<UIntLanes> : Of<FloatLanes> {
  using Element = std::uint32_t;
};
}  // namespace lane_types

template <class T>
using FloatOf = typename lane_types::Of<T>::Float;
template <class T>
using IntOf = typename lane_types::Of<T>::Int;
template <class T>
using UIntOf = typename lane_types::Of<T>::UInt;
template <class T>
inline constexpr bool kOneLane = std::is_arithmetic_v<T>;

/// `v` in every lane of a T (any lane type: float, int or uint, one lane or eight).
template <class T, class V>
[[gnu::always_inline]] inline T splat(V v) {
  using E = typename lane_types::Of<T>::Element;
  if constexpr (kOneLane<T>) {
    return static_cast<E>(v);
  } else {
    return T{} + static_cast<E>(v);
  }
}

namespace lane_detail {
/// Lanes 0-3 and 4-7 of eight.
template <class T>
[[gnu::always_inline]] inline auto low(T x) {
  return __builtin_shufflevector(x, x, 0, 1, 2, 3);
}
template <class T>
[[gnu::always_inline]] inline auto high(T x) {
  return __builtin_shufflevector(x, x, 4, 5, 6, 7);
}
}  // namespace lane_detail

// Bit casts between a width's float, int and unsigned types.
template <class F>
[[gnu::always_inline]] inline IntOf<F> as_int(F x) {
  return std::bit_cast<IntOf<F>>(x);
}
template <class F>
[[gnu::always_inline]] inline UIntOf<F> as_uint(F x) {
  return std::bit_cast<UIntOf<F>>(x);
}
template <class I>
[[gnu::always_inline]] inline FloatOf<I> as_float(I x) {
  return std::bit_cast<FloatOf<I>>(x);
}

// Comparisons: a mask, 0 or -1 in each lane. Float ones are IEEE's: false with a NaN, except ne. Eight
// lanes compare as two halves: GCC lowers a 32-byte comparison lane by lane where the ISA has no 32-byte
// vectors (SSE2), and joins the halves back into one instruction where it has (AVX2).
#define RASTER_LANE_COMPARE(name, op)                                 \
  template <class T>                                                  \
  [[gnu::always_inline]] inline IntOf<T> name(T a, T b) {             \
    if constexpr (kOneLane<T>) {                                      \
      return (a op b) ? -1 : 0;                                       \
    } else {                                                          \
      const auto lo = lane_detail::low(a) op lane_detail::low(b);     \
      const auto hi = lane_detail::high(a) op lane_detail::high(b);   \
      return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7); \
    }                                                                 \
  }
RASTER_LANE_COMPARE(lt, <)
RASTER_LANE_COMPARE(le, <=)
RASTER_LANE_COMPARE(gt, >)
RASTER_LANE_COMPARE(ge, >=)
RASTER_LANE_COMPARE(eq, ==)
RASTER_LANE_COMPARE(ne, !=)
#undef RASTER_LANE_COMPARE

/// a where the mask is set (-1), b where it is clear (0); the mask's lanes are 0 or -1.
template <class M, class T>
[[gnu::always_inline]] inline T select(M mask, T a, T b) {
  static_assert(sizeof(M) == sizeof(T), "a mask of the value's width");
  if constexpr (kOneLane<T>) {
    return mask != 0 ? a : b;
  } else {
    // Bitwise: GCC lowers a `mask ? a : b` of eight lanes lane by lane where the ISA has no 32-byte vectors.
    using U = UIntOf<FloatOf<T>>;
    const U m = std::bit_cast<U>(mask);
    return std::bit_cast<T>((std::bit_cast<U>(a) & m) | (std::bit_cast<U>(b) & ~m));
  }
}

// Conversions, elementwise.
template <class T, class S>
[[gnu::always_inline]] inline T convert(S x) {
  if constexpr (kOneLane<S>) {
    return static_cast<T>(x);
  } else {
    return __builtin_convertvector(x, T);
  }
}

/// |x|: the sign bit cleared (NaN stays NaN, -0 is +0). Exact.
template <class F>
[[gnu::always_inline]] inline F abs(F x) {
  return as_float(as_int(x) & INT32_MAX);
}

namespace lane_detail {
inline constexpr std::int32_t kSignBit = INT32_MIN;
inline constexpr float kTwo23 = 8388608.0f;  // from here up every float is an integer

/// x with the sign bit of `sign_of` or'ed in.
template <class F>
[[gnu::always_inline]] inline F or_sign(F x, F sign_of) {
  return as_float(as_int(x) | (as_int(sign_of) & kSignBit));
}
/// x rounded toward zero where |x| < 2^23 (an integer-valued float), and the mask of those lanes.
template <class F>
[[gnu::always_inline]] inline F trunc_small(F x, IntOf<F>& small) {
  small = lt(abs(x), splat<F>(kTwo23));
  const F safe = select(small, x, F{});
  return convert<F>(convert<IntOf<F>>(safe));
}
}  // namespace lane_detail

// --- GLSL ES 3.00 8.3, common functions -------------------------------------------------------------------
// Exact (0 ulp) unless said: each is IEEE arithmetic on its operands, in the order llvmpipe evaluates it.

template <class F>
[[gnu::always_inline]] inline IntOf<F> isnan(F x) {
  return ne(x, x);
}
template <class F>
[[gnu::always_inline]] inline IntOf<F> isinf(F x) {
  return eq(abs(x), splat<F>(__builtin_inff()));
}

/// -1, 0 or 1; llvmpipe's lp_build_sgn: sign(+-0) = +0 and sign(NaN) = 0 (its zero test is unordered).
template <class F>
[[gnu::always_inline]] inline F sign(F x) {
  const F one = lane_detail::or_sign(splat<F>(1.0f), x);
  return select(eq(x, F{}) | isnan(x), F{}, one);
}

/// Rounding to integers (IEEE roundps semantics: NaN, +-Inf and |x| >= 2^23 pass through, -0 kept, a
/// negative x rounding to zero gives -0).
template <class F>
[[gnu::always_inline]] inline F trunc(F x) {
  IntOf<F> small;
  const F t = lane_detail::trunc_small(x, small);
  return select(small, lane_detail::or_sign(t, x), x);
}
template <class F>
[[gnu::always_inline]] inline F floor(F x) {
  const F t = trunc(x);
  return select(gt(t, x), t - 1.0f, t);
}
template <class F>
[[gnu::always_inline]] inline F ceil(F x) {
  const F t = trunc(x);
  return select(lt(t, x), t + 1.0f, t);
}
/// Nearest integer, halves to even. GLSL's round is this too in Mesa (ir_unop_round_even).
template <class F>
[[gnu::always_inline]] inline F roundEven(F x) {
  const F ax = abs(x);
  // Adding 2^23 leaves no fraction bits: the addition itself rounds, to nearest even.
  const F r = (ax + lane_detail::kTwo23) - lane_detail::kTwo23;
  return select(lt(ax, splat<F>(lane_detail::kTwo23)), lane_detail::or_sign(r, x), x);
}
template <class F>
[[gnu::always_inline]] inline F round(F x) {
  return roundEven(x);
}
/// x - floor(x), correctly rounded (0.5 ulp): in [0, 1], 1 for a tiny negative x (llvmpipe's ffract); NaN
/// for +-Inf.
template <class F>
[[gnu::always_inline]] inline F fract(F x) {
  return x - floor(x);
}
/// x - y * floor(x / y), the spec's formula and NIR's lowering of fmod: within 1 ulp of max(|x|, |y|) of
/// the exact formula, except where the rounded x / y falls on the other side of an integer (then off by y).
/// y = 0: NaN.
template <class F>
[[gnu::always_inline]] inline F mod(F x, F y) {
  return x - y * floor(x / y);
}
/// modf's parts: the whole part trunc(x) and the fraction x - trunc(x) (NaN for +-Inf, as llvmpipe).
template <class F>
[[gnu::always_inline]] inline F modf_whole(F x) {
  return trunc(x);
}
template <class F>
[[gnu::always_inline]] inline F modf_fraction(F x) {
  return x - trunc(x);
}

/// llvmpipe's fmin/fmax (minps/maxps with a NaN fix): a NaN operand gives the other one; with equal
/// operands (+0 and -0) the second. NIR swaps the operands when only the first is known not NaN, which
/// changes which zero comes back; a compiler matching that passes them swapped.
template <class F>
[[gnu::always_inline]] inline F min(F a, F b) {
  return select(lt(a, b) | isnan(b), a, b);
}
template <class F>
[[gnu::always_inline]] inline F max(F a, F b) {
  return select(gt(a, b) | isnan(b), a, b);
}
/// min(max(x, lo), hi): a NaN x gives lo (GLSL IR's clamp; fsat is lowered to the same).
template <class F>
[[gnu::always_inline]] inline F clamp(F x, F lo, F hi) {
  return min(max(x, lo), hi);
}

/// mix: NIR's flrp lowering (nir_lower_flrp.c). `mix` is its general form x + a * (y - x);
/// `mix_precise` is x * (1 - a) + y * a, which it picks when a is a constant, the flrp is `precise`, y is a
/// constant +-1, or another flrp shares x and a, or y and a; `mix_unit_x` is (x - a * x) + y * a, which is
/// (1 - a) + y * a and (-1 + a) + y * a, its form for a constant x of 1 or -1. The compiler picks. For a
/// in [0, 1] mix and mix_precise are within 2 ulp of max(|x|, |y|).
template <class F>
[[gnu::always_inline]] inline F mix(F x, F y, F a) {
  return x + a * (y - x);
}
template <class F>
[[gnu::always_inline]] inline F mix_precise(F x, F y, F a) {
  return x * (1.0f - a) + y * a;
}
template <class F>
[[gnu::always_inline]] inline F mix_unit_x(F x, F y, F a) {
  return (x - a * x) + y * a;
}
/// mix with a bool vector: y where the mask is set.
template <class F>
[[gnu::always_inline]] inline F mix(F x, F y, IntOf<F> a) {
  return select(a, y, x);
}

/// 1 where x >= edge, else 0 (0 for a NaN).
template <class F>
[[gnu::always_inline]] inline F step(F edge, F x) {
  return select(ge(x, edge), splat<F>(1.0f), F{});
}
/// t = clamp((x - e0) / (e1 - e0), 0, 1); t * (t * (3 - 2t)), GLSL IR's order: absolute error 2e-7. e0 = e1
/// gives 0 or 1, a NaN 0.
template <class F>
[[gnu::always_inline]] inline F smoothstep(F e0, F e1, F x) {
  const F t = clamp((x - e0) / (e1 - e0), F{}, splat<F>(1.0f));
  return t * (t * (3.0f - 2.0f * t));
}

/// IEEE square root, exactly rounded (sqrt(-0) = -0, negative: NaN).
template <class F>
[[gnu::always_inline]] inline F sqrt(F x) {
  detail::sqrt_lanes(x);
  return x;
}
/// 1 / sqrt(x), llvmpipe's frsq (a division, no rsqrt): at most 1.5 ulp (two roundings); +-0 gives +-Inf.
template <class F>
[[gnu::always_inline]] inline F inversesqrt(F x) {
  return 1.0f / sqrt(x);
}

// --- Conversions (GLSL ES leaves out-of-range ones undefined; rasterd defines them) ------------------------
// Float to int or uint: toward zero; NaN gives 0; out of range saturates. (llvmpipe differs there: x86's
// cvttps2dq gives INT_MIN for NaN and out-of-range ints; see the note.) Int or uint to float: rounded to
// nearest, like the hardware's.

template <class F>
[[gnu::always_inline]] inline IntOf<F> float_to_int(F x) {
  using I = IntOf<F>;
  const I in_range = lt(abs(x), splat<F>(2147483648.0f));  // also false for NaN
  const I whole = convert<I>(select(in_range, x, F{}));
  const I saturated = select(lt(x, F{}), splat<I>(INT32_MIN), splat<I>(INT32_MAX));
  return select(in_range | isnan(x), whole, saturated);
}
template <class F>
[[gnu::always_inline]] inline UIntOf<F> float_to_uint(F x) {
  using I = IntOf<F>;
  using U = UIntOf<F>;
  // [2^31, 2^32): convert x - 2^31 (exact there) and put the top bit back.
  const I high = ge(x, splat<F>(2147483648.0f));
  const F lowered = select(high, x - 2147483648.0f, x);
  const I in_range = gt(lowered, splat<F>(-1.0f)) & lt(lowered, splat<F>(2147483648.0f));
  const U whole = std::bit_cast<U>(convert<I>(select(in_range, lowered, F{})));
  const U with_top = whole | std::bit_cast<U>(high & lane_detail::kSignBit);
  const U saturated = select(gt(x, F{}), splat<U>(UINT32_MAX), U{});  // NaN: 0
  return select(in_range, with_top, saturated);
}
template <class I>
[[gnu::always_inline]] inline FloatOf<I> int_to_float(I x) {
  return convert<FloatOf<I>>(x);
}
/// Rounded once: the top 16 bits' value (exact) plus the low 16 bits' (exact), one rounding in the sum.
template <class U>
[[gnu::always_inline]] inline FloatOf<U> uint_to_float(U x) {
  using F = FloatOf<U>;
  using I = IntOf<F>;
  const F high = convert<F>(std::bit_cast<I>(x >> 16)) * 65536.0f;
  const F low = convert<F>(std::bit_cast<I>(x & 0xffffu));
  return high + low;
}

}  // namespace raster::shader

#pragma GCC diagnostic pop
