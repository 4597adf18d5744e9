// How the readers and the plan ask a render's Budget (raster/budget.h): memory before they allocate what
// their counts call for, and whether to stop. One place, so every stage refuses and stops alike.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

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

/// Throws RenderCancelled once the budget says the render must stop. Cheap: readers call it every
/// kLinesPerCheck lines or elements.
inline void stop_if_expired(const Limits& limits) {
  if (limits.budget && limits.budget->expired())
    throw RenderCancelled("stopped while reading: deadline passed or cancelled");
}
inline constexpr std::uint32_t kLinesPerCheck = 1u << 16;

}  // namespace raster::detail
