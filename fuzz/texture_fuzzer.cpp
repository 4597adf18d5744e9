// libFuzzer target: the texture path. Bytes -> decode_texture (header size check, stb_image PNG/JPEG) ->
// a textured quad seen in perspective (mipmaps built, trilinear sampling, repeat or clamp by input length)
// -> PNG, on a small image. Any crash, sanitizer report, an image larger than the budget it was given, or
// an exception other than SceneError is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "raster/raster.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr std::int64_t kBudget = 512 * 512;  // texels: keeps each run fast; the check is the same at 4096^2
  try {
    raster::Texture texture = raster::decode_texture(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.png", kBudget);
    if (texture.width < 1 || texture.height < 1 ||
        static_cast<std::int64_t>(texture.width) * texture.height > kBudget ||
        texture.rgba.size() != static_cast<std::size_t>(texture.width) * texture.height * 4)
      std::abort();
    texture.clamp = size % 2 == 0;
    raster::Scene scene;
    scene.width = 40;
    scene.height = 30;
    scene.antialias = size % 3 == 0 ? raster::Antialias::msaa4 : raster::Antialias::none;
    raster::Mesh quad;
    quad.positions = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -20}, {-1, 0, -20}};  // a floor receding: every mip level
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.uvs = {{0, 0}, {3, 0}, {3, 40}, {0, 40}};
    quad.uv_triangles = quad.triangles;
    quad.colors = {raster::Rgba8{255, 255, 255, 255}};
    quad.textures.push_back(std::move(texture));
    scene.meshes.push_back(std::move(quad));
    scene.camera.eye = {0, 1, 2}, scene.camera.has_eye = true;
    scene.camera.target = {0, 0, -3}, scene.camera.has_target = true;
    raster::Primitive p;
    p.kind = raster::PrimitiveKind::mesh;
    scene.primitives.push_back(p);
    raster::PlanOptions options;
    options.max_threads = 1;
    const raster::RenderPlan plan = raster::plan(scene, {}, options);
    raster::encode_png(raster::render(scene, plan), plan.png);
  } catch (const raster::SceneError& e) {
    // rejected image: expected for most inputs; its message (echoed to clients) must be UTF-8
    if (raster::first_invalid_utf8(e.what()) != std::string_view::npos) std::abort();
  }
  return 0;
}
