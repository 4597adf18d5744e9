// Each request's context and identity: when it began, the id its answer and log line carry, and the Date
// header. In: a request as it arrives (its X-Request-Id, if any). Out: the thread-local RequestContext that
// the body reader, the render route and the logger read, and the Date and X-Request-Id headers.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include <httplib.h>

namespace rasterd {

using Clock = std::chrono::steady_clock;

/// Milliseconds from `a` to `b`.
double ms_between(Clock::time_point a, Clock::time_point b);

// cpp-httplib runs a request's pre-routing handler, route handler and logger on one thread, one request
// at a time, and offers no per-request user data: this thread-local is that request's context.
struct RequestContext {
  Clock::time_point start;  ///< when the request began: its log duration and its body deadline
  std::chrono::system_clock::time_point wall;  ///< when the request began: the log line, the Date header
  std::string method;        ///< as sent (a 304 is written as a HEAD answer: see render_route.cpp)
  std::size_t bytes_in = 0;  ///< body bytes read so far
};
extern thread_local RequestContext t_request;

/// Starts this thread's RequestContext now and sets the Date and X-Request-Id headers: `client_id` when it
/// is one a log line can carry as it is, else a new id of ours.
void start_request(httplib::Response& res, const std::string& client_id);

}  // namespace rasterd
