// PLY models (Turk's polygon file format, as scanners and MeshLab write it): a text header of elements
// and their properties, then the data in ASCII or binary of either byte order. The vertex element gives
// positions and, when present, normals and colours; the face element gives index lists. Every count the
// header declares is checked against the bytes that are left before anything is sized from it.
//
// parse_ply in three steps: the header (read_header, then check_elements against the data's size), the
// data element by element (read_fixed for binary entries of one size, read_values value by value for the
// rest), and the faces, split into triangles as they come (Faces).
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "model/polygon.h"
#include "raster/model.h"

namespace raster {
namespace {

[[noreturn]] void ply_error(const std::string& message, std::size_t line = 0, std::size_t byte = 0) {
  throw SceneError(ErrorKind::model, "PLY: " + message, ErrorLocation{"", byte, line});
}

enum class Type : std::uint8_t { i8, u8, i16, u16, i32, u32, f32, f64 };
constexpr int kSize[] = {1, 1, 2, 2, 4, 4, 4, 8};

bool type_named(std::string_view name, Type& type) {
  static constexpr std::pair<std::string_view, Type> kTypes[] = {
      {"char", Type::i8},   {"int8", Type::i8},     {"uchar", Type::u8},   {"uint8", Type::u8},
      {"short", Type::i16}, {"int16", Type::i16},   {"ushort", Type::u16}, {"uint16", Type::u16},
      {"int", Type::i32},   {"int32", Type::i32},   {"uint", Type::u32},   {"uint32", Type::u32},
      {"float", Type::f32}, {"float32", Type::f32}, {"double", Type::f64}, {"float64", Type::f64}};
  for (const auto& [n, t] : kTypes)
    if (n == name) return type = t, true;
  return false;
}

// What the reader does with a property of the vertex or face element.
enum class Role : std::uint8_t { none, x, y, z, nx, ny, nz, red, green, blue, alpha, indices };

struct Property {
  std::string name;
  Type type = Type::f32;
  bool list = false;
  Type count_type = Type::u8;  ///< lists: the type of the length before the items
  Role role = Role::none;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::size_t line = 0;  ///< the header line that declares it
};

enum class Encoding : std::uint8_t { ascii, little, big };

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  std::size_t data = 0;   ///< byte offset of the first data byte
  std::size_t lines = 0;  ///< lines in the header, for ASCII data's line numbers
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

Role role_of(std::string_view element, std::string_view property) {
  if (element == "vertex") {
    static constexpr std::pair<std::string_view, Role> kRoles[] = {{"x", Role::x},
                                                                   {"y", Role::y},
                                                                   {"z", Role::z},
                                                                   {"nx", Role::nx},
                                                                   {"ny", Role::ny},
                                                                   {"nz", Role::nz},
                                                                   {"red", Role::red},
                                                                   {"green", Role::green},
                                                                   {"blue", Role::blue},
                                                                   {"alpha", Role::alpha},
                                                                   {"r", Role::red},
                                                                   {"g", Role::green},
                                                                   {"b", Role::blue},
                                                                   {"diffuse_red", Role::red},
                                                                   {"diffuse_green", Role::green},
                                                                   {"diffuse_blue", Role::blue}};
    for (const auto& [n, r] : kRoles)
      if (n == property) return r;
  }
  if (element == "face" && (property == "vertex_indices" || property == "vertex_index")) return Role::indices;
  return Role::none;
}

Header read_header(std::string_view bytes) {
  Header h;
  std::size_t at = 0;
  bool format_seen = false;
  while (true) {
    const std::size_t eol = bytes.find('\n', at);
    if (eol == std::string_view::npos) ply_error("the header has no \"end_header\" line", h.lines + 1);
    const std::string_view line = bytes.substr(at, eol - at);
    at = eol + 1;
    ++h.lines;
    const std::vector<std::string_view> w = split(line);
    if (h.lines == 1) continue;  // "ply", which sniff_model or the caller checked
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() < 3 || w[2] != "1.0") ply_error("expected \"format <encoding> 1.0\"", h.lines);
      if (w[1] == "ascii")
        h.encoding = Encoding::ascii;
      else if (w[1] == "binary_little_endian")
        h.encoding = Encoding::little;
      else if (w[1] == "binary_big_endian")
        h.encoding = Encoding::big;
      else
        ply_error("unknown format \"" + std::string(w[1].substr(0, 40)) +
                      "\"; expected ascii, binary_little_endian or binary_big_endian",
                  h.lines);
      format_seen = true;
    } else if (w[0] == "element") {
      std::uint64_t count = 0;
      if (w.size() != 3) ply_error("expected \"element <name> <count>\"", h.lines);
      const auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), count);
      if (ec == std::errc::result_out_of_range)
        ply_error("element \"" + std::string(w[1].substr(0, 40)) + "\" declares " +
                      std::string(w[2].substr(0, 40)) + " entries, more than any file holds",
                  h.lines);
      if (ec != std::errc() || end != w[2].data() + w[2].size())
        ply_error("expected \"element <name> <count>\", with a whole number as the count", h.lines);
      h.elements.push_back({std::string(w[1]), count, {}, h.lines});
    } else if (w[0] == "property") {
      if (h.elements.empty()) ply_error("a property before any element", h.lines);
      Element& e = h.elements.back();
      Property p;
      bool ok = false;
      if (w.size() == 5 && w[1] == "list") {
        p.list = true;
        ok = type_named(w[2], p.count_type) && type_named(w[3], p.type);
        if (ok && (p.count_type == Type::f32 || p.count_type == Type::f64))
          ply_error("a list's length must have an integer type, not \"" + std::string(w[2]) + "\"", h.lines);
        p.name = w[4];
      } else if (w.size() == 3) {
        ok = type_named(w[1], p.type);
        p.name = w[2];
      }
      if (!ok)
        ply_error("expected \"property <type> <name>\" or \"property list <type> <type> <name>\"", h.lines);
      p.role = role_of(e.name, p.name);
      if ((p.role == Role::indices) != p.list) p.role = Role::none;  // a scalar "vertex_indices", a list "x"
      e.properties.push_back(std::move(p));
    }
    // Any other line is passed over, as other readers do: old Blender wrote "Created by Blender3D 247 - ..."
    // without "comment".
  }
  if (!format_seen) ply_error("the header has no \"format\" line", 2);
  h.data = at;
  return h;
}

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

// The fewest bytes one instance of `e` takes: binary, its scalars and each list's length; ASCII, one
// character and a separator per value.
std::uint64_t min_bytes(const Element& e, Encoding enc) {
  std::uint64_t n = 0;
  for (const Property& p : e.properties)
    n += enc == Encoding::ascii ? 2 : kSize[static_cast<int>(p.list ? p.count_type : p.type)];
  return n;
}

std::uint8_t colour_byte(double v, Type t) {
  if (!std::isfinite(v)) return 0;
  const double unit = t == Type::f32 || t == Type::f64 ? v : t == Type::u16 ? v / 65535 : v / 255;
  return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255));
}

// The vertex and face elements of a header, checked against the data after it before anything is sized
// from their counts, and what the vertices hold.
struct Layout {
  const Element* vertex = nullptr;  ///< the "vertex" element, which has x, y and z
  const Element* face = nullptr;    ///< the "face" element, which has a list of vertex indices
  bool normals = false;             ///< the vertices have nx, ny and nz
  bool colours = false;             ///< the vertices have red, green and blue
};

Layout check_elements(const Header& h, std::size_t data_bytes, const Limits& limits) {
  Layout l;
  for (const Element& e : h.elements) {
    // Checked before anything is sized from a count: a 100-byte file can declare 2^60 vertices.
    const std::uint64_t least = min_bytes(e, h.encoding);
    if (e.count > 0 && least > 0 && e.count > (data_bytes + 1) / least)
      ply_error("element \"" + e.name + "\" declares " + std::to_string(e.count) + " entries, but the " +
                    std::to_string(data_bytes) + " bytes of data after the header cannot hold them",
                e.line);
    if (e.name == "vertex") l.vertex = &e;
    if (e.name == "face") l.face = &e;
  }
  if (!l.vertex || l.vertex->count == 0) ply_error("the model has no vertices (no \"element vertex\")");
  bool has[12] = {};
  for (const Property& p : l.vertex->properties) has[static_cast<int>(p.role)] = true;
  if (!has[int(Role::x)] || !has[int(Role::y)] || !has[int(Role::z)])
    ply_error("the vertex element has no x, y and z properties", l.vertex->line);
  if (!l.face || l.face->count == 0) {
    // A point cloud (what scanners and photogrammetry write): every vertex is drawn as a point.
    l.face = nullptr;
    if (l.vertex->count > static_cast<std::uint64_t>(limits.max_model_points))
      throw SceneError(ErrorKind::limit,
                       "the model has more than " + std::to_string(limits.max_model_points) + " points");
    l.colours = has[int(Role::red)] && has[int(Role::green)] && has[int(Role::blue)];
    return l;
  }
  if (l.face->count > static_cast<std::uint64_t>(limits.max_model_faces))
    throw SceneError(ErrorKind::limit,
                     "the model has more than " + std::to_string(limits.max_model_faces) + " faces");
  if (std::none_of(l.face->properties.begin(), l.face->properties.end(),
                   [](const Property& p) { return p.role == Role::indices; }))
    ply_error("the face element has no \"vertex_indices\" list", l.face->line);
  l.normals = has[int(Role::nx)] && has[int(Role::ny)] && has[int(Role::nz)];
  l.colours = has[int(Role::red)] && has[int(Role::green)] && has[int(Role::blue)];
  return l;
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
      throw SceneError(ErrorKind::limit,
                       "the model has more than " + std::to_string(limits.max_model_faces) + " faces");
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
      throw SceneError(ErrorKind::limit,
                       "the model has more than " + std::to_string(limits.max_model_faces) + " faces");
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
  // The header counts what the mesh will hold (faces of more than three corners become more triangles,
  // each of which the limit counts, so at most max_model_faces of them).
  const std::uint64_t face_count = l.face ? l.face->count : 0;
  detail::reserve(limits,
                  cost::kPlyPerFace * static_cast<std::int64_t>(face_count) +
                      cost::kPlyPerVertex * static_cast<std::int64_t>(l.vertex->count),
                  [&] {
                    return "the model's " + std::to_string(face_count) + " faces and " +
                           std::to_string(l.vertex->count) + " vertices";
                  });

  Mesh mesh;
  Values in(bytes, h);
  Faces faces(mesh, limits);
  for (const Element& e : h.elements) {
    // An element without properties holds no bytes, however many entries it declares (6e9 of them took a
    // fuzzed file 12 s to count through).
    if (e.properties.empty()) continue;
    if (&e == l.vertex) {
      mesh.positions.resize(e.count);
      if (l.normals) mesh.normals.resize(e.count);
      if (l.colours) mesh.colors.resize(e.count);
    } else if (&e == l.face) {
      mesh.triangles.reserve(e.count);
    }
    const bool fixed =
        std::none_of(e.properties.begin(), e.properties.end(), [](const Property& p) { return p.list; });
    if (!in.ascii() && fixed)
      read_fixed(e, l, h, bytes.size(), in, mesh, faces.meter);
    else
      read_values(e, l, in, mesh, faces);
  }
  faces.add_early();
  if (!l.face) {  // a point cloud: its vertices are its points; they carry no normal (points are unlit)
    mesh.normals.clear();
    mesh.points.resize(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.points.size(); ++i) mesh.points[i] = i;
    return mesh;
  }
  if (mesh.triangles.empty()) ply_error("the model's faces have no three corners to draw");
  // A face's corners are vertices, so normals are indexed as positions are.
  if (l.normals) mesh.normal_triangles = mesh.triangles;
  return mesh;
}

}  // namespace raster
