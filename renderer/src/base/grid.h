// Grid: the pixel and sub-pixel grid every stage after the plan works on. Pixel (i, j) is the square
// [i, i+1) x [j, j+1); coverage tests points on a 1/256 px fixed-point grid (a pixel's centre is (128, 128)
// of its 256 x 256 units), in square blocks of kBlock pixels. Coordinates go in as pixels (snap) and come out
// as integral 1/256 px units.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace raster::detail {

inline constexpr int kSubpixelBits = 8;                             ///< GPU-style 8 sub-pixel bits
inline constexpr std::int64_t kSubpixelScale = 1 << kSubpixelBits;  ///< fixed-point units per pixel

/// Triangles (and line quads) whose vertices all lie within +-kFastRangePx take the int64 records: snapped
/// coordinates fit in 24 bits, so every edge value at a pixel of the image fits in 50 bits (exact in a
/// double, too). Others take the exact wide records (wide.h). The plan reads it to choose line quads.
inline constexpr double kFastRangePx = 32768.0;

/// Coverage works on square blocks of this many pixels a side; tiles are whole blocks.
inline constexpr int kBlock = 8;

/// A half-open pixel rectangle [x0, x1) x [y0, y1): tiles, bounding boxes, clip regions.
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

/// Where in each pixel coverage is tested: 1/256 px from the pixel's top-left corner; (128, 128) is the
/// centre. Multisampling tests every position of a standard pattern.
struct SamplePoint {
  std::int32_t x = 128, y = 128;
};

/// The standard (Direct3D) sample pattern for each count of kSampleCounts (scene.h), on the 1/256 px grid
/// (grid.cpp). Throws std::logic_error for any other count.
const std::vector<SamplePoint>& sample_pattern(int samples);

/// Snaps a coordinate (pixels) to an integral number of 1/256 px, rounding half up, so that translating by
/// whole pixels translates the result exactly.
inline double snap(double px) {
  const double units = px * static_cast<double>(kSubpixelScale);  // exact: a power-of-two scale
  // From 2^52 up every double is already an integer; adding 0.5 there would round to even instead.
  return std::fabs(units) >= 0x1p52 ? units : std::floor(units + 0.5);
}

}  // namespace raster::detail
