// Edges: an aliased picture -> the pixels that differ visibly from a neighbour. Edge-sampled anti-aliasing
// (Coverage::edge_samples) draws every tile aliased, finds these pixels over the whole image, and draws
// only them again multisampled: inside a smooth surface neighbouring pixels differ by a shade or two and
// multisampling would give back about the same colours, so only silhouettes, creases and depth steps pay
// for samples.
#pragma once

#include <cstdint>
#include <vector>

#include "base/grid.h"
#include "base/masks.h"
#include "base/stop.h"
#include "raster/image.h"

namespace raster::detail {

/// Two neighbouring pixels (side by side, one above the other, or diagonal) are an edge when a channel
/// differs by more than this (in 1/255): docs/accuracy.md's measure counts a pixel as an edge pixel when its
/// 64 reference samples differ by more than 8, and a smaller step stays within the error the picture is
/// judged by. Measured on the model corpus (bench/model_defaults, mean edge error; models no worse than 4
/// samples; edge pixels of the knot at 512x512): 4 gives 1.74, 46 of 47, 37,337 pixels; 8 gives 1.74, 46 of
/// 47, 18,001; 16 gives 1.91, 45 of 47, 10,872; 32 gives 2.33, 38 of 47, 9,284.
inline constexpr int kEdgeContrast = 8;

/// The image's edge pixels: those that differ by more than the contrast from a neighbour in the eight
/// directions (inside the image), as a mask per 8x8 block (base/masks.h's layout).
struct EdgePixels {
  int columns = 0, rows = 0;  ///< blocks a row, block rows: the image's size in blocks, rounded up
  /// columns x rows, row-major: bit 8 r + i for pixel (8 bx + i, 8 by + r)
  std::vector<std::uint64_t> masks;
  std::int64_t pixels = 0;  ///< edge pixels
  std::int64_t blocks = 0;  ///< blocks with an edge pixel
  std::int64_t bytes = 0;   ///< allocated to find them (MemoryPlan::edge_bytes)

  BlockMasks view() const { return {masks.data(), columns}; }
  /// Whether a pixel of `rect` (inside the image) is an edge pixel.
  bool any_in(Rect rect) const;
};

/// The edge pixels of `image` at `contrast` (kEdgeContrast unless a test asks otherwise). Counts a row's
/// pixels of work on `meter` and returns early, incomplete, once it says the render must stop.
EdgePixels find_edge_pixels(const Image& image, StopMeter& meter, int contrast = kEdgeContrast);

}  // namespace raster::detail
