// One line per answered request, on stderr: in text for people (`--log-format text`, the default) or one
// JSON object for log collectors (`--log-format json`). Every line carries the request id that the answer's
// X-Request-Id header and a proxy's own log (deploy/nginx.conf) carry, so the three can be matched.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace rasterd {

struct LogLine {
  std::chrono::system_clock::time_point wall;  ///< when the request began (UTC in the line, to the ms)
  std::string client;                          ///< the peer's address (a proxy's, behind one)
  std::string method;                          ///< "-" when cpp-httplib answered before parsing it (414)
  std::string path;                            ///< as the client sent it, percent-decoded; "-" as above
  int status = 0;                              ///< HTTP status answered
  std::size_t bytes_in = 0;                    ///< request body bytes read
  std::size_t bytes_out = 0;                   ///< response body bytes
  double ms = 0;                               ///< from the request's start to the answer
  std::string id;                              ///< the X-Request-Id answered
  std::string user_agent;                      ///< the User-Agent header, "" without one

  /// `2026-11-26T17:24:01.042Z 10.0.0.7 POST /render 200 in=512 out=2048 ms=3.1 id=r00000001
  /// ua="curl/7.88.1"`. Client text (path, user agent) is escaped so that it cannot split or forge a line.
  std::string text() const;
  /// The same fields as one JSON object on one line: time, client, method, path, status, bytes_in,
  /// bytes_out, ms, id, user_agent.
  std::string json() const;
};

}  // namespace rasterd
