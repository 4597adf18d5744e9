// libFuzzer target: OBJ text -> mesh -> render through the default camera -> PNG, on a small image.
// Any crash, sanitizer report, or exception other than SceneError is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "raster/raster.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  raster::Limits limits;
  limits.max_obj_faces = 20000;
  try {
    raster::Scene scene;
    scene.width = 64;
    scene.height = 48;
    scene.meshes.push_back(
        raster::parse_obj(std::string_view(reinterpret_cast<const char*>(data), size), {}, limits));
    scene.meshes[0].colors = {raster::Rgba8{200, 180, 160, 255}};
    // Alternate shadings by input length so every path sees inputs.
    scene.meshes[0].shading = static_cast<raster::Shading>(size % 3);
    scene.meshes[0].wireframe = size % 7 == 0;
    raster::Primitive p;
    p.kind = raster::PrimitiveKind::mesh;
    scene.primitives.push_back(p);
    raster::PlanOptions options;
    options.max_threads = 1;
    const raster::RenderPlan plan = raster::plan(scene, limits, options);
    raster::encode_png(raster::render(scene, plan), plan.png);
  } catch (const raster::SceneError& e) {
    // rejected model: expected for most inputs; its message (echoed to clients) must be UTF-8
    if (raster::first_invalid_utf8(e.what()) != std::string_view::npos) std::abort();
  }
  return 0;
}
