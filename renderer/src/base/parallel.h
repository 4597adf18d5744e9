// Parallel: one render's independent pieces of work (parts of a mesh, tiles) spread over its threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <vector>

#include "base/stop.h"

namespace raster::detail {

/// One parallel_for in flight: its pieces and who is working on them. Lives on the caller's stack.
struct ParallelJob {
  std::size_t count = 0;             ///< pieces, [0, count)
  std::atomic<std::size_t> next{0};  ///< the next piece not yet taken
  int helpers_wanted = 0;            ///< threads beyond the caller that may join (threads - 1)
  int helpers_joined = 0;            ///< how many have joined (guarded by the pool's mutex)
  int helpers_active = 0;            ///< joined and not yet left (guarded by the pool's mutex)
  void (*run)(void* context, int thread) = nullptr;  ///< takes pieces until none is left, as `thread`
  void* context = nullptr;
};

/// Runs `job` on the calling thread (as thread 0) and on up to job.helpers_wanted of the process's helper
/// threads (threads 1, 2, ... in the order they join), and returns when every piece is done. The helpers
/// are started once, on first need, and kept for the life of the process: a render does not pay for
/// starting threads (about 60 us each on the 2-core test VM). They are shared by every render in the process;
/// a helper busy elsewhere simply does not join, and the caller always works, so no render waits for
/// another. Which thread runs a piece never changes what the piece makes.
void run_parallel(ParallelJob& job);

/// Runs work(piece, meter, thread) once for every piece in [0, count), on at most `threads` threads: the
/// calling thread is thread 0, and with one thread (or one piece) no other is asked. Pieces are taken in
/// order by whichever thread is free; each must write only its own output, so what the pieces make does not
/// depend on which thread made them. Each thread counts its work on its own meter, which asks `stop` when
/// the thread starts (an expired deadline stops even the smallest render) and then as work adds up; a
/// stopped thread takes no further piece, and the caller sees `stop.stopped`. `thread` is below `threads`.
template <typename Work>
void parallel_for(int threads, std::size_t count, const Stop& stop, Work&& work) {
  const int n =
      static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count));
  struct Context {
    ParallelJob job;
    const Stop& stop;
    Work& work;
  } context{{}, stop, work};
  ParallelJob& job = context.job;
  job.count = count;
  job.helpers_wanted = n - 1;
  job.context = &context;
  job.run = [](void* c, int thread) {
    Context& ctx = *static_cast<Context*>(c);
    StopMeter meter(ctx.stop);
    if (meter.check()) return;
    for (std::size_t piece; (piece = ctx.job.next.fetch_add(1, std::memory_order_relaxed)) < ctx.job.count;) {
      ctx.work(piece, meter, thread);
      if (meter.stopped()) return;
    }
  };
  if (n <= 1) return job.run(&context, 0);
  run_parallel(job);
}

/// Runs work(piece) once for every piece in [0, count) on at most `threads` threads, as parallel_for does,
/// for work that reports failure by throwing (a reader's SceneError, RenderCancelled, MemoryRefused): each
/// piece's exception is kept, the pieces after a failed one are still run or skipped as they come (their
/// outcome is not needed), and once all are done the exception of the lowest failed piece is rethrown, so
/// the caller sees the same failure whatever the thread count.
template <typename Work>
void run_pieces(int threads, std::size_t count, Work&& work) {
  std::vector<std::exception_ptr> failed(count);
  std::atomic<std::size_t> first_failed{count};  // pieces after it need not run
  std::atomic<bool> never{false};
  const Stop stop{std::chrono::steady_clock::time_point::max(), nullptr, &never, nullptr};
  parallel_for(threads, count, stop, [&](std::size_t piece, StopMeter&, int) {
    if (piece > first_failed.load(std::memory_order_relaxed)) return;
    try {
      work(piece);
    } catch (...) {
      failed[piece] = std::current_exception();
      for (std::size_t f = first_failed.load(); piece < f && !first_failed.compare_exchange_weak(f, piece);) {
      }
    }
  });
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace raster::detail
