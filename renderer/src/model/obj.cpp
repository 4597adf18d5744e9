// OBJ models: text -> Mesh, read by rasterd itself, straight into the mesh's arrays. The text is split at
// line ends into pieces that the render's threads read at once, in passes over each piece:
//  1. count: each piece's statements (v, vt, vn lines; faces, their triangles, segments and points), its
//     lines, its last `usemtl` and its `mtllib`s; summed in piece order, they say where each piece's
//     vertices and triangles go, and what to allocate, once;
//  2. read: every number and reference, checked as it is read (each index against what is defined so far),
//     written where it goes; a face of more than three corners leaves its corners in its triangles' room;
//  3. split: those faces, into triangles, now that every position is known (quads on their shorter
//     diagonal in each piece, larger polygons by ear clipping in file order).
// What is read does not depend on how the text was split or how many threads read it. A piece that finds
// anything wrong stops, and the text is then checked from its start, one line after another
// (check_obj_text), so the error reported is the one a reader of the lines in order meets first, in the
// words the previous reader (through tinyobjloader, now the tests' oracle) used. The materials (MTL) are read
// as before (obj_mtl.cpp, tinyobjloader's MTL parser), after the OBJ's own errors.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include <tiny_obj_loader.h>

#include "base/budget_ask.h"
#include "base/memory.h"
#include "base/parallel.h"
#include "model/obj_mtl.h"
#include "model/obj_text.h"
#include "model/polygon.h"
#include "raster/model.h"
#include "raster/utf8.h"

namespace raster::obj {
namespace {

// Bytes a piece reads at least (to its next line end). Below this much text, one piece on the calling thread.
constexpr std::size_t kPieceBytes = std::size_t{1} << 20;
constexpr Rgba8 kGrey{204, 204, 204, 255};  // faces without a material's colour
constexpr std::uint32_t kNone = ~0u;        // a corner without a texture coordinate or normal

// Calls line(begin, end) for every line of text[from, to) (without its '\n'; the last may have none).
template <typename Line>
void each_line(std::string_view text, std::size_t from, std::size_t to, Line&& line) {
  const char* p = text.data() + from;
  const char* const stop = text.data() + to;
  while (p < stop) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(stop - p)));
    const char* end = eol ? eol : stop;
    line(p, end);
    p = end + 1;
  }
}

// One piece of the text and what the passes learn of it.
struct Piece {
  std::size_t begin = 0, end = 0;  ///< bytes of the text: whole lines
  // Pass 1, counted:
  std::int64_t v = 0, vt = 0, vn = 0;
  std::int64_t faces = 0, triangles = 0, segments = 0, point_lines = 0, point_refs = 0;
  bool wrong = false;              ///< something pass 1 can see is wrong (check_obj_text says what)
  bool bad_utf8 = false;           ///< a byte of it is not well-formed UTF-8
  const char* material = nullptr;  ///< the last `usemtl` name in it (null: none), and its length
  std::size_t material_size = 0;
  /// tinyobjloader reads the materials at the first `mtllib` and a `usemtl` before that finds none: whether
  /// an `mtllib` in the piece comes before its last `usemtl`.
  bool loaded_before_material = false;
  std::vector<std::string_view> mtllibs;  ///< what follows each `mtllib`, in order
  // Where its things go (sums over the pieces before it):
  std::int64_t first_v = 0, first_vt = 0, first_vn = 0, first_triangle = 0, first_segment = 0,
               first_point = 0;
  std::string_view material_before;     ///< the `usemtl` name in force where it starts
  bool has_material_before = false;     ///< false: no `usemtl` before it
  bool loaded = false;                  ///< some `mtllib` comes before it
  bool material_before_loaded = false;  ///< ... before that `usemtl`, which therefore names a material
  // Pass 2, read:
  std::int64_t coloured = 0;                           ///< v lines with a colour (six numbers)
  bool all_normals = true;                             ///< every corner of every face names a normal
  bool any_material = false;                           ///< a face has a material the MTL defines
  std::vector<std::array<std::uint32_t, 2>> polygons;  ///< faces of > 3 corners: first triangle, corners
};

// Everything the mesh will hold and the passes need, decided once the counts are in.
struct Plan {
  std::int64_t v = 0, vt = 0, vn = 0, faces = 0, triangles = 0, segments = 0, point_refs = 0, point_lines = 0;
  bool textured = false;      ///< the materials have textures: uvs, uv_triangles and face_textures are kept
  bool materials = false;     ///< some `usemtl` and an MTL: face colours (and materials) may be kept
  ObjMaterials materials_of;  ///< the MTL's materials, as the faces name them
  std::uint32_t no_uv = 0;    ///< the (0, 0) coordinate of faces without their own
};

// ---- Pass 1: counting --------------------------------------------------------------------------------

// tinyobjloader loads the materials at an `mtllib` (keyword read) with a blank after it, name or not.
bool loads_materials(const LineWords& w) {
  return w.at < w.end && (*w.at == ' ' || *w.at == '\t');
}

void count_piece(std::string_view text, Piece& piece, const Limits& limits) {
  if (first_invalid_utf8(text.substr(piece.begin, piece.end - piece.begin)) != std::string_view::npos) {
    piece.bad_utf8 = true;  // a piece ends at a '\n', which no multi-byte sequence holds: it is the text's
    return;
  }
  detail::ReadMeter meter(limits);
  meter.check();  // every piece asks as it starts, however little it holds
  const bool has_cr = std::memchr(text.data() + piece.begin, '\r', piece.end - piece.begin);
  each_line(text, piece.begin, piece.end, [&](const char* begin, const char* end) {
    meter.add(1);
    if (has_cr) piece.wrong |= inner_carriage_return({begin, static_cast<std::size_t>(end - begin)});
    LineWords w{begin, end};
    switch (statement(w)) {
      case Statement::v:
        ++piece.v;
        break;
      case Statement::vt:
        ++piece.vt;
        break;
      case Statement::vn:
        ++piece.vn;
        break;
      case Statement::f: {
        const auto n = static_cast<std::int64_t>(w.count());
        meter.add(static_cast<std::uint64_t>(n));
        if (n < 3) piece.wrong = true;
        ++piece.faces, piece.triangles += std::max<std::int64_t>(n - 2, 0);
        break;
      }
      case Statement::l: {
        const auto n = static_cast<std::int64_t>(w.count());
        meter.add(static_cast<std::uint64_t>(n));
        if (n < 2) piece.wrong = true;
        piece.segments += std::max<std::int64_t>(n - 1, 0);
        break;
      }
      case Statement::p: {
        const auto n = static_cast<std::int64_t>(w.count());
        meter.add(static_cast<std::uint64_t>(n));
        if (n < 1) piece.wrong = true;
        ++piece.point_lines, piece.point_refs += n;
        break;
      }
      case Statement::usemtl: {  // tinyobjloader's name: the first word after it
        const std::string_view name = w.next();
        piece.material = name.data(), piece.material_size = name.size();
        piece.loaded_before_material = !piece.mtllibs.empty();
        break;
      }
      case Statement::mtllib:
        if (loads_materials(w)) piece.mtllibs.push_back(w.rest());
        break;
      case Statement::none:
        break;
    }
  });
}

// ---- Pass 2: reading ---------------------------------------------------------------------------------

// A piece's reading found a line that is not as OBJ has it: check_obj_text says which and how.
struct Wrong {};

// The mesh's arrays as the pieces write them, each at the indices pass 1 gave.
struct Out {
  Mesh& mesh;
  const Plan& plan;
  const Limits& limits;
  std::vector<Rgba8> face_colors;  ///< one per triangle when Plan::materials
  std::once_flag coloured;         ///< the vertex colours are made by the first piece that finds one
  std::vector<Rgba8> colors;       ///< one per position, once some v line has a colour
};

// One v, vt or vn line (its words after the keyword) into the mesh at `index`; Wrong when it is malformed.
void read_vertex(Statement s, LineWords& w, std::int64_t index, Out& out, Piece& piece) {
  double c[6];
  int n = 0;
  const int most = s == Statement::v ? 6 : 3;
  if (s == Statement::vn) {
    for (std::string_view word; n < most && !(word = w.next()).empty(); ++n) c[n] = lenient_number(word);
  } else {
    const double bound = s == Statement::v ? kMaxCoordinate : 1e30;
    for (bool present = true; n < most; ++n) {
      if (!next_number(w, c[n], present)) {
        if (!present) break;
        throw Wrong{};
      }
      if (std::fabs(c[n]) > bound) throw Wrong{};
    }
  }
  const auto i = static_cast<std::size_t>(index);
  if (s == Statement::vt) {
    if (n < 1) throw Wrong{};
    if (out.plan.textured)
      out.mesh.uvs[i] = {static_cast<float>(c[0]), n > 1 ? static_cast<float>(c[1]) : 0.0f};
    return;
  }
  if (n < 3) throw Wrong{};
  const Vec3f p(Vec3{c[0], c[1], c[2]});
  if (s == Statement::vn) return void(out.mesh.normals[i] = p);
  out.mesh.positions[i] = p;
  if (n == 6) {  // `v x y z r g b`: kept when every vertex has one
    std::call_once(out.coloured, [&] {
      detail::reserve(out.limits, static_cast<std::int64_t>(out.mesh.positions.size() * sizeof(Rgba8)),
                      [] { return std::string("the model's vertex colours"); });
      out.colors.resize(out.mesh.positions.size());
    });
    out.colors[i] = {unit_byte(c[3]), unit_byte(c[4]), unit_byte(c[5]), 255};
    ++piece.coloured;
  }
}

// A face's corner as pass 2 resolves it: indices into positions, texture coordinates and normals.
struct Corner {
  std::uint32_t v, vt, vn;  ///< 0-based; vt and vn kNone when the reference has none
};

// The corner `ref` names, each of its indices against what is defined so far (v, vt, vn lines).
Corner corner(std::string_view ref, const std::int64_t (&defined)[3]) {
  const Reference r = split_reference(ref);
  const std::int64_t v = resolve(r.vertex, defined[0]);
  const std::int64_t vt = r.texture.empty() ? -2 : resolve(r.texture, defined[1]);
  const std::int64_t vn = r.has_normal ? resolve(r.normal, defined[2]) : -2;
  if (v < 0 || vt == -1 || vn == -1) throw Wrong{};
  return {static_cast<std::uint32_t>(v), vt < 0 ? kNone : static_cast<std::uint32_t>(vt),
          vn < 0 ? kNone : static_cast<std::uint32_t>(vn)};
}

// One index part of a reference read in place: [-]digits (at most 18), resolved against `defined` into
// `out` (-1: out of range, as resolve() has it). Null when not plain digits (the caller reads it generally).
const char* scan_index(const char* at, const char* end, std::int64_t defined, std::int64_t& out) {
  const bool negative = at < end && *at == '-';
  at += negative;
  const char* start = at;
  std::int64_t value = 0;
  for (unsigned d; at < end && (d = static_cast<unsigned>(*at - '0')) < 10 && at - start < 18; ++at)
    value = value * 10 + d;
  if (at == start) return nullptr;
  const std::int64_t resolved = negative ? defined - value : value - 1;
  out = value == 0 || resolved < 0 || resolved >= defined ? -1 : resolved;
  return at;
}

// The next reference of a face, line or point statement, read in one pass over its characters when it is
// plain ("v", "v/vt", "v//vn", "v/vt/vn" of digits), else as corner() reads the word. False at the line's
// end; Wrong for a reference corner() refuses.
bool next_corner(LineWords& w, const std::int64_t (&defined)[3], Corner& c) {
  while (w.at < w.end && LineWords::blank(*w.at)) ++w.at;
  if (w.at == w.end) return false;
  const char* start = w.at;
  std::int64_t v = -1, vt = -2, vn = -2;
  const char* at = scan_index(start, w.end, defined[0], v);
  if (at && at < w.end && *at == '/') {
    ++at;
    if (at < w.end && *at != '/') at = scan_index(at, w.end, defined[1], vt);
    if (at && at < w.end && *at == '/') at = scan_index(at + 1, w.end, defined[2], vn);
  }
  if (at && (at == w.end || LineWords::blank(*at))) {
    if (v < 0 || vt == -1 || vn == -1) throw Wrong{};
    c = {static_cast<std::uint32_t>(v), vt < 0 ? kNone : static_cast<std::uint32_t>(vt),
         vn < 0 ? kNone : static_cast<std::uint32_t>(vn)};
    w.at = at;
    return true;
  }
  w.at = start;
  c = corner(w.next(), defined);
  return true;
}

// What the triangles of a face of material `m` (-1: none or undefined) take.
struct FaceLook {
  bool material = false;  ///< m names a material the MTL defines
  Rgba8 color = kGrey;
  std::int32_t surface = -1;  ///< into Mesh::materials
  std::int32_t texture = -1;  ///< into Mesh::textures, for the triangles whose corners have coordinates
};

FaceLook look_of(int m, const Plan& plan) {
  FaceLook look;
  const auto& extras = plan.materials_of.textures.materials.extras;
  if (m < 0 || static_cast<std::size_t>(m) >= plan.materials_of.list.size() || !extras[m]) return look;
  look.material = true;
  const tinyobj::material_t& mat = plan.materials_of.list[m];
  // MTL: the texture is multiplied by Kd; a map without Kd is shown as it is.
  const bool white = extras[m]->has_map && !extras[m]->has_kd;
  const auto kd = [&](int k) { return white ? std::uint8_t{255} : unit_byte(mat.diffuse[k]); };
  look.color = {kd(0), kd(1), kd(2), unit_byte(mat.dissolve)};
  look.surface = plan.materials_of.surface[m];
  look.texture = plan.materials_of.textures.materials.texture[m];
  return look;
}

// Triangle t's look: its colour and material, and (textured) the texture its face's material has, which
// the triangle keeps when its corners have coordinates (put_corners).
void put_look(Out& out, std::size_t t, const FaceLook& look) {
  if (out.plan.materials) out.face_colors[t] = look.color;
  if (!out.mesh.face_materials.empty()) out.mesh.face_materials[t] = look.material ? look.surface : -1;
  if (out.plan.textured) out.mesh.face_textures[t] = look.material ? look.texture : -1;
}

// Triangle t's corners, after its look: a triangle whose corners lack a texture coordinate is drawn
// untextured, with the (0, 0) coordinate of faces without their own.
void put_corners(Out& out, std::size_t t, const Corner (&c)[3]) {
  Mesh& mesh = out.mesh;
  mesh.triangles[t] = {c[0].v, c[1].v, c[2].v};
  if (!mesh.normal_triangles.empty()) mesh.normal_triangles[t] = {c[0].vn, c[1].vn, c[2].vn};
  if (!out.plan.textured) return;
  const bool has_uv = c[0].vt != kNone && c[1].vt != kNone && c[2].vt != kNone;
  std::int32_t& texture = mesh.face_textures[t];
  if (!has_uv) texture = -1;
  const std::uint32_t none = out.plan.no_uv;
  mesh.uv_triangles[t] = texture >= 0 ? std::array{c[0].vt, c[1].vt, c[2].vt} : std::array{none, none, none};
}

// The corners of the face of n > 3 corners whose triangles start at t, kept in its triangles' room (3 (n -
// 2) >= n indices each of vertices, normals and coordinates) until pass 3 splits it.
void stash_corners(Out& out, std::size_t t, const std::vector<Corner>& corners) {
  Mesh& mesh = out.mesh;
  auto* v = reinterpret_cast<std::uint32_t*>(&mesh.triangles[t]);
  auto* vn =
      mesh.normal_triangles.empty() ? nullptr : reinterpret_cast<std::uint32_t*>(&mesh.normal_triangles[t]);
  auto* vt = out.plan.textured ? reinterpret_cast<std::uint32_t*>(&mesh.uv_triangles[t]) : nullptr;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    v[k] = corners[k].v;
    if (vn) vn[k] = corners[k].vn;
    if (vt) vt[k] = corners[k].vt;
  }
}

void read_piece(std::string_view text, Piece& piece, Out& out, const Limits& limits) {
  detail::ReadMeter meter(limits);
  meter.check();
  std::int64_t defined[3] = {piece.first_v, piece.first_vt, piece.first_vn};
  std::int64_t triangle = piece.first_triangle, segment = piece.first_segment, point = piece.first_point;
  const Plan& plan = out.plan;
  Mesh& mesh = out.mesh;
  bool loaded = piece.material_before_loaded;
  auto look_named = [&](std::string_view name) {
    if (!plan.materials || !loaded) return FaceLook{};  // "" too: an MTL may name a material so
    const auto it = plan.materials_of.by_name.find(std::string(name));
    return look_of(it == plan.materials_of.by_name.end() ? -1 : it->second, plan);
  };
  FaceLook look = piece.has_material_before ? look_named(piece.material_before) : FaceLook{};
  loaded = piece.loaded;
  std::vector<Corner> corners;
  each_line(text, piece.begin, piece.end, [&](const char* begin, const char* end) {
    meter.add(1);
    LineWords w{begin, end};
    const Statement s = statement(w);
    if (s == Statement::v || s == Statement::vt || s == Statement::vn) {
      const int k = s == Statement::v ? 0 : s == Statement::vt ? 1 : 2;
      return read_vertex(s, w, defined[k]++, out, piece);
    }
    if (s == Statement::usemtl) return void(look = look_named(w.next()));
    if (s == Statement::mtllib) return void(loaded |= loads_materials(w));
    if (s != Statement::f && s != Statement::l && s != Statement::p) return;
    corners.clear();
    for (Corner c; next_corner(w, defined, c);) corners.push_back(c);
    meter.add(corners.size());
    if (s == Statement::p) {
      for (const Corner& c : corners) mesh.points[static_cast<std::size_t>(point++)] = c.v;
      return;
    }
    if (s == Statement::l) {
      for (std::size_t k = 0; k + 1 < corners.size(); ++k)
        mesh.segments[static_cast<std::size_t>(segment++)] = {corners[k].v, corners[k + 1].v};
      return;
    }
    const std::size_t n = corners.size(), t = static_cast<std::size_t>(triangle);
    triangle += static_cast<std::int64_t>(n) - 2;
    piece.any_material |= look.material;
    for (const Corner& c : corners) piece.all_normals &= c.vn != kNone;
    for (std::size_t k = 0; k + 2 < n; ++k) put_look(out, t + k, look);
    if (n == 3) return put_corners(out, t, {corners[0], corners[1], corners[2]});
    stash_corners(out, t, corners);
    piece.polygons.push_back({static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(n)});
  });
}

// ---- Pass 3: splitting -------------------------------------------------------------------------------

// The face of `n` corners stashed at triangle t, split into its n - 2 triangles (PolygonSplitter: a quad on
// its shorter diagonal, as tinyobjloader splits one; more corners by ear clipping in the face's plane).
class Splitter {
 public:
  explicit Splitter(detail::ReadMeter* meter) : split_(meter) {}
  void split(Out& out, std::size_t t, std::size_t n) {
    const Mesh& mesh = out.mesh;
    const auto* v = reinterpret_cast<const std::uint32_t*>(&mesh.triangles[t]);
    const auto* vn = mesh.normal_triangles.empty()
                         ? nullptr
                         : reinterpret_cast<const std::uint32_t*>(&mesh.normal_triangles[t]);
    const auto* vt =
        out.plan.textured ? reinterpret_cast<const std::uint32_t*>(&mesh.uv_triangles[t]) : nullptr;
    corners_.resize(n), polygon_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      corners_[k] = {v[k], vt ? vt[k] : kNone, vn ? vn[k] : kNone};
      polygon_[k] = mesh.positions[v[k]];
    }
    pieces_.clear();
    split_.split(polygon_, pieces_);
    for (std::size_t k = 0; k < pieces_.size(); ++k)
      put_corners(out, t + k, {corners_[pieces_[k][0]], corners_[pieces_[k][1]], corners_[pieces_[k][2]]});
  }

 private:
  PolygonSplitter split_;
  std::vector<Corner> corners_;
  std::vector<Vec3> polygon_;
  std::vector<std::array<std::uint32_t, 3>> pieces_;
};

// ---- Putting it together -----------------------------------------------------------------------------

// The text in pieces of about kPieceBytes (or `piece_bytes`), each ending at a line end.
std::vector<Piece> pieces_of(std::string_view text, std::size_t piece_bytes) {
  std::vector<Piece> pieces;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = std::min(text.size(), at + std::max<std::size_t>(piece_bytes, 1));
    if (end < text.size()) {
      const std::size_t eol = text.find('\n', end - 1);
      end = eol == std::string_view::npos ? text.size() : eol + 1;
    }
    pieces.push_back({});
    pieces.back().begin = at, pieces.back().end = end;
    at = end;
  }
  return pieces;
}

// What the counts say of the whole text: where each piece's things go, what the mesh holds, and the first
// error a reader of the lines in order meets, when the counts show there is one (check_obj_text).
struct Whole {
  Plan plan;
  bool cloud = false;  ///< only vertices: a point cloud, every vertex a point
  bool any_usemtl = false;
  std::vector<std::string_view> mtllibs;  ///< in file order
};

Whole sum_pieces(std::string_view text, std::vector<Piece>& pieces, const Limits& limits) {
  Whole w;
  Plan& plan = w.plan;
  bool wrong = false, material_loaded = false;
  std::string_view material;
  for (Piece& p : pieces) {
    p.first_v = plan.v, p.first_vt = plan.vt, p.first_vn = plan.vn, p.first_triangle = plan.triangles;
    p.first_segment = plan.segments, p.first_point = plan.point_refs;
    p.material_before = material, p.has_material_before = w.any_usemtl;
    p.material_before_loaded = material_loaded, p.loaded = !w.mtllibs.empty();
    if (p.material) {
      material = {p.material, p.material_size}, w.any_usemtl = true;
      material_loaded = !w.mtllibs.empty() || p.loaded_before_material;
    }
    w.mtllibs.insert(w.mtllibs.end(), p.mtllibs.begin(), p.mtllibs.end());
    plan.v += p.v, plan.vt += p.vt, plan.vn += p.vn, plan.faces += p.faces, plan.triangles += p.triangles;
    plan.segments += p.segments, plan.point_lines += p.point_lines, plan.point_refs += p.point_refs;
    wrong |= p.wrong;
  }
  if (wrong || plan.faces > limits.max_model_faces || plan.point_refs > limits.max_model_points) {
    check_obj_text(text, limits);
    model_error(0, "the model could not be read consistently");
  }
  if (plan.v == 0) {
    check_obj_text(text, limits);  // a face naming no vertex is the error, not the emptiness
    model_error(0, "the model is empty: it defines no vertices");
  }
  w.cloud = plan.faces == 0 && plan.segments == 0 && plan.point_lines == 0;
  if (w.cloud && plan.v > limits.max_model_points) {
    check_obj_text(text, limits);
    throw SceneError(ErrorKind::limit,
                     "the model has more than " + std::to_string(limits.max_model_points) + " points");
  }
  return w;
}

// Every array the mesh holds, asked of the budget and made once, at its size.
void make_arrays(const Whole& w, Out& out, const Limits& limits) {
  const Plan& plan = w.plan;
  Mesh& mesh = out.mesh;
  const auto v = static_cast<std::size_t>(plan.v), t = static_cast<std::size_t>(plan.triangles);
  const auto vt = static_cast<std::size_t>(plan.vt), vn = static_cast<std::size_t>(plan.vn);
  const std::size_t per_triangle = sizeof(mesh.triangles[0]) + (vn ? sizeof(mesh.normal_triangles[0]) : 0) +
                                   (plan.textured ? sizeof(mesh.uv_triangles[0]) + sizeof(std::int32_t) : 0) +
                                   (plan.materials ? sizeof(Rgba8) : 0) +
                                   (mesh.materials.empty() ? 0 : sizeof(std::int32_t));
  const std::size_t bytes =
      v * sizeof(Vec3f) + vn * sizeof(Vec3f) + (plan.textured ? (vt + 1) * sizeof(mesh.uvs[0]) : 0) +
      t * per_triangle + static_cast<std::size_t>(plan.segments) * sizeof(mesh.segments[0]) +
      static_cast<std::size_t>(w.cloud ? plan.v : plan.point_refs) * sizeof(std::uint32_t);
  detail::reserve(limits, static_cast<std::int64_t>(bytes), [&] {
    return "the model's " + std::to_string(plan.faces) + " faces and " + std::to_string(plan.v) + " vertices";
  });
  auto make = [](auto& array, std::size_t n) { detail::reserve_huge(array, n), array.resize(n); };
  make(mesh.positions, v);
  if (vn) make(mesh.normals, vn), make(mesh.normal_triangles, t);
  make(mesh.triangles, t);
  make(mesh.segments, static_cast<std::size_t>(plan.segments));
  make(mesh.points, static_cast<std::size_t>(plan.point_refs));
  if (plan.textured) {
    make(mesh.uvs, vt + 1);  // the last: (0, 0), for faces without their own
    make(mesh.uv_triangles, t), make(mesh.face_textures, t);
  }
  if (plan.materials) make(out.face_colors, t);
  if (!mesh.materials.empty()) make(mesh.face_materials, t);
}

// Pass 3, then what the pieces found together decides what the mesh keeps.
void finish(const Whole& w, std::vector<Piece>& pieces, Out& out, int threads, const Limits& limits,
            const Uploads& files) {
  // Faces of more corners: quads in each piece at once, larger ones in order (their splitting is counted
  // against one budget).
  detail::run_pieces(threads, pieces.size(), [&](std::size_t i) {
    Splitter quads(nullptr);
    for (const auto& [first, corners] : pieces[i].polygons)
      if (corners == 4) quads.split(out, first, 4);
  });
  detail::ReadMeter meter(limits);
  Splitter larger(&meter);
  for (const Piece& p : pieces)
    for (const auto& [first, corners] : p.polygons)
      if (corners > 4) larger.split(out, first, corners);
  Mesh& mesh = out.mesh;
  decode_textures(w.plan.materials_of.textures, files, limits, mesh.textures);
  std::int64_t coloured = 0;
  bool all_normals = true, any_material = false;
  for (const Piece& p : pieces)
    coloured += p.coloured, all_normals &= p.all_normals, any_material |= p.any_material;
  if (coloured == w.plan.v) mesh.colors = std::move(out.colors);
  // Normals are used only when every face has them; otherwise they are computed, smooth within the crease.
  if (!all_normals || mesh.triangles.empty()) mesh.normals.clear(), mesh.normal_triangles.clear();
  mesh.crease_deg = kModelCreaseDeg;
  if (any_material) mesh.face_colors = std::move(out.face_colors);
  if (w.cloud) {
    mesh.points.resize(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.points.size(); ++i) mesh.points[i] = i;
  }
  if (mesh.triangles.empty() && mesh.segments.empty() && mesh.points.empty())
    model_error(0, "the model has no faces, lines or points to draw");
}

}  // namespace

Mesh read_obj_text(std::string_view obj_text, std::string_view mtl_text, const Limits& limits,
                   const Uploads& files, std::size_t piece_bytes) {
  const int threads = limits.threads > 0
                          ? limits.threads
                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<Piece> pieces = pieces_of(obj_text, piece_bytes);
  detail::run_pieces(threads, pieces.size(),
                     [&](std::size_t i) { count_piece(obj_text, pieces[i], limits); });
  // Checked first: names and tokens of the model are quoted in its errors.
  if (std::any_of(pieces.begin(), pieces.end(), [](const Piece& p) { return p.bad_utf8; }))
    require_utf8(obj_text, "the model (OBJ)", true);
  require_utf8(mtl_text, "the materials (MTL)", true);
  Whole w = sum_pieces(obj_text, pieces, limits);

  // The materials, whose errors come after the OBJ's own (held until the text is read).
  Mesh mesh;
  MtlPass mtl;
  std::exception_ptr mtl_failed;
  if (!w.mtllibs.empty()) try {
      w.plan.materials_of = read_materials(mtl_text, w.mtllibs, files, mtl, mesh);
    } catch (const SceneError&) {
      mtl_failed = std::current_exception();  // the text is still read, for an error of its own first
      mesh.materials.clear();
    }
  else if (!mtl_text.empty())  // sent with a model that loads no library: unused, still checked (as 0.4 did)
    try {
      (void)read_mtl(mtl_text);
    } catch (const SceneError&) {
      mtl_failed = std::current_exception();
    }
  w.plan.materials = w.any_usemtl && !w.plan.materials_of.list.empty();
  w.plan.textured = !w.plan.materials_of.textures.maps.empty();
  w.plan.no_uv = static_cast<std::uint32_t>(w.plan.vt);

  Out out{mesh, w.plan, limits, {}, {}, {}};
  make_arrays(w, out, limits);
  try {
    detail::run_pieces(threads, pieces.size(),
                       [&](std::size_t i) { read_piece(obj_text, pieces[i], out, limits); });
  } catch (const Wrong&) {
    check_obj_text(obj_text, limits);
    model_error(0, "the model could not be read consistently");
  }
  if (mtl_failed) std::rethrow_exception(mtl_failed);
  finish(w, pieces, out, threads, limits, files);
  return mesh;
}

}  // namespace raster::obj

namespace raster {

Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text, const Limits& limits,
               const Uploads& files) {
  return obj::read_obj_text(obj_text, mtl_text, limits, files, obj::kPieceBytes);
}

}  // namespace raster
