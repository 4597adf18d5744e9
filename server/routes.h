// The route table: every path the service answers, with its methods. In: the handlers that need the
// service's state (the render route, the metrics page). Out: the routes registered on a cpp-httplib server;
// each request's metrics label (a bounded set: the route's pattern, or "other"); and the problem body of an
// answer no handler wrote (405 with the route's Allow, 404, 414, other HTTP errors).
#pragma once

#include <string>

#include <httplib.h>

#include "metrics.h"
#include "render_route.h"

namespace rasterd {

/// What the table registers that is not a fixed page.
struct RouteHandlers {
  RenderRoute& render;               ///< POST, GET and OPTIONS /render
  httplib::Server::Handler metrics;  ///< GET /metrics
};

/// Registers every route of the table on `server`, with the handlers of the methods it lists.
void install_routes(httplib::Server& server, const RouteHandlers& handlers);

/// The metrics label of a request path: its route's pattern (e.g. "/examples/{name}"), or "other".
std::string route_label(const std::string& path);

/// For an error answer (status set, no body of ours): writes its problem body, and the Allow header of a
/// route that exists but not with the request's method (cpp-httplib says 404 or 400 there; this says 405).
void write_error_problem(Metrics& metrics, const httplib::Request& req, httplib::Response& res);

}  // namespace rasterd
