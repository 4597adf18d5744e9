// Wall-clock end to end through the rasterd binary: the CLI and the HTTP service.
#pragma once

#include <cstddef>
#include <string>

namespace bench {

struct WallTimes {
  double cli_ms = 0;   ///< median wall time of `rasterd render file -o /dev/null`
  double http_ms = 0;  ///< median wall time of POST /render on loopback, body sent to PNG received
  std::size_t png_bytes = 0;
};

/// Runs `rasterd` (a path) both ways on `scene_json`, `runs` times each.
WallTimes wall_times(const std::string& rasterd, const std::string& scene_json, int runs);

/// A server's own account of its requests (their Server-Timing headers), milliseconds: medians of the
/// counted requests, and the first counted request alone.
struct ServerTimes {
  double parse_ms = 0, raster_ms = 0, encode_ms = 0;
  double first_raster_ms = 0, first_encode_ms = 0;
  double wall_ms = 0;  ///< the client's median: the body sent to the whole PNG received, on loopback
};

/// POSTs `body` (a model, or with `content_type` "application/json" a scene) to a new `rasterd serve` at
/// /render?`query`, `runs` times after `warm_up` requests that are not counted.
ServerTimes server_times(const std::string& rasterd, const std::string& body, const std::string& query,
                         int runs, const std::string& content_type = "text/plain", int warm_up = 4);

}  // namespace bench
