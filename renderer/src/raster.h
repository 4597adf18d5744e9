// Raster: DrawList -> pixels of one band of the colour buffer. Triangle coverage by fixed-point edge
// functions with the top-left rule; 1-px lines by clipped, symmetric Bresenham.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "framebuffer.h"
#include "geometry.h"
#include "raster/image.h"

namespace raster::detail {

/// When a render must stop: the caller's deadline and cancel flag. `stopped` is shared by all bands so
/// that one band's discovery stops the others at their next check.
struct Stop {
  std::chrono::steady_clock::time_point deadline;
  const std::atomic<bool>* cancel;
  std::atomic<bool>* stopped;
  const std::function<std::chrono::steady_clock::time_point()>* clock;  ///< empty: steady_clock::now
  bool now() const;
};

/// One band's account of work done since it last asked `Stop`: a pixel written or tested is 1 unit, a row
/// of a primitive kRowWork, a primitive kPrimitiveWork. Every kWorkPerCheck units it asks again, so the
/// time between two checks is bounded by what ~64k pixels cost (under a millisecond with full shading),
/// whether the work is a million small triangles or one that covers the image.
class StopMeter {
 public:
  static constexpr std::int64_t kWorkPerCheck = 1 << 16;
  static constexpr std::int64_t kRowWork = 16;
  static constexpr std::int64_t kPrimitiveWork = 64;

  explicit StopMeter(const Stop& stop) : stop_(stop) {}
  /// Counts `work`; true once the render must stop (and from then on).
  bool add(std::int64_t work) {
    if ((work_ += work) < kWorkPerCheck) return stopped_;
    work_ = 0;
    return stopped_ = stop_.now();
  }
  /// Asks now, whatever the count: at the start of a band, so an expired deadline stops even a tiny render.
  bool check() { return stopped_ = stop_.now(); }
  bool stopped() const { return stopped_; }

 private:
  const Stop& stop_;
  std::int64_t work_ = 0;
  bool stopped_ = false;
};

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
