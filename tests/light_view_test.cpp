// Named views (a camera shorthand that still frames the content) and lights: the default rig, the 0.1
// "light", and "lights" with ambient, directional and point lights, coloured, in world or camera space.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "support.h"

namespace {

using nlohmann::json;

// A cube of side 2 whose faces have their own colours (unlit): +x red, -x cyan, +y green, -y magenta,
// +z blue, -z yellow.
const char* kCubeObj =
    "mtllib c.mtl\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "usemtl nz\nf 1 4 3 2\nusemtl pz\nf 5 6 7 8\nusemtl ny\nf 1 2 6 5\n"
    "usemtl py\nf 4 8 7 3\nusemtl nx\nf 1 5 8 4\nusemtl px\nf 2 3 7 6\n";
const char* kCubeMtl =
    "newmtl px\nKd 1 0 0\nnewmtl nx\nKd 0 1 1\nnewmtl py\nKd 0 1 0\n"
    "newmtl ny\nKd 1 0 1\nnewmtl pz\nKd 0 0 1\nnewmtl nz\nKd 1 1 0\n";

raster::Scene cube_scene(const json& camera, int size = 33) {
  const json doc = {
      {"width", size},
      {"height", size},
      {"camera", camera},
      {"primitives", {{{"type", "obj"}, {"data", kCubeObj}, {"mtl", kCubeMtl}, {"shading", "unlit"}}}}};
  return raster::parse_scene(doc.dump());
}

raster::SceneError error_of(const json& doc) {
  try {
    raster::Scene s = raster::parse_scene(doc.dump());
    raster::plan(s);
  } catch (const raster::SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << doc.dump();
  return raster::SceneError(raster::ErrorKind::invalid, "none");
}

TEST(View, EachNamedViewLooksAtItsFace) {
  const std::pair<const char*, raster::Rgba8> cases[] = {
      {"front", {0, 0, 255, 255}},  {"back", {255, 255, 0, 255}}, {"right", {255, 0, 0, 255}},
      {"left", {0, 255, 255, 255}}, {"top", {0, 255, 0, 255}},    {"bottom", {255, 0, 255, 255}}};
  int front_count = -1;
  for (const auto& [name, colour] : cases) {
    const raster::Image image = test::render(cube_scene({{"view", name}}));
    EXPECT_EQ(test::pixel(image, 16, 16), colour) << name;
    // Framed alike: seen square on from any side, the cube covers the same pixels.
    const int count = test::count_not(image, test::kBlack);
    if (front_count < 0) front_count = count;
    EXPECT_EQ(count, front_count) << name;
    EXPECT_GT(count, 33 * 33 / 5) << name << ": fitted, not a speck";
  }
}

TEST(View, TopAndBottomPutTheFrontEdgeDown) {
  raster::Scene top = cube_scene({{"view", "top"}});
  EXPECT_EQ(raster::plan(top).view.up, (raster::Vec3{0, 0, -1}));
  raster::Scene bottom = cube_scene({{"view", "bottom"}});
  EXPECT_EQ(raster::plan(bottom).view.up, (raster::Vec3{0, 0, 1}));
  // Relative to a given up axis (issue 42): a Z-up model's top view looks down +Z with its front (-Y) edge
  // at the bottom of the picture.
  raster::Scene z_up = cube_scene({{"view", "top"}, {"up", "+z"}});
  const raster::ViewPlan v = raster::plan(z_up).view;
  EXPECT_EQ(v.up, (raster::Vec3{0, 1, 0}));
  EXPECT_GT(v.eye.z - v.target.z, 0) << "looks down the up axis";
  EXPECT_NEAR(v.eye.x - v.target.x, 0, 1e-9);
  EXPECT_NEAR(v.eye.y - v.target.y, 0, 1e-9);
}

// Issue 42: every named view is relative to the up axis, so a Z-up model (up "+z", as CAD and 3D printing
// write STL) is seen from its front with the default view, and each view shows the face it names in that
// frame: front is -Y, back +Y, top +Z; and in the iso view the model's top (+Z) is at the top of the image.
TEST(View, NamedViewsAreRelativeToTheUpAxis) {
  const raster::Rgba8 blue{0, 0, 255, 255}, yellow{255, 255, 0, 255}, red{255, 0, 0, 255},
      cyan{0, 255, 255, 255}, green{0, 255, 0, 255}, magenta{255, 0, 255, 255};
  // The cube's faces: +Z blue, -Z yellow, +X red, -X cyan, +Y green, -Y magenta.
  const std::pair<const char*, raster::Rgba8> cases[] = {
      {"front", magenta}, {"back", green}, {"right", red}, {"left", cyan}, {"top", blue}, {"bottom", yellow}};
  for (const auto& [name, colour] : cases) {
    const raster::Image image = test::render(cube_scene({{"view", name}, {"up", "+z"}}));
    EXPECT_EQ(test::pixel(image, 16, 16), colour) << name;
  }
  EXPECT_EQ(test::pixel(test::render(cube_scene({{"up", "+z"}})), 16, 16), magenta)
      << "the default view: front";
  EXPECT_EQ(test::pixel(test::render(cube_scene({{"up", {0, 0, 1}}})), 16, 16), magenta) << "as a vector too";
  const raster::Image iso =
      test::render(cube_scene({{"view", "iso"}, {"up", "+z"}, {"projection", "orthographic"}}, 65));
  double top_rows = 0, side_rows = 0;
  int top = 0, side = 0;
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) {
      const raster::Rgba8 p = test::pixel(iso, x, y);
      if (p == blue) top_rows += y, ++top;
      if (p == red || p == magenta) side_rows += y, ++side;
    }
  ASSERT_GT(top, 0);
  ASSERT_GT(side, 0);
  EXPECT_LT(top_rows / top, side_rows / side) << "the model's top is above its sides";
}

TEST(View, IsoShowsThreeFacesEqually) {
  const raster::Image image = test::render(cube_scene({{"view", "iso"}, {"projection", "orthographic"}}, 65));
  int red = 0, green = 0, blue = 0;
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) {
      const raster::Rgba8 p = test::pixel(image, x, y);
      red += p == test::kRed, green += p == raster::Rgba8{0, 255, 0, 255}, blue += p == test::kBlue;
    }
  EXPECT_GT(red, 300);
  // Orthographic along (1, 1, 1): the three faces project to equal areas (up to their shared edges' pixels).
  EXPECT_NEAR(green, red, red / 20);
  EXPECT_NEAR(blue, red, red / 20);
  const raster::RenderPlan plan = raster::plan(cube_scene({{"view", "iso"}}));
  const raster::Vec3 d{plan.view.eye.x - plan.view.target.x, plan.view.eye.y - plan.view.target.y,
                       plan.view.eye.z - plan.view.target.z};
  EXPECT_NEAR(d.x, d.y, 1e-9);
  EXPECT_NEAR(d.y, d.z, 1e-9);
}

TEST(View, ViewAndEyeExcludeEachOtherAndNamesAreChecked) {
  const json base = {{"width", 8}, {"height", 8}};
  json both = base;
  both["camera"] = {{"view", "iso"}, {"eye", {1, 2, 3}}};
  raster::SceneError e = error_of(both);
  EXPECT_EQ(e.kind(), raster::ErrorKind::invalid);
  EXPECT_EQ(e.where().pointer, "/camera/view");
  json bad = base;
  bad["camera"] = {{"view", "isometric"}};
  e = error_of(bad);
  EXPECT_EQ(e.where().pointer, "/camera/view");
  EXPECT_NE(std::string(e.what()).find("\"iso\""), std::string::npos) << e.what();
}

// A white quad facing +z filling an 8x8 orthographic view of [-1, 1]^2.
json quad(const char* shading = "smooth") {
  return {{"type", "mesh"},
          {"positions", {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}},
          {"indices", {{0, 1, 2}, {0, 2, 3}}},
          {"color", "#ffffff"},
          {"shading", shading}};
}

json quad_scene(const json& lights, const char* view = "front", const char* shading = "smooth") {
  json doc = {{"width", 8},
              {"height", 8},
              {"camera", {{"projection", "orthographic"}, {"view", view}, {"height", 2}}},
              {"primitives", {quad(shading)}}};
  if (!lights.is_null()) doc["lights"] = lights;
  return doc;
}

raster::Image render(const json& doc, int threads = 1) {
  return test::render(raster::parse_scene(doc.dump()), threads);
}

TEST(Lights, ColouredDirectionalLightTintsAndTheImageIsNotGrey) {
  const json doc = quad_scene(
      {{{"type", "directional"}, {"direction", {0, 0, -1}}, {"color", "#ff8000"}, {"intensity", 0.8}}});
  const raster::Scene s = raster::parse_scene(doc.dump());
  EXPECT_EQ(raster::plan(s).format, raster::PixelFormat::rgb8);
  EXPECT_EQ(test::pixel(test::render(s), 3, 3), (raster::Rgba8{204, 102, 0, 255}));  // 255 x 0.8 x colour
}

// Per pixel, lit by a point light one unit in front of the quad's centre: n . (light - p) / |light - p|
// = 1 / sqrt(1 + x^2 + y^2) at the pixel centre's world point (x, y, 0).
TEST(Lights, PointLightFollowsTheExactFalloffOfAngle) {
  const raster::Image image = render(quad_scene({{{"type", "point"}, {"position", {0, 0, 1}}}}));
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const double x = -1 + (i + 0.5) / 4, y = 1 - (j + 0.5) / 4;
      const double want = 255 / std::sqrt(1 + x * x + y * y);
      ASSERT_NEAR(test::pixel(image, i, j).r, want, 1.0) << i << "," << j;
    }
  EXPECT_EQ(test::pixel(image, 3, 3).r, test::pixel(image, 4, 4).r) << "symmetric about the centre";
  EXPECT_GT(test::pixel(image, 3, 3).r, test::pixel(image, 0, 0).r + 40);
  // Flat shading: one term per face, at its centroid (1/3 of the way to the corners): 1 / sqrt(1 + 2/9 +
  // 2/9)...
  const raster::Image flat =
      render(quad_scene({{{"type", "point"}, {"position", {0, 0, 1}}}}, "front", "flat"));
  const double centroid = 255 / std::sqrt(1 + 1.0 / 9 + 1.0 / 9);
  EXPECT_NEAR(test::pixel(flat, 0, 7).r, centroid, 1.0);
  EXPECT_NEAR(test::pixel(flat, 7, 0).r, centroid, 1.0);
  // And threads do not change a byte.
  EXPECT_EQ(render(quad_scene({{{"type", "point"}, {"position", {0.3, -0.2, 0.5}}}}), 1).pixels,
            render(quad_scene({{{"type", "point"}, {"position", {0.3, -0.2, 0.5}}}}), 2).pixels);
}

TEST(Lights, CameraSpaceLightsMoveWithTheViewWorldLightsStay) {
  const json camera_light = {{{"type", "directional"}, {"space", "camera"}, {"direction", {0, 0, -1}}}};
  EXPECT_EQ(test::pixel(render(quad_scene(camera_light, "front")), 4, 4).r, 255);
  EXPECT_EQ(test::pixel(render(quad_scene(camera_light, "back")), 4, 4).r, 255) << "the side seen is lit";
  const json world_light = {{{"type", "ambient"}, {"intensity", 0.25}},
                            {{"type", "directional"}, {"direction", {0, 0, -1}}, {"intensity", 0.75}}};
  EXPECT_EQ(test::pixel(render(quad_scene(world_light, "front")), 4, 4).r, 255);
  EXPECT_EQ(test::pixel(render(quad_scene(world_light, "back")), 4, 4).r, 64) << "from behind: ambient only";
}

// rasterd 0.1's "light" keeps its meaning: ambient + (1 - ambient) max(0, n . -direction).
TEST(Lights, SingleLightKeepsItsFormula) {
  json doc = quad_scene(nullptr);
  doc["light"] = {{"ambient", 0.3}, {"direction", {0, -1, -1}}};
  EXPECT_NEAR(test::pixel(render(doc), 4, 4).r, 255 * (0.3 + 0.7 * std::sqrt(0.5)), 1.0);
}

// The default rig, head on: ambient 0.35 + key 0.45 cos(54.7 deg) + fill 0.25, on the default grey.
TEST(Lights, DefaultRigLightsAFaceSeenHeadOn) {
  json doc = quad_scene(nullptr);
  doc["primitives"][0].erase("color");
  double sum = 0;
  for (const raster::Light& l : raster::default_lights())
    sum += l.intensity *
           (l.kind == raster::LightKind::ambient
                ? 1
                : -l.direction.z / std::sqrt(l.direction.x * l.direction.x + l.direction.y * l.direction.y +
                                             l.direction.z * l.direction.z));
  EXPECT_NEAR(sum, 0.35 + 0.45 / std::sqrt(3.0) + 0.25, 1e-12);
  EXPECT_LT(sum, 1) << "a face seen head on is not washed out";
  EXPECT_NEAR(test::pixel(render(doc), 4, 4).r, 204 * sum, 1.0);
  const std::string explained = raster::explain_json(raster::plan(raster::parse_scene(doc.dump())));
  EXPECT_EQ(nlohmann::json::parse(explained).at("lights").size(), 3u) << explained;
}

// A grey image (grey colours under grey lights) computes one channel per pixel where an RGB image computes
// three (issue 41's shader lanes): the same mesh gives the same bytes either way. A seeded bumpy grid lit per
// pixel by grey ambient, directional and point lights, drawn alone (grey8) and beside a small red triangle in
// a corner that makes the image RGB, aliased and at 4 samples.
TEST(Lights, GreyImagesAreLitAsEachChannelOfAnRgbImage) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> bump(-0.25, 0.25), unit(0, 1);
  raster::Mesh grid;
  for (int j = 0; j <= 6; ++j)
    for (int i = 0; i <= 6; ++i) {
      grid.positions.push_back(raster::Vec3f(raster::Vec3{i / 3.0 - 1, j / 3.0 - 1, bump(rng)}));
      const auto v = static_cast<std::uint8_t>(rng());
      grid.colors.push_back({v, v, v, 255});
    }
  for (std::uint32_t j = 0; j < 6; ++j)
    for (std::uint32_t i = 0; i < 6; ++i) {
      const std::uint32_t a = j * 7 + i;
      grid.triangles.push_back({a, a + 1, a + 8});
      grid.triangles.push_back({a, a + 8, a + 7});
    }
  test::SceneBuilder grey(64, 64);
  grey.scene.meshes.push_back(grid);
  raster::Primitive mesh;
  mesh.kind = raster::PrimitiveKind::mesh;
  grey.scene.primitives.push_back(mesh);
  grey.scene.camera.has_eye = true, grey.scene.camera.eye = {0.4, -0.8, 2.5};
  for (raster::LightKind kind :
       {raster::LightKind::ambient, raster::LightKind::directional, raster::LightKind::point}) {
    raster::Light l;
    l.kind = kind, l.intensity = 0.2 + 0.5 * unit(rng);
    l.color = {0.9, 0.9, 0.9};
    l.direction = {bump(rng), bump(rng), -1}, l.position = {bump(rng), bump(rng), 0.8};
    grey.scene.lights.push_back(l);
  }
  test::SceneBuilder rgb = grey;
  rgb.triangle({0, 0}, {3, 0}, {0, 3}, test::kRed);
  for (raster::Antialias aa : {raster::Antialias::none, raster::Antialias::msaa4}) {
    grey.scene.antialias = rgb.scene.antialias = aa;
    ASSERT_EQ(raster::plan(grey.scene).format, raster::PixelFormat::grey8);
    ASSERT_EQ(raster::plan(rgb.scene).format, raster::PixelFormat::rgb8);
    const raster::Image a = test::render(grey.scene), b = test::render(rgb.scene);
    ASSERT_GT(test::count_not(a, test::kBlack), 1500);
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        if (x + y > 6) {  // away from the red corner
          ASSERT_EQ(test::pixel(a, x, y), test::pixel(b, x, y)) << x << ", " << y;
        }
  }
}

TEST(Lights, BadLightsAreInvalidWithTheirPointer) {
  const std::pair<json, const char*> cases[] = {
      {{{{"type", "point"}}}, "/lights/0"},
      {{{{"type", "spot"}}}, "/lights/0/type"},
      {{{{"type", "ambient"}, {"color", "#ffffff80"}}}, "/lights/0/color"},
      {{{{"type", "ambient"}, {"intensity", -1}}}, "/lights/0/intensity"},
      {{{{"type", "directional"}, {"direction", {0, 0, 0}}}}, "/lights/0/direction"},
      {{{{"type", "directional"}, {"space", "screen"}}}, "/lights/0/space"},
      {{{{"type", "ambient"}, {"position", {0, 0, 1}}}}, "/lights/0/position"},
      {json::array(), "/lights"},  // leave "lights" out for the default rig
  };
  for (const auto& [lights, pointer] : cases) {
    const raster::SceneError e = error_of(quad_scene(lights));
    EXPECT_EQ(e.kind(), raster::ErrorKind::invalid) << lights.dump();
    EXPECT_EQ(e.where().pointer, pointer) << lights.dump() << ": " << e.what();
  }
  json nine = json::array();
  for (int i = 0; i < 9; ++i) nine.push_back({{"type", "ambient"}});
  EXPECT_EQ(error_of(quad_scene(nine)).where().pointer, "/lights");
  json both = quad_scene({{{"type", "ambient"}}});
  both["light"] = {{"ambient", 0.5}};
  EXPECT_EQ(error_of(both).where().pointer, "/lights");
}

// A transparent background gives an RGBA image; with multisampling the model's silhouette is a coverage
// ramp in alpha over the model's own colour (samples averaged premultiplied: no dark fringe).
TEST(View, TransparentBackgroundGivesAntialiasedRgbaEdges) {
  raster::Scene s = cube_scene({{"view", "front"}});
  s.background = {0, 0, 0, 0};
  s.antialias = raster::Antialias::msaa8;
  const raster::RenderPlan plan = raster::plan(s);
  ASSERT_EQ(plan.format, raster::PixelFormat::rgba8);
  const raster::Image image = raster::render(s, plan);
  EXPECT_EQ(test::pixel(image, 0, 0).a, 0);
  EXPECT_EQ(test::pixel(image, 16, 16), test::kBlue);
  int partial = 0;
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 33; ++x) {
      const raster::Rgba8 p = test::pixel(image, x, y);
      if (p.a == 0 || p.a == 255) continue;
      ++partial;
      EXPECT_EQ(p.b, 255) << x << "," << y << ": the colour of the part covered, not darkened";
    }
  EXPECT_GT(partial, 8) << "the silhouette is anti-aliased";
}

// Feature edges of the unlit cube, iso view, orthographic, 65 px.
raster::Scene edged_cube(const json& edges, const char* obj = kCubeObj) {
  const json doc = {
      {"width", 65},
      {"height", 65},
      {"camera", {{"view", "iso"}, {"projection", "orthographic"}}},
      {"primitives",
       {{{"type", "obj"}, {"data", obj}, {"mtl", kCubeMtl}, {"shading", "unlit"}, {"edges", edges}}}}};
  return raster::parse_scene(doc.dump());
}

// Where world point p lands in the image, in pixels.
std::pair<double, double> on_screen(const raster::RenderPlan& plan, raster::Vec3 p) {
  const raster::Mat4& m = plan.view.world_to_clip;
  const double x = m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.z + m(0, 3);
  const double y = m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.z + m(1, 3);
  const double w = m(3, 0) * p.x + m(3, 1) * p.y + m(3, 2) * p.z + m(3, 3);
  return {(x / w + 1) * 0.5 * plan.width, (1 - y / w) * 0.5 * plan.height};
}

bool black_near(const raster::Image& image, double x, double y, int radius) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int px = static_cast<int>(std::floor(x)) + dx, py = static_cast<int>(std::floor(y)) + dy;
      if (px >= 0 && py >= 0 && px < image.width && py < image.height &&
          test::pixel(image, px, py) == test::kBlack)
        return true;
    }
  return false;
}

TEST(Edges, VisibleCreasesAreDrawnWholeHiddenOnesAndFaceDiagonalsAreNot) {
  const raster::Scene s = edged_cube(true);
  const raster::RenderPlan plan = raster::plan(s);
  const raster::Image image = raster::render(s, plan);
  const raster::Vec3 corners[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                            {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  int visible = 0;
  for (const auto& e : edges) {
    const raster::Vec3 a = corners[e[0]], b = corners[e[1]];
    const bool hidden = e[0] == 0 || e[1] == 0;  // the three edges at the corner facing away
    // Visible edges whole, up to their corners (the nearest corner's edges once lost their ends to the near
    // plane); hidden ones away from the visible corners they end at.
    for (double t = hidden ? 0.2 : 0.05; t <= (hidden ? 0.8 : 0.951); t += 0.05) {
      const auto [x, y] =
          on_screen(plan, {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t});
      if (hidden)
        EXPECT_FALSE(black_near(image, x, y, 1)) << "hidden edge " << e[0] << "-" << e[1] << " at " << t;
      else
        EXPECT_TRUE(black_near(image, x, y, 0) || black_near(image, x, y, 1))
            << "edge " << e[0] << "-" << e[1] << " at " << t;
    }
    visible += !hidden;
  }
  EXPECT_EQ(visible, 9);
  // The diagonal splitting each quad face is coplanar: no crease, not drawn.
  for (const auto& [a, b] : {std::pair{5, 7}, {2, 7}, {5, 2}}) {
    const raster::Vec3 p = corners[a], q = corners[b];
    const auto [x, y] = on_screen(plan, {(p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2});
    EXPECT_FALSE(black_near(image, x, y, 1)) << "diagonal " << a << "-" << b;
  }
}

// On a small image two pixels are more than the 1% margin the fitted near plane leaves in front of the
// content: edges pulled that far toward the eye were clipped away, and a cube seen from the front at 64 px
// had no outline. The pull stops at the near plane.
TEST(Edges, TheNearestFaceKeepsItsEdgesOnASmallImage) {
  for (const char* projection : {"perspective", "orthographic"}) {
    const json doc = {
        {"width", 64},
        {"height", 64},
        {"background", "#ffffff"},  // black is an edge, not the background beside the outline
        {"camera", {{"projection", projection}}},
        {"primitives",
         {{{"type", "obj"}, {"data", kCubeObj}, {"mtl", kCubeMtl}, {"shading", "unlit"}, {"edges", true}}}}};
    const raster::Scene s = raster::parse_scene(doc.dump());
    const raster::RenderPlan plan = raster::plan(s);
    const raster::Image image = raster::render(s, plan);
    const raster::Vec3 front[4] = {
        {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};  // the face toward the eye
    for (int k = 0; k < 4; ++k) {
      const raster::Vec3 a = front[k], b = front[(k + 1) % 4];
      for (double t = 0.05; t <= 0.951; t += 0.05) {
        const auto [x, y] = on_screen(plan, {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, 1});
        EXPECT_TRUE(black_near(image, x, y, 1)) << projection << ": front edge " << k << " at " << t;
      }
    }
    // Inside the face, its blue, not an edge.
    EXPECT_EQ(test::pixel(image, 32, 32), (raster::Rgba8{0, 0, 255, 255})) << projection;
  }
}

TEST(Edges, RepeatedCornersAreWeldedWidthAndAngleApply) {
  // The same cube with every face's corners repeated (as UV seams and STL soups have them).
  std::string soup = "mtllib c.mtl\n";
  const char* faces[6][4] = {
      {"-1 -1 -1", "-1 1 -1", "1 1 -1", "1 -1 -1"}, {"-1 -1 1", "1 -1 1", "1 1 1", "-1 1 1"},
      {"-1 -1 -1", "1 -1 -1", "1 -1 1", "-1 -1 1"}, {"-1 1 -1", "-1 1 1", "1 1 1", "1 1 -1"},
      {"-1 -1 -1", "-1 -1 1", "-1 1 1", "-1 1 -1"}, {"1 -1 -1", "1 1 -1", "1 1 1", "1 -1 1"}};
  const char* materials[6] = {"nz", "pz", "ny", "py", "nx", "px"};
  for (int f = 0; f < 6; ++f) {
    for (const char* v : faces[f]) soup += std::string("v ") + v + "\n";
    soup += std::string("usemtl ") + materials[f] + "\nf -4 -3 -2 -1\n";
  }
  const raster::Image shared = test::render(edged_cube(true));
  EXPECT_EQ(test::render(edged_cube(true, soup.c_str())).pixels, shared.pixels);

  const int thin = test::count_not(shared, test::kBlack),
            none = test::count_not(test::render(edged_cube(false)), test::kBlack);
  const int wide = test::count_not(test::render(edged_cube({{"width", 3}})), test::kBlack);
  EXPECT_LT(thin, none);
  EXPECT_LT(none - wide, 4 * (none - thin)) << "3 px edges cover about three times the pixels of 1 px";
  EXPECT_GT(none - wide, 2 * (none - thin));
  // A crease angle above the cube's 90 degrees, and a closed cube has no boundary: nothing is drawn.
  EXPECT_EQ(test::render(edged_cube({{"angle", 95}})).pixels, test::render(edged_cube(false)).pixels);
  // Grey edges take at least the pixels black ones took (more: the black ones outside the silhouette
  // did not show against the black background).
  const raster::Image grey = test::render(edged_cube({{"color", "#808080"}}));
  int grey_pixels = 0;
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) grey_pixels += test::pixel(grey, x, y) == raster::Rgba8{128, 128, 128, 255};
  EXPECT_GE(grey_pixels, none - thin);
}

TEST(Edges, BadEdgesAreInvalidWithTheirPointer) {
  for (const auto& [edges, pointer] :
       {std::pair<json, const char*>{{{"width", 0}}, "/primitives/0/edges/width"},
        {{{"angle", 200}}, "/primitives/0/edges/angle"},
        {{{"colour", "#000"}}, "/primitives/0/edges/colour"},
        {"yes", "/primitives/0/edges"}}) {
    const json doc = {{"width", 8},
                      {"height", 8},
                      {"primitives", {{{"type", "obj"}, {"data", kCubeObj}, {"edges", edges}}}}};
    const raster::SceneError e = error_of(doc);
    EXPECT_EQ(e.where().pointer, pointer) << edges.dump() << ": " << e.what();
  }
}

}  // namespace
