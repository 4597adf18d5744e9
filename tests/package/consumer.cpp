// scene.json -> out.png through the installed library: `consumer scene.json out.png`.
#include <fstream>
#include <sstream>

#include "raster/raster.h"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  std::stringstream text;
  text << std::ifstream(argv[1], std::ios::binary).rdbuf();
  const raster::Scene scene = raster::parse_scene(text.str());
  const raster::RenderPlan plan = raster::plan(scene);
  const std::vector<std::uint8_t> png = raster::encode_png(raster::render(scene, plan), plan.png);
  std::ofstream(argv[2], std::ios::binary).write(reinterpret_cast<const char*>(png.data()), png.size());
}
