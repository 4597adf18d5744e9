// The shader engine's maths over lanes, part two: GLSL ES 3.00's angle, trigonometry and exponential
// functions (8.1, 8.2), over F = float or FloatLanes like lane_math.h, with its rules (IEEE operations,
// integer operations, comparisons and selects; no libm; one lane and eight give the same bits).
//
// They are llvmpipe's (Mesa 22.3) algorithms, step for step, so that rasterd's pixels follow llvmpipe's:
// exp2, log2, sin and cos are gallivm's polynomials (lp_bld_arit.c); pow, exp and log are built from them
// as gallivm and glsl_to_nir build them; tan, asin, acos, the hyperbolics and their inverses are GLSL IR's
// formulas (builtin_functions.cpp); atan and atan(y, x) are NIR's (nir_builtin_builder.c). gallivm's
// polynomials use llvm.fmuladd, one fused operation on a CPU with FMA and two roundings without: rasterd
// rounds twice on every CPU (a non-FMA host's llvmpipe bits), as an exact fused step in doubles cost five
// times as much. One departure: sin and cos reduce |x| >= 2^16 exactly (llvmpipe's reduction loses
// precision there and breaks past 1.7e9), so they stay within 1.6 ulp there.
//
// The error bounds in the comments were measured by tests/shader_math_test.cpp against long double.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <type_traits>

#include "shader/lane_math.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace raster::shader {
namespace lane_detail {

/// gallivm's llvm.fmuladd as a host without FMA computes it: a * b rounded, then + c rounded.
template <class F>
[[gnu::always_inline]] inline F fused_mul_add(F a, F b, F c) {
  return a * b + c;
}

/// A gallivm constant: the double rounded once to float (lp_build_const_vec), in every lane.
template <class F>
[[gnu::always_inline]] inline F constant(double v) {
  return splat<F>(static_cast<float>(v));
}

/// gallivm's lp_build_polynomial: c[0] + c[1] x + ..., its even and odd terms in x^2 separately, each a
/// fused Horner chain, joined by one more fused step.
template <class F, int n>
[[gnu::always_inline]] inline F lp_polynomial(F x, const double (&c)[n]) {
  const F x2 = x * x;
  const int top_even = (n - 1) & ~1, top_odd = (n - 2) | 1;
  F even = constant<F>(c[top_even]);
  F odd = constant<F>(c[top_odd]);
  for (int i = top_even - 2; i >= 0; i -= 2) even = fused_mul_add(x2, even, constant<F>(c[i]));
  for (int i = top_odd - 2; i >= 1; i -= 2) odd = fused_mul_add(x2, odd, constant<F>(c[i]));
  return fused_mul_add(odd, x, even);
}

// gallivm's minimax fits (EXP_POLY_DEGREE 5, LOG_POLY_DEGREE 4); constants are rounded to float once.
inline constexpr double kExp2Poly[] = {1.0,
                                       0.693153073200168932794,
                                       0.240153617044375388211,
                                       0.0558263180532956664775,
                                       0.00898934009049466391101,
                                       0.00187757667519147912699};
inline constexpr double kLog2Poly[] = {2.88539009343309178325, 0.961791550404184197881,
                                       0.577440339438736392009, 0.403343858251329912514,
                                       0.406718052498846252698};
inline constexpr float kFloatMin = 1.17549435e-38f;

/// x's lanes that llvmpipe sees as zero: it runs shaders with denormals flushed (MXCSR DAZ and FTZ).
template <class F>
[[gnu::always_inline]] inline IntOf<F> zero_or_denormal(F x) {
  return lt(abs(x), splat<F>(kFloatMin));
}

}  // namespace lane_detail

/// 2^x, lp_build_exp2: x clamped to [-126.99999, 128], 2^floor(x) built in the exponent bits times a
/// degree-5 polynomial of the fraction. At most 3.3 ulp on [-126, 128); results below 2^-126 are 0,
/// x >= 128 gives +Inf, -Inf gives 0, NaN gives NaN.
template <class F>
[[gnu::always_inline]] inline F exp2(F x) {
  using U = UIntOf<F>;
  x = select(lt(splat<F>(128.0f), x), splat<F>(128.0f), x);  // minps(128, x): a NaN x stays
  x = select(gt(splat<F>(-126.99999f), x), splat<F>(-126.99999f), x);
  const F whole = floor(x);
  const F fraction = x - whole;
  const U biased = std::bit_cast<U>(convert<IntOf<F>>(select(isnan(whole), F{}, whole))) + 127u;
  return as_float(biased << 23) * lane_detail::lp_polynomial(fraction, lane_detail::kExp2Poly);
}

/// log2(x), lp_build_log2_safe: the exponent plus y * P(y^2), y = (m - 1) / (m + 1) for the mantissa m in
/// [1, 2). Absolute error at most 1.8e-7 for x in [0.5, 2] (the relative error is large just below 1), at
/// most 1.9 ulp elsewhere. +-0 and denormals give -Inf (llvmpipe flushes them), x < 0 and NaN give NaN,
/// +Inf gives +Inf.
template <class F>
[[gnu::always_inline]] inline F log2(F x) {
  using I = IntOf<F>;
  const I bits = as_int(x);
  const F exponent = convert<F>(((bits & 0x7f800000) >> 23) - 127);
  const F m = as_float((bits & 0x007fffff) | 0x3f800000);
  const F y = (m - 1.0f) / (m + 1.0f);
  const F p = lane_detail::lp_polynomial(y * y, lane_detail::kLog2Poly);
  F r = lane_detail::fused_mul_add(y, p, exponent);
  const I zero = lane_detail::zero_or_denormal(x);
  r = select(ge(x, splat<F>(__builtin_inff())), splat<F>(__builtin_inff()), r);
  r = select(zero, splat<F>(-__builtin_inff()), r);
  return select((lt(x, F{}) & ~zero) | isnan(x), splat<F>(__builtin_nanf("")), r);
}

/// e^x = 2^(x * log2(e)), glsl_to_nir's ir_unop_exp (the constant rounded to float). The product's
/// rounding and the constant's go through exp2 amplified: within 3.4 + 1.25 |x| ulp on [-87.3, 88.7].
template <class F>
[[gnu::always_inline]] inline F exp(F x) {
  return exp2(x * static_cast<float>(1.4426950408889634));
}
/// ln(x) = log2(x) * ln(2), glsl_to_nir's ir_unop_log. Absolute error at most 1.3e-7 on [0.5, 2], at
/// most 2.5 ulp elsewhere; special values as log2's.
template <class F>
[[gnu::always_inline]] inline F log(F x) {
  return log2(x) * static_cast<float>(1.0 / 1.4426950408889634);
}
/// x^y = 2^(log2(x) * y), lp_build_pow, which returns 0 for x = 0 (also 0^0 and 0^-1), for denormals and
/// for NaN; x < 0 gives NaN. log2's error times |y| and the product's rounding go through exp2: within
/// 3.2 + 2.1 |y log2 x| ulp, plus 2.1 |y| ulp for x in [0.5, 2], where log2's error is absolute (so
/// pow(1.0001, 10000) is off by about 0.1%).
template <class F>
[[gnu::always_inline]] inline F pow(F x, F y) {
  const IntOf<F> zero = lane_detail::zero_or_denormal(x) | isnan(x);
  return select(zero, F{}, exp2(log2(x) * y));
}

namespace lane_detail {

/// |x| = j * pi/4 + r: j even (only its low three bits matter), |r| <= pi/4 (a little more from
/// rounding).
template <class F>
struct Quadrant {
  IntOf<F> j;
  F r;
};

/// llvmpipe's (Cephes') reduction: j = (int(|x| * 4/pi) + 1) & ~1 and r = |x| - j * pi/4, pi/4 in three
/// parts, fused. Sound for |x| < 2^16; the lanes beyond are left for reduce_large.
template <class F>
[[gnu::always_inline]] inline Quadrant<F> reduce_cephes(F ax) {
  using I = IntOf<F>;
  const F scaled = ax * static_cast<float>(1.27323954473516);
  const I j = (convert<I>(select(lt(ax, splat<F>(65536.0f)), scaled, F{})) + 1) & ~1;
  const F y = convert<F>(j);
  F r = fused_mul_add(y, splat<F>(-0.78515625f), ax);
  r = fused_mul_add(y, constant<F>(-2.4187564849853515625e-4), r);
  r = fused_mul_add(y, constant<F>(-3.77489497744594108e-8), r);
  return {j, r};
}

/// 2/pi's bits for reduce_large: row k is floor(2^(8k + 72) * 2/pi) mod 2^96 in three words, high first
/// (for exponent fields 8(k + 16) to 8(k + 16) + 7).
inline constexpr std::uint32_t kTwoOverPi[16][3] = {
    {0x000000a2, 0xf9836e4e, 0x441529fc}, {0x0000a2f9, 0x836e4e44, 0x1529fc27},
    {0x00a2f983, 0x6e4e4415, 0x29fc2757}, {0xa2f9836e, 0x4e441529, 0xfc2757d1},
    {0xf9836e4e, 0x441529fc, 0x2757d1f5}, {0x836e4e44, 0x1529fc27, 0x57d1f534},
    {0x6e4e4415, 0x29fc2757, 0xd1f534dd}, {0x4e441529, 0xfc2757d1, 0xf534ddc0},
    {0x441529fc, 0x2757d1f5, 0x34ddc0db}, {0x1529fc27, 0x57d1f534, 0xddc0db62},
    {0x29fc2757, 0xd1f534dd, 0xc0db6295}, {0xfc2757d1, 0xf534ddc0, 0xdb629599},
    {0x2757d1f5, 0x34ddc0db, 0x6295993c}, {0x57d1f534, 0xddc0db62, 0x95993c43},
    {0xd1f534dd, 0xc0db6295, 0x993c4390}, {0xf534ddc0, 0xdb629599, 0x3c439041}};

/// Exact reduction for |x| >= 2^16 (Payne and Hanek's idea, with 64-bit integers). |x| = M * 2^(8a + b -
/// 150) for the 24-bit mantissa M; x * 2/pi mod 4 in 2.62 fixed point is (M << b) times 96 bits of 2/pi
/// chosen by a, of which only the product's middle 64 bits are kept. Its nearest integer n is the quadrant
/// (j = 2n) and the rest, times pi/2, is r. One lane; eight lanes take it lane by lane (64-bit products
/// and table loads a lane do not vectorize on SSE2 or AVX2), which gives them the same bits.
[[gnu::always_inline]] inline Quadrant<float> reduce_large(float ax) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(ax);
  const std::uint32_t field = bits >> 23;
  const std::uint32_t* w = kTwoOverPi[std::max(field, 128u) / 8 - 16];  // below 2^16: unused lanes
  const std::uint64_t m = static_cast<std::uint64_t>((bits & 0x7fffffu) | 0x800000u) << (field & 7);
  const std::uint64_t q = (m * w[0] << 32) + m * w[1] + (m * w[2] >> 32);
  const std::uint64_t n = (q + (1ull << 61)) >> 62;
  const auto rest = static_cast<std::int64_t>(q - (n << 62));
  const double r = static_cast<double>(rest) * 3.4061215800865545e-19;  // rest * (pi/2) / 2^62
  return {static_cast<std::int32_t>(n << 1), static_cast<float>(r)};
}
[[gnu::always_inline]] inline Quadrant<FloatLanes> reduce_large(FloatLanes ax) {
  Quadrant<FloatLanes> out;
  for (int i = 0; i < kLanes; ++i) {
    const Quadrant<float> one = reduce_large(ax[i]);
    out.j[i] = one.j;
    out.r[i] = one.r;
  }
  return out;
}

/// sin (cos = false) or cos of a, lp_build_sin_or_cos: reduce, evaluate Cephes' sine or cosine
/// polynomial by the quadrant, set the sign, clamp to [-1, 1]; +-Inf and NaN give NaN.
template <bool cos, class F>
[[gnu::always_inline]] inline F sin_or_cos(F a) {
  using I = IntOf<F>;
  const F ax = abs(a);
  const Quadrant<F> small = reduce_cephes(ax);
  const I is_small = lt(ax, splat<F>(65536.0f));
  I j = small.j;
  F r = small.r;
  // The exact reduction costs several times the rest: it runs only where a lane needs it (the answer of
  // each lane is the same either way).
  bool any_large;
  if constexpr (kOneLane<F>) {
    any_large = !is_small;
  } else {
    any_large = detail::lane_bits(~is_small) != 0;
  }
  if (any_large) {
    const Quadrant<F> large = reduce_large(ax);
    j = select(is_small, small.j, large.j);
    r = select(is_small, small.r, large.r);
  }
  const I q = cos ? j - 2 : j;
  const I sign = cos ? (~q & 4) << 29 : (as_int(a) ^ (j << 29)) & kSignBit;
  const F z = r * r;
  const F cp = fused_mul_add(
      fused_mul_add(z, constant<F>(2.443315711809948E-005), constant<F>(-1.388731625493765E-003)), z,
      constant<F>(4.166664568298827E-002));
  const F cosine = ((cp * z) * z - z * 0.5f) + 1.0f;
  const F sp = fused_mul_add(fused_mul_add(z, constant<F>(-1.9515295891E-4), constant<F>(8.3321608736E-3)), z,
                             constant<F>(-1.6666654611E-1));
  const F sine = fused_mul_add(sp * z, r, r);
  F v = as_float(as_int(select(eq(q & 2, I{}), sine, cosine)) ^ sign);
  v = select(lt(v, splat<F>(1.0f)), v, splat<F>(1.0f));  // lp_build_clamp: minps, maxps
  v = select(gt(v, splat<F>(-1.0f)), v, splat<F>(-1.0f));
  return select(ne(as_int(a) & 0x7f800000, splat<I>(0x7f800000)), v, splat<F>(__builtin_nanf("")));
}

}  // namespace lane_detail

/// sin(x), cos(x): on [-pi, pi] at most 1.6 ulp, or 2e-9 absolute where the result is below 2^-5 (near the
/// zeros); up to 2^16 the reduction's rounded steps add 1.8e-11 |x| absolute (1.2e-6 at 2^16), bit for bit
/// llvmpipe's on a host without FMA; beyond, reduced exactly: 1.6 ulp again. sin(+-0) = +-0; +-Inf and
/// NaN give NaN.
template <class F>
[[gnu::always_inline]] inline F sin(F x) {
  return lane_detail::sin_or_cos<false>(x);
}
template <class F>
[[gnu::always_inline]] inline F cos(F x) {
  return lane_detail::sin_or_cos<true>(x);
}
/// sin(x) / cos(x), GLSL IR's tan. At most 3 ulp on [-1.5, 1.5] (3e-9 absolute where |tan x| < 2^-5);
/// nearer the poles cos's absolute error shows.
template <class F>
[[gnu::always_inline]] inline F tan(F x) {
  return sin(x) / cos(x);
}

namespace lane_detail {
/// GLSL IR's asin_expr: sign(x) (pi/2 - sqrt(1 - |x|) (pi/2 + |x| (pi/4 - 1 + |x| (p0 + |x| p1)))).
template <class F>
[[gnu::always_inline]] inline F asin_expr(F x, float p0, float p1) {
  const float half_pi = static_cast<float>(1.57079632679489661923);
  const float quarter_pi_minus_one = static_cast<float>(0.78539816339744830962) - 1.0f;
  const F ax = abs(x);
  const F poly = half_pi + ax * (quarter_pi_minus_one + ax * (p0 + ax * p1));
  return sign(x) * (half_pi - sqrt(1.0f - ax) * poly);
}
}  // namespace lane_detail

/// asin, acos: GLSL IR's polynomial approximations. Absolute error at most 4e-4 (asin) and 1.6e-4 (acos)
/// on [-1, 1]; |x| > 1 and NaN give NaN.
template <class F>
[[gnu::always_inline]] inline F asin(F x) {
  return lane_detail::asin_expr(x, 0.086566724f, -0.03102955f);
}
template <class F>
[[gnu::always_inline]] inline F acos(F x) {
  return static_cast<float>(1.57079632679489661923) - lane_detail::asin_expr(x, 0.08132463f, -0.02363318f);
}

/// atan(x), nir_atan: t = min(|x|, 1) / max(|x|, 1), an odd degree-11 polynomial summed term by term (as
/// NIR leaves it after its reassociation), pi/2 minus it for |x| > 1, times sign(x). Absolute error at most
/// 3.3e-6; atan(NaN) = 0 (NIR drops NaN here).
template <class F>
[[gnu::always_inline]] inline F atan(F x) {
  const F one = splat<F>(1.0f);
  const F ax = abs(x);
  const F t = min(ax, one) / max(ax, one);
  const F t2 = t * t, t3 = t2 * t, t5 = t3 * t2, t7 = t5 * t2, t9 = t7 * t2;
  F s = t * 0.9999793128310355f + t3 * -0.3326756418091246f;
  s = s + t5 * 0.1938924977115610f;
  s = s + t7 * -0.1173503194786851f;
  s = s + t9 * 0.0536813784310406f;
  s = s + (t9 * -0.0121323213173444f) * t2;     // t^11 * c: nir_opt_algebraic moves the constant in
  const F big = select(lt(one, ax), one, F{});  // b2f(1 < |x|)
  s = big * (s * -2.0f + static_cast<float>(1.57079632679489661923)) + s;
  return s * sign(x);
}

/// atan(y, x), nir_atan2: atan of the quotient of the smaller by the larger coordinate after turning the
/// left half-plane by pi/2, |x| = |y| taken as 1 (so +-Inf's give the IEEE multiples of pi/4 and (0, 0)
/// gives 3pi/4 with y's sign), the sign from min(y, 1/t). Absolute error at most 3.5e-6 where x and y are
/// not denormal (1 / a denormal overflows; llvmpipe flushes them to 0). A NaN gives 0 or +-pi/2, no NaN.
template <class F>
[[gnu::always_inline]] inline F atan(F y, F x) {
  const F one = splat<F>(1.0f);
  const IntOf<F> flip = ge(F{}, x);
  const F s = select(flip, abs(x), y);
  const F t = select(flip, y, abs(x));
  const F scale = select(ge(abs(t), splat<F>(1e18f)), splat<F>(0.25f), one);
  const F rcp_scaled_t = 1.0f / (t * scale);
  const F s_over_t = (s * scale) * rcp_scaled_t;
  const F tangent = select(eq(abs(x), abs(y)), one, abs(s_over_t));
  const F arc = select(flip, one, F{}) * static_cast<float>(1.57079632679489661923) + atan(tangent);
  return select(lt(min(y, rcp_scaled_t), F{}), -arc, arc);
}

/// sinh, cosh, tanh: GLSL IR's (e^x -+ e^-x) forms, e^x as exp. tanh clamps x to [-10, 10] first (NaN
/// gives -1, as llvmpipe). sinh and cosh: within 4 + 1.25 |x| ulp (exp's), sinh 3.2e-7 absolute on
/// [-1, 1]; tanh: 2.7 ulp for |x| >= 1, 1.5e-7 absolute below (the differences lose relative precision).
template <class F>
[[gnu::always_inline]] inline F sinh(F x) {
  return 0.5f * (exp(x) - exp(-x));
}
template <class F>
[[gnu::always_inline]] inline F cosh(F x) {
  return 0.5f * (exp(x) + exp(-x));
}
template <class F>
[[gnu::always_inline]] inline F tanh(F x) {
  const F t = min(max(x, splat<F>(-10.0f)), splat<F>(10.0f));
  const F ep = exp(t), en = exp(-t);
  return (ep - en) / (ep + en);
}

/// asinh, acosh, atanh: GLSL IR's log forms. asinh(x) = sign(x) ln(|x| + sqrt(x^2 + 1)), acosh(x) =
/// ln(x + sqrt(x^2 - 1)), atanh(x) = 0.5 ln((1 + x) / (1 - x)); x^2 overflows past 1.8e19 (+Inf). asinh:
/// 2.7 ulp for |x| > 1, 1.8e-7 absolute on [-1, 1]; acosh: 2 ulp for x > 2, 1.2e-6 absolute on [1, 2];
/// atanh: 2.3 ulp for |x| > 0.5, 1.3e-7 absolute on [-0.5, 0.5].
template <class F>
[[gnu::always_inline]] inline F asinh(F x) {
  return sign(x) * log(abs(x) + sqrt(x * x + 1.0f));
}
template <class F>
[[gnu::always_inline]] inline F acosh(F x) {
  return log(x + sqrt(x * x - 1.0f));
}
template <class F>
[[gnu::always_inline]] inline F atanh(F x) {
  return 0.5f * log((1.0f + x) / (1.0f - x));
}

}  // namespace raster::shader

#pragma GCC diagnostic pop
