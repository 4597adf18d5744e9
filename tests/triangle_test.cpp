// Triangle coverage: the GPU rules (1/256 snapping, pixel centres, top-left), watertight shared edges,
// exact colour interpolation, and a differential test against the literal reference in reference.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "reference.h"
#include "support.h"

namespace {

using raster::Point2;
using test::kBlack;
using test::kWhite;
using test::SceneBuilder;

constexpr raster::Rgba8 kHalfWhite{255, 255, 255, 128};

// D3D's documented example: a 5x5 square split along its diagonal. The diagonal's pixel centres lie on
// the shared edge; it is a left edge of the first triangle only, so it gets 15 pixels and the other 10.
TEST(Triangle, D3DSquareSplitCovers15And10) {
  auto a = test::render(SceneBuilder(8, 8).triangle({0, 0}, {5, 0}, {5, 5}, kWhite).scene);
  auto b = test::render(SceneBuilder(8, 8).triangle({0, 5}, {0, 0}, {5, 5}, kWhite).scene);
  EXPECT_EQ(test::count_not(a, kBlack), 15);
  EXPECT_EQ(test::count_not(b, kBlack), 10);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(test::pixel(a, i, i), kWhite) << "diagonal pixel " << i << " belongs to the left-edge triangle";
    EXPECT_EQ(test::pixel(b, i, i), kBlack);
  }
}

// Centres exactly on an edge: covered for left and top edges, not for right and bottom edges.
TEST(Triangle, TopLeftRuleOnAxisAlignedEdges) {
  // Rectangle x in [0.5, 4.5], y in [0.5, 3.5] as two triangles: centres of column 0 and row 0 lie on the
  // left and top edges (covered); column 4 and row 3 lie on the right and bottom edges (not covered).
  SceneBuilder s(8, 8);
  s.triangle({0.5, 0.5}, {4.5, 0.5}, {4.5, 3.5}, kWhite).triangle({0.5, 0.5}, {4.5, 3.5}, {0.5, 3.5}, kWhite);
  auto img = test::render(s.scene);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool expect = x >= 0 && x <= 3 && y >= 0 && y <= 2;
      EXPECT_EQ(test::pixel(img, x, y) == kWhite, expect) << x << "," << y;
    }
}

// Vertices snap to 1/256 px: an edge 1/1024 px right of a centre snaps onto it (right edge: excluded),
// one full sub-pixel step right of it does not (covered).
TEST(Triangle, VerticesSnapToEightSubpixelBits) {
  auto with_right_edge_at = [](double x) {
    SceneBuilder s(8, 4);
    s.triangle({0, 0}, {x, 0}, {x, 4}, kWhite).triangle({0, 0}, {x, 4}, {0, 4}, kWhite);
    return test::pixel(test::render(s.scene), 3, 1);
  };
  EXPECT_EQ(with_right_edge_at(3.5 + 1.0 / 1024), kBlack)
      << "snapped onto the centre: right edge excludes it";
  EXPECT_EQ(with_right_edge_at(3.5 + 1.0 / 256), kWhite) << "one sub-pixel step past the centre covers it";
  EXPECT_EQ(with_right_edge_at(3.5 - 1.0 / 256), kBlack);
}

// Snapping rounds half up (floor(256 x + 1/2)), not half away from zero: only that is invariant under
// translation. Here a vertex at y = -100 - 1/512 must snap to exactly -100, keeping the edge through the
// diagonal's pixel centres, where the left-edge rule includes them; rounding away from zero would move the
// edge 1/256 px and drop the whole diagonal.
TEST(Triangle, SnappingRoundsHalfUpAlsoForNegativeCoordinates) {
  auto tie = test::render(
      SceneBuilder(32, 32).triangle({-100, -100 - 1.0 / 512}, {60, 60}, {60, -100}, kWhite).scene);
  auto exact = test::render(SceneBuilder(32, 32).triangle({-100, -100}, {60, 60}, {60, -100}, kWhite).scene);
  EXPECT_EQ(tie.pixels, exact.pixels);
  for (int i = 0; i < 32; ++i) EXPECT_EQ(test::pixel(tie, i, i), kWhite) << i;
}

TEST(Triangle, BothWindingsCoverTheSamePixels) {
  auto cw = test::render(SceneBuilder(32, 32).triangle({3.2, 1.7}, {29.1, 9.3}, {11.6, 30.2}, kWhite).scene);
  auto ccw = test::render(SceneBuilder(32, 32).triangle({3.2, 1.7}, {11.6, 30.2}, {29.1, 9.3}, kWhite).scene);
  EXPECT_GT(test::count_not(cw, kBlack), 200);
  EXPECT_EQ(cw.pixels, ccw.pixels);
}

TEST(Triangle, DegenerateTrianglesDrawNothing) {
  SceneBuilder s(16, 16);
  s.triangle({1, 1}, {8, 8}, {15, 15}, kWhite)               // collinear through pixel centres' diagonal
      .triangle({4.5, 4.5}, {4.5, 4.5}, {4.5, 4.5}, kWhite)  // a point on a centre
      .triangle({2, 2}, {9, 2}, {2, 2}, kWhite);             // repeated vertex
  EXPECT_EQ(test::count_not(test::render(s.scene), kBlack), 0);
}

// An asymmetric shape with distinct red/green/blue corners: a flip, transpose or channel swap fails.
TEST(Triangle, CornersKeepTheirColoursAndPlaces) {
  SceneBuilder s(64, 48);
  s.triangle({2, 2}, {60, 6}, {10, 45}, test::kRed, test::kGreen, test::kBlue);
  auto img = test::render(s.scene);
  auto near = [&](int x, int y) { return test::pixel(img, x, y); };
  EXPECT_GT(near(4, 4).r, 200);
  EXPECT_LT(near(4, 4).g, 40);
  EXPECT_GT(near(56, 7).g, 200);
  EXPECT_LT(near(56, 7).r, 40);
  EXPECT_GT(near(10, 42).b, 200);
  EXPECT_LT(near(10, 42).g, 40);
  EXPECT_EQ(near(60, 40), kBlack);  // the empty corner stays background
}

// Interpolated colours are convex combinations: they never leave the vertex range, even on slivers
// (aspect ratio ~1e6) where a float formulation drifts.
TEST(Triangle, SliverColoursStayInTheVertexRange) {
  const raster::Rgba8 lo{40, 90, 10, 255}, mid{41, 91, 200, 255}, hi{42, 92, 255, 255};
  SceneBuilder s(512, 8);
  s.triangle({0.1, 3.5}, {511.9, 3.5 + 1e-4}, {200, 4.6}, lo, mid, hi);
  s.triangle({0.1, 3.5}, {200, 4.6}, {511.9, 3.5 + 2e-6}, hi, lo, mid);
  auto img = test::render(s.scene);
  int covered = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 512; ++x) {
      const auto c = test::pixel(img, x, y);
      if (c == kBlack) continue;
      ++covered;
      ASSERT_GE(c.r, 40);
      ASSERT_LE(c.r, 42);
      ASSERT_GE(c.g, 90);
      ASSERT_LE(c.g, 92);
      ASSERT_GE(c.b, 10);
    }
  EXPECT_GT(covered, 100);
}

// Watertightness as the conformance suites test it: translucent white over black; a pixel hit twice is
// brighter than 128, a hole stays 0. Every pixel centre strictly inside the union must read 128.
void expect_single_coverage(const raster::Image& img, int x0, int y0, int x1, int y1) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) ASSERT_EQ(test::pixel(img, x, y).r, 128) << "pixel " << x << "," << y;
}

// The smooth span writer packs several pixels per store; on any background, what it covers must be exactly
// what the flat writer covers, and every byte outside stays the background's (RGB and RGBA formats).
TEST(Triangle, SmoothSpansWriteExactlyTheirPixels) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> pos(-20, 120), size(0.5, 90);
  int checked = 0;  // triangles drawn by the packed writer (RGB or RGBA)
  for (raster::Rgba8 background : {raster::Rgba8{255, 255, 255, 255}, raster::Rgba8{255, 255, 255, 0}}) {
    for (int i = 0; i < 300; ++i) {
      const double cx = pos(rng), cy = pos(rng), r = size(rng);
      std::uniform_real_distribution<double> d(-r, r);
      const Point2 a{cx + d(rng), cy + d(rng)}, b{cx + d(rng), cy + d(rng)}, c{cx + d(rng), cy + d(rng)};
      auto colour = [&] {
        return raster::Rgba8{static_cast<std::uint8_t>(rng() % 200), static_cast<std::uint8_t>(rng() % 200),
                             static_cast<std::uint8_t>(rng() % 200), 255};
      };
      SceneBuilder flat(101, 67, background), smooth(101, 67, background);
      flat.triangle(a, b, c, test::kBlack);
      smooth.triangle(a, b, c, colour(), colour(), colour());
      const auto flat_image = test::render(flat.scene), smooth_image = test::render(smooth.scene);
      if (smooth_image.channels() < 3) continue;  // off the image: planned grey, nothing drawn
      ++checked;
      for (int y = 0; y < 67; ++y)
        for (int x = 0; x < 101; ++x) {
          const bool covered = test::pixel(flat_image, x, y) != background;
          const bool untouched = test::pixel(smooth_image, x, y) == background;
          ASSERT_NE(covered, untouched) << "pixel " << x << "," << y << " of triangle " << i;
        }
    }
  }
  EXPECT_GT(checked, 300);
}

TEST(Triangle, JitteredGridIsWatertight) {
  constexpr int n = 24, cell = 5;
  std::mt19937 rng(7);
  // +-1 px on a 5 px cell keeps every quad convex (3 x 1.41 < 5 / sqrt 2), so no two triangles overlap
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);
  std::vector<Point2> grid((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      grid[j * (n + 1) + i] = {4.0 + i * cell + (border ? 0 : jitter(rng)),
                               4.0 + j * cell + (border ? 0 : jitter(rng))};
    }
  SceneBuilder s(n * cell + 8, n * cell + 8);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Point2 a = grid[j * (n + 1) + i], b = grid[j * (n + 1) + i + 1];
      const Point2 c = grid[(j + 1) * (n + 1) + i], d = grid[(j + 1) * (n + 1) + i + 1];
      // alternate the diagonal and the winding so every edge orientation occurs
      if ((i + j) % 2) {
        s.triangle(a, b, d, kHalfWhite).triangle(a, c, d, kHalfWhite);
      } else {
        s.triangle(a, b, c, kHalfWhite).triangle(b, d, c, kHalfWhite);
      }
    }
  expect_single_coverage(test::render(s.scene), 4, 4, 4 + n * cell, 4 + n * cell);
}

TEST(Triangle, ThousandSliceFanIsWatertight) {
  // 1000 slivers around a centre on a pixel corner; every pixel well inside the circle is hit once.
  SceneBuilder s(128, 128);
  const Point2 c{64, 64};
  const int slices = 1000;
  const double r = 60;
  for (int k = 0; k < slices; ++k) {
    const double t0 = 2 * M_PI * k / slices, t1 = 2 * M_PI * (k + 1) / slices;
    s.triangle(c, {c.x + r * std::cos(t0), c.y + r * std::sin(t0)},
               {c.x + r * std::cos(t1), c.y + r * std::sin(t1)}, kHalfWhite);
  }
  auto img = test::render(s.scene);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const double dx = x + 0.5 - c.x, dy = y + 0.5 - c.y;
      if (dx * dx + dy * dy < 58 * 58) {
        ASSERT_EQ(test::pixel(img, x, y).r, 128) << x << "," << y;
      }
    }
}

// The production rasterizer (blocks in tiles, corner accept/reject, SIMD lanes) against the literal reference
// on seeded random triangles of every size and position: zero mismatching pixels, colours within 1/255.
TEST(Triangle, MatchesExactReferenceOnRandomTriangles) {
  constexpr int w = 48, h = 40;
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> unit(0, 1);
  int mismatches = 0, compared = 0;
  double worst_colour = 0;
  for (int t = 0; t < 10000; ++t) {
    // sizes from sub-pixel to several times the image, centred anywhere in and around it
    const double size = std::pow(10.0, -1.5 + unit(rng) * 4.0);
    const double cx = -20 + unit(rng) * (w + 40), cy = -20 + unit(rng) * (h + 40);
    Point2 p[3];
    for (auto& q : p) q = {cx + (unit(rng) - 0.5) * size, cy + (unit(rng) - 0.5) * size};
    if (t % 7 == 0) p[1].y = p[0].y;   // exact horizontal edges exercise the top rule
    if (t % 11 == 0) p[2].x = p[1].x;  // exact vertical edges exercise the left rule
    const raster::Rgba8 c0{255, 0, 30, 255}, c1{0, 255, 60, 255}, c2{10, 20, 255, 255};
    auto img = test::render(
        SceneBuilder(w, h, raster::Rgba8{0, 0, 0, 255}).triangle(p[0], p[1], p[2], c0, c1, c2).scene);
    const auto expect = ref::triangle(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y, w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        const auto got = test::pixel(img, x, y);
        const bool covered = !(got == raster::Rgba8{0, 0, 0, 255});
        if (covered != (expect.mask[i] != 0)) {
          ++mismatches;
          continue;
        }
        if (!covered) continue;
        ++compared;
        const double* b = &expect.bary[i * 3];
        const double er = b[0] * c0.r + b[1] * c1.r + b[2] * c2.r,
                     eg = b[0] * c0.g + b[1] * c1.g + b[2] * c2.g;
        worst_colour = std::max({worst_colour, std::abs(got.r - er), std::abs(got.g - eg)});
      }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(compared, 50000) << "the random suite must actually cover pixels";
  EXPECT_LT(worst_colour, 1.0) << "colours within 1/255 of the exact barycentric value";
}

// Rotating the vertex order, reversing the winding and translating by whole pixels give the same set.
TEST(Triangle, InvariantUnderVertexOrderWindingAndTranslation) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(2, 30);
  for (int t = 0; t < 300; ++t) {
    const Point2 a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)}, c{coord(rng), coord(rng)};
    const auto base =
        test::mask_not(test::render(SceneBuilder(64, 64).triangle(a, b, c, kWhite).scene), kBlack);
    EXPECT_EQ(base,
              test::mask_not(test::render(SceneBuilder(64, 64).triangle(b, c, a, kWhite).scene), kBlack));
    EXPECT_EQ(base,
              test::mask_not(test::render(SceneBuilder(64, 64).triangle(c, b, a, kWhite).scene), kBlack));
    const int dx = 17, dy = 23;
    const auto moved = test::mask_not(
        test::render(SceneBuilder(64, 64)
                         .triangle({a.x + dx, a.y + dy}, {b.x + dx, b.y + dy}, {c.x + dx, c.y + dy}, kWhite)
                         .scene),
        kBlack);
    for (int y = 0; y + dy < 64; ++y)
      for (int x = 0; x + dx < 64; ++x) ASSERT_EQ(base[y * 64 + x], moved[(y + dy) * 64 + x + dx]) << t;
  }
}

// Vertices beyond the fixed-point range take the exact wide-integer path (no floating-point clipping): the
// visible part is exact (compare with the same half-plane drawn with image-sized coordinates).
TEST(Triangle, HugeCoordinatesCoverExactlyTheRightPixels) {
  for (double big : {1e4, 1e6, 1e9, 1e30, 3.4e38}) {
    // A half-plane y >= x (below the diagonal), drawn as one giant triangle.
    auto img =
        test::render(SceneBuilder(32, 32).triangle({-big, -big}, {big, big}, {-big, big}, kWhite).scene);
    auto small = test::render(SceneBuilder(32, 32).triangle({-64, -64}, {64, 64}, {-64, 64}, kWhite).scene);
    EXPECT_EQ(img.pixels, small.pixels) << big;
    EXPECT_EQ(test::count_not(img, kBlack), 32 * 31 / 2) << big;  // the diagonal is a right edge: excluded
  }
}

TEST(Triangle, SharedEdgeReachingFarOutsideStaysWatertight) {
  // Two triangles share the edge A-B, whose far end A lies way outside the fixed-point range; C1 is above the
  // edge's line and C2 below it, so they do not overlap and both reach into the image.
  const Point2 a{-5e7, -3e7}, b{70.3, 40.1}, c1{60.5, -10.2}, c2{-10.7, 70.3};
  SceneBuilder s(64, 64);
  s.triangle(a, b, c1, kHalfWhite).triangle(a, c2, b, kHalfWhite);
  auto img = test::render(s.scene);
  int both = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const auto v = test::pixel(img, x, y).r;
      ASSERT_TRUE(v == 0 || v == 128) << "double hit or gap at " << x << "," << y;
      both += v == 128;
    }
  EXPECT_GT(both, 500);
}

}  // namespace
