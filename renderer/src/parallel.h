// Parallel: one render's independent pieces of work (parts of a mesh, tiles) spread over its threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

#include "stop.h"

namespace raster::detail {

/// Runs work(piece, meter, thread) once for every piece in [0, count), on at most `threads` threads: the
/// calling thread is thread 0, and with one thread (or one piece) no other is started. Pieces are taken in
/// order by whichever thread is free; each must write only its own output, so what the pieces make does not
/// depend on which thread made them. Each thread counts its work on its own meter, which asks `stop` when
/// the thread starts (an expired deadline stops even the smallest render) and then as work adds up; a
/// stopped thread takes no further piece, and the caller sees `stop.stopped`.
template <typename Work>
void parallel_for(int threads, std::size_t count, const Stop& stop, Work&& work) {
  const int n =
      static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count));
  std::atomic<std::size_t> next{0};
  auto run = [&](int thread) {
    StopMeter meter(stop);
    if (meter.check()) return;
    for (std::size_t piece; (piece = next.fetch_add(1, std::memory_order_relaxed)) < count;) {
      work(piece, meter, thread);
      if (meter.stopped()) return;
    }
  };
  if (n <= 1) return run(0);
  std::vector<std::jthread> others;
  others.reserve(static_cast<std::size_t>(n - 1));
  for (int t = 1; t < n; ++t) others.emplace_back(run, t);
  run(0);
}  // the other threads join here

}  // namespace raster::detail
