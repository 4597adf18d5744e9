// libFuzzer target: scene text -> parse -> plan -> render -> PNG, with small caps so each input is fast.
// Any crash, sanitizer report, or exception other than SceneError is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "raster/raster.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  raster::Limits limits;
  limits.max_width = 256;
  limits.max_height = 256;
  limits.max_pixels = 256 * 256;
  limits.max_primitives = 2000;
  try {
    const raster::Scene scene =
        raster::parse_scene(std::string_view(reinterpret_cast<const char*>(data), size), limits);
    raster::PlanOptions options;
    options.max_threads = 1;
    const raster::RenderPlan plan = raster::plan(scene, limits, options);
    const raster::Image image = raster::render(scene, plan);
    raster::encode_png(image, plan.png);
  } catch (const raster::SceneError&) {
    // rejected input: the expected outcome for most of the corpus
  }
  return 0;
}
