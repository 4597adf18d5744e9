// Render: executes a RenderPlan over a Scene and returns the finished Image.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <stdexcept>

#include "raster/budget.h"
#include "raster/image.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster {

/// What a render reports back.
struct RenderStats {
  std::int64_t pixel_bytes = 0;  ///< bytes allocated for pixel storage: output, tile storage, samples, depth
  std::int64_t bin_bytes = 0;    ///< bytes of the tile bins: 4 per record per tile it may touch, 4 per tile
  std::int64_t records = 0;      ///< triangle and line records set up
  std::int64_t bin_entries = 0;  ///< record-tile pairs in the bins
  std::int64_t shaded_pixels = 0;  ///< multisampled renders: pixels shaded, once per pixel per triangle
                                   ///< whatever the samples it covers; 0 for other renders
  std::int64_t edge_blocks = 0;    ///< "antialias": "auto": the 8x8 blocks holding an edge pixel
  std::int64_t edge_pixels = 0;    ///< "antialias": "auto": the pixels drawn again multisampled
  // Wall time of each stage, milliseconds (filled only when stats are asked for):
  double geometry_ms = 0;    ///< transform, lighting per face, clipping, projection and setup of every record
  double bin_ms = 0;         ///< binning the records to tiles
  double clear_ms = 0;       ///< allocating and clearing the colour buffer and the tile storage
  double tiles_ms = 0;       ///< coverage and shading of every tile (all threads), and the resolve
  double find_edges_ms = 0;  ///< "antialias": "auto": finding the edge pixels in the aliased picture
  double edge_tiles_ms = 0;  ///< "antialias": "auto": drawing them again multisampled (all threads)
};

/// Per-render control from the caller: a deadline and a cancel flag. Both are looked at when each thread
/// starts and then after every ~64k pixels of work (inside a primitive too, so one image-sized triangle is
/// checked every few dozen rows), so a render stops within a bounded time of its deadline however its work
/// is split (docs/robustness.md has the measured bound). Nothing here is process-wide.
struct RenderControl {
  using Clock = std::chrono::steady_clock;
  Clock::time_point deadline = Clock::time_point::max();  ///< the render stops once clock() >= deadline
  const std::atomic<bool>* cancel = nullptr;  ///< optional; true stops the render (e.g. on shutdown)
  RenderStats* stats = nullptr;               ///< optional; filled in by render()
  /// Optional; the time source for `deadline` (empty: steady_clock::now). Tests inject one to decide
  /// when the deadline passes without depending on how fast the machine is. Called from every thread's
  /// thread, so it must be thread-safe.
  std::function<Clock::time_point()> clock;
  /// Optional; asked for the bins' bytes once they are counted, before they are filled (the pixel buffers
  /// and the records were reserved by the plan). A refusal stops the render with MemoryRefused.
  Budget* budget = nullptr;
};

/// Draws `scene` exactly as `plan` says. The plan must have been made from this scene.
/// Output is the same bytes for any plan.threads.
Image render(const Scene& scene, const RenderPlan& plan, const RenderControl& control = {});

/// Convenience: plan with default options, then render.
Image render(const Scene& scene, const Limits& limits = {});

}  // namespace raster
