// Raster: DrawList -> pixels of one band of the colour buffer. Triangle coverage by fixed-point edge
// functions with the top-left rule; 1-px lines by clipped, symmetric Bresenham.
#pragma once

#include <atomic>
#include <chrono>

#include "framebuffer.h"
#include "geometry.h"
#include "raster/image.h"

namespace raster::detail {

/// When a render must stop: checked between batches of ops. `stopped` is shared by all bands so that one
/// band's discovery stops the others at their next check.
struct Stop {
  std::chrono::steady_clock::time_point deadline;
  const std::atomic<bool>* cancel;
  std::atomic<bool>* stopped;
  bool now() const;
};

/// Draws every op of `list`, in order, into the pixels of `image` inside `clip`; 3D ops also test and write
/// `depth` (row-major like the image; nullptr when the plan has no depth buffer). Pixels outside `clip`
/// are not read or written, so disjoint clips can run on different threads.
void draw(const DrawList& list, Image& image, float* depth, Rect clip, const Stop& stop);

}  // namespace raster::detail
