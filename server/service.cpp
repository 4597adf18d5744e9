#include "service.h"

#include <dirent.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string_view>
#include <thread>
#include <vector>

#include "access_log.h"
#include "api.h"
#include "connection_threads.h"
#include "etag.h"
#include "memory_budget.h"
#include "playground.h"
#include "problem.h"
#include "raster/raster.h"
#include "request.h"
#include "resources.h"
#include "scene_url.h"

namespace rasterd {
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// Renders at once (`workers`), and who may wait for one. A render waits when the wait it can expect is
// short: (renders ahead of it / workers) x the recent mean render time, within `max_wait`; the bodies
// of waiting renders within `max_queued_bytes`; and at most `max_queue` of them, which bounds the
// connection threads. Past any of these a request is refused at once with how long to wait, and one that
// waited `max_wait` without a worker gives up. Health and metrics never pass through here.
class Admission {
 public:
  struct Verdict {
    const char* refused = nullptr;     ///< nullptr: admitted; else the metrics reason of the refusal
    std::chrono::milliseconds wait{};  ///< the expected wait when refused (for Retry-After)
  };

  Admission(int workers, int max_queue, std::size_t max_queued_bytes, std::chrono::milliseconds max_wait)
      : workers_(workers), max_queue_(max_queue), max_queued_bytes_(max_queued_bytes), max_wait_(max_wait) {}

  Verdict enter(std::size_t body_bytes) {
    std::unique_lock lock(mutex_);
    if (running_ < workers_) return ++running_, Verdict{};
    const auto expected = std::chrono::milliseconds(
        static_cast<std::int64_t>(std::ceil((waiting_ + 1) * mean_render_ms_ / workers_)));
    if (waiting_ >= max_queue_) return {"queue_full", expected};
    if (expected > max_wait_) return {"queue_wait", expected};
    if (waiting_ > 0 && queued_bytes_ + body_bytes > max_queued_bytes_) return {"queue_memory", expected};
    ++waiting_, queued_bytes_ += body_bytes;
    const bool free = freed_.wait_for(lock, max_wait_, [&] { return running_ < workers_; });
    --waiting_, queued_bytes_ -= body_bytes;
    if (!free) return {"queue_timeout", max_wait_};
    ++running_;
    return {};
  }
  void leave(double render_ms) {
    {
      std::lock_guard lock(mutex_);
      --running_;
      // A moving mean over roughly the last ten renders: follows a change of load within a second or two.
      mean_render_ms_ = rendered_++ == 0 ? render_ms : 0.9 * mean_render_ms_ + 0.1 * render_ms;
    }
    freed_.notify_one();
  }
  std::pair<int, int> load() {
    std::lock_guard lock(mutex_);
    return {running_, waiting_};
  }

 private:
  const int workers_, max_queue_;
  const std::size_t max_queued_bytes_;
  const std::chrono::milliseconds max_wait_;
  std::mutex mutex_;
  std::condition_variable freed_;
  int running_ = 0, waiting_ = 0;
  std::size_t queued_bytes_ = 0;
  double mean_render_ms_ = 0;  // admission to answer, of the renders so far
  std::uint64_t rendered_ = 0;
};

std::size_t uploads_size(const raster::Uploads& uploads) {
  std::size_t n = 0;
  for (const auto& [name, bytes] : uploads) n += bytes.size();
  return n;
}

// Prometheus counters; one mutex, touched once or twice per request.
class Metrics {
 public:
  static constexpr std::array<double, 10> kBucketsMs{1, 2.5, 5, 10, 25, 50, 100, 250, 1000, 10000};

  void request(const std::string& route, int status, std::size_t in, std::size_t out) {
    std::lock_guard lock(mutex_);
    ++requests_[{route, status}];
    bytes_in_ += in, bytes_out_ += out;
  }
  void render(double ms) {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < kBucketsMs.size(); ++i) buckets_[i] += ms <= kBucketsMs[i];
    ++render_count_, render_sum_ms_ += ms;
  }
  void rejected(const std::string& reason) {
    std::lock_guard lock(mutex_);
    ++rejected_[reason];
  }
  std::string text(int in_flight, int queued) {
    std::lock_guard lock(mutex_);
    std::string t;
    auto line = [&](const std::string& s) { t += s + "\n"; };
    line("# HELP rasterd_requests_total HTTP requests by route and status.");
    line("# TYPE rasterd_requests_total counter");
    for (const auto& [key, n] : requests_)
      line("rasterd_requests_total{route=\"" + key.first + "\",status=\"" + std::to_string(key.second) +
           "\"} " + std::to_string(n));
    line("# HELP rasterd_render_duration_seconds Parse + render + encode time of admitted renders.");
    line("# TYPE rasterd_render_duration_seconds histogram");
    for (std::size_t i = 0; i < kBucketsMs.size(); ++i)
      line("rasterd_render_duration_seconds_bucket{le=\"" + format(kBucketsMs[i] / 1000) + "\"} " +
           std::to_string(buckets_[i]));
    line("rasterd_render_duration_seconds_bucket{le=\"+Inf\"} " + std::to_string(render_count_));
    line("rasterd_render_duration_seconds_sum " + format(render_sum_ms_ / 1000));
    line("rasterd_render_duration_seconds_count " + std::to_string(render_count_));
    line("# HELP rasterd_renders_in_flight Renders running now.");
    line("# TYPE rasterd_renders_in_flight gauge");
    line("rasterd_renders_in_flight " + std::to_string(in_flight));
    line("# HELP rasterd_render_queue_length Renders waiting for a worker.");
    line("# TYPE rasterd_render_queue_length gauge");
    line("rasterd_render_queue_length " + std::to_string(queued));
    line("# HELP rasterd_rejected_total Requests refused before rendering, by reason.");
    line("# TYPE rasterd_rejected_total counter");
    for (const auto& [reason, n] : rejected_)
      line("rasterd_rejected_total{reason=\"" + reason + "\"} " + std::to_string(n));
    line("# HELP rasterd_bytes_total Request and response body bytes.");
    line("# TYPE rasterd_bytes_total counter");
    line("rasterd_bytes_total{direction=\"in\"} " + std::to_string(bytes_in_));
    line("rasterd_bytes_total{direction=\"out\"} " + std::to_string(bytes_out_));
    return t;
  }
  static std::string gauge(const std::string& name, const std::string& help, const std::string& type,
                           double value, const std::string& labels = "") {
    char number[40];  // bytes and seconds since 1970 need all their digits
    std::snprintf(number, sizeof number, "%.15g", value);
    return "# HELP " + name + " " + help + "\n# TYPE " + name + " " + type + "\n" + name + labels + " " +
           number + "\n";
  }

 private:
  static std::string format(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }
  std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::uint64_t> requests_;
  std::array<std::uint64_t, kBucketsMs.size()> buckets_{};
  std::uint64_t render_count_ = 0;
  double render_sum_ms_ = 0;
  std::map<std::string, std::uint64_t> rejected_;
  std::uint64_t bytes_in_ = 0, bytes_out_ = 0;
};

// The process_* metrics every Prometheus client library exports, from /proc/self: what an operator alerts on
// before the kernel's OOM killer acts (resident memory against the container's limit), and CPU, fds and
// start time for dashboards.
std::string process_metrics() {
  std::string t;
  const double tick = static_cast<double>(::sysconf(_SC_CLK_TCK));
  const double page = static_cast<double>(::sysconf(_SC_PAGESIZE));
  std::ifstream stat_file("/proc/self/stat");
  std::string stat((std::istreambuf_iterator<char>(stat_file)), std::istreambuf_iterator<char>());
  // Fields after the command's closing ')': state is field 3; utime 14, stime 15, starttime 22, vsize 23,
  // rss 24 (man 5 proc).
  std::vector<std::string> f;
  if (const auto close = stat.rfind(')'); close != std::string::npos) {
    std::istringstream in(stat.substr(close + 2));
    for (std::string w; in >> w;) f.push_back(w);
  }
  auto field = [&](std::size_t n) { return n - 3 < f.size() ? std::strtod(f[n - 3].c_str(), nullptr) : 0.0; };
  double boot = 0;  // seconds since 1970 at boot: /proc/stat's btime
  std::ifstream kernel("/proc/stat");
  for (std::string key; kernel >> key;)
    if (key == "btime") {
      kernel >> boot;
      break;
    }
  int fds = 0;
  if (DIR* d = ::opendir("/proc/self/fd")) {
    while (const dirent* e = ::readdir(d)) fds += e->d_name[0] != '.';
    ::closedir(d);
    --fds;  // the one opendir holds
  }
  rlimit nofile{};
  ::getrlimit(RLIMIT_NOFILE, &nofile);
  t += Metrics::gauge("process_cpu_seconds_total", "User and system CPU time spent in seconds.", "counter",
                      (field(14) + field(15)) / tick);
  t += Metrics::gauge("process_resident_memory_bytes", "Resident memory size in bytes.", "gauge",
                      field(24) * page);
  t += Metrics::gauge("process_virtual_memory_bytes", "Virtual memory size in bytes.", "gauge", field(23));
  t += Metrics::gauge("process_start_time_seconds", "Start time of the process since unix epoch in seconds.",
                      "gauge", boot + field(22) / tick);
  t += Metrics::gauge("process_open_fds", "Number of open file descriptors.", "gauge", fds);
  t += Metrics::gauge("process_max_fds", "Maximum number of open file descriptors.", "gauge",
                      static_cast<double>(nofile.rlim_cur));
  return t;
}

// RFC 9110 5.6.7's IMF-fixdate, for the Date header every answer carries (6.6.1).
std::string http_date(std::time_t when) {
  std::tm utc{};
  ::gmtime_r(&when, &utc);
  char buf[40];
  std::strftime(buf, sizeof buf, "%a, %d %b %Y %H:%M:%S GMT", &utc);
  return buf;
}

// cpp-httplib runs a request's pre-routing handler, route handler and logger on one thread, one request
// at a time, and offers no per-request user data: this thread-local is that request's context.
struct RequestContext {
  Clock::time_point start;
  std::chrono::system_clock::time_point wall;  ///< when the request began: the log line, the Date header
  std::string method;                          ///< as sent (a 304 is written as a HEAD answer: see render())
  std::size_t bytes_in = 0;
};
thread_local RequestContext t_request;

std::string next_request_id() {
  static std::atomic<std::uint64_t> counter{0};  // process-wide by nature: ids must be unique
  char buf[32];
  std::snprintf(buf, sizeof buf, "r%08llx", static_cast<unsigned long long>(++counter));
  return buf;
}

// Every route by its path pattern, with the methods it answers: the metrics count requests by pattern (a
// bounded set of labels), and a request with another method gets a 405 naming them (cpp-httplib would
// answer 404 or 400).
struct Route {
  std::string_view pattern;  ///< the path, or "/examples/{name}" for any one example
  std::string_view methods;  ///< for the Allow header, e.g. "GET, HEAD"
};

const Route* route_of(const std::string& path) {
  static constexpr Route kRoutes[] = {
      {"/render", "GET, HEAD, POST, OPTIONS"},
      {"/healthz", "GET, HEAD"},
      {"/metrics", "GET, HEAD"},
      {"/schema/scene.json", "GET, HEAD"},
      {"/openapi.json", "GET, HEAD"},
      {"/", "GET, HEAD"},
      {"/examples", "GET, HEAD"},
      {"/examples/{name}", "GET, HEAD"},
  };
  for (const Route& route : kRoutes)
    if (path == route.pattern) return &route;
  if (path.starts_with("/examples/") && path.find('/', 10) == std::string::npos)
    return &std::end(kRoutes)[-1];
  return nullptr;
}

std::string route_label(const std::string& path) {
  const Route* route = route_of(path);
  return route ? std::string(route->pattern) : "other";
}

// A client's own request id is passed on when it is one a log line can carry as it is: short, and made of
// letters, digits and "-_.:". Anything else is replaced, so no client text reaches the logs unescaped.
bool plain_request_id(const std::string& id) {
  return !id.empty() && id.size() <= 64 && std::all_of(id.begin(), id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == ':';
  });
}

}  // namespace

struct Service::State {
  ServiceConfig config;
  Admission admission;
  MemoryPool memory;
  Metrics metrics;
  std::atomic<bool> cancel{false};
  int listen_socket = -1;  // remembered from the socket-options hook, for widen_backlog()

  explicit State(ServiceConfig c)
      : config(c),
        admission(c.workers, c.max_queue, c.max_queued_bytes, c.max_queue_wait),
        memory(c.memory_budget) {}

  // How long a connection may stay silent: the body deadline, at most 5 s (also between requests' headers).
  std::chrono::milliseconds read_timeout() const {
    return std::min<std::chrono::milliseconds>(config.body_deadline, std::chrono::milliseconds(5000));
  }

  // CORS on every answer, errors included (a page must be able to read why it failed): which origin may
  // read it, and which of our headers it may see. With a list of origins the answer varies by Origin.
  void set_cors_headers(const httplib::Request& req, httplib::Response& res) const {
    const auto& allowed = config.cors_origins;
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

  bool refuse(httplib::Response& res, const Problem& p, const std::string& reason) {
    metrics.rejected(reason);
    write_problem(res, p);
    return false;
  }

  // Refuses compressed bodies and bodies declared over the cap before reading anything; then reads the
  // body through the ContentReader. cpp-httplib 0.11 caps a buffered form-urlencoded body (what
  // `curl -d` sends) at 8 KiB with a 413, but a ContentReader route receives any body. The cap is counted
  // while streaming (chunked bodies declare no length) and the deadline holds whatever the pace of the
  // bytes. Multipart parts go to `uploads`, except "scene", which becomes the body.
  // 503 with Retry-After: the memory budget could not give `bytes` within the queue's wait.
  bool refuse_memory(httplib::Response& res, std::int64_t bytes, const char* reason) {
    const auto seconds = std::max<std::int64_t>(1, (config.max_queue_wait.count() + 999) / 1000);
    res.set_header("Retry-After", std::to_string(seconds));
    return refuse(res,
                  problem(503, "overloaded", "Not enough memory is free for this request now",
                          "it needs about " + std::to_string(bytes >> 20) + " MiB more of the " +
                              std::to_string(memory.capacity() >> 20) +
                              " MiB memory budget, and other requests "
                              "held it for " +
                              std::to_string(config.max_queue_wait.count()) + " ms; try again in " +
                              std::to_string(seconds) + " s"),
                  reason);
  }

  bool read_body(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader,
                 RequestBudget& budget, std::string& body, raster::Uploads& uploads,
                 std::string& model_file_name) {
    const std::size_t cap = config.max_body_bytes;
    if (req.has_header("Content-Encoding") && req.get_header_value("Content-Encoding") != "identity")
      return refuse(res,
                    problem(415, "unsupported-encoding", "Compressed request bodies are not accepted",
                            "send the body uncompressed (got Content-Encoding: " +
                                req.get_header_value("Content-Encoding") + ")"),
                    "encoding");
    auto too_large = [&] {
      return refuse(res,
                    problem(413, "body-too-large", "The request body is too large",
                            "the limit is " + std::to_string(cap) + " bytes"),
                    "body_size");
    };
    if (req.get_header_value<std::uint64_t>("Content-Length") > cap) return too_large();
    // The body's memory is reserved before it is read: declared, at once; else as it arrives, a MiB at a
    // time. One larger than the whole budget could never be held.
    const auto declared = static_cast<std::int64_t>(req.get_header_value<std::uint64_t>("Content-Length"));
    if (declared > memory.capacity())
      return refuse(
          res,
          problem(413, "body-too-large", "The request body is too large",
                  "the body's " + std::to_string(declared) + " bytes are more than the memory budget of " +
                      std::to_string(memory.capacity()) + " bytes (--memory-budget)"),
          "body_size");
    if (!budget.reserve(declared)) return refuse_memory(res, declared, "memory");
    bool no_memory = false;

    const Clock::time_point deadline = t_request.start + config.body_deadline;
    bool over = false, late = false;
    Clock::time_point last_arrival = Clock::now();
    auto take = [&](std::string& into, const char* data, std::size_t n) {
      last_arrival = Clock::now();
      t_request.bytes_in += n;
      over = t_request.bytes_in > cap;
      late = !over && Clock::now() > deadline;
      if (over || late) return false;  // stop reading
      if (static_cast<std::int64_t>(t_request.bytes_in) > budget.held() && !budget.reserve(1 << 20))
        return !(no_memory = true);
      into.append(data, n);
      return true;
    };
    // RFC 9112 6.3: a request with neither Content-Length nor chunked framing has no body (`curl -X POST`);
    // reading on would wait for bytes that never come.
    const bool chunked = req.get_header_value("Transfer-Encoding").find("chunked") != std::string::npos;
    if (!req.has_header("Content-Length") && !chunked) return true;
    bool complete;
    if (req.is_multipart_form_data()) {
      std::string* current = nullptr;
      std::string bad_name;   // a part or file name that is not UTF-8: the names are echoed in errors
      std::string duplicate;  // two parts kept under one name: which bytes are meant is not knowable
      std::vector<PartName> parts;
      complete = reader(
          [&](const httplib::MultipartFormData& part) {
            for (const std::string* name : {&part.name, &part.filename})
              if (raster::first_invalid_utf8(*name) != std::string_view::npos) {
                bad_name = *name;
                return false;
              }
            if (part.name == "scene") {
              current = &body;
              return true;
            }
            if (part.name == "model") model_file_name = part.filename;
            const std::string key = upload_key(part.name, part.filename);
            parts.push_back({part.name, key});
            const auto [it, added] = uploads.try_emplace(key);
            if (!added) {
              duplicate = key;
              return false;
            }
            current = &it->second;
            return true;
          },
          [&](const char* data, std::size_t n) { return take(*current, data, n); });
      if (!bad_name.empty()) {
        try {
          raster::require_utf8(bad_name, "a multipart part or file name");
        } catch (const raster::SceneError& e) {
          return refuse(res, problem_from(e), "encoding");
        }
      }
      if (!duplicate.empty())
        return refuse(res,
                      problem(400, "duplicate-part", "Two multipart parts have the same name",
                              "more than one part is named \"" + duplicate +
                                  "\" (texture parts are named by their file name); send each once"),
                      "duplicate_part");
      add_part_names(uploads, parts);
      if (const std::string unnamed = adopt_main_part(body, uploads, parts, &model_file_name);
          !unnamed.empty())
        return refuse(res, problem(400, "missing-part", "No scene or model part in the upload", unnamed),
                      "missing_part");
    } else {
      if (const auto declared = req.get_header_value<std::uint64_t>("Content-Length")) body.reserve(declared);
      complete = reader([&](const char* data, std::size_t n) { return take(body, data, n); });
    }
    if (over) return too_large();
    if (no_memory) return refuse_memory(res, 1 << 20, "memory");
    // A client that went quiet for the socket's read timeout also failed to deliver its body in time;
    // one whose connection ended is past answering anyway.
    if (!complete && Clock::now() - last_arrival >= read_timeout()) late = true;
    if (late)
      return refuse(res,
                    problem(408, "body-timeout", "The request body did not arrive in time",
                            "the whole body must arrive within " +
                                std::to_string(config.body_deadline.count()) + " ms"),
                    "body_timeout");
    if (!complete)  // the connection ended early, or the multipart framing is broken
      return refuse(res,
                    problem(400, "incomplete-body", "The request body is incomplete or malformed",
                            "the body ended before its declared length, or its multipart framing is broken"),
                    "body_incomplete");
    return true;
  }

  // POST /render: the scene (or model, or multipart upload) is the body.
  void render_post(const httplib::Request& req, httplib::Response& res,
                   const httplib::ContentReader& reader) {
    std::string body;
    raster::Uploads uploads;
    std::string model_file_name;  // of the multipart part that carried the model
    RequestBudget budget(memory, config.max_queue_wait);
    if (!read_body(req, res, reader, budget, body, uploads, model_file_name)) return;
    const bool multipart = req.is_multipart_form_data();
    const bool declared_json = !multipart && is_json_media_type(req.get_header_value("Content-Type"));
    // What the request says the model is, for bytes that do not tell: the file name, else the media type.
    std::optional<raster::ModelFormat> named = raster::format_of_file_name(model_file_name);
    if (!named && !multipart) named = format_of_media_type(req.get_header_value("Content-Type"));
    render(req, res, budget, std::move(body), std::move(uploads),
           Params(req.params.begin(), req.params.end()), false, declared_json, named);
  }

  // GET /render?scene=...: the scene is in the URL, so the answer can be cached by URL.
  void render_get(const httplib::Request& req, httplib::Response& res) {
    if (!req.has_param("scene")) {
      refuse(
          res,
          problem(400, "missing-scene", "No scene in the URL",
                  "GET /render needs ?scene=<base64url of the raw-deflated or plain scene JSON>; or POST the "
                  "scene to /render"),
          "bad_scene_url");
      return;
    }
    std::string body;
    try {
      body = decode_scene_param(req.get_param_value("scene"), config.max_body_bytes);
    } catch (const SceneUrlError& e) {
      if (e.status() == 413)
        refuse(res, problem(413, "body-too-large", "The scene is too large", e.what()), "body_size");
      else
        refuse(res, problem(400, "invalid-scene-url", "The scene in the URL cannot be decoded", e.what()),
               "bad_scene_url");
      return;
    }
    Params params(req.params.begin(), req.params.end());
    params.erase("scene");
    RequestBudget budget(memory, config.max_queue_wait);
    if (!budget.reserve(static_cast<std::int64_t>(body.size())))
      return void(refuse_memory(res, static_cast<std::int64_t>(body.size()), "memory"));
    render(req, res, budget, std::move(body), {}, params, true, false);
  }

  // Both methods from here: admission, parse, plan, conditional request, render, encode. `cacheable`: the
  // request is a GET, whose answer is named by its URL alone. `declared_json`: its Content-Type says JSON.
  void render(const httplib::Request& req, httplib::Response& res, RequestBudget& budget, std::string body,
              raster::Uploads uploads, const Params& params, bool cacheable, bool declared_json,
              std::optional<raster::ModelFormat> named_format = std::nullopt) {
    const Admission::Verdict verdict = admission.enter(body.size() + uploads_size(uploads));
    if (verdict.refused) {
      const auto seconds = std::max<std::int64_t>(1, (verdict.wait.count() + 999) / 1000);
      res.set_header("Retry-After", std::to_string(seconds));
      const bool timed_out = std::string_view(verdict.refused) == "queue_timeout";
      refuse(
          res,
          problem(503, "overloaded", "All render workers are busy",
                  timed_out ? "no worker was free within " + std::to_string(config.max_queue_wait.count()) +
                                  " ms; try again in " + std::to_string(seconds) + " s"
                            : "the wait for a worker would be about " + std::to_string(verdict.wait.count()) +
                                  " ms; try again in " + std::to_string(seconds) + " s"),
          verdict.refused);
      return;
    }
    const Clock::time_point admitted = Clock::now();
    struct Leave {
      Admission& a;
      Clock::time_point since;
      ~Leave() { a.leave(ms_between(since, Clock::now())); }
    } leave{admission, admitted};
    if (config.after_admission) config.after_admission();

    const Clock::time_point t0 = Clock::now();
    // This request's limits: the service's, asking this request's budget for memory and time.
    raster::Limits limits = config.limits;
    limits.budget = &budget;
    budget.start_render(t0 + config.render_deadline, &cancel);
    try {
      const auto body_bytes = static_cast<std::int64_t>(body.size() + uploads_size(uploads));
      raster::Scene scene = scene_from_request(std::move(body), std::move(uploads), params, limits,
                                               declared_json, named_format);
      budget.release(body_bytes);  // read and freed: what was sent is gone, the scene holds what it needs
      const raster::RenderPlan plan = raster::plan(scene, limits, {config.render_threads});
      if (explain_requested(params)) {  // no tag: the plan also depends on the thread count
        res.set_content(raster::explain_json(plan), "application/json");
        return;
      }
      // The tag names the image, so a client that holds it gets no render; hashing the parsed scene is
      // cheap next to parsing it. The cache headers go only on a 200 or 304: an error must not be cached.
      const std::string scene_tag = scene_etag(scene);
      auto set_cache_headers = [&](std::size_t png_bytes) {
        res.set_header("ETag", image_etag(scene_tag, png_bytes));
        if (cacheable)
          res.set_header("Cache-Control",
                         "public, max-age=" + std::to_string(config.cache_max_age) + ", immutable");
      };
      // A 304 declares the length its 200 had (RFC 9110 8.6; cpp-httplib 0.11 would otherwise write
      // "Content-Length: 0" on an empty answer). It is written as the answer to a HEAD, which has the length
      // of a body it does not carry: the request is the server's own object (as for `ranges` in the
      // pre-routing handler), and the log keeps the method that was sent.
      auto not_modified = [&](std::size_t png_bytes) {
        set_cache_headers(png_bytes);
        res.status = 304;
        const_cast<httplib::Request&>(req).method = "HEAD";
        res.set_content_provider(png_bytes, "image/png",
                                 [](std::size_t, std::size_t, httplib::DataSink&) { return false; });
      };
      NoneMatch match;
      if (req.has_header("If-None-Match"))
        match = none_match(req.get_header_value("If-None-Match"), scene_tag);
      if (match.hit && !cacheable) {
        // RFC 9110 13.1.2: 304 for GET and HEAD; any other method must not be performed: 412.
        write_problem(res, problem(412, "precondition-failed", "The precondition failed",
                                   "If-None-Match names this scene's tag " + scene_tag +
                                       "; a POST with it is not performed (send GET for a 304)"));
        return;
      }
      // The tag the client holds tells the length; "*" or a tag without one leaves only the render to tell.
      if (match.hit && match.png_bytes) return not_modified(*match.png_bytes);
      const Clock::time_point t1 = Clock::now();
      raster::RenderControl control;
      control.deadline = t0 + config.render_deadline;
      control.cancel = &cancel;
      control.budget = &budget;
      raster::Image image = raster::render(scene, plan, control);
      scene = {};  // done with: its memory goes before the PNG's comes
      const Clock::time_point t2 = Clock::now();
      // Consumed: filtered in place, so a request never holds two images.
      const std::vector<std::uint8_t> png = raster::encode_png(std::move(image), plan.png);
      const Clock::time_point t3 = Clock::now();
      metrics.render(ms_between(t0, t3));
      char timing[160];
      std::snprintf(timing, sizeof timing, "parse;dur=%.3f, raster;dur=%.3f, encode;dur=%.3f",
                    ms_between(t0, t1), ms_between(t1, t2), ms_between(t2, t3));
      res.set_header("Server-Timing", timing);
      if (match.hit) return not_modified(png.size());
      res.set_header("X-Render-Plan", raster::explain_line(plan));
      set_cache_headers(png.size());
      res.set_content(reinterpret_cast<const char*>(png.data()), png.size(), "image/png");
    } catch (const QueryError& e) {
      // The URL is wrong, not the scene: its own type, naming the parameter.
      Problem p = problem(400, "invalid-query", "A query parameter is not valid", e.what());
      p.parameter = e.parameter();
      write_problem(res, p);
    } catch (const raster::SceneError& e) {
      write_problem(res, problem_from(e));
    } catch (const raster::RenderCancelled&) {
      const bool shutting_down = cancel.load();
      metrics.rejected(shutting_down ? "shutdown" : "render_timeout");
      // Past the deadline is a property of the request, not of this replica: every replica has the same
      // deadline, so a 4xx, which proxies do not retry elsewhere (a 503 would be, costing every replica
      // the whole deadline).
      write_problem(res, shutting_down
                             ? problem(503, "shutting-down", "The server is shutting down",
                                       "the render was stopped; retry elsewhere")
                             : problem(422, "deadline-exceeded", "The render needs more time than allowed",
                                       "reading and drawing this request took more than the " +
                                           std::to_string(config.render_deadline.count()) +
                                           " ms every replica allows (--render-deadline-ms), so it is not "
                                           "retried: send fewer primitives or faces, fewer pixels, or less "
                                           "anti-aliasing"));
    } catch (const raster::MemoryRefused& e) {
      const std::int64_t wanted = budget.wanted();
      if (wanted > memory.capacity()) {
        metrics.rejected("memory_limit");
        write_problem(res, problem(422, "memory-limit", "The request needs more memory than allowed",
                                   "reading and drawing it needs at least " + std::to_string(wanted >> 20) +
                                       " MiB, more than the service's memory budget of " +
                                       std::to_string(memory.capacity() >> 20) + " MiB (--memory-budget); " +
                                       e.what() + ". Send a smaller model or image"));
      } else {
        refuse_memory(res, e.bytes(), "memory");
      }
    }
  }
};

Service::Service(ServiceConfig config) {
  // The CPUs this process may use (its affinity and cgroup quota), not the machine's: a container limited
  // to one CPU renders on one thread.
  const int cpus = static_cast<int>(std::max<std::int64_t>(1, cpu_limit().value));
  if (config.workers <= 0) config.workers = cpus;
  if (config.render_threads <= 0) config.render_threads = cpus;
  if (config.memory_budget <= 0) config.memory_budget = default_memory_budget(memory_limit());
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
  // Connection threads: every admitted or queued render holds one, slow bodies hold one while they
  // arrive, and health and metrics must still find one free.
  const std::size_t threads = static_cast<std::size_t>(s.config.workers + s.config.max_queue) + 16;
  server.new_task_queue = [threads] { return new ConnectionThreads(threads); };
  // One request per connection. After a 408 a kept-alive connection goes on reading whatever the client
  // still drips as its next request line, holding a thread for as long as the client likes; cpp-httplib
  // 0.11 decides keep-alive from the request, before routing, so a handler cannot close its own
  // connection. A new connection costs tens of microseconds on a service whose requests cost
  // milliseconds, and no idle connection holds a thread.
  server.set_keep_alive_max_count(1);
  server.set_read_timeout(s.read_timeout());
  server.set_socket_options([&s](socket_t sock) {
    // SO_REUSEADDR alone: a restarted server may bind while old connections linger in TIME_WAIT. Not
    // SO_REUSEPORT (cpp-httplib's default), with which a second server on a taken port binds silently and
    // takes a share of the connections, so a forgotten old instance keeps answering.
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    if (s.listen_socket < 0)
      s.listen_socket = sock;  // the first socket this server creates is the listening one
  });

  server.set_pre_routing_handler([&s](const httplib::Request& req, httplib::Response& res) {
    t_request = RequestContext{Clock::now(), std::chrono::system_clock::now(), {}, 0};
    res.set_header("Date", http_date(std::chrono::system_clock::to_time_t(t_request.wall)));
    t_request.method = req.method;
    const std::string client_id = req.get_header_value("X-Request-Id");
    res.set_header("X-Request-Id", plain_request_id(client_id) ? client_id : next_request_id());
    s.set_cors_headers(req, res);
    // Range is ignored (RFC 9110 14.2 allows it): a byte range of a picture is of no use, and cpp-httplib
    // 0.11 would slice every answer, problems included, with a Content-Range past their end. The Request is
    // the server's own non-const object, handed to handlers as const.
    const_cast<httplib::Request&>(req).ranges.clear();
    res.set_header("Accept-Ranges", "none");  // else cpp-httplib advertises "bytes" on HEAD answers
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // CORS preflight (a page's POST of JSON, or a GET with If-None-Match): which methods and request headers a
  // page on an allowed origin may use.
  server.Options("/render", [](const httplib::Request&, httplib::Response& res) {
    res.status = 204;
    res.set_header("Allow", "GET, HEAD, POST, OPTIONS");
    if (!res.has_header("Access-Control-Allow-Origin")) return;
    res.set_header("Access-Control-Allow-Methods", "GET, HEAD, POST, OPTIONS");
    res.set_header("Access-Control-Allow-Headers", "Content-Type, If-None-Match, X-Request-Id");
    res.set_header("Access-Control-Max-Age", "86400");
  });

  server.Post("/render", [&s](const httplib::Request& req, httplib::Response& res,
                              const httplib::ContentReader& reader) { s.render_post(req, res, reader); });
  // Image URLs, GET /render?scene=..., and GET /schema/scene.json, GET /openapi.json: server/api.cpp.
  server.Get("/render",
             [&s](const httplib::Request& req, httplib::Response& res) { s.render_get(req, res); });
  install_api_routes(server);
  server.Get("/healthz",
             [](const httplib::Request&, httplib::Response& res) { res.set_content("ok\n", "text/plain"); });
  server.Get("/metrics", [&s](const httplib::Request&, httplib::Response& res) {
    const auto [running, waiting] = s.admission.load();
    std::string text = s.metrics.text(running, waiting);
    text +=
        Metrics::gauge("rasterd_memory_budget_bytes", "Bytes requests may reserve at once (--memory-budget).",
                       "gauge", static_cast<double>(s.memory.capacity()));
    text +=
        Metrics::gauge("rasterd_memory_reserved_bytes",
                       "Bytes reserved now by requests: bodies, parsed scenes and models, render buffers.",
                       "gauge", static_cast<double>(s.memory.reserved()));
    text += Metrics::gauge("rasterd_memory_reserved_peak_bytes", "Most bytes reserved at once since start.",
                           "gauge", static_cast<double>(s.memory.peak()));
    text += Metrics::gauge("rasterd_build_info", "The release and render version of this binary.", "gauge", 1,
                           "{version=\"" RASTERD_VERSION "\",render_version=\"" +
                               std::to_string(raster::kRenderVersion) + "\"}");
    text += process_metrics();
    res.set_content(text, "text/plain; version=0.0.4");
  });
  // GET / (the playground page) and GET /examples[/<name>.json]: server/playground.cpp.
  install_playground(server);

  // Any error response without a body of ours (404, 405, ...) still gets a problem body.
  server.set_error_handler(
      httplib::Server::HandlerWithResponse([&s](const httplib::Request& req, httplib::Response& res) {
        if (!res.has_header("X-Request-Id")) {
          // cpp-httplib answered before routing (a request line over its 8192-byte limit, or a malformed
          // one): no pre-routing handler ran, so this request has no id or start time of its own yet.
          t_request = RequestContext{Clock::now(), std::chrono::system_clock::now(), {}, 0};
          res.set_header("Date", http_date(std::chrono::system_clock::to_time_t(t_request.wall)));
          res.set_header("X-Request-Id", next_request_id());
          s.set_cors_headers(req, res);
        }
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        const std::string detail = req.method + " " + req.path;
        if (res.status == 414) {
          s.metrics.rejected("uri_too_long");
          write_problem(res, problem(414, "uri-too-long", "The request URI is too long",
                                     "a request line is at most 8192 bytes; POST the scene to /render "
                                     "instead of putting it in the URL"));
        } else if (const Route* route = route_of(req.path);
                   route && (", " + std::string(route->methods) + ",").find(", " + req.method + ",") ==
                                std::string::npos) {
          // The route exists but not with this method (cpp-httplib says 404 or 400 here).
          const std::string allowed(route->methods);
          res.set_header("Allow", allowed);
          write_problem(res, problem(405, "method-not-allowed", "Method not allowed",
                                     detail + ": " + req.path + " answers " + allowed));
        } else if (res.status == 404) {
          write_problem(res, problem(404, "not-found", "No such route",
                                     detail + " (the routes are described at GET /openapi.json)"));
        } else
          write_problem(
              res, problem(res.status, "http-error", "HTTP error " + std::to_string(res.status), detail));
        return httplib::Server::HandlerResponse::Handled;
      }));

  // Nothing internal reaches the client; the log line carries the detail and the request id.
  server.set_exception_handler(
      [](const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
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
      });

  server.set_logger([&s](const httplib::Request& req, const httplib::Response& res) {
    const std::size_t in = t_request.bytes_in ? t_request.bytes_in : req.body.size();
    s.metrics.request(route_label(req.path), res.status, in, res.body.size());
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
    const std::string text = s.config.log_json ? line.json() : line.text();
    std::fwrite(text.data(), 1, text.size(), stderr);
  });
}

namespace {

struct Flag {
  const char* name;  // --name, and RASTERD_NAME (upper case, '-' as '_') in the environment
  const char* help;
};
constexpr Flag kFlags[] = {
    {"host", "address to listen on (default 0.0.0.0)"},
    {"port", "port (default 8080; also PORT); 0 = any free port, named in the \"listening on\" line"},
    {"max-body-bytes", "request body limit, 413 above (default 33554432 = 32 MiB)"},
    {"max-width", "image width limit, 422 above (default 8192)"},
    {"max-height", "image height limit, 422 above (default 8192)"},
    {"max-pixels", "width x height limit, 422 above (default 40000000)"},
    {"max-primitives", "primitives (and mesh triangles) limit, 422 above (default 2000000)"},
    {"max-obj-faces",
     "faces of one model (OBJ faces; STL, PLY and glTF triangles), 422 above (default 5000000)"},
    {"max-json-depth", "JSON nesting limit, 400 above (default 64)"},
    {"render-deadline-ms", "parse + render + encode deadline, 422 deadline-exceeded past it (default 10000)"},
    {"body-deadline-ms", "time for the whole request body to arrive, 408 past it (default 10000)"},
    {"workers", "renders at once (default: the CPUs the process may use: affinity and cgroup quota)"},
    {"memory-budget",
     "bytes requests may reserve at once, e.g. 1536M or 2G (default: the cgroup's memory limit, else 3/4 of "
     "the machine's, less 480 MiB set aside; docs/memory.md)"},
    {"log-format", "text (default) or json: one line per request on stderr"},
    {"max-queue", "renders waiting for a worker at most, 503 + Retry-After beyond (default 256)"},
    {"max-queue-wait-ms",
     "a render waits only if its expected wait is within this, and at most this long (default 2000)"},
    {"max-queued-bytes", "request bytes held by waiting renders, 503 beyond (default 268435456 = 256 MiB)"},
    {"cors-origins",
     "origins whose pages may read answers, comma-separated; * = any (default), none = no CORS"},
    {"render-threads", "band threads per render (default: the CPUs the process may use)"},
    {"shutdown-grace-ms", "after SIGTERM/SIGINT, time for running and queued renders (default 20000)"},
    {"cache-max-age",
     "seconds in Cache-Control: public, max-age=N, immutable on GET /render (default 86400)"},
};

// "*", "none", or a comma-separated list of origins (blanks around commas ignored).
std::vector<std::string> parse_origins(const std::string& text) {
  std::vector<std::string> origins;
  if (text == "none") return origins;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t comma = text.find(',', at);
    if (comma == std::string::npos) comma = text.size();
    std::string origin = text.substr(at, comma - at);
    origin.erase(0, origin.find_first_not_of(" \t"));
    origin.erase(origin.find_last_not_of(" \t") + 1);
    while (origin.size() > 1 && origin.back() == '/') origin.pop_back();  // an origin has no path
    if (!origin.empty()) origins.push_back(origin);
    at = comma + 1;
  }
  return origins;
}

std::string env_name(const char* flag) {
  std::string e = "RASTERD_";
  for (const char* c = flag; *c; ++c)
    e += *c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
  return e;
}

}  // namespace

std::string service_help() {
  std::string h =
      "rasterd serve [--flag value ...]\n\nEach flag can also be set in the environment as RASTERD_<FLAG> "
      "(e.g. RASTERD_MAX_BODY_BYTES);\nflags win over the environment.\n\n";
  for (const Flag& f : kFlags) {
    char line[200];
    std::snprintf(line, sizeof line, "  --%-20s %s\n", f.name, f.help);
    h += line;
  }
  return h;
}

std::string parse_service_flags(int argc, const char* const* argv, ServiceConfig& config, std::string& host,
                                int& port) {
  std::map<std::string, std::string> values;
  for (const Flag& f : kFlags)
    if (const char* v = std::getenv(env_name(f.name).c_str())) values[f.name] = v;
  if (const char* p = std::getenv("PORT"); p && !values.count("port")) values["port"] = p;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (a.rfind("--", 0) != 0) return "unexpected argument '" + a + "'";
    a = a.substr(2);
    std::string value;
    if (const auto eq = a.find('='); eq != std::string::npos)
      value = a.substr(eq + 1), a = a.substr(0, eq);
    else if (i + 1 < argc)
      value = argv[++i];
    else
      return "--" + a + " needs a value";
    if (std::none_of(std::begin(kFlags), std::end(kFlags), [&](const Flag& f) { return a == f.name; }))
      return "unknown flag --" + a;
    values[a] = value;
  }
  std::string error;
  auto number = [&](const std::string& name, long long lo, long long hi) -> long long {
    const std::string& v = values[name];
    char* end = nullptr;
    const long long n = std::strtoll(v.c_str(), &end, 10);
    if (v.empty() || *end || n < lo || n > hi) {
      if (error.empty())
        error = "--" + name + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                ", got '" + v + "'";
      return lo;
    }
    return n;
  };
  for (const auto& [name, v] : values) {
    if (name == "host")
      host = v;
    else if (name == "port")
      port = static_cast<int>(number(name, 0, 65535));
    else if (name == "max-body-bytes")
      config.max_body_bytes = static_cast<std::size_t>(number(name, 1, 1ll << 32));
    else if (name == "max-width")
      config.limits.max_width = static_cast<int>(number(name, 1, raster::kMaxImageSide));
    else if (name == "max-height")
      config.limits.max_height = static_cast<int>(number(name, 1, raster::kMaxImageSide));
    else if (name == "max-pixels")
      config.limits.max_pixels = number(name, 1, 1ll << 28);
    else if (name == "max-primitives")
      config.limits.max_primitives = number(name, 1, 1ll << 31);
    else if (name == "max-obj-faces")
      config.limits.max_obj_faces = number(name, 1, 1ll << 31);
    else if (name == "max-json-depth")
      config.limits.max_json_depth = static_cast<int>(number(name, 2, 1000));
    else if (name == "render-deadline-ms")
      config.render_deadline = std::chrono::milliseconds(number(name, 1, 3'600'000));
    else if (name == "body-deadline-ms")
      config.body_deadline = std::chrono::milliseconds(number(name, 1, 3'600'000));
    else if (name == "workers")
      config.workers = static_cast<int>(number(name, 1, 1024));
    else if (name == "max-queue")
      config.max_queue = static_cast<int>(number(name, 1, 4096));
    else if (name == "max-queue-wait-ms")
      config.max_queue_wait = std::chrono::milliseconds(number(name, 0, 3'600'000));
    else if (name == "max-queued-bytes")
      config.max_queued_bytes = static_cast<std::size_t>(number(name, 0, 1ll << 40));
    else if (name == "cors-origins")
      config.cors_origins = parse_origins(v);
    else if (name == "render-threads")
      config.render_threads = static_cast<int>(number(name, 1, 1024));
    else if (name == "shutdown-grace-ms")
      config.shutdown_grace = std::chrono::milliseconds(number(name, 0, 3'600'000));
    else if (name == "memory-budget") {
      config.memory_budget = parse_size(v);
      if (config.memory_budget < (1 << 20) && error.empty())
        error = "--memory-budget must be a size of at least 1M (e.g. 1536M, 2G or bytes), got '" + v + "'";
    } else if (name == "log-format") {
      if (v != "text" && v != "json" && error.empty())
        error = "--log-format must be text or json, got '" + v + "'";
      config.log_json = v == "json";
    } else if (name == "cache-max-age")
      config.cache_max_age = static_cast<int>(number(name, 0, 31'536'000));
  }
  return error;
}

}  // namespace rasterd
