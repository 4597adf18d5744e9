// make bench-accuracy: error against an exact reference, and render time, for every anti-aliasing mode,
// with Cairo (Debian's libcairo2-dev, its C API, default anti-aliasing) drawing the same shapes in the same
// run. The reference is per-pixel *area* coverage: each triangle (and each line's butt-capped rectangle)
// clipped to the pixel square in double precision, composited in primitive order. The bunny (3D, where
// visibility makes per-triangle areas wrong) is compared with a 16x16-supersampled render instead. Two
// held-back suites (white on black, where errors show most) are never tuned on. Writes docs/accuracy.md
// and docs/accuracy.png (the plot drawn by rasterd itself).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <cairo/cairo.h>

#include "blend2d_peer.h"
#include "plot.h"
#include "raster/raster.h"
#include "scenes.h"

namespace {

using raster::Point2;
using raster::Rgba8;

constexpr int kSize = 256;
constexpr int kRuns = 21;  // renders per measurement; the median is reported

/// One way of drawing a suite: rasterd at a sample count or with area coverage, or Cairo.
struct Level {
  const char* label;
  int samples;
  bool area;
  bool cairo;
  bool automatic = false;  // "auto": aliased, then the edge pixels at 8 samples
  bool blend2d = false;    // Blend2D (bench/blend2d_peer.h), when the bench was built against it
};
constexpr Level kLevels[] = {{"1", 1, false, false},    {"4", 4, false, false},
                             {"8", 8, false, false},    {"16", 16, false, false},
                             {"area", 1, true, false},  {"auto", 8, false, false, true},
                             {"Cairo", 1, false, true}, {"Blend2D", 1, false, false, false, true}};
constexpr std::size_t kSampleLevels = 4;  // the first four are the sample counts

struct Shape {               // what the reference composites: a convex polygon with one colour
  std::vector<Point2> poly;  // pixels
  Rgba8 color;
};

struct Suite {
  std::string name;
  raster::Scene scene;
  std::vector<Shape> shapes;  // empty: compare with a supersampled render instead
  bool tiles = false;  // the shapes do not overlap: the exact colour is the area-weighted sum, no conflation
  bool held_back = false;  // never looked at while tuning: white on black, where errors show most
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
  Suite s{name, {}, {}, false, false};
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
  {
    // Abutting squares of one colour, two triangles each, off the pixel grid: the true picture is one
    // rectangle, so every error inside it is a seam (shared edges that coverage compositing conflates).
    Suite s = blank("grid");
    s.tiles = true;
    const double cell = 240.0 / 11, x0 = 8.3, y0 = 7.7;
    const Rgba8 color{230, 200, 80, 255};
    for (int j = 0; j < 11; ++j)
      for (int i = 0; i < 11; ++i) {
        const Point2 a{x0 + i * cell, y0 + j * cell}, b{a.x + cell, a.y}, c{a.x + cell, a.y + cell},
            d{a.x, a.y + cell};
        add_triangle(s, a, b, c, color);
        add_triangle(s, a, c, d, color);
      }
    out.push_back(std::move(s));
  }
  // Held back: a different seed and shapes the modes were never tuned on.
  std::mt19937 held(90210);
  std::uniform_real_distribution<double> u(0, 1);
  {
    Suite s = blank("held-back triangles");
    s.held_back = true;
    s.scene.background = {0, 0, 0, 255};
    for (int i = 0; i < 64; ++i) {
      const double size = 8 + u(held) * 40, cx = u(held) * kSize, cy = u(held) * kSize;
      auto p = [&] { return Point2{cx + (u(held) - 0.5) * size, cy + (u(held) - 0.5) * size}; };
      add_triangle(s, p(), p(), p(), Rgba8{255, 255, 255, 255});
    }
    out.push_back(std::move(s));
  }
  {
    Suite s = blank("held-back lines");
    s.held_back = true;
    s.scene.background = {0, 0, 0, 255};
    for (int i = 0; i < 40; ++i) {
      const Point2 a{u(held) * kSize, u(held) * kSize}, b{u(held) * kSize, u(held) * kSize};
      add_line(s, a, b, 0.5 + u(held) * 2.5, Rgba8{255, 255, 255, 255});
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

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The scene's "antialias" for a level of rasterd's own.
raster::Antialias antialias_of(const Level& level) {
  if (level.automatic) return raster::Antialias::automatic;
  raster::Antialias mode = raster::Antialias::area;
  if (!level.area && !raster::antialias_of_samples(level.samples, mode)) std::abort();
  return mode;
}

raster::Image render_at(raster::Scene scene, const Level& level, double* ms) {
  scene.antialias = antialias_of(level);
  std::vector<double> times;
  raster::Image img;
  for (int r = 0; r < kRuns; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    img = raster::render(scene, raster::plan(scene));
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  *ms = median(times);
  return img;
}

// The same shapes through Cairo: an RGB24 image surface, the background painted, each polygon filled in
// order with the default anti-aliasing. Timed from surface creation to the flushed pixels.
raster::Image cairo_render(const Suite& s, double* ms) {
  std::vector<double> times;
  raster::Image img;
  for (int r = 0; r < kRuns; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, kSize, kSize);
    cairo_t* cr = cairo_create(surface);
    const Rgba8 bg = s.scene.background;
    cairo_set_source_rgb(cr, bg.r / 255.0, bg.g / 255.0, bg.b / 255.0);
    cairo_paint(cr);
    for (const Shape& shape : s.shapes) {
      cairo_move_to(cr, shape.poly[0].x, shape.poly[0].y);
      for (std::size_t k = 1; k < shape.poly.size(); ++k) cairo_line_to(cr, shape.poly[k].x, shape.poly[k].y);
      cairo_close_path(cr);
      cairo_set_source_rgba(cr, shape.color.r / 255.0, shape.color.g / 255.0, shape.color.b / 255.0,
                            shape.color.a / 255.0);
      cairo_fill(cr);
    }
    cairo_surface_flush(surface);
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (r + 1 == kRuns) {  // the last one's pixels, as 8-bit RGB: RGB24 is xRGB in a native-endian word
      img.width = img.height = kSize;
      img.format = raster::PixelFormat::rgb8;
      img.pixels.resize(kSize * kSize * 3);
      const unsigned char* data = cairo_image_surface_get_data(surface);
      const int stride = cairo_image_surface_get_stride(surface);
      for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
          std::uint32_t v;
          std::memcpy(&v, data + y * stride + x * 4, 4);
          for (int k = 0; k < 3; ++k)
            img.pixels[(y * kSize + x) * 3 + k] = static_cast<std::uint8_t>(v >> (16 - 8 * k));
        }
    }
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  *ms = median(times);
  return img;
}

// The same shapes through Blend2D, its default (analytic) anti-aliasing, in the same order.
raster::Image blend2d_render(const Suite& s, double* ms) {
  std::vector<bench::PeerPolygon> polygons;
  for (const Shape& shape : s.shapes) {
    bench::PeerPolygon p{{}, shape.color};
    for (const Point2& v : shape.poly) p.points.push_back({v.x, v.y});
    polygons.push_back(std::move(p));
  }
  return bench::blend2d_render(polygons, s.scene.background, kSize, kRuns, ms);
}

struct Errors {
  double mean = 0, p99 = 0, max = 0;
  double over8 = 0;  // share of edge pixels with some channel more than 8/255 off
};

Errors errors(const raster::Image& img, const std::vector<double>& ref,
              const std::vector<std::uint8_t>& edge) {
  std::vector<double> e;
  std::size_t pixels = 0, over = 0;
  for (int i = 0; i < kSize * kSize; ++i) {
    if (!edge[i]) continue;
    double worst = 0;
    for (int k = 0; k < 3; ++k) {
      e.push_back(std::abs(img.pixels[i * img.channels() + (img.channels() >= 3 ? k : 0)] - ref[i * 3 + k]));
      worst = std::max(worst, e.back());
    }
    ++pixels, over += worst > 8;
  }
  Errors r;
  if (e.empty()) return r;
  r.over8 = static_cast<double>(over) / static_cast<double>(pixels);
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

}  // namespace

int main(int argc, char** argv) {
  const std::string root = argc > 1 ? argv[1] : ".";
  std::ifstream obj_file(root + "/../shared/models/bunny.obj");
  const std::string obj((std::istreambuf_iterator<char>(obj_file)), {});
  std::vector<Suite> all = suites();
  if (!obj.empty()) all.push_back(bunny_suite(obj));

  struct Row {
    std::string suite;
    const Level* level;
    Errors err;
    double ms;
    int samples_used;  // what the plan drew with ("area" on 3D content multisamples)
  };
  std::vector<Row> rows;
  auto find = [&](const std::string& suite, const char* label) -> const Row* {
    for (const Row& r : rows)
      if (r.suite == suite && std::string(r.level->label) == label) return &r;
    return nullptr;
  };
  for (const Suite& s : all) {
    std::vector<double> ref;
    std::vector<std::uint8_t> edge;
    if (s.shapes.empty())
      supersampled_reference(s, ref, edge);
    else
      reference(s, ref, edge);
    for (const Level& level : kLevels) {
      if ((level.cairo || level.blend2d) && s.shapes.empty()) continue;  // the 2D peers have no 3D
      if (level.blend2d && !bench::blend2d_built()) continue;
      double ms = 0;
      const raster::Image img = level.cairo     ? cairo_render(s, &ms)
                                : level.blend2d ? blend2d_render(s, &ms)
                                                : render_at(s.scene, level, &ms);
      raster::Scene planned = s.scene;
      planned.antialias = antialias_of(level);
      rows.push_back({s.name, &level, errors(img, ref, edge), ms, raster::plan(planned).samples});
      const Row& r = rows.back();
      std::fprintf(stderr, "%-20s %-6s mean %6.2f p99 %6.1f max %6.1f >8: %5.1f%%  %.3f ms\n", s.name.c_str(),
                   level.label, r.err.mean, r.err.p99, r.err.max, 100 * r.err.over8, ms);
    }
  }

  char buf[512];
  auto mode_name = [&](const Row& r) {
    if (r.level->cairo) return std::string("Cairo 1.16, default");
    if (r.level->blend2d) return std::string("Blend2D, default");
    if (r.level->automatic) return std::string("auto (edge pixels at 8 samples)");
    if (r.level->area)
      return r.samples_used > 1 ? "area (3D: " + std::to_string(r.samples_used) + " samples)"
                                : std::string("area");
    return r.level->samples == 1 ? std::string("1 (aliased)") : std::to_string(r.level->samples) + " samples";
  };
  // docs/accuracy.md
  std::string md =
      "# Anti-aliasing: error against run time\n\n"
      "Produced by `make bench-accuracy` (bench/accuracy.cpp); every number below comes from one run. Each "
      "scene is 256×256 and seeded. The reference is exact area coverage: every triangle (and every line's "
      "butt-capped rectangle) clipped to each pixel square in double precision and composited in primitive "
      "order (for the fan and the grid, whose shapes tile their region without overlap, summed by area "
      "instead, which is exact: there, any error of a compositing renderer is a seam). The bunny is 3D, "
      "where visibility makes per-triangle areas wrong; its reference is its own render at 16× the "
      "resolution, box-filtered (256 samples per pixel). Errors are per channel over *edge pixels* (partly "
      "covered by some shape; for the bunny, pixels whose 256 samples differ), in 1/255 units; \"> 8\" is "
      "the share of edge pixels with a channel more than 8/255 off. Times are the median of " +
      std::to_string(kRuns) +
      " renders (rasterd: plan + render; Cairo: surface creation to flushed pixels, the same polygons filled "
      "in the same order with its default anti-aliasing; Blend2D likewise, its synchronous context, when the "
      "bench is built against it), one thread, this machine. The two *held-back* "
      "scenes (white on black) were never looked at while tuning.\n\n" +
      (bench::blend2d_built()
           ? std::string("Blend2D was built from the checkout in `BLEND2D_DIR` (below: how).\n\n")
           : std::string(
                 "**Blend2D was not measured in this run**: the bench was built without `BLEND2D_DIR` "
                 "(below: how to give it one).\n\n"));
  md +=
      "| scene | anti-aliasing | mean error | p99 error | max error | > 8 | render ms |\n"
      "|---|---|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows) {
    std::snprintf(buf, sizeof buf, "| %s | %s | %.2f | %.1f | %.1f | %.1f%% | %.3f |\n", r.suite.c_str(),
                  mode_name(r).c_str(), r.err.mean, r.err.p99, r.err.max, 100 * r.err.over8, r.ms);
    md += buf;
  }
  md += "\n![error against time](accuracy.png)\n\n";

  // The targets, read off the rows above.
  md += "## Against the targets\n\n| target | scene | measured | met |\n|---|---|---:|---|\n";
  auto target = [&](const std::string& what, const std::string& suite, double value, double bound,
                    const char* unit) {
    std::snprintf(buf, sizeof buf, "| %s | %s | %.2f%s | %s |\n", what.c_str(), suite.c_str(), value, unit,
                  value <= bound ? "yes" : "**no**");
    md += buf;
  };
  for (const char* suite : {"triangles", "slivers", "lines", "held-back triangles", "held-back lines"}) {
    const Row* area = find(suite, "area");
    const Row* aliased = find(suite, "1");
    const Row* cairo = find(suite, "Cairo");
    if (!area || !aliased || !cairo) continue;
    target("area: mean edge error ≤ 0.5", suite, area->err.mean, 0.5, "");
    target("area: p99 edge error ≤ 2", suite, area->err.p99, 2, "");
    target("area: time ≤ Cairo's", suite, area->ms / cairo->ms, 1, "× Cairo");
    target("area: time ≤ 3× aliased", suite, area->ms / aliased->ms, 3, "× aliased");
    if (const Row* b2d = find(suite, "Blend2D"))
      target("area: time ≤ 1.5× Blend2D's", suite, area->ms / b2d->ms, 1.5, "× Blend2D");
  }
  for (const char* suite : {"triangles", "fan", "slivers", "lines", "grid", "held-back triangles",
                            "held-back lines", "bunny (3D)"}) {
    const Row* aliased = find(suite, "1");
    if (!aliased) continue;
    if (const Row* r = find(suite, "4"))
      target("4 samples: ≤ 1.5× aliased", suite, r->ms / aliased->ms, 1.5, "×");
    if (const Row* r = find(suite, "16"))
      target("16 samples: ≤ 3× aliased", suite, r->ms / aliased->ms, 3, "×");
  }
  for (const char* suite : {"fan", "grid"})
    if (const Row* r = find(suite, "area")) {
      std::snprintf(buf, sizeof buf,
                    "| area's seam (no target: the known limit) | %s | mean %.2f, p99 %.1f, max %.1f | — |\n",
                    suite, r->err.mean, r->err.p99, r->err.max);
      md += buf;
    }

  // Each level in one table (the README's): its cost and the error it leaves, as medians over the 2D scenes,
  // and on the bunny.
  md +=
      "\n## Each level in one table\n\nMedians over the seven 2D scenes of this run (time as a multiple of "
      "the same scene aliased, with the least and the most; error over edge pixels, in 1/255), and the bunny "
      "(3D):\n\n"
      "| anti-aliasing | 2D time × aliased | 2D mean error | 2D p99 error | bunny time × aliased |"
      " bunny mean error |\n|---|---:|---:|---:|---:|---:|\n";
  for (const Level& level : kLevels) {
    std::vector<double> times, means, p99s;
    std::string name;
    for (const Suite& s : all) {
      if (s.shapes.empty()) continue;
      const Row* r = find(s.name, level.label);
      const Row* aliased = find(s.name, "1");
      if (!r || !aliased) continue;
      times.push_back(r->ms / aliased->ms), means.push_back(r->err.mean), p99s.push_back(r->err.p99);
      name = mode_name(*r);
    }
    if (times.empty()) continue;
    const auto [least, most] = std::minmax_element(times.begin(), times.end());
    std::snprintf(buf, sizeof buf, "| %s | %.2f (%.2f–%.2f) | %.2f | %.1f |", name.c_str(), median(times),
                  *least, *most, median(means), median(p99s));
    md += buf;
    const Row* bunny = find("bunny (3D)", level.label);
    const Row* bunny_aliased = find("bunny (3D)", "1");
    if (bunny && bunny_aliased && bunny->samples_used > 1 && level.area)  // 3D under "area" is multisampled
      std::snprintf(buf, sizeof buf, " %.2f (%d samples) | %.2f |\n", bunny->ms / bunny_aliased->ms,
                    bunny->samples_used, bunny->err.mean);
    else if (bunny && bunny_aliased)
      std::snprintf(buf, sizeof buf, " %.2f | %.2f |\n", bunny->ms / bunny_aliased->ms, bunny->err.mean);
    else
      std::snprintf(buf, sizeof buf, " — | — |\n");
    md += buf;
  }

  md +=
      "\n## Which mode to choose\n\nEach step of the sample count, as the median over the scenes of this run "
      "(error and time relative to the level before):\n\n"
      "| step | mean edge error | render time |\n|---|---:|---:|\n";
  for (std::size_t k = 1; k < kSampleLevels; ++k) {
    std::vector<double> err_ratio, time_ratio;
    for (const Suite& s : all) {
      const Row* a = find(s.name, kLevels[k - 1].label);
      const Row* b = find(s.name, kLevels[k].label);
      err_ratio.push_back(b->err.mean / a->err.mean);
      time_ratio.push_back(b->ms / a->ms);
    }
    std::snprintf(buf, sizeof buf, "| %d → %d samples | ×%.2f | ×%.2f |\n", kLevels[k - 1].samples,
                  kLevels[k].samples, median(err_ratio), median(time_ratio));
    md += buf;
  }
  md +=
      "\n- **`\"area\"`** for 2D: each pixel takes the exact share of its square that each shape covers, "
      "so an edge is within a level of exact whatever its angle, thin lines keep their true weight, and "
      "it costs per cut pixel, not per sample. Its limit is conflation: shapes are composited one after "
      "another, so where two shapes *share* an edge inside a pixel the background shows through (the fan "
      "and grid rows: a seam of the size shown above, about a quarter of the contrast on a half-covered "
      "pixel). A line segment is one shape, its rectangle's four edges in one record, and a polyline's "
      "segments are one shape too (their coverage is summed, at most 1, before compositing), so lines have "
      "no seam and translucent joints are not darker. Scenes with 3D content get 8 samples instead (the plan "
      "says so): with depth, a triangle's share of a pixel is not what is visible.\n"
      "- **1 (default)**: exactly the GPU rules and the fastest; on edge pixels the error is the whole step "
      "between two colours, by design.\n"
      "- **4, 8, 16 samples**: coverage per sample position (Direct3D's patterns), each pixel shaded once "
      "per primitive, a pixel's samples stored apart only where they differ, resolved per tile. No seams "
      "between "
      "abutting shapes (each sample belongs to exactly one of them), so meshes, fans and grids are exact "
      "where area is not; the error left is the pattern's: a fixed set of N points cannot measure an edge "
      "finer than about 1/N of a pixel, and along lines of rational slope the lattice aliases (a 45° line "
      "of width 1 is −12% of its area with 4 samples, +6% with 8, +1.5% with 16).\n"
      "- **`\"auto\"`**: aliased, then the pixels more than 8/255 from a neighbour drawn again at 8 samples; "
      "it pays where few pixels are edges (models), not in 2D scenes made mostly of edges.\n"
      "\n## Blend2D\n\nBlend2D is not a Debian package; to measure it, fetch it and AsmJit side by side, "
      "build "
      "it, and give the bench its checkout (nothing of it enters this repository):\n\n"
      "```sh\n"
      "git clone https://github.com/blend2d/blend2d && git clone https://github.com/asmjit/asmjit\n"
      "cmake -S blend2d -B blend2d/build -DCMAKE_BUILD_TYPE=Release -DBLEND2D_STATIC=ON -DBLEND2D_TEST=OFF\n"
      "cmake --build blend2d/build -j2\n"
      "make bench-accuracy BLEND2D_DIR=$PWD/blend2d\n"
      "```\n";
  // A record of what render version 2 changed, measured once between two binaries (not by this program):
  // the test Shading.FloatLanesAreWithinOneLevelOfTheDoubleReference holds every build to it.
  md +=
      "\n## 3D shading in float\n\n"
      "Render version 2 (issue 41) shades 3D triangles in float lanes, eight pixels a step, where version 1 "
      "shaded each pixel in doubles: the perspective-correct interpolation, the renormalised normal, the "
      "Lambert sum and the texture coordinates are floats; depth is still computed in doubles and rounded "
      "once to the float the depth buffer holds. Over the corpus of `scripts/compare-renders` (the examples, "
      "the Stanford bunny, the OBJ, STL, PLY and glTF 2.0 files of "
      "Debian's assimp-testmodels, each bare from two views and in scenes at 1, 4, 16 samples and area "
      "coverage under the default lights and a point-light rig), against version 1's binary (8c6648f): 467 "
      "renders compared, 64 differ, **by at most 1 level of 255**, and every golden image of version 1 kept "
      "its bytes. Measured 2026-11-26 by `scripts/compare-renders <rasterd of 8c6648f> build/rasterd`. "
      "`Shading.FloatLanesAreWithinOneLevelOfTheDoubleReference` (tests/shading_test.cpp) holds every build "
      "to one level of a double-precision reference on seeded random triangles, light rigs and textures.\n";
  std::ofstream(root + "/docs/accuracy.md") << md;

  // docs/accuracy.png: mean error against time, log-log, one line per scene through the sample counts,
  // a square for area and a cross for Cairo, drawn with rasterd.
  bench::PlotScene plot;
  plot.scene.width = 720;
  plot.scene.height = 460;
  plot.scene.background = {255, 255, 255, 255};
  plot.scene.antialias = raster::Antialias::area;
  const double left = 70, right = 560, top = 40, bottom = 400;
  double t_lo = 1e9, t_hi = 0, e_lo = 1e9, e_hi = 0;
  for (const Row& r : rows)
    t_lo = std::min(t_lo, r.ms), t_hi = std::max(t_hi, r.ms),
    e_lo = std::min(e_lo, std::max(r.err.mean, 0.05)), e_hi = std::max(e_hi, r.err.mean);
  const double lt0 = std::floor(std::log10(t_lo)), lt1 = std::ceil(std::log10(t_hi)),
               le0 = std::floor(std::log10(e_lo)), le1 = std::ceil(std::log10(e_hi));
  auto px = [&](double ms) { return left + (std::log10(ms) - lt0) / (lt1 - lt0) * (right - left); };
  auto py = [&](double e) {
    return bottom - (std::log10(std::max(e, 0.05)) - le0) / (le1 - le0) * (bottom - top);
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
  plot.text(left, 12,
            "error (1/255) against time: samples 1/4/8/16 (line), area (square), auto (diamond), Cairo (x), "
            "Blend2D (+)",
            ink, 1.2);
  const Rgba8 palette[] = {{220, 60, 60, 255},   {40, 120, 220, 255}, {30, 160, 90, 255},
                           {200, 130, 20, 255},  {140, 70, 200, 255}, {20, 160, 170, 255},
                           {120, 120, 120, 255}, {230, 90, 170, 255}};
  for (std::size_t series = 0; series < all.size(); ++series) {
    const Rgba8 col = palette[series % std::size(palette)];
    const std::string& name = all[series].name;
    for (std::size_t k = 0; k < kSampleLevels; ++k) {
      const Row& r = *find(name, kLevels[k].label);
      const Point2 c{px(r.ms), py(r.err.mean)};
      if (k > 0) {
        const Row& p = *find(name, kLevels[k - 1].label);
        plot.line({px(p.ms), py(p.err.mean)}, c, col, 2);
      }
      plot.tri({c.x - 3, c.y - 3}, {c.x + 3, c.y - 3}, {c.x + 3, c.y + 3}, col);
      plot.tri({c.x - 3, c.y - 3}, {c.x + 3, c.y + 3}, {c.x - 3, c.y + 3}, col);
    }
    if (const Row* a = find(name, "area")) {
      const Point2 c{px(a->ms), py(a->err.mean)};
      plot.line({c.x - 5, c.y - 5}, {c.x + 5, c.y - 5}, col, 2),
          plot.line({c.x + 5, c.y - 5}, {c.x + 5, c.y + 5}, col, 2);
      plot.line({c.x + 5, c.y + 5}, {c.x - 5, c.y + 5}, col, 2),
          plot.line({c.x - 5, c.y + 5}, {c.x - 5, c.y - 5}, col, 2);
    }
    if (const Row* a = find(name, "auto")) {  // a diamond
      const Point2 c{px(a->ms), py(a->err.mean)};
      plot.line({c.x, c.y - 6}, {c.x + 6, c.y}, col, 2), plot.line({c.x + 6, c.y}, {c.x, c.y + 6}, col, 2);
      plot.line({c.x, c.y + 6}, {c.x - 6, c.y}, col, 2), plot.line({c.x - 6, c.y}, {c.x, c.y - 6}, col, 2);
    }
    if (const Row* a = find(name, "Blend2D")) {  // a plus
      const Point2 c{px(a->ms), py(a->err.mean)};
      plot.line({c.x - 6, c.y}, {c.x + 6, c.y}, col, 2), plot.line({c.x, c.y - 6}, {c.x, c.y + 6}, col, 2);
    }
    if (const Row* a = find(name, "Cairo")) {
      const Point2 c{px(a->ms), py(a->err.mean)};
      plot.line({c.x - 5, c.y - 5}, {c.x + 5, c.y + 5}, col, 2),
          plot.line({c.x - 5, c.y + 5}, {c.x + 5, c.y - 5}, col, 2);
    }
    plot.line({right + 20, top + 12 + 16 * series}, {right + 40, top + 12 + 16 * series}, col, 3);
    plot.text(right + 46, top + 7 + 16 * series, name, ink, 1.2);
  }
  const raster::RenderPlan plan = raster::plan(plot.scene);
  const auto png = raster::encode_png(raster::render(plot.scene, plan), plan.png);
  std::ofstream(root + "/docs/accuracy.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  std::fprintf(stderr, "wrote docs/accuracy.md and docs/accuracy.png\n");
}
