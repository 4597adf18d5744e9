// The test oracle for OBJ: rasterd 0.4's OBJ reader, text -> Mesh through tinyobjloader, after validating
// what tinyobjloader 2.0.0~rc10 does not (face indices: negative ones are CVE-2020-28589, out-of-range
// positive ones only warn). It is kept, unchanged in what it reads, only to check the library's own OBJ
// reader against (tests/obj_reader_test.cpp and fuzz/obj_fuzzer.cpp); it is not linked into the library or
// the server.
//
// parse_obj in steps: the prescan (every line tinyobjloader would index with, validated and counted), the
// materials (obj_mtl.cpp: the MTL pass and the textures it names), tinyobjloader's parse, then the mesh:
// vertices, faces split into triangles with their normals, texture coordinates and colours, and lines.
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
#include "model/obj_mtl.h"
#include "model/polygon.h"
#include "obj_tinyobj.h"
#include "raster/model.h"
#include "raster/utf8.h"

namespace raster::obj {
namespace {

// What the reader through tinyobjloader reserved (rasterd 0.4's measured costs).
constexpr std::int64_t kObjPerCorner = 64;  // per face corner (tinyobjloader's index and ours)
constexpr std::int64_t kObjPerVertex = 72;  // per v, vt or vn line (doubles there, floats here)

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

// Refuses a model once `count` passes `limit` (faces or points), naming the line that passed it.
void check_limit(std::int64_t count, std::int64_t limit, const char* what, std::size_t line_no) {
  if (count > limit)
    throw SceneError(ErrorKind::limit, "the model has more than " + std::to_string(limit) + " " + what,
                     ErrorLocation{"", 0, line_no});
}

struct Counts {
  std::int64_t v = 0, vt = 0, vn = 0, faces = 0, segments = 0, points = 0;  ///< points: 'p' lines
  std::int64_t point_refs = 0;  ///< vertices named on 'p' lines (each is a point)
  std::int64_t corners = 0;  ///< face corners (references on 'f' lines), what tinyobjloader stores per face
  /// (0-based face number, corners) of each face of 256 corners or more, in file order: tinyobjloader
  /// stores a face's corner count in a byte.
  std::vector<std::pair<std::int64_t, std::uint32_t>> long_faces;
  std::vector<std::string_view> mtllibs;  ///< what follows each `mtllib` (one or more file names)
};

// Validates every line tinyobjloader would index with, before it sees the text.
Counts prescan(std::string_view text, const Limits& limits) {
  Counts n;
  detail::ReadMeter meter(limits);  // a line and each of its words a unit: one line may hold a huge face
  std::size_t line_no = 0;
  std::string why;
  std::vector<std::string_view> w;
  for (std::size_t pos = 0; pos <= text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    split_words(line, w);
    meter.add(1 + w.size());
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
        check_limit(++n.faces, limits.max_model_faces, "faces", line_no);
      } else if (key == "l") {
        n.segments += static_cast<std::int64_t>(w.size()) - 2;
      } else {
        ++n.points;
        n.point_refs += static_cast<std::int64_t>(w.size()) - 1;
        check_limit(n.point_refs, limits.max_model_points, "points", line_no);
      }
    }
  }
  return n;
}

// tinyobjloader's model of the text.
struct Parsed {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
};

// What ObjReader::ParseFromString does (but faces as written, split below as PLY's are; colours only
// where the file has them: no white fallback), on a stream over the text where it lies: ParseFromString
// copied a model twice (into a std::string, then into a stringbuf), 2 x its size of fresh memory per
// request. From memory: a `mtllib` line reads the uploaded MTL text, never a file named in the upload.
Parsed parse_with_tinyobj(std::string_view obj_text, std::string_view mtl_text) {
  Parsed out;
  TextBuf obj_buf(obj_text), mtl_buf(mtl_text);
  std::istream obj_stream(&obj_buf), mtl_stream(&mtl_buf);
  tinyobj::MaterialStreamReader mtl_reader(mtl_stream);
  std::string warning, error;
  if (!tinyobj::LoadObj(&out.attrib, &out.shapes, &out.materials, &warning, &error, &obj_stream, &mtl_reader,
                        /*triangulate=*/false, /*default_vcols_fallback=*/false))
    model_error(0, "the model could not be parsed: " + error);
  return out;
}

// The mesh's positions, normals and vertex colours (`v x y z r g b`: honoured when every vertex has one).
Mesh vertices_of(const tinyobj::attrib_t& attrib) {
  Mesh mesh;
  mesh.positions.reserve(attrib.vertices.size() / 3);
  for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
    mesh.positions.push_back(Vec3f(Vec3{attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]}));
  mesh.normals.reserve(attrib.normals.size() / 3);
  for (std::size_t i = 0; i + 2 < attrib.normals.size(); i += 3)
    mesh.normals.push_back(Vec3f(Vec3{attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]}));
  if (!attrib.colors.empty() && attrib.colors.size() == attrib.vertices.size()) {
    for (std::size_t i = 0; i + 2 < attrib.colors.size(); i += 3)
      mesh.colors.push_back({unit_byte(attrib.colors[i]), unit_byte(attrib.colors[i + 1]),
                             unit_byte(attrib.colors[i + 2]), 255});
  }
  return mesh;
}

// The texture coordinates of a textured model, then one (0, 0) for faces without "vt" references
// (drawn untextured).
void add_uvs(const tinyobj::attrib_t& attrib, Mesh& mesh) {
  const std::size_t texcoords = attrib.texcoords.size() / 2;
  mesh.uvs.reserve(texcoords + 1);
  for (std::size_t i = 0; i < texcoords; ++i)
    mesh.uvs.push_back(
        {static_cast<float>(attrib.texcoords[2 * i]), static_cast<float>(attrib.texcoords[2 * i + 1])});
  mesh.uvs.push_back({0, 0});
}

// Room for every triangle the faces make, sized once: growing the arrays by doubling copied a large
// model's ~20 times. Each face's corners are tinyobjloader's count, plus what its byte lost for a face of
// 256 corners and more.
void reserve_triangles(const std::vector<tinyobj::shape_t>& shapes, const Counts& counts, bool normals,
                       Mesh& mesh, std::vector<Rgba8>& face_colors) {
  std::size_t triangles = 0;
  for (const tinyobj::shape_t& shape : shapes)
    for (const unsigned corners : shape.mesh.num_face_vertices) triangles += corners >= 3 ? corners - 2 : 0;
  for (const auto& [face, corners] : counts.long_faces) triangles += corners - (corners & 255);
  mesh.triangles.reserve(triangles), face_colors.reserve(triangles);
  if (normals) mesh.normal_triangles.reserve(triangles);
  if (!mesh.textures.empty()) mesh.face_textures.reserve(triangles), mesh.uv_triangles.reserve(triangles);
}

// The triangles of the face of `n` corners from idx[first], as indices into its corners, into `pieces`.
void split_face(const std::vector<tinyobj::index_t>& idx, std::size_t first, std::size_t n,
                const std::vector<Vec3f>& positions, PolygonSplitter& splitter, std::vector<Vec3>& polygon,
                std::vector<std::array<std::uint32_t, 3>>& pieces) {
  pieces.clear();
  if (n == 3) return pieces.push_back({0, 1, 2});
  polygon.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const auto v = static_cast<std::size_t>(idx[first + k].vertex_index);
    polygon.push_back(v < positions.size() ? positions[v] : Vec3{});  // checked by check_references
  }
  splitter.split(polygon, pieces);
}

// What the face loop found across the faces.
struct FaceTotals {
  bool any_material = false;  ///< a face has a material the MTL defines: face colours are kept
  bool all_normals = true;    ///< every triangle's corners have normals: the model's normals are kept
};

// Every face's triangles, in file order, into the mesh with their normal and texture-coordinate
// references, texture and colour (into `face_colors`, one per triangle). `no_uv` is the (0, 0) coordinate
// of faces without their own.
FaceTotals add_faces(const Parsed& model, const Counts& counts, const MaterialTextures& textures,
                     std::uint32_t no_uv, Mesh& mesh, std::vector<Rgba8>& face_colors,
                     detail::ReadMeter& meter) {
  const auto& materials = model.materials;
  FaceTotals totals;
  // Each material's index into mesh.materials (-1: Lambert).
  const std::vector<std::int32_t> surface = specular_materials(materials, textures, mesh);
  if (!mesh.materials.empty()) mesh.face_materials.reserve(mesh.triangles.capacity());
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
  PolygonSplitter splitter(&meter);                  // ear clipping's point tests count as the reader's work
  std::vector<Vec3> polygon;                         // a face's corners' positions
  std::vector<std::array<std::uint32_t, 3>> pieces;  // its triangles, as indices into its corners
  std::int64_t face_number = 0;                      // across shapes, in file order
  for (const tinyobj::shape_t& shape : model.shapes) {
    const auto& idx = shape.mesh.indices;
    std::size_t next_face = 0;  // where the next face's corners start in idx
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t n = corners_of(face_number++, shape.mesh.num_face_vertices[f]), first = next_face;
      next_face += n;
      if (next_face > idx.size()) model_error(0, "the model's faces could not be read consistently");
      meter.add(n);
      if (n < 3) continue;
      split_face(idx, first, n, mesh.positions, splitter, polygon, pieces);
      const int m = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      // tinyobjloader makes a black material of its own for a `usemtl` the MTL does not define (or with no
      // MTL at all, as assimp's empty_mat.obj): such faces keep the default grey, like faces without one.
      const bool material = m >= 0 && static_cast<std::size_t>(m) < materials.size() && textures.extras[m];
      Rgba8 face_color{204, 204, 204, 255};  // the default light grey
      if (material) {
        totals.any_material = true;
        const auto& kd = materials[m].diffuse;
        // MTL: the texture is multiplied by Kd; a map without Kd is shown as it is.
        const bool white = textures.extras[m] && textures.extras[m]->has_map && !textures.extras[m]->has_kd;
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
        totals.all_normals = totals.all_normals && has_normals;
        if (has_normals)
          mesh.normal_triangles.push_back({static_cast<std::uint32_t>(c[0].normal_index),
                                           static_cast<std::uint32_t>(c[1].normal_index),
                                           static_cast<std::uint32_t>(c[2].normal_index)});
        face_colors.push_back(face_color);
        if (!mesh.materials.empty()) mesh.face_materials.push_back(material ? surface[m] : -1);
        if (!mesh.textures.empty()) {
          const bool has_uv =
              c[0].texcoord_index >= 0 && c[1].texcoord_index >= 0 && c[2].texcoord_index >= 0;
          const std::int32_t texture = material && has_uv ? textures.texture[m] : -1;
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
  }
  return totals;
}

// Every 'l' line's segments, shape after shape.
void add_lines(const std::vector<tinyobj::shape_t>& shapes, Mesh& mesh) {
  for (const tinyobj::shape_t& shape : shapes) {
    const auto& li = shape.lines.indices;
    std::size_t at = 0;
    for (int count : shape.lines.num_line_vertices) {
      for (int k = 0; k + 1 < count && at + k + 1 < li.size(); ++k)
        mesh.segments.push_back({static_cast<std::uint32_t>(li[at + k].vertex_index),
                                 static_cast<std::uint32_t>(li[at + k + 1].vertex_index)});
      at += static_cast<std::size_t>(count);
    }
  }
}

// Every 'p' line's vertices, shape after shape: each is a point.
void add_points(const std::vector<tinyobj::shape_t>& shapes, Mesh& mesh) {
  for (const tinyobj::shape_t& shape : shapes)
    for (const tinyobj::index_t& i : shape.points.indices)
      mesh.points.push_back(static_cast<std::uint32_t>(i.vertex_index));
}

// Defence in depth: the prescan validated every index; a disagreement with the parser is a model error.
void check_references(const Mesh& mesh) {
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t)
      if (i >= mesh.positions.size()) model_error(0, "a face refers to a vertex the model does not define");
  for (const auto& s : mesh.segments)
    for (std::uint32_t i : s)
      if (i >= mesh.positions.size()) model_error(0, "a line refers to a vertex the model does not define");
  for (std::uint32_t i : mesh.points)
    if (i >= mesh.positions.size()) model_error(0, "a point refers to a vertex the model does not define");
  for (const auto& t : mesh.normal_triangles)
    for (std::uint32_t i : t)
      if (i >= mesh.normals.size()) model_error(0, "a face refers to a normal the model does not define");
  for (const auto& t : mesh.uv_triangles)
    for (std::uint32_t i : t)
      if (i >= mesh.uvs.size())
        model_error(0, "a face refers to a texture coordinate the model does not define");
}

}  // namespace
}  // namespace raster::obj

namespace raster::oracle {

using namespace obj;  // parse_obj_tinyobj is made of the steps above

Mesh parse_obj_tinyobj(std::string_view obj_text, std::string_view mtl_text, const Limits& limits,
                       const Uploads& files) {
  // Checked first: names and tokens of the model are quoted in its errors.
  require_utf8(obj_text, "the model (OBJ)", true);
  require_utf8(mtl_text, "the materials (MTL)", true);
  const Counts counts = prescan(obj_text, limits);
  if (counts.v == 0) model_error(0, "the model is empty: it defines no vertices");
  // Only vertices ('v' lines, as a scan exported to OBJ has them): a point cloud, every vertex a point.
  const bool cloud = counts.faces == 0 && counts.segments == 0 && counts.points == 0;
  if (cloud) check_limit(counts.v, limits.max_model_points, "points", 0);

  std::string libraries;
  if (mtl_text.empty() && !counts.mtllibs.empty()) {
    libraries = named_libraries(counts.mtllibs, files);
    require_utf8(libraries, "the materials (MTL)", true);
    mtl_text = libraries;
  }
  const MtlPass mtl = read_mtl(mtl_text);
  // The prescan has counted what tinyobjloader and the mesh will hold: asked for before either is built.
  detail::reserve(limits,
                  kObjPerCorner * (counts.corners + 2 * counts.segments + counts.point_refs) +
                      kObjPerVertex * (counts.v + counts.vt + counts.vn),
                  [&] {
                    return "the model's " + std::to_string(counts.faces) + " faces and " +
                           std::to_string(counts.v) + " vertices";
                  });

  // tinyobjloader's parse cannot be asked to stop: it is linear in the text the prescan has just read (and
  // checked as it went), and is asked about before and after. Every later step counts its work.
  detail::ReadMeter meter(limits);
  meter.check();
  const Parsed model = parse_with_tinyobj(obj_text, mtl.text);
  meter.check();
  Mesh mesh = vertices_of(model.attrib);
  const MaterialTextures textures = material_textures(model.materials, mtl, files, limits, mesh.textures);
  if (!mesh.textures.empty()) add_uvs(model.attrib, mesh);
  std::vector<Rgba8> face_colors;
  reserve_triangles(model.shapes, counts, !model.attrib.normals.empty(), mesh, face_colors);
  const auto no_uv = static_cast<std::uint32_t>(model.attrib.texcoords.size() / 2);
  meter.check();
  const FaceTotals totals = add_faces(model, counts, textures, no_uv, mesh, face_colors, meter);
  meter.check();
  add_lines(model.shapes, mesh);
  add_points(model.shapes, mesh);
  if (cloud) {
    mesh.points.resize(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.points.size(); ++i) mesh.points[i] = i;
  }
  // Normals are used only when every face has them; otherwise they are computed.
  if (!totals.all_normals || mesh.normal_triangles.size() != mesh.triangles.size()) {
    mesh.normals.clear();
    mesh.normal_triangles.clear();
  }
  if (totals.any_material) mesh.face_colors = std::move(face_colors);
  meter.check();
  check_references(mesh);
  if (mesh.triangles.empty() && mesh.segments.empty() && mesh.points.empty())
    model_error(0, "the model has no faces, lines or points to draw");
  return mesh;
}

}  // namespace raster::oracle
