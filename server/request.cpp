#include "request.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <nlohmann/json.hpp>

#include "raster/utf8.h"

namespace rasterd {
namespace {

[[noreturn]] void bad_param(const std::string& name, const std::string& message) {
  throw raster::SceneError(raster::ErrorKind::invalid, "query parameter \"" + name + "\": " + message);
}

// `curl -d @model.obj` drops newlines: what arrives is "v 0 0 0v 1 0 0f 1 2 3..." on one line.
bool looks_like_flattened_obj(std::string_view body) {
  if (body.size() < 64 || body.find('\n') != std::string_view::npos) return false;
  const bool vertices =
      body.find("v ") != std::string_view::npos || body.find("v\t") != std::string_view::npos;
  return vertices && body.find("f ") != std::string_view::npos;
}

// The default scene of a bare model, with the parameters turned into JSON and parsed like any scene, so
// that a bad parameter gets the same precise message as the same field in a scene document.
std::string default_scene_json(const Params& params) {
  nlohmann::json scene = {{"width", 512}, {"height", 512}};
  nlohmann::json camera = nlohmann::json::object();
  auto number = [&](const std::string& name, const std::string& text) {
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
      bad_param(name, "expected a number, got \"" + text + "\"");
    return v;
  };
  auto vector = [&](const std::string& name, const std::string& text) {
    nlohmann::json out = nlohmann::json::array();
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t comma = text.find(',', start);
      if (comma == std::string::npos) comma = text.size();
      out.push_back(number(name, text.substr(start, comma - start)));
      start = comma + 1;
    }
    if (out.size() != 3) bad_param(name, "expected x,y,z");
    return out;
  };
  for (const auto& [name, value] : params) {
    if (name == "width" || name == "height")
      scene[name] = number(name, value);
    else if (name == "background")
      scene["background"] = value;
    else if (name == "projection" || name == "view")
      camera[name] = value;
    else if (name == "fov")
      camera["fov"] = number(name, value);
    else if (name == "eye" || name == "target" || name == "up")
      camera[name] = vector(name, value);
    else if (name == "explain")
      continue;  // the route's, not the scene's
    else
      bad_param(name, "unknown; known: width, height, background, view, projection, fov, eye, target, up");
  }
  if (!camera.empty()) scene["camera"] = camera;
  scene["primitives"] = nlohmann::json::array({{{"type", "obj"}, {"source", "model"}}});
  return scene.dump();
}

}  // namespace

bool is_scene_text(std::string_view body) {
  const std::size_t i = body.find_first_not_of(" \t\r\n");
  return i != std::string_view::npos && body[i] == '{';
}

std::string upload_key(std::string_view part_name, std::string_view file_name) {
  if (part_name == "scene" || part_name == "model" || part_name == "mtl") return std::string(part_name);
  const std::size_t slash = file_name.find_last_of("/\\");
  const std::string_view base = slash == std::string_view::npos ? file_name : file_name.substr(slash + 1);
  return std::string(base.empty() ? part_name : base);
}

void add_part_names(raster::Uploads& uploads, const std::vector<PartName>& parts) {
  for (const PartName& p : parts) {
    if (p.part == p.key || uploads.contains(p.part)) continue;
    const bool shared =
        std::count_if(parts.begin(), parts.end(), [&](const PartName& q) { return q.part == p.part; }) > 1;
    if (auto bytes = uploads.find(p.key); !shared && bytes != uploads.end())
      uploads.emplace(p.part, bytes->second);
  }
}

raster::Scene scene_from_request(std::string body, raster::Uploads uploads, const Params& params,
                                 const raster::Limits& limits) {
  // Parameters become JSON text below and are quoted in errors: their bytes must be UTF-8 first.
  for (const auto& [name, value] : params) {
    raster::require_utf8(name, "the name of a query parameter");
    raster::require_utf8(value, "query parameter \"" + name + "\"");
  }
  if (is_scene_text(body)) return raster::parse_scene(body, limits, uploads);
  if (looks_like_flattened_obj(body))
    throw raster::SceneError(
        raster::ErrorKind::syntax,
        "the body looks like an OBJ model whose line breaks were removed (curl -d does that); "
        "send it with --data-binary @model.obj");
  if (body.find_first_not_of(" \t\r\n") == std::string_view::npos && !uploads.count("model"))
    throw raster::SceneError(raster::ErrorKind::syntax,
                             "the request is empty: send a scene (JSON) or a model (OBJ)");
  if (!body.empty()) uploads["model"] = std::move(body);
  return raster::parse_scene(default_scene_json(params), limits, uploads);
}

}  // namespace rasterd
