#include "service.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include "problem.h"
#include "raster/raster.h"

namespace rasterd {
namespace {

std::string next_request_id() {
  static std::atomic<std::uint64_t> counter{0};  // process-wide by nature: ids must be unique
  char buf[32];
  std::snprintf(buf, sizeof buf, "r%08llx", static_cast<unsigned long long>(++counter));
  return buf;
}

// Reads the body through the ContentReader: cpp-httplib 0.11 caps a buffered form-urlencoded body (what
// `curl -d` sends) at 8 KiB with a 413, but a ContentReader route receives any body. The cap is ours.
// Returns false, with the problem written, when the body is refused.
bool read_body(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader,
               std::size_t cap, std::string& body) {
  if (req.has_header("Content-Encoding") && req.get_header_value("Content-Encoding") != "identity") {
    write_problem(res, problem(415, "unsupported-encoding", "Compressed request bodies are not accepted",
                               "send the scene uncompressed (Content-Encoding: " +
                                   req.get_header_value("Content-Encoding") + ")"));
    return false;
  }
  const auto declared = req.get_header_value<std::uint64_t>("Content-Length");
  auto too_large = [&] {
    write_problem(res, problem(413, "body-too-large", "The request body is too large",
                               "the limit is " + std::to_string(cap) + " bytes"));
    return false;
  };
  if (declared > cap) return too_large();  // decided before reading a byte
  if (declared > 0) body.reserve(declared);
  bool over = false;
  reader([&](const char* data, std::size_t n) {
    if (body.size() + n > cap) {
      over = true;
      return false;
    }
    body.append(data, n);
    return true;
  });
  if (over) return too_large();
  return true;
}

void handle_render(const ServiceConfig& config, const httplib::Request& req, httplib::Response& res,
                   const httplib::ContentReader& reader) {
  if (req.is_multipart_form_data()) {
    write_problem(res, problem(415, "unsupported-media-type", "Multipart uploads are not supported yet",
                               "send the scene JSON as the request body"));
    return;
  }
  std::string body;
  if (!read_body(req, res, reader, config.max_body_bytes, body)) return;
  try {
    const raster::Scene scene = raster::parse_scene(body, config.limits);
    const raster::RenderPlan plan = raster::plan(scene, config.limits, {config.render_threads});
    if (req.get_param_value("explain") == "1") {
      res.set_content(raster::explain_json(plan), "application/json");
      return;
    }
    const raster::Image image = raster::render(scene, plan);
    const std::vector<std::uint8_t> png = raster::encode_png(image, plan.png);
    res.set_header("X-Render-Plan", raster::explain_line(plan));
    res.set_content(reinterpret_cast<const char*>(png.data()), png.size(), "image/png");
  } catch (const raster::SceneError& e) {
    write_problem(res, problem_from(e));
  }
}

}  // namespace

void register_routes(httplib::Server& server, const ServiceConfig& config) {
  server.set_pre_routing_handler([](const httplib::Request&, httplib::Response& res) {
    res.set_header("X-Request-Id", next_request_id());
    return httplib::Server::HandlerResponse::Unhandled;
  });

  server.Post("/render", [config](const httplib::Request& req, httplib::Response& res,
                                  const httplib::ContentReader& reader) { handle_render(config, req, res, reader); });
  server.Get("/healthz", [](const httplib::Request&, httplib::Response& res) { res.set_content("ok\n", "text/plain"); });

  // Any error response without a body of ours (404, 405, ...) still gets a problem body.
  server.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
    const std::string detail = req.method + " " + req.path;
    if (res.status == 404) write_problem(res, problem(404, "not-found", "No such route", detail + " (routes: POST /render, GET /healthz)"));
    else if (res.status == 405) write_problem(res, problem(405, "method-not-allowed", "Method not allowed", detail));
    else write_problem(res, problem(res.status, "http-error", "HTTP error " + std::to_string(res.status), detail));
    return httplib::Server::HandlerResponse::Handled;
  }));

  // Nothing internal reaches the client; the log line carries the detail and the request id.
  server.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "unknown exception";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    std::fprintf(stderr, "error %s %s %s: %s\n", res.get_header_value("X-Request-Id").c_str(), req.method.c_str(),
                 req.path.c_str(), what.c_str());
    write_problem(res, problem(500, "internal", "Internal server error",
                               "the render failed unexpectedly; quote request id " + res.get_header_value("X-Request-Id")));
  });

  server.set_logger([](const httplib::Request& req, const httplib::Response& res) {
    // Bodies are streamed through ContentReaders, so bytes in are what the client declared.
    std::fprintf(stderr, "%s %s %d in=%llu out=%zu id=%s\n", req.method.c_str(), req.path.c_str(), res.status,
                 static_cast<unsigned long long>(req.get_header_value<std::uint64_t>("Content-Length")),
                 res.body.size(), res.get_header_value("X-Request-Id").c_str());
  });
}

}  // namespace rasterd
