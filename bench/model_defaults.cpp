// make bench-accuracy, second part: the picture a bare model gets by default (raster::kModelPicture),
// chosen by measurement over a corpus of real models: the Stanford bunny, the knot of examples/models in
// each format, and every OBJ, STL, PLY and glTF 2.0 file of Debian's assimp-testmodels that rasterd reads.
//
// - Anti-aliasing: each model drawn as a bare model (raster::model_scene) at 256x256 at 1, 4, 8 and 16
//   samples, against its own aliased render at 8x the resolution box-filtered down (64 samples a pixel).
//   Errors are per channel over edge pixels (pixels whose 64 samples differ by more than 8/255).
// - Background: each model drawn on black and on white; the pixels that agree are the model's. For every
//   grey, the contrast ratio (WCAG's (L1 + 0.05) / (L2 + 0.05), relative luminance) between it and each
//   model's median pixel; the grey whose worst model has the highest contrast is the choice.
//
// Replaces the section "## The default picture of a model" at the end of docs/accuracy.md (bench/accuracy
// writes the rest) and writes the before/after crops docs/images/model-aa-1.png and model-aa-N.png.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "raster/raster.h"
#include "raster/scene_checks.h"
#include "scenes.h"
#include "timing.h"

namespace {

namespace fs = std::filesystem;
using raster::Rgba8;

constexpr int kSize = 256;                   // pixels a side of the measured pictures
constexpr int kRefScale = 8;                 // the reference's pixels per picture pixel, a side: 64 samples
constexpr int kRuns = 5;                     // renders per time; the median is kept
constexpr int kLevels[] = {1, 4, 8, 16, 0};  // 0: "auto" (edge pixels at 8 samples)
constexpr std::size_t kSampled = 4;          // the sampled levels come first; the default is one of them
// A pixel stands out from the background when their contrast ratio is at least this (a luminance step of
// a quarter: plain over a shape many pixels across; WCAG's 3:1 is for text and thin lines). The report also
// shows the choice at the stricter kStrict.
constexpr double kVisible = 1.25, kStrict = 1.5;

struct Model {
  std::string name;  // as the tables show it: the file name, with its folder for assimp's
  raster::Scene scene;
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// A model as the CLI reads it (bench::read_model_file), then raster::model_scene; false, and said, for a
// file in no format rasterd reads or one its reader or the plan refuses.
bool load(const fs::path& path, const std::string& name, std::vector<Model>& out) {
  if (!raster::format_of_file_name(path.filename().string())) return false;
  try {
    const bench::ModelFile file = bench::read_model_file(path.string());
    raster::Mesh mesh =
        raster::checks::model_mesh(file.bytes, file.format, {}, file.files, "", "", 0, file.format);
    Model m{name, raster::model_scene(std::move(mesh), file.format)};
    m.scene.width = m.scene.height = kSize;
    raster::validate(m.scene);
    raster::plan(m.scene);  // a model the plan refuses is not in the corpus either
    out.push_back(std::move(m));
    return true;
  } catch (const std::exception& e) {  // refused, or not there (the bunny outside a clone's sibling)
    std::fprintf(stderr, "skipped %s: %s\n", name.c_str(), e.what());
    return false;
  }
}

std::vector<Model> corpus(const std::string& root) {
  std::vector<Model> models;
  load(fs::path(root) / "../shared/models/bunny.obj", "bunny.obj", models);
  for (const char* knot : {"knot.obj", "knot.stl", "knot.ply", "knot.glb"})
    load(fs::path(root) / "examples/models" / knot, knot, models);
  const fs::path assimp = "/usr/share/assimp/models";
  for (const char* folder : {"OBJ", "STL", "PLY", "glTF2"}) {
    std::error_code error;
    if (!fs::is_directory(assimp / folder, error)) continue;
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(assimp / folder, error))
      if (entry.is_regular_file() && entry.file_size() <= (8u << 20)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) load(file, fs::relative(file, assimp).string(), models);
  }
  return models;
}

raster::Image draw(const raster::Scene& scene, double* ms = nullptr) {
  raster::PlanOptions one_thread;
  one_thread.max_threads = 1;
  raster::Image image;
  const double t =
      bench::median_ms(kRuns, [&] { image = raster::render(scene, raster::plan(scene, {}, one_thread)); });
  if (ms) *ms = t;
  return image;
}

// Channel k (0 red, 1 green, 2 blue) of pixel (x, y): a grey picture (PixelFormat grey8) has one.
std::uint8_t channel(const raster::Image& image, int x, int y, int k) {
  return image.at(x, y)[image.channels() >= 3 ? k : 0];
}
std::array<std::uint8_t, 3> rgb_at(const raster::Image& image, int x, int y) {
  return {channel(image, x, y, 0), channel(image, x, y, 1), channel(image, x, y, 2)};
}

double luminance(const std::array<std::uint8_t, 3>& rgb) {  // relative luminance of an sRGB colour, 0..1
  double l = 0;
  const double weight[3] = {0.2126, 0.7152, 0.0722};
  for (int k = 0; k < 3; ++k) {
    const double c = rgb[k] / 255.0;
    l += weight[k] * (c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  return l;
}
double contrast(double a, double b) {
  return (std::max(a, b) + 0.05) / (std::min(a, b) + 0.05);
}

// The relative luminance of each of the model's pixels: those that agree on a black and a white background.
std::vector<double> pixel_luminances(raster::Scene scene) {
  scene.antialias = raster::Antialias::none;
  scene.background = {0, 0, 0, 255};
  const raster::Image on_black = draw(scene);
  scene.background = {255, 255, 255, 255};
  const raster::Image on_white = draw(scene);
  auto inside = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < kSize && y < kSize && rgb_at(on_black, x, y) == rgb_at(on_white, x, y);
  };
  std::vector<double> l;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (inside(x, y)) l.push_back(luminance(rgb_at(on_black, x, y)));
  return l;
}

// The reference: the picture at 8x the resolution, each 8x8 block averaged; edge pixels are those whose
// samples differ by more than 8/255 in some channel.
void reference(raster::Scene scene, std::vector<double>& rgb, std::vector<std::uint8_t>& edge) {
  scene.antialias = raster::Antialias::none;
  scene.width = scene.height = kSize * kRefScale;
  const raster::Image big = raster::render(scene, raster::plan(scene));
  rgb.assign(kSize * kSize * 3, 0);
  edge.assign(kSize * kSize, 0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double sum[3] = {0, 0, 0}, lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
      for (int v = 0; v < kRefScale; ++v)
        for (int u = 0; u < kRefScale; ++u) {
          const std::array<std::uint8_t, 3> p = rgb_at(big, x * kRefScale + u, y * kRefScale + v);
          for (int k = 0; k < 3; ++k)
            sum[k] += p[k], lo[k] = std::min<double>(lo[k], p[k]), hi[k] = std::max<double>(hi[k], p[k]);
        }
      for (int k = 0; k < 3; ++k) {
        rgb[(y * kSize + x) * 3 + k] = sum[k] / (kRefScale * kRefScale);
        edge[y * kSize + x] |= hi[k] - lo[k] > 8;
      }
    }
}

struct Pooled {
  std::vector<double> errors;  // per channel of every edge pixel
  std::size_t pixels = 0, over8 = 0, over32 = 0;
  double ms = 0;  // summed over the models
  void add(const raster::Image& image, const std::vector<double>& ref,
           const std::vector<std::uint8_t>& edge) {
    for (int i = 0; i < kSize * kSize; ++i) {
      if (!edge[i]) continue;
      double worst = 0;
      for (int k = 0; k < 3; ++k) {
        errors.push_back(std::abs(channel(image, i % kSize, i / kSize, k) - ref[i * 3 + k]));
        worst = std::max(worst, errors.back());
      }
      ++pixels, over8 += worst > 8, over32 += worst > 32;
    }
  }
  double mean() const {
    double s = 0;
    for (double e : errors) s += e;
    return errors.empty() ? 0 : s / static_cast<double>(errors.size());
  }
  double quantile(double q) {
    if (errors.empty()) return 0;
    std::sort(errors.begin(), errors.end());
    return errors[static_cast<std::size_t>(q * static_cast<double>(errors.size() - 1))];
  }
};

raster::Antialias mode(int samples) {
  if (samples == 0) return raster::Antialias::automatic;
  raster::Antialias a = raster::Antialias::none;
  raster::antialias_of_samples(samples, a);
  return a;
}

// A crop of the bunny at 512x512 (an ear), enlarged 3x without filtering, as a PNG.
void write_crop(raster::Scene scene, int samples, const fs::path& path) {
  scene.width = scene.height = 512;
  scene.antialias = mode(samples);
  const raster::Image full = raster::render(scene, raster::plan(scene));
  constexpr int kX = 140, kY = 105, kSide = 112, kZoom = 3;
  raster::Image crop;
  crop.width = crop.height = kSide * kZoom;
  crop.format = full.format;
  crop.pixels.resize(static_cast<std::size_t>(crop.width) * crop.height * full.channels());
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x)
      std::copy_n(full.at(kX + x / kZoom, kY + y / kZoom), full.channels(),
                  crop.pixels.data() + (static_cast<std::size_t>(y) * crop.width + x) * full.channels());
  const auto png = raster::encode_png(crop);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
}

std::string hex(Rgba8 c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string root = argc > 1 ? argv[1] : ".";
  std::vector<Model> models = corpus(root);
  std::fprintf(stderr, "%zu models\n", models.size());
  char buf[2048];

  // The background: the grey under which the worst-shown model keeps most of its pixels visible.
  struct Shown {
    std::string name;
    std::vector<double> luminance;  // of each of its pixels
    // The share of its pixels that stand out against the background at contrast ratio `at` or more.
    double visible(double background, double at = kVisible) const {
      std::size_t n = 0;
      for (double l : luminance) n += contrast(l, background) >= at;
      return static_cast<double>(n) / static_cast<double>(luminance.size());
    }
  };
  std::vector<Shown> shown;
  for (const Model& m : models)
    if (std::vector<double> l = pixel_luminances(m.scene); !l.empty())
      shown.push_back({m.name, std::move(l)});
  auto grey_luminance = [](int grey) {
    const auto g = static_cast<std::uint8_t>(grey);
    return luminance({g, g, g});
  };
  auto worst_at = [&](int grey, const Shown** who = nullptr, double at = kVisible) {
    double worst = 2;
    for (const Shown& s : shown)
      if (const double v = s.visible(grey_luminance(grey), at); v < worst) {
        worst = v;
        if (who) *who = &s;
      }
    return worst;
  };
  int best_grey = 0;
  double best_worst = -1;
  for (int grey = 0; grey < 256; ++grey)
    if (const double w = worst_at(grey); w > best_worst) best_worst = w, best_grey = grey;
  const Rgba8 background{static_cast<std::uint8_t>(best_grey), static_cast<std::uint8_t>(best_grey),
                         static_cast<std::uint8_t>(best_grey), 255};

  // Anti-aliasing, on the chosen background.
  Pooled pooled[std::size(kLevels)];
  struct Named {
    std::string name;
    double ms[std::size(kLevels)];
    double mean[std::size(kLevels)];
  };
  std::vector<Named> named;
  std::size_t measured = 0, auto_not_worse = 0;
  for (Model& m : models) {
    m.scene.background = background;
    const raster::Mesh& mesh = m.scene.meshes[0];
    // Lines and points keep their size in pixels and textures pick a finer mipmap at 8x the resolution:
    // the reference would differ from the picture inside the model, not at its edges. Such models are left
    // out.
    if (!mesh.segments.empty() || !mesh.points.empty() || mesh.wireframe || mesh.edges.enabled ||
        !mesh.textures.empty())
      continue;
    ++measured;
    std::vector<double> ref;
    std::vector<std::uint8_t> edge;
    reference(m.scene, ref, edge);
    Named row{m.name, {}, {}};
    std::size_t stairs_of[std::size(kLevels)] = {};
    for (std::size_t k = 0; k < std::size(kLevels); ++k) {
      raster::Scene s = m.scene;
      s.antialias = mode(kLevels[k]);
      double ms = 0;
      const raster::Image image = draw(s, &ms);
      Pooled one;
      one.add(image, ref, edge);
      stairs_of[k] = one.over32;
      pooled[k].add(image, ref, edge);
      pooled[k].ms += ms;
      row.ms[k] = ms, row.mean[k] = one.mean();
    }
    if (m.name == "bunny.obj" || m.name.starts_with("knot.")) named.push_back(row);
    std::fprintf(stderr,
                 "%-40s aliased %.2f  4x %.2f (%.2f ms / %.2f ms)  auto %.2f (%.2f ms)  stairs %zu / %zu\n",
                 m.name.c_str(), row.mean[0], row.mean[1], row.ms[0], row.ms[1], row.mean[4], row.ms[4],
                 stairs_of[1], stairs_of[4]);
    // "auto" against 4 samples, model by model: the mean edge error and the stairs.
    auto_not_worse += row.mean[4] <= row.mean[1] && stairs_of[4] <= stairs_of[1];
  }
  // Smooth: at most 1% of edge pixels off by more than 32/255 (an eighth of full contrast, the size of a
  // step still seen as a stair) against the 64-sample picture. The default is the level that removes the
  // most stair pixels for the time it adds (this project's error-against-time measure); the cheapest smooth
  // level is reported beside it.
  const auto stairs = [&](std::size_t k) {
    return static_cast<double>(pooled[k].over32) / static_cast<double>(pooled[k].pixels);
  };
  std::size_t smooth = kSampled - 1, chosen = 1;
  for (std::size_t k = kSampled; k-- > 0;)
    if (stairs(k) <= 0.01) smooth = k;
  auto per_time = [&](std::size_t k) { return (stairs(0) - stairs(k)) / (pooled[k].ms / pooled[0].ms - 1); };
  for (std::size_t k = 2; k < kSampled; ++k)
    if (per_time(k) > per_time(chosen)) chosen = k;

  std::string md =
      "\n## The default picture of a model\n\n"
      "Made by `make bench-accuracy` (bench/model_defaults.cpp) in the same run as the tables above. A bare "
      "model (a model sent without a scene, to the service or the CLI) is drawn in `raster::model_scene`, "
      "whose background and anti-aliasing (`raster::kModelPicture`) were chosen by these measurements over a "
      "corpus of " +
      std::to_string(models.size()) +
      " models: the Stanford bunny, the knot of examples/models in each format, and every OBJ, STL, PLY and "
      "glTF 2.0 file of Debian's assimp-testmodels that rasterd reads, each drawn as a bare model at "
      "256×256.\n\n"
      "**Anti-aliasing.** Each model at 1, 4, 8 and 16 samples and at `\"auto\"` (aliased, then the edge "
      "pixels, those more than 8/255 from a neighbour, drawn again at 8 samples) against its own aliased "
      "render at 8× the "
      "resolution, box-filtered (64 samples a pixel); the " +
      std::to_string(measured) +
      " models without textures, lines or points (a line or point keeps its size in pixels and a texture "
      "takes a finer mipmap at 8× the resolution, so there the reference differs inside the model, not at "
      "its "
      "edges). Errors per channel over edge pixels (whose 64 samples differ by more than 8/255), in 1/255, "
      "pooled over the corpus; time is the sum over the corpus of each model's median plan + render, one "
      "thread. A *stair* is an edge pixel off by more than 32/255 (an eighth of full contrast: a larger step "
      "reads as a stair); *smooth* means at most 1% of edge pixels are stairs. The default is the level that "
      "removes the most stairs for the time it adds (stairs removed per unit of time over the aliased "
      "render, the last column), the error-against-time measure this project reports.\n\n"
      "| samples | mean error | p99 error | max error | > 8 | stairs (> 32) | corpus ms | × aliased | stairs "
      "removed per × |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t k = 0; k < std::size(kLevels); ++k) {
    Pooled& p = pooled[k];
    const double share = static_cast<double>(p.pixels);
    const std::string level = kLevels[k] ? std::to_string(kLevels[k]) : "auto";
    std::snprintf(buf, sizeof buf, "| %s%s%s | %.2f | %.1f | %.1f | %.1f%% | %.2f%% | %.1f | %.2f | %s |\n",
                  k == chosen ? "**" : "", level.c_str(), k == chosen ? "**" : "", p.mean(), p.quantile(0.99),
                  p.quantile(1), 100 * static_cast<double>(p.over8) / share, 100 * stairs(k), p.ms,
                  p.ms / pooled[0].ms,
                  k == 0 ? "" : (std::to_string(100 * per_time(k)).substr(0, 4) + " points").c_str());
    md += buf;
  }
  std::snprintf(buf, sizeof buf,
                "\nThe default by that measure is **%d samples**; the cheapest smooth level is %d samples. "
                "`raster::kModelPicture` has %d. `\"auto\"` has a mean edge error and stairs no larger than "
                "4 samples on %zu of the %zu models. Per model (mean edge error / ms, one thread, "
                "256×256):\n\n",
                kLevels[chosen], kLevels[smooth], raster::sample_count(raster::kModelPicture.antialias),
                auto_not_worse, measured);
  md += buf;
  md += "| model | 1 | 4 | 8 | 16 | auto |\n|---|---:|---:|---:|---:|---:|\n";
  for (const Named& r : named) {
    md += "| " + r.name;
    for (std::size_t k = 0; k < std::size(kLevels); ++k) {
      std::snprintf(buf, sizeof buf, " | %.2f / %.2f", r.mean[k], r.ms[k]);
      md += buf;
    }
    md += " |\n";
  }
  std::snprintf(buf, sizeof buf,
                "\nThe bunny's ear at 512×512, enlarged 3×: aliased, then at %d samples.\n\n"
                "![aliased](images/model-aa-1.png) ![%d samples](images/model-aa-%d.png)\n\n",
                kLevels[chosen], kLevels[chosen], kLevels[chosen]);
  md += buf;
  std::snprintf(
      buf, sizeof buf,
      "**Background.** A model's pixels are those that agree when it is drawn on black and on white; "
      "one stands out from a background when their contrast ratio ((L1 + 0.05) / (L2 + 0.05) of "
      "relative luminances, as WCAG defines it) is at least %.2f (a quarter's step in luminance: "
      "plain on a shape many pixels across; WCAG's 3:1 is for text). The choice is the grey whose "
      "worst-shown model keeps the largest share of its pixels standing out: **%s** "
      "(`raster::kModelPicture` has %s). Some greys (each share is of the model's own pixels; "
      "the mean is over the %zu models that show pixels):\n\n"
      "| background | worst model at %.2f | its share | mean share | worst at %.2f | mean at %.2f |\n"
      "|---|---|---:|---:|---:|---:|\n",
      kVisible, hex(background).c_str(), hex(raster::kModelPicture.background).c_str(), shown.size(),
      kVisible, kStrict, kStrict);
  md += buf;
  std::vector<int> greys = {0, 51, 102, 153, 204, 255};
  if (std::find(greys.begin(), greys.end(), best_grey) == greys.end()) greys.push_back(best_grey);
  for (int grey : greys) {
    const Shown* who = nullptr;
    const double worst = worst_at(grey, &who), strict = worst_at(grey, nullptr, kStrict);
    double mean = 0, mean_strict = 0;
    for (const Shown& s : shown)
      mean += s.visible(grey_luminance(grey)), mean_strict += s.visible(grey_luminance(grey), kStrict);
    const auto g = static_cast<std::uint8_t>(grey);
    std::snprintf(buf, sizeof buf, "| %s%s | %s | %.1f%% | %.1f%% | %.1f%% | %.1f%% |\n",
                  hex({g, g, g, 255}).c_str(),
                  grey == best_grey ? " (chosen)"
                  : grey == 0       ? " (before)"
                                    : "",
                  who->name.c_str(), 100 * worst, 100 * mean / static_cast<double>(shown.size()),
                  100 * strict, 100 * mean_strict / static_cast<double>(shown.size()));
    md += buf;
  }

  // Replace the section (and anything after it) in docs/accuracy.md.
  const fs::path doc = fs::path(root) / "docs/accuracy.md";
  std::string text = read_file(doc);
  if (const std::size_t at = text.find("\n## The default picture of a model"); at != std::string::npos)
    text.resize(at);
  std::ofstream(doc) << text << md;

  for (const Model& m : models)
    if (m.name == "bunny.obj") {
      write_crop(m.scene, 1, fs::path(root) / "docs/images/model-aa-1.png");
      write_crop(m.scene, kLevels[chosen],
                 fs::path(root) / ("docs/images/model-aa-" + std::to_string(kLevels[chosen]) + ".png"));
    }
  std::fprintf(stderr, "wrote the model section of docs/accuracy.md\n");
}
