#include "connection_threads.h"

#include <algorithm>

namespace rasterd {

void ConnectionThreads::enqueue(std::function<void()> job) {
  std::lock_guard lock(mutex_);
  if (!idle_.empty()) {
    Worker* worker = idle_.back();
    idle_.pop_back();
    worker->job = std::move(job);
    worker->wake.notify_one();
    return;
  }
  if (workers_.size() < max_threads_ && !stopping_) {
    auto worker = std::make_unique<Worker>();
    worker->job = std::move(job);
    Worker& w = *worker;
    workers_.push_back(std::move(worker));
    w.thread = std::thread([this, &w] { run(w); });
    return;
  }
  waiting_.push_back(std::move(job));
}

void ConnectionThreads::run(Worker& worker) {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (!worker.job && !waiting_.empty()) {
      worker.job = std::move(waiting_.front());
      waiting_.pop_front();
    }
    if (worker.job) {
      std::function<void()> job = std::move(worker.job);
      worker.job = nullptr;
      lock.unlock();
      job();
      lock.lock();
      continue;
    }
    if (stopping_) return;  // nothing of its own and nothing waiting
    idle_.push_back(&worker);
    worker.wake.wait(lock, [&] { return worker.job || stopping_; });
    if (!worker.job) idle_.erase(std::find(idle_.begin(), idle_.end(), &worker));  // woken to stop
  }
}

void ConnectionThreads::shutdown() {
  {
    std::lock_guard lock(mutex_);
    if (joined_) return;
    stopping_ = true;
    for (Worker* worker : idle_) worker->wake.notify_one();
  }
  // No thread is made once stopping_ is set, so workers_ no longer changes.
  for (auto& worker : workers_)
    if (worker->thread.joinable()) worker->thread.join();
  std::lock_guard lock(mutex_);
  joined_ = true;
}

std::size_t ConnectionThreads::thread_count() {
  std::lock_guard lock(mutex_);
  return workers_.size();
}

std::size_t ConnectionThreads::idle_count() {
  std::lock_guard lock(mutex_);
  return idle_.size();
}

}  // namespace rasterd
