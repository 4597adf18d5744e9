// Framebuffer: colour storage in the plan's pixel format, cleared to the background, and the bands that
// threads write to.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"
#include "raster/scene.h"
#include "stop.h"

namespace raster::detail {

/// A half-open pixel rectangle [x0, x1) x [y0, y1); bands and clip regions.
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// Allocates exactly plan.memory.color_bytes and fills it with the background; the `output` image (not a
/// sample plane) reserves room for the PNG filter bytes. Returns early, incomplete, once `meter` says the
/// render must stop (it is asked every megabyte).
Image make_color_buffer(const RenderPlan& plan, Rgba8 background, StopMeter& meter, bool output = true);

/// One depth plane, cleared to 0 (reversed depth: infinitely far); empty for 2D. Aliased renders have one
/// (the plan's depth_bytes), anti-aliased ones one per sample (part of its sample_bytes).
/// Returns early, incomplete, once `meter` says the render must stop.
std::vector<float> make_depth_buffer(const RenderPlan& plan, StopMeter& meter);

/// Averages the sample planes into `out` over `band`: the plain mean for opaque formats, and for formats
/// with alpha the mean of premultiplied values (a transparent sample adds no colour), rounded to nearest.
void resolve(const std::vector<Image>& planes, Image& out, Rect band);

/// Row band `index` of `count` equal bands covering the image (the last takes the remainder).
Rect band(const RenderPlan& plan, int index, int count);

}  // namespace raster::detail
