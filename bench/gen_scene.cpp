// Writes a seeded benchmark scene as JSON: gen_scene KIND [SEED] > scene.json
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "scenes.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: gen_scene small|large|grid|mid [seed]\n");
    return 2;
  }
  try {
    const std::string json = bench::scene_json(
        bench::make_scene(argv[1], argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 1));
    std::fwrite(json.data(), 1, json.size(), stdout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gen_scene: %s\n", e.what());
    return 2;
  }
}
