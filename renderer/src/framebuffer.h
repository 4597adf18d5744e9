// Framebuffer: colour storage in the plan's pixel format, cleared to the background, and the bands that
// threads write to.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

/// A half-open pixel rectangle [x0, x1) x [y0, y1); bands and clip regions.
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// Allocates exactly plan.memory.color_bytes and fills it with the background.
Image make_color_buffer(const RenderPlan& plan, Rgba8 background);

/// Allocates exactly plan.memory.depth_bytes, cleared to 0 (reversed depth: infinitely far); none for 2D.
std::vector<float> make_depth_buffer(const RenderPlan& plan);

/// Row band `index` of `count` equal bands covering the image (the last takes the remainder).
Rect band(const RenderPlan& plan, int index, int count);

}  // namespace raster::detail
