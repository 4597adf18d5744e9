// The shader engine's lane maths (renderer/src/shader/lane_math.h, lane_transcendental.h): each function's
// error measured against a long double reference (libm is fine here) over dense and seeded random samples
// of its domain and asserted against the bound its header states; the special values the headers
// promise; and the one-lane, SSE2 eight-lane and AVX2 eight-lane versions giving the same bits.
#pragma GCC diagnostic ignored "-Wpsabi"  // eight-lane values by value, all inlined (lane_math.h)

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "shader/lane_math.h"
#include "shader/lane_transcendental.h"

namespace {

// More samples for a long measuring run (the bounds below were set from one at 50).
#ifndef SHADER_MATH_SAMPLES
#define SHADER_MATH_SAMPLES 1
#endif
constexpr int kScale = SHADER_MATH_SAMPLES;

namespace sh = raster::shader;
using sh::FloatLanes;
using LD = long double;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kPi = 3.14159265358979323846f;

bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

/// One ulp of a float near r: 2^(e - 24) for |r| in [2^(e-1), 2^e), 2^-149 below the normal range.
LD ulp_of(LD r) {
  r = std::fabs(r);
  if (r < 0x1p-126L) return 0x1p-149L;
  int e;
  std::frexp(r, &e);
  return std::ldexp(1.0L, e - 24);
}

/// A float's position in the ordered sequence of floats (so random integers between two give floats spread
/// over every binade between them).
std::int64_t order_of(float f) {
  const std::int32_t i = std::bit_cast<std::int32_t>(f);
  return i < 0 ? -static_cast<std::int64_t>(i & 0x7fffffff) : i;
}
float float_at(std::int64_t o) {
  return o < 0 ? std::bit_cast<float>(static_cast<std::int32_t>(-o) | INT32_MIN)
               : std::bit_cast<float>(static_cast<std::int32_t>(o));
}

/// Inputs in [lo, hi]: evenly spaced, uniform random, and random over the floats' order (every binade).
std::vector<float> samples(float lo, float hi, int dense, int random, std::uint32_t seed) {
  std::vector<float> xs;
  xs.reserve(dense + 2 * random + 2);
  xs.push_back(lo);
  xs.push_back(hi);
  for (int i = 0; i < dense; ++i)
    xs.push_back(static_cast<float>(lo + (double{hi} - lo) * (i + 0.5) / dense));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(lo, hi);
  std::uniform_int_distribution<std::int64_t> ordered(order_of(lo), order_of(hi));
  for (int i = 0; i < random; ++i) xs.push_back(static_cast<float>(uniform(rng)));
  for (int i = 0; i < random; ++i) xs.push_back(float_at(ordered(rng)));
  return xs;
}

/// The worst errors over a set of samples: in ulps where the error is judged relatively, in absolute value
/// where the case judges it absolutely (near a function's zeros, or where its header states an absolute
/// bound).
struct Worst {
  double ulps = 0, abs = 0;
  float ulps_at = 0, abs_at = 0;
  /// `growth`: ulps allowed on top per unit of |x| (exp's product rounding); ulps records the error less it.
  void add(float x, float got, LD ref, bool absolute, double growth = 0) {
    if (std::fabs(ref) >= 0x1.ffffffp127L) ref = std::copysign(LD(INFINITY), ref);  // rounds to +-Inf
    if (std::isnan(ref) || std::isinf(ref) || std::isnan(got) || std::isinf(got)) {
      const bool same = (std::isnan(ref) && std::isnan(got)) || static_cast<LD>(got) == ref;
      if (!same) ulps = INFINITY, ulps_at = x;
      return;
    }
    const LD e = std::fabs(static_cast<LD>(got) - ref);
    if (absolute) {
      if (e > abs) abs = static_cast<double>(e), abs_at = x;
    } else if (e / ulp_of(ref) - growth * std::fabs(x) > ulps) {
      ulps = static_cast<double>(e / ulp_of(ref)) - growth * std::fabs(x), ulps_at = x;
    }
  }
};

struct Unary {
  const char* name;
  std::function<float(float)> f;
  std::function<LD(LD)> ref;
  float lo, hi;
  double max_ulps;                                    // the header's bound where judged in ulps
  double max_abs = 0;                                 // and where judged absolutely
  std::function<bool(float, LD)> absolute = nullptr;  // which samples are judged absolutely
  double growth = 0;                                  // more ulps allowed per unit of |x|
};

Worst measure(const Unary& c, std::uint32_t seed) {
  Worst w;
  for (float x : samples(c.lo, c.hi, 20000 * kScale, 20000 * kScale, seed)) {
    const LD r = c.ref(x);
    w.add(x, c.f(x), r, c.absolute && c.absolute(x, r), c.growth);
  }
  return w;
}

void expect_within(const char* name, const Worst& w, double max_ulps, double max_abs, double growth = 0) {
  std::printf("  %-30s max %.3f ulp%s (at %.9g), max abs %.3g (at %.9g)\n", name, w.ulps,
              growth ? (" + " + std::to_string(growth).substr(0, 4) + " |x|").c_str() : "", w.ulps_at, w.abs,
              w.abs_at);
  EXPECT_LE(w.ulps, max_ulps) << name << " at x = " << w.ulps_at;
  EXPECT_LE(w.abs, max_abs) << name << " at x = " << w.abs_at;
}

// Where the headers state an absolute bound: inside an interval, or where the result is small.
auto inside(float lo, float hi) {
  return [=](float x, LD) { return x >= lo && x <= hi; };
}
auto small_result(LD below) {
  return [=](float, LD r) { return std::fabs(r) < below; };
}

// exp2's reference with a flushed result below 2^-126, as the header states.
LD exp2_ref(LD x) {
  return std::exp2(x);
}

std::vector<Unary> unary_cases() {
  auto exp_error_grows = [](Unary c) {
    c.growth = 1.25;  // x * log2(e): its rounding and the constant's, through exp2
    return c;
  };
  return {
      {"exp2 [-126, 128)", [](float x) { return sh::exp2(x); }, exp2_ref, -126, 127.99999f, 3.3},
      {"log2 [FLT_MIN, FLT_MAX]", [](float x) { return sh::log2(x); }, [](LD x) { return std::log2(x); },
       FLT_MIN, FLT_MAX, 1.9, 1.8e-7, inside(0.5f, 2.0f)},
      exp_error_grows({"exp [-87.3, 88.7]", [](float x) { return sh::exp(x); },
                       [](LD x) { return std::exp(x); }, -87.3f, 88.7f, 3.4}),
      exp_error_grows(
          {"exp [-1, 1]", [](float x) { return sh::exp(x); }, [](LD x) { return std::exp(x); }, -1, 1, 3.4}),
      {"log [FLT_MIN, FLT_MAX]", [](float x) { return sh::log(x); }, [](LD x) { return std::log(x); },
       FLT_MIN, FLT_MAX, 2.5, 1.3e-7, inside(0.5f, 2.0f)},
      {"sin [-pi, pi]", [](float x) { return sh::sin(x); }, [](LD x) { return std::sin(x); }, -kPi, kPi, 1.6,
       2e-9, small_result(0x1p-5L)},
      // Beyond pi the reduction's rounded steps add up to 1.8e-11 |x| (1.2e-6 at 2^16), judged absolutely.
      {"sin [-2^16, 2^16]", [](float x) { return sh::sin(x); }, [](LD x) { return std::sin(x); }, -65536,
       65536, 0, 1.2e-6, [](float, LD) { return true; }},
      {"sin [2^16, FLT_MAX]", [](float x) { return sh::sin(x); }, [](LD x) { return std::sin(x); }, 65536,
       FLT_MAX, 1.6, 2e-9, small_result(0x1p-5L)},
      {"cos [-pi, pi]", [](float x) { return sh::cos(x); }, [](LD x) { return std::cos(x); }, -kPi, kPi, 1.6,
       2e-9, small_result(0x1p-5L)},
      {"cos [-2^16, 2^16]", [](float x) { return sh::cos(x); }, [](LD x) { return std::cos(x); }, -65536,
       65536, 0, 1.2e-6, [](float, LD) { return true; }},
      {"cos [-FLT_MAX, -2^16]", [](float x) { return sh::cos(x); }, [](LD x) { return std::cos(x); },
       -FLT_MAX, -65536, 1.6, 2e-9, small_result(0x1p-5L)},
      {"tan [-1.5, 1.5]", [](float x) { return sh::tan(x); }, [](LD x) { return std::tan(x); }, -1.5f, 1.5f,
       3.0, 3e-9, small_result(0x1p-5L)},
      {"asin [-1, 1]", [](float x) { return sh::asin(x); }, [](LD x) { return std::asin(x); }, -1, 1, 0, 4e-4,
       inside(-1, 1)},
      {"acos [-1, 1]", [](float x) { return sh::acos(x); }, [](LD x) { return std::acos(x); }, -1, 1, 0,
       1.6e-4, inside(-1, 1)},
      {"atan [-FLT_MAX, FLT_MAX]", [](float x) { return sh::atan(x); }, [](LD x) { return std::atan(x); },
       -FLT_MAX, FLT_MAX, 0, 3.3e-6, inside(-FLT_MAX, FLT_MAX)},
      exp_error_grows({"sinh [-88.7, 88.7]", [](float x) { return sh::sinh(x); },
                       [](LD x) { return std::sinh(x); }, -88.7f, 88.7f, 4, 3.2e-7, inside(-1, 1)}),
      exp_error_grows({"cosh [-88.7, 88.7]", [](float x) { return sh::cosh(x); },
                       [](LD x) { return std::cosh(x); }, -88.7f, 88.7f, 4}),
      {"tanh [-10, 10]", [](float x) { return sh::tanh(x); }, [](LD x) { return std::tanh(x); }, -10, 10, 2.7,
       1.5e-7, inside(-1, 1)},
      {"asinh [-1e18, 1e18]", [](float x) { return sh::asinh(x); }, [](LD x) { return std::asinh(x); },
       -1e18f, 1e18f, 2.7, 1.8e-7, inside(-1, 1)},
      {"acosh [1, 1e18]", [](float x) { return sh::acosh(x); }, [](LD x) { return std::acosh(x); }, 1, 1e18f,
       2.0, 1.2e-6, inside(1, 2)},
      {"atanh (-1, 1)", [](float x) { return sh::atanh(x); }, [](LD x) { return std::atanh(x); },
       -0.99999994f, 0.99999994f, 2.3, 1.3e-7, inside(-0.5f, 0.5f)},
      {"sqrt [0, FLT_MAX]", [](float x) { return sh::sqrt(x); }, [](LD x) { return std::sqrt(x); }, 0,
       FLT_MAX, 0.5},
      {"inversesqrt [FLT_MIN, FLT_MAX]", [](float x) { return sh::inversesqrt(x); },
       [](LD x) { return 1 / std::sqrt(x); }, FLT_MIN, FLT_MAX, 1.5},
      {"floor", [](float x) { return sh::floor(x); }, [](LD x) { return std::floor(x); }, -1e9f, 1e9f, 0},
      {"ceil", [](float x) { return sh::ceil(x); }, [](LD x) { return std::ceil(x); }, -1e9f, 1e9f, 0},
      {"trunc", [](float x) { return sh::trunc(x); }, [](LD x) { return std::trunc(x); }, -1e9f, 1e9f, 0},
      {"roundEven", [](float x) { return sh::roundEven(x); }, [](LD x) { return std::nearbyint(x); }, -1e9f,
       1e9f, 0},
      {"fract", [](float x) { return sh::fract(x); }, [](LD x) { return x - std::floor(x); }, -1e9f, 1e9f,
       0.5},
      {"abs", [](float x) { return sh::abs(x); }, [](LD x) { return std::fabs(x); }, -FLT_MAX, FLT_MAX, 0},
      {"sign", [](float x) { return sh::sign(x); }, [](LD x) { return LD((x > 0) - (x < 0)); }, -FLT_MAX,
       FLT_MAX, 0},
      {"modf fraction", [](float x) { return sh::modf_fraction(x); }, [](LD x) { return x - std::trunc(x); },
       -1e9f, 1e9f, 0},
      {"int_to_float(float_to_int)", [](float x) { return sh::int_to_float(sh::float_to_int(x)); },
       [](LD x) { return std::trunc(x); }, -2e9f, 2e9f, 0},
      {"uint_to_float(float_to_uint)", [](float x) { return sh::uint_to_float(sh::float_to_uint(x)); },
       [](LD x) { return std::trunc(x); }, 0, 4e9f, 0},
  };
}

class UnaryError : public testing::TestWithParam<int> {};

TEST_P(UnaryError, WithinTheStatedBound) {
  const Unary c = unary_cases()[GetParam()];
  expect_within(c.name, measure(c, 1234 + GetParam()), c.max_ulps, c.max_abs, c.growth);
}

INSTANTIATE_TEST_SUITE_P(ShaderMath, UnaryError, testing::Range(0, static_cast<int>(unary_cases().size())),
                         [](const testing::TestParamInfo<int>& info) {
                           std::string n = unary_cases()[info.param].name;
                           std::string out;
                           for (char ch : n) out += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return out;
                         });

// --- Two arguments -----------------------------------------------------------------------------------------

std::vector<std::pair<float, float>> pairs(float lo0, float hi0, float lo1, float hi1, int n,
                                           std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> a(lo0, hi0), b(lo1, hi1);
  std::uniform_int_distribution<std::int64_t> oa(order_of(lo0), order_of(hi0)),
      ob(order_of(lo1), order_of(hi1));
  std::vector<std::pair<float, float>> out;
  for (int i = 0; i < n; ++i) out.emplace_back(a(rng), b(rng));
  for (int i = 0; i < n; ++i) out.emplace_back(float_at(oa(rng)), float_at(ob(rng)));
  return out;
}

/// pow's error grows with t = y log2 x (log2's error times |y| and the product's rounding, through exp2):
/// within 3.2 + 2.1 |t| ulp, plus 2.1 |y| ulp for x in [0.5, 2] (where log2's error is absolute).
TEST(ShaderMath, PowWithinItsBound) {
  double worst_margin = -1e9, worst_e = 0;
  float wx = 0, wy = 0;
  int over = 0;
  auto check = [&](float x, float y) {
    const LD t = y * std::log2(static_cast<LD>(x));
    if (t < -126 || t >= 127.99) return;  // the result is flushed or overflows
    const LD r = std::pow(static_cast<LD>(x), static_cast<LD>(y));
    const double e = static_cast<double>(std::fabs(sh::pow(x, y) - r) / ulp_of(r));
    const double bound =
        3.2 + 2.1 * static_cast<double>(std::fabs(t)) + (x >= 0.5f && x <= 2.0f ? 2.1 * std::fabs(y) : 0);
    if (e - bound > worst_margin) worst_margin = e - bound, worst_e = e, wx = x, wy = y;
    over += e > bound;
  };
  for (auto [x, y] : pairs(0x1p-20f, 0x1p20f, -8, 8, 40000 * kScale, 7)) check(x, y);
  for (auto [x, y] : pairs(0.5f, 2.0f, -100, 100, 40000 * kScale, 8)) check(x, y);
  std::printf("  pow: closest to the bound: %.2f ulp at (%.9g, %.9g), %.2f from it\n", worst_e, wx, wy,
              -worst_margin);
  EXPECT_EQ(over, 0) << "worst: pow(" << wx << ", " << wy << ") off by " << worst_e << " ulp";
}

/// atan(y, x): absolute error at most 3.5e-6 (atan's), over every quadrant and magnitude (no denormals).
TEST(ShaderMath, Atan2WithinItsBound) {
  Worst w;
  auto add = [&](float y, float x) {
    if (std::fabs(x) < FLT_MIN || std::fabs(y) < FLT_MIN)
      return;  // 1 / a denormal overflows (see the header)
    w.add(y, sh::atan(y, x), std::atan2(LD(y), LD(x)), true);
  };
  for (auto [y, x] : pairs(-1e3f, 1e3f, -1e3f, 1e3f, 60000 * kScale, 8)) add(y, x);
  for (auto [y, x] : pairs(-FLT_MAX, FLT_MAX, -FLT_MAX, FLT_MAX, 20000 * kScale, 9)) add(y, x);
  expect_within("atan(y, x)", w, 0, 3.5e-6);
}

/// mod: x - y * floor(x / y) computed exactly, within 1 ulp of max(|x|, |y|), except where the rounded x / y
/// lands on the other side of an integer than the exact one (the defining formula then differs by y).
TEST(ShaderMath, ModWithinItsBound) {
  double worst = 0;
  int crossings = 0;
  for (auto [x, y] : pairs(-1e4f, 1e4f, -1e4f, 1e4f, 60000 * kScale, 10)) {
    if (y == 0) continue;
    const LD exact_q = static_cast<LD>(x) / y;
    if (std::floor(static_cast<LD>(x / y)) != std::floor(exact_q)) {
      ++crossings;
      continue;
    }
    const LD r = x - y * std::floor(exact_q);
    const double e = static_cast<double>(std::fabs(sh::mod(x, y) - r) /
                                         ulp_of(std::max(std::fabs(LD(x)), std::fabs(LD(y)))));
    worst = std::max(worst, e);
  }
  std::printf("  mod: %.3f ulp of max(|x|, |y|); %d quotients rounded across an integer\n", worst, crossings);
  EXPECT_LE(worst, 1.0);
}

/// mix (both forms): within 2 ulp of max(|x|, |y|) for a in [0, 1]; smoothstep: absolute error 2e-7.
TEST(ShaderMath, MixAndSmoothstepWithinTheirBounds) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> v(-1e3f, 1e3f), t(0, 1);
  double mix_worst = 0, precise_worst = 0, smooth_worst = 0;
  for (int i = 0; i < 100000 * kScale; ++i) {
    const float x = v(rng), y = v(rng), a = t(rng);
    const LD r = x + static_cast<LD>(a) * (static_cast<LD>(y) - x);
    const LD u = ulp_of(std::max(std::fabs(LD(x)), std::fabs(LD(y))));
    mix_worst = std::max(mix_worst, static_cast<double>(std::fabs(sh::mix(x, y, a) - r) / u));
    precise_worst = std::max(precise_worst, static_cast<double>(std::fabs(sh::mix_precise(x, y, a) - r) / u));
    const float e0 = v(rng) * 0.01f, e1 = e0 + t(rng) * 10 + 1e-3f, s = e0 + (e1 - e0) * t(rng) * 1.2f - 0.1f;
    LD q = (static_cast<LD>(s) - e0) / (static_cast<LD>(e1) - e0);
    q = std::min<LD>(std::max<LD>(q, 0), 1);
    smooth_worst = std::max(smooth_worst,
                            static_cast<double>(std::fabs(sh::smoothstep(e0, e1, s) - q * q * (3 - 2 * q))));
  }
  std::printf("  mix %.3f ulp, mix_precise %.3f ulp, smoothstep abs %.3g\n", mix_worst, precise_worst,
              smooth_worst);
  EXPECT_LE(mix_worst, 2.0);
  EXPECT_LE(precise_worst, 2.0);
  EXPECT_LE(smooth_worst, 2e-7);
}

// --- Special values ----------------------------------------------------------------------------------------

TEST(ShaderMath, SpecialValuesOfTheTranscendentals) {
  const float denormal = 1e-40f;
  EXPECT_TRUE(std::isnan(sh::exp2(kNaN)));
  EXPECT_EQ(sh::exp2(kInf), kInf);
  EXPECT_EQ(sh::exp2(128.0f), kInf);
  EXPECT_TRUE(same_bits(sh::exp2(-kInf), 0.0f));
  EXPECT_TRUE(same_bits(sh::exp2(-126.5f), 0.0f));  // below 2^-126: flushed
  EXPECT_EQ(sh::exp2(0.0f), 1.0f);
  EXPECT_EQ(sh::exp2(-0.0f), 1.0f);
  EXPECT_EQ(sh::exp2(10.0f), 1024.0f);
  EXPECT_EQ(sh::log2(0.0f), -kInf);
  EXPECT_EQ(sh::log2(-0.0f), -kInf);
  EXPECT_EQ(sh::log2(denormal), -kInf);
  EXPECT_EQ(sh::log2(-denormal), -kInf);
  EXPECT_TRUE(std::isnan(sh::log2(-1.0f)));
  EXPECT_TRUE(std::isnan(sh::log2(-kInf)));
  EXPECT_TRUE(std::isnan(sh::log2(kNaN)));
  EXPECT_EQ(sh::log2(kInf), kInf);
  EXPECT_EQ(sh::log2(1.0f), 0.0f);
  EXPECT_EQ(sh::log2(1024.0f), 10.0f);
  EXPECT_EQ(sh::pow(0.0f, 0.0f), 0.0f);  // lp_build_pow
  EXPECT_EQ(sh::pow(0.0f, -1.0f), 0.0f);
  EXPECT_EQ(sh::pow(kNaN, 2.0f), 0.0f);
  EXPECT_TRUE(std::isnan(sh::pow(-2.0f, 2.0f)));
  EXPECT_EQ(sh::pow(2.0f, 10.0f), 1024.0f);
  EXPECT_EQ(sh::pow(kInf, 1.0f), kInf);
  for (float x : {kNaN, kInf, -kInf}) {
    EXPECT_TRUE(std::isnan(sh::sin(x))) << x;
    EXPECT_TRUE(std::isnan(sh::cos(x))) << x;
    EXPECT_TRUE(std::isnan(sh::tan(x))) << x;
  }
  EXPECT_TRUE(same_bits(sh::sin(0.0f), 0.0f));
  EXPECT_TRUE(same_bits(sh::sin(-0.0f), -0.0f));
  EXPECT_EQ(sh::cos(0.0f), 1.0f);
  EXPECT_TRUE(same_bits(sh::sin(denormal), denormal));
  // Large arguments, exactly reduced: within 2 ulp, or 2^-24 where the result is near 0.
  for (float x : {1e4f, -1e4f, 1e6f, 1.5e9f, 1e10f, 1e20f, 1e30f, 3.4e38f, -3.4e38f, FLT_MAX, 65536.0f}) {
    for (int which = 0; which < 2; ++which) {
      const LD r = which ? std::cos(static_cast<LD>(x)) : std::sin(static_cast<LD>(x));
      const float got = which ? sh::cos(x) : sh::sin(x);
      const LD e = std::fabs(got - r);
      EXPECT_TRUE(e <= 2 * ulp_of(r) || (std::fabs(r) < 0x1p-5L && e <= 0x1p-24L))
          << (which ? "cos(" : "sin(") << x << ") = " << got << ", want " << static_cast<double>(r);
    }
  }
  EXPECT_EQ(sh::asin(1.0f), static_cast<float>(M_PI_2));
  EXPECT_TRUE(std::isnan(sh::asin(1.5f)));
  EXPECT_TRUE(std::isnan(sh::acos(-1.5f)));
  EXPECT_EQ(sh::atan(kNaN), 0.0f);  // NIR's atan: no NaN
  EXPECT_EQ(sh::atan(kInf), static_cast<float>(M_PI_2));
  EXPECT_EQ(sh::atan(-kInf), -static_cast<float>(M_PI_2));
  EXPECT_EQ(sh::atan(kInf, kInf), sh::atan(1.0f));  // |x| = |y|: atan(1), pi/4 within atan's error
  EXPECT_NEAR(sh::atan(kInf, kInf), M_PI_4, 3.5e-6);
  EXPECT_NEAR(sh::atan(-kInf, -kInf), -3 * M_PI_4, 3.5e-6);
  EXPECT_NEAR(sh::atan(0.0f, 0.0f), 3 * M_PI_4, 3.5e-6);  // nir_atan2's (0, 0)
  EXPECT_NEAR(sh::atan(-0.0f, -0.0f), -3 * M_PI_4, 3.5e-6);
  EXPECT_NEAR(sh::atan(1.0f, -1e30f), M_PI, 1e-6);
  EXPECT_NEAR(sh::atan(-1.0f, -1e30f), -M_PI, 1e-6);
  EXPECT_EQ(sh::tanh(kNaN), -1.0f);  // the clamp to [-10, 10] takes NaN to -10
  EXPECT_EQ(sh::tanh(kInf), 1.0f);
  EXPECT_EQ(sh::sinh(kInf), kInf);
  EXPECT_EQ(sh::cosh(-kInf), kInf);
  EXPECT_EQ(sh::acosh(1e30f), kInf);  // x * x overflows
  EXPECT_TRUE(std::isnan(sh::acosh(0.5f)));
  EXPECT_EQ(sh::atanh(1.0f), kInf);
  EXPECT_TRUE(std::isnan(sh::atanh(1.5f)));
}

TEST(ShaderMath, SpecialValuesOfTheCommonFunctions) {
  const float denormal = 1e-40f;
  EXPECT_TRUE(same_bits(sh::floor(-0.0f), -0.0f));
  EXPECT_TRUE(same_bits(sh::ceil(-0.5f), -0.0f));
  EXPECT_TRUE(same_bits(sh::trunc(-0.5f), -0.0f));
  EXPECT_TRUE(same_bits(sh::roundEven(-0.4f), -0.0f));
  EXPECT_EQ(sh::roundEven(2.5f), 2.0f);
  EXPECT_EQ(sh::roundEven(3.5f), 4.0f);
  EXPECT_EQ(sh::round(-2.5f), -2.0f);
  EXPECT_EQ(sh::floor(-denormal), -1.0f);
  EXPECT_TRUE(same_bits(sh::floor(denormal), 0.0f));
  for (float x : {kInf, -kInf, 3e38f, -16777217.0f}) {
    EXPECT_EQ(sh::floor(x), x);
    EXPECT_EQ(sh::ceil(x), x);
    EXPECT_EQ(sh::trunc(x), x);
    EXPECT_EQ(sh::roundEven(x), x);
  }
  EXPECT_TRUE(std::isnan(sh::floor(kNaN)));
  EXPECT_TRUE(std::isnan(sh::fract(kInf)));
  EXPECT_EQ(sh::fract(-1e-10f), 1.0f);  // x - floor(x) rounds to 1, as llvmpipe's
  EXPECT_TRUE(std::isnan(sh::mod(1.0f, 0.0f)));
  EXPECT_EQ(sh::mod(-1.0f, 3.0f), 2.0f);
  EXPECT_EQ(sh::mod(5.5f, -2.0f), -0.5f);
  EXPECT_EQ(sh::modf_whole(-2.5f), -2.0f);
  EXPECT_EQ(sh::modf_fraction(-2.5f), -0.5f);
  EXPECT_TRUE(same_bits(sh::sign(-0.0f), 0.0f));
  EXPECT_EQ(sh::sign(kNaN), 0.0f);
  EXPECT_EQ(sh::sign(-denormal), -1.0f);
  EXPECT_EQ(sh::sign(-kInf), -1.0f);
  EXPECT_EQ(sh::min(kNaN, 1.0f), 1.0f);
  EXPECT_EQ(sh::min(1.0f, kNaN), 1.0f);
  EXPECT_EQ(sh::max(kNaN, 1.0f), 1.0f);
  EXPECT_TRUE(std::isnan(sh::max(kNaN, kNaN)));
  EXPECT_TRUE(same_bits(sh::min(0.0f, -0.0f), -0.0f));  // equal operands: the second
  EXPECT_TRUE(same_bits(sh::max(-0.0f, 0.0f), 0.0f));
  EXPECT_EQ(sh::clamp(kNaN, 0.0f, 1.0f), 0.0f);
  EXPECT_EQ(sh::clamp(2.0f, 0.0f, 1.0f), 1.0f);
  EXPECT_EQ(sh::step(kNaN, 1.0f), 0.0f);
  EXPECT_EQ(sh::step(1.0f, 1.0f), 1.0f);
  EXPECT_EQ(sh::smoothstep(0.0f, 1.0f, kNaN), 0.0f);
  EXPECT_EQ(sh::smoothstep(1.0f, 1.0f, 2.0f), 1.0f);
  EXPECT_EQ(sh::mix(2.0f, 4.0f, 0.5f), 3.0f);
  EXPECT_EQ(sh::mix_unit_x(1.0f, 3.0f, 0.25f), 1.5f);
  EXPECT_EQ(sh::mix_unit_x(-1.0f, 3.0f, 0.25f), 0.0f);
  EXPECT_EQ(sh::mix(2.0f, 4.0f, sh::IntOf<float>{-1}), 4.0f);
  EXPECT_TRUE(same_bits(sh::sqrt(-0.0f), -0.0f));
  EXPECT_TRUE(std::isnan(sh::sqrt(-1.0f)));
  EXPECT_EQ(sh::inversesqrt(0.0f), kInf);
  EXPECT_EQ(sh::inversesqrt(-0.0f), -kInf);
  EXPECT_EQ(sh::inversesqrt(kInf), 0.0f);
  EXPECT_EQ(sh::isnan(kNaN), -1);
  EXPECT_EQ(sh::isnan(kInf), 0);
  EXPECT_EQ(sh::isinf(-kInf), -1);
  EXPECT_EQ(sh::isinf(FLT_MAX), 0);
  EXPECT_TRUE(std::isnan(sh::abs(-kNaN)));
  EXPECT_FALSE(std::signbit(sh::abs(-kNaN)));
  EXPECT_TRUE(same_bits(sh::abs(-0.0f), 0.0f));
}

TEST(ShaderMath, Conversions) {
  EXPECT_EQ(sh::float_to_int(kNaN), 0);
  EXPECT_EQ(sh::float_to_int(kInf), INT32_MAX);
  EXPECT_EQ(sh::float_to_int(-kInf), INT32_MIN);
  EXPECT_EQ(sh::float_to_int(3e9f), INT32_MAX);
  EXPECT_EQ(sh::float_to_int(-2147483648.0f), INT32_MIN);
  EXPECT_EQ(sh::float_to_int(2147483520.0f), 2147483520);
  EXPECT_EQ(sh::float_to_int(-2.9f), -2);
  EXPECT_EQ(sh::float_to_int(-0.5f), 0);
  EXPECT_EQ(sh::float_to_uint(kNaN), 0u);
  EXPECT_EQ(sh::float_to_uint(-1.0f), 0u);
  EXPECT_EQ(sh::float_to_uint(-0.9f), 0u);
  EXPECT_EQ(sh::float_to_uint(-kInf), 0u);
  EXPECT_EQ(sh::float_to_uint(kInf), UINT32_MAX);
  EXPECT_EQ(sh::float_to_uint(4294967296.0f), UINT32_MAX);
  EXPECT_EQ(sh::float_to_uint(4294967040.0f), 4294967040u);
  EXPECT_EQ(sh::float_to_uint(2147483648.0f), 2147483648u);
  EXPECT_EQ(sh::float_to_uint(3.9f), 3u);
  // Int and uint to float: rounded once, to nearest even, like the hardware conversion.
  std::mt19937 rng(12);
  for (int i = 0; i < 200000; ++i) {
    const std::uint32_t u = i < 64 ? (1u << (i % 32)) + (i / 32) * 0x7fu : rng();
    ASSERT_TRUE(same_bits(sh::uint_to_float(u), static_cast<float>(u))) << u;
    const auto s = static_cast<std::int32_t>(u);
    ASSERT_TRUE(same_bits(sh::int_to_float(s), static_cast<float>(s))) << s;
  }
  // Float to int against the definition, over the floats' order.
  for (float x : samples(-5e9f, 5e9f, 0, 100000, 13)) {
    const LD t = std::trunc(static_cast<LD>(x));
    const auto want_i = static_cast<std::int32_t>(std::clamp<LD>(t, INT32_MIN, INT32_MAX));
    const auto want_u = static_cast<std::uint32_t>(std::clamp<LD>(t, 0, UINT32_MAX));
    ASSERT_EQ(sh::float_to_int(x), want_i) << x;
    ASSERT_EQ(sh::float_to_uint(x), want_u) << x;
  }
}

TEST(ShaderMath, PlumbingMasksAndSelects) {
  EXPECT_EQ(sh::lt(1.0f, 2.0f), -1);
  EXPECT_EQ(sh::lt(kNaN, 2.0f), 0);
  EXPECT_EQ(sh::ge(kNaN, kNaN), 0);
  EXPECT_EQ(sh::ne(kNaN, kNaN), -1);
  EXPECT_EQ(sh::eq(0.0f, -0.0f), -1);
  EXPECT_EQ(sh::select(-1, 1.0f, 2.0f), 1.0f);
  EXPECT_EQ(sh::select(0, 1.0f, 2.0f), 2.0f);
  EXPECT_EQ(sh::select(-1, 7, 9), 7);
  EXPECT_EQ(sh::as_int(1.0f), 0x3f800000);
  EXPECT_EQ(sh::as_uint(-0.0f), 0x80000000u);
  EXPECT_EQ(sh::as_float(0x3f800000), 1.0f);
  const FloatLanes v = sh::splat<FloatLanes>(2.0f);
  const sh::IntLanes m = sh::lt(v, FloatLanes{0, 1, 2, 3, 4, 5, 6, kNaN});
  const sh::IntLanes want = {0, 0, 0, -1, -1, -1, -1, 0};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(m[i], want[i]) << i;
  const FloatLanes s = sh::select(m, v, sh::splat<FloatLanes>(5.0f));
  for (int i = 0; i < 8; ++i) EXPECT_EQ(s[i], want[i] ? 2.0f : 5.0f) << i;
  static_assert(std::is_same_v<sh::IntOf<FloatLanes>, sh::IntLanes>);
  static_assert(std::is_same_v<sh::UIntOf<float>, std::uint32_t>);
}

// --- One lane, SSE2 eight lanes and AVX2 eight lanes give the same bits ------------------------------------

// Each function as a callable that is inlined where it is called (so into the AVX2 function below too).
#define UNARY_OP(Name, expr)                            \
  struct Name {                                         \
    static constexpr const char* name = #Name;          \
    template <class F>                                  \
    [[gnu::always_inline]] F operator()(F x, F) const { \
      return expr;                                      \
    }                                                   \
  };
#define BINARY_OP(Name, expr)                             \
  struct Name {                                           \
    static constexpr const char* name = #Name;            \
    template <class F>                                    \
    [[gnu::always_inline]] F operator()(F x, F y) const { \
      return expr;                                        \
    }                                                     \
  };
UNARY_OP(Exp2, sh::exp2(x))
UNARY_OP(Log2, sh::log2(x))
UNARY_OP(Exp, sh::exp(x))
UNARY_OP(Log, sh::log(x))
BINARY_OP(Pow, sh::pow(x, y))
UNARY_OP(Sin, sh::sin(x))
UNARY_OP(Cos, sh::cos(x))
UNARY_OP(Tan, sh::tan(x))
UNARY_OP(Asin, sh::asin(x))
UNARY_OP(Acos, sh::acos(x))
UNARY_OP(Atan, sh::atan(x))
BINARY_OP(Atan2, sh::atan(x, y))
UNARY_OP(Sinh, sh::sinh(x))
UNARY_OP(Cosh, sh::cosh(x))
UNARY_OP(Tanh, sh::tanh(x))
UNARY_OP(Asinh, sh::asinh(x))
UNARY_OP(Acosh, sh::acosh(x))
UNARY_OP(Atanh, sh::atanh(x))
UNARY_OP(Sqrt, sh::sqrt(x))
UNARY_OP(Inversesqrt, sh::inversesqrt(x))
UNARY_OP(Floor, sh::floor(x))
UNARY_OP(Ceil, sh::ceil(x))
UNARY_OP(Trunc, sh::trunc(x))
UNARY_OP(RoundEven, sh::roundEven(x))
UNARY_OP(Fract, sh::fract(x))
BINARY_OP(Mod, sh::mod(x, y))
BINARY_OP(Min, sh::min(x, y))
BINARY_OP(Max, sh::max(x, y))
BINARY_OP(Clamp, sh::clamp(x, y, y + 1.0f))
BINARY_OP(Mix, sh::mix(x, y, x * 0.25f))
BINARY_OP(MixPrecise, sh::mix_precise(x, y, y * 0.5f))
BINARY_OP(MixUnitX, sh::mix_unit_x(sh::sign(x), y, x))
BINARY_OP(Step, sh::step(x, y))
BINARY_OP(Smoothstep, sh::smoothstep(x, y, x* y))
UNARY_OP(Abs, sh::abs(x))
UNARY_OP(Sign, sh::sign(x))
UNARY_OP(ModfFraction, sh::modf_fraction(x))
UNARY_OP(IsNanInf, sh::as_float(sh::isnan(x) ^ (sh::isinf(x) & 2)))
UNARY_OP(ToInt, sh::as_float(sh::float_to_int(x)))
UNARY_OP(ToUint, sh::as_float(sh::float_to_uint(x)))
UNARY_OP(FromInt, sh::int_to_float(sh::as_int(x)))
UNARY_OP(FromUint, sh::uint_to_float(sh::as_uint(x)))
BINARY_OP(FusedMulAdd, sh::lane_detail::fused_mul_add(x, y, x * -0.75f))

template <class Op>
void eight_generic(const float* x, const float* y, float* out) {
  FloatLanes a, b;
  std::memcpy(&a, x, sizeof a);
  std::memcpy(&b, y, sizeof b);
  const FloatLanes r = Op{}(a, b);
  std::memcpy(out, &r, sizeof r);
}
template <class Op>
__attribute__((target("avx2"))) void eight_avx2(const float* x, const float* y, float* out) {
  FloatLanes a, b;
  std::memcpy(&a, x, sizeof a);
  std::memcpy(&b, y, sizeof b);
  const FloatLanes r = Op{}(a, b);
  std::memcpy(out, &r, sizeof r);
}

/// Random floats of every kind: the specials, denormals, small and huge magnitudes, the usual range.
std::vector<float> identity_inputs(std::uint32_t seed, int n) {
  const float specials[] = {0.0f,     -0.0f,   kNaN,     -kNaN, kInf,   -kInf,  1e-40f, -1e-40f,
                            FLT_MIN,  FLT_MAX, -FLT_MAX, 1.0f,  -1.0f,  0.5f,   2.5f,   -2.5f,
                            65536.0f, 3.4e38f, 1e4f,     1e6f,  128.0f, -127.0f};
  std::mt19937 rng(seed);
  std::vector<float> v(std::begin(specials), std::end(specials));
  std::uniform_real_distribution<float> near(-10, 10);
  while (static_cast<int>(v.size()) < n) {
    const std::uint32_t k = rng() % 4;
    v.push_back(k == 0   ? std::bit_cast<float>(static_cast<std::uint32_t>(rng()))
                : k == 1 ? specials[rng() % std::size(specials)]
                         : near(rng));
  }
  return v;
}

template <class... Ops>
void expect_same_bits_everywhere(bool avx2) {
  const int n = 4096;
  const std::vector<float> xs = identity_inputs(21, n), ys = identity_inputs(22, n);
  (
      [&] {
        using Op = Ops;
        int differ_generic = 0, differ_avx2 = 0, payloads = 0;
        float out8[8], out_avx[8];
        // Bits, except a NaN's payload: where two NaNs meet in one operation IEEE lets the operand order pick
        // it, and compilers order commutative operands as they like (so do the interpreter's operators).
        auto differ = [&](float a, float b) {
          if (std::isnan(a) && std::isnan(b)) {
            payloads += !same_bits(a, b);
            return false;
          }
          return !same_bits(a, b);
        };
        for (int i = 0; i < n; i += 8) {
          eight_generic<Op>(&xs[i], &ys[i], out8);
          if (avx2) eight_avx2<Op>(&xs[i], &ys[i], out_avx);
          for (int k = 0; k < 8; ++k) {
            const float one = Op{}(xs[i + k], ys[i + k]);
            differ_generic += differ(one, out8[k]);
            differ_avx2 += avx2 && differ(one, out_avx[k]);
          }
        }
        EXPECT_EQ(differ_generic, 0) << Op::name << ": one lane against eight (SSE2)";
        EXPECT_EQ(differ_avx2, 0) << Op::name << ": one lane against eight (AVX2)";
        if (payloads) std::printf("  %s: %d NaNs with another payload\n", Op::name, payloads);
      }(),
      ...);
}

TEST(ShaderMath, OneLaneAndEightLanesGiveTheSameBits) {
  expect_same_bits_everywhere<Exp2, Log2, Exp, Log, Pow, Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Sinh, Cosh,
                              Tanh, Asinh, Acosh, Atanh, Sqrt, Inversesqrt, Floor, Ceil, Trunc, RoundEven,
                              Fract, Mod, Min, Max, Clamp, Mix, MixPrecise, MixUnitX, Step, Smoothstep, Abs,
                              Sign, ModfFraction, IsNanInf, ToInt, ToUint, FromInt, FromUint, FusedMulAdd>(
      false);
}

TEST(ShaderMath, AvxTwoGivesTheSameBits) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "no AVX2 here";
  expect_same_bits_everywhere<Exp2, Log2, Exp, Log, Pow, Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Sinh, Cosh,
                              Tanh, Asinh, Acosh, Atanh, Sqrt, Inversesqrt, Floor, Ceil, Trunc, RoundEven,
                              Fract, Mod, Min, Max, Clamp, Mix, MixPrecise, MixUnitX, Step, Smoothstep, Abs,
                              Sign, ModfFraction, IsNanInf, ToInt, ToUint, FromInt, FromUint>(true);
}

}  // namespace
