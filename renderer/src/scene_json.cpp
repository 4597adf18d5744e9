// Scene parsing: JSON text -> Scene. Every rejection names the JSON pointer (or byte offset) it concerns.
#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

#include "raster/scene.h"

namespace raster {
namespace {

using nlohmann::json;

[[noreturn]] void fail(ErrorKind kind, const std::string& pointer, const std::string& message) {
  throw SceneError(kind, message, ErrorLocation{pointer, 0, 0});
}

[[noreturn]] void invalid(const std::string& pointer, const std::string& message) {
  fail(ErrorKind::invalid, pointer, message);
}

// RFC 6901: '~' and '/' inside a key are escaped.
std::string pointer_key(const std::string& parent, const std::string& key) {
  std::string out = parent + "/";
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string pointer_index(const std::string& parent, std::size_t i) { return parent + "/" + std::to_string(i); }

const char* type_name(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    case json::value_t::binary: return "binary data";
    case json::value_t::discarded: return "nothing";
    default: return "a number";
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
void check_keys(const json& obj, const std::string& pointer, std::initializer_list<const char*> known) {
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
    if (!best.empty()) message += "; did you mean \"" + best + "\"?";
    else {
      message += "; known fields are";
      for (const char* k : known) message += std::string(" \"") + k + "\"";
    }
    invalid(pointer_key(pointer, key), message);
  }
}

double read_number(const json& v, const std::string& pointer) {
  if (!v.is_number()) invalid(pointer, std::string("expected a number, got ") + type_name(v));
  double d = v.get<double>();
  // The JSON grammar has no NaN or Infinity, and the lexer rejects overflow; this guards the rest.
  if (!std::isfinite(d)) invalid(pointer, "number is not finite");
  return d;
}

// Integer fields accept 256 and 256.0 but not 256.5; the range check is the caller's.
std::int64_t read_integer(const json& v, const std::string& pointer) {
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

bool read_bool(const json& v, const std::string& pointer) {
  if (!v.is_boolean()) invalid(pointer, std::string("expected true or false, got ") + type_name(v));
  return v.get<bool>();
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::uint8_t unit_to_byte(double v) { return static_cast<std::uint8_t>(std::floor(v * 255.0 + 0.5)); }

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

// "#rgb", "#rgba", "#rrggbb", "#rrggbbaa", [r,g,b] or [r,g,b,a] with components in 0..1.
Rgba8 read_color(const json& v, const std::string& pointer) {
  if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    const std::size_t n = s.size();
    bool ok = n >= 1 && s[0] == '#' && (n == 4 || n == 5 || n == 7 || n == 9);
    for (std::size_t i = 1; ok && i < n; ++i) ok = hex_digit(s[i]) >= 0;
    if (!ok)
      invalid(pointer, "expected a colour \"#rgb\", \"#rgba\", \"#rrggbb\" or \"#rrggbbaa\", got \"" + s + "\"");
    std::array<std::uint8_t, 4> c{0, 0, 0, 255};
    const bool short_form = n <= 5;
    const std::size_t count = short_form ? n - 1 : (n - 1) / 2;
    for (std::size_t k = 0; k < count; ++k) {
      c[k] = short_form ? static_cast<std::uint8_t>(hex_digit(s[1 + k]) * 17)
                        : static_cast<std::uint8_t>(hex_digit(s[1 + 2 * k]) * 16 + hex_digit(s[2 + 2 * k]));
    }
    return {c[0], c[1], c[2], c[3]};
  }
  if (v.is_array()) {
    if (v.size() != 3 && v.size() != 4)
      invalid(pointer, "a colour array has 3 or 4 components [r, g, b(, a)], got " + std::to_string(v.size()));
    std::vector<double> comp;
    for (std::size_t k = 0; k < v.size(); ++k) comp.push_back(read_number(v[k], pointer_index(pointer, k)));
    for (std::size_t k = 0; k < comp.size(); ++k) {
      if (comp[k] >= 0.0 && comp[k] <= 1.0) continue;
      std::string message = "colour components are in 0..1, got " + v[k].dump();
      const bool bytes = std::all_of(comp.begin(), comp.end(),
                                     [](double c) { return c >= 0 && c <= 255 && c == std::floor(c); });
      if (bytes) message += "; did you mean \"" + hex_of(comp) + "\"?";
      invalid(pointer_index(pointer, k), message);
    }
    return {unit_to_byte(comp[0]), unit_to_byte(comp[1]), unit_to_byte(comp[2]),
            comp.size() == 4 ? unit_to_byte(comp[3]) : std::uint8_t{255}};
  }
  invalid(pointer, std::string("expected a colour (\"#rrggbb\" or [r, g, b]), got ") + type_name(v));
}

double read_coordinate(const json& v, const std::string& pointer) {
  const double d = read_number(v, pointer);
  if (std::fabs(d) > kMaxCoordinate) invalid(pointer, "coordinate " + v.dump() + " is outside +-3.4e38 (+-2^128)");
  return d;
}

Point2 read_point(const json& v, const std::string& pointer) {
  if (!v.is_array()) invalid(pointer, std::string("expected a point [x, y], got ") + type_name(v));
  if (v.size() != 2) invalid(pointer, "expected a point [x, y], got " + std::to_string(v.size()) + " numbers");
  return {read_coordinate(v[0], pointer_index(pointer, 0)), read_coordinate(v[1], pointer_index(pointer, 1))};
}

const char* kind_name(PrimitiveKind k) {
  switch (k) {
    case PrimitiveKind::triangle: return "triangle";
    case PrimitiveKind::line: return "line";
    case PrimitiveKind::polyline: return "polyline";
  }
  return "?";
}

void read_primitive(const json& v, const std::string& pointer, Scene& scene) {
  if (!v.is_object()) invalid(pointer, std::string("expected a primitive object, got ") + type_name(v));
  auto type_it = v.find("type");
  if (type_it == v.end()) invalid(pointer, "missing \"type\" (\"triangle\", \"line\" or \"polyline\")");
  const std::string type_pointer = pointer + "/type";
  if (!type_it->is_string()) invalid(type_pointer, std::string("expected a string, got ") + type_name(*type_it));
  const std::string& type = type_it->get_ref<const std::string&>();

  Primitive p;
  if (type == "triangle") {
    p.kind = PrimitiveKind::triangle;
    check_keys(v, pointer, {"type", "points", "color", "colors", "fill"});
  } else if (type == "line") {
    p.kind = PrimitiveKind::line;
    check_keys(v, pointer, {"type", "points", "color", "colors"});
  } else if (type == "polyline") {
    p.kind = PrimitiveKind::polyline;
    check_keys(v, pointer, {"type", "points", "color", "colors", "closed"});
  } else {
    invalid(type_pointer, "unknown primitive type \"" + type + "\"; expected \"triangle\", \"line\" or \"polyline\"");
  }

  auto points_it = v.find("points");
  const std::string points_pointer = pointer + "/points";
  if (points_it == v.end()) invalid(pointer, std::string("a ") + kind_name(p.kind) + " needs \"points\"");
  if (!points_it->is_array()) invalid(points_pointer, std::string("expected an array of points, got ") + type_name(*points_it));
  const std::size_t n = points_it->size();
  if (p.kind == PrimitiveKind::triangle && n != 3)
    invalid(points_pointer, "a triangle has exactly 3 points, got " + std::to_string(n));
  if (p.kind == PrimitiveKind::line && n != 2)
    invalid(points_pointer, "a line has exactly 2 points, got " + std::to_string(n));
  if (p.kind == PrimitiveKind::polyline && n < 2)
    invalid(points_pointer, "a polyline has at least 2 points, got " + std::to_string(n));
  if (scene.points.size() + n > UINT32_MAX) fail(ErrorKind::limit, points_pointer, "too many points in the scene");

  p.first_point = static_cast<std::uint32_t>(scene.points.size());
  p.point_count = static_cast<std::uint32_t>(n);
  for (std::size_t k = 0; k < n; ++k) scene.points.push_back(read_point((*points_it)[k], pointer_index(points_pointer, k)));

  auto color_it = v.find("color");
  auto colors_it = v.find("colors");
  p.first_color = static_cast<std::uint32_t>(scene.colors.size());
  if (color_it != v.end() && colors_it != v.end())
    invalid(pointer, "give either \"color\" (flat) or \"colors\" (one per point), not both");
  if (colors_it != v.end()) {
    const std::string colors_pointer = pointer + "/colors";
    if (!colors_it->is_array() || colors_it->size() != n)
      invalid(colors_pointer, "\"colors\" needs one colour per point (" + std::to_string(n) + ")");
    for (std::size_t k = 0; k < n; ++k) scene.colors.push_back(read_color((*colors_it)[k], pointer_index(colors_pointer, k)));
    p.per_vertex_color = true;
  } else if (color_it != v.end()) {
    scene.colors.push_back(read_color(*color_it, pointer + "/color"));
  } else {
    scene.colors.push_back(Rgba8{255, 255, 255, 255});  // default: opaque white
  }

  if (auto it = v.find("fill"); it != v.end()) p.fill = read_bool(*it, pointer + "/fill");
  if (auto it = v.find("closed"); it != v.end()) p.closed = read_bool(*it, pointer + "/closed");
  scene.primitives.push_back(p);
}

// Byte offset (1-based) of the first bracket that opens level max_depth + 1, skipping strings.
std::size_t depth_violation_offset(std::string_view text, int max_depth) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
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
// is iterative, but dump, copy and compare of the resulting document recurse; and (2) turns every parse
// error, number overflow included, into a SceneError with the byte offset the parser reports.
class BoundedDomBuilder {
 public:
  BoundedDomBuilder(json& out, std::string_view text, int max_depth) : dom_(out, true), text_(text), max_depth_(max_depth) {}

  bool null() { return dom_.null(); }
  bool boolean(bool v) { return dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) { return dom_.number_float(v, s); }
  bool string(json::string_t& v) { return dom_.string(v); }
  bool binary(json::binary_t& v) { return dom_.binary(v); }
  bool key(json::string_t& v) { return dom_.key(v); }
  bool start_object(std::size_t n) { return enter() && dom_.start_object(n); }
  bool end_object() { return --depth_, dom_.end_object(); }
  bool start_array(std::size_t n) { return enter() && dom_.start_array(n); }
  bool end_array() { return --depth_, dom_.end_array(); }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 1, column 2: ..."; keep the sentence.
    std::string message = e.what();
    if (auto at = message.find("] "); at != std::string::npos) message.erase(0, at + 2);
    throw SceneError(ErrorKind::syntax, "malformed JSON: " + message, ErrorLocation{"", position, 0});
  }

 private:
  bool enter() {
    if (++depth_ <= max_depth_) return true;
    throw SceneError(ErrorKind::syntax, "JSON nested deeper than " + std::to_string(max_depth_) + " levels",
                     ErrorLocation{"", depth_violation_offset(text_, max_depth_), 0});
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::string_view text_;
  int max_depth_;
  int depth_ = 0;
};

json parse_document(std::string_view text, int max_depth) {
  if (text.empty()) throw SceneError(ErrorKind::syntax, "the scene is empty (0 bytes); expected a JSON object");
  json doc;
  BoundedDomBuilder builder(doc, text, max_depth);
  json::sax_parse(text.begin(), text.end(), &builder);
  return doc;
}

}  // namespace

Scene parse_scene(std::string_view json_text, const Limits& limits) {
  const json doc = parse_document(json_text, limits.max_json_depth);
  if (!doc.is_object()) invalid("", std::string("a scene is a JSON object, got ") + type_name(doc));
  check_keys(doc, "", {"width", "height", "background", "primitives"});

  Scene scene;
  auto read_side = [&](const char* key, int max_side) {
    auto it = doc.find(key);
    const std::string pointer = std::string("/") + key;
    if (it == doc.end()) invalid("", std::string("missing \"") + key + "\" (image size in pixels)");
    const std::int64_t side = read_integer(*it, pointer);
    if (side < 1) invalid(pointer, std::string("\"") + key + "\" must be at least 1, got " + it->dump());
    const int cap = std::min(max_side, kMaxImageSide);
    if (side > cap) fail(ErrorKind::limit, pointer, std::string("\"") + key + "\" " + it->dump() + " exceeds the limit of " + std::to_string(cap));
    return static_cast<int>(side);
  };
  scene.width = read_side("width", limits.max_width);
  scene.height = read_side("height", limits.max_height);
  const std::int64_t pixels = static_cast<std::int64_t>(scene.width) * scene.height;
  if (pixels > limits.max_pixels)
    fail(ErrorKind::limit, "", std::to_string(scene.width) + "x" + std::to_string(scene.height) + " is " +
                                   std::to_string(pixels) + " pixels, over the limit of " + std::to_string(limits.max_pixels));

  if (auto it = doc.find("background"); it != doc.end()) scene.background = read_color(*it, "/background");

  if (auto it = doc.find("primitives"); it != doc.end()) {
    if (!it->is_array()) invalid("/primitives", std::string("expected an array, got ") + type_name(*it));
    if (static_cast<std::int64_t>(it->size()) > limits.max_primitives)
      fail(ErrorKind::limit, "/primitives", std::to_string(it->size()) + " primitives exceed the limit of " + std::to_string(limits.max_primitives));
    scene.primitives.reserve(it->size());
    for (std::size_t i = 0; i < it->size(); ++i) read_primitive((*it)[i], pointer_index("/primitives", i), scene);
  }
  return scene;
}

}  // namespace raster
