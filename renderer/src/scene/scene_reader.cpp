// The scene reader: JSON text -> Scene in one pass, the format described once.
//
// Each object kind of format v1 (the root, a primitive, a camera, a light, a transform, edges, a texture)
// is a table of fields: a key, the JSON kinds its value may be, and the function that reads it where it
// stands in the text. read_object() walks an object with its table; that one loop owns unknown keys (with
// a "did you mean"), keys given twice and values of the wrong kind. A primitive's table is the union of
// every type's keys, and its "type" narrows the keys allowed. Checks across fields (a colour per point,
// indices within the positions) run when the object ends. Defaults are those of the Scene's structs.
//
// Every error is a SceneError with the JSON pointer and the 1-based byte offset of the value it is about.
// A document with an error that is also malformed is reported as malformed (see parse_scene).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "base/json_cursor.h"
#include "raster/model.h"
#include "raster/scene.h"
#include "raster/utf8.h"
#include "scene/scene_format.h"
#include "shade/texture.h"
#include "base/vecmath.h"

namespace raster {
namespace {

using Kind = JsonCursor::Kind;
using Path = JsonPointer;
using format::Range;

constexpr Rgba8 kMeshGrey{204, 204, 204, 255};  // meshes and models without colours
constexpr Rgba8 kWhite{255, 255, 255, 255};     // 2D primitives without colours

const char* phrase(Kind k) {
  static constexpr const char* kPhrases[] = {"null",     "a boolean", "a number",
                                             "a string", "an array",  "an object"};
  return kPhrases[static_cast<int>(k)];
}

// Keys are a few bytes: compared inline, not through a call to memcmp.
bool same_key(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return false;
  return true;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

constexpr std::array<std::int8_t, 256> kHexDigit = [] {
  std::array<std::int8_t, 256> t{};
  for (int c = 0; c < 256; ++c)
    t[c] = c >= '0' && c <= '9'   ? static_cast<std::int8_t>(c - '0')
           : c >= 'a' && c <= 'f' ? static_cast<std::int8_t>(c - 'a' + 10)
           : c >= 'A' && c <= 'F' ? static_cast<std::int8_t>(c - 'A' + 10)
                                  : std::int8_t{-1};
  return t;
}();

// "#rgb", "#rgba", "#rrggbb" or "#rrggbbaa"; false for anything else.
[[gnu::always_inline]] inline bool parse_hex_color(std::string_view s, Rgba8& out) {
  const std::size_t n = s.size();
  if (n == 0 || s[0] != '#' || (n != 4 && n != 5 && n != 7 && n != 9)) return false;
  int d[8] = {0, 0, 0, 0, 0, 0, 15, 15};  // absent alpha reads as "ff"
  int bad = 0;
  for (std::size_t i = 1; i < n; ++i) bad |= d[i - 1] = kHexDigit[static_cast<unsigned char>(s[i])];
  if (bad < 0) return false;
  auto byte = [](int v) { return static_cast<std::uint8_t>(v); };
  if (n <= 5)
    return out = {byte(d[0] * 17), byte(d[1] * 17), byte(d[2] * 17), byte(n == 5 ? d[3] * 17 : 255)}, true;
  out = {byte(d[0] * 16 + d[1]), byte(d[2] * 16 + d[3]), byte(d[4] * 16 + d[5]), byte(d[6] * 16 + d[7])};
  return true;
}

// Texels the scene's textures hold so far: what is left of the limit is what the next one may take.
std::int64_t texels_left(const Scene& scene, const Limits& limits) {
  std::int64_t used = 0;
  for (const Mesh& m : scene.meshes)
    for (const Texture& t : m.textures) used += std::int64_t{t.width} * t.height;
  return limits.max_texture_pixels - used;
}

// The state of each object kind while it is read. `allowed` and `seen` are bits of its table's fields.
struct Keys {
  std::uint32_t allowed = ~0u, seen = 0;
};
struct CameraState : Keys {
  Camera camera;
};
struct LightState : Keys {  // "light"
  double ambient = 0.2;
  bool directed = false;
  Vec3 direction;
};
struct LightsEntry : Keys {  // one of "lights"
  Light light;
  bool typed = false;
};
struct TransformState : Keys {
  Vec3 scale{1, 1, 1}, rotate, translate;
  Mat4 matrix;
};
struct EdgesState : Keys {
  Edges edges;
};
struct TextureState : Keys {
  Texture texture;
  std::int64_t budget = 0;  // texels the scene has left
  bool clamp = false;       // "wrap": "clamp", which may come before the image
};
// A primitive: what each key gave, put together when the object ends.
struct PrimitiveState : Keys {
  int type = -1;  // index into kTypes
  std::size_t byte = 0, points_byte = 0, colors_byte = 0, indices_byte = 0, normals_byte = 0, uvs_byte = 0;
  Primitive primitive;
  std::size_t dims = 0;         // numbers per point: 2 (image space) or 3 (world space)
  std::size_t first_point = 0;  // image-space "points" are scene.points from here
  std::vector<double> coords;   // world-space "points", three numbers each
  std::vector<Rgba8> colors;    // "colors"
  Rgba8 color;                  // "color"
  Mesh mesh;                    // "mesh" and "obj": positions, normals, uvs, texture, options
  bool indices_nested = false;
  std::string bad_index;              // the text of the first index below 0 or above 2^32 - 2
  std::string obj, mtl;               // an "obj"'s inline texts: "data" and "mtl"
  std::string source, mtl_source;     // a model's uploaded parts by name: "source" and "mtl_source"
  Uploads textures;                   // a model's "textures": the files it names, by file name
  std::optional<ModelFormat> format;  // a model's "format"; "obj" for the type "obj"
  // Ready for the next primitive, keeping the flat buffers' capacity.
  void reset() {
    static_cast<Keys&>(*this) = Keys{};
    type = -1, dims = 0, indices_nested = false, primitive = Primitive{};  // `mesh` is reset when moved out
    coords.clear(), colors.clear();
    if (seen_model) {  // what only meshes and models use, cleared only after one
      obj.clear(), mtl.clear(), textures.clear(), bad_index.clear();
      source.clear(), mtl_source.clear();
      format.reset();
      seen_model = false;
    }
  }
  bool seen_model = false;  // the last primitive was a mesh or a model
};

struct Reader;
template <class T>
using Field = format::Field<void (*)(Reader&, T&, const Path&)>;

struct Reader {
  JsonCursor in;
  const Limits& limits;
  const Uploads& uploads;
  Scene scene;
  PrimitiveState prim;  // reused from primitive to primitive, so its buffers are allocated once

  [[noreturn, gnu::cold]] static void fail(ErrorKind kind, const Path& at, const std::string& message) {
    throw SceneError(kind, message, ErrorLocation{at.str(), at.byte(), 0});
  }
  [[noreturn, gnu::cold]] static void invalid(const Path& at, const std::string& message) {
    fail(ErrorKind::invalid, at, message);
  }
  [[noreturn, gnu::cold, gnu::noinline]] static void wrong_kind(const Path& at, Kind k,
                                                                const char* expected) {
    invalid(at, std::string("expected ") + expected + ", got " + phrase(k));
  }

  // The next value's kind, which must be one of `kinds`.
  Kind expect(const Path& at, std::uint8_t kinds, const char* expected) {
    const Kind k = in.peek();
    if (!(kinds >> static_cast<int>(k) & 1)) wrong_kind(at, k, expected);
    return k;
  }
  // The next array element's pointer, its byte where its value starts.
  Path element(const Path& at, std::size_t k) { return Path(at, k, in.next_offset()); }

  // The readers of numbers take `where(byte)`, which makes the pointer of the value starting at `byte`:
  // it is called only for an error, so a million numbers build no pointers. (A Path converts to one.)
  template <class Where>
  double number(const Where& where) {
    if (!in.at_number()) expect(where(in.offset()), format::kNumber, "a number");
    return in.number_here();
  }
  std::string number_text() const { return std::string(in.number_text()); }
  template <class Where>
  double ranged(const Where& where, const Range& r) {
    const double d = number(where);
    if (!r.contains(d)) invalid(where(in.number_offset()), std::string(r.rule) + "; got " + number_text());
    return d;
  }
  template <class Where>
  double coordinate(const Where& where) {
    const double d = number(where);
    if (std::fabs(d) > kMaxCoordinate)
      invalid(where(in.number_offset()), "coordinate " + number_text() + " is outside +-3.4e38 (+-2^128)");
    return d;
  }
  // 256 and 256.0, not 256.5; clamped to int64 (the range check is the caller's).
  template <class Where>
  std::int64_t integer(const Where& where) {
    const double d = number(where);
    if (!in.integral() && d != std::floor(d))
      invalid(where(in.number_offset()), "expected a whole number, got " + number_text());
    if (std::fabs(d) >= 9.2e18) return d < 0 ? INT64_MIN : INT64_MAX;
    return static_cast<std::int64_t>(d);
  }
  bool boolean(const Path& at) {
    expect(at, format::kBool, "true or false");
    return in.boolean();
  }
  // One of `names` (a string); its index.
  template <std::size_t N>
  std::size_t choice(const Path& at, const std::array<std::string_view, N>& names) {
    std::string expected = "expected";
    for (std::size_t i = 0; i < N; ++i)
      expected += (i == 0 ? " \"" : i + 1 == N ? " or \"" : ", \"") + std::string(names[i]) + "\"";
    if (in.peek() != Kind::string) invalid(at, expected + ", got " + phrase(in.peek()));
    const std::string_view s = in.string();
    for (std::size_t i = 0; i < N; ++i)
      if (s == names[i]) return i;
    invalid(at, expected + ", got \"" + std::string(s) + "\"");
  }
  // Growing the flat arrays by doubling would copy them and fault their pages in twice. Every 2D point is
  // an array and a primitive holds at least two, so counting '[' bounds the points and the primitives; the
  // shortest point, "[0,0],", caps the count by the text's length.
  void reserve(std::string_view text) {
    if (text.size() < (1 << 16)) return;
    const std::size_t arrays = std::min(JsonCursor::count(text, '['), text.size() / 6);
    scene.points.reserve(arrays);
    scene.colors.reserve(arrays);
    scene.primitives.reserve(std::min(arrays / 2, static_cast<std::size_t>(limits.max_primitives)));
  }

  template <class T, std::size_t N>
  void read_object(const Field<T> (&fields)[N], T& state, const Path& at, const char* expected);
  template <class F, std::size_t N>
  [[noreturn]] void unknown_key(const F (&fields)[N], std::uint32_t allowed, std::string_view key,
                                const Path& at);

  Rgba8 color(const Path& at);
  Vec3 vec3(const Path& at);
  void points(PrimitiveState& s, const Path& at);
  template <std::size_t N, class Number, class Add>
  bool tuples(const Path& at, const char* shape, const char* names, Number number, Add add);
  void vec3_list(std::vector<Vec3>& out, const Path& at);
  void indices(PrimitiveState& s, const Path& at);
  void uvs(PrimitiveState& s, const Path& at);
  std::string base64(const Path& at);
  void primitives(const Path& at);
  void primitive(const Path& at);
  void set_type(PrimitiveState& s, std::string_view name, const Path& at);
  void type_first(JsonCursor::Mark start, const Path& at);
  void finish_drawn(PrimitiveState& s, const Path& at);
  void finish_mesh(PrimitiveState& s, const Path& at);
  void finish_obj(PrimitiveState& s, const Path& at);
  void lights(const Path& at);
  void read_root();
};

template <class F, std::size_t N>
void Reader::unknown_key(const F (&fields)[N], std::uint32_t allowed, std::string_view key, const Path& at) {
  std::string best, known;
  std::size_t best_distance = 3;  // more than two edits away is not a typo
  for (std::size_t i = 0; i < N; ++i) {
    if (!(allowed >> i & 1)) continue;
    known += " \"" + std::string(fields[i].key) + "\"";
    if (const std::size_t d = edit_distance(key, fields[i].key); d < best_distance)
      best_distance = d, best = fields[i].key;
  }
  invalid(at, "unknown field \"" + std::string(key) + "\"" +
                  (best.empty() ? "; known fields are" + known : "; did you mean \"" + best + "\"?"));
}

template <class T, std::size_t N>
void Reader::read_object(const Field<T> (&fields)[N], T& state, const Path& at, const char* expected) {
  static_assert(N <= 32, "`allowed` and `seen` hold a bit per field");
  expect(at, format::kObject, expected);
  std::size_t next = 0;  // where the search for a key starts: documents tend to keep the table's order
  for (bool more = in.object_begin(); more; more = in.object_next()) {
    std::string own;
    std::string_view key = in.key();
    if (!in.in_text(key)) own = key, key = own;  // an escaped key: the next string read reuses its buffer
    const Kind kind = in.peek();
    const Path field(at, key, in.offset());
    std::size_t i = next, tried = 0;
    for (; tried < N && !same_key(fields[i].key, key); ++tried) i = i + 1 == N ? 0 : i + 1;
    if (tried == N || !(state.allowed >> i & 1)) unknown_key(fields, state.allowed, key, field);
    next = i + 1 == N ? 0 : i + 1;
    if (state.seen >> i & 1)
      invalid(field, "\"" + std::string(key) + "\" is given twice in one object; give each key once");
    state.seen |= 1u << i;
    if (!(fields[i].kinds >> static_cast<int>(kind) & 1)) wrong_kind(field, kind, fields[i].expected);
    fields[i].read(*this, state, field);
    if (const std::uint32_t early =
            state.seen & ~state.allowed) {  // read before a "type" that does not take it
      const std::string_view k = fields[std::countr_zero(early)].key;
      unknown_key(fields, state.allowed, k, Path(at, k, field.byte()));
    }
  }
}

// "#rgb", "#rgba", "#rrggbb", "#rrggbbaa", [r,g,b] or [r,g,b,a] with components in 0..1.
Rgba8 Reader::color(const Path& at) {
  if (expect(at, format::kString | format::kArray, "a colour (\"#rrggbb\" or [r, g, b])") == Kind::string) {
    const std::string_view s = in.string();
    Rgba8 c;
    if (!parse_hex_color(s, c))
      invalid(at, "expected a colour \"#rgb\", \"#rgba\", \"#rrggbb\" or \"#rrggbbaa\", got \"" +
                      std::string(s) + "\"");
    return c;
  }
  double comp[4];
  std::string_view text[4];
  std::size_t n = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++n) {
    const Path c = element(at, n);
    const double v = number(c);
    if (n < 4) comp[n] = v, text[n] = in.number_text();
  }
  if (n != 3 && n != 4)
    invalid(at, "a colour array has 3 or 4 components [r, g, b(, a)], got " + std::to_string(n));
  for (std::size_t k = 0; k < n; ++k) {
    if (comp[k] >= 0.0 && comp[k] <= 1.0) continue;
    std::string message = "colour components are in 0..1, got " + std::string(text[k]);
    // Hex is suggested only for components that all read as 0..255 bytes. A 1 among them reads as "full"
    // on the 0..1 scale ([1, 0, 0, 255] is opaque red with a slip), and so does [1, 1, 2]: no guess then.
    if (std::all_of(comp, comp + n,
                    [](double c) { return c >= 0 && c <= 255 && c == std::floor(c) && c != 1; })) {
      message += "; did you mean \"#";
      for (std::size_t j = 0; j < n; ++j)
        message += "0123456789abcdef"[int(comp[j]) >> 4], message += "0123456789abcdef"[int(comp[j]) & 15];
      message += "\"?";
    }
    invalid(Path(at, k, at.byte()), message);
  }
  auto byte = [](double v) { return static_cast<std::uint8_t>(std::floor(v * 255.0 + 0.5)); };
  return {byte(comp[0]), byte(comp[1]), byte(comp[2]), n == 4 ? byte(comp[3]) : std::uint8_t{255}};
}

Vec3 Reader::vec3(const Path& at) {
  expect(at, format::kArray, "a point [x, y, z]");
  double v[3];
  std::size_t n = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++n) {
    const Path c = element(at, n);
    const double d = coordinate(c);
    if (n < 3) v[n] = d;
  }
  if (n != 3) invalid(at, "expected a point [x, y, z], got " + std::to_string(n) + " numbers");
  return {v[0], v[1], v[2]};
}

// [[x, y], ...] or [[x, y, z], ...]: the first point decides, and every other must agree.
void Reader::points(PrimitiveState& s, const Path& at) {
  s.points_byte = at.byte();
  s.first_point = scene.points.size();
  const char* shape = s.dims == 3 ? "[x, y, z]" : "[x, y]";
  std::size_t k = 0;
  // The hot loop of big 2D scenes: pointers are made only for an error.
  for (bool more = in.array_begin(); more; more = in.array_next(), ++k) {
    const JsonCursor::Mark start = in.mark();
    if (double x, y; s.dims != 3 && in.pair(x, y)) {
      if (std::fabs(x) <= kMaxCoordinate && std::fabs(y) <= kMaxCoordinate) {
        s.dims = 2;
        scene.points.push_back({x, y});
        continue;
      }
      in.seek(start);  // read again below, for the error's words
    }
    if (!in.at('['))
      expect(element(at, k), format::kArray, s.dims == 3 ? "a point [x, y, z]" : "a point [x, y]");
    const std::size_t byte = in.offset();
    double v[3];
    std::size_t n = 0;
    for (bool inner = in.array_begin(); inner; inner = in.array_next(), ++n) {
      if (!in.at_number() || n >= 3) {
        const Path point(at, k, byte);
        const double d = coordinate(element(point, n));
        if (n < 3) v[n] = d;
        continue;
      }
      const std::size_t number_byte = in.offset();
      v[n] = in.number();
      if (std::fabs(v[n]) > kMaxCoordinate)
        invalid(Path(Path(at, k, byte), n, number_byte),
                "coordinate " + number_text() + " is outside +-3.4e38 (+-2^128)");
    }
    if (k == 0) s.dims = n == 3 ? 3 : 2, shape = s.dims == 3 ? "[x, y, z]" : "[x, y]";
    if (n != s.dims)
      invalid(Path(at, k, byte), std::string("expected a point ") + shape + " like the first point, got " +
                                     std::to_string(n) + " numbers");
    if (s.dims == 2)  // image space, straight into the scene (an error anywhere discards it)
      scene.points.push_back({v[0], v[1]});
    else
      s.coords.push_back(v[0]), s.coords.push_back(v[1]), s.coords.push_back(v[2]);
  }
}

// Entries of N numbers, nested ([[a, b, c], ...]) or flat ([a, b, c, a, b, c, ...]): the first element
// decides. `number(pointer)` reads one number, `add(entry)` takes each entry. True when flat.
template <std::size_t N, class Number, class Add>
bool Reader::tuples(const Path& at, const char* shape, const char* names, Number number, Add add) {
  std::array<double, N> v;
  std::size_t k = 0;
  if (!in.array_begin()) return false;
  if (in.at_number()) {  // flat: N numbers at a time, the hot loop of big meshes
    for (bool more = true; more;) {
      for (std::size_t j = 0; j < N; ++j, ++k) {
        v[j] = number([&](std::size_t byte) { return Path(at, k, byte); });
        if (!(more = in.array_next()) && j + 1 < N)
          invalid(at, std::string("a flat list holds ") + names + "; its length " + std::to_string(k + 1) +
                          " is not a multiple of " + std::to_string(N));
      }
      add(v);
    }
    return true;
  }
  for (bool more = true; more; more = in.array_next(), ++k) {
    const Path e = element(at, k);
    expect(e, format::kArray, shape);
    std::size_t n = 0;
    for (bool inner = in.array_begin(); inner; inner = in.array_next(), ++n) {
      const double d = number([&](std::size_t byte) { return Path(e, n, byte); });
      if (n < N) v[n] = d;
    }
    if (n != N) invalid(e, std::string("expected ") + shape + ", got " + std::to_string(n) + " numbers");
    add(v);
  }
  return false;
}

void Reader::vec3_list(std::vector<Vec3>& out, const Path& at) {
  out.reserve(in.flat_array_size() / 3);
  tuples<3>(
      at, "a point [x, y, z]", "x, y, z triples", [&](const auto& where) { return coordinate(where); },
      [&](const std::array<double, 3>& v) {
        out.push_back({v[0], v[1], v[2]});
      });
}

// 0-based into the positions, checked when the mesh ends: one outside every range is kept as UINT32_MAX.
void Reader::indices(PrimitiveState& s, const Path& at) {
  s.indices_byte = at.byte();
  auto& triangles = s.mesh.triangles;
  triangles.reserve(in.flat_array_size() / 3);
  auto index = [&](const auto& where) {
    if (std::uint32_t i; in.index(i)) return static_cast<double>(i);
    const std::int64_t i = integer(where);
    const bool outside = i < 0 || i >= UINT32_MAX;
    if (outside && s.bad_index.empty()) s.bad_index = number_text();
    return outside ? double{UINT32_MAX} : static_cast<double>(i);
  };
  s.indices_nested =
      !tuples<3>(at, "a triangle [a, b, c]", "a, b, c triples", index, [&](const std::array<double, 3>& v) {
        if (static_cast<std::int64_t>(triangles.size()) == limits.max_primitives)
          fail(ErrorKind::limit, at,
               "more triangles than the limit of " + std::to_string(limits.max_primitives));
        triangles.push_back({static_cast<std::uint32_t>(v[0]), static_cast<std::uint32_t>(v[1]),
                             static_cast<std::uint32_t>(v[2])});
      });
}

void Reader::uvs(PrimitiveState& s, const Path& at) {
  s.uvs_byte = at.byte();
  s.mesh.uvs.reserve(in.flat_array_size() / 2);
  tuples<2>(
      at, "a texture coordinate [u, v]", "u, v pairs",
      [&](const auto& where) { return ranged(where, format::kTexCoord); },
      [&](const std::array<double, 2>& v) {
        s.mesh.uvs.push_back({static_cast<float>(v[0]), static_cast<float>(v[1])});
      });
}

// The bytes of an image given as base64 text.
std::string Reader::base64(const Path& at) {
  expect(at, format::kString, "the image file as base64 text");
  std::string bytes;
  if (!decode_base64(in.string(), bytes))
    invalid(at, "not base64 (RFC 4648, '+' and '/', optionally a data: URI)");
  return bytes;
}

// ---- The tables. A field's function reads its value into the state of the object it is in.

// "transform": {"translate", "rotate" (degrees about x, then y, then z), "scale"} or {"matrix"}.
constexpr Field<TransformState> kTransformFields[] = {
    {"translate", format::kArray, "[x, y, z]",
     [](Reader& r, TransformState& t, const Path& at) { t.translate = r.vec3(at); }},
    {"rotate", format::kArray, "[x, y, z] in degrees",
     [](Reader& r, TransformState& t, const Path& at) { t.rotate = r.vec3(at); }},
    {"scale", format::kNumber | format::kArray, "a number or [x, y, z]",
     [](Reader& r, TransformState& t, const Path& at) {
       if (r.in.peek() != Kind::number) return void(t.scale = r.vec3(at));
       const double k = r.number(at);
       t.scale = {k, k, k};
     }},
    {"matrix", format::kArray, "16 numbers (a row-major 4x4 matrix)",
     [](Reader& r, TransformState& t, const Path& at) {
       std::size_t k = 0;
       for (bool more = r.in.array_begin(); more; more = r.in.array_next(), ++k) {
         const double v = r.number(r.element(at, k));
         if (k < 16) t.matrix.m[k] = v;
       }
       if (k != 16) r.invalid(at, "expected 16 numbers (a row-major 4x4 matrix)");
     }},
};

constexpr Field<EdgesState> kEdgesFields[] = {
    {"color", format::kString | format::kArray, "a colour",
     [](Reader& r, EdgesState& e, const Path& at) { e.edges.color = r.color(at); }},
    {"width", format::kNumber, "a number",
     [](Reader& r, EdgesState& e, const Path& at) {
       e.edges.width = static_cast<float>(r.ranged(at, format::kEdgeWidth));
     }},
    {"angle", format::kNumber, "a number",
     [](Reader& r, EdgesState& e, const Path& at) {
       e.edges.crease_deg = static_cast<float>(r.ranged(at, format::kCreaseAngle));
     }},
};

constexpr Field<TextureState> kTextureFields[] = {
    {"data", format::kString, "the image file as base64 text",
     [](Reader& r, TextureState& t, const Path& at) {
       try {
         t.texture = decode_texture(r.base64(at), "data", t.budget);
       } catch (const SceneError& e) {
         if (!e.where().pointer.empty()) throw;
         r.fail(e.kind(), at, e.what());
       }
     }},
    {"source", format::kString, "the name of an uploaded part",
     [](Reader& r, TextureState& t, const Path& at) {
       const std::string name(r.in.string());
       const auto part = r.uploads.find(name);
       if (part == r.uploads.end())
         r.invalid(at, "no uploaded part named \"" + name + "\" (send it as a multipart part of that name)");
       try {
         t.texture = decode_texture(part->second, name, t.budget);
       } catch (const SceneError& e) {
         r.fail(e.kind(), at, e.what());
       }
     }},
    {"wrap", format::kString, "\"repeat\" or \"clamp\"",
     [](Reader& r, TextureState& t, const Path& at) {
       t.clamp = r.choice(at, std::array<std::string_view, 2>{"repeat", "clamp"}) == 1;
     }},
};

// A primitive: the union of every type's keys; "type" narrows them to its own (kTypes).
constexpr Field<PrimitiveState> kPrimitiveFields[] = {
    {"type", format::kString, "a string",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.set_type(s, r.in.string(), at); }},
    {"points", format::kArray, "an array of points",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.points(s, at); }},
    {"color", format::kString | format::kArray, "a colour (\"#rrggbb\" or [r, g, b])",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.color = r.color(at); }},
    {"colors", format::kArray, "an array of colours, one per point",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.colors_byte = at.byte();
       std::size_t k = 0;
       for (bool more = r.in.array_begin(); more; more = r.in.array_next(), ++k) {
         Rgba8 c;
         const JsonCursor::Mark start = r.in.mark();
         if (r.in.at('"') && parse_hex_color(r.in.string_here(), c)) {  // the usual colour: no pointer made
           s.colors.push_back(c);
           continue;
         }
         r.in.seek(start);  // anything else is read again by color(), which has the words for its errors
         s.colors.push_back(r.color(r.element(at, k)));
       }
     }},
    {"fill", format::kBool, "true or false",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.primitive.fill = r.boolean(at); }},
    {"closed", format::kBool, "true or false",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.primitive.closed = r.boolean(at); }},
    {"width", format::kNumber, "a number",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.primitive.width = static_cast<float>(r.ranged(at, format::kLineWidth));
     }},
    {"positions", format::kArray, "an array of [x, y, z] or of numbers",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.vec3_list(s.mesh.positions, at); }},
    {"indices", format::kArray, "an array of [a, b, c] or of integers",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.indices(s, at); }},
    {"normals", format::kArray, "an array of [x, y, z] or of numbers",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.normals_byte = at.byte(), r.vec3_list(s.mesh.normals, at);
     }},
    {"uvs", format::kArray, "an array of [u, v] or of numbers",
     [](Reader& r, PrimitiveState& s, const Path& at) { r.uvs(s, at); }},
    {"texture", format::kObject, "{\"data\": base64} or {\"source\": part name}",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       TextureState t;
       t.budget = texels_left(r.scene, r.limits);
       r.read_object(kTextureFields, t, at, "a texture object");
       if (std::popcount(t.seen & 3u) != 1)
         r.invalid(
             at,
             "a texture needs \"data\" (the PNG or JPEG file as base64) or \"source\" (an uploaded part)");
       t.texture.clamp = t.clamp;
       s.mesh.textures.push_back(std::move(t.texture));
     }},
    {"shading", format::kString, "\"flat\", \"smooth\" or \"unlit\"",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.mesh.shading =
           static_cast<Shading>(r.choice(at, std::array<std::string_view, 3>{"flat", "smooth", "unlit"}));
     }},
    {"cull", format::kString, "\"none\" or \"back\"",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.mesh.cull = static_cast<Cull>(r.choice(at, std::array<std::string_view, 2>{"none", "back"}));
     }},
    {"wireframe", format::kBool, "true or false",
     [](Reader& r, PrimitiveState& s, const Path& at) { s.mesh.wireframe = r.boolean(at); }},
    {"edges", format::kBool | format::kObject, "true or {\"color\", \"width\", \"angle\"}",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       EdgesState e;
       if (r.in.peek() == Kind::boolean)
         e.edges.enabled = r.in.boolean();
       else
         r.read_object(kEdgesFields, e, at, "an edges object"), e.edges.enabled = true;
       s.mesh.edges = e.edges;
     }},
    {"transform", format::kObject, "a transform object",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       TransformState t;
       r.read_object(kTransformFields, t, at, "a transform object");
       if (t.seen & 8u) {  // "matrix"
         if (t.seen != 8u) r.invalid(at, "\"matrix\" replaces translate/rotate/scale; give one or the other");
         return void(s.mesh.transform = t.matrix);
       }
       // Scale first, then rotate about x, y and z, then translate: T * Rz * Ry * Rx * S.
       Mat4 m;
       m(0, 0) = t.scale.x, m(1, 1) = t.scale.y, m(2, 2) = t.scale.z;
       const double angles[3] = {t.rotate.x, t.rotate.y, t.rotate.z};
       for (int axis = 0; axis < 3 && (t.seen & 2u); ++axis) {
         const double rad = angles[axis] * std::numbers::pi / 180.0, c = std::cos(rad), sn = std::sin(rad);
         Mat4 rot;
         const int a = (axis + 1) % 3, b = (axis + 2) % 3;
         rot(a, a) = c, rot(a, b) = -sn, rot(b, a) = sn, rot(b, b) = c;
         m = detail::operator*(rot, m);
       }
       Mat4 tm;
       tm(0, 3) = t.translate.x, tm(1, 3) = t.translate.y, tm(2, 3) = t.translate.z;
       s.mesh.transform = (t.seen & 1u) ? detail::operator*(tm, m) : m;
     }},
    {"data", format::kString, "text",
     [](Reader& r, PrimitiveState& s, const Path&) { s.obj = r.in.string(); }},
    {"source", format::kString, "the name of an uploaded part",
     [](Reader& r, PrimitiveState& s, const Path&) { s.source = r.in.string(); }},
    {"mtl", format::kString, "text",
     [](Reader& r, PrimitiveState& s, const Path&) { s.mtl = r.in.string(); }},
    {"mtl_source", format::kString, "the name of an uploaded part",
     [](Reader& r, PrimitiveState& s, const Path&) { s.mtl_source = r.in.string(); }},
    {"format", format::kString, "a string",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       s.format = model_formats()[r.choice(at, format_names())].format;
     }},
    {"textures", format::kObject, "an object of file name: base64 image",
     [](Reader& r, PrimitiveState& s, const Path& at) {
       for (bool more = r.in.object_begin(); more; more = r.in.object_next()) {
         const std::string name(r.in.key());
         const Path image(at, name, (r.in.peek(), r.in.offset()));
         if (s.textures.contains(name))
           r.invalid(image, "\"" + name + "\" is given twice in one object; give each key once");
         s.textures[name] = r.base64(image);
       }
     }},
};

// The bit of a primitive's key, at compile time.
consteval std::uint32_t bit(std::string_view key) {
  return format::mask_of(kPrimitiveFields, {key});
}

struct PrimitiveType {
  std::string_view name;
  PrimitiveKind kind;
  std::uint32_t min_points, max_points;
  std::uint32_t keys;  // bits of kPrimitiveFields
};
constexpr PrimitiveType kTypes[] = {
    {"triangle", PrimitiveKind::triangle, 3, 3,
     format::mask_of(kPrimitiveFields, {"type", "points", "color", "colors", "fill", "width"})},
    {"line", PrimitiveKind::line, 2, 2,
     format::mask_of(kPrimitiveFields, {"type", "points", "color", "colors", "width"})},
    {"polyline", PrimitiveKind::polyline, 2, UINT32_MAX,
     format::mask_of(kPrimitiveFields, {"type", "points", "color", "colors", "closed", "width"})},
    {"mesh", PrimitiveKind::mesh, 0, 0,
     format::mask_of(kPrimitiveFields, {"type", "positions", "indices", "colors", "color", "normals", "uvs",
                                        "texture", "shading", "wireframe", "edges", "cull", "transform"})},
    // A model file in any format (model.h), its format told by its bytes, else by "format"; "obj" is the
    // same with OBJ as the format to fall back on (rasterd 0.1's name, kept).
    {"model", PrimitiveKind::mesh, 0, 0,
     format::mask_of(kPrimitiveFields, {"type", "data", "source", "format", "mtl", "mtl_source", "textures",
                                        "color", "shading", "wireframe", "edges", "cull", "transform"})},
    {"obj", PrimitiveKind::mesh, 0, 0,
     format::mask_of(kPrimitiveFields, {"type", "data", "source", "mtl", "mtl_source", "textures", "color",
                                        "shading", "wireframe", "edges", "cull", "transform"})},
};
constexpr const char* kTypeNames = "\"triangle\", \"line\", \"polyline\", \"mesh\", \"model\" or \"obj\"";

void Reader::set_type(PrimitiveState& s, std::string_view name, const Path& at) {
  const auto* t = std::find_if(std::begin(kTypes), std::end(kTypes),
                               [&](const PrimitiveType& t) { return t.name == name; });
  if (t == std::end(kTypes))
    invalid(at, "unknown primitive type \"" + std::string(name) + "\"; expected " + kTypeNames);
  s.type = static_cast<int>(t - kTypes);
  s.allowed = t->keys;
}

void Reader::finish_drawn(PrimitiveState& s, const Path& at) {
  const PrimitiveType& t = kTypes[s.type];
  if (!(s.seen & bit("points"))) invalid(at, "a " + std::string(t.name) + " needs \"points\"");
  const std::size_t n = s.dims == 3 ? s.coords.size() / 3 : scene.points.size() - s.first_point;
  const Path points(at, "points", s.points_byte);
  if (n < t.min_points || n > t.max_points)
    invalid(points, "a " + std::string(t.name) +
                        (t.min_points == t.max_points ? " has exactly " : " has at least ") +
                        std::to_string(t.min_points) + " points, got " + std::to_string(n));
  if (s.first_point + n > UINT32_MAX) fail(ErrorKind::limit, points, "too many points in the scene");
  if ((s.seen & bit("color")) && (s.seen & bit("colors")))
    invalid(at, "give either \"color\" (flat) or \"colors\" (one per point), not both");
  if ((s.seen & bit("colors")) && s.colors.size() != n)
    invalid(Path(at, "colors", s.colors_byte),
            "\"colors\" needs one colour per point (" + std::to_string(n) + ")");
  if (!(s.seen & bit("colors"))) s.colors.assign(1, (s.seen & bit("color")) ? s.color : kWhite);
  Primitive p = s.primitive;
  p.kind = t.kind;
  const bool per_vertex = s.seen & bit("colors");
  if (s.dims == 3) {  // world space: an unlit mesh through the camera
    Mesh mesh;
    for (std::size_t k = 0; k < s.coords.size(); k += 3)
      mesh.positions.push_back({s.coords[k], s.coords[k + 1], s.coords[k + 2]});
    mesh.colors = s.colors;
    mesh.shading = Shading::unlit;
    const auto m = static_cast<std::uint32_t>(n);
    if (p.kind == PrimitiveKind::triangle && p.fill) {
      mesh.triangles.push_back({0, 1, 2});
    } else {
      for (std::uint32_t i = 0; i + 1 < m; ++i) mesh.segments.push_back({i, i + 1});
      if ((p.closed || p.kind == PrimitiveKind::triangle) && m >= 3) mesh.segments.push_back({m - 1, 0});
    }
    p.kind = PrimitiveKind::mesh;
    p.mesh = static_cast<std::uint32_t>(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));
    scene.primitives.push_back(p);
    return;
  }
  p.first_point = static_cast<std::uint32_t>(s.first_point);
  p.point_count = static_cast<std::uint32_t>(n);
  p.first_color = static_cast<std::uint32_t>(scene.colors.size());
  p.per_vertex_color = per_vertex;
  for (const Rgba8 c : s.colors) scene.colors.push_back(c);
  scene.primitives.push_back(p);
}

void Reader::finish_mesh(PrimitiveState& s, const Path& at) {
  Mesh& mesh = s.mesh;
  if (!(s.seen & bit("positions"))) invalid(at, "a mesh needs \"positions\"");
  if (!(s.seen & bit("indices"))) invalid(at, "a mesh needs \"indices\" (triangles as [a, b, c], 0-based)");
  const std::size_t n = mesh.positions.size();
  // Indices come before or after the positions they index: checked now that both are read.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t j = 0; j < 3; ++j) {
      const std::uint32_t i = mesh.triangles[t][j];
      if (i < n) continue;
      const Path indices(at, "indices", s.indices_byte), triangle(indices, t, s.indices_byte);
      invalid(s.indices_nested ? Path(triangle, j, s.indices_byte) : Path(indices, 3 * t + j, s.indices_byte),
              "index " + (i == UINT32_MAX ? s.bad_index : std::to_string(i)) + " is outside the " +
                  std::to_string(n) + " positions (0-based)");
    }
  if ((s.seen & bit("color")) && (s.seen & bit("colors")))
    invalid(at, "give either \"color\" (flat) or \"colors\" (one per point), not both");
  if ((s.seen & bit("colors")) && s.colors.size() != n)
    invalid(Path(at, "colors", s.colors_byte),
            "\"colors\" needs one colour per point (" + std::to_string(n) + ")");
  mesh.colors = (s.seen & bit("colors")) ? std::move(s.colors)
                                         : std::vector<Rgba8>{(s.seen & bit("color")) ? s.color : kMeshGrey};
  if (s.seen & bit("normals")) {
    if (mesh.normals.size() != n)
      invalid(Path(at, "normals", s.normals_byte),
              "\"normals\" needs one normal per position (" + std::to_string(n) + ")");
    mesh.normal_triangles = mesh.triangles;
  }
  const bool uvs = s.seen & bit("uvs"), texture = s.seen & bit("texture");
  if (uvs != texture)
    invalid(at, uvs ? "\"uvs\" are used with a \"texture\"; give both"
                    : "a \"texture\" needs \"uvs\" (one [u, v] per position)");
  if (uvs) {
    if (mesh.uvs.size() != n)
      invalid(Path(at, "uvs", s.uvs_byte), "\"uvs\" needs one [u, v] per position (" + std::to_string(n) +
                                               "), got " + std::to_string(mesh.uvs.size()));
    mesh.uv_triangles = mesh.triangles;
  }
}

void Reader::finish_obj(PrimitiveState& s, const Path& at) {
  auto text_of = [&](std::uint32_t inline_bit, std::uint32_t source_bit, const std::string& text,
                     std::string_view name) -> std::string_view {
    const std::string_view inline_key = kPrimitiveFields[std::countr_zero(inline_bit)].key,
                           source_key = kPrimitiveFields[std::countr_zero(source_bit)].key;
    if ((s.seen & inline_bit) && (s.seen & source_bit))
      invalid(at, "give either \"" + std::string(inline_key) + "\" or \"" + std::string(source_key) +
                      "\", not both");
    if (s.seen & inline_bit) return text;
    if (!(s.seen & source_bit)) return {};
    const auto part = uploads.find(name);
    if (part == uploads.end())
      invalid(Path(at, source_key, s.byte), "no uploaded part named \"" + std::string(name) +
                                                "\" (send it as a multipart part of that name)");
    return part->second;
  };
  const std::string_view obj = text_of(bit("data"), bit("source"), s.obj, s.source);
  const std::string_view type = kTypes[s.type].name;
  if (!(s.seen & (bit("data") | bit("source"))))
    invalid(at, "a" + std::string(type == "obj" ? "n " : " ") + std::string(type) + " needs \"data\" (" +
                    (type == "obj" ? "OBJ text" : "the model's text") +
                    ") or \"source\" (the name of an uploaded part)");
  std::string_view mtl = text_of(bit("mtl"), bit("mtl_source"), s.mtl, s.mtl_source);
  // An MTL uploaded as part "mtl" goes with a model taken from the uploads.
  if (mtl.empty() && (s.seen & bit("source")) && !(s.seen & bit("mtl_source")))
    if (const auto part = uploads.find("mtl"); part != uploads.end()) mtl = part->second;
  Limits model_limits = limits;
  model_limits.max_texture_pixels = texels_left(scene, limits);
  Mesh mesh;
  try {
    // Bytes that do not tell their format: "format", else the uploaded part's file name (a scene's
    // "source": "part.stl"), as for a model sent alone.
    std::optional<ModelFormat> hint = type == "obj" ? ModelFormat::obj : s.format;
    if (!hint && (s.seen & bit("source"))) hint = format_of_file_name(s.source);
    mesh = parse_model(obj, hint, model_limits, (s.seen & bit("textures")) ? s.textures : uploads, mtl);
  } catch (const SceneError& e) {
    // An encoding error keeps its byte: the offset into the model's own text, which the message names.
    std::string message = e.what();
    if (e.where().line)
      message += " (line " + std::to_string(e.where().line) + ")";
    else if (e.where().byte && e.kind() != ErrorKind::encoding)  // a binary model's place in its own bytes
      message += " (byte " + std::to_string(e.where().byte) + " of the model)";
    throw SceneError(e.kind(), message,
                     ErrorLocation{at.str(), e.kind() == ErrorKind::encoding ? e.where().byte : at.byte(),
                                   e.where().line});
  }
  if (s.seen & bit("color")) {  // an explicit colour wins over the model's own
    mesh.colors = {s.color};
    mesh.face_colors.clear();
  } else if (mesh.colors.empty()) {
    mesh.colors = {kMeshGrey};
  }
  if (s.seen & bit("shading")) mesh.shading = s.mesh.shading;
  if (s.seen & bit("cull")) mesh.cull = s.mesh.cull;
  if (s.seen & bit("wireframe")) mesh.wireframe = s.mesh.wireframe;
  if (s.seen & bit("edges")) mesh.edges = s.mesh.edges;
  if (s.seen & bit("transform")) mesh.transform = s.mesh.transform;
  s.mesh = std::move(mesh);
}

// The type decides what else a primitive may hold, so a wrong or missing "type" is the error to report,
// wherever it stands in the object. Only after an error: the object is read again from its start.
void Reader::type_first(JsonCursor::Mark start, const Path& at) {
  JsonCursor look = in.from(start);
  try {
    if (look.peek() != Kind::object) return;
    for (bool more = look.object_begin(); more; more = look.object_next()) {
      if (look.key() != "type") {
        look.skip();
        continue;
      }
      const Kind k = look.peek();
      const Path type(at, "type", look.offset());
      if (k != Kind::string) invalid(type, std::string("expected a string, got ") + phrase(k));
      PrimitiveState probe;
      return set_type(probe, look.string(), type);
    }
  } catch (const SceneError& e) {
    if (e.kind() == ErrorKind::syntax) return;  // malformed: parse_scene reports that
    throw;
  }
  invalid(at, std::string("missing \"type\" (") + kTypeNames + ")");
}

void Reader::primitive(const Path& at) {
  PrimitiveState& s = prim;
  s.reset();
  s.byte = at.byte();
  const JsonCursor::Mark start = in.mark();
  try {
    read_object(kPrimitiveFields, s, at, "a primitive object");
  } catch (const SceneError&) {
    if (s.type < 0) type_first(start, at);  // a key before "type" was wrong: is "type" itself?
    throw;
  }
  if (s.type < 0) invalid(at, std::string("missing \"type\" (") + kTypeNames + ")");
  if (kTypes[s.type].kind != PrimitiveKind::mesh) return finish_drawn(s, at);
  s.seen_model = true;
  if (kTypes[s.type].name == "mesh")
    finish_mesh(s, at);
  else
    finish_obj(s, at);
  Primitive p;
  p.kind = PrimitiveKind::mesh;
  p.mesh = static_cast<std::uint32_t>(scene.meshes.size());
  scene.meshes.push_back(std::move(s.mesh));
  s.mesh = Mesh{};
  scene.primitives.push_back(p);
}

constexpr Field<CameraState> kCameraFields[] = {
    {"projection", format::kString, "\"perspective\" or \"orthographic\"",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.projection = static_cast<Projection>(
           r.choice(at, std::array<std::string_view, 2>{"perspective", "orthographic"}));
     }},
    {"view", format::kString, "a view name",
     [](Reader& r, CameraState& c, const Path& at) {
       static constexpr std::array<std::string_view, 7> kViews{"front", "back",   "left", "right",
                                                               "top",   "bottom", "iso"};
       c.camera.view = static_cast<View>(r.choice(at, kViews)), c.camera.has_view = true;
     }},
    {"eye", format::kArray, "a point [x, y, z]",
     [](Reader& r, CameraState& c, const Path& at) { c.camera.eye = r.vec3(at), c.camera.has_eye = true; }},
    {"target", format::kArray, "a point [x, y, z]",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.target = r.vec3(at), c.camera.has_target = true;
     }},
    {"up", format::kArray, "a direction [x, y, z]",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.up = r.vec3(at), c.camera.has_up = true;
       if (c.camera.up == Vec3{}) r.invalid(at, "\"up\" must not be the zero vector");
     }},
    {"fov", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) { c.camera.fov_deg = r.ranged(at, format::kFov); }},
    {"near", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.near = r.ranged(at, format::kNear), c.camera.has_near = true;
     }},
    {"far", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.far = r.ranged(at, format::kFar), c.camera.has_far = true;
     }},
    {"height", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.height = r.ranged(at, format::kViewHeight), c.camera.has_height = true;
     }},
};

Vec3 direction(Reader& r, const Path& at) {
  const Vec3 d = r.vec3(at);
  if (d == Vec3{}) r.invalid(at, "the light direction must not be the zero vector");
  return d;
}

// "light": rasterd 0.1's one directional light plus ambient.
constexpr Field<LightState> kLightFields[] = {
    {"direction", format::kArray, "a direction [x, y, z]",
     [](Reader& r, LightState& l, const Path& at) { l.direction = direction(r, at), l.directed = true; }},
    {"ambient", format::kNumber, "a number",
     [](Reader& r, LightState& l, const Path& at) { l.ambient = r.ranged(at, format::kAmbient); }},
};

std::uint32_t light_keys(LightKind kind);

// One of "lights"; its "type" narrows the keys (light_keys).
constexpr Field<LightsEntry> kLightsFields[] = {
    {"type", format::kString, "\"ambient\", \"directional\" or \"point\"",
     [](Reader& r, LightsEntry& l, const Path& at) {
       l.light.kind = static_cast<LightKind>(
           r.choice(at, std::array<std::string_view, 3>{"ambient", "directional", "point"}));
       l.allowed = light_keys(l.light.kind), l.typed = true;
     }},
    {"color", format::kString | format::kArray, "a colour",
     [](Reader& r, LightsEntry& l, const Path& at) {
       const Rgba8 c = r.color(at);
       if (c.a != 255) r.invalid(at, "a light's colour is opaque (it has no alpha)");
       l.light.color = {c.r / 255.0, c.g / 255.0, c.b / 255.0};
     }},
    {"space", format::kString, "\"world\" or \"camera\"",
     [](Reader& r, LightsEntry& l, const Path& at) {
       l.light.camera_space = r.choice(at, std::array<std::string_view, 2>{"world", "camera"}) == 1;
     }},
    {"direction", format::kArray, "a direction [x, y, z]",
     [](Reader& r, LightsEntry& l, const Path& at) { l.light.direction = direction(r, at); }},
    {"intensity", format::kNumber, "a number",
     [](Reader& r, LightsEntry& l, const Path& at) { l.light.intensity = r.ranged(at, format::kIntensity); }},
    {"position", format::kArray, "a point [x, y, z]",
     [](Reader& r, LightsEntry& l, const Path& at) { l.light.position = r.vec3(at); }},
};

std::uint32_t light_keys(LightKind kind) {
  constexpr std::uint32_t kAll = format::mask_of(kLightsFields, {"type", "color", "intensity"});
  if (kind == LightKind::ambient) return kAll;
  return kAll |
         format::mask_of(kLightsFields, {kind == LightKind::point ? "position" : "direction", "space"});
}

void Reader::lights(const Path& at) {
  std::size_t k = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++k) {
    const Path entry = element(at, k);
    if (k == kMaxLights) invalid(at, "at most " + std::to_string(kMaxLights) + " lights");
    LightsEntry l;
    read_object(kLightsFields, l, entry, "a light object");
    if (!l.typed) invalid(entry, "missing \"type\": \"ambient\", \"directional\" or \"point\"");
    if (l.light.kind == LightKind::point && !(l.seen & format::mask_of(kLightsFields, {"position"})))
      invalid(entry, "a point light needs \"position\": [x, y, z]");
    scene.lights.push_back(l.light);
  }
  if (k == 0) invalid(at, "an empty list of lights; leave \"lights\" out for the default ones");
}

void Reader::primitives(const Path& at) {
  std::size_t i = 0;
  const JsonCursor::Mark start = in.mark();
  const std::string over = "more primitives than the limit of " + std::to_string(limits.max_primitives);
  for (bool more = in.array_begin(); more; more = in.array_next(), ++i) {
    const Path p = element(at, i);
    if (static_cast<std::int64_t>(i) >= limits.max_primitives) fail(ErrorKind::limit, at, over);
    if ((i + 1) % detail::kLinesPerCheck == 0) detail::stop_if_expired(limits);
    try {
      primitive(p);
    } catch (const SceneError& e) {
      if (e.kind() == ErrorKind::syntax) throw;
      // Too many primitives is the error to report, before what is wrong in one of them: count them.
      JsonCursor look = in.from(start);
      try {
        std::int64_t n = 0;
        for (bool more = look.array_begin(); more && n <= limits.max_primitives; more = look.array_next())
          look.skip(), ++n;
        if (n > limits.max_primitives) fail(ErrorKind::limit, at, over);
      } catch (const SceneError& count) {
        if (count.kind() != ErrorKind::syntax) throw;
      }
      throw;
    }
  }
}

// The image's side: a whole number in 1..the limit.
int side(Reader& r, const Path& at, std::string_view key, int max_side) {
  const std::int64_t v = r.integer(at);
  const std::string quoted = "\"" + std::string(key) + "\" ";
  if (v < 1) r.invalid(at, quoted + "must be at least 1, got " + r.number_text());
  const int cap = std::min(max_side, kMaxImageSide);
  if (v > cap)
    r.fail(ErrorKind::limit, at, quoted + r.number_text() + " exceeds the limit of " + std::to_string(cap));
  return static_cast<int>(v);
}

constexpr Field<Keys> kRootFields[] = {
    {"primitives", format::kArray, "an array", [](Reader& r, Keys&, const Path& at) { r.primitives(at); }},
    {"width", format::kNumber, "a number",
     [](Reader& r, Keys&, const Path& at) { r.scene.width = side(r, at, "width", r.limits.max_width); }},
    {"height", format::kNumber, "a number",
     [](Reader& r, Keys&, const Path& at) { r.scene.height = side(r, at, "height", r.limits.max_height); }},
    {"background", format::kString | format::kArray, "a colour (\"#rrggbb\" or [r, g, b])",
     [](Reader& r, Keys&, const Path& at) { r.scene.background = r.color(at); }},
    {"antialias", format::kString | format::kNumber, "\"area\" or a number",
     [](Reader& r, Keys&, const Path& at) {
       const std::string rule = "\"antialias\" is \"area\" or the samples per pixel: 1, 4, 8 or 16; got ";
       if (r.in.peek() == Kind::string) {
         const std::string_view s = r.in.string();
         if (s != "area") r.invalid(at, rule + "\"" + std::string(s) + "\"");
         return void(r.scene.area = true);
       }
       const std::int64_t n = r.integer(at);
       if (n != 1 && n != 4 && n != 8 && n != 16) r.invalid(at, rule + r.number_text());
       r.scene.samples = static_cast<int>(n);
     }},
    {"camera", format::kObject, "a camera object",
     [](Reader& r, Keys&, const Path& at) {
       CameraState c;
       r.read_object(kCameraFields, c, at, "a camera object");
       if (c.camera.has_view && c.camera.has_eye)
         r.invalid(Path(at, "view", at.byte()),
                   "\"view\" and \"eye\" both place the camera: give one of them");
       if (c.camera.has_near && c.camera.has_far && !(c.camera.near < c.camera.far))
         r.invalid(Path(at, "far", at.byte()), "\"far\" must be greater than \"near\"");
       r.scene.camera = c.camera;
     }},
    {"light", format::kObject, "a light object",
     [](Reader& r, Keys&, const Path& at) {
       LightState l;
       r.read_object(kLightFields, l, at, "a light object");
       r.scene.lights = single_light(l.ambient, l.directed ? &l.direction : nullptr);
     }},
    {"lights", format::kArray, "an array of lights", [](Reader& r, Keys&, const Path& at) { r.lights(at); }},
    // What editors and JSON Schema give a document: the schema it follows, and a note. Neither draws.
    {"$schema", format::kString, "a string", [](Reader& r, Keys&, const Path&) { r.in.string(); }},
    {"$comment", format::kString, "a string", [](Reader& r, Keys&, const Path&) { r.in.string(); }},
};

void Reader::read_root() {
  const Path root;
  Keys keys;
  if (const Kind k = in.peek(); k != Kind::object)
    invalid(root, std::string("a scene is a JSON object, got ") + phrase(k));
  read_object(kRootFields, keys, root, "a scene object");
  in.finish();
  for (const char* key : {"width", "height"})
    if (!(keys.seen & format::mask_of(kRootFields, {key})))
      invalid(root, std::string("missing \"") + key + "\" (image size in pixels)");
  if (const std::int64_t pixels = std::int64_t{scene.width} * scene.height; pixels > limits.max_pixels)
    fail(ErrorKind::limit, root,
         std::to_string(scene.width) + "x" + std::to_string(scene.height) + " is " + std::to_string(pixels) +
             " pixels, over the limit of " + std::to_string(limits.max_pixels));
  if ((keys.seen & format::mask_of(kRootFields, {"light"})) &&
      (keys.seen & format::mask_of(kRootFields, {"lights"})))
    invalid(Path(root, "lights", 1), "\"light\" (one light) and \"lights\" (a list) exclude each other");
}

}  // namespace

Scene parse_scene(std::string_view text, const Limits& limits, const Uploads& uploads) {
  if (text.empty())
    throw SceneError(ErrorKind::syntax, "the scene is empty (0 bytes); expected a JSON object");
  // What the parsed primitives hold is bounded by the text's size; a model a primitive names is asked for
  // by its reader once counted.
  detail::reserve(limits, cost::kScenePerByte * static_cast<std::int64_t>(text.size()),
                  [&] { return "the scene's " + std::to_string(text.size()) + " bytes"; });
  Reader r{JsonCursor(text, limits.max_json_depth), limits, uploads, {}, {}};
  r.reserve(text);
  try {
    r.read_root();  // checks the UTF-8 of every string it reads, so a scene read to the end is UTF-8
  } catch (const SceneError& e) {
    // JSON text is UTF-8 (RFC 8259 8.1): a byte that is not is the first thing to report, wherever it is.
    require_utf8(text, "the scene");
    if (e.kind() == ErrorKind::syntax) throw;
    // Then syntax: a document that is not well-formed is reported as such, whatever else is wrong in it.
    JsonCursor whole(text, limits.max_json_depth);
    whole.skip();
    whole.finish();
    throw;
  }
  validate(r.scene);  // the checks across fields, shared with scenes built in code
  return std::move(r.scene);
}

}  // namespace raster
