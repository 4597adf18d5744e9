// The raster core's targets (2D: issue 30; meshes: issue 41), side by side with llvmpipe in one run: plan +
// render time of the 2D scenes and the 3D meshes at 1 and 2 threads, flat fill rate against memset's
// bandwidth, and the bytes the tile bins take; issue 42's points against triangles and the default point size
// (`core --point-size` prints that table alone). Usage: core [runs] [path/to/osmesa_peer]. Prints Markdown.
// This VM runs a whole process at one of two speeds, so each side of a ratio is the fastest of kProcesses
// processes: the peer run that often per thread count, and this program re-run in its hidden mode
// (`core --measure runs`, "scene threads ms" lines), each process's medians, the minimum over processes.
// Also a bare model's default anti-aliasing against the aliased picture (issue 42), bunny and knot at 512².
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "peer.h"
#include "raster/raster.h"
#include "raster/scene_checks.h"
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

constexpr int kProcesses = 3;

struct Target {
  const char* kind;
  double ratio;  // required llvmpipe time / ours
};
constexpr Target kTargets[] = {{"small", 2.5}, {"large", 3},    {"grid", 2},
                               {"flat", 2},    {"sphere", 1.5}, {"bunny", 2}};

// Issue 42: a cloud of a million points renders in at most twice the time of a million triangles.
constexpr const char* kPointKinds[] = {"triangles_1m", "points_1m"};
constexpr double kPointsTarget = 2;  // points_1m ms / triangles_1m ms, at most

raster::Scene target_scene(const std::string& kind) {
  return kind == "sphere" || kind == "bunny" || kind == "triangles_1m" || kind == "points_1m"
             ? bench::mesh_scene(kind)
             : bench::make_scene(kind, 1);
}

// The bare models whose default anti-aliasing is held to <= kModelAntialiasCost x the aliased render
// (issue 42), as the service draws them: raster::model_scene of the file, 512x512.
struct PictureFile {
  const char* name;
  const char* path;  // from the repository's root; the bunny's $RASTERD_BUNNY wins
};
constexpr PictureFile kModelFiles[] = {{"bunny", "../shared/models/bunny.obj"},
                                       {"knot", "examples/models/knot.obj"}};
constexpr double kModelAntialiasCost = 1.5;

raster::Scene model_picture(const PictureFile& file) {
  const char* env = std::getenv("RASTERD_BUNNY");
  const bench::ModelFile model =
      bench::read_model_file(std::string(file.name) == "bunny" && env && *env ? env : file.path);
  return raster::model_scene(
      raster::checks::model_mesh(model.bytes, model.format, {}, model.files, "", "", 0, model.format),
      model.format);
}

// The hidden mode: plan + render of every target scene (or of the `only` ones, when named) at 1 and 2
// threads, medians of `runs`, one "scene threads ms" line each (a scene that cannot be made is left out; the
// parent says why); then each model picture aliased ("bunny-model-1") and at its default
// ("bunny-model-default"), unless `only` names others.
void measure(int runs, const std::vector<std::string>& only) {
  std::vector<std::string> kinds;
  for (const Target& t : kTargets) kinds.push_back(t.kind);
  for (const char* k : kPointKinds) kinds.push_back(k);
  for (const std::string& kind : kinds) {
    if (!only.empty() && std::find(only.begin(), only.end(), kind) == only.end()) continue;
    raster::Scene scene;
    try {
      scene = target_scene(kind);
    } catch (const std::exception&) {
      continue;
    }
    for (int threads : {1, 2}) {
      raster::PlanOptions options;
      options.max_threads = threads;
      raster::Image image;
      const double ms =
          bench::median_ms(runs, [&] { image = raster::render(scene, raster::plan(scene, {}, options)); });
      std::printf("%s %d %.4f\n", kind.c_str(), threads, ms);
      std::fflush(stdout);
    }
  }
  for (const PictureFile& file : kModelFiles) {
    if (!only.empty()) break;
    raster::Scene scene;
    try {
      scene = model_picture(file);
    } catch (const std::exception&) {
      continue;
    }
    for (const bool aliased : {true, false}) {
      if (aliased)
        scene.antialias = raster::Antialias::none;
      else
        scene.antialias = raster::kModelPicture.antialias;
      for (int threads : {1, 2}) {
        raster::PlanOptions options;
        options.max_threads = threads;
        const double ms =
            bench::median_ms(runs, [&] { raster::render(scene, raster::plan(scene, {}, options)); });
        std::printf("%s-model-%s %d %.4f\n", file.name, aliased ? "1" : "default", threads, ms);
        std::fflush(stdout);
      }
    }
  }
}

// One process of the hidden mode: scene -> threads -> median ms.
std::map<std::string, std::map<int, double>> measure_in_child(int runs) {
  std::map<std::string, std::map<int, double>> out;
  std::istringstream lines(bench::measure_in_child(runs));
  std::string name;
  int threads = 0;
  double ms = 0;
  while (lines >> name >> threads >> ms) out[name][threads] = ms;
  return out;
}

// The default point size (issue 42): the bunny's surface sampled as a scanner would, 100,000 points spread
// over its triangles by area (seeded), drawn at 512x512 through the camera fitted to the mesh, at each size
// in half pixels; a hole is a pixel of the mesh's own silhouette that the points leave as background.
// raster::kDefaultPointSize is the smallest size with under 1% holes.
void point_size_table() {
  raster::Scene mesh_scene;
  try {
    mesh_scene = bench::mesh_scene("bunny");
  } catch (const std::exception& e) {
    std::printf("\nPoint size: %s\n", e.what());
    return;
  }
  raster::Mesh& mesh = mesh_scene.meshes[0];
  mesh.shading = raster::Shading::unlit;
  mesh_scene.background = {0, 0, 0, 255};
  const raster::Rgba8 colour{255, 255, 255, 255};
  mesh.colors = {colour};
  const raster::RenderPlan fitted = raster::plan(mesh_scene);
  raster::Camera& camera = mesh_scene.camera;  // the mesh's fitted camera, for both renders
  camera.eye = fitted.view.eye, camera.target = fitted.view.target, camera.up = fitted.view.up;
  camera.near = fitted.view.near, camera.far = fitted.view.far;
  camera.has_eye = camera.has_target = camera.has_up = camera.has_near = camera.has_far = true;
  const raster::Image silhouette = raster::render(mesh_scene, raster::plan(mesh_scene));

  raster::Scene cloud_scene = mesh_scene;
  raster::Mesh cloud;
  std::vector<double> area_sum;  // running total of the triangles' areas
  auto at = [&](std::uint32_t i) { return mesh.positions[i]; };
  double total = 0;
  for (const auto& t : mesh.triangles) {
    const raster::Vec3 a = at(t[0]), b = at(t[1]), c = at(t[2]);
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y,
                 vz = c.z - a.z;
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    total += std::sqrt(cx * cx + cy * cy + cz * cz) / 2;
    area_sum.push_back(total);
  }
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0, 1);
  constexpr int kScanPoints = 100'000;
  for (int i = 0; i < kScanPoints; ++i) {
    const std::size_t t = std::min<std::size_t>(
        std::lower_bound(area_sum.begin(), area_sum.end(), unit(rng) * total) - area_sum.begin(),
        mesh.triangles.size() - 1);
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const raster::Vec3 a = at(mesh.triangles[t][0]), b = at(mesh.triangles[t][1]),
                       c = at(mesh.triangles[t][2]);
    cloud.positions.push_back(raster::Vec3f(raster::Vec3{a.x + u * (b.x - a.x) + v * (c.x - a.x),
                                                         a.y + u * (b.y - a.y) + v * (c.y - a.y),
                                                         a.z + u * (b.z - a.z) + v * (c.z - a.z)}));
    cloud.points.push_back(static_cast<std::uint32_t>(i));
  }
  cloud.colors = {colour};
  cloud_scene.meshes[0] = cloud;

  std::int64_t inside = 0;
  for (int y = 0; y < silhouette.height; ++y)
    for (int x = 0; x < silhouette.width; ++x) inside += silhouette.at(x, y)[0] != 0;
  std::printf(
      "\nPoint size (issue 42): the bunny as a %d-point scan (points spread over its surface by area) at "
      "%dx%d; holes are pixels of the mesh's silhouette (%lld pixels) the points leave empty, spill is "
      "pixels they cover outside it. Default: %.1f px, the smallest size with under 1%% holes.\n\n"
      "| point_size px | holes | spill | plan + render ms |\n|---:|---:|---:|---:|\n",
      kScanPoints, silhouette.width, silhouette.height, static_cast<long long>(inside),
      static_cast<double>(raster::kDefaultPointSize));
  for (const float size : {1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 3.5f, 4.0f}) {
    cloud_scene.meshes[0].point_size = size;
    raster::Image image;
    const double ms =
        bench::median_ms(5, [&] { image = raster::render(cloud_scene, raster::plan(cloud_scene)); });
    std::int64_t holes = 0, spill = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const bool in = silhouette.at(x, y)[0] != 0;
        const bool drawn = image.at(x, y)[0] != 0;
        holes += in && !drawn, spill += drawn && !in;
      }
    std::printf("| %.1f | %.2f%% | %.2f%% | %.2f |\n", static_cast<double>(size), 100.0 * holes / inside,
                100.0 * spill / inside, ms);
  }
}

// Keeps the smaller of each time already in `into` and the one in `from`.
template <typename Key>
void keep_min(std::map<Key, double>& into, const std::map<Key, double>& from) {
  for (const auto& [key, ms] : from)
    if (!into.count(key) || ms < into[key]) into[key] = ms;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--point-size") {  // that table alone
    point_size_table();
    return 0;
  }
  if (argc > 2 && std::string(argv[1]) == "--measure") {  // core --measure runs [scene...]
    measure(std::max(1, std::atoi(argv[2])), std::vector<std::string>(argv + 3, argv + argc));
    return 0;
  }
  const int runs = argc > 1 ? std::atoi(argv[1]) : 11;
  const std::string peer = argc > 2 ? argv[2] : "";
  // The processes of both sides in turn, so a stretch of slow time falls on both alike.
  std::map<int, std::map<std::string, double>> llvmpipe;   // threads -> scene -> fastest ms
  std::map<std::string, std::map<int, double>> raster_ms;  // scene -> threads -> fastest ms
  for (int process = 0; process < kProcesses; ++process) {
    if (!peer.empty())
      for (int t : {1, 2}) keep_min(llvmpipe[t], bench::peer_ms(peer, t, runs));
    for (const auto& [kind, by_threads] : measure_in_child(runs)) keep_min(raster_ms[kind], by_threads);
  }
  auto theirs_ms = [&](const std::string& kind, int threads) {
    return llvmpipe.count(threads) && llvmpipe[threads].count(kind) ? llvmpipe[threads][kind] : 0.0;
  };
  auto verdict = [](double ratio, double target) {
    return ratio <= 0 ? "n/a" : target <= 0 ? "" : ratio >= target ? "met" : "**gap**";
  };

  std::printf("| scene | threads | triangles | raster ms | llvmpipe ms | vs llvmpipe | target | verdict |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---|\n");
  std::map<std::string, double> flat_ms;
  std::map<std::string, std::size_t> triangle_count;
  raster::Scene flat_scene;
  for (const Target& t : kTargets) {
    raster::Scene scene;
    try {
      scene = target_scene(t.kind);
    } catch (const std::exception& e) {
      std::printf("| %s | | | %s | | | | |\n", t.kind, e.what());
      continue;
    }
    const std::size_t triangles =
        scene.meshes.empty() ? scene.primitives.size() : scene.meshes[0].triangles.size();
    triangle_count[t.kind] = triangles;
    for (int threads : {1, 2}) {
      if (!raster_ms[t.kind].count(threads)) {
        std::printf("| %s | %d | %zu | (no measurement) | | | | |\n", t.kind, threads, triangles);
        continue;
      }
      const double ms = raster_ms[t.kind][threads], theirs = theirs_ms(t.kind, threads);
      const double ratio = theirs > 0 ? theirs / ms : 0;
      std::printf("| %s | %d | %zu | %.2f | %.2f | %.2fx | %.1fx | %s |\n", t.kind, threads, triangles, ms,
                  theirs, ratio, t.ratio, verdict(ratio, t.ratio));
      if (std::string(t.kind) == "flat") flat_ms[std::to_string(threads)] = ms, flat_scene = scene;
    }
  }

  // The meshes against llvmpipe's cheaper lighting of the same lights: per vertex, GL's fixed function.
  std::printf(
      "\nThe meshes against llvmpipe lighting per vertex (Gouraud, GL's fixed function, the same lights), "
      "fastest of %d processes a side:\n\n",
      kProcesses);
  std::printf(
      "| scene | threads | raster ms | llvmpipe Gouraud ms | vs Gouraud | target | verdict |\n"
      "|---|---:|---:|---:|---:|---:|---|\n");
  const std::pair<const char*, double> gouraud_targets[] = {{"sphere", 0}, {"bunny", 1.5}};
  for (const auto& [kind, target] : gouraud_targets) {
    if (!triangle_count.count(kind)) continue;
    for (int threads : {1, 2}) {
      if (!raster_ms[kind].count(threads)) continue;
      const double ms = raster_ms[kind][threads], theirs = theirs_ms(std::string(kind) + "-gouraud", threads);
      const double ratio = theirs > 0 ? theirs / ms : 0;
      char wanted[16] = "";
      if (target > 0) std::snprintf(wanted, sizeof wanted, "%.1fx", target);
      std::printf("| %s | %d | %.2f | %.2f | %.2fx | %s | %s |\n", kind, threads, ms, theirs, ratio, wanted,
                  verdict(ratio, target));
    }
  }

  // A bare model's default anti-aliasing against its aliased picture, both from this program's processes.
  std::printf(
      "\nA bare model's default anti-aliasing (%d samples, raster::kModelPicture) against the same picture "
      "aliased, 512×512, plan + render, fastest of %d processes:\n\n"
      "| model | threads | aliased ms | default ms | × aliased | target | verdict |\n"
      "|---|---:|---:|---:|---:|---:|---|\n",
      raster::sample_count(raster::kModelPicture.antialias), kProcesses);
  for (const PictureFile& file : kModelFiles)
    for (int threads : {1, 2}) {
      const std::string name = file.name;
      if (!raster_ms[name + "-model-1"].count(threads) ||
          !raster_ms[name + "-model-default"].count(threads)) {
        std::printf("| %s | %d | (cannot read %s) | | | | |\n", file.name, threads, file.path);
        continue;
      }
      const double aliased = raster_ms[name + "-model-1"][threads];
      const double smooth = raster_ms[name + "-model-default"][threads];
      std::printf("| %s | %d | %.2f | %.2f | %.2f | ≤ %.1f | %s |\n", file.name, threads, aliased, smooth,
                  smooth / aliased, kModelAntialiasCost,
                  smooth / aliased <= kModelAntialiasCost ? "met" : "**gap**");
    }

  // Points against triangles (issue 42): the same sphere as a million points and as a million triangles.
  std::printf(
      "\nA million points against a million triangles (issue 42), 1024x1024, plan + render, fastest of %d "
      "processes:\n\n| threads | triangles_1m ms | points_1m ms | points / triangles | target | verdict |\n"
      "|---:|---:|---:|---:|---:|---|\n",
      kProcesses);
  for (int threads : {1, 2}) {
    if (!raster_ms["triangles_1m"].count(threads) || !raster_ms["points_1m"].count(threads)) continue;
    const double tri = raster_ms["triangles_1m"][threads], pts = raster_ms["points_1m"][threads];
    std::printf("| %d | %.2f | %.2f | %.2fx | ≤ %.0fx | %s |\n", threads, tri, pts, pts / tri, kPointsTarget,
                pts / tri <= kPointsTarget ? "met" : "**gap**");
  }

  point_size_table();

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
