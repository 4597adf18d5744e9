// The render plan: each scene class gets exactly the buffers, formats and modes it needs, and the bytes
// actually allocated for pixels equal what the plan says.
#include <gtest/gtest.h>

#include "support.h"

namespace {

using test::SceneBuilder;

raster::RenderPlan plan_of(const raster::Scene& s, int threads = 0) {
  raster::PlanOptions o;
  o.max_threads = threads;
  return raster::plan(s, raster::Limits{}, o);
}

TEST(Plan, FlatLineDrawingIsOneGreyChannelAndNothingElse) {
  SceneBuilder s(64, 64, raster::Rgba8{255, 255, 255, 255});
  s.line({1, 1}, {60, 30}, raster::Rgba8{0, 0, 0, 255})
      .line({1, 60}, {60, 3}, raster::Rgba8{90, 90, 90, 255});
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::grey8);
  EXPECT_FALSE(p.depth_buffer);
  EXPECT_EQ(p.samples, 1);
  EXPECT_EQ(p.flat_count, 2);
  EXPECT_EQ(p.smooth_count, 0);
  EXPECT_EQ(p.blend_count, 0);
  EXPECT_EQ(p.threads, 1);
  EXPECT_EQ(p.memory.color_bytes, 64 * 64);
  EXPECT_EQ(p.memory.depth_bytes + p.memory.sample_bytes, 0);
  EXPECT_EQ(p.png.color_type, 0);
  const auto img = raster::render(s.scene, p);
  EXPECT_EQ(static_cast<std::int64_t>(img.pixels.size()), p.memory.color_bytes);
  EXPECT_EQ(test::decode_png(raster::encode_png(img, p.png)).channels, 1)
      << "a grey scene is a 1-channel PNG";
}

TEST(Plan, GradientIsRgbAndSmooth) {
  SceneBuilder s(32, 32);
  s.triangle({1, 1}, {30, 2}, {5, 30}, test::kRed, test::kGreen, test::kBlue);
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::rgb8);
  EXPECT_EQ(p.smooth_count, 1);
  EXPECT_EQ(p.png.color_type, 2);
  EXPECT_EQ(test::decode_png(raster::encode_png(raster::render(s.scene, p), p.png)).channels, 3);
}

TEST(Plan, TranslucentInkOnOpaqueBackgroundStaysOpaqueRgb) {
  SceneBuilder s(16, 16, raster::Rgba8{10, 20, 30, 255});
  s.triangle({1, 1}, {15, 1}, {1, 15}, raster::Rgba8{255, 0, 0, 100});
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::rgb8)
      << "blending onto opaque pixels cannot make them transparent";
  EXPECT_EQ(p.blend_count, 1);
  EXPECT_TRUE(p.draw_of(0)->mode.blend);
}

TEST(Plan, TransparentBackgroundNeedsAlpha) {
  SceneBuilder rgba(16, 16, raster::Rgba8{0, 0, 0, 0});
  rgba.triangle({1, 1}, {15, 1}, {1, 15}, test::kRed);
  EXPECT_EQ(plan_of(rgba.scene).format, raster::PixelFormat::rgba8);
  SceneBuilder ga(16, 16, raster::Rgba8{0, 0, 0, 0});
  ga.triangle({1, 1}, {15, 1}, {1, 15}, raster::Rgba8{200, 200, 200, 255});
  const auto p = plan_of(ga.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::grey_alpha8);
  EXPECT_EQ(p.png.color_type, 4);
  const auto d = test::decode_png(raster::encode_png(raster::render(ga.scene, p), p.png));
  EXPECT_EQ(d.channels, 2);
  EXPECT_EQ(d.pixels[0], 0);                   // background grey ...
  EXPECT_EQ(d.pixels[1], 0);                   // ... fully transparent
  EXPECT_EQ(d.pixels[(2 * 16 + 2) * 2], 200);  // ink
  EXPECT_EQ(d.pixels[(2 * 16 + 2) * 2 + 1], 255);
}

TEST(Plan, EqualVertexColoursTakeTheFlatPathWithIdenticalPixels) {
  const raster::Rgba8 c{30, 140, 220, 255};
  SceneBuilder s(48, 48);
  s.triangle({1.3, 2.2}, {46.1, 9.7}, {8.8, 45.5}, c, c, c).line({0.5, 40.5}, {47.5, 3.5}, c, c);
  auto p = plan_of(s.scene);
  EXPECT_EQ(p.flat_count, 2);
  EXPECT_FALSE(p.draw_of(0)->mode.smooth);
  const auto flat = raster::render(s.scene, p);
  for (auto& d : p.draws) {  // force the interpolating path
    d.mode.smooth = true;
    d.mode.varyings.add(raster::Varying::color, raster::Interpolation::affine);
  }
  EXPECT_EQ(flat.pixels, raster::render(s.scene, p).pixels);
}

TEST(Plan, PrimitivesOutsideTheImageAreCulled) {
  SceneBuilder s(32, 32);
  s.triangle({-50, -50}, {-10, -40}, {-30, -5}, test::kRed)  // left of and above the image
      .line({40, 0}, {90, 31}, test::kRed)                   // right of it
      .triangle({1, 1}, {30, 1}, {1, 30}, test::kGreen);
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.culled_count, 2);
  EXPECT_EQ(p.draw_of(0), nullptr);
  EXPECT_EQ(p.draw_of(1), nullptr);
  EXPECT_NE(p.draw_of(2), nullptr);
  // Culled primitives do not decide the format either: only green ink is visible, still RGB.
  EXPECT_EQ(p.format, raster::PixelFormat::rgb8);
}

TEST(Plan, SmallScenesStayOnTheCallingThreadLargeOnesUseBands) {
  SceneBuilder tiny(256, 256);
  for (int i = 0; i < 100; ++i) tiny.line({0, double(i)}, {255, double(i)}, test::kRed);
  EXPECT_EQ(plan_of(tiny.scene, 8).threads, 1);
  // Few large primitives on a small image: the work estimate is over the threshold, the scene is small.
  SceneBuilder thumbnail(256, 256);
  for (int i = 0; i < 4; ++i)
    thumbnail.triangle({0, 0}, {256, 0}, {0, 256}, test::kRed)
        .triangle({256, 0}, {256, 256}, {0, 256}, test::kRed);
  EXPECT_GT(plan_of(thumbnail.scene, 8).work, 100'000);
  EXPECT_EQ(plan_of(thumbnail.scene, 8).threads, 1) << "256x256 with <= 100 primitives never hands off";
  SceneBuilder big(1024, 1024);
  big.triangle({0, 0}, {1024, 0}, {0, 1024}, test::kRed);
  EXPECT_EQ(plan_of(big.scene, 4).threads, 4);
  EXPECT_EQ(plan_of(big.scene, 1).threads, 1) << "the caller's cap wins";
}

TEST(Plan, MemoryIsCheckedBeforeAllocation) {
  SceneBuilder s(4000, 4000, raster::Rgba8{255, 0, 0, 0});  // not grey, not opaque: RGBA
  raster::Limits limits;
  raster::PlanOptions one_thread;
  one_thread.max_threads = 1;
  limits.max_buffer_bytes = 1ll << 40;
  const raster::MemoryPlan need = raster::plan(s.scene, limits, one_thread).memory;
  EXPECT_EQ(need.color_bytes, 4000ll * 4000 * 4);
  EXPECT_EQ(need.tile_bytes, 0) << "2D, aliased, whole blocks wide: tiles draw in place";
  EXPECT_EQ(need.total(), need.color_bytes);
  SceneBuilder odd(4001, 4000, raster::Rgba8{255, 0, 0, 0});  // a block at the right edge is partly outside
  EXPECT_EQ(raster::plan(odd.scene, limits, one_thread).memory.tile_bytes, 128 * 128 * 4)
      << "one thread's tile";
  limits.max_buffer_bytes = need.total() - 1;
  try {
    raster::plan(s.scene, limits, one_thread);
    FAIL() << "a 64 MB RGBA buffer is over a limit one byte short of it";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::limit);
  }
  limits.max_buffer_bytes += 1;
  EXPECT_EQ(raster::plan(s.scene, limits, one_thread).memory.total(), need.total());
}

TEST(Plan, LinesBecomeRectanglesOnlyWhenWideOrAntialiased) {
  SceneBuilder s(32, 32);
  s.line({1, 1}, {30, 20}, test::kRed).line({1, 5}, {30, 25}, test::kRed);
  s.scene.primitives[1].width = 3;
  auto p = plan_of(s.scene);
  EXPECT_FALSE(p.draw_of(0)->mode.line_rectangles) << "a 1 px aliased line is Bresenham";
  EXPECT_TRUE(p.draw_of(1)->mode.line_rectangles);
  s.scene.antialias = raster::Antialias::msaa4;
  p = plan_of(s.scene);
  EXPECT_TRUE(p.draw_of(0)->mode.line_rectangles) << "anti-aliased lines are rectangles";
}

TEST(Plan, ExplainShowsTheDecisions) {
  SceneBuilder s(20, 10);
  s.triangle({1, 1}, {19, 1}, {1, 9}, test::kRed, test::kGreen, test::kBlue)
      .line({0, 0}, {5, 5}, raster::Rgba8{1, 2, 3, 4});
  const auto p = plan_of(s.scene);
  EXPECT_EQ(raster::explain_line(p), "rgb8 depth=none samples=1 flat=1 smooth=1 blend=1 culled=0 threads=1");
  const std::string j = raster::explain_json(p);
  EXPECT_NE(j.find("\"format\": \"rgb8\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"color\": 600"), std::string::npos) << j;
}

TEST(Plan, RejectsScenesBuiltInCodeThatReferToMissingData) {
  SceneBuilder s(8, 8);
  s.triangle({1, 1}, {2, 2}, {1, 3}, test::kRed);
  s.scene.primitives[0].point_count = 4;
  EXPECT_THROW(raster::plan(s.scene), raster::SceneError);
  s.scene.primitives[0].point_count = 3;
  s.scene.colors.clear();
  EXPECT_THROW(raster::plan(s.scene), raster::SceneError);
}

}  // namespace
