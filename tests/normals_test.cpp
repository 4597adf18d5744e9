// Computed vertex normals (renderer/src/geometry/normals.h): with a vertex's mark (only the corners of the
// triangles that may draw), each marked vertex gets the bits it gets when every normal is computed, on one
// thread or several, under the identity or a transform, and on every instruction set.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstring>
#include <random>
#include <vector>

#include "base/stop.h"
#include "geometry/normals.h"

namespace {

// A seeded sphere-like mesh of `n` x `n` quads whose triangles are in a shuffled order (so that a thread's
// vertices lie in spans of triangles all over the list), with some degenerate triangles (a repeated
// corner) and vertices no triangle uses.
raster::Mesh seeded_mesh(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> bump(-0.05, 0.05);
  raster::Mesh mesh;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < n; ++j) {
      const double t = pi * i / n, p = 2 * pi * j / n, r = 1 + bump(rng);
      mesh.positions.push_back(raster::Vec3f(
          raster::Vec3{r * std::sin(t) * std::cos(p), r * std::cos(t), r * std::sin(t) * std::sin(p)}));
    }
  mesh.positions.push_back(raster::Vec3f(raster::Vec3{5, 5, 5}));  // used by no triangle
  const auto u = static_cast<std::uint32_t>(n);
  for (std::uint32_t i = 0; i < u; ++i)
    for (std::uint32_t j = 0; j < u; ++j) {
      const std::uint32_t a = i * u + j, b = i * u + (j + 1) % u, c = a + u, d = b + u;
      mesh.triangles.push_back({a, c, b});
      mesh.triangles.push_back(rng() % 50 ? std::array<std::uint32_t, 3>{b, c, d}
                                          : std::array<std::uint32_t, 3>{b, b, d});
    }
  std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), rng);
  mesh.colors = {{200, 200, 200, 255}};
  return mesh;
}

raster::detail::PodArray<raster::Vec3> normals_of(const raster::Mesh& mesh,
                                                  std::span<const raster::Vec3> world, int threads,
                                                  raster::Simd simd, const std::uint8_t* needed) {
  std::atomic<bool> never{false};
  const raster::detail::Stop stop{std::chrono::steady_clock::time_point::max(), nullptr, &never, nullptr};
  raster::detail::StopMeter meter(stop);
  return raster::detail::vertex_normals(mesh, world, threads, simd, meter, needed);
}

bool same_bits(const raster::Vec3& a, const raster::Vec3& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(Normals, MarkedVerticesGetTheBitsOfEveryVertex) {
  const raster::Mesh mesh = seeded_mesh(60, 3);
  // A transform's world positions, as MeshView holds them.
  std::vector<raster::Vec3> world;
  for (const raster::Vec3f& p : mesh.positions) world.push_back({p.x * 3.5 - 1, p.y * 0.25 + 2, p.z * -2.0});
  std::mt19937 rng(11);
  for (int density : {0, 3, 30, 100}) {  // percent of the vertices marked
    std::vector<std::uint8_t> needed(mesh.positions.size());
    for (std::uint8_t& b : needed) b = static_cast<int>(rng() % 100) < density;
    for (const bool transformed : {false, true}) {
      const std::span<const raster::Vec3> w =
          transformed ? std::span<const raster::Vec3>(world) : std::span<const raster::Vec3>();
      const auto every = normals_of(mesh, w, 1, raster::Simd::sse2, nullptr);
      for (raster::Simd simd : {raster::Simd::sse2, raster::best_simd()})
        for (int threads : {1, 2, 3, 7}) {
          const auto marked = normals_of(mesh, w, threads, simd, needed.data());
          std::size_t wrong = 0, unmarked_not_zero = 0;
          for (std::size_t v = 0; v < needed.size(); ++v)
            if (needed[v])
              wrong += !same_bits(marked[v], every[v]);
            else
              unmarked_not_zero += !same_bits(marked[v], raster::Vec3{});
          EXPECT_EQ(wrong, 0u) << density << "% marked, " << threads << " threads, transformed "
                               << transformed;
          EXPECT_EQ(unmarked_not_zero, 0u) << density << "% marked, " << threads << " threads";
          // And unmarked: every normal, the same bits on any thread count and instruction set.
          const auto all = normals_of(mesh, w, threads, simd, nullptr);
          for (std::size_t v = 0; v < needed.size(); ++v)
            ASSERT_TRUE(same_bits(all[v], every[v])) << "vertex " << v << ", " << threads << " threads";
        }
    }
  }
}

}  // namespace
