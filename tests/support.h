// Test support: building scenes in code, rendering them, reading pixels, decoding PNGs.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "raster/raster.h"

namespace test {

using raster::Point2;
using raster::Rgba8;

inline constexpr Rgba8 kBlack{0, 0, 0, 255};
inline constexpr Rgba8 kWhite{255, 255, 255, 255};
inline constexpr Rgba8 kRed{255, 0, 0, 255};
inline constexpr Rgba8 kGreen{0, 255, 0, 255};
inline constexpr Rgba8 kBlue{0, 0, 255, 255};

/// Builds a Scene in code, without JSON.
struct SceneBuilder {
  raster::Scene scene;
  SceneBuilder(int width, int height, Rgba8 background = kBlack);
  SceneBuilder& triangle(Point2 a, Point2 b, Point2 c, Rgba8 color, bool fill = true);
  SceneBuilder& triangle(Point2 a, Point2 b, Point2 c, Rgba8 ca, Rgba8 cb, Rgba8 cc);
  SceneBuilder& line(Point2 a, Point2 b, Rgba8 color);
  SceneBuilder& line(Point2 a, Point2 b, Rgba8 ca, Rgba8 cb);
  SceneBuilder& polyline(std::vector<Point2> points, Rgba8 color, bool closed);
};

/// The multisampling mode of `samples` per pixel (1, 4, 8 or 16; anything else aborts the test binary):
/// for tests that loop over sample counts.
raster::Antialias multisample(int samples);

/// Renders with a fixed thread count (1 unless a test is about threads).
raster::Image render(const raster::Scene& scene, int threads = 1);

/// The pixel at (x, y) as RGBA, whatever the image's format (grey expands to r = g = b; no alpha = 255).
Rgba8 pixel(const raster::Image& image, int x, int y);

/// How many pixels differ from `background`.
int count_not(const raster::Image& image, Rgba8 background);

/// A coverage mask: 1 where the pixel differs from `background`, row-major.
std::vector<std::uint8_t> mask_not(const raster::Image& image, Rgba8 background);

/// Decodes a PNG with stb_image; channels = what the file holds.
struct Decoded {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> pixels;
};
Decoded decode_png(const std::vector<std::uint8_t>& png);
Decoded decode_png(const std::string& png);

std::string read_file(const std::string& path);

/// FNV-1a over the pixel bytes and format, for golden images.
std::uint64_t image_hash(const raster::Image& image);

}  // namespace test
