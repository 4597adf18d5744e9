// The llvmpipe peer's timings: `LP_NUM_THREADS=t osmesa_peer runs` (llvmpipe reads its thread count once
// per process), one "scene milliseconds" line per scene.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <map>
#include <string>

namespace bench {

inline std::map<std::string, double> peer_ms(const std::string& peer, int threads, int runs) {
  std::map<std::string, double> out;
  const std::string command =
      "LP_NUM_THREADS=" + std::to_string(threads) + " " + peer + " " + std::to_string(runs);
  if (FILE* f = popen(command.c_str(), "r")) {
    char name[32];
    double ms = 0;
    while (std::fscanf(f, "%31s %lf", name, &ms) == 2) out[name] = ms;
    pclose(f);
  }
  return out;
}

/// What this program prints when it re-runs itself as `self --measure runs` in a child process: the VM runs
/// a whole process at one of two speeds, so each side of a ratio is measured in several processes and the
/// fastest taken (bench/core.cpp and bench/e2e.cpp parse their own lines). Empty when it cannot be run.
inline std::string measure_in_child(int runs) {
  std::string out;
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return out;
  self[n] = 0;
  const std::string command = std::string("'") + self + "' --measure " + std::to_string(runs);
  if (FILE* f = popen(command.c_str(), "r")) {
    char buf[4096];
    while (std::size_t got = std::fread(buf, 1, sizeof buf, f)) out.append(buf, got);
    pclose(f);
  }
  return out;
}

}  // namespace bench
