// libFuzzer target: OBJ (+ MTL) text -> mesh -> render through the default camera -> PNG, on a small image.
// The input is the OBJ, optionally followed by a NUL byte and an MTL. The MTL is given as text on even
// lengths and as the uploaded file "a.mtl" (which `mtllib a.mtl` names) on odd ones, so the MTL reader,
// its map_Kd options and the library lookup are all reached; the uploads also hold a 2x2 PNG under "t.png"
// for map_Kd to find. Any crash, sanitizer report, or exception other than SceneError is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "raster/raster.h"

namespace {

std::string small_png() {
  raster::Image image;
  image.width = image.height = 2, image.format = raster::PixelFormat::rgba8;
  image.pixels = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 255, 255, 255, 0};
  const auto bytes = raster::encode_png(image);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string kPng = small_png();
  raster::Limits limits;
  limits.max_model_faces = 20000;
  limits.max_texture_pixels = 64;
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = input.find('\0');
  const std::string_view obj = input.substr(0, nul);
  const std::string_view mtl = nul == std::string_view::npos ? std::string_view() : input.substr(nul + 1);
  raster::Uploads files{{"t.png", kPng}};
  if (size % 2 == 1) files["a.mtl"] = std::string(mtl);
  try {
    raster::Scene scene;
    scene.width = 64;
    scene.height = 48;
    scene.meshes.push_back(raster::parse_obj(obj, size % 2 == 0 ? mtl : std::string_view(), limits, files));
    if (scene.meshes[0].colors.empty()) scene.meshes[0].colors = {raster::Rgba8{200, 180, 160, 255}};
    // Alternate shadings, wireframe and edges by input length so every path sees inputs.
    scene.meshes[0].shading = static_cast<raster::Shading>(size % 3);
    scene.meshes[0].wireframe = size % 7 == 0;
    scene.meshes[0].edges.enabled = size % 5 == 0;
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
