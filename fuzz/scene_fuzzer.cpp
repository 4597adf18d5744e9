// libFuzzer target: scene text -> parse -> plan -> render -> PNG, with small caps so each input is fast.
// Any crash, sanitizer report, or exception other than SceneError is a finding; so is the streaming
// scene reader accepting a document the DOM reader rejects, or reading one differently (scene_json.h).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "raster/raster.h"
#include "scene_json.h"

namespace {

void check_readers_agree(std::string_view text, const raster::Limits& limits) {
  const std::optional<raster::Scene> fast = raster::scene_json::parse_scene_fast(text, limits, {});
  if (!fast) return;
  try {
    if (!(raster::scene_json::parse_scene_dom(text, limits, {}) == *fast)) std::abort();  // read differently
  } catch (const raster::SceneError&) {
    std::abort();  // accepted what the DOM reader rejects
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  raster::Limits limits;
  limits.max_width = 256;
  limits.max_height = 256;
  limits.max_pixels = 256 * 256;
  limits.max_primitives = 2000;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check_readers_agree(text, limits);
  try {
    const raster::Scene scene = raster::parse_scene(text, limits);
    raster::PlanOptions options;
    options.max_threads = 1;
    const raster::RenderPlan plan = raster::plan(scene, limits, options);
    const raster::Image image = raster::render(scene, plan);
    raster::encode_png(image, plan.png);
  } catch (const raster::SceneError& e) {
    // rejected input: the expected outcome for most of the corpus. Its message is echoed to clients, so
    // it must be UTF-8 whatever bytes the input held.
    if (raster::first_invalid_utf8(e.what()) != std::string_view::npos) std::abort();
  }
  return 0;
}
