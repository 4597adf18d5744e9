// Luminance of lit pixels under a light rig, for docs/lighting.md: is a model without materials too dark
// or washed out? Each model is read as an upload without its MTL (so it is the default grey #cccccc),
// drawn with the default camera (and the iso view) at 256x256 over a transparent background, and every
// covered pixel's luma is taken: Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' on the 8-bit sRGB values, 0..255.
// Printed per model and rig: mean, 5th and 95th percentile, and the share of pixels at the surface colour's
// full value (the light saturated: 204 for #cccccc) or above.
//
//   lighting MODEL.obj...   (a cube is built in code and always measured first)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "raster/raster.h"

namespace {

struct Rig {
  const char* name;
  std::vector<raster::Light> lights;
};

struct Figures {
  double mean = 0, p5 = 0, p95 = 0, saturated = 0;
  std::size_t pixels = 0;
  const char* unmeasured = nullptr;  ///< why there is nothing to measure (then pixels = 0)
};

const char* kCube =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

Figures measure(const std::string& obj, const Rig& rig, raster::View view) {
  const std::string doc = R"({"width": 256, "height": 256, "background": "#00000000",)"
                          R"( "primitives": [{"type": "obj", "source": "model"}]})";
  raster::Scene scene = raster::parse_scene(doc, {}, {{"model", obj}});
  scene.lights = rig.lights;
  scene.camera.view = view, scene.camera.has_view = true;
  const raster::RenderPlan plan = raster::plan(scene);
  Figures f;
  if (plan.lit_count == 0) {
    f.unmeasured = "lines only, drawn unlit";
    return f;
  }
  const raster::Image image = raster::render(scene, plan);
  std::vector<double> luma;
  const int c = raster::channel_count(image.format);
  for (std::size_t i = 0; i + c <= image.pixels.size(); i += c) {
    if (image.pixels[i + c - 1] == 0) continue;  // not covered (alpha 0)
    const double r = image.pixels[i], g = c >= 3 ? image.pixels[i + 1] : r,
                 b = c >= 3 ? image.pixels[i + 2] : r;
    luma.push_back(0.2126 * r + 0.7152 * g + 0.0722 * b);
  }
  f.pixels = luma.size();
  if (luma.empty()) {
    f.unmeasured = "no pixel covered from this view (a flat model seen edge-on)";
    return f;
  }
  std::sort(luma.begin(), luma.end());
  double sum = 0;
  std::size_t full = 0;
  for (double y : luma) sum += y, full += y >= 203.5;
  f.mean = sum / luma.size();
  f.p5 = luma[luma.size() * 5 / 100];
  f.p95 = luma[std::min(luma.size() - 1, luma.size() * 95 / 100)];
  f.saturated = 100.0 * full / luma.size();
  return f;
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string base_name(const std::string& path) {
  return path.substr(path.find_last_of('/') + 1);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<Rig> rigs = {
      {"before (0.1: headlight 0.8 + ambient 0.2)", raster::single_light(0.2, nullptr)},
      {"after (default: key 0.45 + fill 0.25 + ambient 0.35)", raster::default_lights()}};
  std::vector<std::pair<std::string, std::string>> models = {{"cube (built in)", kCube}};
  for (int i = 1; i < argc; ++i) models.emplace_back(base_name(argv[i]), read(argv[i]));

  std::printf("| model | view | rig | lit pixels | mean | p5 | p95 | at full value |\n");
  std::printf("|---|---|---|--:|--:|--:|--:|--:|\n");
  std::vector<Figures> totals(rigs.size());
  std::vector<std::vector<double>> means(rigs.size()), p5s(rigs.size()), p95s(rigs.size());
  for (const auto& [name, obj] : models) {
    bool drawn = true;
    for (const auto& [view, view_name] :
         {std::pair{raster::View::front, "front"}, {raster::View::iso, "iso"}}) {
      for (std::size_t r = 0; drawn && r < rigs.size(); ++r) {
        Figures f;
        try {
          f = measure(obj, rigs[r], view);
        } catch (const std::exception& e) {  // the model itself is refused: once, for every view
          std::printf("| %s | | not drawn: %.80s | | | | | |\n", name.c_str(), e.what());
          drawn = false;
          break;
        }
        if (f.unmeasured) {  // the same for every rig
          std::printf("| %s | %s | not measured: %s | | | | | |\n", name.c_str(), view_name, f.unmeasured);
          break;
        }
        std::printf("| %s | %s | %s | %zu | %.0f | %.0f | %.0f | %.1f%% |\n", name.c_str(), view_name,
                    r == 0 ? "before" : "after", f.pixels, f.mean, f.p5, f.p95, f.saturated);
        means[r].push_back(f.mean), p5s[r].push_back(f.p5), p95s[r].push_back(f.p95);
        totals[r].saturated += f.saturated;
      }
    }
  }
  std::printf(
      "\n| rig | renders | mean of means | lowest p5 | median p5 | median p95 | highest p95 | mean share at "
      "full value |\n");
  std::printf("|---|--:|--:|--:|--:|--:|--:|--:|\n");
  for (std::size_t r = 0; r < rigs.size(); ++r) {
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v.empty() ? 0.0 : v[v.size() / 2];
    };
    double mean = 0;
    for (double m : means[r]) mean += m;
    const std::size_t n = means[r].size();
    std::printf("| %s | %zu | %.0f | %.0f | %.0f | %.0f | %.0f | %.1f%% |\n", rigs[r].name, n,
                n ? mean / n : 0, n ? *std::min_element(p5s[r].begin(), p5s[r].end()) : 0, median(p5s[r]),
                median(p95s[r]), n ? *std::max_element(p95s[r].begin(), p95s[r].end()) : 0,
                n ? totals[r].saturated / n : 0);
  }
  return 0;
}
