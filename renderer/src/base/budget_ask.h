// How the readers and the plan ask a render's Budget (raster/budget.h): memory before they allocate what
// their counts call for, and whether to stop. One place, so every stage refuses and stops alike.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include "base/memory.h"
#include "raster/budget.h"
#include "raster/scene.h"

namespace raster::detail {

/// Takes `bytes` from `budget` (nothing without one); throws MemoryRefused naming `what()` when refused.
/// `what` is called only then: most renders have no budget, and none should format words it never shows.
template <typename What>
void reserve(Budget* budget, std::int64_t bytes, What&& what) {
  if (budget && bytes > 0 && !budget->reserve(bytes)) throw MemoryRefused(bytes, what());
}
template <typename What>
void reserve(const Limits& limits, std::int64_t bytes, What&& what) {
  reserve(limits.budget, bytes, std::forward<What>(what));
}

/// Gives `bytes` back to `limits`' budget (nothing without one): what a stage reserved and has freed.
inline void release(const Limits& limits, std::int64_t bytes) {
  if (limits.budget && bytes > 0) limits.budget->release(bytes);
}

/// Room for `n` elements in a reader's array `v` (std::vector), grown geometrically (at least twice its
/// capacity) and asked of the budget: the larger array before it is made, the smaller given back once its
/// elements have moved. New storage is advised to take huge pages (reserve_huge).
template <typename Vector, typename What>
void grow_asked(const Limits& limits, Vector& v, std::size_t n, What&& what) {
  if (n <= v.capacity()) return;
  const std::size_t capacity = std::max(n, 2 * v.capacity()), old = v.capacity();
  reserve(limits, static_cast<std::int64_t>(capacity * sizeof(v[0])), std::forward<What>(what));
  reserve_huge(v, capacity);
  release(limits, static_cast<std::int64_t>(old * sizeof(v[0])));
}

/// Throws RenderCancelled once the budget says the render must stop. Cheap: readers call it every
/// kLinesPerCheck lines or elements.
inline void stop_if_expired(const Limits& limits) {
  if (limits.budget && limits.budget->expired())
    throw RenderCancelled("stopped while reading: deadline passed or cancelled");
}
inline constexpr std::uint32_t kLinesPerCheck = 1u << 16;

/// A reader's account of work since it last asked the budget whether to stop: a line, element, vertex,
/// corner or point test is a unit, and every kLinesPerCheck units it asks (stop_if_expired). So a reader
/// stops within that much work of the deadline however its work is shaped: many short lines, one PLY face
/// of a million corners, or a concave polygon's ear clipping. Without a budget it only counts.
class ReadMeter {
 public:
  explicit ReadMeter(const Limits& limits) : limits_(limits) {}
  /// Counts `work` units; throws RenderCancelled once they add up to a check that finds the deadline passed.
  void add(std::uint64_t work) {
    if ((work_ += work) < kLinesPerCheck) return;
    work_ = 0;
    stop_if_expired(limits_);
  }
  /// Asks now, whatever the count: before a step whose work is not counted unit by unit (a library's
  /// parse, a texture's decoding).
  void check() {
    work_ = 0;
    stop_if_expired(limits_);
  }

 private:
  const Limits& limits_;
  std::uint64_t work_ = 0;
};

}  // namespace raster::detail
