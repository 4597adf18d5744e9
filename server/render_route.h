// The render route: POST /render (the scene, model or multipart upload is the body), GET /render?scene=
// (the scene is in the URL) and its CORS preflight. In: the request, the service's configuration, and the
// admission, memory pool, metrics, cancel flag and shader cache it shares with the other requests. Out: a PNG
// (with its ETag, Server-Timing, X-Render-Plan and cache headers), a 304, the plan as JSON (?explain), or a
// problem.
#pragma once

#include <atomic>
#include <chrono>
#include <optional>
#include <string>
#include <string_view>

#include <httplib.h>

#include "admission.h"
#include "memory_budget.h"
#include "metrics.h"
#include "raster/scene.h"
#include "request.h"
#include "service_config.h"

namespace rasterd {

class RenderRoute {
 public:
  RenderRoute(const ServiceConfig& config, Admission& admission, MemoryPool& memory, Metrics& metrics,
              const std::atomic<bool>& cancel, raster::ShaderCache* shader_cache)
      : config_(config),
        admission_(admission),
        memory_(memory),
        metrics_(metrics),
        cancel_(cancel),
        shader_cache_(shader_cache) {}

  /// POST /render: the scene (or model, or multipart upload) is the body.
  void post(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader);
  /// GET /render?scene=...: the scene is in the URL, so the answer can be cached by URL.
  void get(const httplib::Request& req, httplib::Response& res);
  /// OPTIONS /render, the CORS preflight; `methods` are the route's (routes.cpp), e.g. "GET, HEAD, POST".
  static void preflight(httplib::Response& res, std::string_view methods);

 private:
  /// What both methods hand to render(), read from the request.
  struct Input {
    std::string body;                                 ///< the scene or model bytes
    raster::Uploads uploads;                          ///< multipart parts besides the scene (POST only)
    Params params;                                    ///< the query parameters (without GET's "scene")
    bool cacheable = false;                           ///< a GET, whose answer is named by its URL alone
    bool declared_json = false;                       ///< its Content-Type says JSON
    std::optional<raster::ModelFormat> named_format;  ///< what the request says the model is, if anything
    std::optional<Sniffed> sniffed;                   ///< the request's sniff, if reading the body made it
  };

  void render(const httplib::Request& req, httplib::Response& res, RequestBudget& budget, Input in);
  void draw(const httplib::Request& req, httplib::Response& res, RequestBudget& budget, Input in,
            std::chrono::steady_clock::time_point t0);
  void answer_failure(httplib::Response& res, const RequestBudget& budget);
  void set_cache_headers(httplib::Response& res, const std::string& scene_tag, std::size_t png_bytes,
                         bool cacheable) const;
  void not_modified(const httplib::Request& req, httplib::Response& res, const std::string& scene_tag,
                    std::size_t png_bytes, bool cacheable) const;

  const ServiceConfig& config_;
  Admission& admission_;
  MemoryPool& memory_;
  Metrics& metrics_;
  const std::atomic<bool>& cancel_;    ///< set at shutdown past the grace period: running renders stop
  raster::ShaderCache* shader_cache_;  ///< compiled programs shared by every request; null: none kept
};

}  // namespace rasterd
