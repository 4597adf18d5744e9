#include "base/parallel.h"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace raster::detail {
namespace {

/// The process's helper threads and the jobs that want help. One mutex guards the job list and every
/// job's helper counts; pieces themselves are taken without it (ParallelJob::next).
class HelperPool {
 public:
  void run(ParallelJob& job) {
    {
      std::lock_guard lock(mutex_);
      while (helpers_ < std::min(job.helpers_wanted, kMaxHelpers)) {
        std::thread([this] { serve(); }).detach();
        ++helpers_;
      }
      jobs_.push_back(&job);
    }
    wake_.notify_all();
    // However the caller's share ends (done, stopped, or an exception), no helper may still hold the job
    // when it goes out of scope.
    struct Finish {
      HelperPool& pool;
      ParallelJob& job;
      ~Finish() {
        std::unique_lock lock(pool.mutex_);
        pool.jobs_.erase(std::find(pool.jobs_.begin(), pool.jobs_.end(), &job));  // no one joins from here
        pool.left_.wait(lock, [&] { return job.helpers_active == 0; });
      }
    } finish{*this, job};
    job.run(job.context, 0);
  }

 private:
  // Up to 255 helpers: more than any machine's cores, so a plan's thread count is what it gets.
  static constexpr int kMaxHelpers = 255;

  // A job that still has pieces to take and room for a helper, or nullptr.
  ParallelJob* wanting_help() const {
    for (ParallelJob* job : jobs_)
      if (job->helpers_joined < job->helpers_wanted && job->next.load(std::memory_order_relaxed) < job->count)
        return job;
    return nullptr;
  }

  void serve() {
    std::unique_lock lock(mutex_);
    for (;;) {
      // The job found is the one joined: asked twice, a job's last piece could be taken (without the lock)
      // between the two, and the second answer be none (a helper joined nothing and crashed).
      ParallelJob* wanting = nullptr;
      wake_.wait(lock, [&] { return (wanting = wanting_help()) != nullptr; });
      ParallelJob& job = *wanting;
      const int thread = ++job.helpers_joined;
      ++job.helpers_active;
      lock.unlock();
      job.run(job.context, thread);
      lock.lock();
      if (--job.helpers_active == 0) left_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;  // a job was posted
  std::condition_variable left_;  // a job's last active helper left it
  std::vector<ParallelJob*> jobs_;
  int helpers_ = 0;
};

}  // namespace

void run_parallel(ParallelJob& job) {
  // Never destroyed: helpers wait on it until the process ends, and no exit-time destructor may pull it
  // from under them.
  static HelperPool* const pool = new HelperPool;
  pool->run(job);
}

}  // namespace raster::detail
