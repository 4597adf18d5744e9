// libFuzzer target for one model reader (MODEL_FORMAT: stl, ply, gltf or 3mf; built once per reader): bytes
// -> mesh -> render through the default camera -> PNG, on a small image. For glTF the input may hold a NUL
// byte: what follows it is the uploaded file "b.bin", which a document's buffer URI can name, and the
// uploads hold a 2x2 PNG as "t.png" for an image URI. Any crash, sanitizer report, hang, or exception other
// than SceneError is a finding.
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

raster::Mesh read(std::string_view input, const raster::Limits& limits, const raster::Uploads& files) {
#if defined(MODEL_STL)
  (void)files;
  return raster::parse_stl(input, limits);
#elif defined(MODEL_PLY)
  (void)files;
  return raster::parse_ply(input, limits);
#elif defined(MODEL_3MF)
  (void)files;
  return raster::parse_3mf(input, limits);
#else
  return raster::parse_gltf(input, limits, files);
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string kPng = small_png();
  raster::Limits limits;
  limits.max_model_faces = 20000;
  limits.max_texture_pixels = 64;
  std::string_view input(reinterpret_cast<const char*>(data), size);
  raster::Uploads files{{"t.png", kPng}};
#if !defined(MODEL_STL) && !defined(MODEL_PLY) && !defined(MODEL_3MF)
  if (const std::size_t nul = input.rfind('\0');
      nul != std::string_view::npos && !input.starts_with("glTF")) {
    files["b.bin"] = std::string(input.substr(nul + 1));
    input = input.substr(0, nul);
  }
#endif
  try {
    raster::Scene scene;
    scene.width = 64;
    scene.height = 48;
    scene.meshes.push_back(read(input, limits, files));
    if (scene.meshes[0].colors.empty()) scene.meshes[0].colors = {raster::Rgba8{200, 180, 160, 255}};
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
