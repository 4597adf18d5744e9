// PLY models (Turk's polygon file format, as scanners and MeshLab write it): a text header of elements
// and their properties, then the data in ASCII or binary of either byte order. The vertex element gives
// positions and, when present, normals and colours; the face element gives index lists. Every count the
// header declares is checked against the bytes that are left before anything is sized from it.
//
// parse_ply in three steps: the header (ply_header.cpp: read_header, then check_elements against the data's
// size), the data element by element (read_fixed for binary entries of one size, read_direct_faces for the
// common binary face list, read_values value by value for the rest), and the faces, split into triangles
// as they come (Faces).
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "base/memory.h"
#include "model/ply_header.h"
#include "model/polygon.h"
#include "model/reading.h"
#include "raster/model.h"

namespace raster {
namespace {

using namespace ply;  // the header's types (model/ply_header.h)

using mesh_triangle = std::array<std::uint32_t, 3>;  // what Mesh::triangles holds

template <typename T>
T load_as(const unsigned char* p, bool swapped) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof b);
  if (swapped) std::reverse(b, b + sizeof b);
  return std::bit_cast<T>(b);
}

// One binary value of type t at p, in the file's byte order (swapped: not this machine's).
double load(const unsigned char* p, Type t, bool swapped) {
  switch (t) {
    case Type::i8:
      return static_cast<std::int8_t>(p[0]);
    case Type::u8:
      return p[0];
    case Type::i16:
      return load_as<std::int16_t>(p, swapped);
    case Type::u16:
      return load_as<std::uint16_t>(p, swapped);
    case Type::i32:
      return load_as<std::int32_t>(p, swapped);
    case Type::u32:
      return load_as<std::uint32_t>(p, swapped);
    case Type::f32:
      return load_as<float>(p, swapped);
    case Type::f64:
      return load_as<double>(p, swapped);
  }
  return 0;
}

// The data of the elements, one value at a time, in the file's encoding.
class Values {
 public:
  Values(std::string_view bytes, const Header& h)
      : bytes_(bytes), at_(h.data), line_(h.lines + 1), enc_(h.encoding) {}

  std::size_t left() const { return bytes_.size() - at_; }
  /// The byte offset of `p`, a pointer into the data take() gave.
  std::size_t offset_of(const unsigned char* p) const {
    return static_cast<std::size_t>(p - reinterpret_cast<const unsigned char*>(bytes_.data()));
  }
  bool ascii() const { return enc_ == Encoding::ascii; }
  std::size_t line() const { return line_; }
  std::size_t byte() const { return at_ + 1; }

  double read(Type t) { return ascii() ? read_text() : read_binary(t); }

  // Binary: the next n bytes, which the caller checked are there (n <= left()).
  const unsigned char* take(std::size_t n) {
    const unsigned char* p = reinterpret_cast<const unsigned char*>(bytes_.data()) + at_;
    at_ += n;
    return p;
  }
  bool swapped() const { return (enc_ == Encoding::big) != (std::endian::native == std::endian::big); }

  // Skips n values of type t (binary: without looking at them).
  void skip(Type t, std::uint64_t n) {
    if (!ascii()) {
      at_ +=
          static_cast<std::size_t>(n) * kSize[static_cast<int>(t)];  // checked against left() by the caller
      return;
    }
    for (std::uint64_t i = 0; i < n; ++i) read_text();
  }

 private:
  double read_binary(Type t) {
    if (left() < static_cast<std::size_t>(kSize[static_cast<int>(t)]))
      ply_error("the data ends early", 0, bytes_.size());
    return load(take(kSize[static_cast<int>(t)]), t, swapped());
  }
  double read_text() {
    while (at_ < bytes_.size()) {
      const char c = bytes_[at_];
      if (c == '\n')
        ++line_;
      else if (c != ' ' && c != '\t' && c != '\r')
        break;
      ++at_;
    }
    const std::size_t start = at_;
    while (at_ < bytes_.size() && bytes_[at_] != ' ' && bytes_[at_] != '\t' && bytes_[at_] != '\r' &&
           bytes_[at_] != '\n')
      ++at_;
    std::string_view w = bytes_.substr(start, at_ - start);
    if (w.empty()) ply_error("the data ends early", line_);
    if (w.size() > 1 && w[0] == '+') w.remove_prefix(1);
    double v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size())
      ply_error("expected a number, got \"" + std::string(w.substr(0, 40)) + "\"", line_);
    return v;
  }

  std::string_view bytes_;
  std::size_t at_;
  std::size_t line_;
  Encoding enc_;
};

// A colour property's value as a byte: floats are 0..1, ushorts 0..65535, other integers 0..255.
std::uint8_t colour_byte(double v, Type t) {
  if (!std::isfinite(v)) return 0;
  return detail::unit_byte(t == Type::f32 || t == Type::f64 ? v : t == Type::u16 ? v / 65535 : v / 255);
}

// What the vertex element's value of a property with `role` sets.
inline void set_vertex_value(Role role, double v, Type type, Vec3& pos, Vec3& normal, Rgba8& colour) {
  switch (role) {
    case Role::x:
      pos.x = v;
      break;
    case Role::y:
      pos.y = v;
      break;
    case Role::z:
      pos.z = v;
      break;
    case Role::nx:
      normal.x = v;
      break;
    case Role::ny:
      normal.y = v;
      break;
    case Role::nz:
      normal.z = v;
      break;
    case Role::red:
      colour.r = colour_byte(v, type);
      break;
    case Role::green:
      colour.g = colour_byte(v, type);
      break;
    case Role::blue:
      colour.b = colour_byte(v, type);
      break;
    case Role::alpha:
      colour.a = colour_byte(v, type);
      break;
    default:
      break;
  }
}

// Vertex i, once its properties are read, into the mesh (sized for every vertex by then).
inline void store(Mesh& mesh, const Layout& l, const Values& in, std::uint64_t i, const Vec3& pos,
                  const Vec3& normal, Rgba8 colour) {
  if (!(std::fabs(pos.x) <= kMaxCoordinate && std::fabs(pos.y) <= kMaxCoordinate &&
        std::fabs(pos.z) <= kMaxCoordinate))
    ply_error("vertex " + std::to_string(i) + " has a coordinate that is not a finite number within +-2^128",
              in.ascii() ? in.line() : 0, in.ascii() ? 0 : in.byte());
  mesh.positions[i] = Vec3f(pos);
  if (l.normals) mesh.normals[i] = Vec3f(normal);
  if (l.colours) mesh.colors[i] = colour;
}

// Binary entries of one size (no lists): checked once for the whole element, then each vertex property
// read at its offset, the others passed over, rather than value by value; another element is skipped.
void read_fixed(const Element& e, const Layout& l, const Header& h, std::size_t file_size, Values& in,
                Mesh& mesh, detail::ReadMeter& meter) {
  const std::uint64_t stride = min_bytes(e, h.encoding);
  if (e.count * stride > in.left())  // e.count <= data bytes / stride: no overflow
    ply_error("element \"" + e.name + "\" ends after the data", e.line, file_size);
  if (&e != l.vertex) return void(in.take(static_cast<std::size_t>(e.count * stride)));
  struct Field {
    std::size_t offset;  ///< bytes from the entry's start
    Type type;
    Role role;
  };
  std::vector<Field> fields;
  std::size_t offset = 0;
  for (const Property& p : e.properties) {
    if (p.role != Role::none) fields.push_back({offset, p.type, p.role});
    offset += kSize[static_cast<int>(p.type)];
  }
  const bool swapped = in.swapped();
  // The common layout (float coordinates and normals, uchar colours, in this machine's byte order) copied
  // field by field without a conversion per value, its coordinates checked once for the whole element.
  const bool direct = !swapped && std::all_of(fields.begin(), fields.end(), [](const Field& f) {
    return f.role >= Role::red && f.role <= Role::alpha ? f.type == Type::u8 : f.type == Type::f32;
  });
  if (direct) {
    const unsigned char* entries = in.take(static_cast<std::size_t>(e.count * stride));
    float* position = &mesh.positions[0].x;
    float* normal = l.normals ? &mesh.normals[0].x : nullptr;
    std::uint8_t* colour = l.colours ? &mesh.colors[0].r : nullptr;
    std::uint32_t exponents = 0;  // the coordinates' exponents: all ones is an infinity or a NaN
    for (std::uint64_t i = 0; i < e.count; ++i) {
      meter.add(1);
      const unsigned char* entry = entries + i * stride;
      for (const Field& f : fields) {
        const int r = static_cast<int>(f.role);
        if (f.role <= Role::z) {
          std::uint32_t bits;
          std::memcpy(&bits, entry + f.offset, 4);
          exponents |= (bits & 0x7f800000u) == 0x7f800000u;
          std::memcpy(position + 3 * i + (r - int(Role::x)), &bits, 4);
        } else if (f.role <= Role::nz) {
          if (normal) std::memcpy(normal + 3 * i + (r - int(Role::nx)), entry + f.offset, 4);
        } else if (colour) {
          colour[4 * i + (r - int(Role::red))] = entry[f.offset];
        }
      }
    }
    if (!exponents) return;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const Vec3f& q = mesh.positions[i];
      if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z)))
        ply_error(
            "vertex " + std::to_string(i) + " has a coordinate that is not a finite number within +-2^128", 0,
            in.offset_of(entries + i * stride) + 1);
    }
    return;
  }
  for (std::uint64_t i = 0; i < e.count; ++i) {
    meter.add(1);
    const unsigned char* entry = in.take(static_cast<std::size_t>(stride));
    Vec3 pos, normal;
    Rgba8 colour;
    for (const Field& f : fields)
      set_vertex_value(f.role, load(entry + f.offset, f.type, swapped), f.type, pos, normal, colour);
    store(mesh, l, in, i, pos, normal, colour);
  }
}

// The faces, split into triangles as they come; those read before the vertices (legal, if rare) are kept,
// their corners one after another and how many each has, and split once the positions are known.
struct Faces {
  Faces(Mesh& m, const Limits& l) : mesh(m), limits(l) {}
  Mesh& mesh;
  const Limits& limits;
  /// The reader's deadline meter: entries, list items and ear clipping's point tests are its units.
  detail::ReadMeter meter{limits};
  std::vector<std::uint32_t> corners;                // the face at hand's vertices
  std::vector<Vec3> polygon;                         // their positions, for a face of more than three
  std::vector<std::array<std::uint32_t, 3>> pieces;  // its triangles, as indices into corners
  PolygonSplitter splitter{&meter};
  std::vector<std::uint32_t> early_corners, early_sizes;
  std::size_t early_triangles = 0;

  // The face at hand, now or once the vertices are read.
  void add_or_keep() {
    if (!mesh.positions.empty()) return add();
    early_triangles += corners.size() - 2;
    if (early_triangles > static_cast<std::size_t>(limits.max_model_faces))
      detail::too_many_faces(limits.max_model_faces);
    early_corners.insert(early_corners.end(), corners.begin(), corners.end());
    early_sizes.push_back(static_cast<std::uint32_t>(corners.size()));
  }
  void add_early() {
    for (std::size_t f = 0, at = 0; f < early_sizes.size(); at += early_sizes[f++]) {
      meter.add(early_sizes[f]);
      corners.assign(early_corners.begin() + at, early_corners.begin() + at + early_sizes[f]);
      add();
    }
  }
  void add() {
    // The limit counts triangles, as for STL and glTF: one face of a million corners is a million.
    if (mesh.triangles.size() + corners.size() - 2 > static_cast<std::size_t>(limits.max_model_faces))
      detail::too_many_faces(limits.max_model_faces);
    if (corners.size() == 3) {
      mesh.triangles.push_back({corners[0], corners[1], corners[2]});
      return;
    }
    polygon.clear(), pieces.clear();  // split as OBJ faces are
    for (const std::uint32_t c : corners) polygon.push_back(mesh.positions[c]);
    splitter.split(polygon, pieces);
    for (const auto& t : pieces) mesh.triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
  }
};

// List property p of entry i of element e: the face's vertex indices into `faces`, any other list passed
// over.
void read_list(const Element& e, const Property& p, std::uint64_t i, const Layout& l, Values& in,
               Faces& faces) {
  const double n = in.read(p.count_type);
  if (n != std::floor(n))  // ASCII: "3.5" is no length
    ply_error("a list's length in " + e.name + " " + std::to_string(i) + " is not a whole number", in.line());
  const std::uint64_t items = n >= 0 && n < 4294967296.0 ? static_cast<std::uint64_t>(n) : UINT64_MAX;
  if (items == UINT64_MAX || (!in.ascii() && items * kSize[int(p.type)] > in.left()) ||
      (in.ascii() && items > in.left()))
    ply_error("a list of " + std::to_string(n) + " items in " + e.name + " " + std::to_string(i) +
                  " is longer than the data left",
              in.line(), in.ascii() ? 0 : in.byte());
  if (p.role != Role::indices || &e != l.face) return in.skip(p.type, items);
  faces.meter.add(items);  // a list of a million corners is a million units of work
  std::vector<std::uint32_t>& corners = faces.corners;
  corners.clear();
  for (std::uint64_t k = 0; k < items; ++k) {
    const double v = in.read(p.type);
    if (!(v >= 0 && v < static_cast<double>(l.vertex->count)) || v != std::floor(v))
      ply_error("face " + std::to_string(i) + " refers to vertex " + std::to_string(v) + ", but there are " +
                    std::to_string(l.vertex->count),
                in.ascii() ? in.line() : 0, in.ascii() ? 0 : in.byte());
    corners.push_back(static_cast<std::uint32_t>(v));
  }
  if (corners.size() >= 3) faces.add_or_keep();
}

// The face element of the common binary layout, one list of int or uint indices and nothing else, in this
// machine's byte order: a triangle's three indices copied and checked at once, without a conversion per
// value. The same errors, at the same bytes, as read_list gives; other faces go the same way as there.
bool direct_faces(const Element& e, const Layout& l, const Values& in) {
  if (&e != l.face || in.ascii() || in.swapped() || e.properties.size() != 1) return false;
  const Property& p = e.properties[0];
  return p.role == Role::indices && (p.type == Type::i32 || p.type == Type::u32) &&
         (p.count_type == Type::u8 || p.count_type == Type::i8);
}

void read_direct_faces(const Element& e, const Layout& l, Values& in, Mesh& mesh, Faces& faces) {
  const std::uint64_t vertices = l.vertex->count;
  const bool signed_indices = e.properties[0].type == Type::i32;
  const auto limit = static_cast<std::size_t>(faces.limits.max_model_faces);
  for (std::uint64_t i = 0; i < e.count; ++i) {
    faces.meter.add(1);
    if (in.left() < 1) ply_error("the data ends early", 0, in.byte());
    const unsigned n = *in.take(1);
    if (n * 4 > in.left())
      ply_error("a list of " + std::to_string(static_cast<double>(n)) + " items in face " +
                    std::to_string(i) + " is longer than the data left",
                0, in.byte());
    const unsigned char* items = in.take(4 * n);
    faces.meter.add(n);
    std::uint32_t v[3];
    if (n == 3) {
      std::memcpy(v, items, 12);
      if (v[0] < vertices && v[1] < vertices && v[2] < vertices) {
        if (mesh.triangles.size() >= limit) detail::too_many_faces(faces.limits.max_model_faces);
        mesh.triangles.push_back({v[0], v[1], v[2]});
        continue;
      }
    }
    faces.corners.clear();
    for (unsigned k = 0; k < n; ++k) {
      std::uint32_t u;
      std::memcpy(&u, items + 4 * k, 4);
      const double value = signed_indices ? static_cast<double>(static_cast<std::int32_t>(u)) : u;
      if (!(value >= 0 && value < static_cast<double>(vertices)))
        ply_error("face " + std::to_string(i) + " refers to vertex " + std::to_string(value) +
                      ", but there are " + std::to_string(vertices),
                  0, in.offset_of(items + 4 * (k + 1)) + 1);
      faces.corners.push_back(u);
    }
    if (faces.corners.size() >= 3) faces.add_or_keep();
  }
}

// Element e value by value (ASCII, or binary with lists): vertices into the mesh, faces into `faces`.
void read_values(const Element& e, const Layout& l, Values& in, Mesh& mesh, Faces& faces) {
  for (std::uint64_t i = 0; i < e.count; ++i) {
    faces.meter.add(1);
    Vec3 pos, normal;
    Rgba8 colour;
    for (const Property& p : e.properties) {
      if (p.list) {
        read_list(e, p, i, l, in, faces);
        continue;
      }
      const double v = in.read(p.type);
      if (&e == l.vertex) set_vertex_value(p.role, v, p.type, pos, normal, colour);
    }
    if (&e == l.vertex) store(mesh, l, in, i, pos, normal, colour);
  }
}

}  // namespace

Mesh parse_ply(std::string_view bytes, const Limits& limits) {
  if (!(bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n")))
    ply_error("the file does not start with \"ply\" and a line break", 1);
  const Header h = read_header(bytes);
  const Layout l = check_elements(h, bytes.size() - h.data, limits);
  // The header counts what the mesh will hold: its arrays as they are, a triangle a face (faces of more
  // corners make more triangles, each of which the limit counts, asked for once they are read).
  const std::uint64_t face_count = l.face ? l.face->count : 0, vertices = l.vertex->count;
  const std::uint64_t per_vertex = sizeof(Vec3f) + (l.normals ? sizeof(Vec3f) : 0) +
                                   (l.colours ? sizeof(Rgba8) : 0) +
                                   (l.face ? 0 : sizeof(std::uint32_t));  // a cloud's points
  detail::reserve(limits,
                  static_cast<std::int64_t>(face_count * sizeof(mesh_triangle) + vertices * per_vertex), [&] {
                    return "the model's " + std::to_string(face_count) + " faces and " +
                           std::to_string(vertices) + " vertices";
                  });

  Mesh mesh;
  Values in(bytes, h);
  Faces faces(mesh, limits);
  for (const Element& e : h.elements) {
    // An element without properties holds no bytes, however many entries it declares (6e9 of them took a
    // fuzzed file 12 s to count through).
    if (e.properties.empty()) continue;
    if (&e == l.vertex) {
      detail::reserve_huge(mesh.positions, e.count), mesh.positions.resize(e.count);
      if (l.normals) detail::reserve_huge(mesh.normals, e.count), mesh.normals.resize(e.count);
      if (l.colours) detail::reserve_huge(mesh.colors, e.count), mesh.colors.resize(e.count);
    } else if (&e == l.face) {
      detail::reserve_huge(mesh.triangles, 2 * e.count);  // quads' two triangles: room taken only as written
    }
    const bool fixed =
        std::none_of(e.properties.begin(), e.properties.end(), [](const Property& p) { return p.list; });
    if (!in.ascii() && fixed)
      read_fixed(e, l, h, bytes.size(), in, mesh, faces.meter);
    else if (direct_faces(e, l, in))
      read_direct_faces(e, l, in, mesh, faces);
    else
      read_values(e, l, in, mesh, faces);
  }
  faces.add_early();
  if (mesh.triangles.size() > face_count)  // the triangles beyond a face's one
    detail::reserve(limits,
                    static_cast<std::int64_t>((mesh.triangles.size() - face_count) * sizeof(mesh_triangle)),
                    [] { return std::string("the model's polygons"); });
  if (!l.face) {  // a point cloud: its vertices are its points; they carry no normal (points are unlit)
    mesh.normals.clear();
    mesh.points.resize(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.points.size(); ++i) mesh.points[i] = i;
    return mesh;
  }
  if (mesh.triangles.empty()) ply_error("the model's faces have no three corners to draw");
  // A face's corners are vertices, so normals are indexed as positions are (no normal_triangles).
  mesh.crease_deg = kModelCreaseDeg;  // computed normals: smooth within the crease
  return mesh;
}

}  // namespace raster
