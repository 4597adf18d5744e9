// The HTTP service: routes -> library -> response. No rendering logic lives here.
#pragma once

#include <cstddef>

#include <httplib.h>

#include "raster/scene.h"

namespace rasterd {

struct ServiceConfig {
  raster::Limits limits;                      ///< scene limits, enforced by the library
  std::size_t max_body_bytes = 32u << 20;     ///< request body cap in bytes (413 above it)
  int render_threads = 0;                     ///< per-render band threads; 0 = core count
};

/// Registers every route (/render, /healthz), the problem+json error handlers, request ids and the
/// request log on `server`. main() and the tests both call this, so tests exercise what is served.
void register_routes(httplib::Server& server, const ServiceConfig& config);

}  // namespace rasterd
