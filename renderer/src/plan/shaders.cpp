#include "plan/shaders.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "base/mip_chain.h"
#include "shader/ir.h"

namespace raster::detail {
namespace {

std::string pointer(std::uint32_t index, std::string_view field = {}) {
  return std::string("/primitives/") + std::to_string(index) +
         (field.empty() ? "" : std::string("/") + std::string(field));
}

// The program, or a SceneError(shader) with every compile error: the first's place, and all of them.
std::shared_ptr<const CompiledShader> compile(const ShaderPrimitive& s, std::uint32_t index,
                                              const Limits& limits, ShaderCache* cache) {
  ShaderCompileResult r =
      cache ? cache->get(s.source, limits.shader) : compile_shadertoy(s.source, limits.shader);
  if (r.shader) return r.shader;
  std::vector<ErrorNote> notes;
  for (const ShaderMessage& m : r.errors)
    notes.push_back({static_cast<std::size_t>(m.string == 1 ? m.line : 0),
                     static_cast<std::size_t>(m.string == 1 ? m.column : 0),
                     (m.string == 1 ? "" : "(in ShaderToy's frame around the program) ") + m.text});
  const ShaderMessage& first = r.errors.front();
  std::string message = "the program does not compile: ";
  if (first.string == 1)
    message += std::to_string(first.line) + std::string(":") + std::to_string(first.column) + ": ";
  message += notes.front().message;
  const std::size_t more = r.errors.size() - 1 + r.more_errors;
  if (more > 0)
    message += std::string(" (and ") + std::to_string(more) + std::string(" more error") +
               (more == 1 ? "" : "s") + ")";
  const ErrorLocation where{pointer(index, "source"), 0, notes.front().line, notes.front().column};
  throw SceneError(ErrorKind::shader, message, where, std::move(notes));
}

std::uint32_t float_bits(double v) {
  return std::bit_cast<std::uint32_t>(static_cast<float>(v));
}

// ShaderToy's own uniform `name`'s slots, from the primitive and its rectangle; false for any other name.
bool shadertoy_value(const ShaderPrimitive& s, const ShaderPlan& p, std::string_view name,
                     std::vector<std::uint32_t>& bits) {
  const auto f = [&](std::initializer_list<double> values) {
    for (const double v : values) bits.push_back(float_bits(v));
    return true;
  };
  if (name == "iResolution") return f({double(p.rect_width), double(p.rect_height), 1.0});
  if (name == "iTime") return f({s.time});
  if (name == "iTimeDelta") return f({1.0 / 60.0});
  if (name == "iFrameRate") return f({60.0});
  if (name == "iFrame") return bits.push_back(static_cast<std::uint32_t>(s.frame)), true;
  if (name == "iMouse") return f({s.mouse[0], s.mouse[1], s.mouse[2], s.mouse[3]});
  if (name == "iDate") return f({s.date[0], s.date[1], s.date[2], s.date[3]});
  if (name == "iSampleRate") return f({44100.0});
  if (name == "iChannelTime") return f({s.time, s.time, s.time, s.time});
  if (name == "iChannelResolution") {
    for (const std::int32_t c : s.channels) {
      const Texture* t = c >= 0 ? &s.textures[static_cast<std::size_t>(c)] : nullptr;
      f({t ? double(t->width) : 0.0, t ? double(t->height) : 0.0, t ? 1.0 : 0.0});
    }
    return true;
  }
  return false;
}

// A scene's value for a uniform of the program, as bits of the uniform's basic type.
std::vector<std::uint32_t> given_value(const std::vector<double>& values, const shader::UniformSlots& u,
                                       const std::string& where) {
  if (static_cast<int>(values.size()) != u.slots)
    throw SceneError(ErrorKind::invalid,
                     std::string("uniform \"") + u.name + std::string("\" is a ") + u.type +
                         std::string(": ") + std::to_string(u.slots) + " value" + (u.slots == 1 ? "" : "s") +
                         std::string(", got ") + std::to_string(values.size()),
                     {where, 0, 0});
  std::vector<std::uint32_t> bits;
  for (const double v : values) {
    switch (u.basic) {
      case 2:  // bool
        if (v != 0 && v != 1)
          throw SceneError(ErrorKind::invalid, std::string("uniform \"") + u.name + "\" takes true or false",
                           {where, 0, 0});
        bits.push_back(v != 0 ? ~0u : 0u);
        break;
      case 3:  // int
      case 4:  // uint
        if (v != std::floor(v) || v < (u.basic == 3 ? -2147483648.0 : 0.0) ||
            v > (u.basic == 3 ? 2147483647.0 : 4294967295.0))
          throw SceneError(ErrorKind::invalid,
                           std::string("uniform \"") + u.name + std::string("\" is a ") + u.type +
                               ": whole numbers " +
                               (u.basic == 3 ? "within 32-bit int" : "from 0 within 32 bits"),
                           {where, 0, 0});
        bits.push_back(static_cast<std::uint32_t>(static_cast<std::int64_t>(v)));
        break;
      default:
        bits.push_back(float_bits(v));
        break;
    }
  }
  return bits;
}

// Every uniform slot the program reads, and a check of the scene's uniforms against its declarations.
void resolve_uniforms(const ShaderPrimitive& s, std::uint32_t index, ShaderPlan& p) {
  const shader::Program& program = p.shader->program();
  for (const auto& [name, values] : s.uniforms) {
    const auto it = std::find_if(program.uniforms.begin(), program.uniforms.end(),
                                 [&](const shader::UniformSlots& u) { return u.name == name; });
    if (it == program.uniforms.end()) {
      std::string declared;
      for (const shader::UniformSlots& u : program.uniforms)
        if (!is_shadertoy_uniform(u.name)) declared += (declared.empty() ? " " : ", ") + u.name;
      throw SceneError(ErrorKind::invalid,
                       std::string("the program declares no uniform \"") + name + "\"" +
                           (declared.empty() ? "" : std::string("; it declares") + declared),
                       {pointer(index, std::string("uniforms/") + name), 0, 0});
    }
  }
  for (const shader::UniformSlots& u : program.uniforms) {
    if (u.first == shader::kUnusedSlot) continue;
    std::vector<std::uint32_t> bits;
    if (!shadertoy_value(s, p, u.name, bits)) {
      const auto given = std::find_if(s.uniforms.begin(), s.uniforms.end(),
                                      [&](const auto& g) { return g.first == u.name; });
      if (given == s.uniforms.end()) continue;  // not given: zero, as GL's uniforms start
      bits = given_value(given->second, u, pointer(index, std::string("uniforms/") + u.name));
    }
    for (int k = 0; k < u.slots && k < static_cast<int>(bits.size()); ++k)
      p.uniforms.emplace_back(u.first + static_cast<std::uint32_t>(k), bits[static_cast<std::size_t>(k)]);
  }
}

}  // namespace

std::int64_t channel_mip_bytes(int width, int height) {
  return mip_bytes(width, height);
}

bool plan_shader(const Scene& scene, std::uint32_t index, const Limits& limits, ShaderCache* cache,
                 RenderPlan& out, DrawPlan& draw) {
  const ShaderPrimitive& s = scene.shaders[scene.primitives[index].mesh];
  ShaderPlan p;
  p.primitive = index;
  p.shader = compile(s, index, limits, cache);
  p.rect_x = s.whole ? 0 : s.rect[0], p.rect_y = s.whole ? 0 : s.rect[1];
  p.rect_width = s.whole ? scene.width : s.rect[2], p.rect_height = s.whole ? scene.height : s.rect[3];
  p.x0 = std::clamp(p.rect_x, 0, scene.width), p.x1 = std::clamp(p.rect_x + p.rect_width, 0, scene.width);
  p.y0 = std::clamp(p.rect_y, 0, scene.height), p.y1 = std::clamp(p.rect_y + p.rect_height, 0, scene.height);
  resolve_uniforms(s, index, p);
  if (p.x0 >= p.x1 || p.y0 >= p.y1) return false;
  const std::uint8_t read = p.shader->channels_read();
  for (int c = 0; c < 4; ++c)
    if (read >> c & 1) p.channels[static_cast<std::size_t>(c)] = s.channels[static_cast<std::size_t>(c)];
  p.opaque = s.opaque;
  p.max_iterations = limits.shader.max_loop_iterations;
  p.register_bytes = static_cast<std::int64_t>(p.shader->slots()) * 64 * 4;
  for (const std::int32_t c : p.channels)
    if (c >= 0) {
      const Texture& t = s.textures[static_cast<std::size_t>(c)];
      out.memory.texture_bytes += static_cast<std::int64_t>(t.rgba.size());
      out.memory.shader_bytes += channel_mip_bytes(t.width, t.height);
    }
  draw.shader = static_cast<std::int32_t>(out.shaders.size());
  out.shaders.push_back(std::move(p));
  return true;
}

}  // namespace raster::detail
