#include "render_route.h"

#include <cstdio>
#include <exception>
#include <string_view>
#include <vector>

#include "body.h"
#include "etag.h"
#include "raster/raster.h"
#include "request_id.h"
#include "scene_url.h"

namespace rasterd {
namespace {

std::size_t uploads_size(const raster::Uploads& uploads) {
  std::size_t n = 0;
  for (const auto& [name, bytes] : uploads) n += bytes.size();
  return n;
}

}  // namespace

void RenderRoute::post(const httplib::Request& req, httplib::Response& res,
                       const httplib::ContentReader& reader) {
  ReceivedBody received;
  RequestBudget budget(memory_, config_.max_queue_wait);
  if (!read_body(config_, metrics_, req, res, reader, budget, memory_.capacity(), received)) return;
  const bool multipart = req.is_multipart_form_data();
  Input in;
  in.body = std::move(received.body);
  in.uploads = std::move(received.uploads);
  in.params = Params(req.params.begin(), req.params.end());
  in.declared_json = !multipart && is_json_media_type(req.get_header_value("Content-Type"));
  in.sniffed = received.sniffed;
  // What the request says the model is, for bytes that do not tell: the file name, else the media type.
  in.named_format = raster::format_of_file_name(received.model_file_name);
  if (!in.named_format && !multipart)
    in.named_format = format_of_media_type(req.get_header_value("Content-Type"));
  render(req, res, budget, std::move(in));
}

void RenderRoute::get(const httplib::Request& req, httplib::Response& res) {
  if (!req.has_param("scene")) {
    refuse(
        metrics_, res,
        problem(400, "missing-scene", "No scene in the URL",
                "GET /render needs ?scene=<base64url of the raw-deflated or plain scene JSON>; or POST the "
                "scene to /render"),
        "bad_scene_url");
    return;
  }
  Input in;
  try {
    in.body = decode_scene_param(req.get_param_value("scene"), config_.max_body_bytes);
  } catch (const SceneUrlError& e) {
    if (e.status() == 413)
      refuse(metrics_, res, problem(413, "body-too-large", "The scene is too large", e.what()), "body_size");
    else
      refuse(metrics_, res,
             problem(400, "invalid-scene-url", "The scene in the URL cannot be decoded", e.what()),
             "bad_scene_url");
    return;
  }
  in.params = Params(req.params.begin(), req.params.end());
  in.params.erase("scene");
  in.cacheable = true;
  RequestBudget budget(memory_, config_.max_queue_wait);
  const auto bytes = static_cast<std::int64_t>(in.body.size());
  if (!budget.reserve(bytes))
    return void(refuse_memory(metrics_, res, bytes, memory_.capacity(), config_.max_queue_wait, "memory"));
  render(req, res, budget, std::move(in));
}

// CORS preflight (a page's POST of JSON, or a GET with If-None-Match): which methods and request headers a
// page on an allowed origin may use.
void RenderRoute::preflight(httplib::Response& res, std::string_view methods) {
  res.status = 204;
  res.set_header("Allow", std::string(methods));
  if (!res.has_header("Access-Control-Allow-Origin")) return;
  res.set_header("Access-Control-Allow-Methods", std::string(methods));
  res.set_header("Access-Control-Allow-Headers", "Content-Type, If-None-Match, X-Request-Id");
  res.set_header("Access-Control-Max-Age", "86400");
}

// Both methods from here: admission, then draw() within the render deadline, its failures as problems.
void RenderRoute::render(const httplib::Request& req, httplib::Response& res, RequestBudget& budget,
                         Input in) {
  const Admission::Verdict verdict = admission_.enter(in.body.size() + uploads_size(in.uploads));
  if (verdict.refused) return refuse_busy(metrics_, res, verdict, config_.max_queue_wait);
  struct Leave {
    Admission& a;
    Clock::time_point since;
    ~Leave() { a.leave(ms_between(since, Clock::now())); }
  } leave{admission_, Clock::now()};
  if (config_.after_admission) config_.after_admission();

  const Clock::time_point t0 = Clock::now();
  budget.start_render(t0 + config_.render_deadline, &cancel_);
  try {
    draw(req, res, budget, std::move(in), t0);
  } catch (...) {
    answer_failure(res, budget);  // rethrows what is not a request's own failure (a 500)
  }
}

// Parse, plan, conditional request, render, encode; `t0` is when the render deadline started.
void RenderRoute::draw(const httplib::Request& req, httplib::Response& res, RequestBudget& budget, Input in,
                       Clock::time_point t0) {
  // This request's limits: the service's, asking this request's budget for memory and time.
  raster::Limits limits = config_.limits;
  limits.budget = &budget;
  const auto body_bytes = static_cast<std::int64_t>(in.body.size() + uploads_size(in.uploads));
  raster::Scene scene = scene_from_request(std::move(in.body), std::move(in.uploads), in.params, limits,
                                           in.declared_json, in.named_format, in.sniffed);
  budget.release(body_bytes);  // read and freed: what was sent is gone, the scene holds what it needs
  raster::PlanOptions options;
  options.max_threads = config_.render_threads;
  options.shader_cache = shader_cache_;  // a program seen before is not compiled again
  const raster::RenderPlan plan = raster::plan(scene, limits, options);
  if (explain_requested(in.params)) {  // no tag: the plan also depends on the thread count
    res.set_content(raster::explain_json(plan), "application/json");
    return;
  }
  // The tag names the image, so a client that holds it gets no render; hashing the parsed scene is
  // cheap next to parsing it.
  const std::string scene_tag = scene_etag(scene);
  NoneMatch match;
  if (req.has_header("If-None-Match")) match = none_match(req.get_header_value("If-None-Match"), scene_tag);
  if (match.hit && !in.cacheable) {
    // RFC 9110 13.1.2: 304 for GET and HEAD; any other method must not be performed: 412.
    write_problem(res, problem(412, "precondition-failed", "The precondition failed",
                               "If-None-Match names this scene's tag " + scene_tag +
                                   "; a POST with it is not performed (send GET for a 304)"));
    return;
  }
  // The tag the client holds tells the length; "*" or a tag without one leaves only the render to tell.
  if (match.hit && match.png_bytes) return not_modified(req, res, scene_tag, *match.png_bytes, in.cacheable);
  const Clock::time_point t1 = Clock::now();
  raster::RenderControl control;
  control.deadline = t0 + config_.render_deadline;
  control.cancel = &cancel_;
  control.budget = &budget;
  raster::Image image = raster::render(scene, plan, control);
  scene = {};  // done with: its memory goes before the PNG's comes
  const Clock::time_point t2 = Clock::now();
  // Consumed: filtered in place, so a request never holds two images.
  const std::vector<std::uint8_t> png = raster::encode_png(std::move(image), plan.png);
  const Clock::time_point t3 = Clock::now();
  metrics_.render(ms_between(t0, t3));
  char timing[160];
  std::snprintf(timing, sizeof timing, "parse;dur=%.3f, raster;dur=%.3f, encode;dur=%.3f", ms_between(t0, t1),
                ms_between(t1, t2), ms_between(t2, t3));
  res.set_header("Server-Timing", timing);
  if (match.hit) return not_modified(req, res, scene_tag, png.size(), in.cacheable);
  res.set_header("X-Render-Plan", raster::explain_line(plan));
  set_cache_headers(res, scene_tag, png.size(), in.cacheable);
  res.set_content(reinterpret_cast<const char*>(png.data()), png.size(), "image/png");
}

// The exception in flight as the request's problem: a bad query or scene, a render stopped (deadline or
// shutdown), or memory refused. Anything else is rethrown, for the server's exception handler (a 500).
void RenderRoute::answer_failure(httplib::Response& res, const RequestBudget& budget) {
  try {
    throw;
  } catch (const QueryError& e) {
    // The URL is wrong, not the scene: its own type, naming the parameter.
    Problem p = problem(400, "invalid-query", "A query parameter is not valid", e.what());
    p.parameter = e.parameter();
    write_problem(res, p);
  } catch (const raster::SceneError& e) {
    write_problem(res, problem_from(e));
  } catch (const raster::RenderCancelled&) {
    const bool shutting_down = cancel_.load();
    metrics_.rejected(shutting_down ? "shutdown" : "render_timeout");
    // Past the deadline is a property of the request, not of this replica: every replica has the same
    // deadline, so a 4xx, which proxies do not retry elsewhere (a 503 would be, costing every replica
    // the whole deadline).
    write_problem(res, shutting_down
                           ? problem(503, "shutting-down", "The server is shutting down",
                                     "the render was stopped; retry elsewhere")
                           : problem(422, "deadline-exceeded", "The render needs more time than allowed",
                                     "reading and drawing this request took more than the " +
                                         std::to_string(config_.render_deadline.count()) +
                                         " ms every replica allows (--render-deadline-ms), so it is not "
                                         "retried: send fewer primitives or faces, fewer pixels, or less "
                                         "anti-aliasing"));
  } catch (const raster::MemoryRefused& e) {
    const std::int64_t wanted = budget.wanted();
    if (wanted > memory_.capacity()) {
      metrics_.rejected("memory_limit");
      write_problem(res, problem(422, "memory-limit", "The request needs more memory than allowed",
                                 "reading and drawing it needs at least " + std::to_string(wanted >> 20) +
                                     " MiB, more than the service's memory budget of " +
                                     std::to_string(memory_.capacity() >> 20) + " MiB (--memory-budget); " +
                                     e.what() + ". Send a smaller model or image"));
    } else {
      refuse_memory(metrics_, res, e.bytes(), memory_.capacity(), config_.max_queue_wait, "memory");
    }
  }
}

// The cache headers go only on a 200 or 304: an error must not be cached.
void RenderRoute::set_cache_headers(httplib::Response& res, const std::string& scene_tag,
                                    std::size_t png_bytes, bool cacheable) const {
  res.set_header("ETag", image_etag(scene_tag, png_bytes));
  if (cacheable)
    res.set_header("Cache-Control",
                   "public, max-age=" + std::to_string(config_.cache_max_age) + ", immutable");
}

// A 304 declares the length its 200 had (RFC 9110 8.6; cpp-httplib 0.11 would otherwise write
// "Content-Length: 0" on an empty answer). It is written as the answer to a HEAD, which has the length
// of a body it does not carry: the request is the server's own object (as for `ranges` in the
// pre-routing handler), and the log keeps the method that was sent.
void RenderRoute::not_modified(const httplib::Request& req, httplib::Response& res,
                               const std::string& scene_tag, std::size_t png_bytes, bool cacheable) const {
  set_cache_headers(res, scene_tag, png_bytes, cacheable);
  res.status = 304;
  const_cast<httplib::Request&>(req).method = "HEAD";
  res.set_content_provider(png_bytes, "image/png",
                           [](std::size_t, std::size_t, httplib::DataSink&) { return false; });
}

}  // namespace rasterd
