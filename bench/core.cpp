// The raster core's targets (2D: issue 30; meshes: issue 29), side by side with llvmpipe in one run: plan +
// render time of the 2D scenes and the 3D meshes at 1 and 2 threads, flat fill rate against memset's
// bandwidth, and the bytes the tile bins take. Usage: core [runs] [path/to/osmesa_peer]. Prints Markdown.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "peer.h"
#include "raster/raster.h"
#include "scenes.h"
#include "timing.h"

namespace {

// Pixels a scene's triangles cover, from their areas (edges shared or overlapping count twice, as they
// are written twice).
double covered_pixels(const raster::Scene& s) {
  double sum = 0;
  for (const raster::Primitive& p : s.primitives) {
    const raster::Point2* q = &s.points[p.first_point];
    sum += std::fabs((q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x)) / 2;
  }
  return sum;
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 11;
  const std::string peer = argc > 2 ? argv[2] : "";
  std::map<int, std::map<std::string, double>> llvmpipe;
  if (!peer.empty())
    for (int t : {1, 2}) llvmpipe[t] = bench::peer_ms(peer, t, runs);

  struct Target {
    const char* kind;
    double ratio;  // required llvmpipe time / ours
  };
  const Target targets[] = {{"small", 2.5}, {"large", 3},    {"grid", 2},
                            {"flat", 2},    {"sphere", 1.5}, {"bunny", 2}};
  std::printf("| scene | threads | triangles | raster ms | llvmpipe ms | vs llvmpipe | target | verdict |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---|\n");
  std::map<std::string, double> flat_ms;
  std::map<std::string, std::map<int, double>> raster_ms;  // scene -> threads -> median ms
  raster::Scene flat_scene;
  for (const Target& t : targets) {
    raster::Scene scene;
    try {
      const std::string kind = t.kind;
      scene = kind == "sphere" || kind == "bunny" ? bench::mesh_scene(kind) : bench::make_scene(kind, 1);
    } catch (const std::exception& e) {
      std::printf("| %s | | | %s | | | | |\n", t.kind, e.what());
      continue;
    }
    const std::size_t triangles =
        scene.meshes.empty() ? scene.primitives.size() : scene.meshes[0].triangles.size();
    for (int threads : {1, 2}) {
      raster::PlanOptions options;
      options.max_threads = threads;
      raster::Image image;
      const double ms =
          bench::median_ms(runs, [&] { image = raster::render(scene, raster::plan(scene, {}, options)); });
      raster_ms[t.kind][threads] = ms;
      const double theirs =
          llvmpipe.count(threads) && llvmpipe[threads].count(t.kind) ? llvmpipe[threads][t.kind] : 0;
      const double ratio = theirs > 0 ? theirs / ms : 0;
      std::printf("| %s | %d | %zu | %.2f | %.2f | %.2fx | %.1fx | %s |\n", t.kind, threads, triangles, ms,
                  theirs, ratio, t.ratio,
                  theirs <= 0        ? "n/a"
                  : ratio >= t.ratio ? "met"
                                     : "**gap**");
      if (std::string(t.kind) == "flat") flat_ms[std::to_string(threads)] = ms, flat_scene = scene;
    }
  }

  // Where the time goes, one thread, and what the bins cost.
  std::printf(
      "\nStages at 1 thread (milliseconds, median of %d; geometry includes transform, clipping and setup"
      " of every record; tiles are coverage and shading):\n\n",
      runs);
  std::printf(
      "| scene | geometry + setup | bin | clear | tiles | records | bin entries | bin bytes | bytes per "
      "record-tile |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  struct Stages {
    double geometry, bin, clear, tiles;
  };
  std::map<std::string, Stages> stage;
  for (const char* kind : {"small", "large", "grid", "sphere", "bunny"}) {
    raster::Scene scene;
    try {
      const std::string k = kind;
      scene = k == "sphere" || k == "bunny" ? bench::mesh_scene(k) : bench::make_scene(k, 1);
    } catch (const std::exception&) {
      continue;
    }
    raster::PlanOptions options;
    options.max_threads = 1;
    const raster::RenderPlan plan = raster::plan(scene, {}, options);
    std::vector<double> g, b, c, t;
    raster::RenderStats stats;
    for (int r = 0; r < runs; ++r) {
      raster::RenderControl control;
      control.stats = &stats;
      raster::render(scene, plan, control);
      g.push_back(stats.geometry_ms), b.push_back(stats.bin_ms), c.push_back(stats.clear_ms),
          t.push_back(stats.tiles_ms);
    }
    stage[kind] = {bench::median(g), bench::median(b), bench::median(c), bench::median(t)};
    std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %lld | %lld | %lld | %.1f |\n", kind, bench::median(g),
                bench::median(b), bench::median(c), bench::median(t), static_cast<long long>(stats.records),
                static_cast<long long>(stats.bin_entries), static_cast<long long>(stats.bin_bytes),
                stats.bin_entries ? double(stats.bin_bytes) / double(stats.bin_entries) : 0.0);
  }

  // What blocks the gaps, from the stage times above.
  if (stage.count("sphere")) {
    const Stages& st = stage["sphere"];
    std::printf(
        "\nWhere the sphere's time goes at 1 thread: geometry + setup %.0f%% (%.1f ms: "
        "each vertex transformed and its angle-weighted normal computed once, facing per face, "
        "and one 88-byte record plus 76 bytes of attributes for each triangle that holds a pixel "
        "centre), tiles %.0f%% (%.1f ms). Every stage but the plan runs on all the render's threads: "
        "vertices, normals and triangles in pieces, each piece's records binned on their own.\n",
        100 * st.geometry / (st.geometry + st.bin + st.clear + st.tiles), st.geometry,
        100 * st.tiles / (st.geometry + st.bin + st.clear + st.tiles), st.tiles);
    if (raster_ms["sphere"].count(1) && raster_ms["sphere"].count(2)) {
      const double speedup = raster_ms["sphere"][1] / raster_ms["sphere"][2];
      std::printf("The sphere from 1 thread to 2: %.2fx faster (target 1.7x: %s).\n", speedup,
                  speedup >= 1.7 ? "met" : "**gap**");
    }
  }
  if (stage.count("small")) {
    const Stages& st = stage["small"];
    std::printf(
        "Where the small scene's time goes at 1 thread: tiles %.1f ms of %.1f (coverage of 8x8 blocks that "
        "triangles of ~44 px mostly cross, and shading per block), geometry + setup %.1f ms, bins %.1f ms.\n",
        st.tiles, st.geometry + st.bin + st.clear + st.tiles, st.geometry, st.bin);
  }

  // Tile size: the same renders at 32, 64 and 128 pixels a side.
  std::printf(
      "\nTile size (raster ms, 1 / 2 threads, median of %d):\n\n| scene | 32 | 64 | 128 "
      "|\n|---|---:|---:|---:|\n",
      runs);
  for (const char* kind : {"small", "large", "grid", "sphere"}) {
    const std::string k = kind;
    const raster::Scene scene = k == "sphere" ? bench::mesh_scene(k) : bench::make_scene(k, 1);
    std::printf("| %s |", kind);
    for (int tile : {32, 64, 128}) {
      double ms[2];
      for (int threads : {1, 2}) {
        raster::PlanOptions options;
        options.max_threads = threads;
        options.tile = tile;
        ms[threads - 1] =
            bench::median_ms(runs, [&] { raster::render(scene, raster::plan(scene, {}, options)); });
      }
      std::printf(" %.2f / %.2f |", ms[0], ms[1]);
    }
    std::printf("\n");
  }

  // Flat fill rate against memset on the same colour buffer (RGB, 3 bytes a pixel), one thread.
  if (!flat_ms.empty()) {
    std::vector<std::uint8_t> buffer(std::size_t{3} * flat_scene.width * flat_scene.height);
    const double memset_ms = bench::median_ms(runs * 5, [&] {
      std::memset(buffer.data(), static_cast<int>(buffer.size() & 0xff), buffer.size());
      asm volatile("" : : "r"(buffer.data()) : "memory");
    });
    const double memset_gpx = buffer.size() / 3.0 / (memset_ms * 1e6);
    const double px =
        covered_pixels(flat_scene) + double(flat_scene.width) * flat_scene.height;  // + the clear
    const double fill_gpx = px / (flat_ms["1"] * 1e6);
    std::printf(
        "\nFlat fill, the \"flat\" scene at 1 thread (clear included): %.2f Gpx/s; memset of the RGB buffer: "
        "%.2f Gpx/s (%.1f GB/s); fill / memset = %.0f%% (target ≥ 25%%: %s)\n",
        fill_gpx, memset_gpx, buffer.size() / (memset_ms * 1e6), 100 * fill_gpx / memset_gpx,
        fill_gpx / memset_gpx >= 0.25 ? "met" : "**gap**");
  }
}
