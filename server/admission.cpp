#include "admission.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

namespace rasterd {

Admission::Verdict Admission::enter(std::size_t body_bytes) {
  std::unique_lock lock(mutex_);
  if (running_ < workers_) return ++running_, Verdict{};
  const auto expected = std::chrono::milliseconds(
      static_cast<std::int64_t>(std::ceil((waiting_ + 1) * mean_render_ms_ / workers_)));
  if (waiting_ >= max_queue_) return {"queue_full", expected};
  if (expected > max_wait_) return {"queue_wait", expected};
  if (waiting_ > 0 && queued_bytes_ + body_bytes > max_queued_bytes_) return {"queue_memory", expected};
  ++waiting_, queued_bytes_ += body_bytes;
  const bool free = freed_.wait_for(lock, max_wait_, [&] { return running_ < workers_; });
  --waiting_, queued_bytes_ -= body_bytes;
  if (!free) return {"queue_timeout", max_wait_};
  ++running_;
  return {};
}

void Admission::leave(double render_ms) {
  {
    std::lock_guard lock(mutex_);
    --running_;
    // A moving mean over roughly the last ten renders: follows a change of load within a second or two.
    mean_render_ms_ = rendered_++ == 0 ? render_ms : 0.9 * mean_render_ms_ + 0.1 * render_ms;
  }
  freed_.notify_one();
}

std::pair<int, int> Admission::load() {
  std::lock_guard lock(mutex_);
  return {running_, waiting_};
}

void refuse_busy(Metrics& metrics, httplib::Response& res, const Admission::Verdict& verdict,
                 std::chrono::milliseconds max_wait) {
  const auto seconds = std::max<std::int64_t>(1, (verdict.wait.count() + 999) / 1000);
  res.set_header("Retry-After", std::to_string(seconds));
  const bool timed_out = std::string_view(verdict.refused) == "queue_timeout";
  refuse(metrics, res,
         problem(503, "overloaded", "All render workers are busy",
                 timed_out ? "no worker was free within " + std::to_string(max_wait.count()) +
                                 " ms; try again in " + std::to_string(seconds) + " s"
                           : "the wait for a worker would be about " + std::to_string(verdict.wait.count()) +
                                 " ms; try again in " + std::to_string(seconds) + " s"),
         verdict.refused);
}

bool refuse_memory(Metrics& metrics, httplib::Response& res, std::int64_t bytes, std::int64_t capacity,
                   std::chrono::milliseconds max_wait, const char* reason) {
  const auto seconds = std::max<std::int64_t>(1, (max_wait.count() + 999) / 1000);
  res.set_header("Retry-After", std::to_string(seconds));
  return refuse(
      metrics, res,
      problem(503, "overloaded", "Not enough memory is free for this request now",
              "it needs about " + std::to_string(bytes >> 20) + " MiB more of the " +
                  std::to_string(capacity >> 20) +
                  " MiB memory budget, and other requests "
                  "held it for " +
                  std::to_string(max_wait.count()) + " ms; try again in " + std::to_string(seconds) + " s"),
      reason);
}

}  // namespace rasterd
