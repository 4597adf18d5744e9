// Stop: when a render must end early (its deadline passed, or the caller cancelled it), and the meter
// through which every stage that does long work (geometry, drawing, resolving) asks.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>

#include "raster/budget.h"

namespace raster::detail {

/// When a render must stop: the caller's deadline and cancel flag. `stopped` is shared by all threads so
/// that one thread's discovery stops the others at their next check.
struct Stop {
  std::chrono::steady_clock::time_point deadline;
  const std::atomic<bool>* cancel;
  std::atomic<bool>* stopped;
  const std::function<std::chrono::steady_clock::time_point()>* clock;  ///< empty: steady_clock::now
  Budget* budget = nullptr;  ///< optional: asked for memory a stage has counted
  /// Bytes of the first ask the budget refused (0: none); a refusal stops the render as the deadline does.
  std::atomic<std::int64_t>* refused = nullptr;
  /// True once the render must stop (another thread saw it, the caller cancelled, or the deadline passed);
  /// remembered in `stopped` for every thread.
  bool now() const;
  /// Asks the budget for `bytes` (true without one); a refusal is remembered and stops every thread.
  bool reserve(std::int64_t bytes) const {
    if (!budget || bytes <= 0 || budget->reserve(bytes)) return true;
    std::int64_t none = 0;
    refused->compare_exchange_strong(none, bytes);
    stopped->store(true, std::memory_order_relaxed);
    return false;
  }
};

/// One thread's account of work done since it last asked `Stop`: a pixel written or tested is 1 unit, a row
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
  /// Asks now, whatever the count: when a thread starts, so an expired deadline stops even a tiny render.
  bool check() { return stopped_ = stop_.now(); }
  bool stopped() const { return stopped_; }
  /// What it asks: other threads of the render make their own meters from it.
  const Stop& stop() const { return stop_; }

 private:
  const Stop& stop_;
  std::int64_t work_ = 0;
  bool stopped_ = false;
};

}  // namespace raster::detail
