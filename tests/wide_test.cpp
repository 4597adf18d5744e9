// The wide integers behind exact coverage at huge coordinates, checked against __int128 where both fit
// and against identities where only Wide does; then huge triangles against a per-pixel exact reference.
#include <gtest/gtest.h>

#include <random>

#include "base/wide.h"
#include "geometry/geometry.h"
#include "support.h"

namespace {

using raster::Point2;
using raster::detail::floor_div_clamped;
using raster::detail::Wide;

Wide from_i128(__int128 v) {
  const bool neg = v < 0;
  unsigned __int128 m = neg ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
  Wide w = Wide(static_cast<std::int64_t>(m >> 64)) * Wide(INT64_C(1) << 32) * Wide(INT64_C(1) << 32) +
           Wide(static_cast<std::int64_t>(m & 0xffffffff)) +
           Wide(static_cast<std::int64_t>((m >> 32) & 0xffffffff)) * Wide(INT64_C(1) << 32);
  return neg ? -w : w;
}

TEST(Wide, ArithmeticMatchesInt128) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 20000; ++i) {
    const __int128 a = static_cast<std::int64_t>(rng()) >> (rng() % 40),
                   b = static_cast<std::int64_t>(rng()) >> (rng() % 40);
    ASSERT_EQ(from_i128(a) + from_i128(b), from_i128(a + b));
    ASSERT_EQ(from_i128(a) - from_i128(b), from_i128(a - b));
    ASSERT_EQ(from_i128(a) * from_i128(b), from_i128(a * b));
    ASSERT_EQ(from_i128(a) < from_i128(b), a < b);
    ASSERT_EQ(from_i128(a * b).negative(), a * b < 0);
    ASSERT_DOUBLE_EQ(from_i128(a * b).to_double(), static_cast<double>(a * b));
  }
}

TEST(Wide, FromDoubleIsExactForIntegralValues) {
  for (double d : {0.0, 1.0, -1.0, 0x1p52, -0x1p53 - 2, 0x1p62, 0x1p63, -0x1p100 * 3, 0x1p136, -0x1p200}) {
    const Wide w = Wide::from_double(d);
    EXPECT_EQ(w.to_double(), d);
    EXPECT_EQ(w.negative(), d < 0);
    EXPECT_EQ(w - Wide::from_double(d), Wide(0));
  }
  // 2^200 + 2^148 is exactly representable; its difference from 2^200 is exactly 2^148.
  EXPECT_EQ(Wide::from_double(0x1p200 + 0x1p148) - Wide::from_double(0x1p200), Wide::from_double(0x1p148));
  // Products far beyond 128 bits keep their low bits: (2^136 + 1)^2 - 2^272 - 2^137 = 1.
  const Wide big = Wide::from_double(0x1p136) + Wide(1);
  EXPECT_EQ(big * big - Wide::from_double(0x1p136) * Wide::from_double(0x1p136) - Wide::from_double(0x1p137),
            Wide(1));
}

TEST(Wide, FloorDivisionClampedIsExact) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 20000; ++i) {
    const __int128 d = static_cast<__int128>((rng() >> (rng() % 60)) | 1);
    const __int128 n = static_cast<__int128>(static_cast<std::int64_t>(rng())) *
                       static_cast<std::int64_t>(rng() >> (rng() % 64));
    __int128 q = n / d;
    if (n % d != 0 && n < 0) --q;
    const std::int64_t expect = q < -1000 ? -1000 : q > 1000 ? 1000 : static_cast<std::int64_t>(q);
    ASSERT_EQ(floor_div_clamped(from_i128(n), from_i128(d), -1000, 1000), expect);
    ASSERT_EQ(floor_div_clamped(n, d, -1000, 1000), expect);
  }
  // Quotients near the clamp boundaries, exactly.
  const Wide d = Wide::from_double(0x1p130) + Wide(3);
  EXPECT_EQ(floor_div_clamped(d * Wide(7), d, -10, 10), 7);
  EXPECT_EQ(floor_div_clamped(d * Wide(7) - Wide(1), d, -10, 10), 6);
  EXPECT_EQ(floor_div_clamped(-(d * Wide(7)) - Wide(1), d, -10, 10), -8);
}

// Exact per-pixel reference for any coordinates: the literal top-left rule on Wide orientations.
std::vector<std::uint8_t> wide_reference(const Point2 (&p)[3], int w, int h) {
  auto snap = [](double v) { return raster::detail::snap(v); };
  Wide x[3], y[3];
  for (int k = 0; k < 3; ++k) x[k] = Wide::from_double(snap(p[k].x)), y[k] = Wide::from_double(snap(p[k].y));
  auto orient = [&](int a, int b, const Wide& px, const Wide& py) {
    return (x[b] - x[a]) * (py - y[a]) - (y[b] - y[a]) * (px - x[a]);
  };
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(w) * h, 0);
  const Wide area = orient(0, 1, x[2], y[2]);
  if (area == Wide(0)) return mask;
  const int sign = area.negative() ? -1 : 1;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const Wide px(i * 256 + 128), py(j * 256 + 128);
      bool in = true;
      for (int k = 0; k < 3 && in; ++k) {
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        Wide e = orient(a, b, px, py);
        if (sign < 0) e = -e;
        // top-left, stated geometrically for the positive orientation: horizontal with the interior below,
        // or the interior to the right (edge running up in y-down space)
        const Wide dy = sign > 0 ? y[b] - y[a] : y[a] - y[b];
        const Wide dx = sign > 0 ? x[b] - x[a] : x[a] - x[b];
        const bool top_left = dy.negative() || (dy == Wide(0) && Wide(0) < dx);
        in = Wide(0) < e || (e == Wide(0) && top_left);
      }
      mask[static_cast<std::size_t>(j) * w + i] = in;
    }
  return mask;
}

TEST(Wide, HugeTrianglesMatchTheExactReference) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  int covered = 0;
  for (int t = 0; t < 400; ++t) {
    Point2 p[3];
    for (auto& q : p) {
      const double mag = std::pow(10.0, 4.5 + unit(rng) * 33.5);  // 3e4 .. 1e38
      q = unit(rng) < 0.3 ? Point2{unit(rng) * 40, unit(rng) * 30}
                          : Point2{(unit(rng) - 0.5) * mag, (unit(rng) - 0.5) * mag};
    }
    const auto got = test::mask_not(
        test::render(test::SceneBuilder(40, 30).triangle(p[0], p[1], p[2], test::kWhite).scene),
        test::kBlack);
    const auto want = wide_reference(p, 40, 30);
    ASSERT_EQ(got, want) << "triangle " << t;
    for (auto m : got) covered += m;
  }
  EXPECT_GT(covered, 20000) << "the suite must cover pixels, not only miss the image";
}

}  // namespace
