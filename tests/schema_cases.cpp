// schema_cases COUNT SEED: writes COUNT generated scene documents, one JSON line each, with the verdict of
// the parser (and the planner, which checks the camera) on it:
//   {"doc": "<scene text>", "verdict": "accepted" | "syntax" | "invalid" | "limit" | "model" | "encoding" |
//    "shader", "message": "...", "pointer": "..."}
// tests/schema/check_schema.py validates every document against server/schema/scene.schema.json and
// compares. Documents start as valid scenes of every kind (seeded, so every run is the same) and most get
// one to three mutations at random places: a value replaced by one from a pool of boundary and
// wrong-typed values, a key removed or added (known names in the wrong place, typos), array elements
// dropped or added. So roughly half are accepted, and the rejected ones sit just across a rule.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/raster.h"

namespace {

using json = nlohmann::json;

class Generator {
 public:
  explicit Generator(std::uint32_t seed) : rng_(seed) {}

  json scene() {
    json s = {{"width", integer(1, 48)}, {"height", integer(1, 48)}};
    if (chance(0.3)) s["background"] = color();
    if (chance(0.2)) s["antialias"] = pick<json>({1, 4, 8, 16, 4.0});
    if (chance(0.25)) s["camera"] = camera();
    if (chance(0.2)) s["light"] = light();
    if (chance(0.9)) {
      json primitives = json::array();
      for (int i = integer(0, 4); i > 0; --i) primitives.push_back(primitive());
      s["primitives"] = primitives;
    }
    return s;
  }

  // 0 to 3 mutations; a third of the documents stay as generated.
  void mutate(json& doc) {
    const int n = chance(0.33) ? 0 : integer(1, 3);
    for (int i = 0; i < n; ++i) mutate_once(doc);
  }

 private:
  json primitive() {
    if (chance(0.12)) return shader();
    switch (integer(0, 4)) {
      case 0:
      case 1:
      case 2:
        return drawn(pick<std::string>({"triangle", "line", "polyline"}));
      case 3:
        return mesh();
      default:
        return obj();
    }
  }

  json drawn(const std::string& type) {
    const std::size_t n = type == "triangle" ? 3
                          : type == "line"   ? 2
                                             : static_cast<std::size_t>(integer(2, 5));
    const bool world = chance(0.2);
    json p = {{"type", type}, {"points", json::array()}};
    for (std::size_t k = 0; k < n; ++k) p["points"].push_back(world ? vec3() : point2());
    const double c = uniform();
    if (c < 0.35) {
      p["colors"] = json::array();
      for (std::size_t k = 0; k < n; ++k) p["colors"].push_back(color());
    } else if (c < 0.7) {
      p["color"] = color();
    }
    if (type == "triangle" && chance(0.3)) p["fill"] = chance(0.5);
    if (type == "polyline" && chance(0.3)) p["closed"] = chance(0.5);
    if (chance(0.2)) p["width"] = pick<json>({1, 2.5, 0.25, 4096});
    return p;
  }

  json mesh() {
    const int positions = integer(3, 6);
    const bool flat = chance(0.4);
    json m = {{"type", "mesh"}, {"positions", json::array()}, {"indices", json::array()}};
    for (int k = 0; k < positions; ++k) {
      const json v = vec3();
      if (flat)
        for (const auto& x : v) m["positions"].push_back(x);
      else
        m["positions"].push_back(v);
    }
    const bool flat_indices = chance(0.4);
    for (int t = integer(0, 3); t > 0; --t) {
      const json tri = {integer(0, positions - 1), integer(0, positions - 1), integer(0, positions - 1)};
      if (flat_indices)
        for (const auto& i : tri) m["indices"].push_back(i);
      else
        m["indices"].push_back(tri);
    }
    if (chance(0.3)) {
      m["normals"] = json::array();
      for (int k = 0; k < positions; ++k) m["normals"].push_back(json{0, 0, 1});
    }
    if (chance(0.3)) {
      m["colors"] = json::array();
      for (int k = 0; k < positions; ++k) m["colors"].push_back(color());
    } else if (chance(0.3)) {
      m["color"] = color();
    }
    mesh_options(m);
    return m;
  }

  json obj() {
    json o = {{"type", "obj"}};
    if (chance(0.7))
      o["data"] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    else
      o["source"] = "model";  // the upload every verdict is given
    if (chance(0.2)) o["mtl"] = "newmtl red\nKd 1 0 0\n";
    if (chance(0.3)) o["color"] = color();
    mesh_options(o);
    return o;
  }

  // A shader primitive: a program that compiles (most of the time) and some of ShaderToy's inputs.
  json shader() {
    static const char* kPrograms[] = {
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(p / iResolution.xy, 0.5, 1.0); }",
        "uniform float k;\nuniform vec2 v;\nvoid mainImage(out vec4 c, in vec2 p) { c = vec4(k, v, 1.0); }",
        "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }",
        "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(y);\n}\n",  // does not compile: 'y'
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(iTime, iMouse.x, float(iFrame), iDate.w); }"};
    json p = {{"type", "shader"}, {"source", kPrograms[integer(0, 4)]}};
    if (chance(0.3)) p["time"] = pick<json>({0, 1.5, -2, 1e9});
    if (chance(0.3)) p["frame"] = pick<json>({0, 7, 60.0, 2147483647});
    if (chance(0.3)) p["mouse"] = chance(0.5) ? json{integer(0, 40), 3.5} : json{1, 2, 0, -1};
    if (chance(0.2)) p["date"] = json{2026, 11, 3, 45296.5};
    if (chance(0.2)) {
      p["channels"] = json::array();
      for (int k = integer(0, 4); k > 0; --k)
        p["channels"].push_back(chance(0.4) ? json(nullptr) : json{{"data", kPng}});
    }
    if (chance(0.3)) p["uniforms"] = uniforms();
    if (chance(0.3)) p["rect"] = json{integer(-10, 40), integer(-10, 40), integer(1, 48), integer(1, 48)};
    if (chance(0.2)) p["opaque"] = chance(0.5);
    return p;
  }

  json uniforms() {
    json u = json::object();
    if (chance(0.7)) u["k"] = pick<json>({0.5, 2, true, json{1, 2}, json::array()});
    if (chance(0.5)) u["v"] = pick<json>({json{0.25, 0.5}, json{json{1}, json{2}}, json{1, 2, 3}});
    if (chance(0.1)) u["iTime"] = 1;
    return u;
  }

  // A 1x1 RGBA PNG as base64: a channel's image.
  static constexpr const char* kPng =
      "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==";

  void mesh_options(json& m) {
    if (chance(0.3)) m["shading"] = pick<std::string>({"flat", "smooth", "unlit"});
    if (chance(0.2)) m["cull"] = pick<std::string>({"none", "back"});
    if (chance(0.2)) m["wireframe"] = chance(0.5);
    if (chance(0.3)) m["transform"] = transform();
  }

  json transform() {
    if (chance(0.2)) {
      json m = json::array();
      for (int k = 0; k < 16; ++k) m.push_back(k % 5 == 0 ? 1 : 0);
      return {{"matrix", m}};
    }
    json t = json::object();
    if (chance(0.5)) t["translate"] = vec3();
    if (chance(0.5)) t["rotate"] = json{integer(0, 90), integer(0, 90), 0};
    if (chance(0.5)) t["scale"] = chance(0.5) ? json(2) : json{1, 2, 0.5};
    return t;
  }

  json camera() {
    json c = json::object();
    if (chance(0.4)) c["projection"] = pick<std::string>({"perspective", "orthographic"});
    if (chance(0.4)) c["eye"] = json{0, 0, 5};
    if (chance(0.3)) c["target"] = json{0, 0, 0};
    if (chance(0.3)) c["up"] = json{0, 1, 0};
    if (chance(0.4)) c["fov"] = pick<json>({30, 45, 90.5, 179});
    if (chance(0.2)) c["near"] = 0.1;
    if (chance(0.2)) c["far"] = 100;
    if (chance(0.2)) c["height"] = 3;
    return c;
  }

  json light() {
    json l = json::object();
    if (chance(0.6)) l["direction"] = json{0, -1, -1};
    if (chance(0.6)) l["ambient"] = pick<json>({0, 0.2, 1});
    return l;
  }

  json point2() { return {coordinate(), coordinate()}; }
  json vec3() { return {coordinate(), coordinate(), coordinate()}; }
  json coordinate() {
    switch (integer(0, 4)) {
      case 0:
        return integer(-10, 50);
      case 1:
        return uniform() * 60 - 5;
      case 2:
        return pick<json>({0, -0.0, 3.4e38, -3.4e38, 1e-300});
      default:
        return integer(0, 40);
    }
  }
  json color() {
    if (chance(0.7)) {
      static const char* digits = "0123456789abcdefABCDEF";
      std::string s = "#";
      for (int k = pick<int>({3, 4, 6, 8}); k > 0; --k) s += digits[integer(0, 21)];
      return s;
    }
    return chance(0.5) ? json{uniform(), uniform(), uniform()} : json{1, 0.5, 0, uniform()};
  }

  // Values from across the format's rules: boundaries, wrong types, valid values of other fields.
  json interesting() {
    static const json pool = json::parse(R"([
      null, true, false, 0, -0.0, 1, -1, 0.5, 1.5, 2, 3, 4, 4.0, 7, 8, 16, 45, 179.99, 180, 255, 256.0,
      4096, 4096.5, 1e-9, 3.4e38, 3.5e38, -3.5e38, 1e300, "", "#fff", "#ffff", "#ffffff", "#ffffff80", "#ff",
      "#fffff", "fff", "#ggg", "#fff\n", " #fff", "triangle", "line", "polyline", "mesh", "obj", "Triangle",
      "flat", "smooth", "unlit", "none", "back", "front", "perspective", "orthographic", "model", "mtl",
      [], {}, [0], [0, 0], [0, 0, 0], [0, 1, 0], [1, 2, 3], [0, 0, 0, 0], [0.5, 0.5, 0.5], [1, 0, 0, 0.5],
      [255, 0, 0], [2, 0, 0], [-0.1, 0, 0], [[0, 0], [1, 1]], [[0, 0], [4, 0], [0, 4]],
      [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 0], [1, 1, 1]], [0, 1, 2], [[0, 1, 2]], [[0, 1]], [0, 1, 2, 3],
      ["#fff", "#000"], ["#fff", "#000", "#f00"], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1],
      {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}, {"translate": [1, 2, 3]},
      {"scale": 2}, {"rotate": [0, 90, 0]}, {"matrix": [1], "scale": 2}, {"eye": [0, 0, 0]},
      {"type": "triangle", "points": [[0, 0], [4, 0], [0, 4]]}, {"type": "line"}, {"direction": [0, 0, 0]},
      "shader", [1, 2, 3, 4, 5], [0, 0, 1], {"k": 1}, {"iTime": 1}, {"2k": 1}, [[1, 2], [3, 4]], [[[1]]], [[]],
      [null], [null, null, null, null, null], "void mainImage(out vec4 c, in vec2 p) { c = vec4(1); }"
    ])");
    return pool[static_cast<std::size_t>(integer(0, static_cast<int>(pool.size()) - 1))];
  }

  // A plausible value for a key added by a mutation: half the time right for that key, else anything.
  json value_for(const std::string& key) {
    if (chance(0.5)) return interesting();
    if (key == "color" || key == "background") return color();
    if (key == "colors") return json::array({color(), color(), color()});
    if (key == "points") return json::array({point2(), point2()});
    if (key == "transform") return transform();
    if (key == "camera") return camera();
    if (key == "light") return light();
    if (key == "fill" || key == "closed" || key == "wireframe") return chance(0.5);
    if (key == "eye" || key == "target" || key == "up" || key == "translate" || key == "rotate" ||
        key == "direction")
      return vec3();
    if (key == "data") return "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    if (key == "source") return "model";
    if (key == "mtl") return "newmtl red\nKd 1 0 0\n";
    if (key == "mtl_source") return "mtl";
    if (key == "scale") return 2;
    if (key == "matrix") return transform_matrix();
    if (key == "shading") return pick<std::string>({"flat", "smooth", "unlit"});
    if (key == "cull") return pick<std::string>({"none", "back"});
    if (key == "projection") return pick<std::string>({"perspective", "orthographic"});
    if (key == "normals") return json::array({json{0, 0, 1}, json{0, 0, 1}, json{0, 0, 1}});
    if (key == "uniforms") return uniforms();
    if (key == "channels") return json::array({nullptr, {{"data", kPng}}});
    if (key == "mouse") return json{1, 2};
    if (key == "date") return json{2026, 0, 1, 0};
    if (key == "rect") return json{0, 0, 4, 4};
    if (key == "opaque") return chance(0.5);
    if (key == "time") return 1.25;
    if (key == "frame") return 3;
    auto b = boundaries(key);
    if (!b.empty()) return b[static_cast<std::size_t>(integer(0, static_cast<int>(b.size()) - 1))];
    return interesting();
  }

  // The keys an object of its kind accepts (by "type", or by the key that holds it).
  static std::vector<std::string> kind_keys(const json& object, const std::string& held_by) {
    const std::string type =
        object.contains("type") && object["type"].is_string() ? object["type"].get<std::string>() : "";
    if (held_by.empty())
      return {"width", "height", "background", "antialias", "primitives", "camera", "light"};
    if (held_by == "transform") return {"translate", "rotate", "scale", "matrix"};
    if (held_by == "camera") return {"projection", "eye", "target", "up", "fov", "near", "far", "height"};
    if (held_by == "light") return {"direction", "ambient"};
    if (type == "triangle") return {"points", "color", "colors", "fill", "width"};
    if (type == "line") return {"points", "color", "colors", "width"};
    if (type == "polyline") return {"points", "color", "colors", "closed", "width"};
    if (type == "mesh")
      return {"positions", "indices",   "colors", "color",    "normals",
              "shading",   "wireframe", "cull",   "transform"};
    if (type == "obj")
      return {"data", "source", "mtl", "mtl_source", "color", "shading", "wireframe", "cull", "transform"};
    if (type == "shader")
      return {"source", "time", "frame", "mouse", "date", "channels", "uniforms", "rect", "opaque"};
    return {};
  }

  // Values on and just past the edges of a field's range (by the key that holds the number, or the array
  // it is an element of).
  static std::vector<json> boundaries(const std::string& key) {
    if (key == "width" || key == "height")  // image sides, and line widths (0, 4096]
      return {0, -1, 1e-9, 1, 1.5, 256.0, 4096, 4096.5, 8192, 8193};
    if (key == "fov") return {0, 1e-9, 179.999, 180, 181, -1};
    if (key == "near" || key == "far") return {0, -0.0, 1e-9, -1, 0.5, 1000};
    if (key == "ambient") return {0, 1, 1.0001, -0.0001, 0.5};
    if (key == "antialias") return {0, 1, 2, 4, 8, 16, 32, 4.5, 8.0};
    if (key == "scale") return {0, -1, 2, 3.5e38};
    if (key == "color" || key == "colors" || key == "background")  // components of colour arrays
      return {0, 1, 1.0001, -0.0001, 255, 0.5};
    if (key == "points" || key == "positions" || key == "normals" || key == "eye" || key == "target" ||
        key == "up" || key == "translate" || key == "rotate" || key == "direction")
      return {0, -0.0, 3.402823669209385e38, -3.402823669209385e38, 3.4028236692093857e38, 1e300, 1.5};
    if (key == "indices") return {-1, 0, 1, 2, 2.5, 5, 1e30};
    if (key == "matrix") return {0, 1, 1e300, -2.5};
    if (key == "time" || key == "mouse" || key == "date") return {0, -1e9, 1e9, 1.0000001e9, -2e9, 0.5};
    if (key == "frame") return {0, -1, 1.5, 2147483647, 2147483648.0, 7.0};
    if (key == "rect") return {0, 1, -16384, 16384, 16385, -16385, 0.5};
    if (key == "uniforms" || key == "k" || key == "v") return {0, 1, 3.4e38, 3.5e38, -0.5};
    return {};
  }

  json transform_matrix() {
    json m = json::array();
    for (int k = 0; k < 16; ++k) m.push_back(k % 5 == 0 ? 1 : 0);
    return m;
  }

  // The key a place is held by: its own for an object member; for an array element, its array's (for an
  // element of a point or colour inside a list, the list's).
  static std::string held_by(const json::json_pointer& place) {
    json::json_pointer p = place;
    while (!p.empty()) {
      const std::string last = p.back();
      if (!last.empty() &&
          std::all_of(last.begin(), last.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        p.pop_back();
        continue;
      }
      return last;
    }
    return "";
  }

  void mutate_once(json& doc) {
    std::vector<json::json_pointer> places;
    collect(doc, json::json_pointer(), places);
    const json::json_pointer place =
        places[static_cast<std::size_t>(integer(0, static_cast<int>(places.size()) - 1))];
    json& at = doc[place];
    static const std::vector<std::string> keys = {
        "width",     "height",     "background", "antialias",  "primitives", "camera",   "light",
        "type",      "points",     "color",      "colors",     "fill",       "closed",   "width",
        "positions", "indices",    "normals",    "shading",    "wireframe",  "cull",     "transform",
        "data",      "source",     "mtl",        "mtl_source", "translate",  "rotate",   "scale",
        "matrix",    "projection", "eye",        "target",     "up",         "fov",      "near",
        "far",       "direction",  "ambient",    "colour",     "Width",      "point",    "indexes",
        "time",      "frame",      "mouse",      "date",       "channels",   "uniforms", "rect",
        "opaque"};
    const double what = uniform();
    const std::string holder = held_by(place);
    const auto edges = boundaries(holder);
    if (at.is_number() && !edges.empty() && what < 0.6) {  // a number onto or just past its range's edge
      at = edges[static_cast<std::size_t>(integer(0, static_cast<int>(edges.size()) - 1))];
    } else if (at.is_object() && !at.empty() && what < 0.2) {  // remove a key
      auto it = at.begin();
      std::advance(it, integer(0, static_cast<int>(at.size()) - 1));
      at.erase(it);
    } else if (at.is_object() && what < 0.45) {  // add a key this kind of object accepts
      const auto own = kind_keys(at, place.empty() ? "" : place.back());
      if (!own.empty()) {
        const std::string& key = own[static_cast<std::size_t>(integer(0, static_cast<int>(own.size()) - 1))];
        at[key] = value_for(key);
      }
    } else if (at.is_object() && what < 0.6) {  // add (or replace) any key
      const std::string& key = keys[static_cast<std::size_t>(integer(0, static_cast<int>(keys.size()) - 1))];
      at[key] = value_for(key);
    } else if (at.is_array() && !at.empty() && what < 0.3) {  // drop an element
      at.erase(static_cast<std::size_t>(integer(0, static_cast<int>(at.size()) - 1)));
    } else if (at.is_array() && !at.empty() && what < 0.45) {  // repeat an element
      at.push_back(at[static_cast<std::size_t>(integer(0, static_cast<int>(at.size()) - 1))]);
    } else if (at.is_array() && what < 0.55) {
      at.push_back(interesting());
    } else {
      at = interesting();
    }
  }

  static void collect(const json& v, const json::json_pointer& here, std::vector<json::json_pointer>& out) {
    out.push_back(here);
    if (v.is_object())
      for (auto it = v.begin(); it != v.end(); ++it) collect(it.value(), here / it.key(), out);
    else if (v.is_array())
      for (std::size_t k = 0; k < v.size(); ++k) collect(v[k], here / k, out);
  }

  bool chance(double p) { return uniform() < p; }
  double uniform() { return std::uniform_real_distribution<double>(0, 1)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  template <class T>
  T pick(std::initializer_list<T> options) {
    return options.begin()[integer(0, static_cast<int>(options.size()) - 1)];
  }

  std::mt19937 rng_;
};

const char* kind_name(raster::ErrorKind k) {
  switch (k) {
    case raster::ErrorKind::syntax:
      return "syntax";
    case raster::ErrorKind::invalid:
      return "invalid";
    case raster::ErrorKind::limit:
      return "limit";
    case raster::ErrorKind::model:
      return "model";
    case raster::ErrorKind::encoding:
      return "encoding";
    case raster::ErrorKind::shader:
      return "shader";
    case raster::ErrorKind::program:
      return "program";
  }
  return "?";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: schema_cases COUNT SEED\n");
    return 2;
  }
  const long count = std::strtol(argv[1], nullptr, 10);
  Generator generator(static_cast<std::uint32_t>(std::strtoul(argv[2], nullptr, 10)));
  // What a multipart request would carry: "source": "model" finds its part, as over HTTP.
  const raster::Uploads uploads = {{"model", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
                                   {"mtl", "newmtl red\nKd 1 0 0\n"}};
  for (long i = 0; i < count; ++i) {
    json doc = generator.scene();
    generator.mutate(doc);
    const std::string text = doc.dump();
    json line = {{"doc", text}, {"verdict", "accepted"}};
    try {
      const raster::Scene scene = raster::parse_scene(text, {}, uploads);
      (void)raster::plan(scene, {}, {1});  // the camera's remaining checks (400s) happen here
    } catch (const raster::SceneError& e) {
      line["verdict"] = kind_name(e.kind());
      line["message"] = e.what();
      line["pointer"] = e.where().pointer;
    }
    std::puts(line.dump().c_str());
  }
  return 0;
}
