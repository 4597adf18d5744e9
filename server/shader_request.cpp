#include "shader_request.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/scene_checks.h"

namespace rasterd {
namespace {

constexpr std::string_view kProgramParams[] = {"width", "height", "time", "frame", "mouse", "antialias"};

[[noreturn]] void bad_option(const std::string& name, const std::string& message) {
  throw QueryError(name, "query parameter \"" + name + "\": " + message);
}

double number(const std::string& name, std::string_view text) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    bad_option(name, "expected a number, got \"" + std::string(text) + "\"");
  return v;
}

// A shader's input (a time, a mouse coordinate): within +-1e9, as in a scene.
double shader_input(const std::string& name, std::string_view text) {
  const double v = number(name, text);
  if (std::fabs(v) > 1e9)
    bad_option(name, "a shader's input is a number within +-1e9; got " + std::string(text));
  return v;
}

// Sets the option `name` on the program's scene; false for one a program does not take.
bool set_option(raster::Scene& scene, const std::string& name, const std::string& value,
                const raster::Limits& limits) {
  raster::ShaderPrimitive& s = scene.shaders[0];
  if (name == "width" || name == "height") {
    (name == "width" ? scene.width : scene.height) = raster::checks::image_side(
        name, number(name, value), value, name == "width" ? limits.max_width : limits.max_height);
  } else if (name == "time") {
    s.time = shader_input(name, value);
  } else if (name == "frame") {
    const double f = number(name, value);
    if (f != std::floor(f) || f < 0 || f > INT32_MAX)
      bad_option(name, "\"frame\" is a whole number from 0 to 2147483647; got " + value);
    s.frame = static_cast<std::int32_t>(f);
  } else if (name == "mouse") {
    std::vector<std::string_view> parts;
    for (std::size_t at = 0; at <= value.size();) {
      const std::size_t comma = std::min(value.find(',', at), value.size());
      parts.push_back(std::string_view(value).substr(at, comma - at));
      at = comma + 1;
    }
    if (parts.size() != 2 && parts.size() != 4)
      bad_option(name, "expected x,y or x,y,click x,click y (pixels, GL's origin at the bottom left)");
    for (std::size_t k = 0; k < parts.size(); ++k) s.mouse[k] = shader_input(name, parts[k]);
  } else if (name == "antialias") {
    scene.antialias = raster::checks::antialias(value);
  } else {
    return false;
  }
  return true;
}

}  // namespace

bool is_shader_program(std::string_view file_name, std::string_view text) {
  std::string name(file_name);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (name.ends_with(".glsl") || name.ends_with(".frag") || name.ends_with(".fs")) return true;
  return !is_scene_text(text) && text.find("mainImage") != std::string_view::npos;
}

std::span<const std::string_view> program_param_names() {
  return kProgramParams;
}

raster::Scene program_scene(std::string source, const Params& params, const raster::Limits& limits) {
  raster::Scene scene;
  scene.width = kProgramWidth, scene.height = kProgramHeight;
  scene.shaders.emplace_back().source = std::move(source);
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::shader;
  scene.primitives.push_back(p);
  for (const auto& [name, value] : params) {
    if (name == "explain") continue;  // the caller's
    try {
      if (!set_option(scene, name, value, limits)) {
        std::string known;
        for (const std::string_view n : kProgramParams) known.append(known.empty() ? "" : ", ").append(n);
        bad_option(name, "unknown; known: " + known);
      }
    } catch (const QueryError&) {
      throw;
    } catch (const raster::SceneError& e) {
      throw QueryError(name, "query parameter \"" + name + "\": " + e.what());
    }
  }
  raster::checks::image_size(scene.width, scene.height, limits);
  raster::validate(scene);
  return scene;
}

}  // namespace rasterd
