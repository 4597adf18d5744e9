// "antialias": "auto" (Coverage::edge_samples): every tile aliased, then the edge pixels (shade/edges.h)
// drawn again at 8 samples. Its contract, checked pixel by pixel: an edge pixel of the aliased picture is the
// 8-sample picture's pixel, every other pixel the aliased one; and the bytes do not depend on threads,
// tiles, kernels or the sample storage.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <random>

#include "base/stop.h"
#include "raster/model.h"
#include "raster/raster.h"
#include "raster/scene_checks.h"
#include "raster/scene_fields.h"
#include "shade/edges.h"
#include "support.h"

namespace {

using raster::Antialias;
using raster::Rgba8;

// A seeded soup of lit boxes and random triangles: silhouettes over the background, creases (flat faces
// of different colours), meshes that cut through each other and depth steps inside one mesh.
raster::Mesh soup(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> at(-1, 1), size(0.15f, 0.6f);
  std::uniform_int_distribution<int> byte(0, 255);
  raster::Mesh mesh;
  mesh.colors = {{200, 200, 200, 255}};  // under the faces' own colours
  for (int box = 0; box < 6; ++box) {    // boxes: creases between faces of one colour each
    const float cx = at(rng), cy = at(rng), cz = at(rng), s = size(rng);
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (int i = 0; i < 8; ++i)
      mesh.positions.push_back({cx + (i & 1 ? s : -s), cy + (i & 2 ? s : -s), cz + (i & 4 ? s : -s)});
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
      const Rgba8 colour{static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                         static_cast<std::uint8_t>(byte(rng)), 255};
      mesh.triangles.push_back({first + f[0], first + f[1], first + f[2]});
      mesh.triangles.push_back({first + f[0], first + f[2], first + f[3]});
      mesh.face_colors.push_back(colour), mesh.face_colors.push_back(colour);
    }
  }
  for (int t = 0; t < 40; ++t) {  // loose triangles, slivers among them, through the boxes
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (int v = 0; v < 3; ++v) mesh.positions.push_back({at(rng), at(rng), at(rng)});
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.face_colors.push_back({static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                                static_cast<std::uint8_t>(byte(rng)), 255});
  }
  return mesh;
}

// A stop meter for find_edge_pixels: no deadline; cancelled when `cancel` is set before it is read.
struct Meter {
  std::atomic<bool> cancel{false}, stopped{false};
  raster::detail::Stop stop{std::chrono::steady_clock::time_point::max(), &cancel, &stopped, nullptr};
  raster::detail::StopMeter meter{stop};
};

raster::Scene knot() {
  const std::string obj = test::read_file(std::string(RASTERD_EXAMPLES_DIR) + "/models/knot.obj");
  return raster::model_scene(
      raster::checks::model_mesh(obj, raster::ModelFormat::obj, {}, {}, "", "", 0, raster::ModelFormat::obj),
      raster::ModelFormat::obj);
}

raster::Image render(raster::Scene scene, Antialias antialias, const raster::PlanOptions& options = {}) {
  scene.antialias = antialias;
  raster::PlanOptions o = options;
  if (o.max_threads == 0) o.max_threads = 1;
  return raster::render(scene, raster::plan(scene, {}, o));
}

// Every pixel of `automatic` is the 8-sample picture's where the aliased picture has an edge pixel, and the
// aliased picture's elsewhere; returns how many edge pixels there were.
std::int64_t expect_the_contract(const raster::Scene& scene, const std::string& what) {
  const raster::Image aliased = render(scene, Antialias::none);
  const raster::Image eight = render(scene, Antialias::msaa8);
  const raster::Image automatic = render(scene, Antialias::automatic);
  Meter unstopped;
  raster::detail::StopMeter& meter = unstopped.meter;
  const raster::detail::EdgePixels edges = raster::detail::find_edge_pixels(aliased, meter);
  std::int64_t edge_pixels = 0, wrong = 0;
  const int c = aliased.channels();
  for (int y = 0; y < aliased.height; ++y)
    for (int x = 0; x < aliased.width; ++x) {
      const bool edge = (edges.view().at(x, y) >> (y % 8 * 8 + x % 8)) & 1;
      edge_pixels += edge;
      const raster::Image& want = edge ? eight : aliased;
      if (std::memcmp(automatic.at(x, y), want.at(x, y), static_cast<std::size_t>(c)) != 0 && wrong++ < 3)
        ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") is not the "
                      << (edge ? "8-sample" : "aliased") << " picture's";
    }
  EXPECT_EQ(wrong, 0) << what;
  return edge_pixels;
}

TEST(EdgeSamples, EdgePixelsAreTheEightSamplePicturesAndTheRestTheAliasedOnes) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    raster::Scene scene = raster::model_scene(soup(seed), raster::ModelFormat::obj);
    scene.width = 160 + 24 * static_cast<int>(seed), scene.height = 150;  // not whole tiles or blocks
    const std::int64_t edges = expect_the_contract(scene, "soup " + std::to_string(seed));
    EXPECT_GT(edges, 500) << "seed " << seed;  // silhouettes and creases were found
  }
  raster::Scene k = knot();
  k.width = k.height = 200;
  EXPECT_GT(expect_the_contract(k, "knot"), 500);
}

TEST(EdgeSamples, TwoDimensionalShapesKeepTheContract) {
  test::SceneBuilder b(97, 75, {250, 250, 240, 255});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-10, 107), y(-10, 85);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int i = 0; i < 30; ++i)
    b.triangle({x(rng), y(rng)}, {x(rng), y(rng)}, {x(rng), y(rng)},
               Rgba8{static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                     static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(i % 3 ? 255 : 128)});
  EXPECT_GT(expect_the_contract(b.scene, "2D triangles"), 300);
}

TEST(EdgeSamples, AnotherRenderWithTheSameSceneGivesTheSameBytes) {
  raster::Scene scene = raster::model_scene(soup(11), raster::ModelFormat::obj);
  scene.width = 300, scene.height = 220;
  const raster::Image one = render(scene, Antialias::automatic);
  for (const int threads : {2, 3, 7}) {
    raster::PlanOptions o;
    o.max_threads = threads;
    EXPECT_EQ(render(scene, Antialias::automatic, o).pixels, one.pixels) << threads << " threads";
  }
  raster::PlanOptions sse2, scalar, kept, tile;
  sse2.max_simd = raster::Simd::sse2;
  scalar.scalar_coverage = true;
  kept.keep_samples = true;
  tile.tile = 24;
  EXPECT_EQ(render(scene, Antialias::automatic, sse2).pixels, one.pixels) << "SSE2";
  EXPECT_EQ(render(scene, Antialias::automatic, scalar).pixels, one.pixels) << "scalar coverage";
  EXPECT_EQ(render(scene, Antialias::automatic, kept).pixels, one.pixels) << "a colour per sample";
  EXPECT_EQ(render(scene, Antialias::automatic, tile).pixels, one.pixels) << "24 px tiles";
}

// find_edge_pixels on pictures made by hand.
raster::Image flat(int w, int h, std::uint8_t grey) {
  raster::Image image{w, h, raster::PixelFormat::grey8, {}};
  image.pixels.assign(static_cast<std::size_t>(w) * h, grey);
  return image;
}
bool marked(const raster::detail::EdgePixels& e, int x, int y) {
  return (e.view().at(x, y) >> (y % 8 * 8 + x % 8)) & 1;
}

TEST(EdgeSamples, AnEdgePixelDiffersFromANeighbourByMoreThanTheContrast) {
  Meter unstopped;
  raster::detail::StopMeter& meter = unstopped.meter;
  raster::Image step = flat(20, 12, 100);
  for (int y = 0; y < 12; ++y)
    for (int x = 9; x < 20; ++x) step.pixels[static_cast<std::size_t>(y) * 20 + x] = 109;  // 9 above
  const raster::detail::EdgePixels e = raster::detail::find_edge_pixels(step, meter);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x) EXPECT_EQ(marked(e, x, y), x == 8 || x == 9) << x << ", " << y;
  EXPECT_EQ(e.blocks, 2);  // columns 8 and 9 are in block column 1, rows 0-11 in block rows 0 and 1
  EXPECT_EQ(raster::detail::find_edge_pixels(step, meter, 9).blocks, 0) << "a step of 9 is not above 9";

  raster::Image dot = flat(17, 9, 0);
  dot.pixels[4 * 17 + 8] = 255;  // one pixel: it and its eight neighbours are edge pixels
  const raster::detail::EdgePixels d = raster::detail::find_edge_pixels(dot, meter);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 17; ++x)
      EXPECT_EQ(marked(d, x, y), std::abs(x - 8) <= 1 && std::abs(y - 4) <= 1) << x << ", " << y;

  raster::Image column = flat(1, 5, 0);  // one pixel wide: neighbours above and below only
  column.pixels[2] = 200;
  const raster::detail::EdgePixels c = raster::detail::find_edge_pixels(column, meter);
  for (int y = 0; y < 5; ++y) EXPECT_EQ(marked(c, 0, y), y >= 1 && y <= 3) << y;
  EXPECT_EQ(raster::detail::find_edge_pixels(flat(1, 1, 7), meter).blocks, 0);
}

TEST(EdgeSamples, FindingEdgesStopsWhenTheRenderMust) {
  raster::Image step = flat(64, 4096, 0);
  for (std::size_t i = 0; i < step.pixels.size(); i += 2) step.pixels[i] = 255;  // every pixel an edge
  Meter cancelled;
  cancelled.cancel = true;
  const raster::detail::EdgePixels e = raster::detail::find_edge_pixels(step, cancelled.meter);
  EXPECT_TRUE(cancelled.meter.stopped());
  EXPECT_LT(e.pixels, 64 * 4096) << "it went on after the cancel";
  Meter running;
  EXPECT_EQ(raster::detail::find_edge_pixels(step, running.meter).pixels, 64 * 4096);
}

TEST(EdgeSamples, IsTheSceneValueAuto) {
  raster::Scene scene = raster::parse_scene(R"({"width": 64, "height": 64, "antialias": "auto"})");
  EXPECT_EQ(scene.antialias, Antialias::automatic);
  EXPECT_EQ(raster::checks::antialias("auto"), Antialias::automatic);
  const raster::RenderPlan plan = raster::plan(scene);
  EXPECT_EQ(plan.coverage, raster::Coverage::edge_samples);
  EXPECT_EQ(plan.samples, 8);
  EXPECT_GT(plan.memory.sample_bytes, 0);
  EXPECT_NE(raster::explain_json(plan).find("\"antialias\": \"auto\""), std::string::npos);
  // Its own canonical bytes (the service's ETag): not those of 1 sample, nor of 8.
  auto bytes = [](const raster::Scene& s) {
    std::string out;
    auto append = [&](const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); };
    raster::write_canonical(s, append);
    return out;
  };
  raster::Scene one = scene, eight = scene;
  one.antialias = Antialias::none, eight.antialias = Antialias::msaa8;
  EXPECT_NE(bytes(scene), bytes(one));
  EXPECT_NE(bytes(scene), bytes(eight));
  EXPECT_THROW(raster::parse_scene(R"({"width": 64, "height": 64, "antialias": "automatic"})"),
               raster::SceneError);
}

}  // namespace
