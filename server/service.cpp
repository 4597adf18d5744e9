#include "service.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include "problem.h"
#include "request.h"
#include "raster/raster.h"

namespace rasterd {
namespace {

std::string next_request_id() {
  static std::atomic<std::uint64_t> counter{0};  // process-wide by nature: ids must be unique
  char buf[32];
  std::snprintf(buf, sizeof buf, "r%08llx", static_cast<unsigned long long>(++counter));
  return buf;
}

// Refuses compressed bodies and bodies declared over the cap, before reading anything.
bool admit_body(const httplib::Request& req, httplib::Response& res, std::size_t cap) {
  if (req.has_header("Content-Encoding") && req.get_header_value("Content-Encoding") != "identity") {
    write_problem(res, problem(415, "unsupported-encoding", "Compressed request bodies are not accepted",
                               "send the body uncompressed (got Content-Encoding: " + req.get_header_value("Content-Encoding") + ")"));
    return false;
  }
  if (req.get_header_value<std::uint64_t>("Content-Length") > cap) {
    write_problem(res, problem(413, "body-too-large", "The request body is too large", "the limit is " + std::to_string(cap) + " bytes"));
    return false;
  }
  return true;
}

// Reads the body through the ContentReader: cpp-httplib 0.11 caps a buffered form-urlencoded body (what
// `curl -d` sends) at 8 KiB with a 413, but a ContentReader route receives any body. The cap is ours,
// counted while streaming (chunked bodies have no Content-Length). Multipart parts go to `uploads`,
// except a part named "scene", which becomes the body. Returns false with the problem written.
bool read_body(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader, std::size_t cap,
               std::string& body, raster::Uploads& uploads) {
  if (!admit_body(req, res, cap)) return false;
  std::size_t total = 0;
  bool over = false;
  auto take = [&](std::string& into, const char* data, std::size_t n) {
    if ((total += n) > cap) {
      over = true;
      return false;
    }
    into.append(data, n);
    return true;
  };
  if (req.is_multipart_form_data()) {
    std::string* current = nullptr;
    reader(
        [&](const httplib::MultipartFormData& part) {
          current = part.name == "scene" ? &body : &uploads[part.name];
          return true;
        },
        [&](const char* data, std::size_t n) { return take(*current, data, n); });
  } else {
    if (const auto declared = req.get_header_value<std::uint64_t>("Content-Length")) body.reserve(declared);
    reader([&](const char* data, std::size_t n) { return take(body, data, n); });
  }
  if (over) {
    write_problem(res, problem(413, "body-too-large", "The request body is too large", "the limit is " + std::to_string(cap) + " bytes"));
    return false;
  }
  return true;
}

void handle_render(const ServiceConfig& config, const httplib::Request& req, httplib::Response& res,
                   const httplib::ContentReader& reader) {
  std::string body;
  raster::Uploads uploads;
  if (!read_body(req, res, reader, config.max_body_bytes, body, uploads)) return;
  try {
    const Params params(req.params.begin(), req.params.end());
    const raster::Scene scene = scene_from_request(body, uploads, params, config.limits);
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
