// Prometheus metrics. In: each request's route label, status and bytes, each render's duration, each
// refusal's reason, and the gauges read at scrape time (admission load, memory pool, shader cache). Out: the
// text of GET /metrics, and refuse(), which writes a refusal's problem and counts it by reason.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include <httplib.h>

#include "memory_budget.h"
#include "problem.h"
#include "raster/shader.h"

namespace rasterd {

// Prometheus counters; one mutex, touched once or twice per request.
class Metrics {
 public:
  static constexpr std::array<double, 10> kBucketsMs{1, 2.5, 5, 10, 25, 50, 100, 250, 1000, 10000};

  void request(const std::string& route, int status, std::size_t in, std::size_t out);
  void render(double ms);
  void rejected(const std::string& reason);
  /// The counters and histograms, with the admission gauges (renders running and waiting now).
  std::string text(int in_flight, int queued);

 private:
  std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::uint64_t> requests_;  ///< by (route label, status)
  std::array<std::uint64_t, kBucketsMs.size()> buckets_{};         ///< renders within each bucket's ms
  std::uint64_t render_count_ = 0;
  double render_sum_ms_ = 0;
  std::map<std::string, std::uint64_t> rejected_;  ///< by reason
  std::uint64_t bytes_in_ = 0, bytes_out_ = 0;     ///< body bytes
};

/// The whole GET /metrics text: `metrics`, the memory pool's gauges, the shader cache's counts (none when
/// `shader_cache` is null), the build and the process_* metrics.
std::string metrics_page(Metrics& metrics, int in_flight, int queued, const MemoryPool& memory,
                         const raster::ShaderCache* shader_cache = nullptr);

/// Writes `p` and counts it under rasterd_rejected_total{reason}. Returns false, for `return refuse(...)`
/// in the checks that stop a request.
bool refuse(Metrics& metrics, httplib::Response& res, const Problem& p, const std::string& reason);

}  // namespace rasterd
