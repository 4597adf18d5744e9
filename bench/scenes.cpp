#include "scenes.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>

#include "raster/model.h"

namespace bench {
namespace {

// A UV sphere of radius 1 at the origin: `n` rings and segments, 2 n^2 triangles (the poles' degenerate
// ones included), in the benchmarks' warm grey.
raster::Mesh uv_sphere(int n) {
  raster::Mesh mesh;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double theta = pi * i / n, phi = 2 * pi * j / n;
      mesh.positions.push_back(raster::Vec3f(
          raster::Vec3{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)}));
    }
  auto at = [n](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
      mesh.triangles.push_back({at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
    }
  mesh.colors = {{220, 200, 180, 255}};
  return mesh;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

raster::Rgba8 random_color(std::mt19937& rng) {
  return {static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
          static_cast<std::uint8_t>(rng()), 255};
}

void random_triangles(raster::Scene& s, int count, double radius, std::mt19937& rng, int ncolors = 3) {
  std::uniform_real_distribution<double> x(0, s.width), y(0, s.height), d(-radius, radius);
  for (int i = 0; i < count; ++i) {
    const double cx = x(rng), cy = y(rng);
    const raster::Point2 p[3] = {
        {cx + d(rng), cy + d(rng)}, {cx + d(rng), cy + d(rng)}, {cx + d(rng), cy + d(rng)}};
    const raster::Rgba8 c[3] = {random_color(rng), random_color(rng), random_color(rng)};
    add_triangle(s, p, c, ncolors);
  }
}

}  // namespace

raster::Scene random_scene(int side, int count, double radius, unsigned seed) {
  std::mt19937 rng(seed);
  raster::Scene s;
  s.width = s.height = side;
  random_triangles(s, count, radius, rng);
  return s;
}

std::string flat_mesh_json(int n) {
  std::mt19937 rng(1);
  std::string positions, indices, colors;
  char buf[96];
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = i / double(n) - 0.5, y = j / double(n) - 0.5;
      std::snprintf(buf, sizeof buf, "%s%.5f,%.5f,%.5f", positions.empty() ? "" : ",", x, y,
                    0.05 * std::sin(12 * x) * std::cos(9 * y));
      positions += buf;
      const raster::Rgba8 c = random_color(rng);
      std::snprintf(buf, sizeof buf, "%s\"#%02x%02x%02x\"", colors.empty() ? "" : ",", c.r, c.g, c.b);
      colors += buf;
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      std::snprintf(buf, sizeof buf, "%s%d,%d,%d,%d,%d,%d", indices.empty() ? "" : ",", a, b, d, a, d, c);
      indices += buf;
    }
  return R"({"width":1024,"height":1024,"primitives":[{"type":"mesh","positions":[)" + positions +
         R"(],"indices":[)" + indices + R"(],"colors":[)" + colors + "]}]}";
}

void add_triangle(raster::Scene& s, const raster::Point2 (&p)[3], const raster::Rgba8* colors, int ncolors) {
  raster::Primitive prim;
  prim.kind = raster::PrimitiveKind::triangle;
  prim.first_point = static_cast<std::uint32_t>(s.points.size());
  prim.point_count = 3;
  prim.first_color = static_cast<std::uint32_t>(s.colors.size());
  prim.per_vertex_color = ncolors == 3;
  s.points.insert(s.points.end(), p, p + 3);
  s.colors.insert(s.colors.end(), colors, colors + ncolors);
  s.primitives.push_back(prim);
}

void add_line(raster::Scene& s, raster::Point2 a, raster::Point2 b, raster::Rgba8 color, float width) {
  raster::Primitive prim;
  prim.kind = raster::PrimitiveKind::line;
  prim.first_point = static_cast<std::uint32_t>(s.points.size());
  prim.point_count = 2;
  prim.first_color = static_cast<std::uint32_t>(s.colors.size());
  prim.width = width;
  s.points.insert(s.points.end(), {a, b});
  s.colors.push_back(color);
  s.primitives.push_back(prim);
}

raster::Scene make_scene(const std::string& kind, unsigned seed) {
  std::mt19937 rng(seed);
  raster::Scene s;
  s.width = s.height = 1024;
  if (kind == "small") {
    random_triangles(s, 100'000, 12, rng);
  } else if (kind == "large") {
    random_triangles(s, 200, 340, rng);
  } else if (kind == "flat") {
    random_triangles(s, 200, 340, rng, 1);
  } else if (kind == "mid") {
    s.width = s.height = 512;
    random_triangles(s, 2'000, 30, rng);
  } else if (kind == "grid") {
    constexpr int n = 64;
    const double cell = 1024.0 / n;
    std::uniform_real_distribution<double> jitter(-cell * 0.25, cell * 0.25);
    std::vector<raster::Point2> v((n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const bool border = i == 0 || j == 0 || i == n || j == n;
        v[j * (n + 1) + i] = {i * cell + (border ? 0 : jitter(rng)), j * cell + (border ? 0 : jitter(rng))};
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const raster::Point2 a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1], c = v[(j + 1) * (n + 1) + i],
                             d = v[(j + 1) * (n + 1) + i + 1];
        const raster::Rgba8 c1 = random_color(rng), c2 = random_color(rng);
        add_triangle(s, {a, b, d}, &c1, 1);
        add_triangle(s, {a, d, c}, &c2, 1);
      }
  } else {
    throw std::invalid_argument("unknown scene kind '" + kind + "' (small, large, flat, grid, mid)");
  }
  return s;
}

std::string scene_json(const raster::Scene& s) {
  std::string out = "{\"width\":" + std::to_string(s.width) + ",\"height\":" + std::to_string(s.height) +
                    ",\"primitives\":[";
  char buf[64];
  auto color = [&](raster::Rgba8 c) {
    std::snprintf(buf, sizeof buf, "\"#%02x%02x%02x\"", c.r, c.g, c.b);
    return std::string(buf);
  };
  for (std::size_t i = 0; i < s.primitives.size(); ++i) {
    const raster::Primitive& p = s.primitives[i];
    out += i ? ",{\"type\":\"triangle\",\"points\":[" : "{\"type\":\"triangle\",\"points\":[";
    for (std::uint32_t k = 0; k < 3; ++k) {
      const raster::Point2& q = s.points[p.first_point + k];
      std::snprintf(buf, sizeof buf, "%s[%.3f,%.3f]", k ? "," : "", q.x, q.y);
      out += buf;
    }
    if (p.per_vertex_color) {
      out += "],\"colors\":[" + color(s.colors[p.first_color]) + "," + color(s.colors[p.first_color + 1]) +
             "," + color(s.colors[p.first_color + 2]) + "]}";
    } else {
      out += "],\"color\":" + color(s.colors[p.first_color]) + "}";
    }
  }
  return out + "]}";
}

}  // namespace bench

namespace bench {

raster::Scene mesh_scene(const std::string& kind, const std::string& bunny_path) {
  raster::Scene s;
  raster::Mesh mesh;
  if (kind == "triangles_1m") {  // issue 42's yardstick for points: a sphere of 999,698 triangles
    s.width = s.height = 1024;
    mesh = uv_sphere(707);
  } else if (kind == "points_1m") {  // the same sphere as 1,000,000 points, evenly spread (a Fibonacci
                                     // lattice), at the default point size
    s.width = s.height = 1024;
    constexpr int n = 1'000'000;
    const double golden = std::acos(-1.0) * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
      const double y = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - y * y), phi = golden * i;
      mesh.positions.push_back(raster::Vec3f(raster::Vec3{r * std::cos(phi), y, r * std::sin(phi)}));
      mesh.points.push_back(static_cast<std::uint32_t>(i));
    }
    mesh.colors = {{220, 200, 180, 255}};
  } else if (kind == "sphere") {
    s.width = s.height = 1024;
    mesh = uv_sphere(548);
  } else if (kind == "bunny") {
    s.width = s.height = 512;
    const char* env = std::getenv("RASTERD_BUNNY");
    const std::string path = env && *env ? env : bunny_path;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw std::runtime_error("cannot read " + path + " (set RASTERD_BUNNY)");
    std::string text;
    char buf[65536];
    for (std::size_t got; (got = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, got);
    std::fclose(f);
    mesh = raster::parse_obj(text);
    if (mesh.colors.empty()) mesh.colors = {{204, 204, 204, 255}};  // as the scene reader gives an OBJ
  } else {
    throw std::invalid_argument("unknown mesh scene: " + kind);
  }
  mesh.shading = raster::Shading::smooth;
  // No lights named: rasterd's default rig (ambient and two directional lights), lit per pixel, as a
  // model sent to the service is; the llvmpipe peer takes the same lights from the plan.
  s.meshes.push_back(std::move(mesh));
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.primitives.push_back(p);
  return s;
}

ModelFile read_model_file(const std::string& path) {
  namespace fs = std::filesystem;
  ModelFile model;
  model.bytes = read_bytes(path);
  model.format =
      raster::model_format_of(model.bytes, raster::format_of_file_name(fs::path(path).filename().string()));
  const raster::ModelFormatInfo& info = raster::model_format(model.format);
  const fs::path folder = fs::path(path).parent_path();
  for (int round = 0; round < info.file_rounds; ++round)  // OBJ: the libraries, then the textures they name
    for (const std::string& name : info.files(model.bytes, "", model.files)) {
      std::error_code error;
      if (!model.files.contains(name) && fs::is_regular_file(folder / name, error))
        model.files.emplace(name, read_bytes(folder / name));
    }
  return model;
}

}  // namespace bench
