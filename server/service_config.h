// The service's configuration: the limits, sizes, deadlines and origins every part of the service reads
// (flags.cpp fills one from `rasterd serve`'s flags and environment; tests build their own). A header of its
// own, so that the parts (body reading, the render route, the flags) take it without the Service that wires
// them (service.h).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "raster/scene.h"

namespace rasterd {

struct ServiceConfig {
  raster::Limits limits;  ///< scene limits, enforced by the library (limits.shader: the programs' bounds)
  /// Request body cap in bytes (413 above it): 256 MiB, which holds the largest binary STL the face limit
  /// takes (5M facets, 250 MB) and so every 3D-print file rasterd would draw (docs/memory.md: what a 2 GiB
  /// pod takes of them at once).
  std::size_t max_body_bytes = 256u << 20;
  /// Most threads one render uses; they take the image's tiles (the plan takes one thread when there is
  /// little to draw, and never more than the tiles). 0 = the CPUs the process may use (cpu_limit()).
  int render_threads = 0;
  int workers = 0;  ///< renders at once; 0 = the CPUs the process may use (cpu_limit())
  /// Bytes all requests may reserve at once (bodies, parsed models, render buffers); 0 = from the memory
  /// the process may use (default_memory_budget(memory_limit())).
  std::int64_t memory_budget = 0;
  bool log_json = false;  ///< one JSON object per log line instead of text
  int max_queue = 256;    ///< renders waiting for a worker, at most (each holds a connection thread)
  /// Bodies held by waiting renders, in bytes: a request that would go past it is refused (one always waits).
  std::size_t max_queued_bytes = 256u << 20;
  /// A render waits for a worker only when its expected wait is within this, and gives up after it (503).
  std::chrono::milliseconds max_queue_wait{2'000};
  std::chrono::milliseconds render_deadline{10'000};  ///< parse + render + encode; 422 past it
  std::chrono::milliseconds body_deadline{10'000};    ///< reading the body, whatever its pace; 408 past it
  std::chrono::milliseconds shutdown_grace{20'000};   ///< after SIGTERM, how long renders may finish
  /// Origins whose pages may read answers (CORS): {"*"} is any origin (the default: the service has no
  /// cookies or credentials to protect); empty sends no CORS headers. Exact "scheme://host[:port]" strings.
  std::vector<std::string> cors_origins{"*"};
  int cache_max_age = 86'400;  ///< seconds, in Cache-Control: public, max-age=N, immutable (GET /render)
  /// Compiled shader programs kept between requests, by their source (raster::ShaderCache), at most this
  /// many bytes; 0 keeps none (each request compiles its programs). The default memory budget sets it aside.
  std::size_t shader_cache_bytes = 64u << 20;
  /// Tests only (empty in service): runs on the request's thread once a render is admitted, before its
  /// scene is read. A test holds renders in flight on a latch here, or throws to force an internal error.
  std::function<void()> after_admission;
};

}  // namespace rasterd
