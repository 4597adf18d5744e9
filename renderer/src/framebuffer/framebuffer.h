// Framebuffer: RenderPlan -> the colour buffer in the plan's pixel format, cleared to the background.
// (Depth, samples and coverage accumulation live in each thread's tile storage, framebuffer/tiles.h.)
#pragma once

#include <cstdint>
#include <vector>

#include "base/stop.h"
#include "raster/image.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

/// Allocates exactly plan.memory.color_bytes and fills it with the background, reserving room for the PNG
/// filter bytes. Returns early, incomplete, once `meter` says the render must stop (it is asked every
/// megabyte).
Image make_color_buffer(const RenderPlan& plan, Rgba8 background, StopMeter& meter);

}  // namespace raster::detail
