// Render: executes a RenderPlan over a Scene and returns the finished Image.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>

#include "raster/image.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster {

/// What a render reports back.
struct RenderStats {
  std::int64_t pixel_bytes = 0;  ///< bytes allocated for pixel storage: output, sample planes, depth
};

/// Per-render control from the caller: a deadline and a cancel flag, checked between batches of
/// primitives in every band. Nothing here is process-wide.
struct RenderControl {
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  const std::atomic<bool>* cancel = nullptr;  ///< optional; true stops the render (e.g. on shutdown)
  RenderStats* stats = nullptr;               ///< optional; filled in by render()
};

/// Thrown by render() when the deadline passed or the cancel flag was set; no image is returned.
class RenderCancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Draws `scene` exactly as `plan` says. The plan must have been made from this scene.
/// Output is the same bytes for any plan.threads.
Image render(const Scene& scene, const RenderPlan& plan, const RenderControl& control = {});

/// Convenience: plan with default options, then render.
Image render(const Scene& scene, const Limits& limits = {});

}  // namespace raster
