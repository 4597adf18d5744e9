// An OBJ model's materials: the MTL text fixed for tinyobjloader in one pass (keywords in its spelling,
// map_Kd read here, with its options), the libraries a model names found among the uploads, the textures
// its materials name decoded once each, and obj_files(), the files a model and its MTL name.
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <istream>
#include <map>
#include <string>
#include <vector>

#include "model/obj_mtl.h"

#include "base/budget_ask.h"
#include "base/text.h"
#include "raster/model.h"
#include "raster/utf8.h"

namespace raster::obj {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

using detail::iequals;

bool is_number(std::string_view w, double* out = nullptr) {
  double d = 0;
  const auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), d);
  if (ec != std::errc() || p != w.data() + w.size() || !std::isfinite(d)) return false;
  if (out) *out = d;
  return true;
}

// A file name as an MTL or OBJ line writes it, without its folders (either slash) and outer blanks: files
// arrive as uploads named by file, never from this disk.
std::string file_name_of(std::string_view path) {
  std::string name(trim(path));
  std::replace(name.begin(), name.end(), '\\', '/');
  if (const std::size_t slash = name.rfind('/'); slash != std::string::npos) name.erase(0, slash + 1);
  return std::string(trim(name));
}

[[noreturn]] void mtl_error(std::size_t line, const std::string& message) {
  model_error(0, "the materials (MTL), line " + std::to_string(line) + ": " + message);
}

// "map_Kd [options] file name": the options of the MTL spec with their argument counts, then the name.
DiffuseMap read_diffuse_map(std::string_view rest, std::size_t line) {
  DiffuseMap map;
  map.line = line;
  std::size_t i = 0;
  auto next_word = [&](std::size_t& start) {
    while (i < rest.size() && is_space(rest[i])) ++i;
    start = i;
    while (i < rest.size() && !is_space(rest[i])) ++i;
    return rest.substr(start, i - start);
  };
  std::size_t start = 0;
  for (;;) {
    const std::size_t before = i;
    const std::string_view w = next_word(start);
    if (w.empty()) mtl_error(line, "map_Kd names no texture file");
    if (w.size() < 2 || w[0] != '-' || !std::isalpha(static_cast<unsigned char>(w[1]))) {
      i = before;
      break;  // the file name starts here
    }
    std::size_t at = 0;
    auto numbers = [&](int min, int most, float* into) {
      int n = 0;
      for (; n < most; ++n) {
        const std::size_t keep = i;
        double d = 0;
        if (!is_number(next_word(at), &d)) {
          i = keep;
          break;
        }
        if (std::fabs(d) > 1e30)
          mtl_error(line, "map_Kd option " + std::string(w) + " takes numbers within +-1e30");
        if (into) into[n] = static_cast<float>(d);
      }
      if (n < min) mtl_error(line, "map_Kd option " + std::string(w) + " needs a number");
    };
    if (iequals(w, "-clamp") || iequals(w, "-blendu") || iequals(w, "-blendv") || iequals(w, "-cc")) {
      const std::string_view v = next_word(at);
      if (!iequals(v, "on") && !iequals(v, "off"))
        mtl_error(line,
                  "map_Kd option " + std::string(w) + " takes on or off, got \"" + std::string(v) + "\"");
      if (iequals(w, "-clamp")) map.clamp = iequals(v, "on");
    } else if (iequals(w, "-s")) {
      float v[3] = {1, 1, 1};
      numbers(1, 3, v);
      map.scale = {v[0], v[1]};
    } else if (iequals(w, "-o")) {
      float v[3] = {0, 0, 0};
      numbers(1, 3, v);
      map.offset = {v[0], v[1]};
    } else if (iequals(w, "-t")) {
      numbers(1, 3, nullptr);
    } else if (iequals(w, "-mm")) {
      numbers(2, 2, nullptr);
    } else if (iequals(w, "-bm") || iequals(w, "-boost") || iequals(w, "-texres")) {
      numbers(1, 1, nullptr);
    } else if (iequals(w, "-imfchan") || iequals(w, "-type") || iequals(w, "-colorspace")) {
      next_word(at);
    } else {
      mtl_error(line, "map_Kd option " + std::string(w) + " is not an MTL texture option");
    }
  }
  std::string name = file_name_of(rest.substr(i));
  if (name.empty()) mtl_error(line, "map_Kd names a folder, not a texture file");
  map.file = std::move(name);
  return map;
}

// The uploaded `file`: by exact name, else by a name that differs only in case (models made on Windows
// name "Head.PNG" for "head.png").
const std::string* find_file(const Uploads& files, const std::string& file) {
  if (file.empty()) return nullptr;
  if (auto it = files.find(file); it != files.end()) return &it->second;
  const std::string* found = nullptr;
  for (const auto& [name, bytes] : files)
    if (iequals(name, file)) {
      if (found) return nullptr;  // ambiguous
      found = &bytes;
    }
  return found;
}

std::string names_of(const Uploads& files) {
  if (files.empty()) return "none";
  std::string out;
  for (const auto& [name, bytes] : files) out += (out.empty() ? "\"" : ", \"") + name + "\"";
  return out;
}

}  // namespace

MtlPass read_mtl(std::string_view mtl) {
  // Keywords tinyobjloader matches, in its spelling; any case is accepted in the file.
  static constexpr std::string_view kKeywords[] = {
      "newmtl",   "Ka",   "Kd",    "Ks",     "Ke",     "Kt",     "Tf",     "Ns",
      "Ni",       "d",    "Tr",    "illum",  "map_Ka", "map_Ks", "map_Ns", "map_d",
      "map_bump", "bump", "disp",  "refl",   "norm",   "Pr",     "Pm",     "Ps",
      "Pc",       "Pcr",  "aniso", "anisor", "map_Pr", "map_Pm", "map_Ps", "map_Ke"};
  MtlPass out;
  out.text.reserve(mtl.size());
  MaterialExtra* current = nullptr;
  std::size_t line_no = 0;
  for (std::size_t pos = 0; pos <= mtl.size();) {
    std::size_t end = mtl.find('\n', pos);
    if (end == std::string_view::npos) end = mtl.size();
    const std::string_view line = trim(mtl.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    std::size_t k = 0;
    while (k < line.size() && !is_space(line[k])) ++k;
    const std::string_view key = line.substr(0, k), rest = trim(line.substr(k));
    if (iequals(key, "map_Kd")) {
      if (current) current->has_map = true, current->map = read_diffuse_map(rest, line_no);
      out.text += '\n';
      continue;
    }
    std::string_view spelled = key;
    for (std::string_view known : kKeywords)
      if (iequals(key, known)) spelled = known;
    // A `newmtl` without a name is passed to tinyobjloader as "newmtl", which it does not take for the
    // statement: the material before goes on, for its Kd as for its map_Kd here.
    if (spelled == "newmtl" && !rest.empty()) current = &out.materials[std::string(rest)];
    if (spelled == "Kd" && current) current->has_kd = true;
    out.text.append(spelled).append(rest.empty() ? "" : " ").append(rest) += '\n';
  }
  return out;
}

std::string named_libraries(const std::vector<std::string_view>& mtllibs, const Uploads& files) {
  std::string text;
  std::vector<const std::string*> used;
  auto append = [&](const std::string* bytes) {
    if (!bytes || std::find(used.begin(), used.end(), bytes) != used.end()) return;
    used.push_back(bytes);
    text += *bytes;
    if (!text.empty() && text.back() != '\n') text += '\n';
  };
  for (std::string_view rest : mtllibs) {
    if (const std::string* whole = find_file(files, file_name_of(rest))) {
      append(whole);
      continue;
    }
    for (std::string_view word : words(rest)) append(find_file(files, file_name_of(word)));
  }
  return text;
}

TexturePlan plan_textures(const std::vector<tinyobj::material_t>& materials, const MtlPass& mtl) {
  TexturePlan plan{{std::vector<const MaterialExtra*>(materials.size(), nullptr),
                    std::vector<std::int32_t>(materials.size(), -1)},
                   {}};
  std::map<std::string, std::int32_t, std::less<>> index;  // a file's index in the mesh's textures
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const auto it = mtl.materials.find(materials[m].name);
    if (it == mtl.materials.end()) continue;
    plan.materials.extras[m] = &it->second;
    if (!it->second.has_map) continue;
    const DiffuseMap& map = it->second.map;
    const auto [at, fresh] = index.emplace(map.file, static_cast<std::int32_t>(plan.maps.size()));
    if (fresh) plan.maps.push_back(&map);
    plan.materials.texture[m] = at->second;
  }
  return plan;
}

void decode_textures(const TexturePlan& plan, const Uploads& files, const Limits& limits,
                     std::vector<Texture>& textures) {
  std::int64_t budget = limits.max_texture_pixels;
  for (const DiffuseMap* map : plan.maps) {
    const std::string* bytes = find_file(files, map->file);
    if (!bytes)
      model_error(0, "the materials (MTL) line " + std::to_string(map->line) + " asks for texture \"" +
                         map->file + "\" (map_Kd), which was not sent; sent: " + names_of(files) +
                         ". Send it as a multipart part with that file name (curl -F 'texture=@" + map->file +
                         "')");
    detail::stop_if_expired(limits);  // each decoding is bounded by the texel budget; asked before each
    Texture texture = decode_texture(*bytes, map->file, budget);
    budget -= std::int64_t{texture.width} * texture.height;
    texture.clamp = map->clamp, texture.scale = map->scale, texture.offset = map->offset;
    textures.push_back(std::move(texture));
  }
}

std::vector<std::int32_t> specular_materials(const std::vector<tinyobj::material_t>& materials,
                                             const MaterialTextures& textures, Mesh& mesh) {
  std::vector<std::int32_t> surface(materials.size(), -1);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (!textures.extras[m]) continue;
    Material look;
    look.model = Material::Model::blinn_phong;
    for (int c = 0; c < 3; ++c) {  // within 0..1, NaN as 0
      const float ks = static_cast<float>(materials[m].specular[c]);
      look.specular[c] = ks > 0 ? std::min(ks, 1.0f) : 0.0f;
    }
    // NaN (from "Ns nan") is no exponent: the MTL's range's end, like any value above it.
    const float ns = static_cast<float>(materials[m].shininess);
    look.shininess = ns >= 0 ? std::min(ns, 1000.0f) : ns < 0 ? 0.0f : 1000.0f;
    if (!look.is_specular()) continue;
    surface[m] = static_cast<std::int32_t>(mesh.materials.size());
    mesh.materials.push_back(look);
  }
  return surface;
}

ObjMaterials read_materials(std::string_view mtl_text, const std::vector<std::string_view>& mtllibs,
                            const Uploads& files, MtlPass& mtl, Mesh& mesh) {
  std::string libraries;
  if (mtl_text.empty() && !mtllibs.empty()) {
    libraries = named_libraries(mtllibs, files);
    require_utf8(libraries, "the materials (MTL)", true);
    mtl_text = libraries;
  }
  mtl = read_mtl(mtl_text);
  ObjMaterials out;
  TextBuf buf(mtl.text);
  std::istream in(&buf);
  std::string warning, error;
  tinyobj::LoadMtl(&out.by_name, &out.list, &in, &warning, &error);
  out.textures = plan_textures(out.list, mtl);
  out.surface = specular_materials(out.list, out.textures.materials, mesh);
  return out;
}

MaterialTextures material_textures(const std::vector<tinyobj::material_t>& materials, const MtlPass& mtl,
                                   const Uploads& files, const Limits& limits,
                                   std::vector<Texture>& textures) {
  TexturePlan plan = plan_textures(materials, mtl);
  const std::size_t first = textures.size();
  decode_textures(plan, files, limits, textures);
  for (std::int32_t& t : plan.materials.texture)
    if (t >= 0) t += static_cast<std::int32_t>(first);
  return std::move(plan.materials);
}

}  // namespace raster::obj

namespace raster {

using namespace obj;  // obj_files is made of the MTL pass above

std::vector<std::string> obj_files(std::string_view obj_text, std::string_view mtl_text,
                                   const Uploads& files) {
  std::vector<std::string> names;
  auto add = [&](std::string name) {
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(std::move(name));
  };
  std::vector<std::string_view> mtllibs;
  // Only the lines holding "mtllib" are split into words (a vector of words for each of a large model's
  // million lines was 17% of its CLI render), and a line once: where the statement is its first word.
  constexpr std::string_view kMtllib = "mtllib";
  for (std::size_t at = obj_text.find(kMtllib); at != std::string_view::npos;
       at = obj_text.find(kMtllib, at + kMtllib.size())) {
    const std::size_t newline = obj_text.rfind('\n', at);
    const std::size_t start = newline == std::string_view::npos ? 0 : newline + 1;
    const std::size_t end = std::min(obj_text.find('\n', at), obj_text.size());
    const std::string_view line = obj_text.substr(start, end - start);
    const auto w = words(line);
    if (w.size() < 2 || w[0] != kMtllib || w[0].data() != obj_text.data() + at) continue;
    const std::string_view rest = line.substr(static_cast<std::size_t>(w[1].data() - line.data()));
    mtllibs.push_back(rest);
    add(file_name_of(rest));                                             // one name with spaces, or
    for (std::size_t k = 1; k < w.size(); ++k) add(file_name_of(w[k]));  // several names
  }
  const std::string libraries = mtl_text.empty() ? named_libraries(mtllibs, files) : std::string();
  try {
    for (const auto& [material, extra] : read_mtl(mtl_text.empty() ? libraries : mtl_text).materials)
      if (extra.has_map) add(extra.map.file);
  } catch (const SceneError&) {
    // an MTL with errors names what it names before them; parse_obj reports the error
  }
  return names;
}

}  // namespace raster
