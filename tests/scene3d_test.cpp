// 3D: camera, homogeneous clipping, depth, perspective-correct interpolation, lighting, OBJ models.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "base/vecmath.h"
#include "support.h"

namespace {

using nlohmann::json;
using test::kBlack;

raster::Image render_json(const json& scene, int threads = 1) {
  return test::render(raster::parse_scene(scene.dump()), threads);
}

json cube_mesh(double half, json colors, json transform = json::object()) {
  const double h = half;
  return {
      {"type", "mesh"},
      {"positions",
       {{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h}, {-h, -h, h}, {h, -h, h}, {h, h, h}, {-h, h, h}}},
      // counter-clockwise seen from outside; faces: -z, +z, -y, +y, -x, +x (two triangles each)
      {"indices",
       {{0, 2, 1},
        {0, 3, 2},
        {4, 5, 6},
        {4, 6, 7},
        {0, 1, 5},
        {0, 5, 4},
        {3, 7, 6},
        {3, 6, 2},
        {0, 4, 7},
        {0, 7, 3},
        {1, 2, 6},
        {1, 6, 5}}},
      {"colors", colors},
      {"shading", "unlit"},
      {"transform", transform}};
}

// An orthographic camera 4 units tall over 64 px: 16 px per unit. The unit cube's front face (z = +1)
// spans x, y in [-1, 1] -> pixels 16..47 exactly (edges on pixel boundaries, centres inside).
TEST(Scene3D, UnitCubeOrthographicCoversExactPixels) {
  json colors = json::array();
  for (int i = 0; i < 8; ++i)
    colors.push_back(i >= 4 ? "#ff0000" : "#0000ff");  // front (z = +1) red, back blue
  const json scene = {
      {"width", 64},
      {"height", 64},
      {"camera", {{"projection", "orthographic"}, {"eye", {0, 0, 10}}, {"target", {0, 0, 0}}, {"height", 4}}},
      {"primitives", {cube_mesh(1, colors)}}};
  const auto img = render_json(scene);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool inside = x >= 16 && x < 48 && y >= 16 && y < 48;
      ASSERT_EQ(test::pixel(img, x, y), inside ? test::kRed : kBlack)
          << x << "," << y << " (the near face hides the far one)";
    }
}

// A tetrahedron seen from above its apex: three side faces meet at the centre, each its own colour, and
// their areas are equal by symmetry (within the rasterization of their shared edges).
TEST(Scene3D, TetrahedronFacesAndDepth) {
  const double s = std::sqrt(3.0) / 2;
  json tet = {
      {"type", "mesh"},
      {"positions", {{0, 0, 1}, {1, 0, 0}, {-0.5, s, 0}, {-0.5, -s, 0}}},  // apex toward the camera on +z
      {"indices", {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}},
      {"shading", "unlit"}};
  // per-face colours through an OBJ-free route: one mesh per face colour would change depth order, so
  // use vertex colours that differ only at the base: each side face shows a distinct dominant colour.
  tet["colors"] = {"#ffffff", "#ff0000", "#00ff00", "#0000ff"};
  const json scene = {
      {"width", 96},
      {"height", 96},
      {"camera",
       {{"projection", "orthographic"}, {"eye", {0, 0, 5}}, {"target", {0, 0, 0}}, {"height", 2.5}}},
      {"primitives", {tet}}};
  const auto img = render_json(scene);
  // 2.5 units over 96 px: vertex (1, 0) lands at x = 48 + 38.4 = 86.4; the apex at the centre is white.
  const auto centre = test::pixel(img, 48, 48);
  EXPECT_GT(centre.r, 240);
  EXPECT_GT(centre.g, 240);
  EXPECT_GT(test::pixel(img, 84, 48).r, 200);  // near the red base vertex
  EXPECT_LT(test::pixel(img, 84, 48).g, 60);
  EXPECT_EQ(test::pixel(img, 90, 48), kBlack);  // just beyond it
  EXPECT_GT(test::pixel(img, 48 - 17, 48 - 31).g, 150)
      << "green base vertex (-0.5, +s) is up and left (y up)";
  EXPECT_GT(test::pixel(img, 48 - 17, 48 + 31).b, 150) << "blue base vertex (-0.5, -s) is down and left";
}

TEST(Scene3D, IntersectingTrianglesGiveTheSameImageInEitherOrder) {
  const json a = {
      {"type", "triangle"}, {"points", {{-1, -1, -1}, {1, -1, 1}, {0, 1, 0}}}, {"color", "#ff0000"}};
  const json b = {
      {"type", "triangle"}, {"points", {{-1, -1, 1}, {1, -1, -1}, {0, 0.8, 0}}}, {"color", "#00ff00"}};
  const json cam = {{"eye", {0.3, 0.2, 4}}, {"target", {0, 0, 0}}, {"fov", 50}};
  const auto ab = render_json({{"width", 80}, {"height", 80}, {"camera", cam}, {"primitives", {a, b}}});
  const auto ba = render_json({{"width", 80}, {"height", 80}, {"camera", cam}, {"primitives", {b, a}}});
  EXPECT_EQ(ab.pixels, ba.pixels);
  int red = 0, green = 0;
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 80; ++x) {
      red += test::pixel(ab, x, y) == test::kRed;
      green += test::pixel(ab, x, y) == test::kGreen;
    }
  EXPECT_GT(red, 300);
  EXPECT_GT(green, 300) << "each triangle is in front somewhere";
}

// Camera at the origin looking down -z, 90 degree fov on 64x64: pixel (i, j) looks along
// (x, y, -1) with x = (i + 0.5) / 32 - 1, y = 1 - (j + 0.5) / 32.
const json kPinhole = {{"eye", {0, 0, 0}}, {"target", {0, 0, -1}}, {"fov", 90}, {"near", 0.5}, {"far", 100}};

// A triangle on the floor y = -1 with one vertex behind the eye: only what lies beyond the near plane
// is drawn, all of it below the horizon, and exactly where the floor's ray hits the triangle.
TEST(Scene3D, TriangleCrossingTheNearPlaneDrawsOnlyItsVisiblePart) {
  const json tri = {
      {"type", "triangle"}, {"points", {{-3, -1, -6}, {3, -1, -6}, {0, -1, 4}}}, {"color", "#ffffff"}};
  const auto img = render_json({{"width", 64}, {"height", 64}, {"camera", kPinhole}, {"primitives", {tri}}});
  // Does the ray through image point (px, py) hit the visible part? The floor point it meets is
  // (x d, -1, -d) with d = -1 / y; the triangle's edges in the xz plane are, inside > 0:
  // z + 6 (edge A-B), 10 (3 - x) - 3 (z + 6) (edge B-C), 10 x - 3 z + 12 (edge C-A).
  auto visible = [](double px, double py) {
    const double x = px / 32 - 1, y = 1 - py / 32;
    if (y >= 0) return false;  // at or above the horizon
    const double d = -1 / y, wx = x * d, wz = -d;
    return d >= 0.5 && wz + 6 > 0 && 10 * (3 - wx) - 3 * (wz + 6) > 0 && 10 * wx - 3 * wz + 12 > 0;
  };
  int covered = 0, decided = 0;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const double cx = i + 0.5, cy = j + 0.5;
      const bool expect = visible(cx, cy);
      // Pixels whose neighbourhood straddles an edge may go either way; all others are decided.
      bool sure = true;
      for (auto [dx, dy] : {std::pair{0.5, 0.0}, {-0.5, 0.0}, {0.0, 0.5}, {0.0, -0.5}})
        sure = sure && visible(cx + dx, cy + dy) == expect;
      const bool got = test::pixel(img, i, j) == test::kWhite;
      covered += got;
      if (!sure) continue;
      ++decided;
      ASSERT_EQ(got, expect) << i << "," << j;
    }
  EXPECT_GT(covered, 300);
  EXPECT_GT(decided, 3500);
}

// A quad on the floor from 2 to 20 units away, red near and green far: the colour at each pixel is the
// linear blend at the world point it shows (perspective-correct), within 1/255.
TEST(Scene3D, RecedingQuadInterpolatesPerspectiveCorrectly) {
  const json quad = {{"type", "mesh"},
                     {"positions", {{-4, -1, -2}, {4, -1, -2}, {4, -1, -20}, {-4, -1, -20}}},
                     {"indices", {{0, 1, 2}, {0, 2, 3}}},
                     {"colors", {"#ff0000", "#ff0000", "#00ff00", "#00ff00"}},
                     {"shading", "unlit"}};
  const auto img = render_json({{"width", 64}, {"height", 64}, {"camera", kPinhole}, {"primitives", {quad}}});
  int checked = 0, worst = 0;
  for (int j = 33; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const double x = (i + 0.5) / 32 - 1, y = 1 - (j + 0.5) / 32;
      const double d = -1 / y, wx = x * d;
      if (d < 2.05 || d > 19.9 || std::abs(wx) > 3.95) continue;  // well inside the quad
      const double t = (d - 2) / 18;
      const auto c = test::pixel(img, i, j);
      worst = std::max({worst, static_cast<int>(std::lround(std::abs(c.r - 255 * (1 - t)))),
                        static_cast<int>(std::lround(std::abs(c.g - 255 * t)))});
      ++checked;
    }
  EXPECT_GT(checked, 200);
  EXPECT_LE(worst, 1) << "affine (screen-space) interpolation would be off by dozens of levels";
}

TEST(Scene3D, OrthographicKeepsSizesPerspectiveShrinksWithDistance) {
  json red = json::array(), green = json::array();
  for (int i = 0; i < 8; ++i) red.push_back("#ff0000"), green.push_back("#00ff00");
  auto scene = [&](const char* projection) {
    return json{{"width", 128},
                {"height", 64},
                {"camera", {{"projection", projection}, {"eye", {0, 0, 10}}, {"target", {0, 0, 0}}}},
                {"primitives",
                 {cube_mesh(0.5, red, {{"translate", {-1.5, 0, 2}}}),
                  cube_mesh(0.5, green, {{"translate", {1.5, 0, -4}}})}}};
  };
  auto count = [](const raster::Image& img, raster::Rgba8 c) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) n += test::pixel(img, x, y) == c;
    return n;
  };
  const auto ortho = render_json(scene("orthographic")), persp = render_json(scene("perspective"));
  EXPECT_NEAR(count(ortho, test::kRed), count(ortho, test::kGreen), 4);
  EXPECT_GT(count(persp, test::kRed), 2 * count(persp, test::kGreen))
      << "the nearer cube (12 units closer) looks bigger";
}

// The default camera frames all 3D content, whatever the image's aspect ratio.
TEST(Scene3D, DefaultCameraKeepsTheWholeModelInside) {
  const std::string bunny = test::read_file(RASTERD_MODELS_DIR "/bunny.obj");
  for (auto [w, h] : {std::pair{256, 256}, {400, 100}, {100, 400}}) {
    for (const char* projection : {"perspective", "orthographic"}) {
      const json scene = {{"width", w},
                          {"height", h},
                          {"camera", {{"projection", projection}}},
                          {"primitives", {{{"type", "obj"}, {"data", bunny}}}}};
      const auto img = render_json(scene);
      int x0 = w, x1 = -1, y0 = h, y1 = -1;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (!(test::pixel(img, x, y) == kBlack))
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      EXPECT_GT(x0, 0) << w << "x" << h << " " << projection;
      EXPECT_GT(y0, 0);
      EXPECT_LT(x1, w - 1);
      EXPECT_LT(y1, h - 1);
      EXPECT_GT(std::max(double(x1 - x0) / w, double(y1 - y0) / h), 0.5)
          << "framed, not lost in the distance";
    }
  }
}

// Projected 3D geometry is watertight too: a rotated grid seen in perspective, translucent white.
TEST(Scene3D, ProjectedGridIsWatertight) {
  constexpr int n = 12;
  json pos = json::array(), idx = json::array();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      pos.push_back({i - n / 2.0 + (border ? 0 : jitter(rng)), j - n / 2.0 + (border ? 0 : jitter(rng)), 0});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      idx.push_back({a, b, d});
      idx.push_back({a, d, c});
    }
  const json grid = {{"type", "mesh"},     {"positions", pos},
                     {"indices", idx},     {"color", "#ffffff80"},
                     {"shading", "unlit"}, {"transform", {{"rotate", {-50, 20, 10}}}}};
  const auto scene =
      raster::parse_scene(json{{"width", 160}, {"height", 120}, {"primitives", {grid}}}.dump());
  const auto plan = raster::plan(scene);
  const auto img = raster::render(scene, plan);
  // The grid's border is not jittered, so the union of its triangles is the projected square: project
  // its corners with the plan's own matrices.
  const raster::Mat4 m = raster::detail::operator*(plan.view.world_to_clip, scene.meshes[0].transform);
  double qx[4], qy[4];
  const double corner[4][2] = {
      {-n / 2.0, -n / 2.0}, {n / 2.0, -n / 2.0}, {n / 2.0, n / 2.0}, {-n / 2.0, n / 2.0}};
  for (int k = 0; k < 4; ++k) {
    const auto c = raster::detail::transform(m, {corner[k][0], corner[k][1], 0});
    qx[k] = (c.x / c.w + 1) * 80, qy[k] = (1 - c.y / c.w) * 60;
  }
  auto depth_inside = [&](double x, double y) {  // signed distance to the nearest edge of the convex quad
    double best = 1e9, sign = 0;
    for (int k = 0; k < 4; ++k) {
      const double ex = qx[(k + 1) % 4] - qx[k], ey = qy[(k + 1) % 4] - qy[k];
      const double d = (ex * (y - qy[k]) - ey * (x - qx[k])) / std::hypot(ex, ey);
      if (k == 0) sign = d >= 0 ? 1 : -1;  // either winding
      best = std::min(best, d * sign);
    }
    return best;
  };
  int hit = 0, interior = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x) {
      const int v = test::pixel(img, x, y).r;
      ASSERT_TRUE(v == 0 || v == 128) << "double hit at " << x << "," << y << ": " << v;
      hit += v == 128;
      if (depth_inside(x + 0.5, y + 0.5) > 1.0) {
        ++interior;
        ASSERT_EQ(v, 128) << "hole at " << x << "," << y;
      }
    }
  EXPECT_GT(interior, 1500);
  EXPECT_GE(hit, interior);
}

TEST(Scene3D, InvalidCamerasAreRejectedExtremeOnesRender) {
  const json tri = {{"type", "triangle"}, {"points", {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}}};
  auto with_camera = [&](const json& cam) {
    return json{{"width", 32}, {"height", 32}, {"camera", cam}, {"primitives", {tri}}}.dump();
  };
  struct Case {
    json camera;
    std::string pointer;
  };
  for (const Case& c : {Case{{{"eye", {0, 0, 3}}, {"target", {0, 0, 3}}}, "/camera/target"},
                        Case{{{"fov", 0}}, "/camera/fov"}, Case{{{"fov", 180}}, "/camera/fov"},
                        Case{{{"near", 5}, {"far", 5}}, "/camera/far"}, Case{{{"near", -1}}, "/camera/near"},
                        // up along the view: the named views turn with up, so only an eye can make it
                        Case{{{"eye", {0, 0, 3}}, {"up", {0, 0, 1}}}, "/camera/up"},
                        Case{{{"up", {0, 0, 0}}}, "/camera/up"}}) {
    try {
      const auto scene = raster::parse_scene(with_camera(c.camera));
      raster::plan(scene);
      ADD_FAILURE() << c.camera.dump() << " should be rejected";
    } catch (const raster::SceneError& e) {
      EXPECT_EQ(e.kind(), raster::ErrorKind::invalid) << c.camera.dump();
      EXPECT_EQ(e.where().pointer, c.pointer) << c.camera.dump() << ": " << e.what();
    }
  }
  // Extreme but valid: a tiny fov, near 1e-6 with far 1e6.
  EXPECT_GT(test::count_not(test::render(raster::parse_scene(with_camera({{"fov", 1e-3}}))), kBlack), 100);
  EXPECT_GT(
      test::count_not(test::render(raster::parse_scene(with_camera({{"near", 1e-6}, {"far", 1e6}}))), kBlack),
      100);
}

// The fitted near plane follows the content near the eye, not the farthest vertex: with the eye inside the
// content's box and one vertex 1e30 away, a near plane derived from `far` would clip everything.
TEST(Scene3D, FittedNearPlaneIgnoresAFarOutlier) {
  const json near_tri = {
      {"type", "triangle"}, {"points", {{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}}}, {"color", "#ff0000"}};
  const json outlier = {
      {"type", "triangle"}, {"points", {{0, 0, -1e30}, {0, 0, 10}, {1, 0, 10}}}, {"color", "#00ff00"}};
  const json cam = {{"eye", {0, 0, 0}}, {"target", {0, 0, -1}}};
  const auto scene = raster::parse_scene(
      json{{"width", 32}, {"height", 32}, {"camera", cam}, {"primitives", {near_tri, outlier}}}.dump());
  const auto plan = raster::plan(scene);
  EXPECT_LT(plan.view.near, 5) << "near " << plan.view.near << ", far " << plan.view.far;
  EXPECT_EQ(test::pixel(test::render(scene), 16, 16), test::kRed);
}

// Reversed float depth keeps its relative precision: two surfaces 1% apart in distance are ordered
// correctly at every range from 1e-3 to 1e5 with near = 1e-6 and far = 1e6.
TEST(Scene3D, DepthOrdersSurfacesOnePercentApartAcrossTheRange) {
  for (double d : {1e-3, 1.0, 1e3, 1e5}) {
    auto square = [&](double dist, const char* color) {
      const double h = dist * 0.5;  // fills the middle of a 90 degree view
      return json{{"type", "mesh"},
                  {"positions", {{-h, -h, -dist}, {h, -h, -dist}, {h, h, -dist}, {-h, h, -dist}}},
                  {"indices", {{0, 1, 2}, {0, 2, 3}}},
                  {"color", color},
                  {"shading", "unlit"}};
    };
    const json cam = {{"eye", {0, 0, 0}}, {"target", {0, 0, -1}}, {"fov", 90}, {"near", 1e-6}, {"far", 1e6}};
    // far one drawn last: it must lose everywhere
    const auto img = render_json({{"width", 16},
                                  {"height", 16},
                                  {"camera", cam},
                                  {"primitives", {square(d, "#ff0000"), square(d * 1.01, "#00ff00")}}});
    EXPECT_EQ(test::pixel(img, 8, 8), test::kRed) << "distance " << d;
  }
}

TEST(Scene3D, LightingFollowsTheNormalAndTheLight) {
  // A square facing +z, lit from straight ahead: full brightness; lit edge-on: ambient only.
  auto lit = [](json light) {
    const json sq = {{"type", "mesh"},
                     {"positions", {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}},
                     {"indices", {{0, 1, 2}, {0, 2, 3}}},
                     {"color", "#c8c8c8"},
                     {"shading", "flat"}};
    return test::pixel(render_json({{"width", 16}, {"height", 16}, {"light", light}, {"primitives", {sq}}}),
                       8, 8)
        .r;
  };
  EXPECT_EQ(lit({{"direction", {0, 0, -1}}, {"ambient", 0.2}}), 200);
  EXPECT_EQ(lit({{"direction", {1, 0, 0}}, {"ambient", 0.25}}), 50);
  EXPECT_EQ(lit({{"direction", {0, -1, -1}}, {"ambient", 0}}), 141);  // 200 cos 45
}

// --- OBJ models ---------------------------------------------------------------------------------------

raster::SceneError obj_error(const std::string& obj) {
  try {
    raster::parse_obj(obj);
  } catch (const raster::SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an error for:\n" << obj;
  return raster::SceneError(raster::ErrorKind::model, "none");
}

TEST(Obj, BadIndicesAreModelErrorsNamingTheLine) {
  struct Case {
    const char* obj;
    std::size_t line;
  };
  for (const Case& c : {Case{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n",
                             4},  // relative index before the first vertex (CVE-2020-28589)
                        Case{"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n", 5},  // past the last vertex
                        Case{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", 4},    // OBJ indices start at 1
                        Case{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", 4},
                        Case{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", 4},
                        Case{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", 4},  // normal never defined
                        Case{"f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", 1},           // used before defined
                        Case{"v 0 0 0\nv 1 0 0\nf 1 2\n", 3}, Case{"v 0 0 nan\n", 1}, Case{"v 0 0\n", 1}}) {
    const auto e = obj_error(c.obj);
    EXPECT_EQ(e.kind(), raster::ErrorKind::model) << c.obj;
    EXPECT_EQ(e.where().line, c.line) << c.obj << e.what();
  }
}

TEST(Obj, EmptyPointsOnlyAndLinesOnlyModels) {
  EXPECT_EQ(obj_error("").kind(), raster::ErrorKind::model);
  EXPECT_EQ(obj_error("# nothing\n").kind(), raster::ErrorKind::model);
  // Points only: drawn as points (issue 42; points_test.cpp has the details).
  EXPECT_EQ(raster::parse_obj("v 0 0 0\nv 1 1 1\np 1 2\n").points, (std::vector<std::uint32_t>{0, 1}));
  const raster::Mesh lines = raster::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3\n");
  EXPECT_EQ(lines.segments.size(), 2u);
  EXPECT_TRUE(lines.triangles.empty());
  const auto img =
      render_json({{"width", 32},
                   {"height", 32},
                   {"primitives", {{{"type", "obj"}, {"data", "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3\n"}}}}});
  EXPECT_GT(test::count_not(img, kBlack), 20) << "a lines-only model draws its lines";
}

TEST(Obj, TooManyFacesIsALimitError) {
  raster::Limits limits;
  limits.max_model_faces = 2;
  try {
    raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\nf 1 2 3\n", {}, limits);
    FAIL();
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::limit);
    EXPECT_EQ(e.where().line, 6u);
  }
}

TEST(Obj, PolygonsTriangulateAndAttributesAreKept) {
  const raster::Mesh quad = raster::parse_obj(
      "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 1 1 1\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n");
  EXPECT_EQ(quad.triangles.size(), 2u);
  ASSERT_EQ(quad.colors.size(), 4u) << "v x y z r g b colours are honoured";
  EXPECT_EQ(quad.colors[1], test::kGreen);
  EXPECT_EQ(quad.normal_triangles.size(), 2u) << "vn are used when every face has them";
  // relative (negative) indices resolve against the vertices defined so far
  EXPECT_EQ(raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n").triangles[0],
            (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST(Obj, MaterialsComeOnlyFromTheUploadedMtl) {
  // `mtllib` names a path; the text read is the uploaded MTL, never a file.
  const std::string obj = "mtllib /etc/passwd\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const raster::Mesh with = raster::parse_obj(obj, "newmtl red\nKd 1 0 0\n");
  ASSERT_EQ(with.face_colors.size(), 1u);
  EXPECT_EQ(with.face_colors[0], test::kRed);
  const raster::Mesh without = raster::parse_obj(obj);
  EXPECT_TRUE(without.face_colors.empty());
}

TEST(Obj, FlatAndSmoothShadingOfTheBunny) {
  const std::string bunny = test::read_file(RASTERD_MODELS_DIR "/bunny.obj");
  auto scene = [&](const char* shading) {
    return json{{"width", 128},
                {"height", 128},
                {"primitives", {{{"type", "obj"}, {"data", bunny}, {"shading", shading}}}}};
  };
  const auto smooth_plan = raster::plan(raster::parse_scene(scene("smooth").dump()));
  EXPECT_TRUE(smooth_plan.depth_buffer);
  EXPECT_EQ(smooth_plan.memory.depth_bytes, 128 * 128 * 4);
  EXPECT_TRUE(smooth_plan.draw_of(0)->mode.lit);
  EXPECT_TRUE(smooth_plan.draw_of(0)->mode.compute_normals) << "the bunny has no vn";
  EXPECT_TRUE(smooth_plan.draw_of(0)->mode.varyings.has(raster::Varying::normal));
  const auto flat_plan = raster::plan(raster::parse_scene(scene("flat").dump()));
  EXPECT_FALSE(flat_plan.draw_of(0)->mode.varyings.has(raster::Varying::normal))
      << "flat: one Lambert term per face";
  EXPECT_FALSE(flat_plan.draw_of(0)->mode.compute_normals) << "face normals only; no vertex normals computed";
  EXPECT_EQ(smooth_plan.format, raster::PixelFormat::grey8) << "light grey, lit, stays grey";
  const auto smooth = render_json(scene("smooth")), flat = render_json(scene("flat")),
             unlit = render_json(scene("unlit"));
  EXPECT_EQ(test::count_not(smooth, kBlack), test::count_not(flat, kBlack))
      << "shading changes colours, not coverage";
  EXPECT_EQ(test::count_not(smooth, kBlack), test::count_not(unlit, kBlack));
  EXPECT_NE(smooth.pixels, flat.pixels);
  // unlit: every covered pixel is the default light grey
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const auto c = test::pixel(unlit, x, y);
      ASSERT_TRUE(c == kBlack || c == (raster::Rgba8{204, 204, 204, 255}));
    }
  // one band or two: same bytes for 3D too
  EXPECT_EQ(render_json(scene("smooth"), 1).pixels, render_json(scene("smooth"), 2).pixels);
}

TEST(Obj, SourceNamesAnUploadedPart) {
  raster::Uploads uploads{{"model", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n"},
                          {"mtl", "newmtl m\nKd 0 0 1\n"}};
  uploads["model"] = "mtllib any.mtl\n" + uploads["model"];
  const auto s = raster::parse_scene(
      R"({"width": 8, "height": 8, "primitives": [{"type": "obj", "source": "model"}]})", {}, uploads);
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.meshes[0].face_colors.size(), 1u);
  EXPECT_EQ(s.meshes[0].face_colors[0], test::kBlue) << "an uploaded part named mtl goes with the model";
  try {
    raster::parse_scene(R"({"width": 8, "height": 8, "primitives": [{"type": "obj", "source": "nope"}]})", {},
                        uploads);
    FAIL();
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.where().pointer, "/primitives/0/source");
  }
  try {
    raster::parse_scene(
        R"({"width": 8, "height": 8, "primitives": [{"type": "obj", "data": "v 0 0 0\nf 1 1 9\n"}]})");
    FAIL();
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::model);
    EXPECT_EQ(e.where().pointer, "/primitives/0");
    EXPECT_EQ(e.where().line, 2u);
  }
}

}  // namespace

namespace {

// w = 0 (a vertex exactly at the eye), w < 0 (behind it) and coordinates a user matrix pushes past the
// double range: clipped or dropped, never divided by zero, never a NaN cast to an integer (the sanitizer
// build checks float-cast-overflow).
TEST(Scene3D, DegenerateAndOverflowingGeometryIsClippedOrDropped) {
  const json at_eye = {
      {"type", "triangle"}, {"points", {{0, 0, 0}, {1, -1, -3}, {-1, -1, -3}}}, {"color", "#ffffff"}};
  const json behind = {
      {"type", "triangle"}, {"points", {{0, 1, 5}, {1, -1, -3}, {-1, -1, -3}}}, {"color", "#ffffff"}};
  // With a vertex at the eye, the eye lies in the triangle's plane: it is seen edge-on and covers nothing.
  EXPECT_EQ(test::count_not(
                render_json({{"width", 32}, {"height", 32}, {"camera", kPinhole}, {"primitives", {at_eye}}}),
                kBlack),
            0);
  const auto img_behind =
      render_json({{"width", 32}, {"height", 32}, {"camera", kPinhole}, {"primitives", {behind}}});
  EXPECT_GT(test::count_not(img_behind, kBlack), 50);
  EXPECT_EQ(test::pixel(img_behind, 16, 0), kBlack) << "nothing from behind the eye wraps around to the top";
  const json overflow = {
      {"type", "mesh"},
      {"positions", {{-1e30, 0, 0}, {1e30, 0, 0}, {0, 1e30, 0}, {0, 0, 1}}},
      {"indices", {{0, 1, 2}, {0, 1, 3}}},
      {"transform", {{"matrix", {1e300, 0, 0, 0, 0, 1e300, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}}}};
  const json fine = {
      {"type", "triangle"}, {"points", {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}}, {"color", "#ff0000"}};
  const auto img = render_json({{"width", 32},
                                {"height", 32},
                                {"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}}},
                                {"primitives", {overflow, fine}}});
  EXPECT_EQ(test::pixel(img, 16, 16), test::kRed) << "the finite triangle still renders";
}

}  // namespace
