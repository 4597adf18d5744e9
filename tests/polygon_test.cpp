// Faces of more than three corners (renderer/src/model/polygon.h), as OBJ and PLY split them: seeded random
// simple polygons, concave ones too, tilted anywhere in space and far from the origin, become n - 2 triangles
// that all turn as the polygon does and add up to its area (a fan over a concave polygon has triangles that
// turn the other way); degenerate polygons still end; a face whose splitting would take hours is refused.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "model/polygon.h"
#include "raster/model.h"

namespace {

using raster::Vec3;

Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// A star-shaped polygon (simple by construction: radii at increasing angles around a centre), mostly
// concave, in the plane spanned by u and v around `centre`; its 2D corners in `flat`.
std::vector<Vec3> star(std::mt19937& rng, int n, Vec3 centre, Vec3 u, Vec3 v,
                       std::vector<std::array<double, 2>>& flat) {
  std::uniform_real_distribution<double> radius(0.2, 1.0), jitter(0.1, 0.9);
  std::vector<Vec3> out;
  flat.clear();
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * (k + jitter(rng)) / n, r = radius(rng);
    const double x = r * std::cos(a), y = r * std::sin(a);
    flat.push_back({x, y});
    out.push_back({centre.x + x * u.x + y * v.x, centre.y + x * u.y + y * v.y, centre.z + x * u.z + y * v.z});
  }
  return out;
}

TEST(Polygon, SimplePolygonsBecomeTrianglesThatCoverThemExactly) {
  std::mt19937 rng(20261126);
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 5 + static_cast<int>(rng() % 60);
    // A random orthonormal frame far from the origin.
    Vec3 u{gauss(rng), gauss(rng), gauss(rng)}, w{gauss(rng), gauss(rng), gauss(rng)};
    u = {u.x / std::sqrt(dot(u, u)), u.y / std::sqrt(dot(u, u)), u.z / std::sqrt(dot(u, u))};
    Vec3 v = cross(w, u);
    v = {v.x / std::sqrt(dot(v, v)), v.y / std::sqrt(dot(v, v)), v.z / std::sqrt(dot(v, v))};
    const Vec3 centre{1000 * gauss(rng), 1000 * gauss(rng), 1000 * gauss(rng)};
    std::vector<std::array<double, 2>> flat;
    const std::vector<Vec3> corners = star(rng, n, centre, u, v, flat);
    raster::PolygonSplitter splitter;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    splitter.split(corners, triangles);
    SCOPED_TRACE(trial);
    ASSERT_EQ(triangles.size(), static_cast<std::size_t>(n - 2));
    double area = 0;  // the polygon's, by the shoelace formula
    for (int k = 0; k < n; ++k) area += flat[k][0] * flat[(k + 1) % n][1] - flat[(k + 1) % n][0] * flat[k][1];
    double sum = 0;
    for (const auto& t : triangles) {
      const auto &a = flat[t[0]], &b = flat[t[1]], &c = flat[t[2]];
      const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      EXPECT_GE(twice, -1e-12) << "a triangle turns against the polygon";
      sum += twice;
    }
    EXPECT_NEAR(sum, area, 1e-9 * std::fabs(area));
  }
}

TEST(Polygon, DegeneratePolygonsStillEnd) {
  std::vector<Vec3> line;
  for (int k = 0; k < 50; ++k) line.push_back({static_cast<double>(k), 2.0 * k, 0});
  std::vector<Vec3> point(50, Vec3{1, 2, 3});
  for (const auto* corners : {&line, &point}) {
    raster::PolygonSplitter splitter;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    splitter.split(*corners, triangles);
    EXPECT_EQ(triangles.size(), 48u);
    for (const auto& t : triangles)
      for (std::uint32_t i : t) EXPECT_LT(i, 50u);
  }
}

// tinyobjloader 2.0.0~rc10 split this star (1,022 corners, away from the origin) into 528 triangles and
// dropped the rest; a face of 200,000 corners, half of them reflex, is refused instead of taking hours.
TEST(Polygon, ObjFacesAreSplitWholeAndHugeOnesAreRefused) {
  auto star_obj = [](int n) {
    std::string s;
    char line[96];
    for (int k = 0; k < n; ++k) {
      // Centred near (10, 10): a mesh holds floats, which still tell 200,000 corners' turns apart there.
      const double a = 2 * M_PI * k / n, r = k % 2 ? 1.0 : 0.9;
      std::snprintf(line, sizeof line, "v %.9g %.9g 0\n", 10 + r * std::cos(a), 10 + r * std::sin(a));
      s += line;
    }
    s += "f";
    for (int k = 1; k <= n; ++k) s.append(" ").append(std::to_string(k));
    return s + "\n";
  };
  EXPECT_EQ(raster::parse_obj(star_obj(1024)).triangles.size(), 1022u);
  try {
    raster::parse_obj(star_obj(200000));
    ADD_FAILURE() << "a face of 200,000 corners was split";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::limit);
    EXPECT_NE(std::string(e.what()).find("a face of 200000 corners, 100000 of them reflex"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
