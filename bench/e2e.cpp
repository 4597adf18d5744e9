// End to end, per stage, on the seeded reference scenes: parse (JSON text -> Scene), raster (plan +
// render), encode (our PNG), and stock stb's encoder on the same pixels, at 1 and 2 threads. Medians of
// repeated runs, side by side in one process.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <tiny_obj_loader.h>

#include "peer.h"
#include "raster/raster.h"
#include "scenes.h"
#include "stb_stock.h"
#include "timing.h"
#include "wall.h"

// Usage: e2e [runs] [path/to/osmesa_peer] [path/to/rasterd]. Prints a Markdown table (one row per scene and
// thread count) and the ratios against llvmpipe + stock stb.
int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 11;
  const std::string peer = argc > 2 ? argv[2] : "";
  const std::string rasterd = argc > 3 ? argv[3] : "";
  std::map<std::string, bench::WallTimes> wall;
  std::printf(
      "| scene | threads | JSON MB | parse ms | parse MB/s | raster ms | encode ms | **total ms** | llvmpipe "
      "raster ms | stb encode ms | raster vs llvmpipe | encode vs stb | **e2e vs llvmpipe+stb** | PNG KB "
      "(stb KB) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  struct Result {
    double parse_mbs, raster, encode, total, peer, stb;
    std::size_t png, stb_png;
  };
  std::map<std::string, std::map<int, Result>> results;
  std::map<int, std::map<std::string, double>> llvmpipe;
  if (!peer.empty())
    for (int t : {1, 2}) llvmpipe[t] = bench::peer_ms(peer, t, runs);
  for (const char* kind : {"small", "large", "grid"}) {
    const raster::Scene generated = bench::make_scene(kind, 1);
    const std::string json = bench::scene_json(generated);
    // Parse only: each run's scene is released after its time is taken.
    raster::Scene scene;
    std::vector<double> parse_runs;
    for (int r = 0; r < runs; ++r) {
      const auto start = std::chrono::steady_clock::now();
      raster::Scene parsed = raster::parse_scene(json);
      parse_runs.push_back(bench::ms_since(start));
      if (r == 0) scene = std::move(parsed);
    }
    const double parse = bench::median(parse_runs);
    if (!rasterd.empty()) wall[kind] = bench::wall_times(rasterd, json, std::max(3, runs / 2));
    for (int threads : {1, 2}) {
      raster::PlanOptions options;
      options.max_threads = threads;
      raster::Image image;
      raster::RenderPlan plan;
      const double raster_ms = bench::median_ms(runs, [&] {
        plan = raster::plan(scene, {}, options);
        image = raster::render(scene, plan);
      });
      // As the service encodes: consuming the image (filtered in place); the copy it consumes is made
      // outside the timed part.
      std::vector<std::uint8_t> png;
      std::vector<double> encode_runs;
      for (int r = 0; r < runs; ++r) {
        raster::Image consumed;  // with the spare byte per row the framebuffer reserves
        consumed.width = image.width, consumed.height = image.height, consumed.format = image.format;
        consumed.pixels.reserve(image.pixels.size() + static_cast<std::size_t>(image.height));
        consumed.pixels = image.pixels;
        const auto start = std::chrono::steady_clock::now();
        png = raster::encode_png(std::move(consumed), plan.png);
        encode_runs.push_back(bench::ms_since(start));
      }
      const double encode = bench::median(encode_runs);
      std::size_t stb_size = 0;
      const double stb =
          bench::median_ms(std::max(3, runs / 3), [&] { stb_size = bench::stb_stock_png_size(image); });
      const double total = parse + raster_ms + encode;
      const double peer_raster =
          llvmpipe.count(threads) && llvmpipe[threads].count(kind) ? llvmpipe[threads][kind] : 0;
      auto ratio = [](double theirs, double ours) {
        char buf[32];
        if (theirs <= 0) return std::string("n/a");
        std::snprintf(buf, sizeof buf, "%.2fx", theirs / ours);
        return std::string(buf);
      };
      results[kind][threads] = {json.size() / 1e6 / (parse / 1e3),
                                raster_ms,
                                encode,
                                total,
                                peer_raster,
                                stb,
                                png.size(),
                                stb_size};
      std::printf(
          "| %s | %d | %.2f | %.1f | %.0f | %.2f | %.2f | **%.1f** | %.2f | %.2f | %s | %s | **%s** | %zu "
          "(%zu) |\n",
          kind, threads, json.size() / 1e6, parse, json.size() / 1e6 / (parse / 1e3), raster_ms, encode,
          total, peer_raster, stb, ratio(peer_raster, raster_ms).c_str(), ratio(stb, encode).c_str(),
          ratio(peer_raster > 0 ? peer_raster + stb : 0, total).c_str(), png.size() / 1024, stb_size / 1024);
    }
  }
  // Verdicts against issue 6's targets, from the numbers above (worst of 1 and 2 threads); what blocks a
  // target is printed only where it is not met.
  auto worst = [&](const char* kind, auto ratio) {
    double w = 1e9;
    for (int t : {1, 2}) w = std::min(w, ratio(results[kind][t]));
    return w;
  };
  auto raster_ratio = [](const Result& r) { return r.peer > 0 ? r.peer / r.raster : 0.0; };
  auto encode_ratio = [](const Result& r) { return r.stb / r.encode; };
  auto e2e_ratio = [](const Result& r) { return r.peer > 0 ? (r.peer + r.stb) / r.total : 0.0; };
  auto row = [](const std::string& target, const std::string& measured, bool met, const char* why) {
    std::printf("| %s | %s | %s | %s |\n", target.c_str(), measured.c_str(), met ? "met" : "**gap**",
                met ? "" : why);
  };
  auto fmt = [](const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return std::string(buf);
  };
  // Through the binary, at its default thread count (every core), against llvmpipe at as many threads.
  const int cores = static_cast<int>(std::min(2u, std::max(1u, std::thread::hardware_concurrency())));
  if (!wall.empty()) {
    std::printf(
        "\nThrough the binary (`rasterd render file -o /dev/null`, and POST /render to `rasterd serve` on "
        "loopback), wall clock, medians of %d, against llvmpipe at %d threads + stb:\n\n",
        std::max(3, runs / 2), cores);
    std::printf(
        "| scene | CLI ms | HTTP ms | llvmpipe + stb ms | CLI vs llvmpipe+stb | HTTP vs llvmpipe+stb |\n");
    std::printf("|---|---:|---:|---:|---:|---:|\n");
    for (const char* k : {"small", "large", "grid"}) {
      const double theirs = results[k][cores].peer + results[k][cores].stb;
      std::printf("| %s | %.1f | %.1f | %.1f | %.2fx | %.2fx |\n", k, wall[k].cli_ms, wall[k].http_ms, theirs,
                  theirs / wall[k].cli_ms, theirs / wall[k].http_ms);
    }
  }

  std::printf("\n## Targets (issue 6), from the tables above\n\n");
  std::printf(
      "| target | measured (worst of 1 and 2 threads) | verdict | what blocks it |\n|---|---|---|---|\n");
  const double small_r = worst("small", raster_ratio), large_r = worst("large", raster_ratio);
  const double grid_r = worst("grid", raster_ratio);
  row("raster ≥ 2× llvmpipe, small", fmt("%.2fx", small_r), small_r >= 2,
      "per-triangle setup and per-row span starts dominate on triangles of ~44 px (callgrind: ~3,700 "
      "instructions per triangle); llvmpipe rasterizes 4x4 blocks with SIMD");
  row("raster ≥ 1× llvmpipe, large", fmt("%.2fx", large_r), large_r >= 1,
      "per block the smooth kernel recomputes its four starting values from the exact edge values (AVX2 "
      "rows since issue 30)");
  row("raster ≥ 1× llvmpipe, grid", fmt("%.2fx", grid_r), grid_r >= 1, "flat spans are plain stores");
  double enc = 1e9;
  bool smaller = true;
  for (const char* k : {"small", "large", "grid"}) {
    enc = std::min(enc, worst(k, encode_ratio));
    for (int t : {1, 2}) smaller = smaller && results[k][t].png <= results[k][t].stb_png;
  }
  row("PNG ≥ 5× stb's encoder, no larger",
      fmt("%.2fx (worst scene), ", enc) +
          (smaller ? "files smaller on every scene" : "a file LARGER than stb's"),
      enc >= 5 && smaller, "deflate itself (see the encoder sweep below)");
  double mbs = 1e9;
  for (const char* k : {"small", "grid"}) mbs = std::min(mbs, results[k][1].parse_mbs);
  row("parsing ≥ 500 MB/s", fmt("%.0f MB/s (worst of small, grid)", mbs), mbs >= 500,
      "the streaming reader is one scalar pass at ~19 instructions per byte (callgrind, parse/small: digit "
      "loops 21%, string scans and hex colours 23%, punctuation 16%, storing into the scene 14%); more "
      "needs SIMD scanning (simdjson's structural index, allocated at 4 bytes per input byte)");
  // End to end: the worst scene, and which of our stages costs most there.
  double e2e = 1e9;
  std::string worst_kind;
  int worst_threads = 1;
  for (const char* k : {"small", "large", "grid"})
    for (int t : {1, 2})
      if (e2e_ratio(results[k][t]) < e2e) e2e = e2e_ratio(results[k][t]), worst_kind = k, worst_threads = t;
  const Result& w = results[worst_kind][worst_threads];
  const double parse_ms = w.total - w.raster - w.encode;
  const char* stage = parse_ms >= w.raster && parse_ms >= w.encode ? "parse"
                      : w.raster >= w.encode                       ? "raster"
                                                                   : "encode";
  const std::string why = "on the " + worst_kind + " scene at " + std::to_string(worst_threads) +
                          " thread(s) our " + stage + " is the largest stage (parse " +
                          fmt("%.1f", parse_ms) + " ms, raster " + fmt("%.1f", w.raster) + " ms, encode " +
                          fmt("%.1f", w.encode) +
                          " ms); a 5x margin needs every stage 5x under llvmpipe's raster + stb's encode";
  row("end to end ≥ 5× llvmpipe + stb, in process", fmt("%.2fx (worst scene)", e2e), e2e >= 5, why.c_str());
  if (!wall.empty()) {
    double cli = 1e9, http = 1e9;
    for (const char* k : {"small", "large", "grid"}) {
      const double theirs = results[k][cores].peer + results[k][cores].stb;
      cli = std::min(cli, theirs / wall[k].cli_ms);
      http = std::min(http, theirs / wall[k].http_ms);
    }
    row("end to end ≥ 5× llvmpipe + stb, CLI", fmt("%.2fx (worst scene)", cli), cli >= 5,
        "the in-process stages above, plus process start and reading the file");
    row("end to end ≥ 5× llvmpipe + stb, HTTP", fmt("%.2fx (worst scene)", http), http >= 5,
        "the in-process stages above, plus moving the request and the PNG over loopback");
  }

  // 2D through the service (issue 30's targets): a warm server's Server-Timing raster, which includes what a
  // request really pays (buffers, the clear), against llvmpipe's draw of the same triangles; and what a
  // fresh server's first requests cost for a thumbnail.
  if (!rasterd.empty()) {
    const int counted = std::max(5, runs);
    std::printf(
        "\n## 2D through the service (issue 30)\n\n"
        "A warm `rasterd serve` (render threads: every core) answering POST /render with each scene's JSON, "
        "medians of %d requests of its Server-Timing *raster* (after four not counted), against llvmpipe "
        "drawing the same triangles at %d threads (the core table's run). Targets: large ≥ 3×, small ≥ 2.5×, "
        "grid ≥ 2×.\n\n"
        "| scene | raster ms | llvmpipe ms | vs llvmpipe | target | verdict "
        "|\n|---|---:|---:|---:|---:|---|\n",
        counted, cores);
    const std::pair<const char*, double> targets[] = {{"small", 2.5}, {"large", 3}, {"grid", 2}, {"flat", 0}};
    for (const auto& [kind, target] : targets) {
      const std::string json = bench::scene_json(bench::make_scene(kind, 1));
      const bench::ServerTimes ours = bench::server_times(rasterd, json, "", counted, "application/json");
      const double peer = llvmpipe.count(cores) && llvmpipe[cores].count(kind) ? llvmpipe[cores][kind] : 0;
      const double ratio = peer > 0 ? peer / ours.raster_ms : 0;
      std::printf("| %s | %.2f | %.2f | %.2fx | %s | %s |\n", kind, ours.raster_ms, peer, ratio,
                  target > 0 ? fmt("%.1fx", target).c_str() : "",
                  target > 0 ? (ratio >= target ? "met" : "**gap**") : "");
    }
    // One smooth triangle at 256x256 (ab-bench's thumb-256), on a server started for it: the first request,
    // and the median of the first five.
    const std::string thumb =
        R"({"width":256,"height":256,"background":"#101418","primitives":[{"type":"triangle",)"
        R"("points":[[12.5,10],[240,52.25],[88,244]],"colors":["#ff4000","#20c0ff","#f0f0f0"]}]})";
    const bench::ServerTimes fresh = bench::server_times(rasterd, thumb, "", 5, "application/json", 0);
    const bench::ServerTimes warm = bench::server_times(rasterd, thumb, "", counted, "application/json");
    std::printf(
        "\nOne smooth triangle at 256×256 (ab-bench's *thumb-256*), Server-Timing in µs (targets on a fresh "
        "server: raster ≤ 50, encode ≤ 200):\n\n"
        "| server | raster µs | encode µs |\n|---|---:|---:|\n"
        "| fresh: first request | %.0f | %.0f |\n| fresh: median of the first 5 | %.0f | %.0f |\n"
        "| warm: median of %d | %.0f | %.0f |\n",
        fresh.first_raster_ms * 1e3, fresh.first_encode_ms * 1e3, fresh.raster_ms * 1e3,
        fresh.encode_ms * 1e3, counted, warm.raster_ms * 1e3, warm.encode_ms * 1e3);
  }

  // Models through the service (issue 29's targets): a warm server's Server-Timing for an OBJ body, against
  // tinyobjloader reading the same text in this process and llvmpipe drawing the same mesh, at 2 threads.
  if (!rasterd.empty()) {
    std::printf(
        "\n## Models through the service (issue 29)\n\n"
        "A warm `rasterd serve` (render threads: every core) answering POST /render with the model "
        "as the raw body, medians of %d requests of its Server-Timing (after four not counted); "
        "*tinyobjloader* is its `ParseFromString` on the same text in this process (triangulating, "
        "as rasterd asks it to); *llvmpipe* draws the same mesh at %d threads (depth test, the "
        "service's default lights evaluated per pixel in a fragment shader, as rasterd does). Targets: parse "
        "≤ 1.3× "
        "tinyobjloader, raster ≥ 1.5× llvmpipe (sphere) and ≥ 2× (bunny), the request ≤ 1× "
        "tinyobjloader + llvmpipe.\n\n",
        std::max(5, runs), cores);
    std::printf(
        "| model | OBJ MB | parse ms | tinyobjloader ms | parse / tinyobjloader | raster ms | llvmpipe ms | "
        "raster vs llvmpipe | request ms | request / (tinyobjloader + llvmpipe) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const char* model : {"sphere", "bunny"}) {
      std::string obj;
      std::string query;
      try {
        const raster::Scene scene = bench::mesh_scene(model);
        const raster::Mesh& mesh = scene.meshes[0];
        obj.reserve(mesh.positions.size() * 40 + mesh.triangles.size() * 30);
        char line[128];
        for (const raster::Vec3& v : mesh.positions) {
          const int n = std::snprintf(line, sizeof line, "v %.7g %.7g %.7g\n", v.x, v.y, v.z);
          obj.append(line, static_cast<std::size_t>(n));
        }
        for (const auto& t : mesh.triangles) {
          const int n = std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
          obj.append(line, static_cast<std::size_t>(n));
        }
        query = "width=" + std::to_string(scene.width) + "&height=" + std::to_string(scene.height);
      } catch (const std::exception& e) {
        std::printf("| %s | %s | | | | | | | | |\n", model, e.what());
        continue;
      }
      const double theirs_parse = bench::median_ms(std::max(5, runs), [&] {
        tinyobj::ObjReader reader;
        tinyobj::ObjReaderConfig config;
        config.triangulate = true;
        config.vertex_color = false;
        reader.ParseFromString(obj, "", config);
      });
      const bench::ServerTimes ours = bench::server_times(rasterd, obj, query, std::max(5, runs));
      const double peer_raster =
          llvmpipe.count(cores) && llvmpipe[cores].count(model) ? llvmpipe[cores][model] : 0;
      const double request = ours.parse_ms + ours.raster_ms + ours.encode_ms;
      std::printf("| %s | %.1f | %.1f | %.1f | %.2f | %.2f | %.2f | %.2fx | %.1f | %.2f |\n", model,
                  obj.size() / 1e6, ours.parse_ms, theirs_parse, ours.parse_ms / theirs_parse, ours.raster_ms,
                  peer_raster, peer_raster > 0 ? peer_raster / ours.raster_ms : 0.0, request,
                  peer_raster > 0 ? request / (theirs_parse + peer_raster) : 0.0);
    }
  }
}
