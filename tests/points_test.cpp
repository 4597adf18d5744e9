// Point clouds (scene.h: Mesh::points): round points of a size in pixels, depth-tested, in their vertex
// colours, anti-aliased as the rest of the render is; the readers' points paths; the limit on points.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "model_files.h"
#include "raster/model.h"
#include "support.h"

namespace {

using raster::ErrorKind;
using raster::Mesh;
using raster::Rgba8;
using raster::Vec3;
using test::kBlack;

// An orthographic camera looking down -z at the origin, 4 units tall over 64 px: 16 px a unit, so world
// (x, y) lands on pixel coordinates (32 + 16 x, 32 - 16 y). The near and far planes are fitted to the
// content.
raster::Scene scene_of(std::vector<Mesh> meshes, int size = 64) {
  raster::Scene s;
  s.width = s.height = size;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    s.meshes.push_back(std::move(meshes[i]));
    raster::Primitive p;
    p.kind = raster::PrimitiveKind::mesh;
    p.mesh = static_cast<std::uint32_t>(i);
    s.primitives.push_back(p);
  }
  s.camera.projection = raster::Projection::orthographic;
  s.camera.eye = {0, 0, 10}, s.camera.has_eye = true;
  s.camera.target = {0, 0, 0}, s.camera.has_target = true;
  s.camera.height = 4, s.camera.has_height = true;
  return s;
}

// The world position whose projection is image point (px, py) in the 64 px view of scene_of.
Vec3 at_pixel(double px, double py, double z = 0) {
  return {(px - 32) / 16, (32 - py) / 16, z};
}

// A point cloud of the given image points (pixel coordinates), one colour each.
Mesh cloud(const std::vector<std::array<double, 3>>& points, const std::vector<Rgba8>& colors, float size) {
  Mesh m;
  for (const auto& p : points) {
    m.points.push_back(static_cast<std::uint32_t>(m.positions.size()));
    m.positions.push_back(raster::Vec3f(at_pixel(p[0], p[1], p[2])));
  }
  m.colors = colors;
  m.point_size = size;
  return m;
}

// A square at depth z covering the image points [x0, x1] x [y0, y1], one colour, unlit.
Mesh square(double x0, double y0, double x1, double y1, double z, Rgba8 color) {
  Mesh m;
  for (const raster::Vec3& p :
       {at_pixel(x0, y1, z), at_pixel(x1, y1, z), at_pixel(x1, y0, z), at_pixel(x0, y0, z)})
    m.positions.push_back(raster::Vec3f(p));
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.colors = {color};
  m.shading = raster::Shading::unlit;
  return m;
}

// Aliased: a pixel is the point's exactly when its centre lies within size / 2 of the projected position.
// Points of several sizes at a pixel centre, a pixel corner and an arbitrary position: each covers those
// pixels and nothing else (a disc, not a square: 4 px across covers 13 pixels, not 16).
TEST(Points, AliasedPointsCoverThePixelsWhoseCentresAreInTheirDiscs) {
  struct Case {
    double x, y;
    float size;
  };
  for (const Case c : {Case{20.5, 20.5, 4}, Case{40, 24, 3}, Case{24.3, 41.7, 5.5}, Case{44.5, 44.5, 1},
                       Case{10.5, 50.5, 3}}) {
    const raster::Image image = test::render(scene_of({cloud({{c.x, c.y, 0}}, {test::kRed}, c.size)}));
    int covered = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const double dx = x + 0.5 - c.x, dy = y + 0.5 - c.y;
        const bool inside = dx * dx + dy * dy <= c.size * c.size / 4;
        covered += inside;
        ASSERT_EQ(test::pixel(image, x, y), inside ? test::kRed : kBlack)
            << "point at " << c.x << "," << c.y << " size " << c.size << ": pixel " << x << "," << y;
      }
    EXPECT_GT(covered, 0);
    if (c.size == 4) {
      EXPECT_EQ(covered, 13) << "round: the corners of the 4x4 square are not covered";
    }
  }
}

// Points are depth-tested against triangles in both orders: a point in front of a square shows whether it is
// drawn before or after the square, one behind it is hidden either way; beside the square both show.
TEST(Points, PointsAreDepthTestedAgainstTriangles) {
  const Rgba8 blue = test::kBlue;
  const Mesh points = cloud({{24.5, 32.5, 0.5}, {40.5, 32.5, -0.5}, {56.5, 32.5, -0.5}},
                            {test::kRed, test::kGreen, test::kWhite}, 3);
  const Mesh quad = square(16, 16, 48, 48, 0, blue);
  for (const bool points_first : {true, false}) {
    const raster::Image image = test::render(
        scene_of(points_first ? std::vector<Mesh>{points, quad} : std::vector<Mesh>{quad, points}));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        EXPECT_EQ(test::pixel(image, 24 + dx, 32 + dy), test::kRed) << "in front: shown, " << points_first;
        EXPECT_EQ(test::pixel(image, 40 + dx, 32 + dy), blue) << "behind: hidden, " << points_first;
        EXPECT_EQ(test::pixel(image, 56 + dx, 32 + dy), test::kWhite) << "beside: shown, " << points_first;
      }
    EXPECT_EQ(test::pixel(image, 58, 32), kBlack) << "nothing beyond the disc";
  }
}

// Each point takes its own vertex's colour; one colour for the mesh colours them all.
TEST(Points, VertexColoursColourThePoints) {
  const std::vector<Rgba8> colors = {
      {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {200, 100, 50, 255}};
  const raster::Image image = test::render(scene_of(
      {cloud({{10.5, 10.5, 0}, {50.5, 10.5, 0.1}, {10.5, 50.5, -0.1}, {50.5, 50.5, 0.2}}, colors, 2)}));
  EXPECT_EQ(test::pixel(image, 10, 10), colors[0]);
  EXPECT_EQ(test::pixel(image, 50, 10), colors[1]);
  EXPECT_EQ(test::pixel(image, 10, 50), colors[2]);
  EXPECT_EQ(test::pixel(image, 50, 50), colors[3]);
  const raster::Image one =
      test::render(scene_of({cloud({{10.5, 10.5, 0}, {50.5, 50.5, 0}}, {colors[3]}, 2)}));
  EXPECT_EQ(test::pixel(one, 10, 10), colors[3]);
  EXPECT_EQ(test::pixel(one, 50, 50), colors[3]);
}

// The plan counts the points and lights none of them (points carry no normals); a mesh of faces and points
// lights its faces alone.
TEST(Points, ThePlanCountsPointsAndLightsNone) {
  const raster::Scene cloud_only = scene_of({cloud({{10.5, 10.5, 0}, {50.5, 50.5, 0}}, {test::kWhite}, 3)});
  const raster::RenderPlan plan = raster::plan(cloud_only);
  EXPECT_EQ(plan.points_3d, 2);
  EXPECT_EQ(plan.lit_count, 0);
  EXPECT_NE(raster::explain_json(plan).find("\"points_3d\": 2"), std::string::npos)
      << raster::explain_json(plan);
  const Rgba8 colour{200, 100, 50, 255};
  Mesh both = square(16, 16, 48, 48, 0, colour);
  both.shading = raster::Shading::smooth;
  both.points = {0};
  const raster::RenderPlan lit = raster::plan(scene_of({both}));
  EXPECT_EQ(lit.lit_count, 1);
  EXPECT_EQ(lit.points_3d, 1);
  // The point at the square's corner (16, 48) keeps its own colour, unlit, beside the square (at the square's
  // own depth it loses the tie to the square drawn first); the lit square is not that colour.
  const raster::Image image = test::render(scene_of({both}));
  EXPECT_EQ(test::pixel(image, 15, 48), colour);
  EXPECT_EQ(test::pixel(image, 14, 48), kBlack);
  EXPECT_NE(test::pixel(image, 32, 32), colour);
}

// Multisampled, a point's rim pixels are partly covered (some of their samples are in the disc): between the
// background and the point's colour. Its centre pixel is whole, and a pixel with no sample in the disc is
// untouched. The covered pixels are those with a sample in the disc.
TEST(Points, MultisamplingGivesPartialCoverageOnTheRim) {
  for (const int samples : {4, 8, 16}) {
    raster::Scene s = scene_of({cloud({{32.3, 31.8, 0}}, {test::kWhite}, 5)});
    s.antialias = test::multisample(samples);
    const raster::Image image = test::render(s);
    EXPECT_EQ(test::pixel(image, 32, 31), test::kWhite) << samples;
    int partial = 0, touched = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const std::uint8_t v = test::pixel(image, x, y).r;
        partial += v > 0 && v < 255;
        touched += v > 0;
        // 2.5 px radius plus a pixel's half-diagonal: nothing beyond can hold a covered sample.
        const double dx = x + 0.5 - 32.3, dy = y + 0.5 - 31.8;
        if (dx * dx + dy * dy > (2.5 + 0.75) * (2.5 + 0.75)) {
          ASSERT_EQ(v, 0) << x << "," << y;
        }
      }
    EXPECT_GT(partial, 4) << samples << " samples: the rim is anti-aliased";
    EXPECT_GT(touched, partial);
  }
  // "area" multisamples 3D content (at 8 samples): points included.
  raster::Scene area = scene_of({cloud({{32.3, 31.8, 0}}, {test::kWhite}, 5)}), eight = area;
  area.antialias = raster::Antialias::area, eight.antialias = raster::Antialias::msaa8;
  EXPECT_EQ(test::render(area).pixels, test::render(eight).pixels);
}

// A cloud too large for one tile, aliased and multisampled: the same bytes at one thread and two.
TEST(Points, SameBytesAtOneAndTwoThreads) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 520), z(-1, 1);
  std::vector<std::array<double, 3>> points;
  std::vector<Rgba8> colors;
  for (int i = 0; i < 20000; ++i) {
    points.push_back({u(rng), u(rng), z(rng)});
    colors.push_back({static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i >> 8), 90,
                      static_cast<std::uint8_t>(i % 7 == 0 ? 128 : 255)});
  }
  for (const raster::Antialias aa : {raster::Antialias::none, raster::Antialias::msaa4}) {
    raster::Scene s =
        scene_of({cloud(points, colors, 3.5f), square(100, 100, 300, 300, 0, test::kBlue)}, 512);
    s.camera.height = 4 * 512 / 64.0;  // 16 px a unit as before, about the image's centre
    s.antialias = aa;
    for (auto& p : s.meshes[0].positions) p.x -= 14, p.y += 14;  // (32, 32) -> (256, 256)
    for (auto& p : s.meshes[1].positions) p.x -= 14, p.y += 14;
    const raster::Image one = test::render(s, 1), two = test::render(s, 2);
    EXPECT_EQ(raster::plan(s, {}, {.max_threads = 2}).threads, 2);
    EXPECT_EQ(one.pixels, two.pixels) << "antialias " << static_cast<int>(aa);
    EXPECT_GT(test::count_not(one, kBlack), 100000);
  }
}

// Points beyond the near or far plane are clipped whole; one outside the image draws the part of its disc
// inside it.
TEST(Points, PointsBeyondTheClipPlanesAreDroppedAndTheImageEdgeClips) {
  raster::Scene s = scene_of({cloud({{0.5, 32.5, 0}, {32.5, 32.5, 20}, {48.5, 32.5, 0}}, {test::kRed}, 5)});
  s.camera.near = 5, s.camera.has_near = true;  // the eye is at z = 10: z = 20 lies behind it
  s.camera.far = 15, s.camera.has_far = true;
  const raster::Image image = test::render(s);
  EXPECT_EQ(test::pixel(image, 0, 32), test::kRed);
  EXPECT_EQ(test::pixel(image, 2, 32), test::kRed);
  EXPECT_EQ(test::pixel(image, 32, 32), kBlack) << "behind the eye: not drawn";
  EXPECT_EQ(test::pixel(image, 48, 32), test::kRed);
}

// ---- The readers ----------------------------------------------------------------------------------------

std::vector<std::uint32_t> iota(std::uint32_t n) {
  std::vector<std::uint32_t> v(n);
  for (std::uint32_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

template <typename Read>
void expect_error(Read read, ErrorKind kind, const std::string& words) {
  try {
    read();
    ADD_FAILURE() << "expected an error with \"" << words << "\"";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

// A bare model as the service draws one (a scene of one model primitive, its defaults), 64 px square.
raster::Image render_model(const std::string& bytes) {
  return test::render(
      raster::parse_scene(R"({"width": 64, "height": 64, "primitives": [{"type": "model", "source": "m"}]})",
                          {}, {{"m", bytes}}));
}

const std::string kPlyCloud =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
    "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n";

TEST(Points, PlyWithoutFacesIsAPointCloud) {
  const Mesh m = raster::parse_ply(kPlyCloud);
  EXPECT_TRUE(m.triangles.empty());
  EXPECT_EQ(m.points, iota(3));
  ASSERT_EQ(m.colors.size(), 3u);
  EXPECT_EQ(m.colors[1], test::kGreen);
  // A face element of no entries is no faces either.
  std::string empty_faces = kPlyCloud;
  empty_faces.replace(empty_faces.find("end_header"), 0,
                      "element face 0\nproperty list uchar int vertex_indices\n");
  EXPECT_EQ(raster::parse_ply(empty_faces).points, iota(3));
  raster::Limits limits;
  limits.max_model_points = 2;
  expect_error([&] { raster::parse_ply(kPlyCloud, limits); }, ErrorKind::limit, "more than 2 points");
  std::string none = kPlyCloud;
  none.replace(none.find("vertex 3"), 8, "vertex 0");
  none.resize(none.find("end_header\n") + 11);
  expect_error([&] { raster::parse_ply(none); }, ErrorKind::model, "no vertices");
}

TEST(Points, AssimpPointsPlyRenders) {
  const std::string path = "/usr/share/assimp/models/PLY/points.ply";
  const std::string bytes = test::read_file(path);
  const Mesh m = raster::parse_ply(bytes);
  EXPECT_EQ(m.points, iota(4));
  EXPECT_TRUE(m.normals.empty()) << "points are unlit: their normals are not kept";
  const raster::Image image = render_model(bytes);
  EXPECT_GT(test::count_not(image, test::pixel(image, 0, 0)), 4);
}

TEST(Points, ObjOfOnlyVerticesAndObjPointStatements) {
  const Mesh only_v = raster::parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\n");
  EXPECT_EQ(only_v.points, iota(3));
  EXPECT_TRUE(only_v.triangles.empty());
  ASSERT_EQ(only_v.colors.size(), 3u) << "v x y z r g b colours colour the points";
  EXPECT_EQ(only_v.colors[2], test::kBlue);
  // 'p' names the points: only those are drawn (with the faces, when there are any).
  const Mesh p = raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\np 4 2\np -1\n");
  EXPECT_EQ(p.points, (std::vector<std::uint32_t>{3, 1, 3}));
  const Mesh both = raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\np 4\n");
  EXPECT_EQ(both.triangles.size(), 1u);
  EXPECT_EQ(both.points, (std::vector<std::uint32_t>{3}));
  raster::Limits limits;
  limits.max_model_points = 2;
  expect_error([&] { raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\n", {}, limits); }, ErrorKind::limit,
               "more than 2 points");
  try {
    raster::parse_obj("v 0 0 0\np 1 1\np 1\n", {}, limits);
    ADD_FAILURE() << "three points over a limit of two";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::limit);
    EXPECT_EQ(e.where().line, 3u) << "the line that passes the limit";
  }
  expect_error([&] { raster::parse_obj("# nothing\n"); }, ErrorKind::model, "no vertices");
  expect_error([&] { raster::parse_obj("v 0 0 0\np 2\n"); }, ErrorKind::model, "out of range");
}

// A glTF primitive of mode POINTS (0): its vertices become points, coloured by its material.
std::string gltf_points(int mode, int count) {
  std::string buffer;
  for (int i = 0; i < count; ++i)
    for (float v : {static_cast<float>(i), 0.f, 0.f}) test::put<float>(buffer, v);
  return R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [
      {"attributes": {"POSITION": 0}, "mode": )" +
         std::to_string(mode) + R"(, "material": 0}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
         std::to_string(count) + R"(, "type": "VEC3", "min": [0, 0, 0], "max": [)" +
         std::to_string(count - 1) +
         R"(, 0, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": )" +
         std::to_string(buffer.size()) + R"(}],
    "buffers": [{"byteLength": )" +
         std::to_string(buffer.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
         test::base64(buffer) + R"("}]})";
}

TEST(Points, GltfPointsPrimitives) {
  const Mesh m = raster::parse_gltf(gltf_points(0, 5));
  EXPECT_EQ(m.points, iota(5));
  EXPECT_TRUE(m.triangles.empty());
  EXPECT_EQ(m.colors, std::vector<Rgba8>{test::kRed});
  raster::Limits limits;
  limits.max_model_points = 4;
  expect_error([&] { raster::parse_gltf(gltf_points(0, 5), limits); }, ErrorKind::limit,
               "more than 4 points");
  const raster::Image image = render_model(gltf_points(0, 5));
  EXPECT_GT(test::count_not(image, test::pixel(image, 0, 0)), 5);
}

}  // namespace
