// The scene reader against the oracle (tests/oracle: rasterd 0.2's DOM reader, which defined the format):
// on every document both accept or both reject, an accepted document is read into the same scene bit for
// bit, and a malformed one is malformed to both. Documents are generated from a seed and then mutated
// byte by byte.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle/scene_dom.h"
#include "raster/scene.h"
#include "raster/utf8.h"

namespace {

using raster::Scene;
using raster::SceneError;

// The verdict of one reader: a scene, or the kind of error.
struct Verdict {
  std::optional<Scene> scene;
  raster::ErrorKind kind = raster::ErrorKind::invalid;
};

template <class Parse>
Verdict verdict_of(Parse parse) {
  try {
    return {parse(), {}};
  } catch (const SceneError& e) {
    return {std::nullopt, e.kind()};
  }
}
Verdict oracle(const std::string& text, const raster::Limits& limits = {}) {
  return verdict_of([&] { return raster::scene_json::parse_scene_oracle(text, limits); });
}
Verdict reader(const std::string& text, const raster::Limits& limits = {}) {
  return verdict_of([&] { return raster::parse_scene(text, limits); });
}

// Scene equality with coordinates compared bit for bit: == holds -0.0 equal to 0.0.
bool same(const Scene& a, const Scene& b) {
  if (!(a == b)) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (std::bit_cast<std::uint64_t>(a.points[i].x) != std::bit_cast<std::uint64_t>(b.points[i].x) ||
        std::bit_cast<std::uint64_t>(a.points[i].y) != std::bit_cast<std::uint64_t>(b.points[i].y))
      return false;
  return true;
}

// A random scene document in random layout.
class DocumentGenerator {
 public:
  explicit DocumentGenerator(std::uint32_t seed) : rng_(seed) {}

  std::string document() {
    std::vector<std::string> fields = {member("width", integer(1, 300)), member("height", integer(1, 300))};
    if (chance(0.3)) fields.push_back(member("background", color()));
    if (chance(0.2)) fields.push_back(member("antialias", pick({"1", "4", "8.0", "16"})));
    if (chance(0.2))
      fields.push_back(member("camera", object({member("eye", vec3()), member("fov", integer(10, 90))})));
    if (chance(0.2)) fields.push_back(member("light", object({member("ambient", "0.25")})));
    std::vector<std::string> primitives;
    const int n = integer_value(0, 12);
    for (int i = 0; i < n; ++i) primitives.push_back(primitive());
    fields.push_back(member("primitives", array(primitives)));
    return space() + object(fields) + space();
  }

 private:
  std::string primitive() {
    std::vector<std::string> fields;
    const int kind = integer_value(0, 5);
    if (kind == 5) return shader();
    if (kind == 4 && chance(0.5)) {  // an OBJ model
      fields = {member("type", "\"obj\""), member("data", "\"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n\"")};
    } else if (kind == 4) {  // a model in another format, named or told by its text
      fields = {member("type", "\"model\""),
                member("data",
                       "\"solid s\\nfacet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 "
                       "0 endloop endfacet\\nendsolid\\n\"")};
      if (chance(0.5)) fields.push_back(member("format", "\"stl\""));
    } else if (kind == 3) {  // a mesh
      const int positions = integer_value(3, 6);
      std::vector<std::string> p, idx;
      const bool flat = chance(0.5);
      for (int k = 0; k < positions; ++k)
        p.push_back(flat ? coordinate() + "," + coordinate() + "," + coordinate() : vec3());
      for (int k = 0; k < integer_value(0, 4); ++k) {
        const std::string a = std::to_string(integer_value(0, positions - 1)),
                          b = std::to_string(integer_value(0, positions - 1)),
                          c = std::to_string(integer_value(0, positions - 1));
        idx.push_back(flat ? a + "," + b + "," + c : array({a, b, c}));
      }
      fields = {member("type", "\"mesh\""), member("positions", array(p)), member("indices", array(idx))};
      if (chance(0.3))
        fields.push_back(member("normals", array(std::vector<std::string>(positions, "[0,0,1]"))));
      if (chance(0.3)) fields.push_back(member("color", color()));
      if (chance(0.3)) fields.push_back(member("shading", pick({"\"flat\"", "\"smooth\"", "\"unlit\""})));
      if (chance(0.2)) fields.push_back(member("cull", "\"back\""));
      if (chance(0.2)) fields.push_back(member("wireframe", "true"));
      if (chance(0.2)) fields.push_back(member("transform", object({member("rotate", "[0, 90, 0]")})));
    } else {
      const char* type = kind == 0 ? "triangle" : kind == 1 ? "line" : "polyline";
      const int n = kind == 0 ? 3 : kind == 1 ? 2 : integer_value(2, 5);
      const bool world = chance(0.15);
      std::vector<std::string> points;
      for (int k = 0; k < n; ++k) points.push_back(world ? vec3() : array({coordinate(), coordinate()}));
      fields = {member(chance(0.05) ? "\\u0074ype" : "type", std::string("\"") + type + "\""),
                member("points", array(points))};
      const double colours = uniform();
      if (colours < 0.4) {
        std::vector<std::string> list;
        const bool as_arrays = chance(0.1);
        for (int k = 0; k < n; ++k) list.push_back(as_arrays ? "[0.5, 0, 1]" : hex_color());
        fields.push_back(member("colors", array(list)));
      } else if (colours < 0.8) {
        fields.push_back(member("color", color()));
      }
      if (kind == 0 && chance(0.3)) fields.push_back(member("fill", pick({"true", "false"})));
      if (kind == 2 && chance(0.3)) fields.push_back(member("closed", pick({"true", "false"})));
      if (chance(0.2)) fields.push_back(member("width", pick({"1", "2.5", "0.5", "4096"})));
    }
    std::shuffle(fields.begin(), fields.end(), rng_);
    return object(fields);
  }

  // A shader primitive with some of its fields (the program is not compiled by the readers).
  std::string shader() {
    std::vector<std::string> fields = {
        member("type", "\"shader\""),
        member("source",
               pick({R"("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }")",
                     R"("uniform float k;\nvoid mainImage(out vec4 c, in vec2 p) {\n  c = vec4(k);\n}\n")",
                     R"("\u0076oid mainImage(out vec4 c, in vec2 p) {}")", R"("")"}))};
    if (chance(0.3)) fields.push_back(member("time", pick({"0", "1.5", "-2", "1e9", "123456.789", "-0"})));
    if (chance(0.3)) fields.push_back(member("frame", pick({"0", "7", "60.0", "2147483647"})));
    if (chance(0.3))
      fields.push_back(member("mouse", chance(0.5) ? array({integer(-50, 300), "12.25"})
                                                   : array({integer(0, 300), integer(0, 300), "0", "-1"})));
    if (chance(0.2)) fields.push_back(member("date", array({"2026", "11", "3", "45296.5"})));
    if (chance(0.2)) {
      std::vector<std::string> channels;
      for (int k = integer_value(0, 4); k > 0; --k)
        channels.push_back(chance(0.4) ? "null" : object({member("data", std::string("\"") + kPng + "\"")}));
      fields.push_back(member("channels", array(channels)));
    }
    if (chance(0.3)) {
      std::vector<std::string> uniforms;
      if (chance(0.7)) uniforms.push_back(member("k", pick({"0.5", "true", "[1, 2]", "[[1, 0], [0, 1]]"})));
      if (chance(0.5)) uniforms.push_back(member("tint_2", array({"0.25", "false", coordinate()})));
      fields.push_back(member("uniforms", object(uniforms)));
    }
    if (chance(0.3))
      fields.push_back(member("rect", array({integer(-20, 40), integer(-20, 40), integer(1, 64), "4.0"})));
    if (chance(0.2)) fields.push_back(member("opaque", pick({"true", "false"})));
    std::shuffle(fields.begin(), fields.end(), rng_);
    return object(fields);
  }

  // A 1x1 RGBA PNG: a channel's image.
  static constexpr const char* kPng =
      "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==";

  std::string coordinate() {
    switch (integer_value(0, 7)) {
      case 0:
        return std::to_string(integer_value(-50, 300));
      case 1:
        return pick({"-0", "-0.0", "0", "0.0", "0e0", "-0E-0"});
      case 2:
        return std::to_string(integer_value(-50, 300)) + "." + std::to_string(integer_value(0, 999999));
      case 3:
        return pick({"1e2", "1.5E+2", "25e-1", "-3.25e1", "1e-300", "3.4e38", "-3.4e38", "1e-320"});
      case 4:
        return pick({"9007199254740993", "18446744073709551615", "18446744073709551616",
                     "123456789012345678901234567890", "0.1000000000000000055511151231257827",
                     "100.00000000000000000000000000001", "0.30000000000000004"});
      default: {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.*f", integer_value(0, 6), uniform() * 300 - 20);
        return buffer;
      }
    }
  }
  std::string vec3() { return array({coordinate(), coordinate(), coordinate()}); }
  std::string hex_color() {
    static const char* digits = "0123456789abcdefABCDEF";
    const int length = pick_value<int>({3, 4, 6, 8});
    std::string s = "\"#";
    for (int k = 0; k < length; ++k) s += digits[integer_value(0, 21)];
    return s + "\"";
  }
  std::string color() { return chance(0.8) ? hex_color() : pick({"[1, 0.5, 0]", "[0, 0, 0, 0.5]"}); }

  std::string space() { return pick({"", "", " ", "\n", "\t", "\r\n  "}); }
  std::string member(const std::string& key, const std::string& value) {
    return space() + "\"" + key + "\"" + space() + ":" + space() + value + space();
  }
  std::string object(const std::vector<std::string>& members) { return wrap('{', join(members), '}'); }
  std::string array(const std::vector<std::string>& values) {
    std::vector<std::string> spaced;
    for (const auto& v : values) spaced.push_back(space() + v + space());
    return wrap('[', join(spaced), ']');
  }
  // Appending (not operator+ on literals, where GCC 12 warns falsely with -Wrestrict).
  static std::string wrap(char open, const std::string& inside, char close) {
    std::string out(1, open);
    out += inside;
    out += close;
    return out;
  }
  static std::string join(const std::vector<std::string>& parts) {
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (i) out += ',';
      out += parts[i];
    }
    return out;
  }

  bool chance(double p) { return uniform() < p; }
  double uniform() { return std::uniform_real_distribution<double>(0, 1)(rng_); }
  int integer_value(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  std::string integer(int lo, int hi) { return std::to_string(integer_value(lo, hi)); }
  std::string pick(std::initializer_list<const char*> options) { return pick_value(options); }
  template <class T>
  T pick_value(std::initializer_list<T> options) {
    return options.begin()[integer_value(0, static_cast<int>(options.size()) - 1)];
  }

  std::mt19937 rng_;
};

TEST(SceneReader, ReadsGeneratedScenesExactlyAsTheOracle) {
  DocumentGenerator generator(20261121);
  std::size_t primitives = 0;
  for (int i = 0; i < 2000; ++i) {
    const std::string text = generator.document();
    const Verdict expected = oracle(text), got = reader(text);
    ASSERT_TRUE(expected.scene.has_value()) << "the generator wrote a document the oracle rejects: " << text;
    ASSERT_TRUE(got.scene.has_value()) << text;
    ASSERT_TRUE(same(*got.scene, *expected.scene)) << text;
    primitives += got.scene->primitives.size();
  }
  EXPECT_GT(primitives, 5000u);
}

TEST(SceneReader, AcceptsAndRejectsWhatTheOracleDoesAndMalformedIsMalformedToBoth) {
  DocumentGenerator generator(7);
  std::mt19937 rng(11);
  std::string alphabet = "{}[],:\"0123456789-+.eE \\#aftnul\x01\xc3";
  alphabet.push_back('\0');  // nlohmann reads a NUL byte as the end of its input
  int accepted = 0, rejected = 0, malformed = 0;
  for (int i = 0; i < 1500; ++i) {
    std::string text = generator.document();
    for (int m = std::uniform_int_distribution<int>(1, 3)(rng); m > 0 && !text.empty(); --m) {
      const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
      const char c = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
      switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
        case 0:
          text.erase(at, 1);
          break;
        case 1:
          text.insert(at, 1, c);
          break;
        default:
          text[at] = c;
      }
    }
    const Verdict got = reader(text);
    if (text.find('\0') != std::string::npos) {  // JSON has none; nlohmann takes one for the end of its input
      ASSERT_FALSE(got.scene.has_value()) << text;
      ASSERT_TRUE(got.kind == raster::ErrorKind::syntax || got.kind == raster::ErrorKind::encoding) << text;
      ++rejected, ++malformed;
      continue;
    }
    const Verdict expected = oracle(text);
    ASSERT_EQ(got.scene.has_value(), expected.scene.has_value()) << text;
    if (got.scene) {
      ASSERT_TRUE(same(*got.scene, *expected.scene)) << "read differently: " << text;
      ++accepted;
      continue;
    }
    ++rejected;
    // Syntax first: whatever else is wrong, a malformed document is reported as malformed. (The oracle
    // reports a key given twice while it parses, before a syntax error further on: JSON itself decides.)
    const bool json = nlohmann::json::accept(text);
    const bool syntax = !json && raster::first_invalid_utf8(text) == std::string::npos;
    ASSERT_EQ(got.kind == raster::ErrorKind::syntax, syntax) << text;
    malformed += syntax;
  }
  // Each outcome occurs, so the property is exercised on each side.
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected - malformed, 100);
  EXPECT_GT(malformed, 300);
}

TEST(SceneReader, NumbersReadBitForBitAsTheOracleReadsThem) {
  for (const char* number : {"0",
                             "-0",
                             "-0.0",
                             "0e5",
                             "-0e0",
                             "7",
                             "-7",
                             "0.1",
                             "0.30000000000000004",
                             "1e5",
                             "1E+5",
                             "2.5e-3",
                             "9007199254740992",
                             "9007199254740993",
                             "9223372036854775807",
                             "9223372036854775808",
                             "18446744073709551615",
                             "18446744073709551616",
                             "-9223372036854775808",
                             "-9223372036854775809",
                             "123456789012345678901234567890",
                             "1.00000000000000011102230246251565404236316680908203125",
                             "0.0000000000000000000000001",
                             "1234567890.123456789",
                             "3.4028236692093846e38",
                             "4.9e-324",
                             "2.2250738585072014e-308",
                             "17976931348623157e292"}) {
    const std::string text =
        std::string(R"({"width":1,"height":1,"primitives":[{"type":"line","points":[[)") + number +
        ",1],[0,0]]}]}";
    const Verdict expected = oracle(text), got = reader(text);
    ASSERT_EQ(got.scene.has_value(), expected.scene.has_value()) << number;
    if (got.scene) {
      EXPECT_TRUE(same(*got.scene, *expected.scene)) << number;
    }
  }
}

TEST(SceneReader, EveryFieldOnEveryKindIsJudgedAsTheOracleJudgesIt) {
  const std::vector<std::pair<std::string, std::string>> kinds = {
      {"triangle", R"("points":[[0,0],[4,0],[0,4]])"},
      {"line", R"("points":[[0,0],[4,4]])"},
      {"polyline", R"("points":[[0,0],[4,4],[8,0]])"},
      {"triangle", R"("points":[[0,0,0],[1,0,0],[0,1,0]])"},
      {"mesh", R"("positions":[0,0,0,1,0,0,0,1,0],"indices":[0,1,2])"},
      {"shader", R"("source":"void mainImage(out vec4 c, in vec2 p) {}")"}};
  const std::vector<std::string> fields = {R"("points":[[1,1],[2,2]])",
                                           R"("time":2.5)",
                                           R"("frame":3)",
                                           R"("mouse":[1,2,3,4])",
                                           R"("date":[2026,11,3,0])",
                                           R"("channels":[null])",
                                           R"("uniforms":{"k":[1,2]})",
                                           R"("rect":[0,0,4,4])",
                                           R"("opaque":false)",
                                           R"("color":"#f00")",
                                           R"("color":[1,0,0])",
                                           R"("colors":["#f00","#0f0","#00f"])",
                                           R"("fill":false)",
                                           R"("closed":true)",
                                           R"("width":2)",
                                           R"("positions":[0,0,0])",
                                           R"("indices":[0,0,0])",
                                           R"("normals":[[0,0,1],[0,0,1],[0,0,1]])",
                                           R"("shading":"flat")",
                                           R"("cull":"back")",
                                           R"("wireframe":true)",
                                           R"("transform":{"scale":2})",
                                           R"("edges":true)",
                                           R"("edges":{"color":"#00f","width":2,"angle":45})",
                                           R"("edges":{"width":0})",
                                           R"("uvs":[[0,0],[1,0],[0,1]])",
                                           R"("data":"v 0 0 0")",
                                           R"("colr":"#fff")",
                                           R"("width":0)",
                                           R"("fill":1)"};
  int accepted = 0;
  for (const auto& [type, base] : kinds) {
    for (const auto& field : fields) {
      const std::string text =
          R"({"width":8,"height":8,"primitives":[{"type":")" + type + "\"," + base + "," + field + "}]}";
      const Verdict expected = oracle(text), got = reader(text);
      ASSERT_EQ(got.scene.has_value(), expected.scene.has_value()) << text;
      if (got.scene) {
        ASSERT_TRUE(same(*got.scene, *expected.scene)) << text;
        ++accepted;
      }
    }
  }
  EXPECT_GT(accepted, 20);
}

// Issue 61: a shader's fields on and just past every rule, to both readers.
TEST(SceneReader, ShaderFieldsAreJudgedAsTheOracleJudgesThem) {
  const std::string png =
      "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==";
  const std::vector<std::string> fields = {R"("time":1e9)",
                                           R"("time":-1e9)",
                                           R"("time":1.0000001e9)",
                                           R"("time":"1")",
                                           R"("frame":0)",
                                           R"("frame":2147483647)",
                                           R"("frame":2147483648)",
                                           R"("frame":-1)",
                                           R"("frame":1.5)",
                                           R"("frame":4.0)",
                                           R"("mouse":[1,2])",
                                           R"("mouse":[1,2,3])",
                                           R"("mouse":[1,2,3,4,5])",
                                           R"("mouse":[])",
                                           R"("mouse":[1e10,0])",
                                           R"("mouse":[1,"2"])",
                                           R"("date":[2026,0,1,0])",
                                           R"("date":[2026,0,1])",
                                           R"("date":{})",
                                           R"("channels":[])",
                                           R"("channels":[null,null,null,null])",
                                           R"("channels":[null,null,null,null,null])",
                                           R"("channels":[{"data":")" + png + R"("}])",
                                           R"("channels":[null,{"data":")" + png + R"(","wrap":"clamp"}])",
                                           R"("channels":[{"data":")" + png + R"(","colour":1}])",
                                           R"("channels":[{"source":"model"}])",
                                           R"("channels":[{}])",
                                           R"("channels":[1])",
                                           R"("channels":{})",
                                           R"("uniforms":{})",
                                           R"("uniforms":{"k":true,"m":[[1,0],[0,1]],"v":[0.5,false,3]})",
                                           R"("uniforms":{"k":[[[1]]]})",
                                           R"("uniforms":{"k":[]})",
                                           R"("uniforms":{"k":[[],[]]})",
                                           R"("uniforms":{"k":[[],[1]]})",
                                           R"("uniforms":{"k":null})",
                                           R"("uniforms":{"k":"1"})",
                                           R"("uniforms":{"iTime":1})",
                                           R"("uniforms":{"2k":1})",
                                           R"("uniforms":{"k-1":1})",
                                           R"("uniforms":{"":1})",
                                           R"("uniforms":{"k":3.5e38})",
                                           R"("uniforms":{"k":3.4e38})",
                                           R"("uniforms":[1])",
                                           R"("rect":[0,0,1,1])",
                                           R"("rect":[-16384,16384,16384,1])",
                                           R"("rect":[-16385,0,1,1])",
                                           R"("rect":[0,0,0,1])",
                                           R"("rect":[0,0,1,16385])",
                                           R"("rect":[0,0,1])",
                                           R"("rect":[0,0,1,1,1])",
                                           R"("rect":[0.5,0,1,1])",
                                           R"("rect":[0,0,2.0,1])",
                                           R"("opaque":true)",
                                           R"("opaque":0)",
                                           R"("source":1)",
                                           R"("sources":"x")",
                                           R"("color":"#fff")"};
  // A uniform of 4096 values is the most; a 4097th, flat or in a nested array, is one too many.
  const auto values = [](int n) {
    std::string v = "[";
    for (int k = 0; k < n; ++k) v += k ? ",1" : "1";
    return v + "]";
  };
  std::vector<std::string> all = fields;
  for (const std::string& v : {values(4096), values(4097), "[" + values(4096) + "]",
                               "[" + values(4096) + ",[]]", "[" + values(4095) + ",1,1]"})
    all.push_back(R"("uniforms":{"big":)" + v + "}");
  int accepted = 0, rejected = 0;
  for (const std::string& field : all) {
    const std::string text =
        R"({"width":8,"height":8,"primitives":[{"type":"shader","source":"x",)" + field + "}]}";
    const Verdict expected = oracle(text), got = reader(text);
    ASSERT_EQ(got.scene.has_value(), expected.scene.has_value()) << field.substr(0, 160);
    if (got.scene) {
      ASSERT_TRUE(same(*got.scene, *expected.scene)) << field.substr(0, 160);
      ++accepted;
    } else {
      ++rejected;
    }
  }
  EXPECT_GT(accepted, 20);
  EXPECT_GT(rejected, 30);
  // Without "source" there is no program: both refuse.
  const std::string bare = R"({"width":8,"height":8,"primitives":[{"type":"shader","time":1}]})";
  EXPECT_FALSE(oracle(bare).scene.has_value());
  EXPECT_FALSE(reader(bare).scene.has_value());
}

// Issue 31, item 5: a mesh's flat arrays are sized from a count of their elements before they are read,
// not grown by doubling (which copies them and leaves up to half their capacity unused).
TEST(SceneReader, FlatMeshArraysAreSizedFromTheirCount) {
  std::string positions, indices;
  const int n = 1000;            // positions, and as many triangles
  for (int i = 0; i < n; ++i) {  // appended piece by piece (GCC 12 warns falsely on operator+ here)
    if (i) positions += ',', indices += ',';
    positions += std::to_string(i), positions += ",0,", positions += std::to_string(i % 7);
    indices += std::to_string(i), indices += ',', indices += std::to_string((i + 1) % n);
    indices += ',', indices += std::to_string((i + 2) % n);
  }
  const Scene scene =
      raster::parse_scene(R"({"width": 8, "height": 8, "primitives": [{"type": "mesh", "positions": [)" +
                          positions + R"(], "indices": [)" + indices + "]}]}");
  const raster::Mesh& mesh = scene.meshes.at(0);
  ASSERT_EQ(mesh.positions.size(), std::size_t{n});
  ASSERT_EQ(mesh.triangles.size(), std::size_t{n});
  EXPECT_EQ(mesh.positions.capacity(), mesh.positions.size());
  EXPECT_EQ(mesh.triangles.capacity(), mesh.triangles.size());
}

TEST(SceneReader, RefusesTheDepthLimitNulBytesAndDuplicateKeys) {
  const std::string scene = R"({"width":2,"height":2,"primitives":[{"type":"line","points":[[0,0],[1,1]]}]})";
  raster::Limits shallow;
  shallow.max_json_depth = 4;  // the points of a line are at depth 5
  EXPECT_EQ(reader(scene, shallow).kind, raster::ErrorKind::syntax);
  EXPECT_EQ(oracle(scene, shallow).kind, raster::ErrorKind::syntax);
  EXPECT_TRUE(reader(scene, raster::Limits{}).scene.has_value());
  // nlohmann stops at a NUL byte: the document is malformed, yet the value text "3<NUL><NUL>4" alone reads 3
  // (found by the fuzzer).
  using namespace std::string_literals;
  const std::string nul = "{\"width\": 3\0\0004, \"height\": 2}"s;
  EXPECT_EQ(reader(nul).kind, raster::ErrorKind::syntax);
  EXPECT_EQ(oracle(nul).kind, raster::ErrorKind::syntax);
  // After the document (found by the fuzzer: the oracle stops at the NUL and accepts what is before it).
  const std::string trailing = "{\"width\": 3, \"height\": 2}\0 "s;
  EXPECT_EQ(reader(trailing).kind, raster::ErrorKind::syntax);
  EXPECT_FALSE(reader(trailing).scene.has_value());
  // A repeated key is refused at the second one, wherever it is (the root, a primitive, a nested value),
  // and its pointer escapes '~' and '/'.
  const std::pair<std::string, std::string> repeated[] = {
      {R"({"width":2,"height":2,"width":3})", "/width"},
      {R"({"width":2,"height":2,"primitives":[{"type":"line","points":[[0,0],[1,1]]},)"
       R"({"type":"line","points":[[0,0],[1,1]],"points":[[1,1],[0,0]]}]})",
       "/primitives/1/points"},
      {R"({"width":2,"height":2,"camera":{"eye":[0,0,5],"eye":[0,0,6]}})", "/camera/eye"},
      {R"({"width":2,"height":2,"primitives":[{"type":"mesh","positions":[[0,0,0],[1,0,0],[0,1,0]],)"
       R"("indices":[[0,1,2]],"transform":{"translate":[0,0,0],"scale":1,"scale":2}}]})",
       "/primitives/0/transform/scale"},
      {R"({"width":2,"height":2,"primitives":[{"type":"obj","data":"","textures":{"a~/b":"","a~/b":""}}]})",
       "/primitives/0/textures/a~0~1b"},
  };
  for (const auto& [text, pointer] : repeated) {
    try {
      raster::parse_scene(text);
      ADD_FAILURE() << "accepted " << text;
    } catch (const raster::SceneError& e) {
      EXPECT_EQ(e.kind(), raster::ErrorKind::invalid) << text;
      EXPECT_EQ(e.where().pointer, pointer) << e.what();
      EXPECT_NE(std::string(e.what()).find("twice"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
