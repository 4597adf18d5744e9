// End to end, per stage, on the seeded reference scenes: parse (JSON text -> Scene), raster (plan +
// render), encode (our PNG), and stock stb's encoder on the same pixels, at 1 and 2 threads. Medians of
// repeated runs, side by side in one process.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "raster/raster.h"
#include "scenes.h"
#include "stb_stock.h"

namespace {

double median_ms(int runs, const std::function<void()>& fn) {
  std::vector<double> ms;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

// LP_NUM_THREADS=t osmesa_peer: llvmpipe reads its thread count once per process.
std::map<std::string, double> peer_ms(const std::string& peer, int threads, int runs) {
  std::map<std::string, double> out;
  const std::string command =
      "LP_NUM_THREADS=" + std::to_string(threads) + " " + peer + " " + std::to_string(runs);
  if (FILE* f = popen(command.c_str(), "r")) {
    char name[32];
    double ms = 0;
    while (std::fscanf(f, "%31s %lf", name, &ms) == 2) out[name] = ms;
    pclose(f);
  }
  return out;
}

}  // namespace

// Usage: e2e [runs] [path/to/osmesa_peer]. Prints a Markdown table (one row per scene and thread count)
// and the ratios against llvmpipe + stock stb.
int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 11;
  const std::string peer = argc > 2 ? argv[2] : "";
  std::printf(
      "| scene | threads | JSON MB | parse ms | parse MB/s | raster ms | encode ms | **total ms** | llvmpipe "
      "raster ms | stb encode ms | raster vs llvmpipe | encode vs stb | **e2e vs llvmpipe+stb** | PNG KB "
      "(stb KB) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::map<int, std::map<std::string, double>> llvmpipe;
  if (!peer.empty())
    for (int t : {1, 2}) llvmpipe[t] = peer_ms(peer, t, runs);
  for (const char* kind : {"small", "large", "grid"}) {
    const raster::Scene generated = bench::make_scene(kind, 1);
    const std::string json = bench::scene_json(generated);
    raster::Scene scene;
    const double parse = median_ms(runs, [&] { scene = raster::parse_scene(json); });
    for (int threads : {1, 2}) {
      raster::PlanOptions options;
      options.max_threads = threads;
      raster::Image image;
      raster::RenderPlan plan;
      const double raster_ms = median_ms(runs, [&] {
        plan = raster::plan(scene, {}, options);
        image = raster::render(scene, plan);
      });
      std::vector<std::uint8_t> png;
      const double encode = median_ms(runs, [&] { png = raster::encode_png(image, plan.png); });
      std::size_t stb_size = 0;
      const double stb =
          median_ms(std::max(3, runs / 3), [&] { stb_size = bench::stb_stock_png_size(image); });
      const double total = parse + raster_ms + encode;
      const double peer_raster =
          llvmpipe.count(threads) && llvmpipe[threads].count(kind) ? llvmpipe[threads][kind] : 0;
      auto ratio = [](double theirs, double ours) {
        char buf[32];
        if (theirs <= 0) return std::string("n/a");
        std::snprintf(buf, sizeof buf, "%.2fx", theirs / ours);
        return std::string(buf);
      };
      std::printf(
          "| %s | %d | %.2f | %.1f | %.0f | %.2f | %.2f | **%.1f** | %.2f | %.2f | %s | %s | **%s** | %zu "
          "(%zu) |\n",
          kind, threads, json.size() / 1e6, parse, json.size() / 1e6 / (parse / 1e3), raster_ms, encode,
          total, peer_raster, stb, ratio(peer_raster, raster_ms).c_str(), ratio(stb, encode).c_str(),
          ratio(peer_raster > 0 ? peer_raster + stb : 0, total).c_str(), png.size() / 1024, stb_size / 1024);
    }
  }
}
