#include "memory_budget.h"

#include <algorithm>

namespace rasterd {

bool MemoryPool::take(std::int64_t bytes, Clock::time_point until) {
  if (bytes <= 0) return true;
  if (bytes > capacity_) return false;
  std::unique_lock lock(mutex_);
  if (!freed_.wait_until(lock, until, [&] { return reserved_ + bytes <= capacity_; })) return false;
  reserved_ += bytes;
  peak_ = std::max(peak_, reserved_);
  return true;
}

void MemoryPool::give(std::int64_t bytes) {
  if (bytes <= 0) return;
  {
    std::lock_guard lock(mutex_);
    reserved_ -= bytes;
  }
  freed_.notify_all();  // any waiter whose ask now fits goes on
}

std::int64_t MemoryPool::reserved() const {
  std::lock_guard lock(mutex_);
  return reserved_;
}

std::int64_t MemoryPool::peak() const {
  std::lock_guard lock(mutex_);
  return peak_;
}

bool RequestBudget::reserve(std::int64_t bytes) noexcept {
  const Clock::time_point until = std::min(deadline_, Clock::now() + max_wait_);
  if (!pool_.take(bytes, until)) {
    refused_ = bytes;
    return false;
  }
  held_ += bytes;
  return true;
}

bool RequestBudget::expired() const noexcept {
  return (cancel_ && cancel_->load(std::memory_order_relaxed)) || Clock::now() >= deadline_;
}

void RequestBudget::release(std::int64_t bytes) noexcept {
  bytes = std::min(bytes, held_.load());
  held_ -= bytes;
  pool_.give(bytes);
}

}  // namespace rasterd
