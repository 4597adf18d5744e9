// Raster: DrawList -> pixels of one band of the colour buffer. Triangle coverage by fixed-point edge
// functions with the top-left rule; 1-px lines by clipped, symmetric Bresenham.
#pragma once

#include <vector>

#include "framebuffer.h"
#include "geometry.h"
#include "raster/image.h"
#include "stop.h"

namespace raster::detail {

/// Where in each pixel coverage is tested: 1/256 px from the pixel's top-left corner; (128, 128) is the
/// centre. Anti-aliasing draws the list once per sample position of the standard patterns.
struct SamplePoint {
  std::int32_t x = 128, y = 128;
};

/// The standard (Direct3D) sample patterns for 1, 4, 8 and 16 samples, on the 1/256 px grid.
const std::vector<SamplePoint>& sample_pattern(int samples);

/// Draws every op of `list`, in order, into the pixels of `image` inside `clip`; 3D ops also test and write
/// `depth` (row-major like the image; nullptr when the plan has no depth buffer). Pixels outside `clip`
/// are not read or written, so disjoint clips can run on different threads. Returns early, with the image
/// half drawn, once `meter` says the render must stop.
void draw(const DrawList& list, Image& image, float* depth, Rect clip, StopMeter& meter,
          SamplePoint sample = {});

}  // namespace raster::detail
