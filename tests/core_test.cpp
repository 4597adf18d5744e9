// The raster core (setup once, tile bins, one coverage routine, one shading place) and the stage contracts:
// differential tests against the literal reference for every tile size and thread count, the SIMD blocks
// against the scalar path of the same routine, and one test per contract so none can silently come back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "reference.h"
#include "support.h"

namespace {

using raster::Point2;
using raster::Rgba8;
using test::SceneBuilder;

Rgba8 random_color(std::mt19937& rng, bool opaque = true) {
  return {static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
          static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(opaque ? 255 : 40 + rng() % 200)};
}

// A seeded scene that mixes every primitive kind: flat, smooth and translucent triangles, slivers, huge
// (wide-path) triangles, 1 px lines and polylines, wide lines, outlines, and a lit 3D mesh.
raster::Scene mixed_scene(unsigned seed, int side, int samples = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> at(-side * 0.2, side * 1.2), d(-40, 40);
  SceneBuilder s(side, side, Rgba8{20, 30, 40, 255});
  for (int i = 0; i < 60; ++i) {
    const Point2 a{at(rng), at(rng)};
    const Point2 b{a.x + d(rng), a.y + d(rng)}, c{a.x + d(rng), a.y + d(rng)};
    switch (rng() % 9) {
      case 0:
        s.triangle(a, b, c, random_color(rng));
        break;
      case 1:
        s.triangle(a, b, c, random_color(rng), random_color(rng), random_color(rng));
        break;
      case 2:
        s.triangle(a, b, c, random_color(rng, false), random_color(rng), random_color(rng, false));
        break;
      case 3:  // a sliver
        s.triangle(a, {a.x + 300, a.y + 7}, {a.x + 150.3, a.y + 3.51}, random_color(rng));
        break;
      case 4:  // huge: the exact wide path
        s.triangle(a, {a.x + 1e12, a.y + 3e11}, {a.x - 2e11, a.y + 9e12}, random_color(rng, false));
        break;
      case 5:
        s.line(a, b, random_color(rng), random_color(rng));
        break;
      case 6:
        s.polyline({a, b, c, {c.x + 20, c.y - 5}}, random_color(rng, false), rng() % 2);
        break;
      case 7:
        s.triangle(a, b, c, random_color(rng), false);  // outline
        break;
      default:
        s.line(a, b, random_color(rng));
        s.scene.primitives.back().width = 1 + static_cast<float>(rng() % 50) / 10;
        break;
    }
  }
  raster::Mesh mesh;  // a lit, smooth tetrahedron-ish fan in front of the default camera
  mesh.positions = {{0, 0, 1}, {-1, -0.8, 0}, {1, -0.8, 0}, {0, 1, 0}, {0, 0, -1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {4, 2, 1}, {4, 3, 2}};
  mesh.segments = {{0, 4}};
  mesh.colors = {{200, 180, 90, 255},
                 {90, 200, 120, 255},
                 {80, 120, 230, 255},
                 {230, 90, 90, 255},
                 {250, 250, 250, 255}};
  s.scene.meshes.push_back(mesh);
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.scene.primitives.insert(s.scene.primitives.begin() + 30, p);
  s.scene.antialias = test::multisample(samples);
  return s.scene;
}

raster::Image render_with(const raster::Scene& scene, int tile, int threads, bool scalar = false) {
  raster::PlanOptions options;
  options.tile = tile;
  options.max_threads = threads;
  options.scalar_coverage = scalar;
  raster::RenderPlan plan = raster::plan(scene, {}, options);
  plan.threads = threads;  // exactly this many, whatever the plan's estimate of the work
  return raster::render(scene, plan);
}

// Same bytes for tile sizes 16, 64, 128 and 1, 2, 3, 7 threads, aliased and at 4 samples.
TEST(Core, SameBytesForEveryTileSizeAndThreadCount) {
  for (unsigned seed = 1; seed <= 6; ++seed)
    for (int samples : {1, 4}) {
      const raster::Scene scene = mixed_scene(seed, 200, samples);
      const raster::Image expected = render_with(scene, 64, 1);
      for (int tile : {16, 64, 128})
        for (int threads : {1, 2, 3, 7}) {
          const raster::Image got = render_with(scene, tile, threads);
          ASSERT_EQ(got.pixels, expected.pixels) << "seed " << seed << ", " << samples << " samples, tile "
                                                 << tile << ", " << threads << " threads";
        }
    }
}

// Large triangles, two in three smooth (per-vertex colour) and the rest flat, over an opaque or a transparent
// background (RGB or RGBA output): most of their pixels are whole blocks and rectangles, where the AVX2
// kernels work.
raster::Scene large_smooth_scene(unsigned seed, bool transparent) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> at(-60, 360);
  SceneBuilder s(301, 203, transparent ? Rgba8{0, 0, 0, 0} : Rgba8{20, 30, 40, 255});
  for (int i = 0; i < 40; ++i) {
    const Point2 a{at(rng), at(rng)}, b{at(rng), at(rng)}, c{at(rng), at(rng)};
    if (i % 3 == 0)
      s.triangle(a, b, c, random_color(rng));  // flat
    else
      s.triangle(a, b, c, random_color(rng), random_color(rng), random_color(rng));
  }
  return s.scene;
}

// Each instruction set the machine has gives the bytes of the SSE2 kernels, aliased, multisampled (4 and 16)
// and with area coverage.
TEST(Core, EverySimdTargetGivesTheBytesOfSse2) {
  if (raster::best_simd() == raster::Simd::sse2) GTEST_SKIP() << "no AVX2 on this machine";
  auto render_at = [](const raster::Scene& scene, raster::Simd simd, int tile) {
    raster::PlanOptions options;
    options.max_simd = simd;
    options.tile = tile;
    const raster::RenderPlan plan = raster::plan(scene, {}, options);
    EXPECT_EQ(plan.simd, simd);
    return raster::render(scene, plan);
  };
  for (unsigned seed = 1; seed <= 4; ++seed)
    for (int aa : {1, 4, 16, 0}) {  // 0: area; 4 and 16: the fused sample masks of each width
      std::vector<raster::Scene> scenes = {mixed_scene(seed, 200), large_smooth_scene(seed, false),
                                           large_smooth_scene(seed, true)};
      for (raster::Scene& scene : scenes) {
        scene.antialias = aa ? test::multisample(aa) : raster::Antialias::area;
        for (int tile : {16, 64}) {
          const raster::Image sse2 = render_at(scene, raster::Simd::sse2, tile);
          ASSERT_EQ(render_at(scene, raster::Simd::avx2, tile).pixels, sse2.pixels)
              << "seed " << seed << ", antialias " << aa << ", tile " << tile << ", " << sse2.channels()
              << " channels";
        }
      }
    }
}

// Tiles drawn in place (2D, aliased, the image whole blocks wide) give the bytes of tiles drawn in their
// own storage: the same 2D scene 200 px wide (in place) and 201 px wide (tile storage) agree on every pixel
// they share, at every tile size and thread count.
TEST(Core, InPlaceTilesGiveTheBytesOfTileStorage) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    raster::Scene scene = mixed_scene(seed, 200);
    std::erase_if(scene.primitives,
                  [](const raster::Primitive& p) { return p.kind == raster::PrimitiveKind::mesh; });
    raster::Scene wider = scene;
    wider.width = 201;
    for (int tile : {16, 64, 128})
      for (int threads : {1, 3}) {
        raster::PlanOptions options;
        options.tile = tile;
        options.max_threads = threads;
        raster::RenderPlan in_place = raster::plan(scene, {}, options),
                           stored = raster::plan(wider, {}, options);
        ASSERT_TRUE(in_place.tiles_in_place);
        ASSERT_FALSE(stored.tiles_in_place);
        in_place.threads = stored.threads = threads;
        const raster::Image a = raster::render(scene, in_place), b = raster::render(wider, stored);
        for (int y = 0; y < 200; ++y)
          for (int x = 0; x < 200; ++x)
            ASSERT_EQ(test::pixel(a, x, y), test::pixel(b, x, y))
                << "seed " << seed << ", tile " << tile << ", " << threads << " threads, pixel " << x << ", "
                << y;
      }
  }
}

// Renders running at once share the process's helper threads: each still gets its own bytes, whether a
// helper joined it or not.
TEST(Core, RendersAtOnceShareTheHelperThreads) {
  std::vector<raster::Scene> scenes;
  std::vector<raster::Image> alone;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    scenes.push_back(seed % 2 ? mixed_scene(seed, 200) : large_smooth_scene(seed, seed == 2));
    alone.push_back(render_with(scenes.back(), 16, 1));
  }
  std::vector<std::vector<std::uint8_t>> got(scenes.size() * 3);
  {
    std::vector<std::jthread> callers;
    for (std::size_t i = 0; i < got.size(); ++i)
      callers.emplace_back([&, i] { got[i] = render_with(scenes[i % scenes.size()], 16, 3).pixels; });
  }
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_EQ(got[i], alone[i % scenes.size()].pixels) << "render " << i;
}

// A UV sphere of 2 n^2 triangles (a large mesh is set up in parts on every render thread from 32,768
// triangles on), per-vertex colours and texture coordinates, every other band of faces textured.
raster::Scene sphere_scene(int n, int side) {
  raster::Scene s;
  s.width = s.height = side;
  raster::Mesh mesh;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double theta = pi * i / n, phi = 2 * pi * j / n;
      mesh.positions.push_back(raster::Vec3f(
          raster::Vec3{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)}));
      mesh.colors.push_back(
          {static_cast<std::uint8_t>(i * 255 / n), static_cast<std::uint8_t>(j * 255 / n), 128, 255});
      mesh.uvs.push_back({static_cast<float>(j) / n * 4, static_cast<float>(i) / n * 4});
    }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
      mesh.triangles.push_back({at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
    }
  mesh.uv_triangles = mesh.triangles;
  raster::Texture checker;
  checker.width = checker.height = 4;
  for (int t = 0; t < 16; ++t) {
    const std::uint8_t v = (t + t / 4) % 2 ? 255 : 40;
    checker.rgba.insert(checker.rgba.end(), {v, v, 255, 255});
  }
  mesh.textures.push_back(checker);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    mesh.face_textures.push_back((t / 512) % 2 ? 0 : -1);
  s.meshes.push_back(std::move(mesh));
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.primitives.push_back(p);
  return s;
}

// Meshes split into parts set up on every thread give the bytes of one thread: lit smooth with computed
// normals, flat, textured, culled, clipped by the near plane (the eye inside the sphere's bounds) and by the
// guard band, aliased and multisampled.
TEST(Core, MeshPartsGiveTheBytesOfOneThread) {
  std::vector<std::pair<std::string, raster::Scene>> cases;
  cases.reserve(8);  // g++ 12 warns of a bound it cannot see when the vector grows
  const raster::Scene lit = sphere_scene(130, 160);
  cases.emplace_back("smooth, computed normals, textured", lit);
  raster::Scene flat = lit;
  flat.meshes[0].shading = raster::Shading::flat, flat.meshes[0].cull = raster::Cull::back;
  cases.emplace_back("flat, back faces culled", flat);
  raster::Scene clipped = lit;
  clipped.camera.has_eye = clipped.camera.has_target = true;
  clipped.camera.eye = {0.2, 0.3, 0.95}, clipped.camera.target = {0, 0, 0}, clipped.camera.fov_deg = 100;
  cases.emplace_back("clipped by the near plane", clipped);
  raster::Scene band = lit;
  band.camera.has_eye = band.camera.has_target = true;
  band.camera.eye = {0.5, 0.5, 60}, band.camera.target = {0.5, 0.5, 0}, band.camera.fov_deg = 0.01;
  cases.emplace_back("clipped by the guard band", band);
  raster::Scene msaa = lit;
  msaa.antialias = raster::Antialias::msaa4;
  cases.emplace_back("4 samples", msaa);
  for (const auto& [name, scene] : cases) {
    const raster::Image one = render_with(scene, 64, 1);
    EXPECT_GT(test::count_not(one, {0, 0, 0, 255}), 1000) << name << ": the mesh is drawn";
    for (int threads : {2, 3, 7})
      EXPECT_EQ(render_with(scene, 64, threads).pixels, one.pixels) << name << ", " << threads << " threads";
  }
}

// A mesh of more triangles than pixels has its normals computed only at the corners of the triangles that
// may draw, those found first (PrimitivePlan::normals_where_drawn): the bytes of every vertex's normals
// computed, whatever is culled, clipped or multisampled, at any thread count, and with the triangles in a
// shuffled order (no run of them keeps to a few vertices).
TEST(Core, NormalsWhereDrawnGiveTheBytesOfEveryNormal) {
  std::vector<std::pair<std::string, raster::Scene>> cases;
  cases.reserve(8);
  const raster::Scene lit = sphere_scene(130, 160);  // 33,800 triangles on 25,600 pixels
  cases.emplace_back("smooth, textured", lit);
  raster::Scene culled = lit;
  culled.meshes[0].cull = raster::Cull::back;
  cases.emplace_back("back faces culled", culled);
  raster::Scene clipped = lit;
  clipped.camera.has_eye = clipped.camera.has_target = true;
  clipped.camera.eye = {0.2, 0.3, 0.95}, clipped.camera.target = {0, 0, 0}, clipped.camera.fov_deg = 100;
  cases.emplace_back("clipped by the near plane", clipped);
  raster::Scene msaa = lit;
  msaa.antialias = raster::Antialias::msaa4;
  cases.emplace_back("4 samples", msaa);
  raster::Scene shuffled = lit;
  raster::Mesh& m = shuffled.meshes[0];
  std::vector<std::size_t> order(m.triangles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  const raster::Mesh before = m;
  for (std::size_t t = 0; t < order.size(); ++t) {
    m.triangles[t] = before.triangles[order[t]], m.uv_triangles[t] = before.uv_triangles[order[t]];
    m.face_textures[t] = before.face_textures[order[t]];
  }
  cases.emplace_back("triangles shuffled", shuffled);
  for (const auto& [name, scene] : cases) {
    raster::RenderPlan plan = raster::plan(scene);
    ASSERT_TRUE(plan.draws[0].mode.compute_normals && plan.draws[0].mode.normals_where_drawn) << name;
    plan.draws[0].mode.normals_where_drawn = false;  // every vertex's normal: what it must equal
    plan.threads = 1;
    const raster::Image every = raster::render(scene, plan);
    EXPECT_GT(test::count_not(every, {0, 0, 0, 255}), 1000) << name << ": the mesh is drawn";
    plan.draws[0].mode.normals_where_drawn = true;
    for (int threads : {1, 2, 3, 7}) {
      plan.threads = threads;
      EXPECT_EQ(raster::render(scene, plan).pixels, every.pixels) << name << ", " << threads << " threads";
    }
  }
  // At no more triangles than pixels every normal is computed, as before.
  raster::Scene coarse = lit;
  coarse.width = coarse.height = 184;  // 33,856 pixels
  EXPECT_FALSE(raster::plan(coarse).draws[0].mode.normals_where_drawn);
}

// The 3D cases of the SIMD comparison below, each a variation of a seeded sphere: lit smooth with computed
// and with given normals, a point light (the position row), textured, vertex-coloured, back faces seen
// through an open hemisphere, the eye inside the bounds (triangles cut by the near plane), and flat.
struct MeshCase {
  std::string name;
  raster::Scene scene;
};

std::vector<MeshCase> simd_mesh_cases(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3), unit(0, 1);
  raster::Scene base = sphere_scene(20, 100);
  raster::Mesh& m = base.meshes[0];
  m.uv_triangles.clear(), m.textures.clear(), m.face_textures.clear();
  m.colors = {random_color(rng)};
  std::vector<MeshCase> cases;
  cases.push_back({"lit smooth, computed normals", base});
  raster::Scene given = base;
  for (const raster::Vec3 p : m.positions)
    given.meshes[0].normals.push_back(
        raster::Vec3f(raster::Vec3{p.x + jitter(rng), p.y + jitter(rng), p.z + jitter(rng)}));
  given.meshes[0].normal_triangles = m.triangles;
  cases.push_back({"lit smooth, given normals", given});
  raster::Scene coloured = base;
  coloured.meshes[0].colors.clear();
  for (std::size_t i = 0; i < m.positions.size(); ++i) coloured.meshes[0].colors.push_back(random_color(rng));
  raster::Scene point = coloured;
  auto light = [&](raster::LightKind kind, double intensity) {
    raster::Light l;
    l.kind = kind, l.intensity = intensity, l.color = {unit(rng), unit(rng), unit(rng)};
    l.direction = {jitter(rng), jitter(rng), -1}, l.position = {1.5 * jitter(rng), 1.2, 1.6};
    return l;
  };
  point.lights = {light(raster::LightKind::ambient, 0.2), light(raster::LightKind::point, 0.8),
                  light(raster::LightKind::directional, 0.5)};
  cases.push_back({"point light, vertex colours", point});
  coloured.meshes[0].shading = raster::Shading::unlit;
  cases.push_back({"unlit vertex colours", coloured});
  raster::Scene textured = sphere_scene(20, 100);
  textured.meshes[0].face_textures.clear();  // every face
  raster::Texture& t = textured.meshes[0].textures[0];
  t.width = t.height = 8, t.rgba.clear();
  for (int i = 0; i < 64; ++i) {
    const Rgba8 c = random_color(rng);
    t.rgba.insert(t.rgba.end(), {c.r, c.g, c.b, 255});
  }
  cases.push_back({"textured, lit", textured});
  raster::Scene open = point;  // the upper half only, seen from below its rim: inside faces show
  open.meshes[0].triangles.resize(open.meshes[0].triangles.size() / 2);
  open.camera.has_eye = open.camera.has_target = true;
  open.camera.eye = {0.4, -2.5, 1.2}, open.camera.target = {0, 0.3, 0};
  cases.push_back({"back faces, cull none", open});
  raster::Scene inside = point;
  inside.camera.has_eye = inside.camera.has_target = true;
  inside.camera.eye = {0.2, 0.3, 0.95}, inside.camera.target = {0, 0, 0}, inside.camera.fov_deg = 100;
  cases.push_back({"clipped by the near plane", inside});
  raster::Scene flat = point;
  flat.meshes[0].shading = raster::Shading::flat;
  cases.push_back({"flat, point light", flat});
  return cases;
}

// 3D meshes: every instruction set gives the bytes of SSE2 (and of one thread and 64 px tiles), at tiles 16
// and 64, 1 and 3 threads, aliased and at 4 and 16 samples (whose edge pixels take the one-lane path).
TEST(Core, EverySimdTargetGivesTheBytesOfSse2ForMeshes) {
  if (raster::best_simd() == raster::Simd::sse2) GTEST_SKIP() << "no AVX2 on this machine";
  auto render_at = [](const raster::Scene& scene, raster::Simd simd, int tile, int threads) {
    raster::PlanOptions options;
    options.max_simd = simd, options.tile = tile, options.max_threads = threads;
    raster::RenderPlan plan = raster::plan(scene, {}, options);
    EXPECT_EQ(plan.simd, simd);
    plan.threads = threads;
    return raster::render(scene, plan);
  };
  for (unsigned seed = 1; seed <= 2; ++seed)
    for (auto& [name, scene] : simd_mesh_cases(seed))
      for (int aa : {1, 4, 16}) {
        scene.antialias = test::multisample(aa);
        const raster::Image expected = render_at(scene, raster::Simd::sse2, 64, 1);
        ASSERT_GT(test::count_not(expected, test::kBlack), 2000) << name << ": the mesh is drawn";
        if (name.starts_with("back faces")) {  // and back faces are what it shows
          raster::Scene culled = scene;
          culled.meshes[0].cull = raster::Cull::back;
          ASSERT_LT(test::count_not(render_at(culled, raster::Simd::sse2, 64, 1), test::kBlack),
                    test::count_not(expected, test::kBlack) - 1000);
        }
        for (raster::Simd simd : {raster::Simd::sse2, raster::Simd::avx2})
          for (int tile : {16, 64})
            for (int threads : {1, 3})
              ASSERT_EQ(render_at(scene, simd, tile, threads).pixels, expected.pixels)
                  << name << ", seed " << seed << ", antialias " << aa << ", "
                  << (simd == raster::Simd::avx2 ? "AVX2" : "SSE2") << ", tile " << tile << ", " << threads
                  << " threads";
      }
}

// A tile size that is not a power of two, and the one-tile direct path, agree too.
TEST(Core, OddTileSizesAndTheDirectPathAgree) {
  const raster::Scene scene = mixed_scene(11, 150);
  const raster::Image expected = render_with(scene, 64, 1);
  EXPECT_EQ(render_with(scene, 24, 2).pixels, expected.pixels);
  EXPECT_EQ(render_with(scene, 152, 1).pixels, expected.pixels) << "one tile holding the whole image";
}

// The SIMD blocks against the scalar path of the same routine: identical coverage and colours.
TEST(Core, SimdBlocksMatchTheScalarPath) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const raster::Scene scene = mixed_scene(seed, 160, seed % 2 ? 1 : 8);
    EXPECT_EQ(render_with(scene, 64, 1, true).pixels, render_with(scene, 64, 1, false).pixels)
        << "seed " << seed;
  }
}

// Against the literal reference: seeded scenes of flat opaque triangles (every kind of shape, the fast and
// the wide path) and 1 px lines, each in its own colour, painted in order. Every pixel is the colour of
// the last primitive that covers it in the reference: identical bytes, at every tile size and thread count.
TEST(Core, PaintedScenesMatchTheLiteralReferenceExactly) {
  constexpr int kSide = 96;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> at(-20, kSide + 20), d(-30, 30);
    SceneBuilder s(kSide, kSide);
    std::vector<std::uint8_t> expect(kSide * kSide * 3, 0);
    auto paint = [&](const std::vector<std::uint8_t>& mask, Rgba8 c) {
      for (int i = 0; i < kSide * kSide; ++i)
        if (mask[i]) expect[3 * i] = c.r, expect[3 * i + 1] = c.g, expect[3 * i + 2] = c.b;
    };
    for (int n = 0; n < 40; ++n) {
      const Rgba8 c{static_cast<std::uint8_t>(1 + n), static_cast<std::uint8_t>(seed), 200, 255};
      const Point2 a{at(rng), at(rng)};
      Point2 b{a.x + d(rng), a.y + d(rng)}, e{a.x + d(rng), a.y + d(rng)};
      // A wide-path sliver (not for lines: the reference steps a line's every column).
      if (n % 7 == 3 && n % 5 != 4) b = {a.x + 2e9, a.y - 1e9}, e = {a.x + 3e9 + 0.5, a.y - 1.5e9 + 0.25};
      if (n % 5 == 4) {
        s.line(a, b, c);
        paint(ref::line(a.x, a.y, b.x, b.y, kSide, kSide), c);
      } else {
        s.triangle(a, b, e, c);
        paint(ref::triangle(a.x, a.y, b.x, b.y, e.x, e.y, kSide, kSide).mask, c);
      }
    }
    for (int tile : {16, 64, 128})
      for (int threads : {1, 3}) {
        const raster::Image got = render_with(s.scene, tile, threads);
        ASSERT_EQ(got.format, raster::PixelFormat::rgb8);
        ASSERT_EQ(got.pixels, expect)
            << "seed " << seed << ", tile " << tile << ", " << threads << " threads";
      }
  }
}

// Contract: the encoder writes the colour type the plan chose, for every format class; a plan for
// another format is refused rather than mislabelling the pixels.
TEST(Contracts, EncoderWritesThePlansColourType) {
  struct Case {
    Rgba8 background, ink;
    raster::PixelFormat format;
  };
  for (const Case& c : {Case{{0, 0, 0, 255}, {200, 200, 200, 255}, raster::PixelFormat::grey8},
                        Case{{0, 0, 0, 0}, {200, 200, 200, 255}, raster::PixelFormat::grey_alpha8},
                        Case{{0, 0, 0, 255}, {200, 10, 10, 255}, raster::PixelFormat::rgb8},
                        Case{{0, 0, 0, 0}, {200, 10, 10, 255}, raster::PixelFormat::rgba8}}) {
    SceneBuilder s(8, 8, c.background);
    s.triangle({0, 0}, {8, 0}, {0, 8}, c.ink);
    const raster::RenderPlan plan = raster::plan(s.scene);
    ASSERT_EQ(plan.format, c.format);
    const std::vector<std::uint8_t> png = raster::encode_png(raster::render(s.scene, plan), plan.png);
    EXPECT_EQ(png.at(25), plan.png.color_type) << "IHDR colour type";
    raster::PngPlan wrong = plan.png;
    wrong.color_type = c.format == raster::PixelFormat::rgb8 ? 6 : 2;
    EXPECT_THROW(raster::encode_png(raster::render(s.scene, plan), wrong), std::invalid_argument);
  }
}

// Contract: one validate() for parsed scenes and scenes built in code, with one wording per error.
TEST(Contracts, ParsedAndBuiltScenesGetTheSameValidation) {
  const std::string json =
      R"({"width": 8, "height": 8, "camera": {"eye": [1, 2, 3], "target": [1, 2, 3]},
          "primitives": [{"type": "triangle", "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]})";
  std::string parsed_message, parsed_pointer;
  try {
    raster::parse_scene(json);
    ADD_FAILURE() << "eye == target must be rejected by the parser";
  } catch (const raster::SceneError& e) {
    parsed_message = e.what(), parsed_pointer = e.where().pointer;
  }
  raster::Scene built = raster::parse_scene(
      R"({"width": 8, "height": 8, "primitives": [{"type": "triangle", "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]})");
  built.camera.eye = built.camera.target = {1, 2, 3};
  built.camera.has_eye = built.camera.has_target = true;
  try {
    raster::plan(built);
    ADD_FAILURE() << "eye == target must be rejected by the plan of a scene built in code";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.what(), parsed_message);
    EXPECT_EQ(e.where().pointer, parsed_pointer);
    EXPECT_EQ(e.where().pointer, "/camera/target");
  }
  built.camera.has_target = false;  // the fitted target (the content's centre) is not the eye: fine
  EXPECT_NO_THROW(raster::plan(built));
}

// Contract: the plan lists only what is drawn, each with its scene index (no array kept parallel to the
// scene's), and it alone decides whether a wide line interpolates colour.
TEST(Contracts, ThePlanOwnsThePerPrimitiveDecisions) {
  SceneBuilder s(32, 32);
  s.line({-90, -90}, {-80, -80}, test::kRed)             // culled
      .line({2, 2}, {30, 20}, test::kRed, test::kRed)    // wide, one colour
      .line({2, 20}, {30, 4}, test::kRed, test::kBlue);  // wide, two colours
  s.scene.primitives[1].width = s.scene.primitives[2].width = 3;
  const raster::RenderPlan p = raster::plan(s.scene);
  ASSERT_EQ(p.draws.size(), 2u);
  EXPECT_EQ(p.draws[0].primitive, 1u);
  EXPECT_EQ(p.draws[1].primitive, 2u);
  EXPECT_EQ(p.draw_of(0), nullptr);
  EXPECT_FALSE(p.draw_of(1)->mode.smooth) << "equal endpoint colours: one colour, decided by the plan";
  EXPECT_TRUE(p.draw_of(2)->mode.smooth);
  // The render obeys it: the one-colour line's pixels are all pure red.
  SceneBuilder only(32, 32);
  only.line({2, 2}, {30, 20}, test::kRed, test::kRed);
  only.scene.primitives[0].width = 3;
  const raster::Image img = raster::render(only.scene, raster::plan(only.scene));
  int red = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const Rgba8 c = test::pixel(img, x, y);
      EXPECT_TRUE(c == test::kRed || c == test::kBlack) << x << "," << y;
      red += c == test::kRed;
    }
  EXPECT_GT(red, 60);
}

}  // namespace

// With centre coverage a triangle that holds no pixel centre draws nothing, so setup writes no record for
// it (a dense model's triangles are mostly smaller than a pixel); with multisampling it may cover a sample
// and keeps its record. Counted by RenderStats::records.
TEST(Core, ATriangleHoldingNoPixelCentreGetsNoRecord) {
  auto records = [](const raster::Scene& scene) {
    raster::RenderStats stats;
    raster::RenderControl control;
    control.stats = &stats;
    const raster::Image image = raster::render(scene, raster::plan(scene), control);
    return std::pair{stats.records, test::count_not(image, test::kBlack)};
  };
  SceneBuilder corner(16, 16);  // inside pixel (5, 5), away from its centre (5.5, 5.5)
  corner.triangle({5.05, 5.05}, {5.4, 5.05}, {5.05, 5.4}, test::kWhite);
  EXPECT_EQ(records(corner.scene), std::pair(std::int64_t{0}, 0));
  SceneBuilder between(16, 16);  // a sliver between two rows of centres
  between.triangle({4.6, 4.9}, {7.4, 5.2}, {7.4, 5.3}, test::kWhite);
  EXPECT_EQ(records(between.scene), std::pair(std::int64_t{0}, 0));
  SceneBuilder diagonal(16, 16);  // its box holds nine centres, it covers none (each lies below it)
  diagonal.triangle({4.0, 4.3}, {7.0, 7.2}, {7.0, 7.4}, test::kWhite);
  EXPECT_EQ(records(diagonal.scene), std::pair(std::int64_t{0}, 0));
  SceneBuilder centre(16, 16);  // the same size around a centre: one record, one pixel
  centre.triangle({5.3, 5.3}, {5.7, 5.3}, {5.5, 5.7}, test::kWhite);
  EXPECT_EQ(records(centre.scene), std::pair(std::int64_t{1}, 1));
  // Multisampled, the same holds of the pattern's samples: the corner triangle covers none of the four (its
  // hypotenuse x + y = 10.45 passes below (5.375, 5.125), the nearest), so it gets no record; grown to take
  // that sample in, it gets one and colours its pixel. What would break: the probe missing a covered sample
  // (the pixel lost), or a triangle kept for its box alone (a record per sub-sample sliver of a dense mesh).
  corner.scene.antialias = raster::Antialias::msaa4;
  EXPECT_EQ(records(corner.scene), std::pair(std::int64_t{0}, 0));
  SceneBuilder sample(16, 16);
  sample.triangle({5.05, 5.05}, {5.5, 5.05}, {5.05, 5.5}, test::kWhite);
  sample.scene.antialias = raster::Antialias::msaa4;
  EXPECT_EQ(records(sample.scene), std::pair(std::int64_t{1}, 1));
  for (const raster::Antialias aa : {raster::Antialias::msaa8, raster::Antialias::msaa16}) {
    corner.scene.antialias = aa;  // denser patterns have a sample in the corner triangle
    const auto [kept, pixels] = records(corner.scene);
    EXPECT_EQ(kept, pixels);
  }
}

namespace {

// Multisampled storage keeps one colour a pixel until its samples differ (and again once a write covers
// them all): the same bytes as keeping a colour per sample throughout (RenderPlan::keep_samples). The mixed
// 2D scenes (flat, smooth, translucent, slivers, huge, lines, polylines, outlines, the lit mesh), large
// smooth triangles over an opaque and a transparent background, and the 3D mesh cases with points added,
// at 4, 8 and 16 samples, tiles of 16 and 64 px, 1 and 3 threads.
TEST(Core, CompressedSamplesGiveTheBytesOfASampleEach) {
  auto render_at = [](const raster::Scene& scene, int tile, int threads, bool keep) {
    raster::PlanOptions options;
    options.tile = tile, options.max_threads = threads, options.keep_samples = keep;
    raster::RenderPlan plan = raster::plan(scene, {}, options);
    plan.threads = threads;
    return raster::render(scene, plan);
  };
  std::vector<std::pair<std::string, raster::Scene>> scenes;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    scenes.emplace_back("mixed " + std::to_string(seed), mixed_scene(seed, 160));
    scenes.emplace_back("large, transparent " + std::to_string(seed), large_smooth_scene(seed, seed != 2));
  }
  for (MeshCase& c : simd_mesh_cases(7)) {
    raster::Mesh& m = c.scene.meshes[0];
    for (std::size_t i = 0; i < m.positions.size(); i += 7) m.points.push_back(static_cast<std::uint32_t>(i));
    scenes.emplace_back(c.name, c.scene);
  }
  for (auto& [name, scene] : scenes) {
    scene.antialias = raster::Antialias::none;
    const raster::Image aliased = render_at(scene, 64, 1, false);
    for (int samples : {4, 8, 16}) {
      scene.antialias = test::multisample(samples);
      const raster::Image compressed = render_at(scene, 64, 1, false);
      // The 2D scenes' edges cross their pixels, so some pixel's samples differ (the picture is not the
      // aliased one): the compressed storage expanded pixels and resolved them, and the comparison below is
      // of that, not of two one-colour buffers. (A 3D case may fill the image edge to edge.)
      if (name.starts_with("mixed") || name.starts_with("large")) {
        ASSERT_NE(compressed.pixels, aliased.pixels) << name << ", " << samples << " samples";
      }
      for (int tile : {16, 64})
        for (int threads : {1, 3})
          ASSERT_EQ(render_at(scene, tile, threads, true).pixels, compressed.pixels)
              << name << ", " << samples << " samples, tile " << tile << ", " << threads << " threads";
    }
  }
}

}  // namespace
