// The model-format table, and which reader a model goes to: its bytes first, then a file name's extension
// or the format a request names (the hint). One reader per format: obj.cpp, stl.cpp, ply.cpp, gltf.cpp,
// threemf.cpp.
#include <algorithm>
#include <array>
#include <cstring>
#include <string>

#include "base/text.h"
#include "raster/model.h"

namespace raster {
namespace {

using detail::iequals;

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

std::string_view skip_blanks(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && is_blank(s[i])) ++i;
  return s.substr(i);
}

std::string_view first_word(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && !is_blank(s[i])) ++i;
  return s.substr(0, i);
}

// The top-level properties of a glTF 2.0 document (the schema's glTF.schema.json). A scene document has
// none of them, so the first key tells the two apart without reading further.
bool is_gltf_key(std::string_view key) {
  static constexpr std::string_view kKeys[] = {"asset",
                                               "scene",
                                               "scenes",
                                               "nodes",
                                               "meshes",
                                               "accessors",
                                               "bufferViews",
                                               "buffers",
                                               "materials",
                                               "textures",
                                               "images",
                                               "samplers",
                                               "animations",
                                               "cameras",
                                               "skins",
                                               "extensionsUsed",
                                               "extensionsRequired",
                                               "extensions",
                                               "extras"};
  return std::find(std::begin(kKeys), std::end(kKeys), key) != std::end(kKeys);
}

bool looks_like_gltf_json(std::string_view bytes) {
  bytes = skip_blanks(without_bom(bytes));
  if (!bytes.starts_with('{')) return false;
  bytes = skip_blanks(bytes.substr(1));
  if (!bytes.starts_with('"')) return false;
  const std::size_t end = bytes.find('"', 1);
  return end != std::string_view::npos && is_gltf_key(bytes.substr(1, end - 1));
}

bool looks_like_ascii_stl(std::string_view bytes) {
  bytes = skip_blanks(bytes);
  if (bytes.size() < 5 || !iequals(bytes.substr(0, 5), "solid")) return false;
  const std::size_t line_end = bytes.find('\n');
  if (line_end == std::string_view::npos) return false;
  const std::string_view next = first_word(skip_blanks(bytes.substr(line_end + 1)));
  return iequals(next, "facet") || iequals(next, "endsolid");
}

bool looks_like_binary_stl(std::string_view bytes) {
  if (bytes.size() < 84) return false;
  std::uint32_t count = 0;
  for (int k = 3; k >= 0; --k) count = count << 8 | static_cast<unsigned char>(bytes[80 + k]);
  return bytes.size() == 84 + 50 * std::uint64_t{count};
}

bool looks_like_obj(std::string_view bytes) {
  bytes = without_bom(bytes);
  while (true) {
    bytes = skip_blanks(bytes);
    if (bytes.empty()) return true;  // only comments and blank lines: an empty OBJ, which parse_obj reports
    if (bytes.front() != '#') break;
    const std::size_t eol = bytes.find('\n');
    if (eol == std::string_view::npos) return true;
    bytes.remove_prefix(eol + 1);
  }
  // No statement is longer than 10 letters: a longer first word is not one, and a minified JSON scene (one
  // "word" of megabytes) is told apart without reading it all (that scan was 5-7 ms of a 7.5 MB scene).
  return is_obj_statement(first_word(bytes.substr(0, 16)));
}

bool looks_like_glb(std::string_view bytes) {
  return bytes.size() >= 12 && bytes.starts_with("glTF") && bytes[4] == 2 && bytes[5] == 0 && bytes[6] == 0 &&
         bytes[7] == 0;
}

bool looks_like_ply(std::string_view bytes) {
  return bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n");
}

// A ZIP archive's local header magic: 3MF is an OPC package, a ZIP archive (other archives are then told
// apart by their content: no 3D model part).
bool looks_like_3mf(std::string_view bytes) {
  return bytes.starts_with(std::string_view("PK\x03\x04", 4));
}

bool looks_like_stl(std::string_view bytes) {
  return looks_like_ascii_stl(bytes) || looks_like_binary_stl(bytes);
}

// The readers and file lists under the table's one signature each.
Mesh read_obj(std::string_view bytes, const Limits& limits, const Uploads& files, std::string_view mtl_text) {
  return parse_obj(bytes, mtl_text, limits, files);
}
Mesh read_stl(std::string_view bytes, const Limits& limits, const Uploads&, std::string_view) {
  return parse_stl(bytes, limits);
}
Mesh read_ply(std::string_view bytes, const Limits& limits, const Uploads&, std::string_view) {
  return parse_ply(bytes, limits);
}
Mesh read_gltf(std::string_view bytes, const Limits& limits, const Uploads& files, std::string_view) {
  return parse_gltf(bytes, limits, files);
}
Mesh read_3mf(std::string_view bytes, const Limits& limits, const Uploads&, std::string_view) {
  return parse_3mf(bytes, limits);
}
std::vector<std::string> files_of_gltf(std::string_view bytes, std::string_view, const Uploads&) {
  return gltf_files(bytes);
}

constexpr std::string_view kObjExtensions[] = {"obj"}, kStlExtensions[] = {"stl"}, kPlyExtensions[] = {"ply"},
                           kGltfExtensions[] = {"gltf"}, kGlbExtensions[] = {"glb"},
                           k3mfExtensions[] = {"3mf"};
constexpr std::string_view kObjTypes[] = {"model/obj", "text/x-obj"};
constexpr std::string_view kStlTypes[] = {"model/stl", "model/x.stl-ascii", "model/x.stl-binary",
                                          "application/sla", "application/vnd.ms-pki.stl"};
constexpr std::string_view kPlyTypes[] = {"model/ply", "application/ply"};
constexpr std::string_view kGltfTypes[] = {"model/gltf+json"};
constexpr std::string_view kGlbTypes[] = {"model/gltf-binary"};
constexpr std::string_view k3mfTypes[] = {"model/3mf",
                                          "application/vnd.ms-package.3dmanufacturing-3dmodel+xml"};

constexpr Vec3 kYUp{0, 1, 0}, kZUp{0, 0, 1};
constexpr ModelFormatInfo kFormats[] = {
    {ModelFormat::obj, "obj", kObjExtensions, kObjTypes, looks_like_obj, read_obj, obj_files, 2, kYUp},
    {ModelFormat::stl, "stl", kStlExtensions, kStlTypes, looks_like_stl, read_stl, nullptr, 0, kZUp},
    {ModelFormat::ply, "ply", kPlyExtensions, kPlyTypes, looks_like_ply, read_ply, nullptr, 0, kYUp},
    {ModelFormat::gltf, "gltf", kGltfExtensions, kGltfTypes, looks_like_gltf_json, read_gltf, files_of_gltf,
     1, kYUp},
    {ModelFormat::glb, "glb", kGlbExtensions, kGlbTypes, looks_like_glb, read_gltf, files_of_gltf, 1, kYUp},
    {ModelFormat::threemf, "3mf", k3mfExtensions, k3mfTypes, looks_like_3mf, read_3mf, nullptr, 0, kZUp},
};
static_assert(std::size(kFormats) == kModelFormatCount);
// model_format() finds a row by its enum value.
static_assert([] {
  for (std::size_t i = 0; i < std::size(kFormats); ++i)
    if (static_cast<std::size_t>(kFormats[i].format) != i) return false;
  return true;
}());

// The order sniff_model tries the tests in: a test that is sure (a magic number) before a looser one that
// could also match the same bytes (a binary STL's free header may start like JSON or like an OBJ
// statement; "glTF" bytes are no text), and OBJ, whose test is a first word, last.
constexpr ModelFormat kSniffOrder[] = {ModelFormat::glb, ModelFormat::threemf, ModelFormat::ply,
                                       ModelFormat::stl, ModelFormat::gltf,    ModelFormat::obj};

// The media type of a Content-Type: before any ';', without trailing blanks, in lower case.
std::string bare_media_type(std::string_view content_type) {
  std::string type(content_type.substr(0, content_type.find(';')));
  while (!type.empty() && (type.back() == ' ' || type.back() == '\t')) type.pop_back();
  std::transform(type.begin(), type.end(), type.begin(), detail::ascii_lower);
  return type;
}

}  // namespace

std::span<const ModelFormatInfo> model_formats() {
  return kFormats;
}

const ModelFormatInfo& model_format(ModelFormat format) {
  return kFormats[static_cast<std::size_t>(format)];
}

const std::array<std::string_view, kModelFormatCount>& format_names() {
  static constexpr std::array<std::string_view, kModelFormatCount> kNames = [] {
    std::array<std::string_view, kModelFormatCount> names;
    for (std::size_t i = 0; i < names.size(); ++i) names[i] = kFormats[i].name;
    return names;
  }();
  return kNames;
}

std::string_view format_name(ModelFormat format) {
  return model_format(format).name;
}

std::optional<ModelFormat> format_named(std::string_view name) {
  for (const ModelFormatInfo& row : kFormats)
    if (iequals(name, row.name)) return row.format;
  return std::nullopt;
}

bool is_obj_statement(std::string_view word) {
  // OBJ 3.0's statements: geometry, grouping, display and free-form (curves and surfaces).
  static constexpr std::string_view kStatements[] = {
      "v",    "vt",    "vn",       "vp",       "f",          "fo",        "l",      "p",     "o",    "g",
      "s",    "mg",    "mtllib",   "usemtl",   "usemap",     "maplib",    "cstype", "deg",   "bmat", "step",
      "curv", "curv2", "surf",     "parm",     "trim",       "hole",      "scrv",   "sp",    "end",  "con",
      "lod",  "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech",  "stech", "call", "csh"};
  return std::find(std::begin(kStatements), std::end(kStatements), word) != std::end(kStatements);
}

std::string_view accepted_formats() {
  return "OBJ, STL (ASCII or binary), PLY (ASCII or binary), glTF 2.0 (.gltf or .glb) and 3MF";
}

std::optional<ModelFormat> sniff_model(std::string_view bytes) {
  for (const ModelFormat format : kSniffOrder)
    if (model_format(format).sniff(bytes)) return format;
  return std::nullopt;
}

std::optional<ModelFormat> format_of_file_name(std::string_view file_name) {
  const std::size_t dot = file_name.find_last_of('.');
  if (dot == std::string_view::npos) return std::nullopt;
  const std::string_view extension = file_name.substr(dot + 1);
  for (const ModelFormatInfo& row : kFormats)
    for (const std::string_view e : row.extensions)
      if (iequals(extension, e)) return row.format;
  return std::nullopt;
}

std::optional<ModelFormat> format_of_media_type(std::string_view media_type) {
  const std::string type = bare_media_type(media_type);
  for (const ModelFormatInfo& row : kFormats)
    for (const std::string_view t : row.media_types)
      if (type == t) return row.format;
  return std::nullopt;
}

ModelFormat model_format_of(std::string_view bytes, std::optional<ModelFormat> hint) {
  return model_format_of(bytes, hint, sniff_model(bytes));
}

ModelFormat model_format_of(std::string_view bytes, std::optional<ModelFormat> hint,
                            std::optional<ModelFormat> sniffed) {
  if (sniffed) return *sniffed;
  if (hint) return *hint;
  if (skip_blanks(bytes).empty())
    throw SceneError(ErrorKind::model,
                     "the model is empty; rasterd reads " + std::string(accepted_formats()));
  throw SceneError(ErrorKind::model, "the model is in no format rasterd reads: its first bytes are not " +
                                         std::string(accepted_formats()) +
                                         ". Name the format if the bytes are one of them (?format=stl, "
                                         "or \"format\" in the scene)");
}

Mesh parse_model(std::string_view bytes, std::optional<ModelFormat> hint, const Limits& limits,
                 const Uploads& files, std::string_view mtl_text) {
  return model_format(model_format_of(bytes, hint)).read(bytes, limits, files, mtl_text);
}

Scene model_scene(Mesh mesh, ModelFormat format) {
  Scene scene;
  scene.width = kModelPicture.width;
  scene.height = kModelPicture.height;
  scene.background = kModelPicture.background;
  scene.antialias = kModelPicture.antialias;
  scene.camera.view = View::three_quarter;
  scene.camera.fit = CameraFit::vertices;
  const Vec3& up = model_format(format).up;
  if (up != Vec3{0, 1, 0}) scene.camera.up = up, scene.camera.has_up = true;
  scene.meshes.push_back(std::move(mesh));
  Primitive model;
  model.kind = PrimitiveKind::mesh;
  scene.primitives.push_back(model);
  return scene;
}

}  // namespace raster
