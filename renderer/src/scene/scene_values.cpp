// The scene reader's values: what a field holds when it is not an object of its own. Colours (hex text
// or 0..1 components), 2D and 3D points, lists of vectors, triangles and texture coordinates (nested or
// flat), and images as base64 text. Each reads at the cursor and appends to the primitive being read or
// returns the value; the loops over big arrays are here, with the number readers of scene_reader.h
// inlined into them.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "base/base64.h"
#include "raster/scene_checks.h"
#include "scene/scene_reader.h"

namespace raster::scene_reader {

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

namespace {

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

}  // namespace

// "#rgb", "#rgba", "#rrggbb", "#rrggbbaa", [r,g,b] or [r,g,b,a] with components in 0..1.
Rgba8 Reader::color(const Path& at) {
  if (expect(at, format::kString | format::kArray, "a colour (\"#rrggbb\" or [r, g, b])") == Kind::string) {
    const std::string_view s = in.string();
    Rgba8 c;
    if (!parse_hex_color(s, c)) invalid(at, format::bad_hex_color(s));
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

// One colour per point: hex text read in place (no pointer made), anything else by color().
void Reader::colors(PrimitiveState& s, const Path& at) {
  s.colors_byte = at.byte();
  std::size_t k = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++k) {
    Rgba8 c;
    const JsonCursor::Mark start = in.mark();
    if (in.at('"') && parse_hex_color(in.string_here(), c)) {  // the usual colour: no pointer made
      s.colors.push_back(c);
      continue;
    }
    in.seek(start);  // anything else is read again by color(), which has the words for its errors
    s.colors.push_back(color(element(at, k)));
  }
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
        invalid(Path(Path(at, k, byte), n, number_byte), format::outside_coordinates(in.number_text()));
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

void Reader::vec3_list(std::vector<Vec3f>& out, const Path& at) {
  out.reserve(in.flat_array_size() / 3);
  tuples<3>(
      at, "a point [x, y, z]", "x, y, z triples", [&](const auto& where) { return coordinate(where); },
      [&](const std::array<double, 3>& v) {
        out.push_back(Vec3f(Vec3{v[0], v[1], v[2]}));
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

}  // namespace raster::scene_reader

namespace raster::checks {

// Here, beside the reader's colours, for the hex parser they share.
Rgba8 color(std::string_view text) {
  Rgba8 c;
  if (!scene_reader::parse_hex_color(text, c))
    throw SceneError(ErrorKind::invalid, format::bad_hex_color(text));
  return c;
}

}  // namespace raster::checks
