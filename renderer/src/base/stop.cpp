#include "base/stop.h"

namespace raster::detail {

bool Stop::now() const {
  if (stopped->load(std::memory_order_relaxed)) return true;
  const bool stop = (cancel && cancel->load(std::memory_order_relaxed)) ||
                    (clock && *clock ? (*clock)() : std::chrono::steady_clock::now()) >= deadline;
  if (stop) stopped->store(true, std::memory_order_relaxed);
  return stop;
}

}  // namespace raster::detail
