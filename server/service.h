// The HTTP service: routes -> library -> response, plus what a service on a network needs: limits,
// deadlines, admission, metrics and a graceful stop. No rendering logic lives here.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include <httplib.h>

#include "raster/scene.h"

namespace rasterd {

struct ServiceConfig {
  raster::Limits limits;                              ///< scene limits, enforced by the library
  std::size_t max_body_bytes = 32u << 20;             ///< request body cap in bytes (413 above it)
  int render_threads = 0;                             ///< band threads per render; 0 = core count
  int workers = 0;                                    ///< renders at once; 0 = core count
  int max_queue = 0;                                  ///< renders waiting for a worker; 0 = 2 x workers
  std::chrono::milliseconds render_deadline{10'000};  ///< parse + render + encode; 503 past it
  std::chrono::milliseconds body_deadline{10'000};    ///< reading the body, whatever its pace; 408 past it
  std::chrono::milliseconds shutdown_grace{20'000};   ///< after SIGTERM, how long renders may finish
  int cache_max_age = 86'400;  ///< seconds, in Cache-Control: public, max-age=N, immutable (GET /render)
  /// Tests only (empty in service): runs on the request's thread once a render is admitted, before its
  /// scene is read. A test holds renders in flight on a latch here, or throws to force an internal error.
  std::function<void()> after_admission;
};

/// Reads the configuration from `--flag value` arguments over environment variables over defaults.
/// Returns an error message, empty on success. `help` receives the text for `rasterd serve --help`.
std::string parse_service_flags(int argc, const char* const* argv, ServiceConfig& config, std::string& host,
                                int& port);
std::string service_help();

class Service {
 public:
  explicit Service(ServiceConfig config);
  ~Service();
  Service(const Service&) = delete;
  Service& operator=(const Service&) = delete;

  /// Routes (/render, /healthz, /metrics, the API documents, the playground), problem+json errors, request
  /// ids and logs, timeouts and the connection thread pool on `server`. main() and the tests both call
  /// this, so tests exercise what is served. Call before binding.
  void install(httplib::Server& server);

  /// After binding: enlarges the kernel's listen backlog on the listening socket, which cpp-httplib 0.11
  /// creates with a compiled-in backlog of 5 (a burst of connections would wait for SYN retries).
  void widen_backlog() const;

  /// Shutdown past the grace period: renders still running stop and answer 503.
  void cancel_renders();

  const ServiceConfig& config() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rasterd
