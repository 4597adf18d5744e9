// Anti-aliasing: multisampling at the standard positions (coverage per sample, shading once per pixel, one
// resolve per tile), checked against the literal reference per sample; and the plan's memory accounting
// for every scene class, checked against what a render actually allocates.
#include <gtest/gtest.h>

#include <array>

#include <cmath>
#include <random>
#include <set>

#include <nlohmann/json.hpp>

#include "coverage/coverage.h"
#include "reference.h"
#include "support.h"

namespace {

using nlohmann::json;
using test::kBlack;

raster::Image render_json(const json& scene, int threads = 1) {
  return test::render(raster::parse_scene(scene.dump()), threads);
}

// Area of the unit pixel [x, x+1] x [y, y+1] on the side n . p >= d of a line (exact polygon clipping).
double area_inside(double x, double y, double nx, double ny, double d) {
  std::vector<std::pair<double, double>> poly = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}, out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto a = poly[i], b = poly[(i + 1) % poly.size()];
    const double fa = nx * a.first + ny * a.second - d, fb = nx * b.first + ny * b.second - d;
    if (fa >= 0) out.push_back(a);
    if ((fa >= 0) != (fb >= 0)) {
      const double t = fa / (fa - fb);
      out.push_back({a.first + t * (b.first - a.first), a.second + t * (b.second - a.second)});
    }
  }
  double area = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto a = out[i], b = out[(i + 1) % out.size()];
    area += a.first * b.second - b.first * a.second;
  }
  return std::abs(area) / 2;
}

// The worst gap, over a dense sweep of half-planes through a pixel, between the fraction of a pattern's
// samples inside and the area inside: the most any straight edge can be off at this level.
double line_discrepancy(int samples) {
  const auto& pattern = raster::detail::sample_pattern(samples);
  double worst = 0;
  for (int a = 0; a < 360; ++a) {
    const double t = a * M_PI / 180, nx = std::cos(t), ny = std::sin(t);
    for (int o = -80; o <= 80; ++o) {
      const double d = nx * 0.5 + ny * 0.5 + o / 100.0;  // lines across the pixel centred at (0.5, 0.5)
      int in = 0;
      for (const auto& s : pattern) in += nx * (s.x / 256.0) + ny * (s.y / 256.0) - d >= 0;
      worst =
          std::max(worst, std::abs(static_cast<double>(in) / pattern.size() - area_inside(0, 0, nx, ny, d)));
    }
  }
  return worst;
}

TEST(Antialias, OneSampleIsTheAliasedImageBitForBit) {
  json scene = json::parse(test::read_file(std::string(RASTERD_EXAMPLES_DIR) + "/overview.json"));
  const auto aliased = render_json(scene);
  scene["antialias"] = 1;
  EXPECT_EQ(render_json(scene).pixels, aliased.pixels);
  scene["antialias"] = 4;
  EXPECT_NE(render_json(scene).pixels, aliased.pixels);
}

TEST(Antialias, OnlyStandardLevelsAreAccepted) {
  for (int bad : {0, 2, 3, 32, -4}) {
    try {
      raster::parse_scene(json{{"width", 4}, {"height", 4}, {"antialias", bad}}.dump());
      ADD_FAILURE() << bad;
    } catch (const raster::SceneError& e) {
      EXPECT_EQ(e.where().pointer, "/antialias");
    }
  }
}

// A half-plane edge at several angles, white on black: every pixel's value is the exact area inside
// within the level's sampling bound (its line discrepancy) plus rounding to 1/255.
TEST(Antialias, HalfPlaneCoverageIsWithinTheSamplingBound) {
  for (int samples : {4, 8, 16}) {
    const double bound = line_discrepancy(samples);
    // A well-spread pattern beats an ordered sqrt(N) x sqrt(N) grid, whose axis-aligned edges are off by 1 /
    // sqrt(N).
    EXPECT_LT(bound, 1 / std::sqrt(static_cast<double>(samples))) << samples;
    RecordProperty("line_discrepancy_" + std::to_string(samples), std::to_string(bound));
    double worst = 0, sum = 0;
    int edge_pixels = 0;
    for (double degrees : {0.0, 7.0, 30.0, 45.0, 61.0, 83.0, 97.0}) {
      const double t = degrees * M_PI / 180, nx = -std::sin(t),
                   ny = std::cos(t);                               // inside: below a line at angle t
      const double cx = 31.37, cy = 32.81, d = nx * cx + ny * cy;  // through a point off the pixel grid
      // A triangle far larger than the image whose one visible edge is that line.
      const double ux = std::cos(t), uy = std::sin(t), far = 1e4;
      const json tri = {
          {"type", "triangle"},
          {"points",
           {{cx - far * ux, cy - far * uy}, {cx + far * ux, cy + far * uy}, {cx + far * nx, cy + far * ny}}},
          {"color", "#ffffff"}};
      const auto img =
          render_json({{"width", 64}, {"height", 64}, {"antialias", samples}, {"primitives", {tri}}});
      for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
          const double area = area_inside(x, y, nx, ny, d);
          const double err = std::abs(test::pixel(img, x, y).r / 255.0 - area);
          ASSERT_LE(err, bound + 0.5 / 255 + 1e-9)
              << samples << " samples, " << degrees << " deg, pixel " << x << "," << y;
          if (area > 0 && area < 1) worst = std::max(worst, err), sum += err, ++edge_pixels;
        }
    }
    EXPECT_GT(edge_pixels, 300);
    RecordProperty("mean_edge_error_" + std::to_string(samples), std::to_string(sum / edge_pixels));
  }
}

TEST(Antialias, ResolvedJitteredGridShowsNoSeam) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);
  constexpr int n = 12, cell = 5;
  json prims = json::array();
  std::vector<std::pair<double, double>> g((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      g[j * (n + 1) + i] = {4.0 + i * cell + (border ? 0 : jitter(rng)),
                            4.0 + j * cell + (border ? 0 : jitter(rng))};
    }
  auto pt = [&](int i, int j) { return json{g[j * (n + 1) + i].first, g[j * (n + 1) + i].second}; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      prims.push_back({{"type", "triangle"},
                       {"points", {pt(i, j), pt(i + 1, j), pt(i + 1, j + 1)}},
                       {"color", "#ffffff80"}});
      prims.push_back({{"type", "triangle"},
                       {"points", {pt(i, j), pt(i + 1, j + 1), pt(i, j + 1)}},
                       {"color", "#ffffff80"}});
    }
  for (int samples : {4, 16}) {
    const auto img = render_json(
        {{"width", 8 + n * cell}, {"height", 8 + n * cell}, {"antialias", samples}, {"primitives", prims}});
    // Every pixel fully inside the grid: every sample hit exactly once, so the resolve is exactly 128.
    for (int y = 5; y < 3 + n * cell; ++y)
      for (int x = 5; x < 3 + n * cell; ++x)
        ASSERT_EQ(test::pixel(img, x, y).r, 128) << samples << ": " << x << "," << y;
  }
}

TEST(Antialias, ResolvedFanShowsNoSeam) {
  json prims = json::array();
  const double cx = 64, cy = 64, r = 60;
  for (int k = 0; k < 1000; ++k) {
    const double t0 = 2 * M_PI * k / 1000, t1 = 2 * M_PI * (k + 1) / 1000;
    prims.push_back({{"type", "triangle"},
                     {"points",
                      {{cx, cy},
                       {cx + r * std::cos(t0), cy + r * std::sin(t0)},
                       {cx + r * std::cos(t1), cy + r * std::sin(t1)}}},
                     {"color", "#ffffff80"}});
  }
  const auto img = render_json({{"width", 128}, {"height", 128}, {"antialias", 8}, {"primitives", prims}});
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      if (dx * dx + dy * dy < 58 * 58) {
        ASSERT_EQ(test::pixel(img, x, y).r, 128)
            << x << "," << y;  // every sample of every inner pixel hit once
      }
    }
}

// A line of width w and length L covers w L of area (butt caps), within 2 px of area on these 80 px lines
// at 16 samples. Not within the issue's 1 px: a periodic sample pattern aliases along lines of rational
// slope (the lattice projects onto the line's normal at a fixed spacing), an error proportional to length
// -- measured on 45 degree, width-1 lines: -12% of the area with 4 samples, +6% with 8, +1.5% with 16.
// Exact area coverage or per-pixel varied patterns would remove it; neither is built (closing note).
TEST(Antialias, LinesCoverWidthTimesLength) {
  for (double width : {1.0, 2.5, 7.0}) {
    for (double degrees : {0.0, 13.0, 45.0, 71.0}) {
      const double t = degrees * M_PI / 180, length = 80;
      const double x0 = 20.3, y0 = 14.6, x1 = x0 + length * std::cos(t), y1 = y0 + length * std::sin(t);
      const json line = {
          {"type", "line"}, {"points", {{x0, y0}, {x1, y1}}}, {"width", width}, {"color", "#ffffff"}};
      const auto img =
          render_json({{"width", 128}, {"height", 128}, {"antialias", 16}, {"primitives", {line}}});
      double covered = 0;
      for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) covered += test::pixel(img, x, y).r / 255.0;
      EXPECT_NEAR(covered, width * length, 2.0) << "width " << width << ", " << degrees << " deg";
    }
  }
}

TEST(Antialias, IntersectingSurfacesGetSmoothIntersectionsFromPerSampleDepth) {
  // Two triangles crossing along the y axis, both turned 30 degrees about z so that the intersection runs
  // across pixels instead of along a column.
  auto turned = [](double x, double y, double z) {
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    return json{c * x - s * y, s * x + c * y, z};
  };
  const json a = {{"type", "triangle"},
                  {"points", {turned(-1, -1, -1), turned(1, -1, 1), turned(0, 1, 0)}},
                  {"color", "#ff0000"}};
  const json b = {{"type", "triangle"},
                  {"points", {turned(-1, -1, 1), turned(1, -1, -1), turned(0, 0.8, 0)}},
                  {"color", "#00ff00"}};
  const json cam = {{"eye", {0.3, 0.2, 4}}, {"target", {0, 0, 0}}, {"fov", 50}};
  const auto aliased = render_json({{"width", 80}, {"height", 80}, {"camera", cam}, {"primitives", {a, b}}});
  const auto smooth =
      render_json({{"width", 80}, {"height", 80}, {"antialias", 8}, {"camera", cam}, {"primitives", {a, b}}});
  // Pixels where the aliased image steps from red to green (to the right or below): the intersection.
  int boundary = 0, mixed_aliased = 0, mixed_smooth = 0;
  for (int y = 0; y + 1 < 80; ++y)
    for (int x = 0; x + 1 < 80; ++x) {
      const auto c = test::pixel(aliased, x, y);
      bool step = false;
      for (const auto n : {test::pixel(aliased, x + 1, y), test::pixel(aliased, x, y + 1)})
        step = step || (c == test::kRed && n == test::kGreen) || (c == test::kGreen && n == test::kRed);
      boundary += step;
      mixed_aliased += c.r > 20 && c.g > 20;
      const auto s = test::pixel(smooth, x, y);
      mixed_smooth += s.r > 20 && s.g > 20;  // both surfaces within one pixel (one sample of 8 is 32)
    }
  EXPECT_GT(boundary, 5);
  EXPECT_EQ(mixed_aliased, 0);
  EXPECT_GE(2 * mixed_smooth, boundary) << "per-sample depth mixes the colours along the intersection";
}

TEST(Antialias, SameBytesForAnyThreadCount) {
  json scene = json::parse(test::read_file(std::string(RASTERD_EXAMPLES_DIR) + "/star.json"));
  scene["antialias"] = 8;
  EXPECT_EQ(render_json(scene, 1).pixels, render_json(scene, 3).pixels);
}

// Issue 8: for each class of scene, the plan's decisions, and the pixel bytes a render actually
// allocates equal the plan's estimate (no depth or sample storage unless the scene uses it).
TEST(PlanMemory, AllocatedPixelBytesEqualThePlanForEveryClass) {
  const std::string bunny = test::read_file(RASTERD_MODELS_DIR "/bunny.obj");
  const json tri3d = {
      {"type", "triangle"}, {"points", {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}}, {"color", "#ff0000"}};
  struct Case {
    const char* name;
    json scene;
    raster::PixelFormat format;
    bool depth;
    int samples;
  };
  const Case cases[] = {
      {"2D flat lines",
       {{"width", 64},
        {"height", 48},
        {"background", "#fff"},
        {"primitives", {{{"type", "line"}, {"points", {{1, 1}, {60, 40}}}, {"color", "#000"}}}}},
       raster::PixelFormat::grey8,
       false,
       1},
      {"2D gradient", json::parse(test::read_file(std::string(RASTERD_EXAMPLES_DIR) + "/gradient.json")),
       raster::PixelFormat::rgb8, false, 1},
      {"2D alpha", json::parse(test::read_file(std::string(RASTERD_EXAMPLES_DIR) + "/alpha.json")),
       raster::PixelFormat::rgb8, false, 1},
      {"2D transparent",
       {{"width", 32},
        {"height", 32},
        {"background", "#00000000"},
        {"primitives", {{{"type", "triangle"}, {"points", {{0, 0}, {30, 0}, {0, 30}}}, {"color", "#f00"}}}}},
       raster::PixelFormat::rgba8,
       false,
       1},
      {"opaque 3D mesh",
       {{"width", 64}, {"height", 64}, {"primitives", {tri3d}}},
       raster::PixelFormat::rgb8,
       true,
       1},
      {"lit OBJ",
       {{"width", 96}, {"height", 96}, {"primitives", {{{"type", "obj"}, {"data", bunny}}}}},
       raster::PixelFormat::grey8,
       true,
       1},
      {"anti-aliased 2D",
       {{"width", 64},
        {"height", 64},
        {"antialias", 4},
        {"primitives", {{{"type", "triangle"}, {"points", {{0, 0}, {60, 5}, {9, 60}}}, {"color", "#0f0"}}}}},
       raster::PixelFormat::rgb8,
       false,
       4},
      {"anti-aliased 3D",
       {{"width", 64}, {"height", 64}, {"antialias", 8}, {"primitives", {tri3d}}},
       raster::PixelFormat::rgb8,
       true,
       8},
      {"auto 3D",
       {{"width", 70}, {"height", 64}, {"antialias", "auto"}, {"primitives", {tri3d}}},
       raster::PixelFormat::rgb8,
       true,
       8},
      {"tiny", {{"width", 1}, {"height", 1}}, raster::PixelFormat::grey8, false, 1},
      {"large",
       {{"width", 2000},
        {"height", 1500},
        {"primitives",
         {{{"type", "triangle"},
           {"points", {{0, 0}, {2000, 0}, {0, 1500}}},
           {"colors", {"#f00", "#0f0", "#00f"}}}}}},
       raster::PixelFormat::rgb8,
       false,
       1},
  };
  for (const Case& c : cases) {
    const auto scene = raster::parse_scene(c.scene.dump());
    const auto plan = raster::plan(scene);
    EXPECT_EQ(plan.format, c.format) << c.name;
    EXPECT_EQ(plan.depth_buffer, c.depth) << c.name;
    EXPECT_EQ(plan.samples, c.samples) << c.name;
    const std::int64_t pixels = static_cast<std::int64_t>(scene.width) * scene.height;
    EXPECT_EQ(plan.memory.color_bytes, pixels * raster::channel_count(c.format)) << c.name;
    // Depth lives in each thread's tile (3D only), one value per sample; multisampling keeps a tile of colour
    // per sample and a bit per pixel, per thread: nothing the size of the image.
    const std::int64_t tile = std::int64_t{plan.threads} * plan.tile_width() * plan.tile_height();
    EXPECT_EQ(plan.memory.depth_bytes, c.depth ? tile * 4 * c.samples : 0) << c.name;
    // 2D aliased images whole blocks wide are drawn in place; the others in each thread's tile of colour.
    EXPECT_EQ(plan.tiles_in_place, !c.depth && c.samples == 1 && scene.width % 8 == 0) << c.name;
    EXPECT_EQ(plan.memory.tile_bytes, plan.tiles_in_place ? 0 : tile * raster::channel_count(c.format))
        << c.name;
    EXPECT_EQ(plan.memory.sample_bytes,
              c.samples > 1 ? tile * c.samples * raster::channel_count(c.format) + tile / 8 : 0)
        << c.name;
    // "auto" finds its edge pixels over the whole image: 8 bytes a block, and a byte a channel of a row.
    const bool automatic = scene.antialias == raster::Antialias::automatic;
    EXPECT_EQ(plan.memory.edge_bytes, automatic ? ((scene.width + 7) / 8) * ((scene.height + 7) / 8) * 8 +
                                                      (scene.width - 1) * raster::channel_count(c.format)
                                                : 0)
        << c.name;
    raster::RenderStats stats;
    raster::RenderControl control;
    control.stats = &stats;
    const auto img = raster::render(scene, plan, control);
    EXPECT_EQ(stats.pixel_bytes, plan.memory.total()) << c.name << ": allocated what the plan said";
    EXPECT_EQ(test::decode_png(raster::encode_png(img, plan.png)).channels, raster::channel_count(c.format))
        << c.name;
  }
}

}  // namespace

namespace {

using raster::Point2;

// Multisampling against the literal reference at each sample position: a sample at (x + ox/256, y +
// oy/256) is inside a triangle exactly when the pixel centre is inside the triangle moved by
// ((128 - ox) / 256, (128 - oy) / 256), an exact move on the 1/256 grid that keeps the top-left rule. So
// every resolved pixel is round(255 k / N) for the k samples the rule covers, and each pixel with any
// covered sample is shaded once, not once per sample.
TEST(Multisample, EverySampleFollowsTheRuleAndEachPixelIsShadedOnce) {
  std::mt19937 rng(1414);
  std::uniform_real_distribution<double> at(-4, 52), d(-30, 30);
  constexpr int kSide = 48;
  for (int samples : {4, 8, 16}) {
    const auto& pattern = raster::detail::sample_pattern(samples);
    for (int n = 0; n < 12; ++n) {
      const Point2 a{at(rng), at(rng)}, b{a.x + d(rng), a.y + d(rng)}, c{a.x + d(rng), a.y + d(rng)};
      std::vector<int> count(kSide * kSide, 0);
      for (const auto& s : pattern) {
        const double mx = (128 - s.x) / 256.0, my = (128 - s.y) / 256.0;
        const ref::Coverage cov =
            ref::triangle(a.x + mx, a.y + my, b.x + mx, b.y + my, c.x + mx, c.y + my, kSide, kSide);
        for (int i = 0; i < kSide * kSide; ++i) count[i] += cov.mask[i];
      }
      test::SceneBuilder flat(kSide, kSide, kBlack);
      flat.triangle(a, b, c, test::kWhite);
      flat.scene.antialias = test::multisample(samples);
      const raster::Image img = test::render(flat.scene);
      int touched = 0;
      for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
          const int k = count[y * kSide + x];
          touched += k > 0;
          ASSERT_EQ(test::pixel(img, x, y).r, (255 * k + samples / 2) / samples)
              << samples << " samples, triangle " << n << ", pixel " << x << "," << y << ": " << k
              << " inside";
        }
      // The same triangle with three vertex colours: shaded once per pixel it touches.
      test::SceneBuilder smooth(kSide, kSide, kBlack);
      smooth.triangle(a, b, c, test::kRed, test::kGreen, test::kBlue);
      smooth.scene.antialias = test::multisample(samples);
      raster::RenderStats stats;
      raster::RenderControl control;
      control.stats = &stats;
      raster::render(smooth.scene, raster::plan(smooth.scene), control);
      EXPECT_EQ(stats.shaded_pixels, touched) << samples << " samples, triangle " << n;
    }
  }
}

// Lines (one quad a segment) and slivers at every orientation against the same literal reference: each
// sample is inside the rectangle's two triangles (the corners geometry makes, on the 1/256 grid; the
// triangles share their diagonal, so by the top-left rule a sample is in at most one) or the sliver, moved
// by the sample's offset, and each resolved pixel is round(255 k / N) for the k samples covered.
TEST(Multisample, LinesAndSliversCoverEverySampleTheRuleCovers) {
  std::mt19937 rng(4343);
  std::uniform_real_distribution<double> unit(0, 1);
  constexpr int kSide = 40;
  for (int samples : {4, 8, 16}) {
    const auto& pattern = raster::detail::sample_pattern(samples);
    for (int n = 0; n < 24; ++n) {
      const double angle = n * M_PI / 12 + unit(rng) * 0.1, length = 5 + unit(rng) * 40;
      const Point2 a{4 + unit(rng) * 32, 4 + unit(rng) * 32},
          b{a.x + length * std::cos(angle), a.y + length * std::sin(angle)};
      const double width = n % 2 ? 0.3 + unit(rng) * 4 : 0.02 + unit(rng) * 0.2;  // line, sliver thickness
      const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
      const double nx = -dy / len * width / 2, ny = dx / len * width / 2;
      std::vector<std::array<Point2, 3>> triangles;
      test::SceneBuilder scene(kSide, kSide, kBlack);
      if (n % 2) {  // a line: its rectangle's two triangles, with the corners as geometry makes them
        const Point2 q[4] = {
            {a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
        triangles = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
        scene.line(a, b, test::kWhite);
        scene.scene.primitives.back().width = static_cast<float>(width);
      } else {  // a sliver: a triangle as thin as `width` at its wide end
        const Point2 c{b.x + 2 * nx, b.y + 2 * ny};
        triangles = {{a, b, c}};
        scene.triangle(a, b, c, test::kWhite);
      }
      scene.scene.antialias = test::multisample(samples);
      std::vector<int> count(kSide * kSide, 0);
      for (const auto& s : pattern) {
        const double mx = (128 - s.x) / 256.0, my = (128 - s.y) / 256.0;
        for (const auto& t : triangles) {
          const ref::Coverage cov = ref::triangle(t[0].x + mx, t[0].y + my, t[1].x + mx, t[1].y + my,
                                                  t[2].x + mx, t[2].y + my, kSide, kSide);
          for (int i = 0; i < kSide * kSide; ++i) count[i] += cov.mask[i];
        }
      }
      const raster::Image img = test::render(scene.scene);
      for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
          const int k = count[y * kSide + x];
          ASSERT_LE(k, samples) << "a sample in both triangles";
          ASSERT_EQ(test::pixel(img, x, y).r, (255 * k + samples / 2) / samples)
              << samples << " samples, " << (n % 2 ? "line " : "sliver ") << n << ", pixel " << x << "," << y;
        }
    }
  }
}

// 3D: depth per sample, and the mesh shaded once per pixel per triangle it is seen through.
TEST(Multisample, MeshesAreShadedOncePerPixelPerVisibleTriangle) {
  const raster::Scene scene =
      raster::parse_scene(R"({"width": 64, "height": 64, "antialias": 16, "primitives": [
      {"type": "mesh", "positions": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "indices": [[0, 1, 2]],
       "colors": ["#ff0000", "#00ff00", "#0000ff"], "shading": "unlit"}]})");
  raster::RenderStats stats;
  raster::RenderControl control;
  control.stats = &stats;
  const raster::Image img = raster::render(scene, raster::plan(scene), control);
  EXPECT_EQ(stats.shaded_pixels, test::count_not(img, kBlack));
  EXPECT_GT(stats.shaded_pixels, 500);
}

// A multisampled pixel whose centre is outside a triangle is shaded at the centroid of its covered samples,
// inside the triangle, not at the centre, where the colours would extrapolate. The triangle's red runs from
// 20 at its base to 235 at its apex over a few pixels, and red + green is 255 everywhere, so a resolved
// pixel's share of red, R / (R + G), is its shading point's red whatever the share of samples covered: within
// [20, 235] up to the rounding of R and G. Shaded at the centre, pixels below the base would come out near 0.
TEST(Multisample, MeshEdgePixelsAreShadedInsideTheTriangle) {
  for (int samples : {4, 8, 16}) {
    const raster::Scene scene = raster::parse_scene(R"({"width": 64, "height": 64, "antialias": )" +
                                                    std::to_string(samples) + R"(, "primitives": [
      {"type": "mesh", "positions": [[-1, -0.1, 0], [1, -0.25, 0], [0.1, 0.2, 0]], "indices": [[0, 1, 2]],
       "colors": ["#14eb00", "#14eb00", "#eb1400"], "shading": "unlit"}]})");
    const raster::Image img = test::render(scene);
    int edge = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const raster::Rgba8 p = test::pixel(img, x, y);
        const double sum = p.r + p.g;
        if (sum < 16 || sum > 250) continue;  // untouched, or every sample covered
        ++edge;
        const double red = 255 * p.r / sum, slack = 255 / sum + 1;
        ASSERT_GE(red, 20 - slack) << samples << " samples, pixel " << x << "," << y;
        ASSERT_LE(red, 235 + slack) << samples << " samples, pixel " << x << "," << y;
      }
    EXPECT_GT(edge, 60) << samples << " samples";
  }
}

}  // namespace

namespace {

// 3D lines and wireframes are anti-aliased too: multisampled, they are rectangles a pixel wide with
// depth, so their edges take intermediate values where aliased ones are only the line or the background.
TEST(Multisample, WireframesAreAntialiased) {
  auto levels = [](int samples) {
    const std::string text = R"({"width": 96, "height": 96, "background": "#ffffff", "antialias": )" +
                             std::to_string(samples) + R"(, "primitives": [{"type": "mesh", "wireframe": true,
        "color": "#000000", "positions": [[-1, -1, 0], [1, -1, 0], [0.3, 1, 0]], "indices": [[0, 1, 2]],
        "transform": {"rotate": [20, 30, 0]}}]})";
    const raster::Image img = test::render(raster::parse_scene(text));
    std::set<int> seen;
    for (int y = 0; y < 96; ++y)
      for (int x = 0; x < 96; ++x) seen.insert(test::pixel(img, x, y).r);
    return seen.size();
  };
  EXPECT_EQ(levels(1), 2u);
  EXPECT_GT(levels(8), 6u);
}

}  // namespace
