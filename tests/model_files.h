// Writers of one generated mesh in every model format, for the tests of the model readers (library and
// service): OBJ, STL (ASCII, binary), PLY (ASCII, binary of both byte orders), glTF and GLB.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "raster/model.h"

namespace test {

// The scene fields that draw a model as a bare request draws it (raster::kModelPicture's background and
// anti-aliasing), to put in a scene whose picture is compared with the bare model's. The format's up axis
// is the camera's ("up": "+z" for STL) and is left to the scene, which has its own camera.
// `antialias` false leaves "antialias" out, for a scene that sets its own.
inline std::string model_picture_fields(bool antialias = true) {
  const raster::Rgba8 b = raster::kModelPicture.background;
  char hex[8];
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", b.r, b.g, b.b);
  return "\"background\": \"" + std::string(hex) + "\"" +
         (antialias
              ? ", \"antialias\": " + std::to_string(raster::sample_count(raster::kModelPicture.antialias))
              : "");
}

// A closed, bumpy ring of quads (a torus with seeded radii), so that the quads are not planar and their
// diagonal matters. Coordinates are multiples of 1/256: exact as floats and in decimal.
struct TestMesh {
  std::vector<std::array<double, 3>> v;
  std::vector<std::vector<std::uint32_t>> faces;  // quads and a few triangles, counter-clockwise outside
};

inline double grid(double x) {
  return std::round(x * 256) / 256;
}

inline TestMesh make_mesh(unsigned seed, int ring = 14, int tube = 8) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> bump(-0.08, 0.08);
  TestMesh m;
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < tube; ++j) {
      const double a = 2 * M_PI * i / ring, b = 2 * M_PI * j / tube, r = 0.35 + bump(rng);
      m.v.push_back({grid((1 + r * std::cos(b)) * std::cos(a)), grid(r * std::sin(b)),
                     grid((1 + r * std::cos(b)) * std::sin(a))});
    }
  auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(((i + ring) % ring) * tube + (j + tube) % tube);
  };
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < tube; ++j) {
      if ((i + j) % 5 == 0) {  // some faces as two triangles, so both kinds are read
        m.faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
        m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
      } else {
        m.faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
      }
    }
  return m;
}

// tinyobjloader's split of a quad (its shorter diagonal), for the formats that hold only triangles.
inline std::vector<std::array<std::uint32_t, 3>> triangles_of(const TestMesh& m) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& f : m.faces) {
    if (f.size() == 3) {
      out.push_back({f[0], f[1], f[2]});
      continue;
    }
    auto d2 = [&](std::uint32_t a, std::uint32_t b) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += (m.v[b][k] - m.v[a][k]) * (m.v[b][k] - m.v[a][k]);
      return s;
    };
    if (d2(f[0], f[2]) < d2(f[1], f[3]))
      out.push_back({f[0], f[1], f[2]}), out.push_back({f[0], f[2], f[3]});
    else
      out.push_back({f[0], f[1], f[3]}), out.push_back({f[1], f[2], f[3]});
  }
  return out;
}

inline std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

template <typename T>
void put(std::string& out, T value, bool big = false) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

inline std::string write_obj(const TestMesh& m) {
  std::string s = "# generated\n";
  for (const auto& p : m.v) s += "v " + num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + "\n";
  for (const auto& f : m.faces) {
    s += "f";
    for (std::uint32_t i : f) s.append(" ").append(std::to_string(i + 1));
    s += "\n";
  }
  return s;
}

inline std::string write_stl_ascii(const TestMesh& m) {
  std::string s = "solid torus\n";
  for (const auto& t : triangles_of(m)) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (std::uint32_t i : t)
      s += "      vertex " + num(m.v[i][0]) + " " + num(m.v[i][1]) + " " + num(m.v[i][2]) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid torus\n";
}

inline std::string write_stl_binary(const TestMesh& m, std::string header = "binary torus") {
  const auto tris = triangles_of(m);
  header.resize(80, ' ');
  std::string s = header;
  put<std::uint32_t>(s, static_cast<std::uint32_t>(tris.size()));
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) put<float>(s, 0);
    for (std::uint32_t i : t)
      for (int k = 0; k < 3; ++k) put<float>(s, static_cast<float>(m.v[i][k]));
    put<std::uint16_t>(s, 0x7fff);  // attribute bytes: ignored
  }
  return s;
}

inline std::string ply_header(const TestMesh& m, const std::string& format) {
  return "ply\nformat " + format + " 1.0\ncomment generated\nelement vertex " + std::to_string(m.v.size()) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar flags\nelement face " +
         std::to_string(m.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

inline std::string write_ply_ascii(const TestMesh& m) {
  std::string s = ply_header(m, "ascii");
  for (const auto& p : m.v) s += num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + " 7\n";
  for (const auto& f : m.faces) {
    s += std::to_string(f.size());
    for (std::uint32_t i : f) s.append(" ").append(std::to_string(i));
    s += "\n";
  }
  return s;
}

inline std::string write_ply_binary(const TestMesh& m, bool big) {
  std::string s = ply_header(m, big ? "binary_big_endian" : "binary_little_endian");
  for (const auto& p : m.v) {
    for (int k = 0; k < 3; ++k) put<float>(s, static_cast<float>(p[k]), big);
    put<std::uint8_t>(s, 7);
  }
  for (const auto& f : m.faces) {
    put<std::uint8_t>(s, static_cast<std::uint8_t>(f.size()));
    for (std::uint32_t i : f) put<std::int32_t>(s, static_cast<std::int32_t>(i), big);
  }
  return s;
}

inline std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[n >> 18 & 63];
    out += kAlphabet[n >> 12 & 63];
    out += i + 1 < bytes.size() ? kAlphabet[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

// The mesh's buffer (positions, then 16- or 32-bit indices) and the document that describes it, with the
// buffer's URI as given ("" for a GLB's own chunk).
struct Gltf {
  std::string json, buffer;
};

inline Gltf make_gltf(const TestMesh& m, const std::string& uri, bool wide_indices,
                      const std::string& extra = "") {
  Gltf g;
  for (const auto& p : m.v)
    for (int k = 0; k < 3; ++k) put<float>(g.buffer, static_cast<float>(p[k]));
  const std::size_t positions = g.buffer.size();
  const auto tris = triangles_of(m);
  for (const auto& t : tris)
    for (std::uint32_t i : t)
      wide_indices ? put<std::uint32_t>(g.buffer, i)
                   : put<std::uint16_t>(g.buffer, static_cast<std::uint16_t>(i));
  while (g.buffer.size() % 4) g.buffer.push_back('\0');
  const std::string n = std::to_string(m.v.size()), c = std::to_string(tris.size() * 3);
  g.json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
           n + R"(, "type": "VEC3"},
                {"bufferView": 1, "componentType": )" +
           (wide_indices ? "5125" : "5123") + R"(, "count": )" + c + R"(, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" +
           std::to_string(positions) + R"(},
                  {"buffer": 0, "byteOffset": )" +
           std::to_string(positions) + R"(, "byteLength": )" + std::to_string(g.buffer.size() - positions) +
           R"(}],
  "buffers": [{"byteLength": )" +
           std::to_string(g.buffer.size()) + (uri.empty() ? "" : R"(, "uri": ")" + uri + "\"") + "}]" +
           extra + "}";
  return g;
}

inline std::string write_glb(const Gltf& g) {
  std::string json = g.json;
  while (json.size() % 4) json += ' ';
  std::string s = "glTF";
  put<std::uint32_t>(s, 2);
  put<std::uint32_t>(s, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + g.buffer.size()));
  put<std::uint32_t>(s, static_cast<std::uint32_t>(json.size()));
  s += "JSON" + json;
  put<std::uint32_t>(s, static_cast<std::uint32_t>(g.buffer.size()));
  s += std::string("BIN\0", 4) + g.buffer;
  return s;
}

}  // namespace test
