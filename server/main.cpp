// rasterd: `rasterd render scene.json -o out.png` (or a model, or a ShaderToy program) and `rasterd serve
// --port 8080`.
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>
#if __has_include(<malloc.h>)
#include <malloc.h>  // mallopt (glibc)
#endif

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "flags.h"
#include "healthcheck.h"
#include "raster/raster.h"
#include "request.h"
#include "resources.h"
#include "service.h"
#include "shader_request.h"

namespace {

constexpr const char* kUsage = R"(usage:
  rasterd render SCENE.json [-o OUT.png] [--explain]   render a scene file ('-' = stdin / stdout)
  rasterd render PROGRAM.glsl [-o OUT.png] [--width N] [--height N] [--time T] [--frame N]
                 [--mouse x,y,cx,cy] [--antialias 1|4|8|16|area|auto] [--explain]
                                                        a bare ShaderToy program (.glsl, .frag, .fs, or
                                                        text with a mainImage), 512x288 by default
  rasterd render MODEL [-o OUT.png] [--width N] [--height N] [--background C] [--view V]
                 [--projection P] [--fov DEG] [--eye x,y,z] [--target x,y,z] [--up x,y,z|+z]
                 [--antialias 1|4|8|16|area|auto] [--format F] [--scale S] [--part NAME=FILE]
                                                        a bare model (OBJ, STL, PLY, glTF) in the default
                                                        scene; the files it names (an OBJ's MTL and
                                                        textures, a glTF's buffers and images) are read
                                                        from its folder
  rasterd serve [--host H] [--port N]                   HTTP service (env PORT; default 8080; 0: any free)
  rasterd healthcheck [--pid N] [--host H] [--port N]   GET /healthz of the server PID N (default 1) at the
                                                        address it was given; exit code 0 when healthy
  rasterd --version                                     the release and the render version

render:  writes the PNG to OUT.png (default: stdout); --explain writes the render plan as JSON instead.
         A scene file sets everything itself: the model options are for a bare model only, and the
         program options for a bare program, whose compile errors are printed as FILE:LINE:COLUMN: message.
serve:   POST /render (scene JSON, a model, or multipart) -> image/png; GET /healthz; GET /metrics.
         `rasterd serve --help` lists the limits and their flags.
)";

int usage_error(const std::string& message) {
  std::cerr << "rasterd: " << message << "\n\n" << kUsage;
  return 2;
}

// The whole file (or stdin for "-"). A file's size is known up front, so its text takes one allocation of
// exactly that size: growing a string by doubling would hold up to twice the request at its peak.
bool read_all(const std::string& path, std::string& out) {
  std::ifstream file;
  std::istream* in = &std::cin;
  if (path != "-") {
    file.open(path, std::ios::binary | std::ios::ate);
    if (!file) return false;
    if (const std::streamoff size = file.tellg(); size > 0) out.reserve(static_cast<std::size_t>(size));
    file.seekg(0);
    in = &file;
  }
  char chunk[1 << 16];
  while (in->read(chunk, sizeof chunk) || in->gcount() > 0)
    out.append(chunk, static_cast<std::size_t>(in->gcount()));
  return !in->bad();
}

// Writes `size` bytes to the file `path` (stdout for "-"). The exit code: 0, or 1 when they cannot be.
int write_all(const std::string& path, const char* data, std::size_t size) {
  if (path == "-") {
    std::cout.write(data, static_cast<std::streamsize>(size));
    return std::cout.flush() ? 0 : 1;
  }
  std::ofstream out(path, std::ios::binary);
  out.write(data, static_cast<std::streamsize>(size));
  if (!out.flush()) {
    std::cerr << "rasterd: cannot write " << path << "\n";
    return 1;
  }
  return 0;
}

// The service's words for a query parameter are a flag's here: 'query parameter "width": ...' reads
// '--width: ...', and an unknown one is answered with the list of flags.
std::string as_flags(std::string message, bool program) {
  const std::string prefix = "query parameter \"";
  if (message.rfind(prefix, 0) == 0)
    if (const std::size_t end = message.find('"', prefix.size()); end != std::string::npos)
      message = "--" + message.substr(prefix.size(), end - prefix.size()) + message.substr(end + 1);
  if (const std::size_t at = message.find(": unknown; known: "); at != std::string::npos) {
    std::string flags;
    for (std::string_view name : program ? rasterd::program_param_names() : rasterd::model_param_names())
      flags.append(", --").append(name);
    message = message.substr(0, at) +
              (program ? ": not a flag of a program's render; its flags: -o, --explain"
                       : ": not a flag of render; its flags: -o, --explain, --part") +
              flags + (program ? "" : ", --scale");
  }
  return message;
}

std::string describe(const raster::SceneError& e, bool program) {
  std::string where;
  if (!e.where().pointer.empty()) where = " at " + e.where().pointer;
  if (e.where().byte) where += " (byte " + std::to_string(e.where().byte) + ")";
  if (e.where().line) where += " (line " + std::to_string(e.where().line) + ")";
  return as_flags(e.what(), program) + where;
}

// A model read from a file finds the files it names beside it, as model viewers do: an OBJ's MTL its mtllib
// lines name, then the textures that MTL names; a glTF's buffers and images; read from the model's folder by
// file name (what --part gave wins; a name that is not there is left to the parser to report). The service
// never does this: it has only what was uploaded.
void gather_model_files(const std::string& model_path, const std::string& model,
                        const raster::ModelFormatInfo& format, raster::Uploads& uploads) {
  const std::filesystem::path folder = std::filesystem::path(model_path).parent_path();
  const auto mtl = uploads.find("mtl");
  for (int round = 0; round < format.file_rounds; ++round)  // OBJ: the libraries, then the textures they name
    for (const std::string& name : format.files(model, mtl == uploads.end() ? "" : mtl->second, uploads)) {
      const std::filesystem::path file = folder / name;
      std::error_code error;
      if (uploads.contains(name) || !std::filesystem::is_regular_file(file, error))
        continue;  // not "..", not a folder
      std::string bytes;
      if (read_all(file.string(), bytes)) uploads.emplace(name, std::move(bytes));
    }
}

// What `rasterd render` was asked: the input, where the output goes, and the options.
struct RenderArgs {
  std::string input, output = "-";
  bool explain = false;
  rasterd::Params params;
  raster::Uploads uploads;
};

// The command line of `rasterd render`; returns the exit code of a usage error or failed read, else -1.
int parse_render_args(const std::vector<std::string>& args, RenderArgs& out) {
  std::vector<rasterd::PartName> parts;  // --part NAME=FILE, in order
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" && i + 1 < args.size()) {
      out.output = args[++i];
    } else if (a == "--explain") {
      out.explain = true;
    } else if (a == "--part" && i + 1 < args.size()) {  // NAME=FILE, as a multipart upload would carry it
      const std::string spec = args[++i];
      const std::size_t eq = spec.find('=');
      if (eq == std::string::npos) return usage_error("--part takes NAME=FILE");
      const std::string file = spec.substr(eq + 1);
      parts.push_back({spec.substr(0, eq), rasterd::upload_key(spec.substr(0, eq), file)});
      if (!read_all(file, out.uploads[parts.back().key])) {
        std::cerr << "rasterd: cannot read " << spec.substr(eq + 1) << ": " << std::strerror(errno) << "\n";
        return 1;
      }
    } else if (a.rfind("--", 0) == 0 && a.size() > 2) {
      // --width 800 -> width=800, --width=800 too (validated with the scene, as query parameters are)
      if (const std::size_t eq = a.find('='); eq != std::string::npos) {
        out.params[a.substr(2, eq - 2)] = a.substr(eq + 1);
      } else if (i + 1 < args.size()) {
        out.params[a.substr(2)] = args[++i];
      } else {
        return usage_error(
            a + " needs a value" +
            (a == "--background" ? " (a shell reads an unquoted '#' as a comment: '#ffffff')" : ""));
      }
    } else if (a == "-o") {
      return usage_error("-o needs a file name");
    } else if (out.input.empty()) {
      out.input = a;
    } else {
      return usage_error("unexpected argument '" + a + "'");
    }
  }
  rasterd::add_part_names(out.uploads, parts);
  if (out.input.empty()) return usage_error("render needs a scene file (or '-' for stdin)");
  return -1;
}

// Every compile error of a program as a compiler says it, one line each: `FILE:LINE:COLUMN: message` for
// a bare program; a scene's program is a string of the scene, so its errors name the primitive's source
// (`FILE: /primitives/0/source:LINE:COLUMN: message`). An error with no place in the program (ShaderToy's
// frame around it) has none.
void print_shader_errors(const std::string& input, bool program, const raster::SceneError& e) {
  const std::string file = program ? input : input + ": " + e.where().pointer;
  for (const raster::ErrorNote& n : e.notes()) {
    std::cerr << (program ? "" : "rasterd: ") << file;
    if (n.line) std::cerr << ":" << n.line << ":" << n.column;
    std::cerr << ": " << n.message << "\n";
  }
  if (e.notes().empty()) std::cerr << "rasterd: " << input << ": " << e.what() << "\n";
}

// The scene `args` asks for: a bare ShaderToy program (by its file name, or text that is no scene and
// holds mainImage), else what the service would make of the file as a request body (a scene or a model,
// whose files are gathered from its folder). Throws raster::SceneError.
raster::Scene read_scene(RenderArgs& args, std::string text, bool& program) {
  program = rasterd::is_shader_program(args.input == "-" ? "" : args.input, text);
  if (program) return rasterd::program_scene(std::move(text), args.params, raster::Limits{});
  // Sniffed once, here, as the readers take it (its byte order mark blanked), and the answer handed on. A
  // model's files are gathered (text that is no scene, or a glTF document): as an OBJ's when the bytes tell
  // no format (what is not OBJ text names none) or the file is empty (its model is a --part, if any).
  const rasterd::Sniffed sniffed = rasterd::sniff_request(text, args.uploads);
  if (args.input != "-" && (!rasterd::is_scene_text(text) || sniffed.format == raster::ModelFormat::gltf)) {
    const auto format =
        text.empty() ? raster::ModelFormat::obj : sniffed.format.value_or(raster::ModelFormat::obj);
    gather_model_files(args.input, text, raster::model_format(format), args.uploads);
  }
  return rasterd::scene_from_request(std::move(text), std::move(args.uploads), args.params, raster::Limits{},
                                     false, raster::format_of_file_name(args.input), sniffed);
}

int run_render(const std::vector<std::string>& argv) {
  RenderArgs args;
  if (const int code = parse_render_args(argv, args); code >= 0) return code;
  std::string text;
  if (!read_all(args.input, text)) {
    std::cerr << "rasterd: cannot read " << args.input << ": " << std::strerror(errno) << "\n";
    return 1;
  }
  bool program = false;
  try {
    raster::Scene scene = read_scene(args, std::move(text), program);
    const raster::RenderPlan plan = raster::plan(scene);
    // The plan or the PNG, written where -o says (the PNG is not copied: it can be tens of MB).
    std::string plan_text;
    std::vector<std::uint8_t> png;
    if (args.explain) {
      plan_text = raster::explain_json(plan) + "\n";
    } else {
      raster::Image image = raster::render(scene, plan);
      scene = {};  // as the server does: the scene's memory goes before the PNG's comes
      png = raster::encode_png(std::move(image), plan.png);
    }
    return args.explain ? write_all(args.output, plan_text.data(), plan_text.size())
                        : write_all(args.output, reinterpret_cast<const char*>(png.data()), png.size());
  } catch (const raster::SceneError& e) {
    if (e.kind() == raster::ErrorKind::shader) {
      print_shader_errors(args.input, program, e);
    } else if (program && e.kind() == raster::ErrorKind::program && e.where().line) {
      std::cerr << args.input << ":" << e.where().line << ": " << e.what() << "\n";
    } else {
      std::cerr << "rasterd: " << args.input << ": " << describe(e, program) << "\n";
    }
    return 1;
  }
}

// Set once when the server starts, before any request (not per request): glibc hands allocations above
// 128 KiB to the kernel as fresh mappings and returns freed heap to it, raising those bounds only as it
// happens to see large frees, so whether a request's image, PNG and model arrays land on pages the last
// request touched was luck. Minor faults per request of a warm server (field 10 of /proc/PID/stat, 5
// requests of each ab-bench scene after 3 uncounted), 2d-large-tris / 2d-lines / 2d-small-tris /
// obj-sphere-400k: 924 / 1,378 / 2,523 / 9,681 without this, 0 / 0 / 0 / 5-7 with it. The render's own
// large arrays are kept apart (renderer/src/base/memory.h).
// What freed memory the heap keeps is resident memory no reservation counts, so it is bounded too and set
// aside from the memory budget (server/resources.h): at most kArenas heaps (glibc would make 8 per core, one
// for each of the busiest connection threads), each keeping at most kTrimBytes free at its top, and
// allocations of kMmapBytes and more (request bodies) mapped apart, returned when freed.
void keep_freed_pages() {
#if defined(M_MMAP_THRESHOLD) && defined(M_TRIM_THRESHOLD) && defined(M_ARENA_MAX)
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(rasterd::kMmapBytes));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(rasterd::kTrimBytes));
  mallopt(M_ARENA_MAX, rasterd::kArenas);
#endif
}

// Tests only (tests/service_test.cpp): each admitted render first reads one byte from this FIFO, so a
// test holds renders in flight, sends a signal, and releases them when it chooses. Opened read-write so
// that opening never blocks and the FIFO stays open between the test's writes. In: RASTERD_TEST_RENDER_GATE
// (unset in service). Out: config.after_admission set; false with the error printed if it cannot be opened.
bool hold_renders_at_test_gate(rasterd::ServiceConfig& config) {
  const char* path = std::getenv("RASTERD_TEST_RENDER_GATE");
  if (!path) return true;
  const int gate = ::open(path, O_RDWR | O_CLOEXEC);
  if (gate < 0) {
    std::cerr << "rasterd: cannot open RASTERD_TEST_RENDER_GATE " << path << ": " << std::strerror(errno)
              << "\n";
    return false;
  }
  config.after_admission = [gate] {
    char byte;
    while (::read(gate, &byte, 1) < 0 && errno == EINTR) {
    }
  };
  return true;
}

// Serves on the bound `server` until one of `signals` (blocked in every thread) arrives, then stops: no new
// connections, accepted requests finish within the grace period, and renders still running after it are
// cancelled (they answer 503). Returns whether listening ended cleanly.
bool serve_until_signalled(httplib::Server& server, rasterd::Service& service, const sigset_t& signals) {
  std::mutex mutex;
  std::condition_variable done_cv;
  bool done = false;
  std::thread signal_thread([&] {
    int sig = 0;
    sigwait(&signals, &sig);
    std::unique_lock lock(mutex);
    if (done) return;  // listen ended by itself; this was the wake-up below
    std::cerr << "rasterd: signal " << sig << ": no new connections; finishing accepted requests (grace "
              << service.config().shutdown_grace.count() << " ms)\n";
    lock.unlock();
    server.stop();  // closes the listening socket; listen_after_bind returns once accepted work is done
    lock.lock();
    if (!done_cv.wait_for(lock, service.config().shutdown_grace, [&] { return done; })) {
      std::cerr << "rasterd: grace period over: stopping the renders still running\n";
      service.cancel_renders();
    }
  });
  const bool ok = server.listen_after_bind();
  {
    std::lock_guard lock(mutex);
    done = true;
  }
  done_cv.notify_all();
  pthread_kill(signal_thread.native_handle(), SIGTERM);  // wakes sigwait if no signal came
  signal_thread.join();
  return ok;
}

int run_serve(const std::vector<std::string>& args) {
  keep_freed_pages();
  std::string host = "0.0.0.0";
  int port = 8080;
  rasterd::ServiceConfig config;
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  if (const std::string error =
          rasterd::parse_service_flags(static_cast<int>(argv.size()), argv.data(), config, host, port);
      !error.empty()) {
    std::cerr << "rasterd: " << error << "\n\n" << rasterd::service_help();
    return 2;
  }

  // Signals are taken by a sigwait thread, not a handler: stopping the server is not async-signal-safe.
  // Blocked signals stay pending even for PID 1 of a container (the kernel drops only *ignored* ones for
  // init), so this works as Docker's PID 1 too: checked with `unshare --pid --fork` and kill -TERM.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);  // inherited by every thread started below
  if (!hold_renders_at_test_gate(config)) return 1;

  httplib::Server server;
  rasterd::Service service(config);
  service.install(server);
  // Port 0: any free port, which the "listening on" line then names (tests and scripts read it there:
  // choosing a free port first and binding it later races with every other process that binds one).
  if (port == 0 ? (port = server.bind_to_any_port(host)) <= 0 : !server.bind_to_port(host, port)) {
    std::cerr << "rasterd: cannot listen on " << host << ":" << port << ": " << std::strerror(errno) << "\n";
    return 1;
  }
  service.widen_backlog();
  std::cerr << "rasterd: listening on " << host << ":" << port << "\n"
            << "try:  curl --data-binary @examples/gradient.json localhost:" << port << "/render > out.png\n";
  const bool ok = serve_until_signalled(server, service, signals);
  std::cerr << "rasterd: stopped\n";
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && (args[0] == "--version" || args[0] == "version")) {
    std::cout << "rasterd " RASTERD_VERSION " (render " << raster::kRenderVersion << ")\n";
    return 0;
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  // --help or -h anywhere on a subcommand's line: its usage, and exit 0 (no flag takes them as a value).
  if (std::find_if(args.begin(), args.end(),
                   [](const std::string& a) { return a == "--help" || a == "-h"; }) != args.end()) {
    if (command == "serve") {
      std::cout << rasterd::service_help();
      return 0;
    }
    if (command == "render" || command == "healthcheck") {
      std::cout << kUsage;
      return 0;
    }
  }
  if (command == "render") return run_render(args);
  if (command == "healthcheck") return rasterd::run_healthcheck(args);
  if (command == "serve") return run_serve(args);
  return usage_error("unknown command '" + command + "'");
}
