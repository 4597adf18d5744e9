// The threads that serve connections: made when needed, up to a bound, and the most recently idle one
// takes the next connection.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <httplib.h>

namespace rasterd {

/// cpp-httplib's task queue for connections. Its own ThreadPool starts every thread at once and wakes
/// them in turn, so with the hundreds a deep render queue needs, each request ran on a cold thread (its
/// stack, its malloc arena and the caches it touched long gone): +0.1 ms of parse and more of raster on
/// small scenes. Here a thread is made only when every one made so far is busy, at most `max_threads`,
/// and an idle thread waits on a stack: the next connection goes to the one that finished last. Past the
/// bound, connections wait in order for the next free thread. shutdown() lets queued connections finish.
class ConnectionThreads final : public httplib::TaskQueue {
 public:
  explicit ConnectionThreads(std::size_t max_threads) : max_threads_(max_threads) {}
  ConnectionThreads(const ConnectionThreads&) = delete;
  ConnectionThreads& operator=(const ConnectionThreads&) = delete;
  ~ConnectionThreads() override { shutdown(); }

  void enqueue(std::function<void()> job) override;
  void shutdown() override;

  /// Threads made so far, and of them the idle ones (for tests and metrics).
  std::size_t thread_count();
  std::size_t idle_count();

 private:
  struct Worker {
    std::thread thread;
    std::function<void()> job;     // the connection handed to this thread; empty while idle
    std::condition_variable wake;  // signalled when `job` is set or on shutdown
  };
  void run(Worker& worker);

  const std::size_t max_threads_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<Worker>> workers_;  // every thread made, in order
  std::vector<Worker*> idle_;                     // idle threads; the back one finished last
  std::deque<std::function<void()>> waiting_;     // connections past the bound, oldest first
  bool stopping_ = false;
  bool joined_ = false;
};

}  // namespace rasterd
