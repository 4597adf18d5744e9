// Setup's batches (renderer/src/setup/batch.h): eight triangles at a time, those whose box holds no sample
// left out before any record is made. The batch must keep every triangle the record's own test keeps
// (Setup::fast_record, which probes a small triangle's samples), give the same answer on every instruction
// set, and leave out most of a dense mesh's slivers.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "base/grid.h"
#include "setup/batch.h"
#include "setup/setup.h"

namespace {

using raster::detail::FastTriangle;
using raster::detail::ScreenVertex;

// Seeded triangles of a dense mesh's size (a few hundredths of a pixel to a few pixels), some reaching past
// the image's edge, some with a vertex that has no screen position.
struct Triangles {
  std::vector<ScreenVertex> screen;
  std::vector<std::array<std::uint32_t, 3>> indices;
};

Triangles seeded(unsigned seed, int width, int height) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::int32_t> where_x(-600, width * 256 + 600),
      where_y(-600, height * 256 + 600);
  std::uniform_int_distribution<int> size_log(0, 10);
  Triangles t;
  for (int i = 0; i < 4000; ++i) {
    const std::int32_t x = where_x(rng), y = where_y(rng), reach = 1 << size_log(rng);
    std::uniform_int_distribution<std::int32_t> off(-reach, reach);
    const auto first = static_cast<std::uint32_t>(t.screen.size());
    for (int k = 0; k < 3; ++k) {
      ScreenVertex v{x + off(rng), y + off(rng), 0.5f, 1.0f};
      if (rng() % 97 == 0) v = {raster::detail::kNoScreen, 0, 0, 0};
      t.screen.push_back(v);
    }
    t.indices.push_back({first, first + 1, first + 2});
  }
  return t;
}

TEST(SetupBatch, BatchesKeepEveryTriangleThatCoversASample) {
  const int width = 37, height = 29;
  const raster::detail::SamplePoint centre{};
  for (const int samples : {1, 4, 8, 16}) {
    raster::detail::Setup setup;
    setup.width = width, setup.height = height;
    setup.centre_samples = samples == 1;
    const raster::detail::SamplePoint* pattern =
        samples == 1 ? &centre : raster::detail::sample_pattern(samples).data();
    if (samples > 1) setup.pattern = pattern, setup.pattern_size = samples;
    const Triangles t = seeded(static_cast<unsigned>(samples), width, height);
    int left_out = 0, kept = 0;
    for (std::size_t first = 0; first < t.indices.size(); first += 8) {
      const int n = static_cast<int>(std::min<std::size_t>(8, t.indices.size() - first));
      const std::uint32_t bits = raster::detail::sample_candidates(
          &t.indices[first], n, t.screen.data(), pattern, samples, width, height, raster::Simd::sse2);
      if (raster::best_simd() == raster::Simd::avx2) {
        EXPECT_EQ(raster::detail::sample_candidates(&t.indices[first], n, t.screen.data(), pattern, samples,
                                                    width, height, raster::Simd::avx2),
                  bits)
            << samples << " samples, triangles " << first << "..";
      }
      for (int i = 0; i < n; ++i) {
        const auto& tri = t.indices[first + static_cast<std::size_t>(i)];
        bool projected = true;
        FastTriangle fast;
        for (int k = 0; k < 3; ++k) {
          projected &= t.screen[tri[k]].x != raster::detail::kNoScreen;
          fast.x[k] = t.screen[tri[k]].x, fast.y[k] = t.screen[tri[k]].y;
        }
        raster::detail::TriangleRecord r;
        int order[3];
        const bool recorded = projected && setup.fast_record(fast, r, order);
        kept += recorded;
        if (!(bits >> i & 1)) {
          ++left_out;
          EXPECT_TRUE(projected) << "a triangle that may be clipped was left out";
          EXPECT_FALSE(recorded) << samples << " samples: a triangle that covers a sample was left out";
        }
      }
    }
    EXPECT_GT(kept, 100) << samples;
    EXPECT_GT(left_out, 1000) << samples << " samples: the batches leave out too few";
  }
}

}  // namespace
