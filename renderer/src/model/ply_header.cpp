// PLY's header: its lines read into elements and properties, and the vertex and face elements checked
// against the data that follows (model/ply_header.h).
#include "model/ply_header.h"

#include <algorithm>
#include <charconv>

#include "model/reading.h"

namespace raster::ply {
namespace {

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

}  // namespace

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

// The fewest bytes one instance of `e` takes: binary, its scalars and each list's length; ASCII, one
// character and a separator per value.
std::uint64_t min_bytes(const Element& e, Encoding enc) {
  std::uint64_t n = 0;
  for (const Property& p : e.properties)
    n += enc == Encoding::ascii ? 2 : kSize[static_cast<int>(p.list ? p.count_type : p.type)];
  return n;
}

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
    detail::too_many_faces(limits.max_model_faces);
  if (std::none_of(l.face->properties.begin(), l.face->properties.end(),
                   [](const Property& p) { return p.role == Role::indices; }))
    ply_error("the face element has no \"vertex_indices\" list", l.face->line);
  l.normals = has[int(Role::nx)] && has[int(Role::ny)] && has[int(Role::nz)];
  l.colours = has[int(Role::red)] && has[int(Role::green)] && has[int(Role::blue)];
  return l;
}

}  // namespace raster::ply
