#include "routes.h"

#include <iterator>
#include <string_view>

#include "api.h"
#include "playground.h"
#include "problem.h"

namespace rasterd {
namespace {

// A route: its path pattern, the methods it answers and how it registers them. The metrics count requests
// by pattern, and a request with another method gets a 405 naming the methods, so the three cannot drift
// apart: a route is added here or nowhere. (cpp-httplib answers HEAD with a GET handler.)
struct Route {
  std::string_view pattern;  ///< the metrics label: the path, or "/examples/{name}" for any one example
  std::string_view methods;  ///< for the Allow header, e.g. "GET, HEAD"
  std::string_view path;     ///< what cpp-httplib matches: the path, or a regex with the name as matches[1]
  void (*add)(httplib::Server& server, const RouteHandlers& handlers, const Route& route);  ///< registers it
};

using Handler = void (*)(const httplib::Request&, httplib::Response&);

void serve_health(const httplib::Request&, httplib::Response& res) {
  res.set_content("ok\n", "text/plain");
}

// A route that answers GET (and so HEAD) with a fixed handler.
template <Handler serve>
void add_get(httplib::Server& server, const RouteHandlers&, const Route& route) {
  server.Get(std::string(route.path), serve);
}

void add_metrics(httplib::Server& server, const RouteHandlers& handlers, const Route& route) {
  server.Get(std::string(route.path), handlers.metrics);
}

// POST /render, GET /render?scene=... (image URLs) and the CORS preflight naming the route's methods.
void add_render(httplib::Server& server, const RouteHandlers& handlers, const Route& route) {
  RenderRoute* render = &handlers.render;
  const std::string path(route.path);
  const std::string_view methods = route.methods;
  server.Options(path, [methods](const httplib::Request&, httplib::Response& res) {
    RenderRoute::preflight(res, methods);
  });
  server.Post(path, [render](const httplib::Request& req, httplib::Response& res,
                             const httplib::ContentReader& reader) { render->post(req, res, reader); });
  server.Get(path, [render](const httplib::Request& req, httplib::Response& res) { render->get(req, res); });
}

const Route kRoutes[] = {
    {"/render", "GET, HEAD, POST, OPTIONS", "/render", add_render},
    {"/healthz", "GET, HEAD", "/healthz", add_get<serve_health>},
    {"/metrics", "GET, HEAD", "/metrics", add_metrics},
    // The described API: server/api.cpp.
    {"/schema/scene.json", "GET, HEAD", "/schema/scene.json", add_get<serve_scene_schema>},
    {"/openapi.json", "GET, HEAD", "/openapi.json", add_get<serve_openapi>},
    // The playground page and its example scenes: server/playground.cpp.
    {"/", "GET, HEAD", "/", add_get<serve_playground>},
    {"/examples", "GET, HEAD", "/examples", add_get<serve_example_list>},
    {"/examples/{name}", "GET, HEAD", R"(/examples/([^/]+))", add_get<serve_example>},
};

const Route* route_of(const std::string& path) {
  for (const Route& route : kRoutes)
    if (path == route.pattern) return &route;
  if (path.starts_with("/examples/") && path.find('/', 10) == std::string::npos)
    return &std::end(kRoutes)[-1];
  return nullptr;
}

}  // namespace

void install_routes(httplib::Server& server, const RouteHandlers& handlers) {
  for (const Route& route : kRoutes) route.add(server, handlers, route);
}

std::string route_label(const std::string& path) {
  const Route* route = route_of(path);
  return route ? std::string(route->pattern) : "other";
}

void write_error_problem(Metrics& metrics, const httplib::Request& req, httplib::Response& res) {
  const std::string detail = req.method + " " + req.path;
  if (res.status == 414) {
    metrics.rejected("uri_too_long");
    write_problem(res, problem(414, "uri-too-long", "The request URI is too long",
                               "a request line is at most 8192 bytes; POST the scene to /render "
                               "instead of putting it in the URL"));
  } else if (const Route* route = route_of(req.path);
             route &&
             (", " + std::string(route->methods) + ",").find(", " + req.method + ",") == std::string::npos) {
    // The route exists but not with this method (cpp-httplib says 404 or 400 here).
    const std::string allowed(route->methods);
    res.set_header("Allow", allowed);
    write_problem(res, problem(405, "method-not-allowed", "Method not allowed",
                               detail + ": " + req.path + " answers " + allowed));
  } else if (res.status == 404) {
    write_problem(res, problem(404, "not-found", "No such route",
                               detail + " (the routes are described at GET /openapi.json)"));
  } else
    write_problem(res, problem(res.status, "http-error", "HTTP error " + std::to_string(res.status), detail));
}

}  // namespace rasterd
