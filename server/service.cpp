#include "service.h"

#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>

#include "access_log.h"
#include "admission.h"
#include "body.h"
#include "connection_threads.h"
#include "memory_budget.h"
#include "metrics.h"
#include "problem.h"
#include "raster/raster.h"
#include "render_route.h"
#include "request_id.h"
#include "resources.h"
#include "routes.h"

namespace rasterd {
namespace {

// CORS on every answer, errors included (a page must be able to read why it failed): which origin may
// read it, and which of our headers it may see. With a list of origins the answer varies by Origin.
void set_cors_headers(const std::vector<std::string>& allowed, const httplib::Request& req,
                      httplib::Response& res) {
  if (allowed.empty()) return;
  const bool any = std::find(allowed.begin(), allowed.end(), "*") != allowed.end();
  const std::string origin = req.get_header_value("Origin");
  if (!any) res.set_header("Vary", "Origin");
  if (!any && std::find(allowed.begin(), allowed.end(), origin) == allowed.end()) return;
  res.set_header("Access-Control-Allow-Origin", any ? "*" : origin);
  res.set_header("Access-Control-Expose-Headers",
                 "ETag, Retry-After, Server-Timing, X-Render-Plan, X-Request-Id");
  res.set_header("Timing-Allow-Origin", any ? "*" : origin);
}

// Nothing internal reaches the client; the log line carries the detail and the request id.
void answer_exception(const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
  std::string what = "unknown exception";
  try {
    std::rethrow_exception(ep);
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  std::fprintf(stderr, "error id=%s %s %s: %s\n", res.get_header_value("X-Request-Id").c_str(),
               req.method.c_str(), raster::escape_for_display(req.path).c_str(),
               raster::escape_for_display(what).c_str());
  write_problem(res, problem(500, "internal", "Internal server error",
                             "the request failed unexpectedly; quote request id " +
                                 res.get_header_value("X-Request-Id")));
}

}  // namespace

struct Service::State {
  ServiceConfig config;
  Admission admission;
  MemoryPool memory;
  Metrics metrics;
  std::atomic<bool> cancel{false};  ///< set by cancel_renders(): running renders stop
  int listen_socket = -1;           ///< remembered from the socket-options hook, for widen_backlog()
  /// Compiled programs by source, shared by every request; null when --shader-cache-bytes is 0.
  std::unique_ptr<raster::ShaderCache> shader_cache;
  RenderRoute render_route;

  explicit State(ServiceConfig c)
      : config(c),
        admission(c.workers, c.max_queue, c.max_queued_bytes, c.max_queue_wait),
        memory(c.memory_budget),
        shader_cache(c.shader_cache_bytes > 0 ? std::make_unique<raster::ShaderCache>(c.shader_cache_bytes)
                                              : nullptr),
        render_route(config, admission, memory, metrics, cancel, shader_cache.get()) {}

  void install_connections(httplib::Server& server);
  void install_request_hooks(httplib::Server& server);
  void log_request(const httplib::Request& req, const httplib::Response& res);
};

// Connection threads, keep-alive, timeouts and socket options.
void Service::State::install_connections(httplib::Server& server) {
  // Connection threads: every admitted or queued render holds one, slow bodies hold one while they
  // arrive, and health and metrics must still find one free.
  const std::size_t threads = static_cast<std::size_t>(config.workers + config.max_queue) + 16;
  server.new_task_queue = [threads] { return new ConnectionThreads(threads); };
  // One request per connection. After a 408 a kept-alive connection goes on reading whatever the client
  // still drips as its next request line, holding a thread for as long as the client likes; cpp-httplib
  // 0.11 decides keep-alive from the request, before routing, so a handler cannot close its own
  // connection. A new connection costs tens of microseconds on a service whose requests cost
  // milliseconds, and no idle connection holds a thread.
  server.set_keep_alive_max_count(1);
  server.set_read_timeout(read_timeout(config));
  server.set_socket_options([this](socket_t sock) {
    // SO_REUSEADDR alone: a restarted server may bind while old connections linger in TIME_WAIT. Not
    // SO_REUSEPORT (cpp-httplib's default), with which a second server on a taken port binds silently and
    // takes a share of the connections, so a forgotten old instance keeps answering.
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    if (listen_socket < 0) listen_socket = sock;  // the first socket this server creates is the listening one
  });
}

// What every request passes through besides its route: its id, Date and CORS headers before routing, a
// problem body on errors, a 500 for an exception, and the log line and metrics at the end.
void Service::State::install_request_hooks(httplib::Server& server) {
  server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    start_request(res, req.get_header_value("X-Request-Id"));
    t_request.method = req.method;
    set_cors_headers(config.cors_origins, req, res);
    // Range is ignored (RFC 9110 14.2 allows it): a byte range of a picture is of no use, and cpp-httplib
    // 0.11 would slice every answer, problems included, with a Content-Range past their end. The Request is
    // the server's own non-const object, handed to handlers as const.
    const_cast<httplib::Request&>(req).ranges.clear();
    res.set_header("Accept-Ranges", "none");  // else cpp-httplib advertises "bytes" on HEAD answers
    return httplib::Server::HandlerResponse::Unhandled;
  });
  // Any error response without a body of ours (404, 405, ...) still gets a problem body.
  server.set_error_handler(
      httplib::Server::HandlerWithResponse([this](const httplib::Request& req, httplib::Response& res) {
        if (!res.has_header("X-Request-Id")) {
          // cpp-httplib answered before routing (a request line over its 8192-byte limit, or a malformed
          // one): no pre-routing handler ran, so this request has no id or start time of its own yet.
          start_request(res, "");
          set_cors_headers(config.cors_origins, req, res);
        }
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        write_error_problem(metrics, req, res);
        return httplib::Server::HandlerResponse::Handled;
      }));
  server.set_exception_handler(answer_exception);
  server.set_logger(
      [this](const httplib::Request& req, const httplib::Response& res) { log_request(req, res); });
}

void Service::State::log_request(const httplib::Request& req, const httplib::Response& res) {
  const std::size_t in = t_request.bytes_in ? t_request.bytes_in : req.body.size();
  metrics.request(route_label(req.path), res.status, in, res.body.size());
  LogLine line;
  line.wall = t_request.wall;
  line.client = req.remote_addr;
  // cpp-httplib answers a request line over its limit (414) before parsing it: no method or path to log.
  line.method = !t_request.method.empty() ? t_request.method : req.method.empty() ? "-" : req.method;
  line.path = req.path.empty() ? "-" : req.path;
  line.status = res.status;
  line.bytes_in = in, line.bytes_out = res.body.size();
  line.ms = ms_between(t_request.start, Clock::now());
  line.id = res.get_header_value("X-Request-Id");
  line.user_agent = req.get_header_value("User-Agent");
  const std::string text = config.log_json ? line.json() : line.text();
  std::fwrite(text.data(), 1, text.size(), stderr);
}

Service::Service(ServiceConfig config) {
  // The CPUs this process may use (its affinity and cgroup quota), not the machine's: a container limited
  // to one CPU renders on one thread.
  const int cpus = static_cast<int>(std::max<std::int64_t>(1, cpu_limit().value));
  if (config.workers <= 0) config.workers = cpus;
  if (config.render_threads <= 0) config.render_threads = cpus;
  if (config.limits.threads <= 0) config.limits.threads = config.render_threads;  // the OBJ reader's pieces
  // The shader cache's memory is held between requests, outside any request's reservation: the default
  // budget sets it aside as it does the process's own.
  if (config.memory_budget <= 0)
    config.memory_budget = std::max<std::int64_t>(
        default_memory_budget(memory_limit()) -
            static_cast<std::int64_t>(std::min<std::size_t>(config.shader_cache_bytes, 1ull << 40)),
        std::int64_t{64} << 20);
  // Each worker's PNG encoder set up now, not on the first requests.
  raster::prepare_png_encoders(config.workers);
  state_ = std::make_unique<State>(config);
}

Service::~Service() = default;

const ServiceConfig& Service::config() const {
  return state_->config;
}

void Service::cancel_renders() {
  state_->cancel = true;
}

void Service::widen_backlog() const {
  if (state_->listen_socket >= 0)
    ::listen(state_->listen_socket, 1024);  // Linux: re-listen updates the backlog
}

void Service::install(httplib::Server& server) {
  State& s = *state_;
  s.install_connections(server);
  s.install_request_hooks(server);
  install_routes(server, {s.render_route, [&s](const httplib::Request&, httplib::Response& res) {
                            const auto [running, waiting] = s.admission.load();
                            res.set_content(
                                metrics_page(s.metrics, running, waiting, s.memory, s.shader_cache.get()),
                                "text/plain; version=0.0.4");
                          }});
}

}  // namespace rasterd
