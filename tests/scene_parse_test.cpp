// Scene format v1: what parses, and that every bad input is a typed error pointing at the culprit.
#include <gtest/gtest.h>

#include <string>

#include "support.h"

namespace {

using raster::ErrorKind;
using raster::SceneError;

SceneError parse_error(const std::string& text, const raster::Limits& limits = {}) {
  try {
    raster::parse_scene(text, limits);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a SceneError for: " << text.substr(0, 200);
  return SceneError(ErrorKind::invalid, "none");
}

std::string with_primitive(const std::string& primitive) {
  return R"({"width": 8, "height": 8, "primitives": [)" + primitive + "]}";
}

TEST(SceneParse, ReadsTheReadmeExample) {
  const auto s = raster::parse_scene(R"({ "width": 256, "height": 128, "background": "#202830",
    "primitives": [
      {"type": "triangle", "points": [[20,20],[230,60],[120,220]], "colors": ["#ff0000","#00ff00","#0000ff"]},
      {"type": "triangle", "points": [[30,200],[90,140],[60,250]], "color": "#ffcc00", "fill": false},
      {"type": "line", "points": [[13,20],[80,40]], "color": "#ffffff"},
      {"type": "polyline", "points": [[10,10],[50,30],[90,10]], "closed": true, "color": [1,0.5,0,0.5]}
    ] })");
  EXPECT_EQ(s.width, 256);
  EXPECT_EQ(s.height, 128);
  EXPECT_EQ(s.background, (raster::Rgba8{0x20, 0x28, 0x30, 255}));
  ASSERT_EQ(s.primitives.size(), 4u);
  EXPECT_TRUE(s.primitives[0].per_vertex_color);
  EXPECT_EQ(s.vertex_color(s.primitives[0], 1), test::kGreen);
  EXPECT_FALSE(s.primitives[1].fill);
  EXPECT_EQ(s.primitives[2].kind, raster::PrimitiveKind::line);
  EXPECT_TRUE(s.primitives[3].closed);
  EXPECT_EQ(s.vertex_color(s.primitives[3], 2), (raster::Rgba8{255, 128, 0, 128}));
  EXPECT_EQ(s.points[s.primitives[3].first_point + 1].x, 50);
}

TEST(SceneParse, ColourForms) {
  auto color = [](const std::string& c) {
    const auto s = raster::parse_scene(R"({"width":1,"height":1,"background":)" + c + "}");
    return s.background;
  };
  EXPECT_EQ(color("\"#f80\""), (raster::Rgba8{255, 136, 0, 255}));
  EXPECT_EQ(color("\"#f808\""), (raster::Rgba8{255, 136, 0, 136}));
  EXPECT_EQ(color("\"#12ABef\""), (raster::Rgba8{0x12, 0xab, 0xef, 255}));
  EXPECT_EQ(color("\"#12abef7f\""), (raster::Rgba8{0x12, 0xab, 0xef, 0x7f}));
  EXPECT_EQ(color("[0, 0.5, 1]"), (raster::Rgba8{0, 128, 255, 255}));
  EXPECT_EQ(color("[1, 1, 1, 0]"), (raster::Rgba8{255, 255, 255, 0}));
}

TEST(SceneParse, DefaultsAreOpaqueBlackBackgroundAndWhiteInk) {
  const auto s = raster::parse_scene(with_primitive(R"({"type":"line","points":[[0,0],[1,1]]})"));
  EXPECT_EQ(s.background, test::kBlack);
  EXPECT_EQ(s.vertex_color(s.primitives[0], 0), test::kWhite);
  EXPECT_TRUE(raster::parse_scene(R"({"width": 3.0, "height": 2})").primitives.empty());
}

TEST(SceneParse, UnknownFieldSuggestsTheClosestName) {
  auto e = parse_error(with_primitive(R"({"type":"triangle","points":[[0,0],[1,0],[0,1]],"colr":"#fff"})"));
  EXPECT_EQ(e.kind(), ErrorKind::invalid);
  EXPECT_EQ(e.where().pointer, "/primitives/0/colr");
  EXPECT_NE(std::string(e.what()).find("did you mean \"color\""), std::string::npos) << e.what();
  e = parse_error(R"({"width": 8, "hieght": 8})");
  EXPECT_EQ(e.where().pointer, "/hieght");
  EXPECT_NE(std::string(e.what()).find("\"height\""), std::string::npos);
}

TEST(SceneParse, WrongTypesAndArities) {
  struct Case {
    std::string text, pointer;
  };
  const Case cases[] = {
      {R"({"width": "8", "height": 8})", "/width"},
      {R"({"width": 8.5, "height": 8})", "/width"},
      {R"({"width": 8, "height": 8, "primitives": {}})", "/primitives"},
      {with_primitive(R"({"type":"triangle","points":[[0,0],[1,0]]})"), "/primitives/0/points"},
      {with_primitive(R"({"type":"line","points":[[0,0],[1,0],[2,2]]})"), "/primitives/0/points"},
      {with_primitive(R"({"type":"polyline","points":[[0,0]]})"), "/primitives/0/points"},
      {with_primitive(R"({"type":"line","points":[[0,0],[1]]})"), "/primitives/0/points/1"},
      {with_primitive(R"({"type":"line","points":[[0,0],[1,"2"]]})"), "/primitives/0/points/1/1"},
      {with_primitive(R"({"type":"line","points":[[0,0],[1,2]],"colors":["#fff"]})"), "/primitives/0/colors"},
      {with_primitive(R"({"type":"line","points":[[0,0],[1,2]],"color":"#ff"})"), "/primitives/0/color"},
      {with_primitive(R"({"type":"line","points":[[0,0],[1,2]],"color":[1,1]})"), "/primitives/0/color"},
      {with_primitive(R"({"type":"triangle","points":[[0,0],[1,0],[0,1]],"fill":"no"})"),
       "/primitives/0/fill"},
      {with_primitive(R"({"type":"circle","points":[[0,0]]})"), "/primitives/0/type"},
      {with_primitive(R"({"points":[[0,0],[1,1]]})"), "/primitives/0"},
      {with_primitive(R"(42)"), "/primitives/0"},
      {with_primitive(R"({"type":"line","points":[[0,0],[1,2]],"color":"#fff","colors":["#fff","#000"]})"),
       "/primitives/0"},
      {R"({"width": 8})", ""},
      {R"([1, 2])", ""},
  };
  for (const auto& c : cases) {
    const auto e = parse_error(c.text);
    EXPECT_EQ(e.kind(), ErrorKind::invalid) << c.text;
    EXPECT_EQ(e.where().pointer, c.pointer) << c.text << " -> " << e.what();
  }
}

TEST(SceneParse, ColourComponentsOutsideUnitRangeHintAtHex) {
  const auto e = parse_error(R"({"width": 8, "height": 8, "background": [255, 0, 0]})");
  EXPECT_EQ(e.where().pointer, "/background/0");
  EXPECT_NE(std::string(e.what()).find("did you mean \"#ff0000\""), std::string::npos) << e.what();
  EXPECT_EQ(parse_error(R"({"width": 8, "height": 8, "background": [0, -0.1, 0]})").where().pointer,
            "/background/1");
}

// (Text that is not UTF-8 is its own kind, ErrorKind::encoding, also with a byte offset: utf8_test.cpp.)
TEST(SceneParse, MalformedJsonIsASyntaxErrorWithAByteOffset) {
  for (const std::string text :
       {"", "{", R"({"width": 8, "height": 8)", R"({"width": NaN, "height": 8})", R"({"width": Infinity})",
        R"({"width": 1e400, "height": 8})", "{} trailing"}) {
    const auto e = parse_error(text);
    EXPECT_EQ(e.kind(), ErrorKind::syntax) << text;
    if (!text.empty()) {
      EXPECT_GT(e.where().byte, 0u) << text;
    }
  }
}

TEST(SceneParse, DeepNestingIsCutAtTheDepthLimit) {
  const std::string deep(1'000'000, '[');
  const auto e = parse_error(deep);
  EXPECT_EQ(e.kind(), ErrorKind::syntax);
  EXPECT_NE(std::string(e.what()).find("deeper than 64"), std::string::npos) << e.what();
  // 64 levels are fine where the grammar allows them (here: inside an ignored-by-type position)
  std::string ok =
      R"({"width": 1, "height": 1, "primitives": [)" + std::string(62, '[') + std::string(62, ']') + "]}";
  EXPECT_EQ(parse_error(ok).kind(), ErrorKind::invalid) << "depth 64 parses; the content is then invalid";
}

TEST(SceneParse, NegativeZeroAndHugeIntegers) {
  EXPECT_EQ(parse_error(R"({"width": -0, "height": 8})").where().pointer, "/width");
  const auto big = parse_error(R"({"width": 18446744073709551616, "height": 8})");
  EXPECT_EQ(big.kind(), ErrorKind::limit);
  EXPECT_EQ(big.where().pointer, "/width");
  EXPECT_EQ(parse_error(R"({"width": 9007199254740993, "height": 8})").kind(), ErrorKind::limit);
  EXPECT_EQ(parse_error(R"({"width": 0, "height": 8})").kind(), ErrorKind::invalid);
  EXPECT_EQ(parse_error(R"({"width": -5, "height": 8})").kind(), ErrorKind::invalid);
}

TEST(SceneParse, SizeLimitsAreLimitErrors) {
  raster::Limits limits;
  limits.max_width = 100;
  limits.max_pixels = 5000;
  limits.max_primitives = 1;
  EXPECT_EQ(parse_error(R"({"width": 101, "height": 1})", limits).kind(), ErrorKind::limit);
  EXPECT_EQ(parse_error(R"({"width": 100, "height": 51})", limits).kind(), ErrorKind::limit);
  const auto many = parse_error(R"({"width": 1, "height": 1, "primitives": [{}, {}]})", limits);
  EXPECT_EQ(many.kind(), ErrorKind::limit);
  EXPECT_EQ(many.where().pointer, "/primitives");
  EXPECT_NO_THROW(raster::parse_scene(R"({"width": 100, "height": 50})", limits));
}

TEST(SceneParse, PointerEscapesSlashAndTilde) {
  EXPECT_EQ(parse_error(R"({"width": 1, "height": 1, "a/b~c": 0})").where().pointer, "/a~1b~0c");
}

}  // namespace
