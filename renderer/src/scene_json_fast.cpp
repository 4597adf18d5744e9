// The streaming scene reader: JSON text -> Scene in one pass, without a document tree.
//
// Big scenes are almost all "primitives": a hundred thousand small objects of "type", "points" and
// "colors", or a mesh's flat arrays of numbers. Building nlohmann's tree for them costs a map per object
// and a heap node per number, several times the text in memory and most of the parse time. This reader
// walks the text once, reads those hot fields straight into the Scene's flat arrays, and passes every
// other value (a camera, a transform, a "width") to nlohmann and the DOM reader's functions, so there is
// one definition of the format. When anything is unusual — an escape in a string, a key it does not
// stream, a wrong count, malformed text — it hands that primitive, or the whole document, back to the DOM
// reader, which then either reads it or reports the error with its pointer. See scene_json.h.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include "scene_json.h"

namespace raster::scene_json {
namespace {

// The whole document goes to the DOM reader.
struct GiveUp {};
// This primitive goes to the DOM reader; the rest of the document keeps streaming.
struct HandOver {};

// Depths of the streamed structure (the root object is 1): what "max_json_depth" must allow for it.
constexpr int kPrimitiveDepth = 3;  // {"primitives": [ {here} ]}
constexpr int kStreamedDepth = 5;   // a point inside "points" inside a primitive

// Powers of ten exact in a double: 10^22 is the last one.
constexpr double kExactPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                  1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Bytes a string this reader takes may hold: printable ASCII except the quote and the backslash.
constexpr std::array<bool, 256> kPlainStringByte = [] {
  std::array<bool, 256> t{};
  for (int c = 0x20; c < 0x80; ++c) t[c] = c != '"' && c != '\\';
  return t;
}();

// How many bytes of text[0, size) equal c: 16 at a time (GCC vector extensions: SSE2 on x86-64).
std::size_t count_byte(const char* text, std::size_t size, char c) {
  using Bytes = std::uint8_t __attribute__((vector_size(16)));
  std::size_t total = 0, i = 0;
  while (size - i >= 16) {
    Bytes hits = {};  // per lane, up to 255 blocks before it could wrap
    const std::size_t end = i + std::min<std::size_t>((size - i) / 16, 255) * 16;
    for (; i < end; i += 16) {
      Bytes block;
      std::memcpy(&block, text + i, 16);
      hits -= reinterpret_cast<Bytes>(block == static_cast<std::uint8_t>(c));  // a match is -1
    }
    for (int k = 0; k < 16; ++k) total += hits[k];
  }
  for (; i < size; ++i) total += text[i] == c;
  return total;
}

// A cursor over the text. Every method throws E on text it does not accept; E is GiveUp at the document
// level and HandOver inside a primitive.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

  const char* pos() const { return p_; }
  void seek(const char* p) { p_ = p; }

  // Machine-written JSON has little whitespace: one compare decides most calls.
  void space() {
    while (p_ < end_ && static_cast<unsigned char>(*p_) <= ' ' &&
           (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t'))
      ++p_;
  }
  bool at_end() {
    space();
    return p_ == end_;
  }
  bool consume(char c) {
    if (p_ < end_ && *p_ == c) return ++p_, true;  // the usual case: no whitespace before it
    space();
    if (p_ < end_ && *p_ == c) return ++p_, true;
    return false;
  }
  template <class E>
  void expect(char c) {
    if (!consume(c)) throw E{};
  }
  template <class E>
  char peek() {
    space();
    if (p_ == end_) throw E{};
    return *p_;
  }

  // A string without escapes or bytes outside printable ASCII; anything else is for nlohmann to judge.
  template <class E>
  std::string_view string() {
    expect<E>('"');
    const char* start = p_;
    while (p_ < end_ && kPlainStringByte[static_cast<unsigned char>(*p_)]) ++p_;
    if (p_ == end_ || *p_ != '"') throw E{};
    return {start, static_cast<std::size_t>(p_++ - start)};
  }

  // A JSON number as nlohmann reads it into a double (strtod, correctly rounded; integer syntax through an
  // integer, so "-0" is +0).
  template <class E>
  double number() {
    space();
    const char* start = p_;
    const bool negative = p_ < end_ && *p_ == '-';
    if (negative) ++p_;
    // All digits go into `mantissa`; up to 19 of them fit in a uint64 (longer numbers take from_chars).
    std::uint64_t mantissa = 0;
    const char* digits = p_;
    if (p_ < end_ && *p_ == '0') {
      ++p_;
    } else {
      if (p_ == end_ || !is_digit(*p_)) throw E{};
      for (; p_ < end_ && is_digit(*p_); ++p_) mantissa = mantissa * 10 + static_cast<unsigned>(*p_ - '0');
    }
    std::ptrdiff_t fraction = 0;
    const bool has_fraction = p_ < end_ && *p_ == '.';
    if (has_fraction) {
      const char* first = ++p_;
      for (; p_ < end_ && is_digit(*p_); ++p_) mantissa = mantissa * 10 + static_cast<unsigned>(*p_ - '0');
      fraction = p_ - first;
      if (fraction == 0) throw E{};
    }
    const std::ptrdiff_t digit_count = p_ - digits - (has_fraction ? 1 : 0);
    const bool has_exponent = p_ < end_ && (*p_ == 'e' || *p_ == 'E');
    if (has_exponent) {
      ++p_;
      if (p_ < end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !is_digit(*p_)) throw E{};
      while (p_ < end_ && is_digit(*p_)) ++p_;
    }
    const bool is_integral = !has_fraction && !has_exponent;
    // Clinger's fast path: mantissa and power of ten are exact doubles, so the one IEEE division rounds
    // correctly, as strtod does.
    if (!has_exponent && digit_count <= 19 && mantissa <= (std::uint64_t{1} << 53) && fraction <= 22) {
      if (is_integral && mantissa == 0) return 0.0;
      const double v = static_cast<double>(mantissa) / kExactPow10[fraction];
      return negative ? -v : v;
    }
    double v = 0;
    const auto [end, error] = std::from_chars(start, p_, v);
    if (error != std::errc() || end != p_ || !std::isfinite(v)) throw E{};
    if (is_integral && v == 0) return 0.0;
    return v;
  }

  // A non-negative integer written as one (an index), below 2^32.
  template <class E>
  std::uint32_t index() {
    space();
    if (p_ == end_ || !is_digit(*p_)) throw E{};
    if (*p_ == '0') {
      ++p_;
      if (p_ < end_ && (is_digit(*p_) || *p_ == '.' || *p_ == 'e' || *p_ == 'E')) throw E{};
      return 0;
    }
    std::uint64_t v = 0;
    while (p_ < end_ && is_digit(*p_)) {
      v = v * 10 + static_cast<std::uint64_t>(*p_++ - '0');
      if (v > UINT32_MAX) throw E{};
    }
    if (p_ < end_ && (*p_ == '.' || *p_ == 'e' || *p_ == 'E')) throw E{};
    return static_cast<std::uint32_t>(v);
  }

  // The text of the next value, found by matching brackets outside strings; nlohmann checks the rest.
  // A number or literal ends at the first byte that cannot be part of one: nlohmann takes a NUL byte for
  // the end of its input, so "3\0 4" must not reach it as one value.
  template <class E>
  std::string_view value_text() {
    space();
    const char* start = p_;
    if (p_ == end_) throw E{};
    if (*p_ != '"' && *p_ != '[' && *p_ != '{') {
      while (p_ < end_ && (is_digit(*p_) || (*p_ >= 'a' && *p_ <= 'z') || *p_ == '-' || *p_ == '+' ||
                           *p_ == '.' || *p_ == 'E'))
        ++p_;
      if (p_ == start) throw E{};
      return {start, static_cast<std::size_t>(p_ - start)};
    }
    int depth = 0;
    do {
      const char c = *p_;
      if (c == '"') {
        for (++p_; p_ < end_ && *p_ != '"'; ++p_)
          if (*p_ == '\\' && p_ + 1 < end_) ++p_;
        if (p_ == end_) throw E{};
      } else if (c == '[' || c == '{') {
        ++depth;
      } else if (c == ']' || c == '}') {
        --depth;
      }
      ++p_;
    } while (depth > 0 && p_ < end_);
    if (depth != 0) throw E{};
    return {start, static_cast<std::size_t>(p_ - start)};
  }

 private:
  const char* p_;
  const char* end_;
};

// The fields of one primitive as read from the text, kept between primitives so their storage is reused.
struct PrimitiveText {
  std::string_view type;
  bool has_points = false, has_colors = false, has_color = false, has_positions = false, has_indices = false,
       has_normals = false;
  std::size_t dims = 0;                // numbers per point in "points": 2 or 3
  std::vector<double> points;          // dims numbers per point
  std::vector<Rgba8> colors;           // "colors", one per point
  Rgba8 color;                         // "color" when it is written "#..."
  std::vector<Vec3> positions;         // a mesh's "positions"
  std::vector<Vec3> normals;           // a mesh's "normals"
  std::vector<std::uint32_t> indices;  // a mesh's "indices", three per triangle
  json other;                          // every other field, parsed by nlohmann (null when there is none)

  void clear() {
    type = {};
    has_points = has_colors = has_color = has_positions = has_indices = has_normals = false;
    dims = 0;
    points.clear(), colors.clear(), positions.clear(), normals.clear(), indices.clear();
    other = nullptr;
  }
  bool has_other(const char* key) const { return other.is_object() && other.contains(key); }
};

class Reader {
 public:
  Reader(std::string_view text, const Limits& limits, const Uploads& uploads, FastStats& stats)
      : in_(text),
        begin_(text.data()),
        text_size_(text.size()),
        limits_(limits),
        uploads_(uploads),
        stats_(stats) {}

  Scene read() {
    if (limits_.max_json_depth < kStreamedDepth) throw GiveUp{};
    Scene scene;
    reserve(scene);
    json fields = json::object();  // the root's fields other than "primitives"
    bool seen_primitives = false;
    in_.expect<GiveUp>('{');
    if (!in_.consume('}')) {
      do {
        const std::string_view key = in_.string<GiveUp>();
        in_.expect<GiveUp>(':');
        if (key == "primitives") {
          if (seen_primitives) throw GiveUp{};  // a repeated key: the DOM reader's rule (last wins) applies
          seen_primitives = true;
          read_primitives(scene);
        } else {
          if (fields.contains(key)) throw GiveUp{};
          fields[std::string(key)] = value(1);
        }
      } while (in_.consume(','));
      in_.expect<GiveUp>('}');
    }
    if (!in_.at_end()) throw GiveUp{};
    read_scene_fields(fields, scene, limits_);
    return scene;
  }

 private:
  // Growing the flat arrays by doubling would copy them and fault their pages in twice. Every point is an
  // array and a triangle, line or mesh holds at least two, so counting '[' bounds the points and (models
  // aside) the primitives; the shortest point, "[0,0],", caps the count by the text's length. A
  // reservation that proves short just grows; its unused part is address space the kernel never backs.
  void reserve(Scene& scene) {
    if (text_size_ < (1 << 16)) return;
    const std::size_t arrays = std::min(count_byte(begin_, text_size_, '['), text_size_ / 6);
    scene.points.reserve(arrays);
    scene.colors.reserve(arrays);
    scene.primitives.reserve(std::min(arrays / 2, static_cast<std::size_t>(limits_.max_primitives)));
  }

  // The next value, parsed by nlohmann; `depth` is the nesting of the object or array holding it.
  template <class E = GiveUp>
  json value(int depth) {
    const std::string_view text = in_.value_text<E>();
    try {
      return parse_document(text, limits_.max_json_depth - depth);
    } catch (const SceneError&) {
      throw E{};
    }
  }

  void read_primitives(Scene& scene) {
    const Path pointer(kRoot, "primitives");
    in_.expect<GiveUp>('[');
    if (in_.consume(']')) return;
    std::size_t i = 0;
    do {
      if (static_cast<std::int64_t>(i) >= limits_.max_primitives) throw GiveUp{};
      const char* start = (in_.space(), in_.pos());
      try {
        read_primitive_text();
        add(scene, Path(pointer, i));
        ++stats_.streamed;
      } catch (const HandOver&) {
        in_.seek(start);
        const json v = value(kPrimitiveDepth - 1);
        // A SceneError from here ends the streaming read; the DOM reader then reports it in document order.
        read_primitive(v, Path(pointer, i), scene, limits_, uploads_);
        ++stats_.handed;
      }
      ++i;
    } while (in_.consume(','));
    in_.expect<GiveUp>(']');
  }

  void read_primitive_text() {
    PrimitiveText& t = text_;
    t.clear();
    in_.expect<HandOver>('{');
    if (in_.consume('}')) throw HandOver{};
    do {
      const std::string_view key = in_.string<HandOver>();
      in_.expect<HandOver>(':');
      auto once = [](bool& seen) {
        if (seen) throw HandOver{};
        seen = true;
      };
      if (key == "type") {
        if (!t.type.empty()) throw HandOver{};
        t.type = in_.string<HandOver>();
        if (t.type.empty()) throw HandOver{};
      } else if (key == "points") {
        once(t.has_points);
        read_points(t);
      } else if (key == "colors") {
        once(t.has_colors);
        read_color_list(t.colors);
      } else if (key == "positions") {
        once(t.has_positions);
        read_vec3_list(t.positions);
      } else if (key == "normals") {
        once(t.has_normals);
        read_vec3_list(t.normals);
      } else if (key == "indices") {
        once(t.has_indices);
        read_index_list(t.indices);
      } else if (key == "color" && in_.peek<HandOver>() == '"') {
        once(t.has_color);
        if (t.has_other("color")) throw HandOver{};
        if (!parse_hex_color(in_.string<HandOver>(), t.color)) throw HandOver{};
      } else if (key == "color" || key == "fill" || key == "closed" || key == "width" || key == "shading" ||
                 key == "cull" || key == "wireframe" || key == "edges" || key == "transform") {
        if (t.has_other(std::string(key).c_str()) || (key == "color" && t.has_color)) throw HandOver{};
        t.other[std::string(key)] = value<HandOver>(kPrimitiveDepth);
      } else {
        throw HandOver{};  // "obj" fields, or an unknown field (an error the DOM reader words)
      }
    } while (in_.consume(','));
    in_.expect<HandOver>('}');
  }

  // [[x, y], ...] or [[x, y, z], ...]: the first point decides, like the DOM reader.
  void read_points(PrimitiveText& t) {
    in_.expect<HandOver>('[');
    if (in_.consume(']')) throw HandOver{};
    do {
      in_.expect<HandOver>('[');
      std::size_t k = 0;
      do {
        if (++k > 3) throw HandOver{};
        t.points.push_back(coordinate());
      } while (in_.consume(','));
      in_.expect<HandOver>(']');
      if (t.dims == 0) t.dims = k == 3 ? 3 : 2;
      if (k != t.dims) throw HandOver{};
    } while (in_.consume(','));
    in_.expect<HandOver>(']');
  }

  double coordinate() {
    const double v = in_.number<HandOver>();
    if (std::fabs(v) > kMaxCoordinate) throw HandOver{};
    return v;
  }

  void read_color_list(std::vector<Rgba8>& out) {
    in_.expect<HandOver>('[');
    if (in_.consume(']')) return;
    do {
      Rgba8 c;
      if (!parse_hex_color(in_.string<HandOver>(), c)) throw HandOver{};
      out.push_back(c);
    } while (in_.consume(','));
    in_.expect<HandOver>(']');
  }

  // [x, y, z, x, y, z, ...] or [[x, y, z], ...]: the first entry decides, like the DOM reader.
  void read_vec3_list(std::vector<Vec3>& out) {
    auto xyz = [&] {
      Vec3 v;
      v.x = coordinate();
      in_.expect<HandOver>(',');
      v.y = coordinate();
      in_.expect<HandOver>(',');
      v.z = coordinate();
      return v;
    };
    in_.expect<HandOver>('[');
    if (in_.consume(']')) return;
    const bool nested = in_.peek<HandOver>() == '[';
    do {
      if (nested) in_.expect<HandOver>('[');
      out.push_back(xyz());
      if (nested) in_.expect<HandOver>(']');
    } while (in_.consume(','));
    in_.expect<HandOver>(']');
  }

  // [a, b, c, ...] or [[a, b, c], ...].
  void read_index_list(std::vector<std::uint32_t>& out) {
    in_.expect<HandOver>('[');
    if (in_.consume(']')) return;
    const bool nested = in_.peek<HandOver>() == '[';
    do {
      if (nested) in_.expect<HandOver>('[');
      out.push_back(in_.index<HandOver>());
      in_.expect<HandOver>(',');
      out.push_back(in_.index<HandOver>());
      in_.expect<HandOver>(',');
      out.push_back(in_.index<HandOver>());
      if (nested) in_.expect<HandOver>(']');
    } while (in_.consume(','));
    in_.expect<HandOver>(']');
  }

  // The checks of the DOM reader's read_primitive / read_mesh on what was streamed; anything they would
  // reject is handed over, so the DOM reader words the error.
  void add(Scene& scene, const Path& pointer) {
    const PrimitiveText& t = text_;
    if (t.type == "mesh") return add_mesh(scene, pointer);
    Primitive p;
    std::size_t n = t.dims ? t.points.size() / t.dims : 0;
    if (t.type == "triangle") {
      p.kind = PrimitiveKind::triangle;
      if (n != 3 || t.has_other("closed")) throw HandOver{};
    } else if (t.type == "line") {
      p.kind = PrimitiveKind::line;
      if (n != 2 || t.has_other("fill") || t.has_other("closed")) throw HandOver{};
    } else if (t.type == "polyline") {
      p.kind = PrimitiveKind::polyline;
      if (n < 2 || t.has_other("fill")) throw HandOver{};
    } else {
      throw HandOver{};
    }
    if (t.has_positions || t.has_indices || t.has_normals || t.has_other("shading") || t.has_other("cull") ||
        t.has_other("wireframe") || t.has_other("edges") || t.has_other("transform"))
      throw HandOver{};
    if (scene.points.size() + n > UINT32_MAX) throw HandOver{};
    if (!t.other.is_null()) read_line_options(t.other, pointer, p);
    flat_.clear();
    const bool per_vertex = colors(pointer, n, Rgba8{255, 255, 255, 255}, flat_);
    add_drawn_primitive(scene, p, t.dims, t.points, per_vertex ? t.colors : flat_, per_vertex);
  }

  // "colors" (true), or "color" or `fallback` appended to `flat`: read_colors on what was streamed.
  bool colors(const Path& pointer, std::size_t n, Rgba8 fallback, std::vector<Rgba8>& flat) {
    const PrimitiveText& t = text_;
    if (t.has_colors) {
      if (t.has_color || t.has_other("color") || t.colors.size() != n) throw HandOver{};
      return true;
    }
    if (t.has_color) {
      flat.push_back(t.color);
      return false;
    }
    return read_colors(t.other, pointer, n, fallback, flat);
  }

  void add_mesh(Scene& scene, const Path& pointer) {
    PrimitiveText& t = text_;
    if (!t.has_positions || !t.has_indices || t.has_points || t.has_other("fill") || t.has_other("closed") ||
        t.has_other("width"))
      throw HandOver{};
    const std::size_t count = t.indices.size() / 3;
    if (static_cast<std::int64_t>(count) > limits_.max_primitives) throw HandOver{};
    for (std::uint32_t i : t.indices)
      if (i >= t.positions.size()) throw HandOver{};
    if (t.has_normals && t.normals.size() != t.positions.size()) throw HandOver{};
    Mesh mesh;
    if (colors(pointer, t.positions.size(), kMeshGrey, mesh.colors)) mesh.colors = t.colors;
    mesh.positions = std::move(t.positions);
    mesh.triangles.resize(count);
    for (std::size_t k = 0; k < count; ++k)
      mesh.triangles[k] = {t.indices[3 * k], t.indices[3 * k + 1], t.indices[3 * k + 2]};
    if (t.has_normals) {
      mesh.normals = std::move(t.normals);
      mesh.normal_triangles = mesh.triangles;
    }
    read_mesh_options(t.other, pointer, mesh);
    Primitive p;
    p.kind = PrimitiveKind::mesh;
    p.mesh = static_cast<std::uint32_t>(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));
    scene.primitives.push_back(p);
  }

  Cursor in_;
  const char* begin_;
  std::size_t text_size_;
  const Limits& limits_;
  const Uploads& uploads_;
  FastStats& stats_;
  PrimitiveText text_;
  std::vector<Rgba8> flat_;
};

}  // namespace

std::optional<Scene> parse_scene_fast(std::string_view text, const Limits& limits, const Uploads& uploads,
                                      FastStats* stats) {
  FastStats local;
  try {
    return Reader(text, limits, uploads, stats ? *stats : local).read();
  } catch (const GiveUp&) {
  } catch (const SceneError&) {
  } catch (const json::exception&) {
  }
  return std::nullopt;
}

}  // namespace raster::scene_json
