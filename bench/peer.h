// The llvmpipe peer's timings: `LP_NUM_THREADS=t osmesa_peer runs` (llvmpipe reads its thread count once
// per process), one "scene milliseconds" line per scene.
#pragma once

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

}  // namespace bench
