// OBJ models: text -> Mesh, through tinyobjloader, after validating what tinyobjloader 2.0.0~rc10 does not
// (face indices: negative ones are CVE-2020-28589, out-of-range positive ones only warn).
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <istream>
#include <map>
#include <streambuf>
#include <string>

#include <tiny_obj_loader.h>

#include "base/budget_ask.h"
#include "model/polygon.h"
#include "raster/model.h"
#include "raster/utf8.h"

namespace raster {
namespace {

[[noreturn]] void model_error(std::size_t line, const std::string& message) {
  throw SceneError(ErrorKind::model, message, ErrorLocation{"", 0, line});
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// The whitespace-separated words of one line, into `out` (reused line after line by the prescan: a vector
// made per line was a malloc and a free per line, 7% of a large model's parse).
void split_words(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  split_words(line, out);
  return out;
}

// One index of a face/line/point reference, resolved like OBJ: 1-based, negative = relative to the end.
// Returns false (with `why`) when it is not an integer or does not name an element defined so far.
bool check_index(std::string_view text, std::int64_t defined, const char* what, std::string& why) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    why = std::string(what) + " index \"" + std::string(text) + "\" is not an integer";
    return false;
  }
  const std::int64_t resolved = value < 0 ? defined + value + 1 : value;
  if (value == 0 || resolved < 1 || resolved > defined) {
    why = std::string(what) + " index " + std::to_string(value) + " is out of range (" +
          std::to_string(defined) + " defined so far)";
    return false;
  }
  return true;
}

// A number as OBJ writers print it: what strtod reads, whole, including a leading '+' ("+1", assimp's
// number_formats.obj), which std::from_chars alone refuses.
bool obj_number(std::string_view word, double& d) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '-' && word[1] != '+') word.remove_prefix(1);
  const auto [p, ec] = std::from_chars(word.data(), word.data() + word.size(), d);
  return ec == std::errc() && p == word.data() + word.size() && std::isfinite(d);
}

struct Counts {
  std::int64_t v = 0, vt = 0, vn = 0, faces = 0, segments = 0, points = 0;
  std::int64_t corners = 0;  ///< face corners (references on 'f' lines), what tinyobjloader stores per face
  /// (0-based face number, corners) of each face of 256 corners or more, in file order: tinyobjloader
  /// stores a face's corner count in a byte.
  std::vector<std::pair<std::int64_t, std::uint32_t>> long_faces;
  std::vector<std::string_view> mtllibs;  ///< what follows each `mtllib` (one or more file names)
};

// Validates every line tinyobjloader would index with, before it sees the text.
Counts prescan(std::string_view text, const Limits& limits) {
  Counts n;
  std::size_t line_no = 0;
  std::string why;
  std::vector<std::string_view> w;
  for (std::size_t pos = 0; pos <= text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (++line_no % detail::kLinesPerCheck == 0) detail::stop_if_expired(limits);
    split_words(line, w);
    if (w.empty() || w[0][0] == '#') continue;
    const std::string_view key = w[0];
    if (key == "mtllib" && w.size() > 1) {
      n.mtllibs.push_back(line.substr(static_cast<std::size_t>(w[1].data() - line.data())));
    } else if (key == "v") {
      if (w.size() < 4) model_error(line_no, "a vertex needs x y z");
      for (std::size_t k = 1; k < w.size() && k <= 6; ++k) {
        double d = 0;
        if (!obj_number(w[k], d) || std::fabs(d) > kMaxCoordinate)
          model_error(line_no, "vertex component \"" + std::string(w[k]) +
                                   "\" is not a finite number within +-3.4e38");
      }
      ++n.v;
    } else if (key == "vt") {
      if (w.size() < 2) model_error(line_no, "a texture coordinate needs u (and v)");
      for (std::size_t k = 1; k < w.size() && k <= 3; ++k) {
        double d = 0;
        // The bound a scene's "uvs" have: beyond it a coordinate would not survive its float conversion.
        if (!obj_number(w[k], d) || std::fabs(d) > 1e30)
          model_error(line_no,
                      "texture coordinate \"" + std::string(w[k]) + "\" is not a number within +-1e30");
      }
      ++n.vt;
    } else if (key == "vn") {
      if (w.size() < 4) model_error(line_no, "a normal needs x y z");
      ++n.vn;
    } else if (key == "f" || key == "l" || key == "p") {
      const std::size_t min_refs = key == "f" ? 3 : key == "l" ? 2 : 1;
      if (w.size() - 1 < min_refs)
        model_error(line_no, std::string(key == "f"   ? "a face"
                                         : key == "l" ? "a line"
                                                      : "a point") +
                                 " needs at least " + std::to_string(min_refs) + " vertices");
      for (std::size_t k = 1; k < w.size(); ++k) {
        // v, v/vt, v//vn or v/vt/vn
        const std::string_view ref = w[k];
        const std::size_t s1 = ref.find('/');
        const std::size_t s2 = s1 == std::string_view::npos ? std::string_view::npos : ref.find('/', s1 + 1);
        const std::string_view vi = ref.substr(0, s1);
        bool ok = check_index(vi, n.v, "vertex", why);
        if (ok && s1 != std::string_view::npos) {
          const std::string_view ti =
              ref.substr(s1 + 1, s2 == std::string_view::npos ? std::string_view::npos : s2 - s1 - 1);
          if (!ti.empty()) ok = check_index(ti, n.vt, "texture coordinate", why);
          if (ok && s2 != std::string_view::npos) ok = check_index(ref.substr(s2 + 1), n.vn, "normal", why);
        }
        if (!ok) model_error(line_no, why);
      }
      if (key == "f") {
        n.corners += static_cast<std::int64_t>(w.size()) - 1;
        if (w.size() - 1 >= 256) n.long_faces.push_back({n.faces, static_cast<std::uint32_t>(w.size() - 1)});
        if (++n.faces > limits.max_obj_faces)
          throw SceneError(ErrorKind::limit,
                           "the model has more than " + std::to_string(limits.max_obj_faces) + " faces",
                           ErrorLocation{"", 0, line_no});
      } else if (key == "l") {
        n.segments += static_cast<std::int64_t>(w.size()) - 2;
      } else {
        ++n.points;
      }
    }
  }
  return n;
}

// ---- MTL: what tinyobjloader 2.0.0~rc10 reads differently from the MTL spec and from the files people
// have, fixed in one pass over the text before it sees it (one output line per input line, so its line
// numbers stay the file's):
//  - keywords are case-insensitive ("map_KD", "KD" from some exporters): spelled as tinyobjloader expects;
//  - trailing blanks (and a CR) are removed: tinyobjloader keeps a blank before the CR in names;
//  - map_Kd is read here, not by tinyobjloader: its options take 1-3 numbers ("-s 2 2 file.png" would
//    make tinyobjloader read "file.png" as the third number), names may hold spaces, and a path is
//    reduced to its file name (textures arrive as uploads named by file, never from this disk). Without
//    Kd, a map_Kd is shown as it is (Kd = 1), not darkened to tinyobjloader's 0.6.

/// A material's diffuse map as the MTL gives it.
struct DiffuseMap {
  std::string file;      ///< file name without folders
  std::size_t line = 0;  ///< MTL line, for errors
  bool clamp = false;
  std::array<float, 2> scale{1, 1}, offset{0, 0};
};

/// What the MTL pass learns per material (by name, as tinyobjloader names it).
struct MaterialExtra {
  bool has_kd = false;
  bool has_map = false;
  DiffuseMap map;
};

struct MtlPass {
  std::string text;  ///< for tinyobjloader
  std::map<std::string, MaterialExtra, std::less<>> materials;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

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
    if (spelled == "newmtl") current = &out.materials[std::string(rest)];
    if (spelled == "Kd" && current) current->has_kd = true;
    out.text.append(spelled).append(rest.empty() ? "" : " ").append(rest) += '\n';
  }
  return out;
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

// The materials a model without given MTL text names: each `mtllib` line's files among the uploads, in
// order, each once (f3d#1973: a viewer that ignores mtllib and guesses <model>.mtl finds none of them). A
// line is one name if a file has that whole name (names with spaces), else names separated by blanks.
// Libraries that were not sent are left out: a bare model keeps its default colours.
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

std::uint8_t unit_byte(double v) {
  return static_cast<std::uint8_t>(std::floor(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5));
}

}  // namespace

std::vector<std::string> obj_files(std::string_view obj_text, std::string_view mtl_text,
                                   const Uploads& files) {
  std::vector<std::string> names;
  auto add = [&](std::string name) {
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(std::move(name));
  };
  std::vector<std::string_view> mtllibs;
  for (std::size_t pos = 0; pos <= obj_text.size();) {
    std::size_t end = obj_text.find('\n', pos);
    if (end == std::string_view::npos) end = obj_text.size();
    const std::string_view line = obj_text.substr(pos, end - pos);
    pos = end + 1;
    const auto w = words(line);
    if (w.size() < 2 || w[0] != "mtllib") continue;
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

namespace {

// A read-only stream buffer over text held elsewhere (tinyobjloader reads lines with sbumpc/sgetc only).
class TextBuf : public std::streambuf {
 public:
  explicit TextBuf(std::string_view text) {
    char* first = const_cast<char*>(text.data());  // a get area only: nothing is written through it
    setg(first, first, first + text.size());
  }
};

}  // namespace

Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text, const Limits& limits,
               const Uploads& files) {
  // Checked first: names and tokens of the model are quoted in its errors.
  require_utf8(obj_text, "the model (OBJ)", true);
  require_utf8(mtl_text, "the materials (MTL)", true);
  const Counts counts = prescan(obj_text, limits);
  if (counts.v == 0) model_error(0, "the model is empty: it defines no vertices");
  if (counts.faces == 0 && counts.segments == 0)
    model_error(0, counts.points ? "the model has only points ('p'); rasterd draws faces and lines"
                                 : "the model has no faces ('f') or lines ('l') to draw");

  std::string libraries;
  if (mtl_text.empty() && !counts.mtllibs.empty()) {
    libraries = named_libraries(counts.mtllibs, files);
    require_utf8(libraries, "the materials (MTL)", true);
    mtl_text = libraries;
  }
  const MtlPass mtl = read_mtl(mtl_text);
  // The prescan has counted what tinyobjloader and the mesh will hold: asked for before either is built.
  detail::reserve(limits,
                  cost::kObjPerCorner * (counts.corners + 2 * counts.segments + counts.points) +
                      cost::kObjPerVertex * (counts.v + counts.vt + counts.vn),
                  [&] {
                    return "the model's " + std::to_string(counts.faces) + " faces and " +
                           std::to_string(counts.v) + " vertices";
                  });

  // What ObjReader::ParseFromString does (but faces as written, split below as PLY's are; colours only
  // where the file has them: no white fallback), on a stream over the text where it lies: ParseFromString
  // copied a model twice (into a std::string, then into a stringbuf), 2 x its size of fresh memory per
  // request. From memory: a `mtllib` line reads the uploaded MTL text, never a file named in the upload.
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  {
    TextBuf obj_buf(obj_text), mtl_buf(mtl.text);
    std::istream obj_stream(&obj_buf), mtl_stream(&mtl_buf);
    tinyobj::MaterialStreamReader mtl_reader(mtl_stream);
    std::string warning, error;
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &obj_stream, &mtl_reader,
                          /*triangulate=*/false, /*default_vcols_fallback=*/false))
      model_error(0, "the model could not be parsed: " + error);
  }

  Mesh mesh;
  mesh.positions.reserve(attrib.vertices.size() / 3);
  for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
    mesh.positions.push_back({attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
  mesh.normals.reserve(attrib.normals.size() / 3);
  for (std::size_t i = 0; i + 2 < attrib.normals.size(); i += 3)
    mesh.normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});
  // `v x y z r g b`: honoured when every vertex has a colour.
  if (!attrib.colors.empty() && attrib.colors.size() == attrib.vertices.size()) {
    for (std::size_t i = 0; i + 2 < attrib.colors.size(); i += 3)
      mesh.colors.push_back({unit_byte(attrib.colors[i]), unit_byte(attrib.colors[i + 1]),
                             unit_byte(attrib.colors[i + 2]), 255});
  }

  // Per material: its MTL extras, and the index of its texture in mesh.textures once decoded (each file
  // decoded once, however many materials use it), -1 without one.
  std::vector<const MaterialExtra*> extras(materials.size(), nullptr);
  std::vector<std::int32_t> material_texture(materials.size(), -1);
  std::map<std::string, std::int32_t, std::less<>> decoded;
  std::int64_t budget = limits.max_texture_pixels;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const auto it = mtl.materials.find(materials[m].name);
    if (it == mtl.materials.end()) continue;
    extras[m] = &it->second;
    if (!it->second.has_map) continue;
    const DiffuseMap& map = it->second.map;
    if (auto d = decoded.find(map.file); d != decoded.end()) {
      material_texture[m] = d->second;
      continue;
    }
    const std::string* bytes = find_file(files, map.file);
    if (!bytes)
      model_error(0, "the materials (MTL) line " + std::to_string(map.line) + " asks for texture \"" +
                         map.file + "\" (map_Kd), which was not sent; sent: " + names_of(files) +
                         ". Send it as a multipart part with that file name (curl -F 'texture=@" + map.file +
                         "')");
    Texture texture = decode_texture(*bytes, map.file, budget);
    budget -= std::int64_t{texture.width} * texture.height;
    texture.clamp = map.clamp, texture.scale = map.scale, texture.offset = map.offset;
    material_texture[m] = decoded[map.file] = static_cast<std::int32_t>(mesh.textures.size());
    mesh.textures.push_back(std::move(texture));
  }
  const std::size_t texcoords = attrib.texcoords.size() / 2;
  if (!mesh.textures.empty()) {
    mesh.uvs.reserve(texcoords + 1);
    for (std::size_t i = 0; i < texcoords; ++i)
      mesh.uvs.push_back(
          {static_cast<float>(attrib.texcoords[2 * i]), static_cast<float>(attrib.texcoords[2 * i + 1])});
    mesh.uvs.push_back({0, 0});  // for faces without "vt" references (drawn untextured)
  }
  const auto no_uv = static_cast<std::uint32_t>(texcoords);
  bool any_material = false, all_normals = true;
  std::vector<Rgba8> face_colors;
  // Each face's corners: tinyobjloader's count, but the prescan's for faces of 256 and more (tinyobjloader
  // keeps faces in file order, every 'f' line one face).
  std::size_t long_face = 0;
  auto corners_of = [&](std::int64_t face, unsigned char stored) -> std::size_t {
    if (long_face < counts.long_faces.size() && counts.long_faces[long_face].first == face) {
      const std::uint32_t n = counts.long_faces[long_face++].second;
      if ((n & 255) != stored) model_error(0, "the model's faces could not be read consistently");
      return n;
    }
    return stored;
  };
  std::size_t triangles = 0;  // sized once: growing them by doubling copied a large model's arrays ~20 times
  for (const tinyobj::shape_t& shape : shapes)
    for (const unsigned corners : shape.mesh.num_face_vertices) triangles += corners >= 3 ? corners - 2 : 0;
  for (const auto& [face, corners] : counts.long_faces) triangles += corners - (corners & 255);
  mesh.triangles.reserve(triangles), face_colors.reserve(triangles);
  if (!attrib.normals.empty()) mesh.normal_triangles.reserve(triangles);
  if (!mesh.textures.empty()) mesh.face_textures.reserve(triangles), mesh.uv_triangles.reserve(triangles);
  PolygonSplitter splitter;
  std::vector<Vec3> polygon;                         // a face's corners' positions
  std::vector<std::array<std::uint32_t, 3>> pieces;  // its triangles, as indices into its corners
  std::int64_t face_number = 0;                      // across shapes, in file order
  for (const tinyobj::shape_t& shape : shapes) {
    const auto& idx = shape.mesh.indices;
    std::size_t next_face = 0;  // where the next face's corners start in idx
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t n = corners_of(face_number++, shape.mesh.num_face_vertices[f]), first = next_face;
      next_face += n;
      if (next_face > idx.size()) model_error(0, "the model's faces could not be read consistently");
      if (n < 3) continue;
      pieces.clear();
      if (n == 3) {
        pieces.push_back({0, 1, 2});
      } else {
        polygon.clear();
        for (std::size_t k = 0; k < n; ++k) {
          const auto v = static_cast<std::size_t>(idx[first + k].vertex_index);
          polygon.push_back(v < mesh.positions.size() ? mesh.positions[v] : Vec3{});  // checked below
        }
        splitter.split(polygon, pieces);
      }
      const int m = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      // tinyobjloader makes a black material of its own for a `usemtl` the MTL does not define (or with no
      // MTL at all, as assimp's empty_mat.obj): such faces keep the default grey, like faces without one.
      const bool material = m >= 0 && static_cast<std::size_t>(m) < materials.size() && extras[m];
      Rgba8 face_color{204, 204, 204, 255};  // the default light grey
      if (material) {
        any_material = true;
        const auto& kd = materials[m].diffuse;
        // MTL: the texture is multiplied by Kd; a map without Kd is shown as it is.
        const bool white = extras[m] && extras[m]->has_map && !extras[m]->has_kd;
        face_color = {white ? std::uint8_t{255} : unit_byte(kd[0]),
                      white ? std::uint8_t{255} : unit_byte(kd[1]),
                      white ? std::uint8_t{255} : unit_byte(kd[2]), unit_byte(materials[m].dissolve)};
      }
      for (const auto& piece : pieces) {
        const tinyobj::index_t c[3] = {idx[first + piece[0]], idx[first + piece[1]], idx[first + piece[2]]};
        mesh.triangles.push_back({static_cast<std::uint32_t>(c[0].vertex_index),
                                  static_cast<std::uint32_t>(c[1].vertex_index),
                                  static_cast<std::uint32_t>(c[2].vertex_index)});
        const bool has_normals = c[0].normal_index >= 0 && c[1].normal_index >= 0 && c[2].normal_index >= 0;
        all_normals = all_normals && has_normals;
        if (has_normals)
          mesh.normal_triangles.push_back({static_cast<std::uint32_t>(c[0].normal_index),
                                           static_cast<std::uint32_t>(c[1].normal_index),
                                           static_cast<std::uint32_t>(c[2].normal_index)});
        face_colors.push_back(face_color);
        if (!mesh.textures.empty()) {
          const bool has_uv =
              c[0].texcoord_index >= 0 && c[1].texcoord_index >= 0 && c[2].texcoord_index >= 0;
          const std::int32_t texture = material && has_uv ? material_texture[m] : -1;
          mesh.face_textures.push_back(texture);
          if (texture >= 0)
            mesh.uv_triangles.push_back({static_cast<std::uint32_t>(c[0].texcoord_index),
                                         static_cast<std::uint32_t>(c[1].texcoord_index),
                                         static_cast<std::uint32_t>(c[2].texcoord_index)});
          else
            mesh.uv_triangles.push_back({no_uv, no_uv, no_uv});
        }
      }
    }
    const auto& li = shape.lines.indices;
    std::size_t at = 0;
    for (int count : shape.lines.num_line_vertices) {
      for (int k = 0; k + 1 < count && at + k + 1 < li.size(); ++k)
        mesh.segments.push_back({static_cast<std::uint32_t>(li[at + k].vertex_index),
                                 static_cast<std::uint32_t>(li[at + k + 1].vertex_index)});
      at += static_cast<std::size_t>(count);
    }
  }
  // Normals are used only when every face has them; otherwise they are computed.
  if (!all_normals || mesh.normal_triangles.size() != mesh.triangles.size()) {
    mesh.normals.clear();
    mesh.normal_triangles.clear();
  }
  if (any_material) mesh.face_colors = std::move(face_colors);
  // Defence in depth: the prescan validated every index; a disagreement with the parser is a model error.
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t)
      if (i >= mesh.positions.size()) model_error(0, "a face refers to a vertex the model does not define");
  for (const auto& s : mesh.segments)
    for (std::uint32_t i : s)
      if (i >= mesh.positions.size()) model_error(0, "a line refers to a vertex the model does not define");
  for (const auto& t : mesh.normal_triangles)
    for (std::uint32_t i : t)
      if (i >= mesh.normals.size()) model_error(0, "a face refers to a normal the model does not define");
  for (const auto& t : mesh.uv_triangles)
    for (std::uint32_t i : t)
      if (i >= mesh.uvs.size())
        model_error(0, "a face refers to a texture coordinate the model does not define");
  if (mesh.triangles.empty() && mesh.segments.empty())
    model_error(0, "the model has no faces or lines to draw");
  return mesh;
}

}  // namespace raster
