#include "request.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "raster/model.h"
#include "raster/scene_checks.h"
#include "raster/utf8.h"

namespace rasterd {
namespace {

[[noreturn]] void bad_param(const std::string& name, const std::string& message) {
  throw QueryError(name, "query parameter \"" + name + "\": " + message);
}

// Whether `text` starts with an OBJ statement's keyword (raster::is_obj_statement) and a space.
bool starts_with_statement(std::string_view text) {
  const std::string_view head = text.substr(0, 12);  // the longest keyword has 10 letters
  const std::size_t space = head.find(' ');
  return space != std::string_view::npos && raster::is_obj_statement(head.substr(0, space));
}

// `curl -d @model.obj` drops newlines: what arrives is "v 0 0 0v 1 0 0f 1 2 3..." on one line. An OBJ
// statement then starts right after the previous one's last number, which no single OBJ line does; so one
// such junction marks the body, however short (a one-face model is 30 bytes).
bool looks_like_flattened_obj(std::string_view body) {
  if (body.find('\n') != std::string_view::npos) return false;
  for (std::size_t i = 1; i < body.size(); ++i) {
    const char before = body[i - 1];
    if (((before >= '0' && before <= '9') || before == '.') && starts_with_statement(body.substr(i)))
      return true;
  }
  return false;
}

// The query parameters of a bare model's default scene ("explain" is the route's).
constexpr std::string_view kModelParams[] = {"width",      "height", "background", "view",
                                             "projection", "fov",    "eye",        "target",
                                             "up",         "format", "antialias",  "point_size"};

}  // namespace

std::span<const std::string_view> model_param_names() {
  return kModelParams;
}

namespace {

std::string known_params() {
  std::string list;
  for (std::string_view name : kModelParams) list.append(name).append(", ");
  return list + "scale, explain (and v, the cache-buster)";
}

std::string text_of(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// ?scale=: a number in kMinScale..kMaxScale, or nullopt without one.
std::optional<double> scale_param(const Params& params) {
  const auto it = params.find("scale");
  if (it == params.end()) return std::nullopt;
  double v = 0;
  const std::string& text = it->second;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !(v >= kMinScale && v <= kMaxScale))
    bad_param("scale",
              "expected a number from 0.25 to 8 (the device pixel ratio: 2 for a 2x srcset picture), "
              "got \"" +
                  text + "\"");
  return v;
}

// "ffffff" for "#ffffff": a URL ends at '#' (curl and browsers keep what follows for themselves), so a
// colour in a query parameter is sent as %23ffffff or, more easily, without its '#'.
std::string colour_param(const std::string& value) {
  if (value.empty())
    bad_param("background",
              "is empty; a URL ends at '#', so a colour arrives empty unless its '#' is written %23 "
              "(?background=%23ffffff) or left out (?background=ffffff)");
  const bool bare_hex = (value.size() == 3 || value.size() == 4 || value.size() == 6 || value.size() == 8) &&
                        std::all_of(value.begin(), value.end(),
                                    [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
  return bare_hex ? "#" + value : value;
}

// The query parameter a field of the default scene comes from ("/camera/fov/..." -> "fov"), or "".
std::string param_of_pointer(const std::string& pointer, const Params& params) {
  std::string name =
      pointer.starts_with("/camera/") ? pointer.substr(8) : pointer.substr(pointer.empty() ? 0 : 1);
  name = name.substr(0, name.find('/'));
  return params.contains(name) ? name : "";
}

// A field's error as the error of the query parameter that set it: the client sent no document to point into.
[[noreturn]] void rethrow_as(const std::string& param, const raster::SceneError& e) {
  if (e.kind() == raster::ErrorKind::invalid)
    throw QueryError(param, "query parameter \"" + param + "\": " + e.what());
  throw raster::SceneError(e.kind(), "query parameter \"" + param + "\": " + e.what());
}

// An OBJ model's first statement (or a comment): what a body declared as JSON holds when a model was sent
// with the wrong Content-Type.
bool starts_like_obj(std::string_view body) {
  const std::size_t i = body.find_first_not_of(" \t\r\n");
  if (i == std::string_view::npos) return false;
  body.remove_prefix(i);
  return body.starts_with("# ") || starts_with_statement(body);
}

// A number of a query parameter, and how an error quotes it: a whole number as one ("0" as it was sent, not
// "0.0"), any other as a JSON writer prints it, the words these errors had when the parameters went through
// a scene document.
struct Number {
  double value;
  std::string text;
};

Number number_param(const std::string& name, const std::string& text) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    bad_param(name, "expected a number, got \"" + text + "\"");
  if (v == std::trunc(v) && std::fabs(v) < 1e15) return {v, std::to_string(static_cast<std::int64_t>(v))};
  return {v, nlohmann::json(v).dump()};
}

// "x,y,z", each coordinate checked as a point's in a scene.
raster::Vec3 vector_param(const std::string& name, const std::string& text) {
  std::vector<Number> numbers;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    numbers.push_back(number_param(name, text.substr(start, comma - start)));
    start = comma + 1;
  }
  if (numbers.size() != 3) bad_param(name, "expected x,y,z");
  double v[3];
  for (std::size_t k = 0; k < 3; ++k) v[k] = raster::checks::coordinate(numbers[k].value, numbers[k].text);
  return {v[0], v[1], v[2]};
}

// Sets the default scene's field that parameter `name` names, checked with the scene reader's words for
// that field; false for a parameter the default scene does not take.
bool set_field(raster::Scene& scene, const std::string& name, const std::string& value,
               const raster::Limits& limits) {
  raster::Camera& camera = scene.camera;
  if (name == "width" || name == "height") {
    const Number n = number_param(name, value);
    (name == "width" ? scene.width : scene.height) = raster::checks::image_side(
        name, n.value, n.text, name == "width" ? limits.max_width : limits.max_height);
  } else if (name == "background") {
    scene.background = raster::checks::color(colour_param(value));
  } else if (name == "projection") {
    camera.projection = raster::checks::projection(value);
  } else if (name == "view") {
    camera.view = raster::checks::view(value), camera.has_view = true;
  } else if (name == "fov") {
    const Number n = number_param(name, value);
    camera.fov_deg = raster::checks::fov(n.value, n.text);
  } else if (name == "eye") {
    camera.eye = vector_param(name, value), camera.has_eye = true;
  } else if (name == "target") {
    camera.target = vector_param(name, value), camera.has_target = true;
  } else if (name == "up") {
    // An axis by name, or a vector; a URL's '+' arrives as a space (?up=+z is " z").
    const std::string axis = value.starts_with(' ') ? "+" + value.substr(1) : value;
    const bool named = !axis.empty() && std::isalpha(static_cast<unsigned char>(axis.back()));
    camera.up = named ? raster::checks::up_axis(axis) : raster::checks::up(vector_param(name, value));
    camera.has_up = true;
  } else if (name == "antialias") {
    scene.antialias = raster::checks::antialias(value);
  } else if (name == "point_size") {  // kept through the model's reading (default_scene)
    const Number n = number_param(name, value);
    scene.meshes[0].point_size = raster::checks::point_size(n.value, n.text);
  } else {
    return false;
  }
  return true;
}

// The default scene of a bare model (raster::model_scene: the library's picture of a model in its format)
// as the parameters shape it, built directly: each value is checked with the words the scene reader has for
// its field, so a bad parameter reads as that field would in a scene document. The order errors are found
// in: ?format=, the model's format; each other parameter when it is read, in name order (the map's); then
// the camera's fields together, the image's pixels, the model, and validate().
raster::Scene default_scene(const Params& params, std::optional<raster::ModelFormat> named_format,
                            const raster::Uploads& uploads, const raster::Limits& limits,
                            const Sniffed& sniffed) {
  // The bytes tell the format first (the request's sniff); else the part's file name, else ?format=.
  std::optional<raster::ModelFormat> hint = named_format;
  if (const auto it = params.find("format"); it != params.end() && !named_format) {
    try {
      hint = raster::checks::model_format(it->second);
    } catch (const raster::SceneError& e) {
      rethrow_as("format", e);
    }
  }
  const std::string& bytes = uploads.at("model");
  const raster::ModelFormat format = raster::model_format_of(bytes, hint, sniffed.format);
  // The library's picture of a bare model (size, background, anti-aliasing, the format's up axis), which
  // the parameters adjust; its mesh is read last.
  raster::Scene scene = raster::model_scene({}, format);
  for (const auto& [name, value] : params) {
    if (name == "explain" || name == "scale" || name == "format")
      continue;  // the route's, the scene's once read (apply_scale), and the format's (above)
    try {
      if (!set_field(scene, name, value, limits)) bad_param(name, "unknown; known: " + known_params());
    } catch (const QueryError&) {
      throw;
    } catch (const raster::SceneError& e) {
      rethrow_as(name, e);
    }
  }
  try {
    raster::checks::camera(scene.camera, "/camera", 0);
    raster::checks::image_size(scene.width, scene.height, limits);
    const auto mtl = uploads.find("mtl");                 // an MTL uploaded as part "mtl" goes with the model
    const float point_size = scene.meshes[0].point_size;  // ?point_size= or the default
    scene.meshes[0] = raster::checks::model_mesh(bytes, hint, limits, uploads,
                                                 mtl == uploads.end() ? std::string_view() : mtl->second,
                                                 "/primitives/0", 0, format);
    scene.meshes[0].point_size = point_size;
    raster::validate(scene);
  } catch (const raster::SceneError& e) {
    const std::string param = param_of_pointer(e.where().pointer, params);
    if (param.empty()) throw;
    rethrow_as(param, e);
  }
  return scene;
}

}  // namespace

bool is_json_media_type(std::string_view content_type) {
  std::string type(content_type.substr(0, content_type.find(';')));
  while (!type.empty() && (type.back() == ' ' || type.back() == '\t')) type.pop_back();
  std::transform(type.begin(), type.end(), type.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return type == "application/json" || type == "text/json" || type.ends_with("+json");
}

bool is_scene_text(std::string_view body) {
  body = raster::without_bom(body);
  const std::size_t i = body.find_first_not_of(" \t\r\n");
  return i != std::string_view::npos && (body[i] == '{' || body[i] == '[');
}

namespace {

// A byte order mark is whitespace to the readers: blanked rather than cut, so every byte offset in an error
// still counts from the start of what was sent.
void blank_bom(std::string& body) {
  if (body.starts_with(raster::kUtf8Bom))
    body.replace(0, raster::kUtf8Bom.size(), raster::kUtf8Bom.size(), ' ');
}

// The request's one sniff, of its main bytes (Sniffed).
Sniffed sniff_main_bytes(std::string_view bytes) {
  return {raster::sniff_model(bytes)};
}

bool is_gltf(std::optional<raster::ModelFormat> format) {
  return format == raster::ModelFormat::gltf || format == raster::ModelFormat::glb;
}

}  // namespace

Sniffed sniff_request(std::string& body, const raster::Uploads& uploads) {
  blank_bom(body);
  const auto model = uploads.find("model");
  return sniff_main_bytes(body.empty() && model != uploads.end() ? std::string_view(model->second) : body);
}

bool explain_requested(const Params& params) {
  const auto it = params.find("explain");
  if (it == params.end()) return false;
  std::string v = it->second;
  std::transform(v.begin(), v.end(), v.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (v.empty() || v == "1" || v == "true" || v == "yes" || v == "on") return true;  // a bare ?explain too
  if (v == "0" || v == "false" || v == "no" || v == "off") return false;
  bad_param("explain", "expected 1, true, yes or on (or 0, false, no, off), got \"" + it->second + "\"");
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

std::string adopt_main_part(std::string& body, raster::Uploads& uploads, const std::vector<PartName>& parts,
                            std::string* model_file_name, std::optional<Sniffed>* sniffed) {
  if (!body.empty() || uploads.contains("model") || parts.empty()) return {};
  auto lower_ends_with = [](std::string name, std::string_view suffix) {
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return name.ends_with(suffix);
  };
  // A lone part is the body whatever its name; among several, the one whose file is a scene or a model.
  std::vector<const PartName*> candidates;
  for (const PartName& p : parts)
    if (parts.size() == 1 || raster::format_of_file_name(p.key) || lower_ends_with(p.key, ".json"))
      candidates.push_back(&p);
  if (candidates.size() == 1) {
    const PartName& p = *candidates.front();
    std::string bytes = std::move(uploads[p.key]);
    uploads.erase(p.key);
    if (p.part != p.key) uploads.erase(p.part);  // the copy add_part_names made under the part's name
    // A part whose file name is a model's is that model, even when its bytes start like JSON (a binary STL's
    // header may start with '{'). This is the request's sniff (of the body or, the body being empty, of the
    // model part these bytes become): for scene text, sniffing before its byte order mark is blanked tells
    // the same.
    const Sniffed told = sniff_main_bytes(bytes);
    if (!raster::format_of_file_name(p.key) && is_scene_text(bytes) && !is_gltf(told.format)) {
      body = std::move(bytes);
    } else {
      uploads["model"] = std::move(bytes);
      if (model_file_name) *model_file_name = p.key;
    }
    if (sniffed) *sniffed = told;
    return {};
  }
  std::string names;
  for (const PartName& p : parts)
    names += (names.empty() ? "\"" : ", \"") + p.part + "\"" + (p.key != p.part ? " (" + p.key + ")" : "");
  return "the upload has the parts " + names + " but none is named \"scene\" or \"model\"" +
         (candidates.empty() ? "" : " and more than one could be") +
         "; send the model as -F model=@model.stl (or .obj, .ply, .gltf, .glb, .3mf) or the scene as -F "
         "scene=@scene.json";
}

bool ignored_param(std::string_view name) {
  return name == "v" || name.starts_with("utm_") || name == "fbclid" || name == "gclid" || name == "msclkid";
}

void apply_scale(raster::Scene& scene, double scale, const raster::Limits& limits) {
  if (scale == 1) return;
  const auto side = [&](int px, int max_px, const char* what) {
    const double scaled = std::max(1.0, std::round(px * scale));
    if (scaled > std::min(max_px, raster::kMaxImageSide))
      throw raster::SceneError(raster::ErrorKind::limit,
                               "query parameter \"scale\": the " + std::string(what) + " of " +
                                   std::to_string(px) + " x " + text_of(scale) + " is over the limit of " +
                                   std::to_string(std::min(max_px, raster::kMaxImageSide)) + " pixels");
    return static_cast<int>(scaled);
  };
  scene.width = side(scene.width, limits.max_width, "width");
  scene.height = side(scene.height, limits.max_height, "height");
  for (raster::Point2& p : scene.points) p.x *= scale, p.y *= scale;
  for (raster::Primitive& p : scene.primitives) p.width = static_cast<float>(p.width * scale);
  for (raster::Mesh& m : scene.meshes)  // edges are drawn in pixels; the camera frames the rest
    m.edges.width = static_cast<float>(m.edges.width * scale);
  raster::validate(scene);  // coordinates scaled past the largest accepted are refused, as in a scene
}

raster::Scene scene_from_request(std::string body, raster::Uploads uploads, const Params& all_params,
                                 const raster::Limits& limits, bool declared_json,
                                 std::optional<raster::ModelFormat> named_format,
                                 std::optional<Sniffed> sniffed) {
  Params params;  // what the request means: without the cache-buster and the sharing tools' parameters
  for (const auto& [name, value] : all_params)
    if (!ignored_param(name)) params.emplace(name, value);
  // Parameters are quoted in errors, which are UTF-8 JSON: their bytes must be UTF-8 first.
  for (const auto& [name, value] : params) {
    raster::require_utf8(name, "the name of a query parameter");
    raster::require_utf8(value, "query parameter \"" + name + "\"");
  }
  explain_requested(params);  // a bad ?explain or ?scale is an error before anything is read
  const std::optional<double> scale = scale_param(params);
  // The byte order mark blanked (sniff_request; a part adopt_main_part sniffed is not blanked yet) and the
  // request sniffed, once: here unless a caller did. An empty body's sniff is its model part's, which
  // decides nothing below: the body is then no scene text, and a request with parts declares no JSON.
  blank_bom(body);
  const Sniffed told = sniffed ? *sniffed : sniff_request(body, uploads);
  // A glTF document is JSON too (model/gltf+json ends in "+json"): its bytes, its file name or a model
  // Content-Type make it a model, and so do a GLB's bytes whatever the request calls them. A body the request
  // calls JSON is otherwise a scene (an OBJ sent so gets a hint below); an undeclared one is a scene by its
  // first byte unless its bytes are a model's or a file name or Content-Type names a model format (a binary
  // STL's header may start with '{').
  // The named format is the body's only when no part carries the model (multipart: the model part's name).
  const bool named_model = named_format && !uploads.contains("model");
  const bool gltf = is_gltf(told.format) || (named_model && is_gltf(named_format));
  if (!gltf && (declared_json || (is_scene_text(body) && !told.format && !named_model))) {
    // A scene says everything itself: a query parameter could only be ignored, which hides a mistake.
    for (const auto& [name, value] : params) {
      if (name == "explain" || name == "scale") continue;
      const bool model_param =
          std::find(std::begin(kModelParams), std::end(kModelParams), name) != std::end(kModelParams);
      bad_param(name, model_param
                          ? "shapes the default scene of a bare model; this body is a scene, which sets "
                            "\"" +
                                name + "\" (or its camera) in its JSON"
                          : "unknown; a scene takes only: scale, explain (and v, the cache-buster)");
    }
    if (declared_json && !is_scene_text(body) && starts_like_obj(body))
      throw raster::SceneError(
          raster::ErrorKind::syntax,
          "the Content-Type says JSON, but the body looks like an OBJ model; send a model "
          "as model/obj, or with curl --data-binary and no Content-Type of its own");
    raster::Scene scene = raster::parse_scene(body, limits, uploads);
    if (scale) apply_scale(scene, *scale, limits);
    return scene;
  }
  if ((!told.format || told.format == raster::ModelFormat::obj) && looks_like_flattened_obj(body))
    throw raster::SceneError(
        raster::ErrorKind::syntax,
        "the body looks like an OBJ model whose line breaks were removed (curl -d does that); "
        "send it with --data-binary @model.obj");
  if (body.find_first_not_of(" \t\r\n") == std::string_view::npos && !uploads.count("model"))
    throw raster::SceneError(raster::ErrorKind::syntax,
                             "the request is empty: send a scene (JSON) or a model (" +
                                 std::string(raster::accepted_formats()) + ")");
  if (!body.empty()) uploads["model"] = std::move(body);  // the body is the model when it has bytes
  raster::Scene scene = default_scene(params, named_format, uploads, limits, told);
  if (scale) apply_scale(scene, *scale, limits);
  return scene;
}

}  // namespace rasterd
