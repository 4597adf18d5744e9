#include "metrics.h"

#include <dirent.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "raster/raster.h"

namespace rasterd {
namespace {

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// One metric with its HELP and TYPE lines.
std::string gauge(const std::string& name, const std::string& help, const std::string& type, double value,
                  const std::string& labels = "") {
  char number[40];  // bytes and seconds since 1970 need all their digits
  std::snprintf(number, sizeof number, "%.15g", value);
  return "# HELP " + name + " " + help + "\n# TYPE " + name + " " + type + "\n" + name + labels + " " +
         number + "\n";
}

// Fields of /proc/self/stat after the command's closing ')': state is field 3; utime 14, stime 15,
// starttime 22, vsize 23, rss 24 (man 5 proc). Field n is at [n - 3].
std::vector<std::string> self_stat_fields() {
  std::ifstream stat_file("/proc/self/stat");
  std::string stat((std::istreambuf_iterator<char>(stat_file)), std::istreambuf_iterator<char>());
  std::vector<std::string> f;
  if (const auto close = stat.rfind(')'); close != std::string::npos) {
    std::istringstream in(stat.substr(close + 2));
    for (std::string w; in >> w;) f.push_back(w);
  }
  return f;
}

double boot_time() {  // seconds since 1970 at boot: /proc/stat's btime
  double boot = 0;
  std::ifstream kernel("/proc/stat");
  for (std::string key; kernel >> key;)
    if (key == "btime") {
      kernel >> boot;
      break;
    }
  return boot;
}

int open_fds() {
  int fds = 0;
  if (DIR* d = ::opendir("/proc/self/fd")) {
    while (const dirent* e = ::readdir(d)) fds += e->d_name[0] != '.';
    ::closedir(d);
    --fds;  // the one opendir holds
  }
  return fds;
}

// The process_* metrics every Prometheus client library exports, from /proc/self: what an operator alerts on
// before the kernel's OOM killer acts (resident memory against the container's limit), and CPU, fds and
// start time for dashboards.
std::string process_metrics() {
  std::string t;
  const double tick = static_cast<double>(::sysconf(_SC_CLK_TCK));
  const double page = static_cast<double>(::sysconf(_SC_PAGESIZE));
  const std::vector<std::string> f = self_stat_fields();
  auto field = [&](std::size_t n) { return n - 3 < f.size() ? std::strtod(f[n - 3].c_str(), nullptr) : 0.0; };
  const double boot = boot_time();
  const int fds = open_fds();
  rlimit nofile{};
  ::getrlimit(RLIMIT_NOFILE, &nofile);
  t += gauge("process_cpu_seconds_total", "User and system CPU time spent in seconds.", "counter",
             (field(14) + field(15)) / tick);
  t += gauge("process_resident_memory_bytes", "Resident memory size in bytes.", "gauge", field(24) * page);
  t += gauge("process_virtual_memory_bytes", "Virtual memory size in bytes.", "gauge", field(23));
  t += gauge("process_start_time_seconds", "Start time of the process since unix epoch in seconds.", "gauge",
             boot + field(22) / tick);
  t += gauge("process_open_fds", "Number of open file descriptors.", "gauge", fds);
  t += gauge("process_max_fds", "Maximum number of open file descriptors.", "gauge",
             static_cast<double>(nofile.rlim_cur));
  return t;
}

}  // namespace

void Metrics::request(const std::string& route, int status, std::size_t in, std::size_t out) {
  std::lock_guard lock(mutex_);
  ++requests_[{route, status}];
  bytes_in_ += in, bytes_out_ += out;
}

void Metrics::render(double ms) {
  std::lock_guard lock(mutex_);
  for (std::size_t i = 0; i < kBucketsMs.size(); ++i) buckets_[i] += ms <= kBucketsMs[i];
  ++render_count_, render_sum_ms_ += ms;
}

void Metrics::rejected(const std::string& reason) {
  std::lock_guard lock(mutex_);
  ++rejected_[reason];
}

std::string Metrics::text(int in_flight, int queued) {
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

// The compiled-program cache: how often a request found its program compiled, and what the cache holds.
std::string shader_cache_metrics(const raster::ShaderCache& cache) {
  return gauge("rasterd_shader_cache_hits_total",
               "Shader programs found compiled in the cache (--shader-cache-bytes).", "counter",
               static_cast<double>(cache.hits())) +
         gauge("rasterd_shader_cache_misses_total",
               "Shader programs compiled because the cache did not hold them.", "counter",
               static_cast<double>(cache.misses())) +
         gauge("rasterd_shader_cache_bytes", "Bytes of compiled shader programs the cache holds now.",
               "gauge", static_cast<double>(cache.bytes()));
}

std::string metrics_page(Metrics& metrics, int in_flight, int queued, const MemoryPool& memory,
                         const raster::ShaderCache* shader_cache) {
  std::string text = metrics.text(in_flight, queued);
  text += gauge("rasterd_memory_budget_bytes", "Bytes requests may reserve at once (--memory-budget).",
                "gauge", static_cast<double>(memory.capacity()));
  text += gauge("rasterd_memory_reserved_bytes",
                "Bytes reserved now by requests: bodies, parsed scenes and models, render buffers.", "gauge",
                static_cast<double>(memory.reserved()));
  text += gauge("rasterd_memory_reserved_peak_bytes", "Most bytes reserved at once since start.", "gauge",
                static_cast<double>(memory.peak()));
  if (shader_cache) text += shader_cache_metrics(*shader_cache);
  text += gauge(
      "rasterd_build_info", "The release and render version of this binary.", "gauge", 1,
      "{version=\"" RASTERD_VERSION "\",render_version=\"" + std::to_string(raster::kRenderVersion) + "\"}");
  text += process_metrics();
  return text;
}

bool refuse(Metrics& metrics, httplib::Response& res, const Problem& p, const std::string& reason) {
  metrics.rejected(reason);
  write_problem(res, p);
  return false;
}

}  // namespace rasterd
