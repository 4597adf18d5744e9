// Who may render now. In: a render's body size as it asks to start. Out: admitted (the caller leaves with
// its render time when done), or refused with the reason and the wait to advise; refuse_busy() and
// refuse_memory() write those refusals (503 with Retry-After).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <utility>

#include <httplib.h>

#include "metrics.h"

namespace rasterd {

// Renders at once (`workers`), and who may wait for one. A render waits when the wait it can expect is
// short: (renders ahead of it / workers) x the recent mean render time, within `max_wait`; the bodies
// of waiting renders within `max_queued_bytes`; and at most `max_queue` of them, which bounds the
// connection threads. Past any of these a request is refused at once with how long to wait, and one that
// waited `max_wait` without a worker gives up. Health and metrics never pass through here.
class Admission {
 public:
  struct Verdict {
    const char* refused = nullptr;     ///< nullptr: admitted; else the metrics reason of the refusal
    std::chrono::milliseconds wait{};  ///< the expected wait when refused (for Retry-After)
  };

  Admission(int workers, int max_queue, std::size_t max_queued_bytes, std::chrono::milliseconds max_wait)
      : workers_(workers), max_queue_(max_queue), max_queued_bytes_(max_queued_bytes), max_wait_(max_wait) {}

  /// Admits at once, after a wait, or refuses; an admitted render must leave().
  Verdict enter(std::size_t body_bytes);
  /// An admitted render is done, after `render_ms` from admission to answer.
  void leave(double render_ms);
  /// {renders running, renders waiting} now.
  std::pair<int, int> load();

 private:
  const int workers_, max_queue_;
  const std::size_t max_queued_bytes_;  ///< bytes
  const std::chrono::milliseconds max_wait_;
  std::mutex mutex_;
  std::condition_variable freed_;
  int running_ = 0, waiting_ = 0;
  std::size_t queued_bytes_ = 0;  ///< bodies of the waiting renders, bytes
  double mean_render_ms_ = 0;     ///< admission to answer, of the renders so far
  std::uint64_t rendered_ = 0;
};

/// 503 with Retry-After for a render `verdict` refused; `max_wait` is the queue's bound it gave up after.
void refuse_busy(Metrics& metrics, httplib::Response& res, const Admission::Verdict& verdict,
                 std::chrono::milliseconds max_wait);

/// 503 with Retry-After: the memory budget (of `capacity` bytes) could not give `bytes` within `max_wait`.
/// Returns false, as refuse() does.
bool refuse_memory(Metrics& metrics, httplib::Response& res, std::int64_t bytes, std::int64_t capacity,
                   std::chrono::milliseconds max_wait, const char* reason);

}  // namespace rasterd
