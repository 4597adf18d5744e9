// The scene reader's shader primitive: ShaderToy's inputs (time, frame, mouse, date, channels), the
// program's own uniforms, and the rectangle it covers. The program itself is compiled by the plan.
#include <cmath>
#include <functional>
#include <string>

#include "scene/scene_reader.h"

namespace raster::scene_reader {
namespace {

bool identifier(std::string_view s) {
  if (s.empty() || s.size() > 256 || (s[0] >= '0' && s[0] <= '9')) return false;
  for (const char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
      return false;
  return true;
}

}  // namespace

// Four numbers (or two, the rest 0), each finite and within +-1e9.
std::array<double, 4> Reader::four_numbers(const Path& at, const char* what, bool two_allowed) {
  expect(at, format::kArray, what);
  std::array<double, 4> v{};
  std::size_t n = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++n) {
    const Path e = element(at, n);
    if (n >= 4) invalid(at, std::string("expected ") + what);
    v[n] = ranged(e, format::kShaderInput);
  }
  if (n != 4 && !(two_allowed && n == 2)) invalid(at, std::string("expected ") + what);
  return v;
}

// Up to four images, one per channel in order, or null for a channel left empty.
void Reader::channels(PrimitiveState& s, const Path& at) {
  std::size_t n = 0;
  std::int64_t pending = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++n) {
    const Path e = element(at, n);
    if (n >= 4) invalid(e, "a shader has four channels (iChannel0..3); got a fifth");
    if (in.peek() == Kind::null) {
      in.skip();
      continue;
    }
    expect(e, format::kObject, "a texture object or null");
    Texture t = texture(e, pending);
    pending += std::int64_t{t.width} * t.height;
    s.shader.channels[n] = static_cast<std::int32_t>(s.shader.textures.size());
    s.shader.textures.push_back(std::move(t));
  }
}

// name: a number, true or false, or an array of them (nested arrays flattened: a matrix by columns).
void Reader::uniforms(PrimitiveState& s, const Path& at) {
  for (bool more = in.object_begin(); more; more = in.object_next()) {
    const std::string name(in.key());
    const Path value(at, name, (in.peek(), in.offset()));
    if (!identifier(name)) invalid(value, std::string("\"") + name + "\" is not a GLSL name");
    if (is_shadertoy_uniform(name))
      invalid(value, std::string("\"") + name +
                         "\" is set by the shader's own fields (time, frame, mouse, date, channels)");
    for (const auto& [seen, unused] : s.shader.uniforms)
      if (seen == name)
        invalid(value, std::string("\"") + name + "\" is given twice in one object; give each key once");
    std::vector<double> slots;
    std::function<void(const Path&, int)> read = [&](const Path& where, int depth) {
      const Kind k = in.peek();
      if (k == Kind::boolean) return slots.push_back(in.boolean() ? 1 : 0);
      if (k == Kind::number) {
        const double d = number(where);
        if (!std::isfinite(d) || std::fabs(d) > 3.4e38)
          invalid(where, "a uniform's number must be a finite float");
        return slots.push_back(d);
      }
      if (k != Kind::array || depth > 1) wrong_kind(where, k, "a number, true, false or an array of them");
      std::size_t i = 0;
      for (bool m = in.array_begin(); m; m = in.array_next(), ++i) {
        if (slots.size() >= 4096) invalid(where, "a uniform holds at most 4096 values");
        read(element(where, i), depth + 1);
      }
    };
    read(value, 0);
    if (slots.empty()) invalid(value, "a uniform needs a value");
    s.shader.uniforms.emplace_back(name, std::move(slots));
  }
}

// [x, y, width, height] in whole pixels, y down; width and height at least 1.
void Reader::rect(PrimitiveState& s, const Path& at) {
  std::array<std::int64_t, 4> v{};
  std::size_t n = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++n) {
    const Path e = element(at, n);
    if (n >= 4) invalid(at, "\"rect\" is [x, y, width, height] in pixels");
    v[n] = integer(e);
    const bool size = n >= 2;
    if (v[n] < (size ? 1 : -kMaxImageSide) || v[n] > kMaxImageSide)
      invalid(e, size ? "a rect's width and height are whole pixels, 1 to 16384"
                      : "a rect's corner is a whole pixel within +-16384");
  }
  if (n != 4) invalid(at, "\"rect\" is [x, y, width, height] in pixels");
  for (std::size_t i = 0; i < 4; ++i) s.shader.rect[i] = static_cast<std::int32_t>(v[i]);
  s.shader.whole = false;
}

}  // namespace raster::scene_reader
