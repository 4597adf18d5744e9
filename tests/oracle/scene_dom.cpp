// Scene parsing: JSON text -> Scene. Every rejection names the JSON pointer (or byte offset) it concerns.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>

#include "base/base64.h"
#include "base/vecmath.h"
#include "raster/model.h"
#include "raster/scene.h"
#include "raster/shader.h"
#include "raster/utf8.h"
#include "scene_dom.h"

namespace raster::scene_json {

std::string Path::str() const {
  if (!parent_) return "";
  std::string out = parent_->str() + "/";
  if (!key_) return out + std::to_string(index_);
  for (const char* c = key_; *c; ++c) {
    if (*c == '~')
      out += "~0";
    else if (*c == '/')
      out += "~1";
    else
      out += *c;
  }
  return out;
}

namespace {

[[noreturn]] void fail(ErrorKind kind, const Path& at, const std::string& message) {
  throw SceneError(kind, message, ErrorLocation{at.str(), 0, 0});
}

[[noreturn]] void invalid(const Path& at, const std::string& message) {
  fail(ErrorKind::invalid, at, message);
}

const char* type_name(const json& v) {
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    case json::value_t::binary:
      return "binary data";
    case json::value_t::discarded:
      return "nothing";
    default:
      return "a number";
  }
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// Rejects any key not in `known`, suggesting the nearest known name when it is a plausible typo.
void check_keys(const json& obj, const Path& pointer, std::initializer_list<const char*> known) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string& key = it.key();
    if (std::any_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) continue;
    std::string best;
    std::size_t best_distance = 3;  // more than two edits away is not a typo
    for (const char* k : known) {
      std::size_t d = edit_distance(key, k);
      if (d < best_distance) best_distance = d, best = k;
    }
    std::string message = "unknown field \"" + key + "\"";
    if (!best.empty())
      message += "; did you mean \"" + best + "\"?";
    else {
      message += "; known fields are";
      for (const char* k : known) message += std::string(" \"") + k + "\"";
    }
    invalid(Path(pointer, key), message);
  }
}

double read_number(const json& v, const Path& pointer) {
  if (!v.is_number()) invalid(pointer, std::string("expected a number, got ") + type_name(v));
  double d = v.get<double>();
  // The JSON grammar has no NaN or Infinity, and the lexer rejects overflow; this guards the rest.
  if (!std::isfinite(d)) invalid(pointer, "number is not finite");
  return d;
}

// Integer fields accept 256 and 256.0 but not 256.5; the range check is the caller's.
std::int64_t read_integer(const json& v, const Path& pointer) {
  if (v.is_number_integer()) {
    if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
      return INT64_MAX;
    return v.get<std::int64_t>();
  }
  double d = read_number(v, pointer);
  if (d != std::floor(d)) invalid(pointer, "expected a whole number, got " + v.dump());
  if (std::fabs(d) >= 9.2e18) return d < 0 ? INT64_MIN : INT64_MAX;
  return static_cast<std::int64_t>(d);
}

bool read_bool(const json& v, const Path& pointer) {
  if (!v.is_boolean()) invalid(pointer, std::string("expected true or false, got ") + type_name(v));
  return v.get<bool>();
}

// Value of each byte as a hex digit, or -1: a table, because big scenes hold a colour per vertex.
constexpr std::array<std::int8_t, 256> kHexDigit = [] {
  std::array<std::int8_t, 256> t{};
  for (int c = 0; c < 256; ++c)
    t[c] = c >= '0' && c <= '9'   ? static_cast<std::int8_t>(c - '0')
           : c >= 'a' && c <= 'f' ? static_cast<std::int8_t>(c - 'a' + 10)
           : c >= 'A' && c <= 'F' ? static_cast<std::int8_t>(c - 'A' + 10)
                                  : std::int8_t{-1};
  return t;
}();

int hex_digit(char c) {
  return kHexDigit[static_cast<unsigned char>(c)];
}

std::uint8_t unit_to_byte(double v) {
  return static_cast<std::uint8_t>(std::floor(v * 255.0 + 0.5));
}

std::string hex_of(const std::vector<double>& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string s = "#";
  for (double b : bytes) {
    int i = static_cast<int>(b);
    s += digits[i >> 4];
    s += digits[i & 15];
  }
  return s;
}

}  // namespace

bool parse_hex_color(std::string_view s, Rgba8& out) {
  const std::size_t n = s.size();
  if (n == 0 || s[0] != '#' || (n != 4 && n != 5 && n != 7 && n != 9)) return false;
  int d[8] = {0, 0, 0, 0, 0, 0, 15, 15};  // absent alpha reads as "ff"
  int bad = 0;
  for (std::size_t i = 1; i < n; ++i) bad |= d[i - 1] = hex_digit(s[i]);
  if (bad < 0) return false;
  if (n <= 5) {  // "#rgb(a)": each digit doubled
    out = {static_cast<std::uint8_t>(d[0] * 17), static_cast<std::uint8_t>(d[1] * 17),
           static_cast<std::uint8_t>(d[2] * 17), static_cast<std::uint8_t>(n == 5 ? d[3] * 17 : 255)};
    return true;
  }
  out = {static_cast<std::uint8_t>(d[0] * 16 + d[1]), static_cast<std::uint8_t>(d[2] * 16 + d[3]),
         static_cast<std::uint8_t>(d[4] * 16 + d[5]), static_cast<std::uint8_t>(d[6] * 16 + d[7])};
  return true;
}

namespace {

// "#rgb", "#rgba", "#rrggbb", "#rrggbbaa", [r,g,b] or [r,g,b,a] with components in 0..1.
Rgba8 read_color(const json& v, const Path& pointer) {
  if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    Rgba8 c;
    if (!parse_hex_color(s, c))
      invalid(pointer,
              "expected a colour \"#rgb\", \"#rgba\", \"#rrggbb\" or \"#rrggbbaa\", got \"" + s + "\"");
    return c;
  }
  if (v.is_array()) {
    if (v.size() != 3 && v.size() != 4)
      invalid(pointer,
              "a colour array has 3 or 4 components [r, g, b(, a)], got " + std::to_string(v.size()));
    std::vector<double> comp;
    for (std::size_t k = 0; k < v.size(); ++k) comp.push_back(read_number(v[k], Path(pointer, k)));
    for (std::size_t k = 0; k < comp.size(); ++k) {
      if (comp[k] >= 0.0 && comp[k] <= 1.0) continue;
      std::string message = "colour components are in 0..1, got " + v[k].dump();
      // Hex is suggested only for components that all read as 0..255 bytes. A 1 among them reads as "full"
      // on the 0..1 scale ([1, 0, 0, 255] is opaque red with a slip, not #010000ff), and so does a
      // small array such as [1, 1, 2]: no guess then, only the range.
      const bool bytes = std::all_of(comp.begin(), comp.end(), [](double c) {
        return c >= 0 && c <= 255 && c == std::floor(c) && c != 1;
      });
      if (bytes) message += "; did you mean \"" + hex_of(comp) + "\"?";
      invalid(Path(pointer, k), message);
    }
    return {unit_to_byte(comp[0]), unit_to_byte(comp[1]), unit_to_byte(comp[2]),
            comp.size() == 4 ? unit_to_byte(comp[3]) : std::uint8_t{255}};
  }
  invalid(pointer, std::string("expected a colour (\"#rrggbb\" or [r, g, b]), got ") + type_name(v));
}

double read_coordinate(const json& v, const Path& pointer) {
  const double d = read_number(v, pointer);
  if (std::fabs(d) > kMaxCoordinate)
    invalid(pointer, "coordinate " + v.dump() + " is outside +-3.4e38 (+-2^128)");
  return d;
}

// A point of `dims` (2 or 3) coordinates.
std::array<double, 3> read_point(const json& v, const Path& pointer, std::size_t dims) {
  const char* shape = dims == 2 ? "[x, y]" : "[x, y, z]";
  if (!v.is_array()) invalid(pointer, std::string("expected a point ") + shape + ", got " + type_name(v));
  if (v.size() != dims)
    invalid(pointer, std::string("expected a point ") + shape + " like the first point, got " +
                         std::to_string(v.size()) + " numbers");
  std::array<double, 3> p{};
  for (std::size_t k = 0; k < dims; ++k) p[k] = read_coordinate(v[k], Path(pointer, k));
  return p;
}

Vec3 read_vec3(const json& v, const Path& pointer) {
  const auto p = read_point(v, pointer, 3);
  return {p[0], p[1], p[2]};
}

const char* kind_name(PrimitiveKind k) {
  switch (k) {
    case PrimitiveKind::triangle:
      return "triangle";
    case PrimitiveKind::line:
      return "line";
    case PrimitiveKind::polyline:
      return "polyline";
    case PrimitiveKind::mesh:
      return "mesh";
    case PrimitiveKind::shader:
      return "shader";
  }
  return "?";
}

}  // namespace

// Colours of a primitive: "color" (flat), "colors" (one per point), or `fallback`.
bool read_colors(const json& v, const Path& pointer, std::size_t n, Rgba8 fallback, std::vector<Rgba8>& out) {
  auto color_it = v.find("color");
  auto colors_it = v.find("colors");
  if (color_it != v.end() && colors_it != v.end())
    invalid(pointer, "give either \"color\" (flat) or \"colors\" (one per point), not both");
  if (colors_it != v.end()) {
    const Path colors_pointer(pointer, "colors");
    if (!colors_it->is_array() || colors_it->size() != n)
      invalid(colors_pointer, "\"colors\" needs one colour per point (" + std::to_string(n) + ")");
    for (std::size_t k = 0; k < n; ++k) out.push_back(read_color((*colors_it)[k], Path(colors_pointer, k)));
    return true;
  }
  out.push_back(color_it != v.end() ? read_color(*color_it, Path(pointer, "color")) : fallback);
  return false;
}

namespace {

// {"translate": [x,y,z], "rotate": [deg x, deg y, deg z], "scale": s | [sx,sy,sz]} -> T * Rz * Ry * Rx * S
// (scale first, then rotate about x, y, z, then translate), or {"matrix": [16 numbers, row-major]}.
Mat4 read_transform(const json& v, const Path& pointer) {
  if (!v.is_object()) invalid(pointer, std::string("expected a transform object, got ") + type_name(v));
  check_keys(v, pointer, {"translate", "rotate", "scale", "matrix"});
  Mat4 m;
  if (auto it = v.find("matrix"); it != v.end()) {
    if (v.size() != 1) invalid(pointer, "\"matrix\" replaces translate/rotate/scale; give one or the other");
    if (!it->is_array() || it->size() != 16)
      invalid(Path(pointer, "matrix"), "expected 16 numbers (a row-major 4x4 matrix)");
    for (std::size_t k = 0; k < 16; ++k) m.m[k] = read_number((*it)[k], Path(Path(pointer, "matrix"), k));
    return m;
  }
  if (auto it = v.find("scale"); it != v.end()) {
    Vec3 s3;
    if (it->is_number()) {
      const double k = read_number(*it, Path(pointer, "scale"));
      s3 = {k, k, k};
    } else {
      s3 = read_vec3(*it, Path(pointer, "scale"));
    }
    Mat4 sm;
    sm(0, 0) = s3.x, sm(1, 1) = s3.y, sm(2, 2) = s3.z;
    m = sm;
  }
  if (auto it = v.find("rotate"); it != v.end()) {
    const Vec3 deg = read_vec3(*it, Path(pointer, "rotate"));
    const double angles[3] = {deg.x, deg.y, deg.z};
    for (int axis = 0; axis < 3; ++axis) {  // x first, then y, then z
      const double rad = angles[axis] * std::numbers::pi / 180.0, c = std::cos(rad), sn = std::sin(rad);
      Mat4 r;
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      r(a, a) = c, r(a, b) = -sn, r(b, a) = sn, r(b, b) = c;
      m = detail::operator*(r, m);
    }
  }
  if (auto it = v.find("translate"); it != v.end()) {
    const Vec3 t = read_vec3(*it, Path(pointer, "translate"));
    Mat4 tm;
    tm(0, 3) = t.x, tm(1, 3) = t.y, tm(2, 3) = t.z;
    m = detail::operator*(tm, m);
  }
  return m;
}

}  // namespace

namespace {

// "edges": true (the defaults) or {"color", "width", "angle"}.
Edges read_edges(const json& v, const Path& pointer) {
  Edges e;
  if (v.is_boolean()) {
    e.enabled = v.get<bool>();
    return e;
  }
  if (!v.is_object())
    invalid(pointer, std::string("expected true or {\"color\", \"width\", \"angle\"}, got ") + type_name(v));
  check_keys(v, pointer, {"color", "width", "angle"});
  e.enabled = true;
  if (auto it = v.find("color"); it != v.end()) e.color = read_color(*it, Path(pointer, "color"));
  if (auto it = v.find("width"); it != v.end()) {
    const double w = read_number(*it, Path(pointer, "width"));
    if (!(w > 0 && w <= 64))
      invalid(Path(pointer, "width"), "edge width is in (0, 64] pixels; got " + it->dump());
    e.width = static_cast<float>(w);
  }
  if (auto it = v.find("angle"); it != v.end()) {
    const double a = read_number(*it, Path(pointer, "angle"));
    if (!(a >= 0 && a <= 180))
      invalid(Path(pointer, "angle"), "the crease angle is in 0..180 degrees; got " + it->dump());
    e.crease_deg = static_cast<float>(a);
  }
  return e;
}

}  // namespace

// Options shared by "mesh" and "obj": shading, wireframe, edges, cull, transform.
void read_mesh_options(const json& v, const Path& pointer, Mesh& mesh) {
  if (auto it = v.find("shading"); it != v.end()) {
    const Path sp(pointer, "shading");
    if (!it->is_string())
      invalid(sp, std::string("expected \"flat\", \"smooth\" or \"unlit\", got ") + type_name(*it));
    const std::string& s = it->get_ref<const std::string&>();
    if (s == "flat")
      mesh.shading = Shading::flat;
    else if (s == "smooth")
      mesh.shading = Shading::smooth;
    else if (s == "unlit")
      mesh.shading = Shading::unlit;
    else
      invalid(sp, "expected \"flat\", \"smooth\" or \"unlit\", got \"" + s + "\"");
  }
  if (auto it = v.find("cull"); it != v.end()) {
    const Path cp(pointer, "cull");
    if (!it->is_string() || (*it != "none" && *it != "back"))
      invalid(cp, "expected \"none\" or \"back\", got " + it->dump());
    mesh.cull = *it == "back" ? Cull::back : Cull::none;
  }
  if (auto it = v.find("wireframe"); it != v.end())
    mesh.wireframe = read_bool(*it, Path(pointer, "wireframe"));
  if (auto it = v.find("edges"); it != v.end()) mesh.edges = read_edges(*it, Path(pointer, "edges"));
  if (auto it = v.find("transform"); it != v.end())
    mesh.transform = read_transform(*it, Path(pointer, "transform"));
}

namespace {

// positions: [[x,y,z], ...] or [x,y,z, x,y,z, ...]; likewise normals. Held as floats, as a Mesh holds them.
std::vector<Vec3f> read_vec3_list(const json& v, const Path& pointer) {
  if (!v.is_array())
    invalid(pointer, std::string("expected an array of [x, y, z] or of numbers, got ") + type_name(v));
  std::vector<Vec3f> out;
  if (!v.empty() && v[0].is_number()) {
    if (v.size() % 3 != 0)
      invalid(pointer, "a flat list holds x, y, z triples; its length " + std::to_string(v.size()) +
                           " is not a multiple of 3");
    out.reserve(v.size() / 3);
    for (std::size_t k = 0; k < v.size(); k += 3)
      out.push_back(
          Vec3f(Vec3{read_coordinate(v[k], Path(pointer, k)), read_coordinate(v[k + 1], Path(pointer, k + 1)),
                     read_coordinate(v[k + 2], Path(pointer, k + 2))}));
    return out;
  }
  out.reserve(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) out.push_back(Vec3f(read_vec3(v[k], Path(pointer, k))));
  return out;
}

// indices: [[a,b,c], ...] or [a,b,c, a,b,c, ...], 0-based into positions.
std::vector<std::array<std::uint32_t, 3>> read_indices(const json& v, const Path& pointer,
                                                       std::size_t positions, const Limits& limits) {
  if (!v.is_array())
    invalid(pointer, std::string("expected an array of [a, b, c] or of integers, got ") + type_name(v));
  auto index = [&](const json& e, const Path& p) {
    const std::int64_t i = read_integer(e, p);
    if (i < 0 || static_cast<std::size_t>(i) >= positions)
      invalid(p,
              "index " + e.dump() + " is outside the " + std::to_string(positions) + " positions (0-based)");
    return static_cast<std::uint32_t>(i);
  };
  const bool flat = !v.empty() && v[0].is_number();
  const std::size_t count = flat ? v.size() / 3 : v.size();
  if (static_cast<std::int64_t>(count) > limits.max_primitives)
    fail(ErrorKind::limit, pointer,
         std::to_string(count) + " triangles exceed the limit of " + std::to_string(limits.max_primitives));
  std::vector<std::array<std::uint32_t, 3>> out;
  out.reserve(count);
  if (flat) {
    if (v.size() % 3 != 0)
      invalid(pointer, "a flat list holds a, b, c triples; its length " + std::to_string(v.size()) +
                           " is not a multiple of 3");
    for (std::size_t k = 0; k < v.size(); k += 3)
      out.push_back({index(v[k], Path(pointer, k)), index(v[k + 1], Path(pointer, k + 1)),
                     index(v[k + 2], Path(pointer, k + 2))});
    return out;
  }
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Path p(pointer, k);
    if (!v[k].is_array() || v[k].size() != 3) invalid(p, "expected a triangle [a, b, c]");
    out.push_back({index(v[k][0], Path(p, std::size_t{0})), index(v[k][1], Path(p, std::size_t{1})),
                   index(v[k][2], Path(p, std::size_t{2}))});
  }
  return out;
}

// Base64 is the library's own decoder (base/base64.h): the oracle checks how a scene is read, not base64.
// Texels the scene's textures hold so far: what is left of the limit is what the next one may take.
std::int64_t texels_left(const Scene& scene, const Limits& limits) {
  std::int64_t used = 0;
  for (const Mesh& m : scene.meshes)
    for (const Texture& t : m.textures) used += std::int64_t{t.width} * t.height;
  for (const ShaderPrimitive& s : scene.shaders)
    for (const Texture& t : s.textures) used += std::int64_t{t.width} * t.height;
  return limits.max_texture_pixels - used;
}

// The bytes of an image given as base64 text (JSON string `v` at `pointer`).
std::string read_base64_image(const json& v, const Path& pointer) {
  if (!v.is_string())
    invalid(pointer, std::string("expected the image file as base64 text, got ") + type_name(v));
  std::string bytes;
  if (!decode_base64(v.get_ref<const std::string&>(), bytes))
    invalid(pointer, "not base64 (RFC 4648, '+' and '/', optionally a data: URI)");
  return bytes;
}

// A texture error from decode_texture, located at the field that gave the image.
[[noreturn]] void rethrow_at(const SceneError& e, const Path& pointer) {
  throw SceneError(e.kind(), e.what(), ErrorLocation{pointer.str(), 0, 0});
}

// A mesh's "texture": {"data": base64} or {"source": part name}, and "wrap": "repeat" | "clamp".
Texture read_texture(const json& v, const Path& pointer, const Uploads& uploads, std::int64_t budget) {
  if (!v.is_object())
    invalid(pointer,
            std::string("expected {\"data\": base64} or {\"source\": part name}, got ") + type_name(v));
  check_keys(v, pointer, {"data", "source", "wrap"});
  auto data = v.find("data");
  auto source = v.find("source");
  if ((data == v.end()) == (source == v.end()))
    invalid(pointer,
            "a texture needs \"data\" (the PNG or JPEG file as base64) or \"source\" (an uploaded part)");
  Texture t;
  try {
    if (data != v.end()) {
      t = decode_texture(read_base64_image(*data, Path(pointer, "data")), "data", budget);
    } else {
      const Path sp(pointer, "source");
      if (!source->is_string())
        invalid(sp, std::string("expected the name of an uploaded part, got ") + type_name(*source));
      const std::string& name = source->get_ref<const std::string&>();
      auto part = uploads.find(name);
      if (part == uploads.end())
        invalid(sp,
                "no uploaded part named " + source->dump() + " (send it as a multipart part of that name)");
      t = decode_texture(part->second, name, budget);
    }
  } catch (const SceneError& e) {
    if (!e.where().pointer.empty()) throw;
    rethrow_at(e, Path(pointer, data != v.end() ? "data" : "source"));
  }
  if (auto it = v.find("wrap"); it != v.end()) {
    if (!it->is_string() || (*it != "repeat" && *it != "clamp"))
      invalid(Path(pointer, "wrap"), "expected \"repeat\" or \"clamp\", got " + it->dump());
    t.clamp = *it == "clamp";
  }
  return t;
}

// uvs: [[u, v], ...] or [u, v, u, v, ...], one pair per position.
std::vector<std::array<float, 2>> read_uvs(const json& v, const Path& pointer, std::size_t positions) {
  if (!v.is_array())
    invalid(pointer, std::string("expected an array of [u, v] or of numbers, got ") + type_name(v));
  std::vector<std::array<float, 2>> out;
  auto number = [&](const json& e, const Path& p) {
    const double d = read_number(e, p);
    if (!(std::fabs(d) <= 1e30)) invalid(p, "a texture coordinate must be a number within +-1e30");
    return static_cast<float>(d);
  };
  if (!v.empty() && v[0].is_number()) {
    if (v.size() % 2 != 0)
      invalid(pointer, "a flat list holds u, v pairs; its length " + std::to_string(v.size()) + " is odd");
    for (std::size_t k = 0; k < v.size(); k += 2)
      out.push_back({number(v[k], Path(pointer, k)), number(v[k + 1], Path(pointer, k + 1))});
  } else {
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Path p(pointer, k);
      if (!v[k].is_array() || v[k].size() != 2) invalid(p, "expected a texture coordinate [u, v]");
      out.push_back({number(v[k][0], Path(p, std::size_t{0})), number(v[k][1], Path(p, std::size_t{1}))});
    }
  }
  if (out.size() != positions)
    invalid(pointer, "\"uvs\" needs one [u, v] per position (" + std::to_string(positions) + "), got " +
                         std::to_string(out.size()));
  return out;
}

Mesh read_mesh(const json& v, const Path& pointer, const Scene& scene, const Limits& limits,
               const Uploads& uploads) {
  check_keys(v, pointer,
             {"type", "positions", "indices", "colors", "color", "normals", "uvs", "texture", "shading",
              "wireframe", "edges", "cull", "transform"});
  Mesh mesh;
  auto pos = v.find("positions");
  if (pos == v.end()) invalid(pointer, "a mesh needs \"positions\"");
  mesh.positions = read_vec3_list(*pos, Path(pointer, "positions"));
  auto idx = v.find("indices");
  if (idx == v.end()) invalid(pointer, "a mesh needs \"indices\" (triangles as [a, b, c], 0-based)");
  mesh.triangles = read_indices(*idx, Path(pointer, "indices"), mesh.positions.size(), limits);
  read_colors(v, pointer, mesh.positions.size(), kMeshGrey, mesh.colors);
  if (auto it = v.find("normals"); it != v.end()) {
    mesh.normals = read_vec3_list(*it, Path(pointer, "normals"));
    if (mesh.normals.size() != mesh.positions.size())
      invalid(Path(pointer, "normals"),
              "\"normals\" needs one normal per position (" + std::to_string(mesh.positions.size()) + ")");
    mesh.normal_triangles = mesh.triangles;
  }
  auto uvs = v.find("uvs");
  auto texture = v.find("texture");
  if ((uvs == v.end()) != (texture == v.end()))
    invalid(pointer, uvs == v.end() ? "a \"texture\" needs \"uvs\" (one [u, v] per position)"
                                    : "\"uvs\" are used with a \"texture\"; give both");
  if (uvs != v.end()) {
    mesh.uvs = read_uvs(*uvs, Path(pointer, "uvs"), mesh.positions.size());
    mesh.uv_triangles = mesh.triangles;
    mesh.textures.push_back(
        read_texture(*texture, Path(pointer, "texture"), uploads, texels_left(scene, limits)));
  }
  read_mesh_options(v, pointer, mesh);
  return mesh;
}

std::string located(const SceneError& e) {
  if (e.where().line) return std::string(e.what()) + " (line " + std::to_string(e.where().line) + ")";
  if (e.where().byte && e.kind() != ErrorKind::encoding)
    return std::string(e.what()) + " (byte " + std::to_string(e.where().byte) + " of the model)";
  return e.what();
}

Mesh read_obj(const json& v, const Path& pointer, const Scene& scene, const Limits& limits,
              const Uploads& uploads) {
  const bool obj = v.at("type") == "obj";
  if (obj)
    check_keys(v, pointer,
               {"type", "data", "source", "mtl", "mtl_source", "textures", "color", "shading", "wireframe",
                "edges", "cull", "transform", "point_size"});
  else
    check_keys(v, pointer,
               {"type", "data", "source", "format", "mtl", "mtl_source", "textures", "color", "shading",
                "wireframe", "edges", "cull", "transform", "point_size"});
  auto text_of = [&](const char* inline_key, const char* source_key, bool required) -> std::string_view {
    auto data = v.find(inline_key);
    auto source = v.find(source_key);
    if (data != v.end() && source != v.end())
      invalid(pointer, std::string("give either \"") + inline_key + "\" or \"" + source_key + "\", not both");
    if (data != v.end()) {
      if (!data->is_string())
        invalid(Path(pointer, inline_key), std::string("expected text, got ") + type_name(*data));
      return data->get_ref<const std::string&>();
    }
    if (source != v.end()) {
      if (!source->is_string())
        invalid(Path(pointer, source_key),
                std::string("expected the name of an uploaded part, got ") + type_name(*source));
      auto part = uploads.find(source->get_ref<const std::string&>());
      if (part == uploads.end())
        invalid(Path(pointer, source_key),
                "no uploaded part named " + source->dump() + " (send it as a multipart part of that name)");
      return part->second;
    }
    if (required)
      invalid(pointer,
              obj ? "an obj needs \"data\" (OBJ text) or \"source\" (the name of an uploaded part)"
                  : "a model needs \"data\" (the model's text) or \"source\" (the name of an uploaded "
                    "part)");
    return {};
  };
  const std::string_view obj_text = text_of("data", "source", true);
  std::string_view mtl_text = text_of("mtl", "mtl_source", false);
  // An MTL uploaded as part "mtl" goes with a model taken from the uploads.
  if (mtl_text.empty() && v.contains("source") && !v.contains("mtl_source"))
    if (auto part = uploads.find("mtl"); part != uploads.end()) mtl_text = part->second;

  // Textures: inline as {"file.png": base64, ...}, else the uploads (multipart parts by file name).
  Uploads inline_images;
  if (auto it = v.find("textures"); it != v.end()) {
    const Path tp(pointer, "textures");
    if (!it->is_object())
      invalid(tp, std::string("expected an object of file name: base64 image, got ") + type_name(*it));
    for (const auto& [name, value] : it->items())
      inline_images[name] = read_base64_image(value, Path(tp, name));
  }
  Limits model_limits = limits;
  model_limits.max_texture_pixels = texels_left(scene, limits);
  Mesh mesh;
  try {
    std::optional<ModelFormat> hint;
    if (obj) hint = ModelFormat::obj;
    if (auto it = v.find("format"); it != v.end()) {
      const Path fp(pointer, "format");
      const char* expected = "expected \"obj\", \"stl\", \"ply\", \"gltf\" or \"glb\"";
      if (!it->is_string()) invalid(fp, std::string(expected) + ", got " + type_name(*it));
      hint = format_named(it->get_ref<const std::string&>());
      if (!hint || it->get_ref<const std::string&>() != format_name(*hint))
        invalid(fp, std::string(expected) + ", got " + it->dump());
    }
    mesh =
        parse_model(obj_text, hint, model_limits, v.contains("textures") ? inline_images : uploads, mtl_text);
  } catch (const SceneError& e) {
    // An encoding error keeps its byte: the offset into the model's own text, which the message names.
    const std::size_t byte = e.kind() == ErrorKind::encoding ? e.where().byte : 0;
    throw SceneError(e.kind(), located(e), ErrorLocation{pointer.str(), byte, e.where().line});
  }
  if (auto it = v.find("color"); it != v.end()) {  // an explicit colour wins over the model's own
    mesh.colors = {read_color(*it, Path(pointer, "color"))};
    mesh.face_colors.clear();
  } else if (mesh.colors.empty()) {
    mesh.colors = {kMeshGrey};
  }
  read_mesh_options(v, pointer, mesh);
  if (auto it = v.find("point_size"); it != v.end()) {
    const double size = read_number(*it, Path(pointer, "point_size"));
    if (!(size > 0 && size <= 64))
      invalid(Path(pointer, "point_size"), "\"point_size\" is in (0, 64] pixels; got " + it->dump());
    mesh.point_size = static_cast<float>(size);
  }
  return mesh;
}

// A shader's input: a number within +-1e9 (time, mouse, date).
double read_shader_input(const json& v, const Path& pointer) {
  const double d = read_number(v, pointer);
  if (!(d >= -1e9 && d <= 1e9))
    invalid(pointer, "a shader's input is a number within +-1e9; got " + v.dump());
  return d;
}

// "mouse" ([x, y] or four numbers) and "date" (four numbers).
std::array<double, 4> read_four(const json& v, const Path& pointer, bool two_allowed, const char* what) {
  if (!v.is_array() || !(v.size() == 4 || (two_allowed && v.size() == 2)))
    invalid(pointer, std::string("expected ") + what);
  std::array<double, 4> out{};
  for (std::size_t k = 0; k < v.size(); ++k) out[k] = read_shader_input(v[k], Path(pointer, k));
  return out;
}

bool glsl_name(const std::string& s) {
  if (s.empty() || s.size() > 256 || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// A uniform's value: a number, true or false, or an array of them, or an array of such arrays (a matrix
// by columns); its slots in order. Before each array element, fewer than 4096 slots may be held.
void read_uniform_value(const json& v, const Path& pointer, int depth, std::vector<double>& slots) {
  if (v.is_boolean()) return slots.push_back(v.get<bool>() ? 1 : 0);
  if (v.is_number()) {
    const double d = read_number(v, pointer);
    if (!(std::fabs(d) <= 3.4e38)) invalid(pointer, "a uniform's number must be a finite float");
    return slots.push_back(d);
  }
  if (!v.is_array() || depth > 1)
    invalid(pointer, std::string("expected a number, true, false or an array of them, got ") + type_name(v));
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (slots.size() >= 4096) invalid(pointer, "a uniform holds at most 4096 values");
    read_uniform_value(v[k], Path(pointer, k), depth + 1, slots);
  }
}

// "uniforms": {"name": value, ...}, in the order given.
void read_uniforms(const json& v, const Path& pointer, ShaderPrimitive& s) {
  if (!v.is_object())
    invalid(pointer, std::string("expected an object of uniform name: value, got ") + type_name(v));
  for (auto it = v.begin(); it != v.end(); ++it) {
    const Path at(pointer, it.key());
    if (!glsl_name(it.key())) invalid(at, "\"" + it.key() + "\" is not a GLSL name");
    if (is_shadertoy_uniform(it.key()))
      invalid(at,
              "\"" + it.key() + "\" is set by the shader's own fields (time, frame, mouse, date, channels)");
    std::vector<double> slots;
    read_uniform_value(it.value(), at, 0, slots);
    if (slots.empty()) invalid(at, "a uniform needs a value");
    s.uniforms.emplace_back(it.key(), std::move(slots));
  }
}

// "channels": up to four texture objects (as a mesh's "texture") or null, iChannel0..3 in order.
void read_channels(const json& v, const Path& pointer, const Scene& scene, const Limits& limits,
                   const Uploads& uploads, ShaderPrimitive& s) {
  if (!v.is_array())
    invalid(pointer,
            std::string("expected an array of up to four texture objects (or null), got ") + type_name(v));
  if (v.size() > 4) invalid(Path(pointer, 4), "a shader has four channels (iChannel0..3); got a fifth");
  std::int64_t pending = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k].is_null()) continue;
    if (!v[k].is_object())
      invalid(Path(pointer, k), std::string("expected a texture object or null, got ") + type_name(v[k]));
    Texture t = read_texture(v[k], Path(pointer, k), uploads, texels_left(scene, limits) - pending);
    pending += std::int64_t{t.width} * t.height;
    s.channels[k] = static_cast<std::int32_t>(s.textures.size());
    s.textures.push_back(std::move(t));
  }
}

// "rect": [x, y, width, height] in whole pixels; the corner within +-16384, the sides 1 to 16384.
std::array<std::int32_t, 4> read_rect(const json& v, const Path& pointer) {
  if (!v.is_array() || v.size() != 4) invalid(pointer, "\"rect\" is [x, y, width, height] in pixels");
  std::array<std::int32_t, 4> r{};
  for (std::size_t k = 0; k < 4; ++k) {
    const std::int64_t n = read_integer(v[k], Path(pointer, k));
    if (n < (k >= 2 ? 1 : -kMaxImageSide) || n > kMaxImageSide)
      invalid(Path(pointer, k), "a rect's value is out of range: " + v[k].dump());
    r[k] = static_cast<std::int32_t>(n);
  }
  return r;
}

// {"type": "shader", "source": GLSL, "time", "frame", "mouse", "date", "channels", "uniforms", "rect",
// "opaque"}: ShaderToy's image pass. The program is compiled by the plan, not here.
ShaderPrimitive read_shader(const json& v, const Path& pointer, const Scene& scene, const Limits& limits,
                            const Uploads& uploads) {
  check_keys(v, pointer,
             {"type", "source", "time", "frame", "mouse", "date", "channels", "uniforms", "rect", "opaque"});
  ShaderPrimitive s;
  const auto source = v.find("source");
  if (source == v.end())
    invalid(pointer, "a shader needs \"source\": the program as ShaderToy's editor holds it (a mainImage)");
  if (!source->is_string())
    invalid(Path(pointer, "source"), std::string("expected a string, got ") + type_name(*source));
  s.source = source->get<std::string>();
  if (auto it = v.find("time"); it != v.end()) s.time = read_shader_input(*it, Path(pointer, "time"));
  if (auto it = v.find("frame"); it != v.end()) {
    const std::int64_t f = read_integer(*it, Path(pointer, "frame"));
    if (f < 0 || f > INT32_MAX)
      invalid(Path(pointer, "frame"), "\"frame\" is a whole number from 0 to 2147483647");
    s.frame = static_cast<std::int32_t>(f);
  }
  if (auto it = v.find("mouse"); it != v.end())
    s.mouse = read_four(*it, Path(pointer, "mouse"), true, "[x, y] or [x, y, click x, click y] in pixels");
  if (auto it = v.find("date"); it != v.end())
    s.date =
        read_four(*it, Path(pointer, "date"), false, "[year, month (0-11), day, seconds since midnight]");
  if (auto it = v.find("channels"); it != v.end())
    read_channels(*it, Path(pointer, "channels"), scene, limits, uploads, s);
  if (auto it = v.find("uniforms"); it != v.end()) read_uniforms(*it, Path(pointer, "uniforms"), s);
  if (auto it = v.find("rect"); it != v.end())
    s.rect = read_rect(*it, Path(pointer, "rect")), s.whole = false;
  if (auto it = v.find("opaque"); it != v.end()) s.opaque = read_bool(*it, Path(pointer, "opaque"));
  return s;
}

// A triangle, line or polyline whose points are [x, y, z]: world space, through the camera, unlit.
Mesh mesh_of_3d_primitive(const Primitive& p, std::span<const double> coords, std::span<const Rgba8> colors) {
  Mesh mesh;
  for (std::size_t k = 0; k + 2 < coords.size(); k += 3)
    mesh.positions.push_back(Vec3f(Vec3{coords[k], coords[k + 1], coords[k + 2]}));
  mesh.colors.assign(colors.begin(), colors.end());
  mesh.shading = Shading::unlit;
  const auto n = static_cast<std::uint32_t>(mesh.positions.size());
  if (p.kind == PrimitiveKind::triangle && p.fill) {
    mesh.triangles.push_back({0, 1, 2});
  } else {
    for (std::uint32_t i = 0; i + 1 < n; ++i) mesh.segments.push_back({i, i + 1});
    if ((p.closed || p.kind == PrimitiveKind::triangle) && n >= 3) mesh.segments.push_back({n - 1, 0});
  }
  return mesh;
}

}  // namespace

void add_drawn_primitive(Scene& scene, Primitive p, std::size_t dims, std::span<const double> coords,
                         std::span<const Rgba8> colors, bool per_vertex) {
  if (dims == 3) {
    Mesh mesh = mesh_of_3d_primitive(p, coords, colors);
    p.kind = PrimitiveKind::mesh;
    p.mesh = static_cast<std::uint32_t>(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));
    scene.primitives.push_back(p);
    return;
  }
  p.first_point = static_cast<std::uint32_t>(scene.points.size());
  p.point_count = static_cast<std::uint32_t>(coords.size() / 2);
  for (std::size_t k = 0; k + 1 < coords.size(); k += 2) scene.points.push_back({coords[k], coords[k + 1]});
  p.first_color = static_cast<std::uint32_t>(scene.colors.size());
  p.per_vertex_color = per_vertex;
  scene.colors.insert(scene.colors.end(), colors.begin(), colors.end());
  scene.primitives.push_back(p);
}

void read_line_options(const json& v, const Path& pointer, Primitive& p) {
  if (auto it = v.find("fill"); it != v.end()) p.fill = read_bool(*it, Path(pointer, "fill"));
  if (auto it = v.find("closed"); it != v.end()) p.closed = read_bool(*it, Path(pointer, "closed"));
  if (auto it = v.find("width"); it != v.end()) {
    const double w = read_number(*it, Path(pointer, "width"));
    if (!(w > 0 && w <= 4096))
      invalid(Path(pointer, "width"),
              "line \"width\" is in pixels, more than 0 and at most 4096; got " + it->dump());
    p.width = static_cast<float>(w);
  }
}

void read_primitive(const json& v, const Path& pointer, Scene& scene, const Limits& limits,
                    const Uploads& uploads) {
  if (!v.is_object()) invalid(pointer, std::string("expected a primitive object, got ") + type_name(v));
  auto type_it = v.find("type");
  if (type_it == v.end())
    invalid(pointer,
            "missing \"type\" (\"triangle\", \"line\", \"polyline\", \"mesh\", \"model\", \"obj\" or "
            "\"shader\")");
  const Path type_pointer(pointer, "type");
  if (!type_it->is_string())
    invalid(type_pointer, std::string("expected a string, got ") + type_name(*type_it));
  const std::string& type = type_it->get_ref<const std::string&>();

  Primitive p;
  if (type == "shader") {
    p.kind = PrimitiveKind::shader;
    p.mesh = static_cast<std::uint32_t>(scene.shaders.size());
    scene.shaders.push_back(read_shader(v, pointer, scene, limits, uploads));
    scene.primitives.push_back(p);
    return;
  }
  if (type == "mesh" || type == "obj" || type == "model") {
    p.kind = PrimitiveKind::mesh;
    p.mesh = static_cast<std::uint32_t>(scene.meshes.size());
    scene.meshes.push_back(type == "mesh" ? read_mesh(v, pointer, scene, limits, uploads)
                                          : read_obj(v, pointer, scene, limits, uploads));
    scene.primitives.push_back(p);
    return;
  }
  if (type == "triangle") {
    p.kind = PrimitiveKind::triangle;
    check_keys(v, pointer, {"type", "points", "color", "colors", "fill", "width"});
  } else if (type == "line") {
    p.kind = PrimitiveKind::line;
    check_keys(v, pointer, {"type", "points", "color", "colors", "width"});
  } else if (type == "polyline") {
    p.kind = PrimitiveKind::polyline;
    check_keys(v, pointer, {"type", "points", "color", "colors", "closed", "width"});
  } else {
    invalid(type_pointer,
            "unknown primitive type \"" + type +
                "\"; expected \"triangle\", \"line\", \"polyline\", \"mesh\", \"model\", \"obj\" or "
                "\"shader\"");
  }

  auto points_it = v.find("points");
  const Path points_pointer(pointer, "points");
  if (points_it == v.end()) invalid(pointer, std::string("a ") + kind_name(p.kind) + " needs \"points\"");
  if (!points_it->is_array())
    invalid(points_pointer, std::string("expected an array of points, got ") + type_name(*points_it));
  const std::size_t n = points_it->size();
  if (p.kind == PrimitiveKind::triangle && n != 3)
    invalid(points_pointer, "a triangle has exactly 3 points, got " + std::to_string(n));
  if (p.kind == PrimitiveKind::line && n != 2)
    invalid(points_pointer, "a line has exactly 2 points, got " + std::to_string(n));
  if (p.kind == PrimitiveKind::polyline && n < 2)
    invalid(points_pointer, "a polyline has at least 2 points, got " + std::to_string(n));
  if (scene.points.size() + n > UINT32_MAX)
    fail(ErrorKind::limit, points_pointer, "too many points in the scene");
  read_line_options(v, pointer, p);

  // The first point decides: [x, y] is image space, [x, y, z] world space; all points must agree.
  const json& first = (*points_it)[0];
  const std::size_t dims = first.is_array() && first.size() == 3 ? 3 : 2;
  std::vector<double> coords;
  coords.reserve(n * dims);
  for (std::size_t k = 0; k < n; ++k) {
    const auto q = read_point((*points_it)[k], Path(points_pointer, k), dims);
    coords.insert(coords.end(), q.begin(), q.begin() + static_cast<std::ptrdiff_t>(dims));
  }
  std::vector<Rgba8> colors;
  const bool per_vertex = read_colors(v, pointer, n, Rgba8{255, 255, 255, 255}, colors);
  add_drawn_primitive(scene, p, dims, coords, colors, per_vertex);
}

namespace {

Camera read_camera(const json& v) {
  const Path pointer(kRoot, "camera");
  if (!v.is_object()) invalid(pointer, std::string("expected a camera object, got ") + type_name(v));
  check_keys(v, pointer,
             {"projection", "view", "fit", "eye", "target", "up", "fov", "near", "far", "height"});
  Camera c;
  if (auto it = v.find("view"); it != v.end()) {
    static constexpr std::pair<const char*, View> kViews[] = {
        {"front", View::front}, {"back", View::back},
        {"left", View::left},   {"right", View::right},
        {"top", View::top},     {"bottom", View::bottom},
        {"iso", View::iso},     {"three-quarter", View::three_quarter}};
    const auto named = it->is_string() ? std::find_if(std::begin(kViews), std::end(kViews),
                                                      [&](const auto& kv) { return *it == kv.first; })
                                       : std::end(kViews);
    if (named == std::end(kViews))
      invalid(Path(pointer, "view"),
              "expected \"front\", \"back\", \"left\", \"right\", \"top\", \"bottom\", \"iso\" or "
              "\"three-quarter\", got " +
                  it->dump());
    if (v.contains("eye"))
      invalid(Path(pointer, "view"), "\"view\" and \"eye\" both place the camera: give one of them");
    c.view = named->second, c.has_view = true;
  }
  if (auto it = v.find("fit"); it != v.end()) {
    if (!it->is_string() || (*it != "sphere" && *it != "vertices"))
      invalid(Path(pointer, "fit"), "expected \"sphere\" or \"vertices\", got " + it->dump());
    c.fit = *it == "vertices" ? CameraFit::vertices : CameraFit::sphere;
  }
  if (auto it = v.find("projection"); it != v.end()) {
    if (!it->is_string() || (*it != "perspective" && *it != "orthographic"))
      invalid(Path(pointer, "projection"), "expected \"perspective\" or \"orthographic\", got " + it->dump());
    c.projection = *it == "orthographic" ? Projection::orthographic : Projection::perspective;
  }
  if (auto it = v.find("eye"); it != v.end()) c.eye = read_vec3(*it, Path(pointer, "eye")), c.has_eye = true;
  if (auto it = v.find("target"); it != v.end())
    c.target = read_vec3(*it, Path(pointer, "target")), c.has_target = true;
  if (auto it = v.find("up"); it != v.end()) {
    c.up = read_vec3(*it, Path(pointer, "up")), c.has_up = true;
    if (c.up.x == 0 && c.up.y == 0 && c.up.z == 0)
      invalid(Path(pointer, "up"), "\"up\" must not be the zero vector");
  }
  if (auto it = v.find("fov"); it != v.end()) {
    c.fov_deg = read_number(*it, Path(pointer, "fov"));
    if (!(c.fov_deg > 0 && c.fov_deg < 180))
      invalid(
          Path(pointer, "fov"),
          "\"fov\" is the vertical field of view in degrees, strictly between 0 and 180; got " + it->dump());
  }
  if (auto it = v.find("near"); it != v.end()) {
    c.near = read_number(*it, Path(pointer, "near")), c.has_near = true;
    if (!(c.near > 0))
      invalid(Path(pointer, "near"),
              "\"near\" is a distance in front of the eye and must be > 0; got " + it->dump());
  }
  if (auto it = v.find("far"); it != v.end()) {
    c.far = read_number(*it, Path(pointer, "far")), c.has_far = true;
    if (!(c.far > 0)) invalid(Path(pointer, "far"), "\"far\" must be > 0; got " + it->dump());
  }
  if (c.has_near && c.has_far && !(c.near < c.far))
    invalid(Path(pointer, "far"), "\"far\" must be greater than \"near\"");
  if (auto it = v.find("height"); it != v.end()) {
    c.height = read_number(*it, Path(pointer, "height")), c.has_height = true;
    if (!(c.height > 0))
      invalid(Path(pointer, "height"), "\"height\" (orthographic view height) must be > 0");
  }
  return c;
}

// "light": rasterd 0.1's one directional light plus ambient.
std::vector<Light> read_light(const json& v) {
  const Path pointer(kRoot, "light");
  if (!v.is_object()) invalid(pointer, std::string("expected a light object, got ") + type_name(v));
  check_keys(v, pointer, {"direction", "ambient"});
  double ambient = 0.2;
  Vec3 direction;
  const bool directed = v.contains("direction");
  if (directed) {
    direction = read_vec3(v["direction"], Path(pointer, "direction"));
    if (direction.x == 0 && direction.y == 0 && direction.z == 0)
      invalid(Path(pointer, "direction"), "the light direction must not be the zero vector");
  }
  if (auto it = v.find("ambient"); it != v.end()) {
    ambient = read_number(*it, Path(pointer, "ambient"));
    if (!(ambient >= 0 && ambient <= 1))
      invalid(Path(pointer, "ambient"), "\"ambient\" is in 0..1; got " + it->dump());
  }
  return single_light(ambient, directed ? &direction : nullptr);
}

// "lights": [{"type": "ambient" | "directional" | "point", ...}, ...].
std::vector<Light> read_lights(const json& v) {
  const Path pointer(kRoot, "lights");
  if (!v.is_array()) invalid(pointer, std::string("expected an array of lights, got ") + type_name(v));
  if (v.empty()) invalid(pointer, "an empty list of lights; leave \"lights\" out for the default ones");
  if (v.size() > kMaxLights)
    invalid(pointer, "at most " + std::to_string(kMaxLights) + " lights; got " + std::to_string(v.size()));
  std::vector<Light> lights;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Path at(pointer, i);
    const json& o = v[i];
    if (!o.is_object()) invalid(at, std::string("expected a light object, got ") + type_name(o));
    Light l;
    const auto type = o.find("type");
    if (type == o.end()) invalid(at, "missing \"type\": \"ambient\", \"directional\" or \"point\"");
    if (*type == "ambient") {
      l.kind = LightKind::ambient;
      check_keys(o, at, {"type", "color", "intensity"});
    } else if (*type == "directional") {
      l.kind = LightKind::directional;
      check_keys(o, at, {"type", "direction", "space", "color", "intensity"});
    } else if (*type == "point") {
      l.kind = LightKind::point;
      check_keys(o, at, {"type", "position", "space", "color", "intensity"});
    } else {
      invalid(Path(at, "type"), "expected \"ambient\", \"directional\" or \"point\", got " + type->dump());
    }
    if (auto it = o.find("space"); it != o.end()) {
      if (*it != "world" && *it != "camera")
        invalid(Path(at, "space"), "expected \"world\" or \"camera\", got " + it->dump());
      l.camera_space = *it == "camera";
    }
    if (auto it = o.find("direction"); it != o.end()) {
      l.direction = read_vec3(*it, Path(at, "direction"));
      if (l.direction.x == 0 && l.direction.y == 0 && l.direction.z == 0)
        invalid(Path(at, "direction"), "the light direction must not be the zero vector");
    }
    if (l.kind == LightKind::point) {
      const auto it = o.find("position");
      if (it == o.end()) invalid(at, "a point light needs \"position\": [x, y, z]");
      l.position = read_vec3(*it, Path(at, "position"));
    }
    if (auto it = o.find("color"); it != o.end()) {
      const Rgba8 c = read_color(*it, Path(at, "color"));
      if (c.a != 255) invalid(Path(at, "color"), "a light's colour is opaque (it has no alpha)");
      l.color = {c.r / 255.0, c.g / 255.0, c.b / 255.0};
    }
    if (auto it = o.find("intensity"); it != o.end()) {
      l.intensity = read_number(*it, Path(at, "intensity"));
      if (!(l.intensity >= 0 && l.intensity <= kMaxLightIntensity))
        invalid(Path(at, "intensity"), "\"intensity\" is in 0.." +
                                           std::to_string(static_cast<int>(kMaxLightIntensity)) + "; got " +
                                           it->dump());
    }
    lights.push_back(l);
  }
  return lights;
}

// Byte offset (1-based) of the first bracket that opens level max_depth + 1, skipping strings.
std::size_t depth_violation_offset(std::string_view text, int max_depth) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return i + 1;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return 0;
}

// nlohmann's DOM builder behind a SAX front that (1) cuts nesting at the limit while parsing: the parser
// is iterative, but dump, copy and compare of the resulting document recurse; (2) refuses a key given twice
// in one object at the second one's pointer (nlohmann keeps the last; RFC 8259 says names SHOULD be unique,
// and a scene that says two things is more likely a mistake than a wish); and (3) turns every parse error,
// number overflow included, into a SceneError with the byte offset the parser reports.
class BoundedDomBuilder {
 public:
  BoundedDomBuilder(json& out, std::string_view text, int max_depth)
      : dom_(out, true), text_(text), max_depth_(max_depth) {}

  bool null() { return element(), dom_.null(); }
  bool boolean(bool v) { return element(), dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return element(), dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return element(), dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) {
    return element(), dom_.number_float(v, s);
  }
  bool string(json::string_t& v) { return element(), dom_.string(v); }
  bool binary(json::binary_t& v) { return element(), dom_.binary(v); }
  bool key(json::string_t& v) {
    Frame& f = frames_.back();
    if (!f.add_key(v))
      throw SceneError(ErrorKind::invalid, "\"" + v + "\" is given twice in one object; give each key once",
                       ErrorLocation{pointer_to(v), 0, 0});
    f.key = v;
    return dom_.key(v);
  }
  bool start_object(std::size_t n) { return enter(true) && dom_.start_object(n); }
  bool end_object() { return leave(), dom_.end_object(); }
  bool start_array(std::size_t n) { return enter(false) && dom_.start_array(n); }
  bool end_array() { return leave(), dom_.end_array(); }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 1, column 2: ..."; keep the sentence.
    std::string message = e.what();
    if (auto at = message.find("] "); at != std::string::npos) message.erase(0, at + 2);
    throw SceneError(ErrorKind::syntax, "malformed JSON: " + message, ErrorLocation{"", position, 0});
  }

 private:
  // An open object or array, for the pointer of a repeated key.
  struct Frame {
    bool object = false;
    std::size_t elements = 0;              // an array's elements so far: the current one is elements - 1
    std::string key;                       // an object's current key
    std::vector<std::string> keys;         // an object's keys so far, while it has few
    std::unordered_set<std::string> many;  // all of them, once there are many (no quadratic search)

    bool add_key(const std::string& k) {
      if (!many.empty()) return many.insert(k).second;
      if (std::find(keys.begin(), keys.end(), k) != keys.end()) return false;
      keys.push_back(k);
      if (keys.size() == 16) many.insert(keys.begin(), keys.end()), keys.clear();
      return true;
    }
  };

  // A value begins: in an array, that is its next element.
  void element() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().elements;
  }
  bool enter(bool object) {
    element();
    if (static_cast<int>(frames_.size()) + 1 > max_depth_)
      throw SceneError(ErrorKind::syntax, "JSON nested deeper than " + std::to_string(max_depth_) + " levels",
                       ErrorLocation{"", depth_violation_offset(text_, max_depth_), 0});
    frames_.emplace_back().object = object;
    return true;
  }
  void leave() { frames_.pop_back(); }

  std::string pointer_to(const std::string& last_key) const {
    auto escaped = [](const std::string& key) {  // RFC 6901: '~' as ~0, '/' as ~1
      std::string out;
      for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
      return out;
    };
    std::string pointer;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
      pointer +=
          "/" + (frames_[i].object ? escaped(frames_[i].key) : std::to_string(frames_[i].elements - 1));
    return pointer + "/" + escaped(last_key);
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::string_view text_;
  int max_depth_;
  std::vector<Frame> frames_;
};

}  // namespace

json parse_document(std::string_view text, int max_depth) {
  if (text.empty())
    throw SceneError(ErrorKind::syntax, "the scene is empty (0 bytes); expected a JSON object");
  json doc;
  BoundedDomBuilder builder(doc, text, max_depth);
  json::sax_parse(text.begin(), text.end(), &builder);
  return doc;
}

void read_scene_fields(const json& doc, Scene& scene, const Limits& limits) {
  if (!doc.is_object()) invalid(kRoot, std::string("a scene is a JSON object, got ") + type_name(doc));
  check_keys(doc, kRoot,
             {"width", "height", "background", "antialias", "primitives", "camera", "light", "lights",
              "$schema", "$comment"});
  // What editors and JSON Schema give a document: the schema it follows, and a note. Neither draws.
  for (const char* key : {"$schema", "$comment"})
    if (auto it = doc.find(key); it != doc.end() && !it->is_string())
      invalid(Path(kRoot, key), std::string("expected a string, got ") + type_name(*it));
  auto read_side = [&](const char* key, int max_side) {
    auto it = doc.find(key);
    const Path pointer(kRoot, key);
    if (it == doc.end()) invalid(kRoot, std::string("missing \"") + key + "\" (image size in pixels)");
    const std::int64_t side = read_integer(*it, pointer);
    if (side < 1) invalid(pointer, std::string("\"") + key + "\" must be at least 1, got " + it->dump());
    const int cap = std::min(max_side, kMaxImageSide);
    if (side > cap)
      fail(ErrorKind::limit, pointer,
           std::string("\"") + key + "\" " + it->dump() + " exceeds the limit of " + std::to_string(cap));
    return static_cast<int>(side);
  };
  scene.width = read_side("width", limits.max_width);
  scene.height = read_side("height", limits.max_height);
  const std::int64_t pixels = static_cast<std::int64_t>(scene.width) * scene.height;
  if (pixels > limits.max_pixels)
    fail(ErrorKind::limit, kRoot,
         std::to_string(scene.width) + "x" + std::to_string(scene.height) + " is " + std::to_string(pixels) +
             " pixels, over the limit of " + std::to_string(limits.max_pixels));

  if (auto it = doc.find("antialias"); it != doc.end()) {
    const Path at(kRoot, "antialias");
    if (it->is_string() && *it == "area") {
      scene.antialias = raster::Antialias::area;
    } else if (it->is_string() && *it == "auto") {
      scene.antialias = raster::Antialias::automatic;
    } else {
      const std::int64_t n = it->is_string() ? 0 : read_integer(*it, at);
      if (!raster::antialias_of_samples(n, scene.antialias))
        invalid(at, "\"antialias\" is \"area\", \"auto\" or the samples per pixel: 1, 4, 8 or 16; got " +
                        it->dump());
    }
  }
  if (auto it = doc.find("background"); it != doc.end())
    scene.background = read_color(*it, Path(kRoot, "background"));

  if (auto it = doc.find("camera"); it != doc.end()) scene.camera = read_camera(*it);
  if (auto it = doc.find("light"); it != doc.end()) {
    if (doc.contains("lights"))
      invalid(Path(kRoot, "lights"), "\"light\" (one light) and \"lights\" (a list) exclude each other");
    scene.lights = read_light(*it);
  }
  if (auto it = doc.find("lights"); it != doc.end()) scene.lights = read_lights(*it);
}

Scene parse_scene_dom(std::string_view text, const Limits& limits, const Uploads& uploads) {
  const json doc = parse_document(text, limits.max_json_depth);
  Scene scene;
  read_scene_fields(doc, scene, limits);
  if (auto it = doc.find("primitives"); it != doc.end()) {
    const Path primitives(kRoot, "primitives");
    if (!it->is_array()) invalid(primitives, std::string("expected an array, got ") + type_name(*it));
    if (static_cast<std::int64_t>(it->size()) > limits.max_primitives)
      fail(ErrorKind::limit, primitives,
           std::to_string(it->size()) + " primitives exceed the limit of " +
               std::to_string(limits.max_primitives));
    scene.primitives.reserve(it->size());
    for (std::size_t i = 0; i < it->size(); ++i)
      read_primitive((*it)[i], Path(primitives, i), scene, limits, uploads);
  }
  return scene;
}

}  // namespace raster::scene_json

namespace raster::scene_json {

Scene parse_scene_oracle(std::string_view json_text, const Limits& limits, const Uploads& uploads) {
  require_utf8(json_text, "the scene");
  Scene scene = parse_scene_dom(json_text, limits, uploads);
  validate(scene);
  return scene;
}

}  // namespace raster::scene_json
