#include "support.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace test {

SceneBuilder::SceneBuilder(int width, int height, Rgba8 background) {
  scene.width = width;
  scene.height = height;
  scene.background = background;
}

static void push(raster::Scene& s, raster::PrimitiveKind kind, std::initializer_list<Point2> pts,
                 std::initializer_list<Rgba8> colors, bool fill, bool closed) {
  raster::Primitive p;
  p.kind = kind;
  p.first_point = static_cast<std::uint32_t>(s.points.size());
  p.point_count = static_cast<std::uint32_t>(pts.size());
  p.first_color = static_cast<std::uint32_t>(s.colors.size());
  p.per_vertex_color = colors.size() > 1;
  p.fill = fill;
  p.closed = closed;
  s.points.insert(s.points.end(), pts);
  s.colors.insert(s.colors.end(), colors);
  s.primitives.push_back(p);
}

SceneBuilder& SceneBuilder::triangle(Point2 a, Point2 b, Point2 c, Rgba8 color, bool fill) {
  push(scene, raster::PrimitiveKind::triangle, {a, b, c}, {color}, fill, false);
  return *this;
}
SceneBuilder& SceneBuilder::triangle(Point2 a, Point2 b, Point2 c, Rgba8 ca, Rgba8 cb, Rgba8 cc) {
  push(scene, raster::PrimitiveKind::triangle, {a, b, c}, {ca, cb, cc}, true, false);
  return *this;
}
SceneBuilder& SceneBuilder::line(Point2 a, Point2 b, Rgba8 color) {
  push(scene, raster::PrimitiveKind::line, {a, b}, {color}, true, false);
  return *this;
}
SceneBuilder& SceneBuilder::line(Point2 a, Point2 b, Rgba8 ca, Rgba8 cb) {
  push(scene, raster::PrimitiveKind::line, {a, b}, {ca, cb}, true, false);
  return *this;
}
SceneBuilder& SceneBuilder::polyline(std::vector<Point2> points, Rgba8 color, bool closed) {
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::polyline;
  p.first_point = static_cast<std::uint32_t>(scene.points.size());
  p.point_count = static_cast<std::uint32_t>(points.size());
  p.first_color = static_cast<std::uint32_t>(scene.colors.size());
  p.closed = closed;
  scene.points.insert(scene.points.end(), points.begin(), points.end());
  scene.colors.push_back(color);
  scene.primitives.push_back(p);
  return *this;
}

raster::Antialias multisample(int samples) {
  raster::Antialias mode{};
  if (!raster::antialias_of_samples(samples, mode)) std::abort();
  return mode;
}

raster::Image render(const raster::Scene& scene, int threads) {
  raster::PlanOptions options;
  options.max_threads = threads;
  raster::RenderPlan plan = raster::plan(scene, raster::Limits{}, options);
  return raster::render(scene, plan);
}

Rgba8 pixel(const raster::Image& image, int x, int y) {
  const std::uint8_t* p = image.at(x, y);
  switch (image.format) {
    case raster::PixelFormat::grey8:
      return {p[0], p[0], p[0], 255};
    case raster::PixelFormat::grey_alpha8:
      return {p[0], p[0], p[0], p[1]};
    case raster::PixelFormat::rgb8:
      return {p[0], p[1], p[2], 255};
    case raster::PixelFormat::rgba8:
      return {p[0], p[1], p[2], p[3]};
  }
  return {};
}

std::vector<std::uint8_t> mask_not(const raster::Image& image, Rgba8 background) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(image.width) * image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      mask[static_cast<std::size_t>(y) * image.width + x] = !(pixel(image, x, y) == background);
  return mask;
}

int count_not(const raster::Image& image, Rgba8 background) {
  int n = 0;
  for (std::uint8_t m : mask_not(image, background)) n += m;
  return n;
}

Decoded decode_png(const std::vector<std::uint8_t>& png) {
  Decoded d;
  unsigned char* data =
      stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &d.width, &d.height, &d.channels, 0);
  if (!data) throw std::runtime_error(std::string("PNG does not decode: ") + stbi_failure_reason());
  d.pixels.assign(data, data + static_cast<std::size_t>(d.width) * d.height * d.channels);
  stbi_image_free(data);
  return d;
}

Decoded decode_png(const std::string& png) {
  return decode_png(std::vector<std::uint8_t>(png.begin(), png.end()));
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::uint64_t image_hash(const raster::Image& image) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](std::uint8_t b) { h = (h ^ b) * 1099511628211ull; };
  mix(static_cast<std::uint8_t>(image.format));
  for (std::uint8_t b : image.pixels) mix(b);
  return h;
}

}  // namespace test
