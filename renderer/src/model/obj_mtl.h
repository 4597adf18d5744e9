// What an OBJ model's reader (obj.cpp) shares with its materials' (obj_mtl.cpp): the error both report
// through, the words of a line, what the pass over the MTL text learns, the textures the materials name,
// decoded once each, and a colour component's byte.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

#include <tiny_obj_loader.h>

#include "model/reading.h"
#include "raster/scene.h"

namespace raster::obj {

[[noreturn]] inline void model_error(std::size_t line, const std::string& message) {
  throw SceneError(ErrorKind::model, message, ErrorLocation{"", 0, line});
}

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// The whitespace-separated words of one line, into `out` (reused line after line by check_obj_text: a
// vector made per line was a malloc and a free per line, 7% of a large model's parse).
inline void split_words(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

inline std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  split_words(line, out);
  return out;
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
  std::string file;                   ///< file name without folders
  std::size_t line = 0;               ///< MTL line, for errors
  bool clamp = false;                 ///< "-clamp on": coordinates clamped to 0..1, not repeated
  std::array<float, 2> scale{1, 1};   ///< "-s u v": texture coordinates multiplied by these
  std::array<float, 2> offset{0, 0};  ///< "-o u v": then these added
};

/// What the MTL pass learns per material (by name, as tinyobjloader names it).
struct MaterialExtra {
  bool has_kd = false;   ///< it gives a diffuse colour (Kd)
  bool has_map = false;  ///< it gives a diffuse map (map_Kd), in `map`
  DiffuseMap map;
};

struct MtlPass {
  std::string text;                                             ///< for tinyobjloader
  std::map<std::string, MaterialExtra, std::less<>> materials;  ///< by the name "newmtl" gives
};

// The MTL text for tinyobjloader, and what it learns of each material on the way.
MtlPass read_mtl(std::string_view mtl);

// The materials a model without given MTL text names: each `mtllib` line's files among the uploads, in
// order, each once (f3d#1973: a viewer that ignores mtllib and guesses <model>.mtl finds none of them). A
// line is one name if a file has that whole name (names with spaces), else names separated by blanks.
// Libraries that were not sent are left out: a bare model keeps its default colours.
std::string named_libraries(const std::vector<std::string_view>& mtllibs, const Uploads& files);

/// Per material of tinyobjloader's list (by index): what the MTL pass learnt of it (null for a material
/// the MTL does not define) and its texture's index into the mesh's textures (-1 without one).
struct MaterialTextures {
  std::vector<const MaterialExtra*> extras;  ///< into the MtlPass, which outlives this
  std::vector<std::int32_t> texture;         ///< index into Mesh::textures, or -1
};

/// The textures of a model's materials before any is decoded: each material's entry (MaterialTextures, the
/// index its map will have among the mesh's textures) and the maps to decode, one per file, in the order
/// those indices give them.
struct TexturePlan {
  MaterialTextures materials;
  std::vector<const DiffuseMap*> maps;  ///< into the MtlPass; maps[i] becomes the mesh's texture i
};
TexturePlan plan_textures(const std::vector<tinyobj::material_t>& materials, const MtlPass& mtl);

/// The plan's maps, found among the uploads by file name and decoded into `textures` in order, within the
/// limit's texels: a map that was not sent, or does not decode, is SceneError(model) naming it.
void decode_textures(const TexturePlan& plan, const Uploads& files, const Limits& limits,
                     std::vector<Texture>& textures);

/// An MTL colour component (Kd, d) or a vertex colour (0..1) as a byte, as every reader makes one.
using detail::unit_byte;

/// A read-only stream buffer over text held elsewhere (tinyobjloader reads from streams; nothing is copied).
class TextBuf : public std::streambuf {
 public:
  explicit TextBuf(std::string_view text) {
    char* first = const_cast<char*>(text.data());  // a get area only: nothing is written through it
    setg(first, first, first + text.size());
  }
};

/// The materials with a specular colour (Ks above 0) into mesh.materials (Blinn-Phong), and each material's
/// index there, -1 for the others (Lambert): a model without any keeps exactly the picture it had before Ks
/// was read.
std::vector<std::int32_t> specular_materials(const std::vector<tinyobj::material_t>& materials,
                                             const MaterialTextures& textures, Mesh& mesh);

/// A model's materials as its faces name them: tinyobjloader's list of the MTL's materials and their index
/// by name, the textures they will have, and each one's index into Mesh::materials (-1: Lambert).
struct ObjMaterials {
  std::map<std::string, int> by_name;
  std::vector<tinyobj::material_t> list;
  TexturePlan textures;
  std::vector<std::int32_t> surface;
};

/// The materials of a model: `mtl_text` when given, else the libraries its `mtllib` lines (`mtllibs`) name
/// among the uploads; through read_mtl (into `mtl`, which the result points into) and tinyobjloader's MTL
/// parser. A specular material is added to mesh.materials. An MTL error is SceneError(model).
ObjMaterials read_materials(std::string_view mtl_text, const std::vector<std::string_view>& mtllibs,
                            const Uploads& files, MtlPass& mtl, Mesh& mesh);

// Each material's diffuse map, found among the uploads by file name and decoded into `textures` once
// however many materials use it, within the limit's texels: plan_textures, then decode_textures.
MaterialTextures material_textures(const std::vector<tinyobj::material_t>& materials, const MtlPass& mtl,
                                   const Uploads& files, const Limits& limits,
                                   std::vector<Texture>& textures);

}  // namespace raster::obj
