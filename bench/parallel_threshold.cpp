// Measures where splitting a render into two bands starts to pay: renders seeded scenes of growing size
// with 1 and with 2 threads, side by side in one run, and prints the plan's work estimate with both times.
// The plan's kParallelWorkThreshold is set from this table.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "raster/raster.h"
#include "scenes.h"

namespace {

raster::Scene scene_of(int side, int triangles, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0, side), offset(-side / 8.0, side / 8.0);
  raster::Scene s;
  s.width = s.height = side;
  auto color = [&] {
    return raster::Rgba8{static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                         static_cast<std::uint8_t>(rng()), 255};
  };
  for (int i = 0; i < triangles; ++i) {
    const double cx = pos(rng), cy = pos(rng);
    const raster::Point2 p[3] = {{cx + offset(rng), cy + offset(rng)},
                                 {cx + offset(rng), cy + offset(rng)},
                                 {cx + offset(rng), cy + offset(rng)}};
    const raster::Rgba8 c[3] = {color(), color(), color()};
    bench::add_triangle(s, p, c, 3);
  }
  return s;
}

double median_ms(const raster::Scene& scene, raster::RenderPlan plan, int threads) {
  plan.threads = threads;
  std::vector<double> ms;
  for (int r = 0; r < 31; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const raster::Image img = raster::render(scene, plan);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (img.pixels.empty()) std::puts("");  // keep the render observable
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

int main() {
  std::printf("%6s %6s %12s %10s %10s %8s\n", "side", "tris", "work", "1 thr ms", "2 thr ms", "2/1");
  for (int side : {64, 128, 181, 256, 362, 512, 724, 1024}) {
    for (int tris : {4, 32}) {
      const raster::Scene scene = scene_of(side, tris, 42);
      const raster::RenderPlan plan = raster::plan(scene);
      const double one = median_ms(scene, plan, 1), two = median_ms(scene, plan, 2);
      std::printf("%6d %6d %12lld %10.3f %10.3f %8.2f\n", side, tris, static_cast<long long>(plan.work), one,
                  two, two / one);
    }
  }
}
