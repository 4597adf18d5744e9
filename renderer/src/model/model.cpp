// Which reader a model goes to: its bytes first, then a file name's extension or the format a request
// names (the hint). One reader per format: obj.cpp, stl.cpp, ply.cpp, gltf.cpp.
#include <algorithm>
#include <array>
#include <cstring>
#include <string>

#include "raster/model.h"

namespace raster {
namespace {

constexpr std::array<std::string_view, 5> kNames = {"obj", "stl", "ply", "gltf", "glb"};

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return (x >= 'A' && x <= 'Z' ? x + 32 : x) == (y >= 'A' && y <= 'Z' ? y + 32 : y);
         });
}

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
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
  bytes = skip_blanks(bytes);
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
  // The statements of OBJ 3.0 (geometry, grouping, display and free-form), as a file's first one.
  static constexpr std::string_view kStatements[] = {
      "v",    "vt",    "vn",       "vp",       "f",          "fo",        "l",      "p",     "o",    "g",
      "s",    "mg",    "mtllib",   "usemtl",   "usemap",     "maplib",    "cstype", "deg",   "bmat", "step",
      "curv", "curv2", "surf",     "parm",     "trim",       "hole",      "scrv",   "sp",    "end",  "con",
      "lod",  "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech",  "stech", "call", "csh"};
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
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
  const std::string_view word = first_word(bytes.substr(0, 16));
  return std::find(std::begin(kStatements), std::end(kStatements), word) != std::end(kStatements);
}

}  // namespace

std::string_view format_name(ModelFormat format) {
  return kNames[static_cast<std::size_t>(format)];
}

std::optional<ModelFormat> format_named(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (iequals(name, kNames[i])) return static_cast<ModelFormat>(i);
  return std::nullopt;
}

std::string_view accepted_formats() {
  return "OBJ, STL (ASCII or binary), PLY (ASCII or binary) and glTF 2.0 (.gltf or .glb)";
}

std::optional<ModelFormat> sniff_model(std::string_view bytes) {
  if (bytes.size() >= 12 && bytes.starts_with("glTF") && bytes[4] == 2 && bytes[5] == 0 && bytes[6] == 0 &&
      bytes[7] == 0)
    return ModelFormat::glb;
  if (bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n")) return ModelFormat::ply;
  if (looks_like_ascii_stl(bytes)) return ModelFormat::stl;
  if (looks_like_binary_stl(bytes)) return ModelFormat::stl;
  if (looks_like_gltf_json(bytes)) return ModelFormat::gltf;
  if (looks_like_obj(bytes)) return ModelFormat::obj;
  return std::nullopt;
}

std::optional<ModelFormat> format_of_file_name(std::string_view file_name) {
  const std::size_t dot = file_name.find_last_of('.');
  if (dot == std::string_view::npos) return std::nullopt;
  return format_named(file_name.substr(dot + 1));
}

Mesh parse_model(std::string_view bytes, std::optional<ModelFormat> hint, const Limits& limits,
                 const Uploads& files, std::string_view mtl_text) {
  std::optional<ModelFormat> format = sniff_model(bytes);
  if (!format) format = hint;
  if (!format) {
    if (skip_blanks(bytes).empty())
      throw SceneError(ErrorKind::model,
                       "the model is empty; rasterd reads " + std::string(accepted_formats()));
    throw SceneError(ErrorKind::model, "the model is in no format rasterd reads: its first bytes are not " +
                                           std::string(accepted_formats()) +
                                           ". Name the format if the bytes are one of them (?format=stl, "
                                           "or \"format\" in the scene)");
  }
  switch (*format) {
    case ModelFormat::obj:
      return parse_obj(bytes, mtl_text, limits, files);
    case ModelFormat::stl:
      return parse_stl(bytes, limits);
    case ModelFormat::ply:
      return parse_ply(bytes, limits);
    case ModelFormat::gltf:
    case ModelFormat::glb:
      return parse_gltf(bytes, limits, files);
  }
  return {};
}

}  // namespace raster
