// How late a render stops after its deadline: for scenes built to be hard to interrupt (one primitive
// covering 40 MP, 16-sample planes and their resolve, two million small triangles, a two-million-triangle
// mesh), renders with a deadline 5 ms after the start and prints the time from the deadline to the
// RenderCancelled exception (the overrun), worst of several runs, beside the full render time.
// The README's and docs/robustness.md's bound comes from this table: build-bench/bench/deadline
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "raster/raster.h"
#include "scenes.h"
#include "timing.h"

namespace {

using Clock = std::chrono::steady_clock;

raster::Antialias multisample(int samples) {
  raster::Antialias mode{};
  if (!raster::antialias_of_samples(samples, mode)) std::abort();
  return mode;
}

raster::Scene covering_triangle(int width, int height, int samples) {
  raster::Scene s;
  s.width = width, s.height = height, s.antialias = multisample(samples);
  const double w = width, h = height;
  const raster::Point2 p[3] = {{-w, -h}, {3 * w, -h}, {-w, 3 * h}};
  const raster::Rgba8 c[3] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
  bench::add_triangle(s, p, c, 3);
  return s;
}

raster::Scene mesh_scene(int n, int side, int samples) {
  std::string json = bench::flat_mesh_json(n);
  // flat_mesh_json makes a document of its own size; the image size and samples are set here
  raster::Scene s = raster::parse_scene(json);
  s.width = s.height = side;
  s.antialias = multisample(samples);
  return s;
}

}  // namespace

int main() {
  struct Case {
    const char* name;
    raster::Scene scene;
  };
  std::vector<Case> cases;
  cases.push_back({"one smooth triangle over 8192x4882 (40 MP)", covering_triangle(8192, 4882, 1)});
  cases.push_back(
      {"one triangle, 16 samples, 3200x3200 (near the storage limit)", covering_triangle(3200, 3200, 16)});
  cases.push_back({"2,000,000 triangles of +-12 px, 1024x1024", bench::random_scene(1024, 2'000'000, 12)});
  cases.push_back({"2,000,000-triangle lit mesh, 2048x2048", mesh_scene(1000, 2048, 1)});
  cases.push_back({"180,000-triangle lit mesh, 16 samples, 1024x1024", mesh_scene(300, 1024, 16)});
  cases.push_back({"2,000,000-triangle mesh as a wireframe, 2048x2048", mesh_scene(1000, 2048, 1)});
  for (raster::Mesh& m : cases.back().scene.meshes) m.wireframe = true;

  constexpr auto kDeadlineAfter = std::chrono::milliseconds(5);
  constexpr int kRuns = 5;
  std::printf("| scene | threads | full render (ms) | worst overrun past a 5 ms deadline (ms) |\n");
  std::printf("|---|---:|---:|---:|\n");
  double worst_of_all = 0;
  for (const Case& c : cases) {
    const raster::RenderPlan plan = raster::plan(c.scene);
    const double full = bench::median_ms(3, [&] { raster::render(c.scene, plan); });
    double worst = 0;
    for (int r = 0; r < kRuns; ++r) {
      raster::RenderControl control;
      control.deadline = Clock::now() + kDeadlineAfter;
      try {
        raster::render(c.scene, plan, control);
        std::printf("(%s: finished before its deadline)\n", c.name);
      } catch (const raster::RenderCancelled&) {
        worst = std::max(worst,
                         std::chrono::duration<double, std::milli>(Clock::now() - control.deadline).count());
      }
    }
    {  // a deadline already past: how long until the first look at it
      raster::RenderControl control;
      control.deadline = Clock::now();
      const auto t0 = Clock::now();
      try {
        raster::render(c.scene, plan, control);
      } catch (const raster::RenderCancelled&) {
      }
      std::printf("(%s: first look after %.1f ms)\n", c.name, bench::ms_since(t0));
    }
    worst_of_all = std::max(worst_of_all, worst);
    std::printf("| %s | %d | %.1f | %.2f |\n", c.name, plan.threads, full, worst);
  }
  std::printf("\nworst overrun: %.2f ms\n", worst_of_all);
}
