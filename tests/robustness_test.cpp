// Extreme sizes and inputs at the edges of the limits: rendered within the limits or refused up front,
// never an allocation the limits did not allow. (Coordinates, JSON and 3D extremes live beside the
// features they stress: triangle_test, line_test, scene_parse_test, scene3d_test.)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support.h"

namespace {

raster::ErrorKind kind_of(const std::string& scene) {
  try {
    raster::plan(raster::parse_scene(scene));
  } catch (const raster::SceneError& e) {
    return e.kind();
  }
  ADD_FAILURE() << "accepted: " << scene;
  return raster::ErrorKind::syntax;
}

TEST(Robustness, ImageSizes) {
  EXPECT_EQ(kind_of(R"({"width": 0, "height": 5})"), raster::ErrorKind::invalid);
  EXPECT_EQ(kind_of(R"({"width": -3, "height": 5})"), raster::ErrorKind::invalid);
  EXPECT_EQ(kind_of(R"({"width": 1, "height": 100000})"), raster::ErrorKind::limit);
  EXPECT_EQ(kind_of(R"({"width": 8193, "height": 1})"), raster::ErrorKind::limit);
  EXPECT_EQ(kind_of(R"({"width": 8000, "height": 8000})"), raster::ErrorKind::limit) << "64 MP > 40 MP";
  const auto one = test::render(raster::parse_scene(R"({"width": 1, "height": 1, "background": "#123456",
      "primitives": [{"type": "triangle", "points": [[0,0],[2,0],[0,2]], "color": "#fedcba"}]})"));
  EXPECT_EQ(test::pixel(one, 0, 0), (raster::Rgba8{0xfe, 0xdc, 0xba, 255}));
  const auto strip = test::render(raster::parse_scene(R"({"width": 8192, "height": 1,
      "primitives": [{"type": "line", "points": [[-5, 0.5], [9000, 0.5]], "color": "#fff"}]})"));
  EXPECT_EQ(test::count_not(strip, test::kBlack), 8192);
}

// The largest square the default limits allow whole (6324^2 < 40 MP) fully covered by one triangle pair:
// rendered, with exactly the planned bytes (1 grey channel).
TEST(Robustness, LargestImageRendersWithPlannedMemory) {
  const auto scene = raster::parse_scene(R"({"width": 6324, "height": 6324, "primitives": [
      {"type": "triangle", "points": [[0,0],[6324,0],[0,6324]], "color": "#808080"},
      {"type": "triangle", "points": [[6324,0],[6324,6324],[0,6324]], "color": "#808080"}]})");
  const auto plan = raster::plan(scene);
  EXPECT_EQ(plan.memory.color_bytes, 6324ll * 6324);
  EXPECT_EQ(plan.memory.total(), plan.memory.color_bytes + plan.memory.tile_bytes) << "no other buffer";
  EXPECT_EQ(plan.tile, 128);
  EXPECT_EQ(plan.memory.tile_bytes, plan.threads * 128 * 128)
      << "6324 is not whole blocks wide: tile storage";
  const auto img = raster::render(scene, plan);
  EXPECT_EQ(static_cast<std::int64_t>(img.pixels.size()), plan.memory.color_bytes);
  EXPECT_EQ(test::pixel(img, 0, 0).r, 128);
  EXPECT_EQ(test::pixel(img, 6323, 6323).r, 128);
}

TEST(Robustness, ManyPrimitivesAreBoundedByTheLimit) {
  raster::Limits limits;
  limits.max_primitives = 1000;
  std::string scene = R"({"width": 16, "height": 16, "primitives": [)";
  for (int i = 0; i < 1001; ++i)
    scene += std::string(i ? "," : "") + R"({"type":"line","points":[[0,0],[1,1]]})";
  scene += "]}";
  try {
    raster::parse_scene(scene, limits);
    FAIL();
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::limit);
    EXPECT_EQ(e.where().pointer, "/primitives");
  }
  // Mesh triangles count against the same limit, before any index is read.
  limits.max_primitives = 2;
  try {
    raster::parse_scene(
        R"({"width": 8, "height": 8, "primitives": [{"type": "mesh", "positions": [0,0,0, 1,0,0, 0,1,0],
                           "indices": [0,1,2, 0,1,2, 0,1,2]}]})",
        limits);
    FAIL();
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::limit);
    EXPECT_EQ(e.where().pointer, "/primitives/0/indices");
  }
}

// One million primitives (half the default limit) render; nothing is allocated per primitive beyond the
// flat arrays and the draw list.
TEST(Robustness, OneMillionPrimitivesRender) {
  test::SceneBuilder s(1000, 1000);
  for (int i = 0; i < 1'000'000; ++i) {
    const double x = i % 1000, y = i / 1000;
    s.triangle({x, y}, {x + 1, y}, {x, y + 1}, raster::Rgba8{static_cast<std::uint8_t>(i), 0, 255, 255});
  }
  const auto plan = raster::plan(s.scene);
  EXPECT_EQ(plan.flat_count, 1'000'000);
  const auto img = raster::render(s.scene, plan);
  // each unit right triangle covers exactly its pixel's centre? no: (x+0.5, y+0.5) lies on the hypotenuse,
  // a right edge, so it is excluded -- every pixel stays background, a million times over
  EXPECT_EQ(test::count_not(img, test::kBlack), 0);
  test::SceneBuilder t(1000, 1000);
  for (int i = 0; i < 1'000'000; ++i) {
    const double x = i % 1000, y = i / 1000;
    t.triangle({x, y}, {x + 2, y}, {x, y + 2}, test::kWhite);  // covers its own pixel's centre
  }
  EXPECT_EQ(test::count_not(raster::render(t.scene), test::kBlack), 1'000'000);
}

TEST(Robustness, CoordinatesBeyondTheFloatRangeAreRefused) {
  const auto e = [] {
    try {
      raster::parse_scene(
          R"({"width": 8, "height": 8, "primitives": [{"type": "line", "points": [[0,0],[1e39, 1]]}]})");
    } catch (const raster::SceneError& e) {
      return e;
    }
    return raster::SceneError(raster::ErrorKind::syntax, "accepted");
  }();
  EXPECT_EQ(e.kind(), raster::ErrorKind::invalid);
  EXPECT_EQ(e.where().pointer, "/primitives/0/points/1/0");
}

}  // namespace

namespace {

// Fuzzer findings, kept as regression tests (the sanitizer build runs them with UBSan).
// Found by the scene fuzzer once it checked that error messages are UTF-8: in valid UTF-8 text, nlohmann's
// parse error quoted the bytes it read up to the error ("last read: '\"type\"\xF0'"), cutting a 4-byte
// character after its first byte. Every SceneError message is valid UTF-8 (error.h), and the reader names
// a byte that is not printable ASCII by its code.
TEST(Robustness, FuzzFindingParseErrorCutsAUtf8Sequence) {
  const std::string text =
      test::read_file(RASTERD_TESTS_DIR "/data/fuzz-parse-error-cuts-a-utf8-sequence.json");
  ASSERT_EQ(raster::first_invalid_utf8(text), std::string_view::npos) << "the input itself is valid UTF-8";
  try {
    raster::parse_scene(text);
    FAIL() << "the document is malformed";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::syntax);
    EXPECT_EQ(raster::first_invalid_utf8(e.what()), std::string_view::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("byte 0xF0"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().byte, text.find('\xF0') + 1) << e.what();
  }
}

TEST(Robustness, FuzzFinding3DLineEndpointAt1e30) {
  // A 3D line with one endpoint at z = 1e30: homogeneous clipping in doubles cancelled catastrophically and
  // a NaN screen coordinate reached Wide::from_double, an integer conversion. Now the segment is dropped.
  const std::string text = test::read_file(RASTERD_TESTS_DIR "/data/fuzz-3d-line-at-1e30.json");
  const auto img = test::render(raster::parse_scene(text));
  // The same scene without that segment (primitive 2) renders the same pixels: only it was dropped.
  auto doc = nlohmann::json::parse(text);
  doc["primitives"].erase(2);
  EXPECT_EQ(img.pixels, test::render(raster::parse_scene(doc.dump())).pixels);
  EXPECT_GT(test::count_not(img, raster::Rgba8{0x18, 0x18, 0x20, 255}), 0)
      << "the small, distant cube is there";
}

}  // namespace
