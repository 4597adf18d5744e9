// Explain: RenderPlan -> the words a caller reads about it (the JSON document of --explain and ?explain=1,
// and the one-line X-Render-Plan header), shader programs' sizes included. Says what the plan decided;
// decides nothing.
#include <string>

#include <nlohmann/json.hpp>

#include "raster/plan.h"

namespace raster {
namespace {

const char* format_name(PixelFormat f) {
  switch (f) {
    case PixelFormat::grey8:
      return "grey8";
    case PixelFormat::grey_alpha8:
      return "grey_alpha8";
    case PixelFormat::rgb8:
      return "rgb8";
    case PixelFormat::rgba8:
      return "rgba8";
  }
  return "?";
}

// One shader draw: where it runs and what its program costs. Instructions run for every 8x8 block (each
// over 64 pixels at once), the prologue's once a render; a thread holds `slots` 32-bit values for each of a
// block's 64 pixels (`register_bytes`); `channels` lists the iChannels it samples.
nlohmann::ordered_json shader_json(const ShaderPlan& s) {
  const CompiledShader& c = *s.shader;
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (int k = 0; k < 4; ++k)
    if (c.channels_read() >> k & 1) channels.push_back(k);
  nlohmann::ordered_json j;
  j["primitive"] = s.primitive;
  j["rect"] = {s.x0, s.y0, s.x1 - s.x0, s.y1 - s.y0};
  j["instructions"] = c.instructions();
  j["prologue_instructions"] = c.prologue_instructions();
  j["slots"] = c.slots();
  j["register_bytes"] = s.register_bytes;
  j["loops"] = c.loops();
  j["max_loop_iterations"] = s.max_iterations;
  j["derivatives"] = c.derivatives();
  j["channels"] = channels;
  j["program_bytes"] = c.bytes();
  j["opaque"] = s.opaque;
  j["samples"] = s.samples;
  return j;
}

}  // namespace

std::string explain_json(const RenderPlan& p) {
  nlohmann::ordered_json j;
  j["width"] = p.width;
  j["height"] = p.height;
  j["format"] = format_name(p.format);
  j["channels"] = channel_count(p.format);
  j["depth_buffer"] = p.depth_buffer;
  j["samples"] = p.samples;
  j["simd"] = p.simd == Simd::avx2 ? "avx2" : "sse2";
  j["tiles_in_place"] = p.tiles_in_place;
  j["antialias"] = p.coverage == Coverage::area           ? "area"
                   : p.coverage == Coverage::samples      ? "multisample"
                   : p.coverage == Coverage::edge_samples ? "auto"
                                                          : "none";
  j["primitives"] = {
      {"flat", p.flat_count},     {"smooth", p.smooth_count},     {"blend", p.blend_count},
      {"culled", p.culled_count}, {"lit", p.lit_count},           {"triangles_3d", p.triangles_3d},
      {"points_3d", p.points_3d}, {"textured", p.textured_count}, {"shaders", p.shader_count}};
  if (p.depth_buffer) {
    const ViewPlan& v = p.view;
    j["camera"] = {{"projection", v.projection == Projection::perspective ? "perspective" : "orthographic"},
                   {"eye", {v.eye.x, v.eye.y, v.eye.z}},
                   {"target", {v.target.x, v.target.y, v.target.z}},
                   {"up", {v.up.x, v.up.y, v.up.z}},
                   {"fov", v.fov_deg},
                   {"near", v.near},
                   {"far", v.far},
                   {"height", v.height}};
  }
  if (p.lit_count > 0) {  // in world space, as resolved for this view
    nlohmann::ordered_json lights = nlohmann::ordered_json::array();
    for (const LightPlan& l : p.view.lights) {
      nlohmann::ordered_json o;
      o["type"] = l.kind == LightKind::ambient ? "ambient"
                  : l.kind == LightKind::point ? "point"
                                               : "directional";
      if (l.kind == LightKind::directional) o["toward_light"] = {l.to_light.x, l.to_light.y, l.to_light.z};
      if (l.kind == LightKind::point) o["position"] = {l.position.x, l.position.y, l.position.z};
      o["rgb"] = {l.rgb[0], l.rgb[1], l.rgb[2]};
      lights.push_back(o);
    }
    j["lights"] = lights;
  }
  if (!p.shaders.empty()) {
    nlohmann::ordered_json shaders = nlohmann::ordered_json::array();
    for (const ShaderPlan& s : p.shaders) shaders.push_back(shader_json(s));
    j["shaders"] = shaders;
  }
  j["work"] = p.work;
  j["threads"] = p.threads;
  j["tile"] = p.tile;
  j["memory_bytes"] = {{"color", p.memory.color_bytes},
                       {"depth", p.memory.depth_bytes},
                       {"samples", p.memory.sample_bytes},
                       {"tiles", p.memory.tile_bytes},
                       {"coverage", p.memory.coverage_bytes},
                       {"textures", p.memory.texture_bytes},
                       {"edges", p.memory.edge_bytes},
                       {"shaders", p.memory.shader_bytes},
                       {"total", p.memory.total()}};
  j["png"] = {{"color_type", p.png.color_type}, {"deflate_level", p.png.deflate_level}};
  return j.dump(2);
}

std::string explain_line(const RenderPlan& p) {
  return std::string(format_name(p.format)) + " depth=" + (p.depth_buffer ? "f32" : "none") + " samples=" +
         (p.coverage == Coverage::area           ? std::string("area")
          : p.coverage == Coverage::edge_samples ? "auto" + std::to_string(p.samples)
                                                 : std::to_string(p.samples)) +
         " flat=" + std::to_string(p.flat_count) + " smooth=" + std::to_string(p.smooth_count) +
         " blend=" + std::to_string(p.blend_count) + " culled=" + std::to_string(p.culled_count) +
         (p.lit_count ? " lit=" + std::to_string(p.lit_count) : "") +
         (p.shader_count ? " shaders=" + std::to_string(p.shader_count) : "") +
         " threads=" + std::to_string(p.threads);
}

}  // namespace raster
