// "antialias": "area": every pixel takes the exact share of its square that each shape covers. Checked
// against polygon clipping in double precision on seeded random triangles (every pixel within one level),
// and for what area coverage promises beyond that: whole pixels are exactly the flat colour, a zero-area
// triangle draws nothing, a line's two triangles and a polyline's segments composite once (no seam, no
// darker joint), and the bytes do not depend on tiles or threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "support.h"

namespace {

using raster::Point2;
using raster::Rgba8;
using test::kBlack;
using test::kWhite;
using test::SceneBuilder;

// Share of the pixel square [x, x+1] x [y, y+1] inside the convex polygon `poly` (Sutherland-Hodgman
// against the square's four sides, then the shoelace formula): an independent reference, in the
// polygon's own coordinates rather than edge functions.
double share(const std::vector<Point2>& poly, int x, int y) {
  std::vector<Point2> cur = poly, next;
  for (int side = 0; side < 4 && !cur.empty(); ++side) {
    auto f = [&](Point2 p) {
      switch (side) {
        case 0:
          return p.x - x;
        case 1:
          return x + 1 - p.x;
        case 2:
          return p.y - y;
        default:
          return y + 1 - p.y;
      }
    };
    next.clear();
    for (std::size_t i = 0; i < cur.size(); ++i) {
      const Point2 a = cur[i], b = cur[(i + 1) % cur.size()];
      const double fa = f(a), fb = f(b);
      if (fa >= 0) next.push_back(a);
      if ((fa >= 0) != (fb >= 0)) {
        const double t = fa / (fa - fb);
        next.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
      }
    }
    std::swap(cur, next);
  }
  double twice = 0;
  for (std::size_t i = 0; i < cur.size(); ++i)
    twice += cur[i].x * cur[(i + 1) % cur.size()].y - cur[(i + 1) % cur.size()].x * cur[i].y;
  return std::abs(twice) / 2;
}

// A coordinate on the rasterizer's 1/256 px grid, so the snapped triangle is the exact one.
double on_grid(double px) {
  return std::round(px * 256) / 256;
}

raster::Image render_area(raster::Scene scene, int threads = 1) {
  scene.antialias = raster::Antialias::area;
  return test::render(scene, threads);
}

TEST(Area, RandomTrianglesAreWithinOneLevelOfTheExactShareAtEveryPixel) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> unit(0, 1);
  constexpr int kSide = 48;
  int cut_pixels = 0, exact = 0;
  for (int n = 0; n < 300; ++n) {
    // Sizes from a tenth of a pixel to beyond the image, and one in five a sliver.
    const double size = std::pow(10.0, -1 + unit(rng) * 3), cx = unit(rng) * kSide, cy = unit(rng) * kSide;
    auto p = [&] {
      return Point2{on_grid(cx + (unit(rng) - 0.5) * size), on_grid(cy + (unit(rng) - 0.5) * size)};
    };
    Point2 a = p(), b = p(), c = p();
    if (n % 5 == 0) c = {on_grid((a.x + b.x) / 2 + 0.02 * size), on_grid((a.y + b.y) / 2 - 0.013 * size)};
    const raster::Image img = render_area(SceneBuilder(kSide, kSide, kBlack).triangle(a, b, c, kWhite).scene);
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        const double want = 255 * share({a, b, c}, x, y);
        const int got = test::pixel(img, x, y).r;
        ASSERT_LE(std::abs(got - want), 1.0) << "triangle " << n << " pixel " << x << "," << y;
        if (want > 0 && want < 255) ++cut_pixels, exact += got == std::lround(want);
      }
  }
  EXPECT_GT(cut_pixels, 3000);          // the test reached many cut pixels
  EXPECT_GT(exact, cut_pixels * 0.99);  // and nearly all are the rounded exact share itself
}

TEST(Area, SliversAtEveryOrientationAreWithinOneLevelOfTheExactShare) {
  // Triangles far thinner than a pixel: along them every cut pixel is crossed by the two long edges, which
  // take the two-edge closed form; near the tips they meet inside a pixel and are clipped. Some reach a
  // million pixels beyond the image, where the edges need the wide integers.
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(0, 1);
  constexpr int kSide = 40;
  int cut_pixels = 0;
  for (int n = 0; n < 160; ++n) {
    const double angle = n * M_PI / 80 + unit(rng) * 0.01, thick = std::pow(10.0, -2 + unit(rng) * 2),
                 length = n % 8 == 7 ? 2e6 : 4 + unit(rng) * 40;
    const double dx = std::cos(angle), dy = std::sin(angle);
    const Point2 a{on_grid(4 + unit(rng) * 32 - (n % 8 == 7 ? 1e6 * dx : 0)),
                   on_grid(4 + unit(rng) * 32 - (n % 8 == 7 ? 1e6 * dy : 0))};
    const Point2 b{on_grid(a.x + length * dx), on_grid(a.y + length * dy)};
    const Point2 c{on_grid(b.x - thick * dy), on_grid(b.y + thick * dx)};
    const raster::Image img = render_area(SceneBuilder(kSide, kSide, kBlack).triangle(a, b, c, kWhite).scene);
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        const double want = 255 * share({a, b, c}, x, y);
        ASSERT_LE(std::abs(test::pixel(img, x, y).r - want), 1.0)
            << "sliver " << n << " pixel " << x << "," << y;
        cut_pixels += want > 0 && want < 255;
      }
  }
  EXPECT_GT(cut_pixels, 2000);  // the test reached many cut pixels
}

TEST(Area, HugeTrianglesTakeTheExactWidePathToTheSameShares) {
  // Vertices far outside the fast range (1e12 px): edges are 384-bit integers; the shares stay exact.
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int n = 0; n < 20; ++n) {
    const Point2 a{on_grid(10 + unit(rng) * 20), on_grid(10 + unit(rng) * 20)};
    const double t = unit(rng) * 2 * M_PI;
    const Point2 b{a.x + 1e12 * std::cos(t), a.y + 1e12 * std::sin(t)},
        c{a.x + 1e12 * std::cos(t + 0.3), a.y + 1e12 * std::sin(t + 0.3)};
    const raster::Image img = render_area(SceneBuilder(40, 40, kBlack).triangle(a, b, c, kWhite).scene);
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        // The reference: the triangle's corner at `a`, with its two edges cut short (same lines).
        const Point2 b1{a.x + 100 * std::cos(t), a.y + 100 * std::sin(t)};
        const Point2 c1{a.x + 100 * std::cos(t + 0.3), a.y + 100 * std::sin(t + 0.3)};
        const double want = 255 * share({a, b1, c1}, x, y);
        ASSERT_LE(std::abs(test::pixel(img, x, y).r - want), 1.0) << n << ": " << x << "," << y;
      }
  }
}

TEST(Area, WholePixelsAreExactlyTheFlatColourAndCutOnesBlendTowardIt) {
  const Rgba8 color{200, 40, 90, 255}, bg{10, 20, 30, 255};
  const Point2 a{3.3, 2.7}, b{60.1, 9.9}, c{20.6, 58.2};
  const raster::Image img = render_area(SceneBuilder(64, 64, bg).triangle(a, b, c, color).scene);
  int whole = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double s = share(
          {{on_grid(a.x), on_grid(a.y)}, {on_grid(b.x), on_grid(b.y)}, {on_grid(c.x), on_grid(c.y)}}, x, y);
      const Rgba8 got = test::pixel(img, x, y);
      if (s == 1) {
        ASSERT_EQ(got, color) << x << "," << y;
        ++whole;
      } else if (s == 0) {
        ASSERT_EQ(got, bg) << x << "," << y;
      } else {
        ASSERT_LE(std::abs(got.g - (bg.g + s * (color.g - bg.g))), 1.0) << x << "," << y;
      }
    }
  EXPECT_GT(whole, 1000);
}

TEST(Area, AZeroAreaTriangleDrawsNothing) {
  const Rgba8 bg{10, 20, 30, 255};
  SceneBuilder s(32, 32, bg);
  s.triangle({1, 1}, {30, 30}, {15.5, 15.5}, kWhite);  // collinear
  s.triangle({5, 5}, {5, 5}, {20, 7}, kWhite);         // two vertices equal
  EXPECT_EQ(test::count_not(render_area(s.scene), bg), 0);
}

TEST(Area, TranslucentColourScalesByTheShare) {
  // A half-covered pixel of white at alpha 128 over black: 255 x 0.5 x 128/255 = 64.
  const raster::Image img = render_area(SceneBuilder(4, 4, kBlack)
                                            .triangle({0, 0}, {2.5, 0}, {2.5, 4}, Rgba8{255, 255, 255, 128})
                                            .triangle({0, 0}, {0, 4}, {2.5, 4}, Rgba8{255, 255, 255, 128})
                                            .scene);
  EXPECT_EQ(test::pixel(img, 2, 1).r, 64);
  EXPECT_EQ(test::pixel(img, 0, 3).r, 128);  // wholly inside the second triangle
}

// The rectangle a line of width w from a to b is drawn as, with its corners snapped as the renderer
// snaps them: the reference for what line coverage is.
std::vector<Point2> line_rectangle(Point2 a, Point2 b, double w) {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy), nx = -dy / len * w / 2,
               ny = dx / len * w / 2;
  std::vector<Point2> q = {
      {a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
  for (Point2& p : q) p = {std::floor(p.x * 256 + 0.5) / 256, std::floor(p.y * 256 + 0.5) / 256};
  return q;
}

TEST(Area, LinesAreTheirRectanglesAreaWithNoSeamAlongTheDiagonal) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int n = 0; n < 40; ++n) {
    const Point2 a{4 + unit(rng) * 56, 4 + unit(rng) * 56}, b{4 + unit(rng) * 56, 4 + unit(rng) * 56};
    const float width = n % 4 == 0 ? 1.0f : 0.5f + static_cast<float>(unit(rng)) * 6;
    SceneBuilder s(64, 64, kBlack);
    s.line(a, b, kWhite);
    s.scene.primitives.back().width = width;
    const raster::Image img = render_area(s.scene);
    const std::vector<Point2> rect = line_rectangle(a, b, width);
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        ASSERT_LE(std::abs(test::pixel(img, x, y).r - 255 * share(rect, x, y)), 1.0)
            << "line " << n << " width " << width << " pixel " << x << "," << y;
  }
}

TEST(Area, ATranslucentPolylineCoversEachPixelOnceAtItsJoints) {
  // A zig-zag of wide translucent segments: where two segments overlap at a joint the pixel is covered
  // once, so no pixel is darker than a segment's middle.
  const Rgba8 ink{0, 0, 0, 128}, paper{255, 255, 255, 255};
  SceneBuilder s(80, 60, paper);
  s.polyline({{8, 50}, {28, 10}, {48, 50}, {70, 12}}, ink, false);
  s.scene.primitives.back().width = 6;
  const raster::Image img = render_area(s.scene);
  const int middle = test::pixel(img, 18, 30).r;  // inside the first segment, far from a joint
  EXPECT_EQ(middle, 127);                         // 255 x (1 - 128/255), rounded
  int darkest = 255;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 80; ++x) darkest = std::min<int>(darkest, test::pixel(img, x, y).r);
  EXPECT_EQ(darkest, middle);
  // Without the union the joints are darker: the same polyline as separate lines overlaps there.
  SceneBuilder apart(80, 60, paper);
  const Point2 pts[] = {{8, 50}, {28, 10}, {48, 50}, {70, 12}};
  for (int i = 0; i < 3; ++i) {
    apart.line(pts[i], pts[i + 1], ink);
    apart.scene.primitives.back().width = 6;
  }
  const raster::Image separate = render_area(apart.scene);
  int separate_darkest = 255;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 80; ++x)
      separate_darkest = std::min<int>(separate_darkest, test::pixel(separate, x, y).r);
  EXPECT_LT(separate_darkest, middle - 30);
}

TEST(Area, SameBytesForEveryTileSizeAndThreadCount) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> at(-40, 340), d(-60, 60);
  SceneBuilder s(300, 300, Rgba8{20, 30, 40, 255});
  for (int i = 0; i < 150; ++i) {
    const Point2 a{at(rng), at(rng)}, b{a.x + d(rng), a.y + d(rng)}, c{a.x + d(rng), a.y + d(rng)};
    const Rgba8 c0{static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                   static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(i % 3 ? 255 : 100)};
    switch (i % 5) {
      case 0:
        s.triangle(a, b, c, c0);
        break;
      case 1:
        s.triangle(a, b, c, c0, kWhite, Rgba8{0, 90, 200, 255});
        break;
      case 2:
        s.polyline({a, b, c}, c0, i % 2);
        s.scene.primitives.back().width = 3;
        break;
      case 3:
        s.triangle(a, {a.x + 1e12, a.y + 3e11}, {a.x - 2e11, a.y + 9e12}, c0);
        break;
      default:
        s.triangle(a, b, c, c0, false);
        break;
    }
  }
  s.scene.antialias = raster::Antialias::area;
  std::uint64_t first = 0;
  for (int tile : {16, 64, 128})
    for (int threads : {1, 2, 3}) {
      raster::PlanOptions options;
      options.tile = tile;
      options.max_threads = threads;
      raster::RenderPlan plan = raster::plan(s.scene, {}, options);
      plan.threads = threads;
      const std::uint64_t h = test::image_hash(raster::render(s.scene, plan));
      if (!first) first = h;
      EXPECT_EQ(h, first) << "tile " << tile << ", " << threads << " threads";
    }
}

TEST(Area, TheSimdMasksMatchTheScalarPath) {
  std::mt19937 rng(18);
  std::uniform_real_distribution<double> at(0, 200), d(-50, 50);
  SceneBuilder s(200, 200, kBlack);
  for (int i = 0; i < 100; ++i) {
    const Point2 a{at(rng), at(rng)};
    s.triangle(a, {a.x + d(rng), a.y + d(rng)}, {a.x + d(rng), a.y + d(rng)},
               Rgba8{static_cast<std::uint8_t>(rng()), 200, 100, 255});
  }
  s.scene.antialias = raster::Antialias::area;
  raster::PlanOptions scalar;
  scalar.scalar_coverage = true;
  EXPECT_EQ(test::image_hash(raster::render(s.scene, raster::plan(s.scene, {}, scalar))),
            test::image_hash(raster::render(s.scene, raster::plan(s.scene))));
}

TEST(Area, ThePlanKeepsAreaFor2DAndMultisamples3D) {
  raster::Scene flat = raster::parse_scene(R"({"width": 8, "height": 8, "antialias": "area", "primitives": [
      {"type": "polyline", "points": [[0, 0], [4, 6], [8, 0]], "color": "#ffffff"}]})");
  EXPECT_EQ(flat.antialias, raster::Antialias::area);
  const raster::RenderPlan p = raster::plan(flat);
  EXPECT_EQ(p.coverage, raster::Coverage::area);
  EXPECT_EQ(p.samples, 1);
  EXPECT_TRUE(p.draws[0].mode.union_coverage);  // its segments overlap at the joint: one shape
  EXPECT_TRUE(p.draws[0].mode.line_quads);
  EXPECT_EQ(p.memory.sample_bytes, 0);
  EXPECT_GT(p.memory.coverage_bytes, 0);
  EXPECT_NE(raster::explain_line(p).find(" samples=area "), std::string::npos) << raster::explain_line(p);
  // A single flat segment is one quad, one shape by itself: no accumulation, so none of its storage.
  raster::Scene line = raster::parse_scene(R"({"width": 8, "height": 8, "antialias": "area", "primitives": [
      {"type": "line", "points": [[0, 0], [8, 8]], "color": "#ffffff"}]})");
  const raster::RenderPlan one = raster::plan(line);
  EXPECT_TRUE(one.draws[0].mode.line_quads);
  EXPECT_FALSE(one.draws[0].mode.union_coverage);
  EXPECT_EQ(one.memory.coverage_bytes, 0);

  raster::Scene mesh = raster::parse_scene(R"({"width": 8, "height": 8, "antialias": "area", "primitives": [
      {"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [[0, 1, 2]]}]})");
  const raster::RenderPlan p3 = raster::plan(mesh);
  EXPECT_EQ(p3.coverage, raster::Coverage::samples);
  EXPECT_EQ(p3.samples, 8);
  EXPECT_GT(p3.memory.sample_bytes, 0);

  try {
    raster::parse_scene(R"({"width": 8, "height": 8, "antialias": "exact", "primitives": []})");
    FAIL() << "accepted";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.where().pointer, "/antialias");
    EXPECT_NE(std::string(e.what()).find("\"area\", \"auto\" or the samples per pixel"), std::string::npos)
        << e.what();
  }
}

}  // namespace
