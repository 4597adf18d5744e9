// make bench-accuracy: error against an exact reference, and render time, for every anti-aliasing level.
// The reference is per-pixel *area* coverage: each triangle (and each line's butt-capped rectangle) clipped
// to the pixel square in double precision, composited in primitive order. The bunny (3D, where visibility
// makes per-triangle areas wrong) is compared with a 16x16-supersampled render instead. Writes
// docs/accuracy.md and docs/accuracy.png (the plot drawn by rasterd itself).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#define STB_EASY_FONT_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

#include "raster/raster.h"
#include "scenes.h"

namespace {

using raster::Point2;
using raster::Rgba8;

constexpr int kSize = 256;
constexpr int kLevels[] = {1, 4, 8, 16};

struct Shape {               // what the reference composites: a convex polygon with one colour
  std::vector<Point2> poly;  // pixels
  Rgba8 color;
};

struct Suite {
  std::string name;
  raster::Scene scene;
  std::vector<Shape> shapes;  // empty: compare with a supersampled render instead
  bool tiles = false;  // the shapes do not overlap: the exact colour is the area-weighted sum, no conflation
};

Rgba8 random_color(std::mt19937& rng) {
  return {static_cast<std::uint8_t>(40 + rng() % 216), static_cast<std::uint8_t>(40 + rng() % 216),
          static_cast<std::uint8_t>(40 + rng() % 216), 255};
}

// Each primitive goes into the scene and, as the polygon it covers, into the reference.
void add_triangle(Suite& s, Point2 a, Point2 b, Point2 c, Rgba8 color) {
  bench::add_triangle(s.scene, {a, b, c}, &color, 1);
  s.shapes.push_back({{a, b, c}, color});
}

void add_line(Suite& s, Point2 a, Point2 b, double width, Rgba8 color) {
  bench::add_line(s.scene, a, b, color, static_cast<float>(width));
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy), nx = -dy / len * width / 2,
               ny = dx / len * width / 2;
  s.shapes.push_back(
      {{{a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}}, color});
}

Suite blank(const std::string& name) {
  Suite s{name, {}, {}, false};
  s.scene.width = s.scene.height = kSize;
  s.scene.background = {16, 20, 28, 255};
  return s;
}

std::vector<Suite> suites() {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Suite> out;
  {
    Suite s = blank("triangles");
    for (int i = 0; i < 300; ++i) {
      const double size = std::pow(10.0, -0.3 + unit(rng) * 2.8), cx = unit(rng) * kSize,
                   cy = unit(rng) * kSize;
      auto p = [&] { return Point2{cx + (unit(rng) - 0.5) * size, cy + (unit(rng) - 0.5) * size}; };
      add_triangle(s, p(), p(), p(), random_color(rng));
    }
    out.push_back(std::move(s));
  }
  {
    Suite s = blank("fan");
    s.tiles = true;
    const Point2 c{128.3, 127.6};
    for (int k = 0; k < 1000; ++k) {
      const double t0 = 2 * M_PI * k / 1000, t1 = 2 * M_PI * (k + 1) / 1000;
      add_triangle(s, c, {c.x + 120 * std::cos(t0), c.y + 120 * std::sin(t0)},
                   {c.x + 120 * std::cos(t1), c.y + 120 * std::sin(t1)},
                   k % 2 ? Rgba8{230, 200, 80, 255} : Rgba8{60, 140, 230, 255});
    }
    out.push_back(std::move(s));
  }
  {
    Suite s = blank("slivers");
    for (int i = 0; i < 200; ++i) {
      const double t = unit(rng) * M_PI, len = 40 + unit(rng) * 200,
                   thick = std::pow(10.0, -1.5 + unit(rng) * 1.5);
      const Point2 a{unit(rng) * kSize, unit(rng) * kSize},
          b{a.x + len * std::cos(t), a.y + len * std::sin(t)};
      add_triangle(s, a, b, {b.x - thick * std::sin(t), b.y + thick * std::cos(t)}, random_color(rng));
    }
    out.push_back(std::move(s));
  }
  {
    Suite s = blank("lines");
    for (int i = 0; i < 72; ++i) {
      const double t = i * M_PI / 36 + 0.013, w = i % 3 == 0 ? 1.0 : i % 3 == 1 ? 2.0 : 4.0;
      add_line(s, {128 + 12 * std::cos(t), 128 + 12 * std::sin(t)},
               {128 + 118 * std::cos(t), 128 + 118 * std::sin(t)}, w, random_color(rng));
    }
    out.push_back(std::move(s));
  }
  return out;
}

// Area of the convex polygon `poly` inside the pixel square [x, x+1] x [y, y+1] (Sutherland-Hodgman +
// shoelace).
double coverage(const std::vector<Point2>& poly, int x, int y) {
  std::vector<Point2> cur = poly, next;
  const double bounds[4] = {double(x), double(x + 1), double(y), double(y + 1)};
  for (int side = 0; side < 4 && !cur.empty(); ++side) {
    next.clear();
    auto inside = [&](Point2 p) {
      switch (side) {
        case 0:
          return p.x >= bounds[0];
        case 1:
          return p.x <= bounds[1];
        case 2:
          return p.y >= bounds[2];
        default:
          return p.y <= bounds[3];
      }
    };
    for (std::size_t i = 0; i < cur.size(); ++i) {
      const Point2 a = cur[i], b = cur[(i + 1) % cur.size()];
      if (inside(a)) next.push_back(a);
      if (inside(a) != inside(b)) {
        const double t = side < 2 ? (bounds[side] - a.x) / (b.x - a.x) : (bounds[side] - a.y) / (b.y - a.y);
        next.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
      }
    }
    std::swap(cur, next);
  }
  double area = 0;
  for (std::size_t i = 0; i < cur.size(); ++i)
    area += cur[i].x * cur[(i + 1) % cur.size()].y - cur[(i + 1) % cur.size()].x * cur[i].y;
  return std::abs(area) / 2;
}

// Exact reference image (RGB doubles, 0..255) and a mask of edge pixels (some shape partly covers them).
void reference(const Suite& s, std::vector<double>& rgb, std::vector<std::uint8_t>& edge) {
  rgb.assign(kSize * kSize * 3, 0);
  edge.assign(kSize * kSize, 0);
  for (int i = 0; i < kSize * kSize; ++i)
    rgb[i * 3] = s.scene.background.r, rgb[i * 3 + 1] = s.scene.background.g,
            rgb[i * 3 + 2] = s.scene.background.b;
  for (const Shape& shape : s.shapes) {
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const Point2& p : shape.poly)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    for (int y = std::max(0, int(std::floor(y0))); y <= std::min(kSize - 1, int(std::floor(y1))); ++y)
      for (int x = std::max(0, int(std::floor(x0))); x <= std::min(kSize - 1, int(std::floor(x1))); ++x) {
        const double a = coverage(shape.poly, x, y);
        if (a <= 0) continue;
        if (a < 1 - 1e-12) edge[y * kSize + x] = 1;
        const double c[3] = {double(shape.color.r), double(shape.color.g), double(shape.color.b)};
        const double bg[3] = {double(s.scene.background.r), double(s.scene.background.g),
                              double(s.scene.background.b)};
        for (int k = 0; k < 3; ++k) {
          double& v = rgb[(y * kSize + x) * 3 + k];
          // Painter's coverage compositing, or for tiling shapes the exact sum: replace background by colour.
          v = s.tiles ? v + (c[k] - bg[k]) * a : v * (1 - a) + c[k] * a;
        }
      }
  }
}

raster::Image render_at(raster::Scene scene, int samples, double* ms) {
  scene.samples = samples;
  std::vector<double> times;
  raster::Image img;
  for (int r = 0; r < 7; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    img = raster::render(scene, raster::plan(scene));
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(times.begin(), times.begin() + 3, times.end());
  if (ms) *ms = times[3];
  return img;
}

struct Errors {
  double mean = 0, p99 = 0, max = 0;
};

Errors errors(const raster::Image& img, const std::vector<double>& ref,
              const std::vector<std::uint8_t>& edge) {
  std::vector<double> e;
  for (int i = 0; i < kSize * kSize; ++i) {
    if (!edge[i]) continue;
    for (int k = 0; k < 3; ++k)
      e.push_back(std::abs(img.pixels[i * img.channels() + (img.channels() >= 3 ? k : 0)] - ref[i * 3 + k]));
  }
  Errors r;
  if (e.empty()) return r;
  for (double v : e) r.mean += v;
  r.mean /= static_cast<double>(e.size());
  std::sort(e.begin(), e.end());
  r.p99 = e[e.size() * 99 / 100];
  r.max = e.back();
  return r;
}

// The 3D case: the bunny, against its own render at 16x the resolution box-filtered down (256 samples).
Suite bunny_suite(const std::string& obj) {
  Suite s = blank("bunny (3D)");
  s.scene.meshes.push_back(raster::parse_obj(obj));
  s.scene.meshes[0].colors = {Rgba8{224, 176, 112, 255}};
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.scene.primitives.push_back(p);
  return s;
}

void supersampled_reference(const Suite& s, std::vector<double>& rgb, std::vector<std::uint8_t>& edge) {
  constexpr int k = 16;
  raster::Scene big = s.scene;
  big.width = big.height = kSize * k;
  const raster::Image img = raster::render(big, raster::plan(big));
  rgb.assign(kSize * kSize * 3, 0);
  edge.assign(kSize * kSize, 0);
  const int c = img.channels();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double sum[3] = {0, 0, 0};
      double lo = 1e9, hi = -1e9;
      for (int v = 0; v < k; ++v)
        for (int u = 0; u < k; ++u) {
          const std::uint8_t* p = img.at(x * k + u, y * k + v);
          for (int ch = 0; ch < 3; ++ch) sum[ch] += p[c >= 3 ? ch : 0];
          lo = std::min(lo, double(p[0])), hi = std::max(hi, double(p[0]));
        }
      for (int ch = 0; ch < 3; ++ch) rgb[(y * kSize + x) * 3 + ch] = sum[ch] / (k * k);
      edge[y * kSize + x] = hi - lo > 8;  // silhouette (or strong shading step) inside the pixel
    }
}

// ---- the plot, drawn by rasterd ------------------------------------------------------------------------

struct PlotScene {
  raster::Scene scene;
  void tri(Point2 a, Point2 b, Point2 c, Rgba8 col) { bench::add_triangle(scene, {a, b, c}, &col, 1); }
  void line(Point2 a, Point2 b, Rgba8 col, float width = 1) { bench::add_line(scene, a, b, col, width); }
  void text(double x, double y, const std::string& s, Rgba8 col, double scale = 1.5) {
    static char buffer[60000];  // stb_easy_font: 4 vertices of 16 bytes per quad
    const int quads = stb_easy_font_print(0, 0, const_cast<char*>(s.c_str()), nullptr, buffer, sizeof buffer);
    const float* v = reinterpret_cast<const float*>(buffer);
    for (int q = 0; q < quads; ++q) {
      Point2 p[4];
      for (int k = 0; k < 4; ++k) p[k] = {x + v[(q * 4 + k) * 4] * scale, y + v[(q * 4 + k) * 4 + 1] * scale};
      tri(p[0], p[1], p[2], col);
      tri(p[0], p[2], p[3], col);
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  const std::string root = argc > 1 ? argv[1] : ".";
  std::ifstream obj_file(root + "/../shared/models/bunny.obj");
  const std::string obj((std::istreambuf_iterator<char>(obj_file)), {});
  std::vector<Suite> all = suites();
  if (!obj.empty()) all.push_back(bunny_suite(obj));

  struct Row {
    std::string suite;
    int samples;
    Errors err;
    double ms;
  };
  std::vector<Row> rows;
  for (const Suite& s : all) {
    std::vector<double> ref;
    std::vector<std::uint8_t> edge;
    if (s.shapes.empty())
      supersampled_reference(s, ref, edge);
    else
      reference(s, ref, edge);
    for (int samples : kLevels) {
      double ms = 0;
      const raster::Image img = render_at(s.scene, samples, &ms);
      rows.push_back({s.name, samples, errors(img, ref, edge), ms});
      std::fprintf(stderr, "%-12s %2d samples: mean %.2f p99 %.1f max %.1f (1/255), %.2f ms\n",
                   s.name.c_str(), samples, rows.back().err.mean, rows.back().err.p99, rows.back().err.max,
                   ms);
    }
  }

  // docs/accuracy.md
  std::string md =
      "# Anti-aliasing: error against run time\n\nProduced by `make bench-accuracy` (bench/accuracy.cpp). "
      "Each scene is 256×256 and seeded. "
      "The reference is exact area coverage: every triangle (and every line's butt-capped rectangle) clipped "
      "to each pixel "
      "square in double precision and composited in primitive order (for the fan, whose slices tile the disk "
      "without "
      "overlap, summed by area instead, which is exact). The bunny is 3D, where visibility makes "
      "per-triangle "
      "areas wrong; its reference is its own render at 16× the resolution, box-filtered (256 samples per "
      "pixel). Errors are "
      "per channel over *edge pixels* (partly covered by some shape; for the bunny, pixels whose 256 samples "
      "differ), in "
      "1/255 units; times are the median of 7 renders (plan + render, this machine, same run).\n\n";
  md +=
      "| scene | samples | mean error | p99 error | max error | render ms "
      "|\n|---|---:|---:|---:|---:|---:|\n";
  char buf[256];
  for (const Row& r : rows) {
    std::snprintf(buf, sizeof buf, "| %s | %d | %.2f | %.1f | %.1f | %.2f |\n", r.suite.c_str(), r.samples,
                  r.err.mean, r.err.p99, r.err.max, r.ms);
    md += buf;
  }
  md +=
      "\n![error against time](accuracy.png)\n\n## Which level to choose\n\n"
      "Each step, as the median over the scenes of this run (error and time relative to the level "
      "before):\n\n"
      "| step | mean edge error | render time |\n|---|---:|---:|\n";
  for (std::size_t k = 1; k < std::size(kLevels); ++k) {
    std::vector<double> err_ratio, time_ratio;
    for (std::size_t i = 0; i < rows.size(); i += std::size(kLevels)) {
      err_ratio.push_back(rows[i + k].err.mean / rows[i + k - 1].err.mean);
      time_ratio.push_back(rows[i + k].ms / rows[i + k - 1].ms);
    }
    std::sort(err_ratio.begin(), err_ratio.end());
    std::sort(time_ratio.begin(), time_ratio.end());
    std::snprintf(buf, sizeof buf, "| %d → %d samples | ×%.2f | ×%.1f |\n", kLevels[k - 1], kLevels[k],
                  err_ratio[err_ratio.size() / 2], time_ratio[time_ratio.size() / 2]);
    md += buf;
  }
  md +=
      "\n- **1 (default)**: exactly the GPU rules and the fastest; on edge pixels the error is the whole "
      "step between "
      "two colours, by design.\n"
      "- **4**: the largest cut in error per unit of time (first row above); the choice for most pictures.\n"
      "- **8, 16**: each doubling of samples doubles the raster time and cuts the remaining edge error by "
      "roughly a third "
      "(about 1/√N overall); for thin lines, slivers and line art where edges dominate.\n\n"
      "A limit of any fixed sample pattern, visible in the *lines* rows: along lines of rational slope the "
      "pattern's "
      "lattice aliases, so a thin line's total coverage is off in proportion to its length (measured on 45°, "
      "1 px "
      "lines: −12% of the area with 4 samples, +6% with 8, +1.5% with 16). Exact area coverage would remove "
      "it.\n\n"
      "Shading is per sample (each sample plane is a full render at that sample position), which costs N× "
      "the raster "
      "time but keeps gradients and per-sample depth exact. Known limit of area coverage as a reference (and "
      "of any "
      "renderer that composites coverage instead of sampling): shapes that share an edge are conflated, two "
      "abutting "
      "triangles each half-covering a pixel let the background through a seam. With painter's compositing "
      "the "
      "1,000-slice fan's reference shows a mean edge error of 36/255 even against 16 samples, all of it "
      "conflation, "
      "which is why the fan is summed by area; the overlapping suites keep painter's compositing, so part of "
      "their "
      "remaining error at 16 samples belongs to the reference.\n";
  std::ofstream(root + "/docs/accuracy.md") << md;

  // docs/accuracy.png: mean error against time, log-log, one line per scene, drawn with rasterd.
  PlotScene plot;
  plot.scene.width = 640;
  plot.scene.height = 420;
  plot.scene.background = {255, 255, 255, 255};
  plot.scene.samples = 8;
  const double left = 70, right = 600, top = 40, bottom = 360;
  double t_lo = 1e9, t_hi = 0, e_lo = 1e9, e_hi = 0;
  for (const Row& r : rows)
    t_lo = std::min(t_lo, r.ms), t_hi = std::max(t_hi, r.ms), e_lo = std::min(e_lo, r.err.mean),
    e_hi = std::max(e_hi, r.err.mean);
  const double lt0 = std::floor(std::log10(t_lo)), lt1 = std::ceil(std::log10(t_hi)),
               le0 = std::floor(std::log10(std::max(e_lo, 1e-3))), le1 = std::ceil(std::log10(e_hi));
  auto px = [&](double ms) { return left + (std::log10(ms) - lt0) / (lt1 - lt0) * (right - left); };
  auto py = [&](double e) {
    return bottom - (std::log10(std::max(e, 1e-3)) - le0) / (le1 - le0) * (bottom - top);
  };
  const Rgba8 ink{40, 40, 40, 255}, grid{225, 225, 225, 255};
  for (double d = lt0; d <= lt1; ++d) {
    plot.line({px(std::pow(10, d)), top}, {px(std::pow(10, d)), bottom}, grid);
    std::snprintf(buf, sizeof buf, "%g ms", std::pow(10, d));
    plot.text(px(std::pow(10, d)) - 14, bottom + 8, buf, ink);
  }
  for (double d = le0; d <= le1; ++d) {
    plot.line({left, py(std::pow(10, d))}, {right, py(std::pow(10, d))}, grid);
    std::snprintf(buf, sizeof buf, "%g", std::pow(10, d));
    plot.text(left - 40, py(std::pow(10, d)) - 5, buf, ink);
  }
  plot.line({left, bottom}, {right, bottom}, ink, 1.5f);
  plot.line({left, top}, {left, bottom}, ink, 1.5f);
  plot.text(left, 12, "mean edge error (1/255) against render time, samples 1 / 4 / 8 / 16", ink);
  const Rgba8 palette[] = {
      {220, 60, 60, 255}, {40, 120, 220, 255}, {30, 160, 90, 255}, {200, 130, 20, 255}, {140, 70, 200, 255}};
  std::size_t series = 0;
  for (std::size_t i = 0; i < rows.size(); i += std::size(kLevels), ++series) {
    const Rgba8 col = palette[series % std::size(palette)];
    for (std::size_t k = 0; k < std::size(kLevels); ++k) {
      const Row& r = rows[i + k];
      const Point2 c{px(r.ms), py(r.err.mean)};
      if (k > 0) plot.line({px(rows[i + k - 1].ms), py(rows[i + k - 1].err.mean)}, c, col, 2);
      plot.tri({c.x - 4, c.y - 4}, {c.x + 4, c.y - 4}, {c.x + 4, c.y + 4}, col);
      plot.tri({c.x - 4, c.y - 4}, {c.x + 4, c.y + 4}, {c.x - 4, c.y + 4}, col);
    }
    plot.line({right - 150, top + 12 + 16 * series}, {right - 130, top + 12 + 16 * series}, col, 3);
    plot.text(right - 124, top + 7 + 16 * series, rows[i].suite, ink);
  }
  const raster::RenderPlan plan = raster::plan(plot.scene);
  const auto png = raster::encode_png(raster::render(plot.scene, plan), plan.png);
  std::ofstream(root + "/docs/accuracy.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  std::fprintf(stderr, "wrote docs/accuracy.md and docs/accuracy.png\n");
}
