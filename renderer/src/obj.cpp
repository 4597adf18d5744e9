// OBJ models: text -> Mesh, through tinyobjloader, after validating what tinyobjloader 2.0.0~rc10 does not
// (face indices: negative ones are CVE-2020-28589, out-of-range positive ones only warn).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include <tiny_obj_loader.h>

#include "raster/scene.h"
#include "raster/utf8.h"

namespace raster {
namespace {

[[noreturn]] void model_error(std::size_t line, const std::string& message) {
  throw SceneError(ErrorKind::model, message, ErrorLocation{"", 0, line});
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// The whitespace-separated words of one line.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
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

struct Counts {
  std::int64_t v = 0, vt = 0, vn = 0, faces = 0, segments = 0, points = 0;
};

// Validates every line tinyobjloader would index with, before it sees the text.
Counts prescan(std::string_view text, const Limits& limits) {
  Counts n;
  std::size_t line_no = 0;
  std::string why;
  for (std::size_t pos = 0; pos <= text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const auto w = words(line);
    if (w.empty() || w[0][0] == '#') continue;
    const std::string_view key = w[0];
    if (key == "v") {
      if (w.size() < 4) model_error(line_no, "a vertex needs x y z");
      for (std::size_t k = 1; k < w.size() && k <= 6; ++k) {
        double d = 0;
        const auto [p, ec] = std::from_chars(w[k].data(), w[k].data() + w[k].size(), d);
        if (ec != std::errc() || p != w[k].data() + w[k].size() || !std::isfinite(d) ||
            std::fabs(d) > kMaxCoordinate)
          model_error(line_no, "vertex component \"" + std::string(w[k]) +
                                   "\" is not a finite number within +-3.4e38");
      }
      ++n.v;
    } else if (key == "vt") {
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

std::uint8_t unit_byte(double v) {
  return static_cast<std::uint8_t>(std::floor(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5));
}

}  // namespace

Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text, const Limits& limits) {
  // Checked first: names and tokens of the model are quoted in its errors.
  require_utf8(obj_text, "the model (OBJ)", true);
  require_utf8(mtl_text, "the materials (MTL)", true);
  const Counts counts = prescan(obj_text, limits);
  if (counts.v == 0) model_error(0, "the model is empty: it defines no vertices");
  if (counts.faces == 0 && counts.segments == 0)
    model_error(0, counts.points ? "the model has only points ('p'); rasterd draws faces and lines"
                                 : "the model has no faces ('f') or lines ('l') to draw");

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;  // colours only where the file has them (no white fallback)
  tinyobj::ObjReader reader;
  // From memory: a `mtllib` line reads the uploaded MTL text, never a file named in the upload.
  if (!reader.ParseFromString(std::string(obj_text), std::string(mtl_text), config))
    model_error(0, "the model could not be parsed: " + reader.Error());

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  Mesh mesh;
  mesh.positions.reserve(attrib.vertices.size() / 3);
  for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
    mesh.positions.push_back({attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
  for (std::size_t i = 0; i + 2 < attrib.normals.size(); i += 3)
    mesh.normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});
  // `v x y z r g b`: honoured when every vertex has a colour.
  if (!attrib.colors.empty() && attrib.colors.size() == attrib.vertices.size()) {
    for (std::size_t i = 0; i + 2 < attrib.colors.size(); i += 3)
      mesh.colors.push_back({unit_byte(attrib.colors[i]), unit_byte(attrib.colors[i + 1]),
                             unit_byte(attrib.colors[i + 2]), 255});
  }

  const auto& materials = reader.GetMaterials();
  bool any_material = false, all_normals = true;
  std::vector<Rgba8> face_colors;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& idx = shape.mesh.indices;
    for (std::size_t f = 0; f * 3 + 2 < idx.size(); ++f) {
      const tinyobj::index_t* c = &idx[f * 3];
      mesh.triangles.push_back({static_cast<std::uint32_t>(c[0].vertex_index),
                                static_cast<std::uint32_t>(c[1].vertex_index),
                                static_cast<std::uint32_t>(c[2].vertex_index)});
      const bool has_normals = c[0].normal_index >= 0 && c[1].normal_index >= 0 && c[2].normal_index >= 0;
      all_normals = all_normals && has_normals;
      if (has_normals)
        mesh.normal_triangles.push_back({static_cast<std::uint32_t>(c[0].normal_index),
                                         static_cast<std::uint32_t>(c[1].normal_index),
                                         static_cast<std::uint32_t>(c[2].normal_index)});
      const int m = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      if (m >= 0 && static_cast<std::size_t>(m) < materials.size()) {
        any_material = true;
        const auto& kd = materials[m].diffuse;
        face_colors.push_back(
            {unit_byte(kd[0]), unit_byte(kd[1]), unit_byte(kd[2]), unit_byte(materials[m].dissolve)});
      } else {
        face_colors.push_back({204, 204, 204, 255});  // the default light grey
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
  if (mesh.triangles.empty() && mesh.segments.empty())
    model_error(0, "the model has no faces or lines to draw");
  return mesh;
}

}  // namespace raster
