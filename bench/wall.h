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

}  // namespace bench
