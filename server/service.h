// The HTTP service: the Service object that wires the concerns together on a cpp-httplib server: the routes
// (routes.cpp), the render route (render_route.cpp), body reading (body.cpp), admission (admission.cpp),
// metrics (metrics.cpp), request ids (request_id.cpp), the compiled shader programs every request shares
// (a raster::ShaderCache, --shader-cache-bytes), and the connection and shutdown settings. In: a
// ServiceConfig (flags.cpp reads one from `rasterd serve`'s flags). Out: a server that answers every route.
// No rendering logic lives here.
#pragma once

#include <memory>

#include <httplib.h>

#include "service_config.h"

namespace rasterd {

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
