// The scene reader's insides, shared by its three files: the state of each object kind while it is read,
// the Reader (a JsonCursor over the text, the limits, the Scene being built) with its readers of numbers,
// and read_object(), the one loop every object of the format goes through.
//
// Each object kind of format v1 (the root, a primitive, a camera, a light, a transform, edges, a texture)
// is a table of fields: a key, the JSON kinds its value may be, and the function that reads it where it
// stands in the text. read_object() walks an object with its table; that one loop owns unknown keys (with
// a "did you mean"), keys given twice and values of the wrong kind. A primitive's table is the union of
// every type's keys, and its "type" narrows the keys allowed. Checks across fields (a colour per point,
// indices within the positions) run when the object ends. Defaults are those of the Scene's structs.
//
//   scene_reader.cpp   the document: the root's and a primitive's tables, what each primitive type makes
//   scene_objects.cpp  objects read whole into one value: camera, light(s), transform, edges, texture
//   scene_values.cpp   values: colours, points, number lists, indices, base64 images
//
// Every error is a SceneError with the JSON pointer and the 1-based byte offset of the value it is about.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/json_cursor.h"
#include "raster/model.h"
#include "raster/scene.h"
#include "scene/scene_format.h"

namespace raster::scene_reader {

using Kind = JsonCursor::Kind;
using Path = JsonPointer;
using format::Range;

inline const char* phrase(Kind k) {
  static constexpr const char* kPhrases[] = {"null",     "a boolean", "a number",
                                             "a string", "an array",  "an object"};
  return kPhrases[static_cast<int>(k)];
}

// Keys are a few bytes: compared inline, not through a call to memcmp.
inline bool same_key(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return false;
  return true;
}

// Edits (insertions, deletions, substitutions) from a to b: how an unknown key is matched to a known one.
std::size_t edit_distance(std::string_view a, std::string_view b);

// Texels the scene's textures hold so far: what is left of the limit is what the next one may take.
inline std::int64_t texels_left(const Scene& scene, const Limits& limits) {
  std::int64_t used = 0;
  for (const Mesh& m : scene.meshes)
    for (const Texture& t : m.textures) used += std::int64_t{t.width} * t.height;
  for (const ShaderPrimitive& p : scene.shaders)
    for (const Texture& t : p.textures) used += std::int64_t{t.width} * t.height;
  return limits.max_texture_pixels - used;
}

// The state of each object kind while it is read. `allowed` and `seen` are bits of its table's fields.
struct Keys {
  std::uint64_t allowed = ~std::uint64_t{0}, seen = 0;
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
  int type = -1;  // index into kTypes (scene_reader.cpp); -1 until "type" is read
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
  ShaderPrimitive shader;             // a shader's values ("source" is `source`)
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
    if (seen_shader) shader = ShaderPrimitive{}, source.clear(), seen_shader = false;
  }
  bool seen_shader = false;  // the last primitive was a shader
  bool seen_model = false;   // the last primitive was a mesh or a model
};

struct Reader;
template <class T>
using Field = format::Field<void (*)(Reader&, T&, const Path&)>;

// The reader of one document: the cursor in its text, what it is allowed, and the scene it builds.
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
    if (!r.contains(d)) invalid(where(in.number_offset()), format::out_of_range(r, in.number_text()));
    return d;
  }
  template <class Where>
  double coordinate(const Where& where) {
    const double d = number(where);
    if (std::fabs(d) > kMaxCoordinate)
      invalid(where(in.number_offset()), format::outside_coordinates(in.number_text()));
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
    const std::string expected = format::expected_one_of(names);
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
  [[noreturn]] void unknown_key(const F (&fields)[N], std::uint64_t allowed, std::string_view key,
                                const Path& at);

  // Values (scene_values.cpp): each reads the value at the cursor, `at` its pointer for errors.
  Rgba8 color(const Path& at);
  void colors(PrimitiveState& s, const Path& at);
  Vec3 vec3(const Path& at);
  void points(PrimitiveState& s, const Path& at);
  template <std::size_t N, class Number, class Add>
  bool tuples(const Path& at, const char* shape, const char* names, Number number, Add add);
  void vec3_list(std::vector<Vec3f>& out, const Path& at);  // held as floats (Vec3f)
  void indices(PrimitiveState& s, const Path& at);
  void uvs(PrimitiveState& s, const Path& at);
  std::string base64(const Path& at);
  // Objects read whole into one value, each with its own table (scene_objects.cpp).
  Camera camera(const Path& at);
  std::vector<Light> light(const Path& at);
  void lights(const Path& at);
  Mat4 transform(const Path& at);
  Edges edges(const Path& at);
  Texture texture(const Path& at, std::int64_t pending = 0);
  // A shader primitive's values (scene_shader.cpp).
  std::array<double, 4> four_numbers(const Path& at, const char* what, bool two_allowed);
  void channels(PrimitiveState& s, const Path& at);
  void uniforms(PrimitiveState& s, const Path& at);
  void rect(PrimitiveState& s, const Path& at);
  void finish_shader(PrimitiveState& s, const Path& at);
  // The document and its primitives (scene_reader.cpp).
  void primitives(const Path& at);
  void primitive(const Path& at);
  void set_type(PrimitiveState& s, std::string_view name, const Path& at);
  void type_first(JsonCursor::Mark start, const Path& at);
  void finish_drawn(PrimitiveState& s, const Path& at);
  void finish_mesh(PrimitiveState& s, const Path& at);
  void finish_model(PrimitiveState& s, const Path& at);
  void read_root();
};

template <class F, std::size_t N>
void Reader::unknown_key(const F (&fields)[N], std::uint64_t allowed, std::string_view key, const Path& at) {
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
  static_assert(N <= 64, "`allowed` and `seen` hold a bit per field");
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
    state.seen |= std::uint64_t{1} << i;
    if (!(fields[i].kinds >> static_cast<int>(kind) & 1)) wrong_kind(field, kind, fields[i].expected);
    fields[i].read(*this, state, field);
    if (const std::uint64_t early =
            state.seen & ~state.allowed) {  // read before a "type" that does not take it
      const std::string_view k = fields[std::countr_zero(early)].key;
      unknown_key(fields, state.allowed, k, Path(at, k, field.byte()));
    }
  }
}

}  // namespace raster::scene_reader
