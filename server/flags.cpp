#include "flags.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <vector>

#include "memory_budget.h"
#include "raster/raster.h"
#include "resources.h"

namespace rasterd {

namespace {

struct Flag {
  const char* name;  // --name, and RASTERD_NAME (upper case, '-' as '_') in the environment
  const char* help;
};
constexpr Flag kFlags[] = {
    {"host", "address to listen on (default 0.0.0.0)"},
    {"port", "port (default 8080; also PORT); 0 = any free port, named in the \"listening on\" line"},
    {"max-body-bytes", "request body limit, 413 above (default 268435456 = 256 MiB)"},
    {"max-width", "image width limit, 422 above (default 8192)"},
    {"max-height", "image height limit, 422 above (default 8192)"},
    {"max-pixels", "width x height limit, 422 above (default 40000000)"},
    {"max-primitives", "primitives (and mesh triangles) limit, 422 above (default 2000000)"},
    {"max-model-faces",
     "faces of one model (OBJ faces; STL, PLY and glTF triangles), 422 above (default 5000000; "
     "--max-obj-faces is its old name)"},
    {"max-model-points",
     "points of one model (a point cloud's vertices, OBJ 'p' vertices, glTF POINTS), 422 above (default "
     "5000000)"},
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
    {"render-threads", "most threads one render draws its tiles on (default: the CPUs the process may use)"},
    {"shutdown-grace-ms", "after SIGTERM/SIGINT, time for running and queued renders (default 20000)"},
    {"cache-max-age",
     "seconds in Cache-Control: public, max-age=N, immutable on GET /render (default 86400)"},
    {"shader-cache-bytes",
     "compiled shader programs kept between requests, by source (default 67108864 = 64 MiB; 0 = none); set "
     "aside from the default memory budget"},
    {"shader-max-source-bytes", "a shader program's text, 400 invalid-shader above (default 65536)"},
    {"shader-max-tokens",
     "a program's tokens after preprocessing, every macro expansion counted, 400 above (default 262144)"},
    {"shader-max-nesting",
     "brackets, operators, statements and #if blocks inside each other, 400 above (default 200)"},
    {"shader-max-instructions",
     "a program's operations once every function is inlined, 400 above (default 1048576)"},
    {"shader-max-slots",
     "32-bit values a program holds for a pixel at once (arrays included), 400 above (default 16384)"},
    {"shader-max-loop-iterations",
     "loop iterations a pixel (a sample) may take, every loop together, 422 shader-limit past it (default "
     "65536)"},
};

// The flags that take a whole number: its range, and where it goes.
struct NumberFlag {
  const char* name;
  long long lo, hi;
  void (*set)(ServiceConfig&, long long);
};
constexpr NumberFlag kNumberFlags[] = {
    {"max-body-bytes", 1, 1ll << 32,
     [](ServiceConfig& c, long long n) { c.max_body_bytes = std::size_t(n); }},
    {"max-width", 1, raster::kMaxImageSide,
     [](ServiceConfig& c, long long n) { c.limits.max_width = int(n); }},
    {"max-height", 1, raster::kMaxImageSide,
     [](ServiceConfig& c, long long n) { c.limits.max_height = int(n); }},
    {"max-pixels", 1, 1ll << 28, [](ServiceConfig& c, long long n) { c.limits.max_pixels = n; }},
    {"max-primitives", 1, 1ll << 31, [](ServiceConfig& c, long long n) { c.limits.max_primitives = n; }},
    {"max-model-faces", 1, 1ll << 31, [](ServiceConfig& c, long long n) { c.limits.max_model_faces = n; }},
    {"max-model-points", 1, 1ll << 31, [](ServiceConfig& c, long long n) { c.limits.max_model_points = n; }},
    {"max-json-depth", 2, 1000, [](ServiceConfig& c, long long n) { c.limits.max_json_depth = int(n); }},
    {"render-deadline-ms", 1, 3'600'000,
     [](ServiceConfig& c, long long n) { c.render_deadline = std::chrono::milliseconds(n); }},
    {"body-deadline-ms", 1, 3'600'000,
     [](ServiceConfig& c, long long n) { c.body_deadline = std::chrono::milliseconds(n); }},
    {"workers", 1, 1024, [](ServiceConfig& c, long long n) { c.workers = int(n); }},
    {"max-queue", 1, 4096, [](ServiceConfig& c, long long n) { c.max_queue = int(n); }},
    {"max-queue-wait-ms", 0, 3'600'000,
     [](ServiceConfig& c, long long n) { c.max_queue_wait = std::chrono::milliseconds(n); }},
    {"max-queued-bytes", 0, 1ll << 40,
     [](ServiceConfig& c, long long n) { c.max_queued_bytes = std::size_t(n); }},
    {"render-threads", 1, 1024, [](ServiceConfig& c, long long n) { c.render_threads = int(n); }},
    {"shutdown-grace-ms", 0, 3'600'000,
     [](ServiceConfig& c, long long n) { c.shutdown_grace = std::chrono::milliseconds(n); }},
    {"cache-max-age", 0, 31'536'000, [](ServiceConfig& c, long long n) { c.cache_max_age = int(n); }},
    {"shader-cache-bytes", 0, 1ll << 40,
     [](ServiceConfig& c, long long n) { c.shader_cache_bytes = std::size_t(n); }},
    {"shader-max-source-bytes", 1, 1ll << 26,
     [](ServiceConfig& c, long long n) { c.limits.shader.max_source_bytes = std::size_t(n); }},
    {"shader-max-tokens", 1, 1ll << 26,
     [](ServiceConfig& c, long long n) { c.limits.shader.max_tokens = std::size_t(n); }},
    // The parser recurses once a level: a bound the connection threads' stacks hold.
    {"shader-max-nesting", 1, 1000,
     [](ServiceConfig& c, long long n) { c.limits.shader.max_nesting = int(n); }},
    {"shader-max-instructions", 1, 1ll << 26,
     [](ServiceConfig& c, long long n) { c.limits.shader.max_instructions = std::size_t(n); }},
    {"shader-max-slots", 1, 1ll << 20,
     [](ServiceConfig& c, long long n) { c.limits.shader.max_slots = std::size_t(n); }},
    {"shader-max-loop-iterations", 1, 1ll << 40,
     [](ServiceConfig& c, long long n) { c.limits.shader.max_loop_iterations = n; }},
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

// The value of each flag given, by flag name: the environment's, then the arguments' over them. Returns an
// error message for an argument that is not a known flag with a value, else empty.
std::string collect_flag_values(int argc, const char* const* argv,
                                std::map<std::string, std::string>& values) {
  // A flag's old name, from when it bounded only OBJ models, still sets it (deployments name it).
  auto current = [](std::string name) {
    return name == "max-obj-faces" ? std::string("max-model-faces") : name;
  };
  if (const char* v = std::getenv(env_name("max-obj-faces").c_str())) values["max-model-faces"] = v;
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
    a = current(a);
    if (std::none_of(std::begin(kFlags), std::end(kFlags), [&](const Flag& f) { return a == f.name; }))
      return "unknown flag --" + a;
    values[a] = value;
  }
  return {};
}

// Sets what each flag names from `values` (flag name -> text). Returns the first error, else empty.
std::string apply_flag_values(std::map<std::string, std::string>& values, ServiceConfig& config,
                              std::string& host, int& port) {
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
    const auto numeric = std::find_if(std::begin(kNumberFlags), std::end(kNumberFlags),
                                      [&](const NumberFlag& f) { return name == f.name; });
    if (numeric != std::end(kNumberFlags)) {
      numeric->set(config, number(name, numeric->lo, numeric->hi));
    } else if (name == "host") {
      host = v;
    } else if (name == "port") {
      port = static_cast<int>(number(name, 0, 65535));
    } else if (name == "cors-origins") {
      config.cors_origins = parse_origins(v);
    } else if (name == "memory-budget") {
      config.memory_budget = parse_size(v);
      if (config.memory_budget < (1 << 20) && error.empty())
        error = "--memory-budget must be a size of at least 1M (e.g. 1536M, 2G or bytes), got '" + v + "'";
    } else if (name == "log-format") {
      if (v != "text" && v != "json" && error.empty())
        error = "--log-format must be text or json, got '" + v + "'";
      config.log_json = v == "json";
    }
  }
  return error;
}

}  // namespace

std::string service_help() {
  std::string h =
      "rasterd serve [--flag value ...]\n\nEach flag can also be set in the environment as RASTERD_<FLAG> "
      "(e.g. RASTERD_MAX_BODY_BYTES);\nflags win over the environment.\n\n";
  for (const Flag& f : kFlags) {
    char line[320];
    std::snprintf(line, sizeof line, "  --%-26s %s\n", f.name, f.help);
    h += line;
  }
  return h;
}

std::string parse_service_flags(int argc, const char* const* argv, ServiceConfig& config, std::string& host,
                                int& port) {
  std::map<std::string, std::string> values;
  if (std::string error = collect_flag_values(argc, argv, values); !error.empty()) return error;
  return apply_flag_values(values, config, host, port);
}

}  // namespace rasterd
