// Lines: symmetric Bresenham between the pixels that contain the endpoints, both endpoints drawn,
// clipped to the image before stepping; polylines draw their joints once.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "reference.h"
#include "support.h"

namespace {

using raster::Point2;
using test::kBlack;
using test::kWhite;
using test::SceneBuilder;

std::vector<std::uint8_t> line_mask(Point2 a, Point2 b, int w = 100, int h = 100) {
  return test::mask_not(test::render(SceneBuilder(w, h).line(a, b, kWhite).scene), kBlack);
}

// tinyrenderer lesson 1: (13,20)-(80,40), (20,13)-(40,80), and (80,40)-(13,20) drawn over the first.
TEST(Line, TinyrendererLessonOneLines) {
  const auto a = line_mask({13, 20}, {80, 40});
  const auto b = line_mask({20, 13}, {40, 80});
  const auto back = line_mask({80, 40}, {13, 20});
  EXPECT_EQ(a, back) << "a line and its reverse cover the same pixels";
  int na = 0, nb = 0;
  for (auto m : a) na += m;
  for (auto m : b) nb += m;
  EXPECT_EQ(na, 80 - 13 + 1) << "x-major: one pixel per column, both endpoints";
  EXPECT_EQ(nb, 80 - 13 + 1) << "y-major: one pixel per row, both endpoints";
  EXPECT_TRUE(a[20 * 100 + 13] && a[40 * 100 + 80]);
  EXPECT_TRUE(b[13 * 100 + 20] && b[80 * 100 + 40]);
  // Each column of the x-major line holds the row nearest the exact line (ties toward larger rows).
  for (int x = 13; x <= 80; ++x) {
    const double exact = 20 + (x - 13) * 20.0 / 67.0;
    const int row = static_cast<int>(std::floor(exact + 0.5));
    EXPECT_TRUE(a[row * 100 + x]) << "column " << x;
  }
  EXPECT_EQ(a, ref::line(13, 20, 80, 40, 100, 100));
  EXPECT_EQ(b, ref::line(20, 13, 40, 80, 100, 100));
}

TEST(Line, EndpointsArePixelsContainingThePoints) {
  const auto m = line_mask({3.99, 5.01}, {3.2, 5.7});  // both inside pixel (3, 5)
  int n = 0;
  for (auto v : m) n += v;
  EXPECT_EQ(n, 1);
  EXPECT_TRUE(m[5 * 100 + 3]);
}

// a->b equals b->a in every octant, including exact diagonals and ties, and matches the reference.
TEST(Line, SymmetricInEveryOctantAndMatchesReference) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coord(-20, 80);
  for (int t = 0; t < 2000; ++t) {
    Point2 a{coord(rng) + 0.5, coord(rng) + 0.5}, b{coord(rng) + 0.5, coord(rng) + 0.5};
    if (t % 5 == 0) b = {a.x + (t % 3 - 1) * 17.0, a.y + 17.0};  // diagonals and axis lines
    const auto fwd = line_mask(a, b, 64, 64), back = line_mask(b, a, 64, 64);
    ASSERT_EQ(fwd, back) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
    ASSERT_EQ(fwd, ref::line(a.x, a.y, b.x, b.y, 64, 64)) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
  }
}

// Clipping happens before stepping: the cost is the visible length, and the visible pixels are exactly
// those of the unclipped line (same columns, same rows). Lines of 2e18 and 2e30 pixels could never be
// stepped; this test would hang (and hit its ctest timeout) if any off-screen pixel were visited.
TEST(Line, HugeLinesAreClippedExactly) {
  for (double big : {1e9, 1e18, 1e30}) {
    const auto diag = line_mask({-big, -big}, {big, big});
    for (int i = 0; i < 100; ++i) EXPECT_TRUE(diag[i * 100 + i]) << big;
  }
  // A shallow line whose endpoints are far outside: compare with the reference stepping every column.
  const auto shallow = line_mask({-5000.5, 7.5}, {9000.5, 93.5});
  EXPECT_EQ(shallow, ref::line(-5000.5, 7.5, 9000.5, 93.5, 100, 100));
  for (double big : {1e30, 3.4e38}) {
    const auto m = line_mask({-big, 50.5}, {big, 50.5});
    for (int x = 0; x < 100; ++x) EXPECT_TRUE(m[50 * 100 + x]) << big;
  }
}

TEST(Line, PerVertexColoursInterpolateAlongTheMajorAxis) {
  auto img = test::render(
      SceneBuilder(11, 3)
          .line({0.5, 1.5}, {10.5, 1.5}, raster::Rgba8{0, 0, 0, 255}, raster::Rgba8{200, 100, 250, 255})
          .scene);
  for (int x = 0; x <= 10; ++x) {
    EXPECT_EQ(test::pixel(img, x, 1).r, 20 * x);
    EXPECT_EQ(test::pixel(img, x, 1).b, 25 * x);
  }
  // reversed: same pixels and colours
  auto rev = test::render(
      SceneBuilder(11, 3)
          .line({10.5, 1.5}, {0.5, 1.5}, raster::Rgba8{200, 100, 250, 255}, raster::Rgba8{0, 0, 0, 255})
          .scene);
  EXPECT_EQ(img.pixels, rev.pixels);
}

// A translucent polyline blends each joint pixel once, like one stroke, not once per segment.
TEST(Line, PolylineJointsBlendOnce) {
  const raster::Rgba8 half{255, 255, 255, 128};
  SceneBuilder open(20, 20);
  open.polyline({{2.5, 2.5}, {15.5, 2.5}, {15.5, 15.5}, {2.5, 15.5}}, half, false);
  SceneBuilder closed(20, 20);
  closed.polyline({{2.5, 2.5}, {15.5, 2.5}, {15.5, 15.5}, {2.5, 15.5}}, half, true);
  for (auto* s : {&open, &closed}) {
    auto img = test::render(s->scene);
    for (int y = 0; y < 20; ++y)
      for (int x = 0; x < 20; ++x) {
        const int v = test::pixel(img, x, y).r;
        ASSERT_TRUE(v == 0 || v == 128) << x << "," << y << " = " << v;
      }
    EXPECT_EQ(test::pixel(img, 15, 2).r, 128);
  }
  EXPECT_EQ(test::count_not(test::render(open.scene), kBlack), 13 * 3 + 1);
  EXPECT_EQ(test::count_not(test::render(closed.scene), kBlack), 13 * 4);
}

TEST(Line, TriangleOutlineUsesTheLineRule) {
  SceneBuilder s(40, 40);
  s.triangle({5.5, 5.5}, {30.5, 8.5}, {12.5, 33.5}, kWhite, /*fill=*/false);
  const auto outline = test::mask_not(test::render(s.scene), kBlack);
  std::vector<std::uint8_t> expect(40 * 40, 0);
  for (auto [a, b] : {std::pair{Point2{5.5, 5.5}, Point2{30.5, 8.5}},
                      {Point2{30.5, 8.5}, Point2{12.5, 33.5}},
                      {Point2{12.5, 33.5}, Point2{5.5, 5.5}}}) {
    const auto m = ref::line(a.x, a.y, b.x, b.y, 40, 40);
    for (std::size_t i = 0; i < m.size(); ++i) expect[i] |= m[i];
  }
  EXPECT_EQ(outline, expect);
  EXPECT_FALSE(outline[15 * 40 + 14]) << "an outline leaves the inside empty";
}

}  // namespace

namespace {

using raster::Rgba8;

// The rectangle a line of `width` is drawn as, corner for corner as geometry makes it (before snapping).
std::array<Point2, 4> rectangle_of(Point2 a, Point2 b, double width) {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy), half = width * 0.5,
               nx = -dy / len * half, ny = dx / len * half;
  return {Point2{a.x + nx, a.y + ny}, Point2{b.x + nx, b.y + ny}, Point2{b.x - nx, b.y - ny},
          Point2{a.x - nx, a.y - ny}};
}

// A flat line drawn as rectangles is one four-edge record per segment (a quad). Its edges are those of the
// two triangles it was drawn as before, so aliased and multisampled it must give their bytes: seeded lines
// of every orientation and width, translucent and opaque, some reaching far beyond the image (within the
// fast range, and beyond it, where lines stay triangles), against the same rectangles given as triangles.
TEST(Line, AQuadGivesTheBytesOfItsTwoTriangles) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> unit(0, 1);
  int compared = 0;
  for (int n = 0; n < 96; ++n) {
    const double angle = n * M_PI / 48 + unit(rng) * 0.05, length = n % 6 == 5 ? 3e4 : 2 + unit(rng) * 50;
    double width = n % 4 == 0 ? 1 : 0.2 + unit(rng) * 9;
    const Point2 mid{4 + unit(rng) * 40, 4 + unit(rng) * 40};
    Point2 a{mid.x - length * std::cos(angle), mid.y - length * std::sin(angle)},
        b{mid.x + length * std::cos(angle) * (n % 12 == 11 ? 100 : 1),
          mid.y + length * std::sin(angle) * (n % 12 == 11 ? 100 : 1)};
    if (n % 8 == 2) {  // on the grid: edges through pixel centres, where the top-left rule decides
      const double c = 5.5 + n % 5;
      a = n % 16 == 2 ? Point2{c, 3} : Point2{3, 3}, b = n % 16 == 2 ? Point2{c, 40} : Point2{40, 40};
      width = n % 16 == 2 ? 2 + n % 3 : std::sqrt(2.0) * (1 + n % 3);
    }
    const Rgba8 color{static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()), 200,
                      static_cast<std::uint8_t>(n % 3 == 0 ? 140 : 255)};
    for (int samples : {1, 4, 16}) {
      SceneBuilder line(48, 48, Rgba8{30, 30, 30, 255});
      line.line(a, b, color);
      line.line({40, 2}, {3, 30}, color);  // a second line over it: the blending order holds too
      for (raster::Primitive& p : line.scene.primitives) p.width = static_cast<float>(width);
      line.scene.antialias = test::multisample(samples);
      if (samples == 1 && width == 1) continue;  // Bresenham, not a rectangle
      SceneBuilder triangles(48, 48, Rgba8{30, 30, 30, 255});
      for (const auto& [p, q] : {std::pair{a, b}, std::pair{Point2{40, 2}, Point2{3, 30}}}) {
        const std::array<Point2, 4> r = rectangle_of(p, q, width);
        triangles.triangle(r[0], r[1], r[2], color).triangle(r[0], r[2], r[3], color);
      }
      triangles.scene.antialias = line.scene.antialias;
      EXPECT_TRUE(raster::plan(line.scene).draws[0].mode.line_quads || n % 12 == 11);
      ASSERT_EQ(test::render(line.scene).pixels, test::render(triangles.scene).pixels)
          << "line " << n << " width " << width << " at " << samples << " samples";
      ++compared;
    }
  }
  EXPECT_GT(compared, 250);
}

// The corners of the quads the plan may refuse or setup may find degenerate: widths far below the 1/256 px
// grid (corners snapped onto each other, or a twisted rectangle, left to the triangles), a width whose
// rectangle leaves the fast range, and endpoints at its edge. Each renders as its two triangles do.
TEST(Line, ExtremeQuadsGiveTheBytesOfTheirTriangles) {
  const double widths[] = {1e-4, 0.003, 0.0045, 3, 4096};  // 4096: the most a line may be
  const std::pair<Point2, Point2> ends[] = {{{3.2, 5.1}, {44.7, 30.2}},
                                            {{-32760.3, 20.5}, {32760.1, 21.7}},
                                            {{20.25, -32000}, {21.75, 32000}},
                                            {{10, 10}, {10.001, 40}}};
  for (const double width : widths)
    for (const auto& [a, b] : ends)
      for (int samples : {1, 4}) {
        SceneBuilder line(48, 48, Rgba8{30, 30, 30, 255});
        line.line(a, b, Rgba8{250, 200, 10, 160});
        line.scene.primitives.back().width = static_cast<float>(width);
        line.scene.antialias = test::multisample(samples);
        SceneBuilder triangles(48, 48, Rgba8{30, 30, 30, 255});
        const std::array<Point2, 4> r = rectangle_of(a, b, static_cast<float>(width));
        triangles.triangle(r[0], r[1], r[2], Rgba8{250, 200, 10, 160})
            .triangle(r[0], r[2], r[3], Rgba8{250, 200, 10, 160});
        triangles.scene.antialias = line.scene.antialias;
        ASSERT_EQ(test::render(line.scene).pixels, test::render(triangles.scene).pixels)
            << "width " << width << " from " << a.x << "," << a.y << " at " << samples << " samples";
      }
}

}  // namespace
