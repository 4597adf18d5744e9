// End to end through the real binary: `rasterd render scene.json -o /dev/null` (process start, file read,
// parse, render, encode, write) and POST /render to `rasterd serve` over loopback (request upload,
// parse, render, encode, response download), wall-clock medians. Both use every core, so e2e compares
// them with llvmpipe at the same thread count.
#include "wall.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <httplib.h>

#include "timing.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace bench {
namespace {

pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);  // the server's log lines are not the bench's output
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  if (pid < 0) throw std::runtime_error("fork failed");
  return pid;
}

}  // namespace

WallTimes wall_times(const std::string& rasterd, const std::string& scene_json, int runs) {
  const std::string path = "/tmp/rasterd-wall-" + std::to_string(getpid()) + ".json";
  std::ofstream(path, std::ios::binary) << scene_json;
  WallTimes out;

  std::vector<double> cli;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    int status = 0;
    waitpid(spawn({rasterd, "render", path, "-o", "/dev/null"}), &status, 0);
    cli.push_back(ms_since(t0));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw std::runtime_error("rasterd render failed");
  }
  out.cli_ms = median(cli);
  std::remove(path.c_str());

  const int port = 20000 + static_cast<int>(getpid() % 20000);
  const pid_t server = spawn({rasterd, "serve", "--host", "127.0.0.1", "--port", std::to_string(port)});
  httplib::Client client("127.0.0.1", port);
  client.set_read_timeout(30, 0);
  for (int tries = 0; !client.Get("/healthz") && tries < 200; ++tries)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  std::vector<double> http;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = client.Post("/render", scene_json, "application/json");
    http.push_back(ms_since(t0));
    if (!res || res->status != 200) {
      kill(server, SIGKILL);
      waitpid(server, nullptr, 0);
      throw std::runtime_error("POST /render failed");
    }
    out.png_bytes = res->body.size();
  }
  out.http_ms = median(http);
  kill(server, SIGTERM);
  waitpid(server, nullptr, 0);
  return out;
}

ServerTimes server_times(const std::string& rasterd, const std::string& body, const std::string& query,
                         int runs, const std::string& content_type, int warm_up) {
  const int port = 20000 + static_cast<int>((getpid() + 1) % 20000);
  const pid_t server = spawn({rasterd, "serve", "--host", "127.0.0.1", "--port", std::to_string(port),
                              "--max-body-bytes", "268435456", "--render-deadline-ms", "120000"});
  httplib::Client client("127.0.0.1", port);
  client.set_read_timeout(120, 0);
  for (int tries = 0; !client.Get("/healthz") && tries < 200; ++tries)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  std::vector<double> stage[3], wall;
  // Warm-up requests are not counted: a fresh server settles (kept blocks, malloc thresholds) in ~4.
  for (int r = 0; r < warm_up + runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = client.Post("/render?" + query, body, content_type);
    if (r >= warm_up) wall.push_back(ms_since(t0));
    if (!res || res->status != 200) {
      kill(server, SIGKILL);
      waitpid(server, nullptr, 0);
      throw std::runtime_error("POST /render failed");
    }
    const std::string timing = res->get_header_value("Server-Timing");
    const char* names[3] = {"parse;dur=", "raster;dur=", "encode;dur="};
    for (int k = 0; k < 3 && r >= warm_up; ++k)
      if (const auto at = timing.find(names[k]); at != std::string::npos)
        stage[k].push_back(std::stod(timing.substr(at + std::char_traits<char>::length(names[k]))));
  }
  kill(server, SIGTERM);
  waitpid(server, nullptr, 0);
  return {median(stage[0]),
          median(stage[1]),
          median(stage[2]),
          stage[1].empty() ? 0 : stage[1][0],
          stage[2].empty() ? 0 : stage[2][0],
          median(wall)};
}

}  // namespace bench
