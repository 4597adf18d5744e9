// Peak memory of a render, measured from outside: `rasterd render scene.json -o /dev/null` in a child
// process, its peak resident set (getrusage after wait4) minus that of rendering a 1x1 empty scene (the
// binary, its libraries and the heap's start). Compared with issue 6's budget for a 2D 1024x1024 scene:
// 1.5 x the colour buffer + the request. Prints a Markdown table.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "raster/raster.h"
#include "scenes.h"
#include "timing.h"

namespace {

// Peak RSS in KiB of `rasterd render <scene> -o /dev/null`; exits on failure.
long peak_kib(const std::string& rasterd, const std::string& scene_path) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl(rasterd.c_str(), rasterd.c_str(), "render", scene_path.c_str(), "-o", "/dev/null",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "memory: %s render %s failed\n", rasterd.c_str(), scene_path.c_str());
    std::exit(1);
  }
  return usage.ru_maxrss;
}

long median_peak_kib(const std::string& rasterd, const std::string& path, int runs) {
  std::vector<double> peaks;
  for (int r = 0; r < runs; ++r) peaks.push_back(static_cast<double>(peak_kib(rasterd, path)));
  return static_cast<long>(bench::median(peaks));
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/rasterd-memory-" + std::to_string(getpid()) + "-" + name + ".json";
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace

// Usage: memory path/to/rasterd [runs]
int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: memory path/to/rasterd [runs]\n");
    return 2;
  }
  const std::string rasterd = argv[1];
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  const std::string empty = write_temp("empty", R"({"width":1,"height":1})");
  const long baseline = median_peak_kib(rasterd, empty, runs);
  std::remove(empty.c_str());

  std::printf(
      "| scene | request MB | colour buffer MB | peak above baseline MB | budget MB (1.5 x colour + request) "
      "| peak / budget | verdict |\n|---|---:|---:|---:|---:|---:|---|\n");
  for (const char* kind : {"small", "large", "grid"}) {
    const raster::Scene scene = bench::make_scene(kind, 1);
    const std::string text = bench::scene_json(scene);
    const std::string path = write_temp(kind, text);
    const long peak = median_peak_kib(rasterd, path, runs);
    std::remove(path.c_str());
    const double mb = 1024.0 * 1024.0;
    const double colour = static_cast<double>(raster::plan(scene).memory.color_bytes) / mb;
    const double request = static_cast<double>(text.size()) / mb;
    const double above = static_cast<double>(peak - baseline) / 1024.0;
    const double budget = 1.5 * colour + request;
    std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %s |\n", kind, request, colour, above, budget,
                above / budget, above <= budget ? "met" : "**gap**");
  }
  std::printf("\nBaseline (a 1x1 empty scene): %.1f MB resident.\n", baseline / 1024.0);
  return 0;
}
