// The render deadline and cancel flag, with an injected clock: when they are looked at is a property of the
// work done, not of how fast the machine does it, so these verdicts hold on any machine.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <functional>

#include <nlohmann/json.hpp>
#include "coverage/coverage.h"

#include "raster/raster.h"
#include "support.h"

namespace {

using Clock = std::chrono::steady_clock;

// A scene of `count` triangles that each cover the whole `side` x `side` image, smooth-shaded.
raster::Scene covering_triangles(int side, int count, int samples = 1) {
  test::SceneBuilder b(side, side);
  const double s = side;
  for (int i = 0; i < count; ++i)
    b.triangle({-s, -s}, {3 * s, -s}, {-s, 3 * s}, test::kRed, test::kGreen, test::kBlue);
  b.scene.antialias = test::multisample(samples);
  return b.scene;
}

// A clock that reads `t0` until its `expire_at`-th reading (1-based), and one hour later from then on; it
// counts its readings. Thread-safe: every thread reads it.
struct FakeClock {
  const Clock::time_point t0 = Clock::now();
  std::atomic<int> readings{0};
  int expire_at = 1 << 30;
  std::function<Clock::time_point()> fn() {
    return [this] { return ++readings >= expire_at ? t0 + std::chrono::hours(1) : t0; };
  }
  /// A RenderControl on this clock whose deadline is a second after t0: it passes at the expire_at-th
  /// reading.
  raster::RenderControl control() {
    raster::RenderControl c;
    c.deadline = t0 + std::chrono::seconds(1);
    c.clock = fn();
    return c;
  }
};

// The plan, with exactly `threads` threads (the planner would keep small work on one).
raster::RenderPlan plan_with_threads(const raster::Scene& scene, int threads) {
  raster::RenderPlan plan = raster::plan(scene);
  plan.threads = threads;
  return plan;
}

TEST(Deadline, APastDeadlineStopsEvenATinyRender) {
  raster::Scene scene = covering_triangles(1, 1);
  raster::RenderControl control;
  control.deadline = Clock::now() - std::chrono::seconds(1);
  EXPECT_THROW(raster::render(scene, raster::plan(scene), control), raster::RenderCancelled);
}

TEST(Deadline, ACancelFlagAlreadySetStopsTheRender) {
  raster::Scene scene = covering_triangles(8, 1);
  std::atomic<bool> cancel{true};
  raster::RenderControl control;
  control.cancel = &cancel;
  EXPECT_THROW(raster::render(scene, raster::plan(scene), control), raster::RenderCancelled);
}

// One primitive, as large as a 2048x2048 image: the deadline is looked at while it is drawn, every
// StopMeter::kWorkPerCheck pixels, not only before and after it.
TEST(Deadline, OneImageSizedTriangleIsCheckedWhileItIsDrawn) {
  const raster::Scene scene = covering_triangles(2048, 1);
  const raster::RenderPlan plan = plan_with_threads(scene, 1);
  FakeClock clock;
  raster::RenderControl control = clock.control();
  raster::render(scene, plan, control);
  const int pixels = 2048 * 2048;
  EXPECT_GE(clock.readings, pixels / raster::detail::StopMeter::kWorkPerCheck)
      << "the deadline was not looked at inside the triangle";
  EXPECT_LE(clock.readings, 2 * pixels / raster::detail::StopMeter::kWorkPerCheck + 2)
      << "looked at far more often than the meter says (a clock read per row or per pixel costs time)";

  // The deadline passes at the 5th look: the render stops there, with no look after it.
  FakeClock expiring;
  expiring.expire_at = 5;
  control = expiring.control();
  EXPECT_THROW(raster::render(scene, plan, control), raster::RenderCancelled);
  EXPECT_EQ(expiring.readings, 5);
}

// Multisampling covers each pixel once for all its samples and then resolves each tile: both are metered,
// and a deadline passing in the middle stops every thread, whatever the thread count.
TEST(Deadline, MultisampledRendersStopInsideATileOrTheResolve) {
  const raster::Scene scene = covering_triangles(1024, 1, 16);
  for (int threads : {1, 2, 3}) {
    const raster::RenderPlan plan = plan_with_threads(scene, threads);
    FakeClock counting;
    raster::RenderControl control = counting.control();
    raster::render(scene, plan, control);
    const int looks = counting.readings;
    // 1024^2 pixels covered, plus the resolve reading them again
    EXPECT_GE(looks, 2 * 1024 * 1024 / raster::detail::StopMeter::kWorkPerCheck) << threads << " threads";

    // In the tiles, half way, and in the resolve. Not at looks - 1: with more than one thread the count of
    // looks varies by up to a look per thread and phase (each thread's meter carries its own remainder), so
    // a render could end before that look and never be cancelled.
    for (int expire_at : {3, looks / 2, looks * 3 / 4}) {
      FakeClock expiring;
      expiring.expire_at = expire_at;
      control = expiring.control();
      EXPECT_THROW(raster::render(scene, plan, control), raster::RenderCancelled)
          << threads << " threads, expiring at look " << expire_at;
      // Each thread stops at its next look after the first one that saw the deadline.
      EXPECT_LE(expiring.readings, expire_at + threads) << threads << " threads";
    }
  }
}

// Geometry is metered too: a mesh of 180,000 triangles that are all behind the camera costs no pixel, yet
// transforming and clipping it is looked at every kWorkPerCheck / kPrimitiveWork triangles.
TEST(Deadline, MeshGeometryIsCheckedWhileItIsTransformed) {
  const int n = 300;  // n x n quads, 2 n^2 triangles
  nlohmann::json positions = nlohmann::json::array(), indices = nlohmann::json::array();
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) positions.insert(positions.end(), {x, y, 0});
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      indices.insert(indices.end(), {a, b, d, a, d, c});
    }
  const nlohmann::json doc = {
      {"width", 64},
      {"height", 64},
      {"camera", {{"eye", {0, 0, 10}}, {"target", {0, 0, 20}}}},  // looking away from the mesh at z = 0
      {"primitives", {{{"type", "mesh"}, {"positions", positions}, {"indices", indices}}}}};
  const raster::Scene scene = raster::parse_scene(doc.dump());
  const raster::RenderPlan plan = plan_with_threads(scene, 1);
  FakeClock clock;
  raster::RenderControl control = clock.control();
  const raster::Image image = raster::render(scene, plan, control);
  EXPECT_EQ(test::count_not(image, test::kBlack), 0) << "the mesh is behind the camera";
  EXPECT_GE(clock.readings,
            2 * n * n * raster::detail::StopMeter::kPrimitiveWork / raster::detail::StopMeter::kWorkPerCheck);

  FakeClock expiring;
  expiring.expire_at = 3;
  control = expiring.control();
  EXPECT_THROW(raster::render(scene, plan, control), raster::RenderCancelled);
  EXPECT_EQ(expiring.readings, 3);
}

// A deadline that does not pass changes nothing: the same bytes as a render without one.
// A texture's mip chain is made in geometry, before any pixel: a 2048^2 texture on an 8x8 image is 1.4M
// texels of mipmaps and 64 pixels, and the deadline is looked at while the chain is built (it was not, once:
// a 4096^2 texture overran the deadline by the ~1 s its chain then took).
TEST(Deadline, TextureMipmapsAreCheckedWhileTheyAreBuilt) {
  raster::Mesh quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.uv_triangles = quad.triangles;
  raster::Texture texture;
  texture.width = texture.height = 2048;
  texture.rgba.assign(std::size_t{2048} * 2048 * 4, 255);
  quad.textures.push_back(std::move(texture));
  quad.colors = {test::kWhite};  // multiplied by the texture
  quad.shading = raster::Shading::unlit;
  raster::Scene scene;
  scene.width = scene.height = 8;
  scene.meshes.push_back(std::move(quad));
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  scene.primitives.push_back(p);
  const raster::RenderPlan plan = plan_with_threads(scene, 1);
  ASSERT_EQ(plan.textured_count, 1);

  FakeClock counting;
  raster::RenderControl control = counting.control();
  raster::render(scene, plan, control);
  const int mip_texels = (1024 * 1024 * 4 - 1) / 3;  // 1024^2 + 512^2 + ... + 1
  EXPECT_GE(counting.readings, mip_texels / raster::detail::StopMeter::kWorkPerCheck)
      << "the deadline was not looked at while the mipmaps were built";

  FakeClock expiring;
  expiring.expire_at = 3;
  control = expiring.control();
  EXPECT_THROW(raster::render(scene, plan, control), raster::RenderCancelled);
  EXPECT_EQ(expiring.readings, 3);
}

TEST(Deadline, AFutureDeadlineDoesNotChangeTheImage) {
  const raster::Scene scene = covering_triangles(300, 3, 4);
  const raster::RenderPlan plan = plan_with_threads(scene, 2);
  FakeClock clock;
  raster::RenderControl control = clock.control();
  EXPECT_EQ(raster::render(scene, plan, control).pixels, raster::render(scene, plan).pixels);
}

}  // namespace
