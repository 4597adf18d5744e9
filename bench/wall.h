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

/// A warm server's own account of a request (its Server-Timing header), medians, milliseconds.
struct ServerTimes {
  double parse_ms = 0, raster_ms = 0, encode_ms = 0;
};

/// POSTs `body` (a model) to `rasterd serve` at /render?`query`, `runs` times after four warm-up requests.
ServerTimes server_times(const std::string& rasterd, const std::string& body, const std::string& query,
                         int runs);

}  // namespace bench
