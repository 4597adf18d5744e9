// The scene reader: JSON text -> Scene in one pass, the format described once (scene_reader.h says how).
// This file is the document: the root's table and a primitive's, the primitive types and what each makes
// of the keys it was given (a 2D shape into the scene's flat arrays, a mesh, a model file read by its
// reader), and parse_scene(), which owns the order in which errors are reported.
//
// A document with an error that is also malformed is reported as malformed (see parse_scene).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "raster/scene_checks.h"
#include "raster/utf8.h"
#include "scene/scene_reader.h"

namespace raster {
namespace scene_reader {
namespace {

constexpr Rgba8 kMeshGrey{204, 204, 204, 255};  // meshes and models without colours
constexpr Rgba8 kWhite{255, 255, 255, 255};     // 2D primitives without colours

// A primitive: the union of every type's keys; "type" narrows them to its own (kTypes).
constexpr Field<PrimitiveState> kPrimitiveFields[] = {
    {"type", format::kString, "a string",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.set_type(s, r.in.string(), at); }},
    {"points", format::kArray, "an array of points",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.points(s, at); }},
    {"color", format::kString | format::kArray, "a colour (\"#rrggbb\" or [r, g, b])",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.color = r.color(at); }},
    {"colors", format::kArray, "an array of colours, one per point",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.colors(s, at); }},
    {"fill", format::kBool, "true or false",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.primitive.fill = r.boolean(at); }},
    {"closed", format::kBool, "true or false",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.primitive.closed = r.boolean(at); }},
    {"width", format::kNumber, "a number",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.primitive.width = static_cast<float>(r.ranged(at, format::kLineWidth));
     }},
    {"positions", format::kArray, "an array of [x, y, z] or of numbers",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.vec3_list(s.mesh.positions, at); }},
    {"indices", format::kArray, "an array of [a, b, c] or of integers",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.indices(s, at); }},
    {"normals", format::kArray, "an array of [x, y, z] or of numbers",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.normals_byte = at.byte(), r.vec3_list(s.mesh.normals, at);
     }},
    {"uvs", format::kArray, "an array of [u, v] or of numbers",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.uvs(s, at); }},
    {"texture", format::kObject, "{\"data\": base64} or {\"source\": part name}",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.mesh.textures.push_back(r.texture(at)); }},
    {"shading", format::kString, "\"flat\", \"smooth\" or \"unlit\"",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.mesh.shading =
           static_cast<Shading>(r.choice(at, std::array<std::string_view, 3>{"flat", "smooth", "unlit"}));
     }},
    {"cull", format::kString, "\"none\" or \"back\"",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.mesh.cull = static_cast<Cull>(r.choice(at, std::array<std::string_view, 2>{"none", "back"}));
     }},
    {"wireframe", format::kBool, "true or false",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.mesh.wireframe = r.boolean(at); }},
    {"edges", format::kBool | format::kObject, "true or {\"color\", \"width\", \"angle\"}",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.mesh.edges = r.edges(at); }},
    {"transform", format::kObject, "a transform object",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.mesh.transform = r.transform(at); }},
    {"point_size", format::kNumber, "a number",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.mesh.point_size = static_cast<float>(r.ranged(at, format::kPointSize));
     }},
    {"data", format::kString, "text",
     [](Reader& r, PrimitiveState& s, const Path&) { s.obj = r.in.string(); }},
    {"source", format::kString, "a string (a model: the name of an uploaded part; a shader: its GLSL)",
     [](Reader& r, PrimitiveState& s, const Path&) { s.source = r.in.string(); }},
    {"mtl", format::kString, "text",
     [](Reader& r, PrimitiveState& s, const Path&) { s.mtl = r.in.string(); }},
    {"mtl_source", format::kString, "the name of an uploaded part",
     [](Reader& r, PrimitiveState& s, const Path&) { s.mtl_source = r.in.string(); }},
    {"format", format::kString, "a string",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.format = model_formats()[r.choice(at, format_names())].format;
     }},
    {"time", format::kNumber, "a number (seconds)",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.shader.time = r.ranged(at, format::kShaderInput);
     }},
    {"frame", format::kNumber, "a whole number",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       const std::int64_t f = r.integer(at);
       if (f < 0 || f > INT32_MAX) r.invalid(at, "\"frame\" is a whole number from 0 to 2147483647");
       s.shader.frame = static_cast<std::int32_t>(f);
     }},
    {"mouse", format::kArray, "[x, y, click x, click y] in pixels",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.shader.mouse = r.four_numbers(at, "[x, y] or [x, y, click x, click y] in pixels", true);
     }},
    {"date", format::kArray, "[year, month, day, seconds]",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.shader.date = r.four_numbers(at, "[year, month (0-11), day, seconds since midnight]", false);
     }},
    {"channels", format::kArray, "an array of up to four texture objects (or null)",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.channels(s, at); }},
    {"uniforms", format::kObject, "an object of uniform name: value",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.uniforms(s, at); }},
    {"rect", format::kArray, "[x, y, width, height] in pixels",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.rect(s, at); }},
    {"opaque", format::kBool, "true or false",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.shader.opaque = r.boolean(at); }},
    {"textures", format::kObject, "an object of file name: base64 image",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       for (bool more = r.in.object_begin(); more; more = r.in.object_next()) {
         const std::string name(r.in.key());
         const Path image(at, name, (r.in.peek(), r.in.offset()));
         if (s.textures.contains(name))
           r.invalid(image, "\"" + name + "\" is given twice in one object; give each key once");
         s.textures[name] = r.base64(image);
       }
     }},
};

// The bit of a primitive's key, at compile time.
consteval std::uint64_t bit(std::string_view key) {
  return format::mask_of(kPrimitiveFields, {key});
}

struct PrimitiveType {
  std::string_view name;
  PrimitiveKind kind;
  std::uint32_t min_points, max_points;
  std::uint64_t keys;  // bits of kPrimitiveFields
};
constexpr PrimitiveType kTypes[] = {
    {"triangle", PrimitiveKind::triangle, 3, 3,
     format::mask_of(kPrimitiveFields, {"type", "points", "color", "colors", "fill", "width"})},
    {"line", PrimitiveKind::line, 2, 2,
     format::mask_of(kPrimitiveFields, {"type", "points", "color", "colors", "width"})},
    {"polyline", PrimitiveKind::polyline, 2, UINT32_MAX,
     format::mask_of(kPrimitiveFields, {"type", "points", "color", "colors", "closed", "width"})},
    {"mesh", PrimitiveKind::mesh, 0, 0,
     format::mask_of(kPrimitiveFields, {"type", "positions", "indices", "colors", "color", "normals", "uvs",
                                        "texture", "shading", "wireframe", "edges", "cull", "transform"})},
    // A model file in any format (model.h), its format told by its bytes, else by "format"; "obj" is the
    // same with OBJ as the format to fall back on (rasterd 0.1's name, kept).
    {"model", PrimitiveKind::mesh, 0, 0,
     format::mask_of(kPrimitiveFields,
                     {"type", "data", "source", "format", "mtl", "mtl_source", "textures", "color", "shading",
                      "wireframe", "edges", "cull", "transform", "point_size"})},
    {"obj", PrimitiveKind::mesh, 0, 0,
     format::mask_of(kPrimitiveFields, {"type", "data", "source", "mtl", "mtl_source", "textures", "color",
                                        "shading", "wireframe", "edges", "cull", "transform", "point_size"})},
    // A program run at every pixel of the image or of "rect" (ShaderToy's image pass).
    {"shader", PrimitiveKind::shader, 0, 0,
     format::mask_of(kPrimitiveFields, {"type", "source", "time", "frame", "mouse", "date", "channels",
                                        "uniforms", "rect", "opaque"})},
};
constexpr const char* kTypeNames =
    "\"triangle\", \"line\", \"polyline\", \"mesh\", \"model\", \"obj\" or \"shader\"";

}  // namespace

void Reader::set_type(PrimitiveState& s, std::string_view name, const Path& at) {
  const auto* t = std::find_if(std::begin(kTypes), std::end(kTypes),
                               [&](const PrimitiveType& t) { return t.name == name; });
  if (t == std::end(kTypes))
    invalid(at, "unknown primitive type \"" + std::string(name) + "\"; expected " + kTypeNames);
  s.type = static_cast<int>(t - kTypes);
  s.allowed = t->keys;
}

void Reader::finish_drawn(PrimitiveState& s, const Path& at) {
  const PrimitiveType& t = kTypes[s.type];
  if (!(s.seen & bit("points"))) invalid(at, "a " + std::string(t.name) + " needs \"points\"");
  const std::size_t n = s.dims == 3 ? s.coords.size() / 3 : scene.points.size() - s.first_point;
  const Path points(at, "points", s.points_byte);
  if (n < t.min_points || n > t.max_points)
    invalid(points, "a " + std::string(t.name) +
                        (t.min_points == t.max_points ? " has exactly " : " has at least ") +
                        std::to_string(t.min_points) + " points, got " + std::to_string(n));
  if (s.first_point + n > UINT32_MAX) fail(ErrorKind::limit, points, "too many points in the scene");
  if ((s.seen & bit("color")) && (s.seen & bit("colors")))
    invalid(at, "give either \"color\" (flat) or \"colors\" (one per point), not both");
  if ((s.seen & bit("colors")) && s.colors.size() != n)
    invalid(Path(at, "colors", s.colors_byte),
            "\"colors\" needs one colour per point (" + std::to_string(n) + ")");
  if (!(s.seen & bit("colors"))) s.colors.assign(1, (s.seen & bit("color")) ? s.color : kWhite);
  Primitive p = s.primitive;
  p.kind = t.kind;
  const bool per_vertex = s.seen & bit("colors");
  if (s.dims == 3) {  // world space: an unlit mesh through the camera
    Mesh mesh;
    for (std::size_t k = 0; k < s.coords.size(); k += 3)
      mesh.positions.push_back(Vec3f(Vec3{s.coords[k], s.coords[k + 1], s.coords[k + 2]}));
    mesh.colors = s.colors;
    mesh.shading = Shading::unlit;
    const auto m = static_cast<std::uint32_t>(n);
    if (p.kind == PrimitiveKind::triangle && p.fill) {
      mesh.triangles.push_back({0, 1, 2});
    } else {
      for (std::uint32_t i = 0; i + 1 < m; ++i) mesh.segments.push_back({i, i + 1});
      if ((p.closed || p.kind == PrimitiveKind::triangle) && m >= 3) mesh.segments.push_back({m - 1, 0});
    }
    p.kind = PrimitiveKind::mesh;
    p.mesh = static_cast<std::uint32_t>(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));
    scene.primitives.push_back(p);
    return;
  }
  p.first_point = static_cast<std::uint32_t>(s.first_point);
  p.point_count = static_cast<std::uint32_t>(n);
  p.first_color = static_cast<std::uint32_t>(scene.colors.size());
  p.per_vertex_color = per_vertex;
  for (const Rgba8 c : s.colors) scene.colors.push_back(c);
  scene.primitives.push_back(p);
}

void Reader::finish_mesh(PrimitiveState& s, const Path& at) {
  Mesh& mesh = s.mesh;
  if (!(s.seen & bit("positions"))) invalid(at, "a mesh needs \"positions\"");
  if (!(s.seen & bit("indices"))) invalid(at, "a mesh needs \"indices\" (triangles as [a, b, c], 0-based)");
  const std::size_t n = mesh.positions.size();
  // Indices come before or after the positions they index: checked now that both are read.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t j = 0; j < 3; ++j) {
      const std::uint32_t i = mesh.triangles[t][j];
      if (i < n) continue;
      const Path indices(at, "indices", s.indices_byte), triangle(indices, t, s.indices_byte);
      invalid(s.indices_nested ? Path(triangle, j, s.indices_byte) : Path(indices, 3 * t + j, s.indices_byte),
              "index " + (i == UINT32_MAX ? s.bad_index : std::to_string(i)) + " is outside the " +
                  std::to_string(n) + " positions (0-based)");
    }
  if ((s.seen & bit("color")) && (s.seen & bit("colors")))
    invalid(at, "give either \"color\" (flat) or \"colors\" (one per point), not both");
  if ((s.seen & bit("colors")) && s.colors.size() != n)
    invalid(Path(at, "colors", s.colors_byte),
            "\"colors\" needs one colour per point (" + std::to_string(n) + ")");
  mesh.colors = (s.seen & bit("colors")) ? std::move(s.colors)
                                         : std::vector<Rgba8>{(s.seen & bit("color")) ? s.color : kMeshGrey};
  if (s.seen & bit("normals")) {
    if (mesh.normals.size() != n)
      invalid(Path(at, "normals", s.normals_byte),
              "\"normals\" needs one normal per position (" + std::to_string(n) + ")");
    mesh.normal_triangles = mesh.triangles;
  }
  const bool uvs = s.seen & bit("uvs"), texture = s.seen & bit("texture");
  if (uvs != texture)
    invalid(at, uvs ? "\"uvs\" are used with a \"texture\"; give both"
                    : "a \"texture\" needs \"uvs\" (one [u, v] per position)");
  if (uvs) {
    if (mesh.uvs.size() != n)
      invalid(Path(at, "uvs", s.uvs_byte), "\"uvs\" needs one [u, v] per position (" + std::to_string(n) +
                                               "), got " + std::to_string(mesh.uvs.size()));
    mesh.uv_triangles = mesh.triangles;
  }
}

void Reader::finish_model(PrimitiveState& s, const Path& at) {
  auto text_of = [&](std::uint32_t inline_bit, std::uint32_t source_bit, const std::string& text,
                     std::string_view name) -> std::string_view {
    const std::string_view inline_key = kPrimitiveFields[std::countr_zero(inline_bit)].key,
                           source_key = kPrimitiveFields[std::countr_zero(source_bit)].key;
    if ((s.seen & inline_bit) && (s.seen & source_bit))
      invalid(at, "give either \"" + std::string(inline_key) + "\" or \"" + std::string(source_key) +
                      "\", not both");
    if (s.seen & inline_bit) return text;
    if (!(s.seen & source_bit)) return {};
    const auto part = uploads.find(name);
    if (part == uploads.end())
      invalid(Path(at, source_key, s.byte), "no uploaded part named \"" + std::string(name) +
                                                "\" (send it as a multipart part of that name)");
    return part->second;
  };
  const std::string_view obj = text_of(bit("data"), bit("source"), s.obj, s.source);
  const std::string_view type = kTypes[s.type].name;
  if (!(s.seen & (bit("data") | bit("source"))))
    invalid(at, "a" + std::string(type == "obj" ? "n " : " ") + std::string(type) + " needs \"data\" (" +
                    (type == "obj" ? "OBJ text" : "the model's text") +
                    ") or \"source\" (the name of an uploaded part)");
  std::string_view mtl = text_of(bit("mtl"), bit("mtl_source"), s.mtl, s.mtl_source);
  // An MTL uploaded as part "mtl" goes with a model taken from the uploads.
  if (mtl.empty() && (s.seen & bit("source")) && !(s.seen & bit("mtl_source")))
    if (const auto part = uploads.find("mtl"); part != uploads.end()) mtl = part->second;
  Limits model_limits = limits;
  model_limits.max_texture_pixels = texels_left(scene, limits);
  // Bytes that do not tell their format: "format", else the uploaded part's file name (a scene's
  // "source": "part.stl"), as for a model sent alone.
  std::optional<ModelFormat> hint = type == "obj" ? ModelFormat::obj : s.format;
  if (!hint && (s.seen & bit("source"))) hint = format_of_file_name(s.source);
  Mesh mesh = checks::model_mesh(obj, hint, model_limits, (s.seen & bit("textures")) ? s.textures : uploads,
                                 mtl, at.str(), at.byte());
  if (s.seen & bit("color")) {  // an explicit colour wins over the model's own
    mesh.colors = {s.color};
    mesh.face_colors.clear();
  }
  if (s.seen & bit("shading")) mesh.shading = s.mesh.shading;
  if (s.seen & bit("cull")) mesh.cull = s.mesh.cull;
  if (s.seen & bit("wireframe")) mesh.wireframe = s.mesh.wireframe;
  if (s.seen & bit("edges")) mesh.edges = s.mesh.edges;
  if (s.seen & bit("transform")) mesh.transform = s.mesh.transform;
  if (s.seen & bit("point_size")) mesh.point_size = s.mesh.point_size;
  s.mesh = std::move(mesh);
}

// The type decides what else a primitive may hold, so a wrong or missing "type" is the error to report,
// wherever it stands in the object. Only after an error: the object is read again from its start.
void Reader::type_first(JsonCursor::Mark start, const Path& at) {
  JsonCursor look = in.from(start);
  try {
    if (look.peek() != Kind::object) return;
    for (bool more = look.object_begin(); more; more = look.object_next()) {
      if (look.key() != "type") {
        look.skip();
        continue;
      }
      const Kind k = look.peek();
      const Path type(at, "type", look.offset());
      if (k != Kind::string) invalid(type, std::string("expected a string, got ") + phrase(k));
      PrimitiveState probe;
      return set_type(probe, look.string(), type);
    }
  } catch (const SceneError& e) {
    if (e.kind() == ErrorKind::syntax) return;  // malformed: parse_scene reports that
    throw;
  }
  invalid(at, std::string("missing \"type\" (") + kTypeNames + ")");
}

void Reader::primitive(const Path& at) {
  PrimitiveState& s = prim;
  s.reset();
  s.byte = at.byte();
  const JsonCursor::Mark start = in.mark();
  try {
    read_object(kPrimitiveFields, s, at, "a primitive object");
  } catch (const SceneError&) {
    if (s.type < 0) type_first(start, at);  // a key before "type" was wrong: is "type" itself?
    throw;
  }
  if (s.type < 0) invalid(at, std::string("missing \"type\" (") + kTypeNames + ")");
  if (kTypes[s.type].kind == PrimitiveKind::shader) return finish_shader(s, at);
  if (kTypes[s.type].kind != PrimitiveKind::mesh) return finish_drawn(s, at);
  s.seen_model = true;
  if (kTypes[s.type].name == "mesh")
    finish_mesh(s, at);
  else
    finish_model(s, at);
  Primitive p;
  p.kind = PrimitiveKind::mesh;
  p.mesh = static_cast<std::uint32_t>(scene.meshes.size());
  scene.meshes.push_back(std::move(s.mesh));
  s.mesh = Mesh{};
  scene.primitives.push_back(p);
}

void Reader::finish_shader(PrimitiveState& s, const Path& at) {
  if (!(s.seen & bit("source")))
    invalid(at, "a shader needs \"source\": the program as ShaderToy's editor holds it (a mainImage)");
  s.seen_shader = true;
  s.shader.source = s.source;
  Primitive p;
  p.kind = PrimitiveKind::shader;
  p.mesh = static_cast<std::uint32_t>(scene.shaders.size());
  scene.shaders.push_back(std::move(s.shader));
  scene.primitives.push_back(p);
}

void Reader::primitives(const Path& at) {
  std::size_t i = 0;
  const JsonCursor::Mark start = in.mark();
  const std::string over = "more primitives than the limit of " + std::to_string(limits.max_primitives);
  for (bool more = in.array_begin(); more; more = in.array_next(), ++i) {
    const Path p = element(at, i);
    if (static_cast<std::int64_t>(i) >= limits.max_primitives) fail(ErrorKind::limit, at, over);
    if ((i + 1) % detail::kLinesPerCheck == 0) detail::stop_if_expired(limits);
    try {
      primitive(p);
    } catch (const SceneError& e) {
      if (e.kind() == ErrorKind::syntax) throw;
      // Too many primitives is the error to report, before what is wrong in one of them: count them.
      JsonCursor look = in.from(start);
      try {
        std::int64_t n = 0;
        for (bool more = look.array_begin(); more && n <= limits.max_primitives; more = look.array_next())
          look.skip(), ++n;
        if (n > limits.max_primitives) fail(ErrorKind::limit, at, over);
      } catch (const SceneError& count) {
        if (count.kind() != ErrorKind::syntax) throw;
      }
      throw;
    }
  }
}

namespace {

// The image's side: a whole number in 1..the limit.
int side(Reader& r, const Path& at, std::string_view key, int max_side) {
  const double v = r.number(at);
  try {
    return checks::image_side(key, v, r.in.number_text(), max_side);
  } catch (const SceneError& e) {
    r.fail(e.kind(), at, e.what());
  }
}

constexpr Field<Keys> kRootFields[] = {
    {"primitives", format::kArray, "an array", [](Reader& r, Keys&, const Path& at) { r.primitives(at); }},
    {"width", format::kNumber, "a number",
     [](Reader& r, Keys&, const Path& at) { r.scene.width = side(r, at, "width", r.limits.max_width); }},
    {"height", format::kNumber, "a number",
     [](Reader& r, Keys&, const Path& at) { r.scene.height = side(r, at, "height", r.limits.max_height); }},
    {"background", format::kString | format::kArray, "a colour (\"#rrggbb\" or [r, g, b])",
     [](Reader& r, Keys&, const Path& at) { r.scene.background = r.color(at); }},
    {"antialias", format::kString | format::kNumber, "\"area\", \"auto\" or a number",
     [](Reader& r, Keys&, const Path& at) {
       const std::string rule(format::kAntialiasRule);
       if (r.in.peek() == Kind::string) {
         const std::string_view s = r.in.string();
         if (s != "area" && s != "auto") r.invalid(at, rule + "\"" + std::string(s) + "\"");
         return void(r.scene.antialias = s == "area" ? Antialias::area : Antialias::automatic);
       }
       if (!antialias_of_samples(r.integer(at), r.scene.antialias)) r.invalid(at, rule + r.number_text());
     }},
    {"camera", format::kObject, "a camera object",
     [](Reader& r, Keys&, const Path& at) { r.scene.camera = r.camera(at); }},
    {"light", format::kObject, "a light object",
     [](Reader& r, Keys&, const Path& at) { r.scene.lights = r.light(at); }},
    {"lights", format::kArray, "an array of lights", [](Reader& r, Keys&, const Path& at) { r.lights(at); }},
    // What editors and JSON Schema give a document: the schema it follows, and a note. Neither draws.
    {"$schema", format::kString, "a string", [](Reader& r, Keys&, const Path&) { r.in.string(); }},
    {"$comment", format::kString, "a string", [](Reader& r, Keys&, const Path&) { r.in.string(); }},
};

}  // namespace

void Reader::read_root() {
  const Path root;
  Keys keys;
  if (const Kind k = in.peek(); k != Kind::object)
    invalid(root, std::string("a scene is a JSON object, got ") + phrase(k));
  read_object(kRootFields, keys, root, "a scene object");
  in.finish();
  for (const char* key : {"width", "height"})
    if (!(keys.seen & format::mask_of(kRootFields, {key})))
      invalid(root, std::string("missing \"") + key + "\" (image size in pixels)");
  try {
    checks::image_size(scene.width, scene.height, limits);
  } catch (const SceneError& e) {
    fail(e.kind(), root, e.what());
  }
  if ((keys.seen & format::mask_of(kRootFields, {"light"})) &&
      (keys.seen & format::mask_of(kRootFields, {"lights"})))
    invalid(Path(root, "lights", 1), "\"light\" (one light) and \"lights\" (a list) exclude each other");
}

}  // namespace scene_reader

Scene parse_scene(std::string_view text, const Limits& limits, const Uploads& uploads) {
  if (text.empty())
    throw SceneError(ErrorKind::syntax, "the scene is empty (0 bytes); expected a JSON object");
  // What the parsed primitives hold is bounded by the text's size; a model a primitive names is asked for
  // by its reader once counted.
  detail::reserve(limits, cost::kScenePerByte * static_cast<std::int64_t>(text.size()),
                  [&] { return "the scene's " + std::to_string(text.size()) + " bytes"; });
  scene_reader::Reader r{JsonCursor(text, limits.max_json_depth), limits, uploads, {}, {}};
  r.reserve(text);
  try {
    r.read_root();  // checks the UTF-8 of every string it reads, so a scene read to the end is UTF-8
  } catch (const SceneError& e) {
    // JSON text is UTF-8 (RFC 8259 8.1): a byte that is not is the first thing to report, wherever it is.
    require_utf8(text, "the scene");
    if (e.kind() == ErrorKind::syntax) throw;
    // Then syntax: a document that is not well-formed is reported as such, whatever else is wrong in it.
    JsonCursor whole(text, limits.max_json_depth);
    whole.skip();
    whole.finish();
    throw;
  }
  validate(r.scene);  // the checks across fields, shared with scenes built in code
  return std::move(r.scene);
}

}  // namespace raster
