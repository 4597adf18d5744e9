// Framebuffer: RenderPlan -> the colour buffer and sample planes in the plan's pixel format, cleared to the
// background; and the resolve of sample planes into the output. (Depth lives in each thread's tile storage.)
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"
#include "raster/scene.h"
#include "setup.h"
#include "stop.h"

namespace raster::detail {

/// Allocates exactly plan.memory.color_bytes and fills it with the background; the `output` image (not a
/// sample plane) reserves room for the PNG filter bytes. Returns early, incomplete, once `meter` says the
/// render must stop (it is asked every megabyte).
Image make_color_buffer(const RenderPlan& plan, Rgba8 background, StopMeter& meter, bool output = true);

/// Averages the sample planes into `out` over `rect`: the plain mean for opaque formats, and for formats
/// with alpha the mean of premultiplied values (a transparent sample adds no colour), rounded to nearest.
void resolve(const std::vector<Image>& planes, Image& out, Rect rect);

}  // namespace raster::detail
