// The memory budget: what the service's requests may hold at once, and each request's share of it. A request
// reserves before it takes: its body's bytes as they are declared or arrive, then what the readers and the
// plan count it will need (raster::Budget). One that cannot get its reservation waits, within the queue's
// bound, for others to give theirs back, and is otherwise refused; so requests within every limit can no
// longer together take more memory than the container has.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>

#include "raster/budget.h"

namespace rasterd {

/// All requests' reservations, within a capacity.
class MemoryPool {
 public:
  using Clock = std::chrono::steady_clock;
  explicit MemoryPool(std::int64_t capacity) : capacity_(capacity) {}

  /// Takes `bytes`, waiting until `until` for others to give back. False when they were not free by then,
  /// at once when they could never be (more than the capacity).
  bool take(std::int64_t bytes, Clock::time_point until);
  void give(std::int64_t bytes);

  std::int64_t capacity() const { return capacity_; }  ///< bytes
  std::int64_t reserved() const;                       ///< bytes held now
  std::int64_t peak() const;                           ///< most bytes held at once since start

 private:
  const std::int64_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable freed_;
  std::int64_t reserved_ = 0, peak_ = 0;
};

/// One request's account: what it took from the pool, all given back when it ends. Also the library's
/// raster::Budget for its parse, plan and render: each ask waits at most `max_wait`, and not past the
/// request's deadline.
class RequestBudget final : public raster::Budget {
 public:
  using Clock = MemoryPool::Clock;
  RequestBudget(MemoryPool& pool, std::chrono::milliseconds max_wait) : pool_(pool), max_wait_(max_wait) {}
  ~RequestBudget() override { pool_.give(held_.load()); }
  RequestBudget(const RequestBudget&) = delete;
  RequestBudget& operator=(const RequestBudget&) = delete;

  /// From here on, asks do not wait past `deadline`, and expired() is true after it or once `cancel` is set.
  void start_render(Clock::time_point deadline, const std::atomic<bool>* cancel) {
    deadline_ = deadline, cancel_ = cancel;
  }
  bool reserve(std::int64_t bytes) noexcept override;
  bool expired() const noexcept override;
  /// Gives back what was freed early (the body, once parsed; a reader's scratch, once the mesh is made).
  void release(std::int64_t bytes) noexcept override;

  std::int64_t held() const { return held_.load(); }  ///< bytes
  /// Held plus the ask that was refused: what the request would have needed at the point it stopped.
  std::int64_t wanted() const { return held_.load() + refused_.load(); }

 private:
  MemoryPool& pool_;
  const std::chrono::milliseconds max_wait_;
  Clock::time_point deadline_ = Clock::time_point::max();
  const std::atomic<bool>* cancel_ = nullptr;
  std::atomic<std::int64_t> held_{0}, refused_{0};
};

}  // namespace rasterd
