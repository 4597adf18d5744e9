// The scene reader is a JSON parser first: JSONTestSuite's parsing cases (../shared/data/JSONTestSuite,
// read from there and not copied here) as whole documents and as the value of a field. y_ cases are JSON,
// so never malformed (a scene they are not, except a string as a comment: invalid); n_ cases are malformed
// (or not UTF-8); i_ cases, which RFC 8259 leaves to the parser, get an error of some kind and never a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "raster/scene.h"

namespace {

namespace fs = std::filesystem;
using raster::ErrorKind;

const fs::path kCases = fs::path(RASTERD_SHARED_DIR) / "data/JSONTestSuite/test_parsing";

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream out;
  out << in.rdbuf();
  return out.str();
}

// The kind of error parse_scene gives, or nothing when it accepts.
std::optional<ErrorKind> verdict(const std::string& text, const raster::Limits& limits = {}) {
  try {
    raster::parse_scene(text, limits);
    return std::nullopt;
  } catch (const raster::SceneError& e) {
    return e.kind();
  }
}

TEST(JsonConformance, JsonTestSuiteParsingCases) {
  if (!fs::is_directory(kCases)) GTEST_SKIP() << kCases << " is not here (it comes with ../shared)";
  int yes = 0, no = 0, either = 0;
  for (const auto& entry : fs::directory_iterator(kCases)) {
    const std::string name = entry.path().filename().string();
    const std::string text = read(entry.path());
    // As the document, and as the value of a field: the reader judges a value where it stands.
    for (const std::string& doc : {text, R"({"width": 1, "height": 1, "$comment": )" + text + "}"}) {
      const auto kind = verdict(doc);
      if (name.starts_with("y_")) {
        // Read as JSON: a scene (a string as "$comment") or an invalid one, never malformed.
        EXPECT_NE(kind, ErrorKind::syntax) << name << " is JSON: " << doc;
        EXPECT_NE(kind, ErrorKind::encoding) << name << " is UTF-8: " << doc;
        ++yes;
      } else if (name.starts_with("n_")) {
        ASSERT_TRUE(kind.has_value()) << name << " is not JSON: " << doc;
        EXPECT_TRUE(*kind == ErrorKind::syntax || *kind == ErrorKind::encoding) << name << ": " << doc;
        ++no;
      } else {
        EXPECT_TRUE(kind.has_value()) << name;  // none of them is a scene; a 4xx either way
        ++either;
      }
    }
  }
  EXPECT_GT(yes, 150);
  EXPECT_GT(no, 300);
  EXPECT_GT(either, 50);
}

// scene_fuzzer (issue 32's final run): a UTF-8 byte order mark before the document made it malformed to the
// reader and JSON to nlohmann. It is passed over at the start, as the service always blanked it, and error
// bytes still count it; elsewhere it is no whitespace.
TEST(JsonConformance, AByteOrderMarkAtTheStartIsPassedOver) {
  const std::string bom = "\xEF\xBB\xBF", scene = R"({"width": 4, "height": 4, "background": "#ff0000"})";
  EXPECT_EQ(raster::parse_scene(bom + scene), raster::parse_scene(scene));
  EXPECT_EQ(verdict(bom + "\"#ff000080\""), ErrorKind::invalid);  // JSON, but no scene
  EXPECT_EQ(verdict(bom), ErrorKind::syntax);
  EXPECT_EQ(verdict(" " + bom + scene), ErrorKind::syntax);
  try {
    raster::parse_scene(bom + R"({"width": 4, "height": -4})");
    ADD_FAILURE() << "a negative height was read";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.where().byte, bom.size() + std::string(R"({"width": 4, "height": )").size() + 1) << e.what();
  }
}

TEST(JsonConformance, AMalformedDocumentIsMalformedWhateverElseIsWrongInIt) {
  // The width is wrong first, but the document is not JSON: that is what the client must fix first.
  const std::string text = R"({"width": -4, "height": 8, "primitives": [1, 2,]})";
  ASSERT_EQ(verdict(text), ErrorKind::syntax);
  try {
    raster::parse_scene(text);
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.where().byte, text.find(",]") + 2) << e.what();
  }
  EXPECT_EQ(verdict(R"({"width": -4, "height": 8})"), ErrorKind::invalid);
  // A key given twice is an invalid scene, but the document is not JSON further on (found by the fuzzer,
  // where the oracle, which reports a repeated key while it parses, disagreed).
  EXPECT_EQ(
      verdict(
          R"({"width": 3, "height": 300, "height": 6, "primitives": [{"type": "triangle", "points": [[30, 0], [pe""]}]})"),
      ErrorKind::syntax);
  EXPECT_EQ(verdict(R"({"width": 3, "height": 300, "height": 6})"), ErrorKind::invalid);
}

// A library caller may allow deep documents; judging one (here: syntax first, after the wrong kind of
// "$comment") takes no stack per level, where a recursive walk would overflow it.
TEST(JsonConformance, DeepNestingWithinAHighLimitNeedsNoStackPerLevel) {
  raster::Limits limits;
  limits.max_json_depth = 1'000'000;
  const std::size_t depth = 500'000;
  const std::string head = R"({"width": 1, "height": 1, "$comment": )" + std::string(depth, '[');
  EXPECT_EQ(verdict(head + std::string(depth, ']') + "}", limits), ErrorKind::invalid);
  EXPECT_EQ(verdict(head + std::string(depth - 1, ']') + "}", limits), ErrorKind::syntax);
}

TEST(JsonConformance, EveryErrorHasTheByteWhereItsValueStarts) {
  const std::pair<std::string, std::string> cases[] = {
      // document, the text the error's byte points at
      {R"({"width": 8, "height": 8, "background": "#ggg"})", R"("#ggg")"},
      {R"({"width": 8, "height": 8, "primitives": [{"type": "line", "points": [[0, 0], [1, "x"]]}]})",
       R"("x")"},
      {R"({"width": 8, "height": 8, "camera": {"fov": 190}})", "190"},
      {R"({"width": 8, "height": 8, "primitives": [{"type": "lne", "points": []}]})", R"("lne")"},
      {R"({"width": 8, "height": 8, "primitives": [{"type": "line", "colour": "#fff"}]})", R"("#fff")"},
      {R"({"width": 0, "height": 8})", "0, "},
  };
  for (const auto& [text, at] : cases) {
    try {
      raster::parse_scene(text);
      ADD_FAILURE() << "accepted " << text;
    } catch (const raster::SceneError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid) << text;
      EXPECT_FALSE(e.where().pointer.empty()) << text;
      EXPECT_EQ(e.where().byte, text.find(at) + 1) << e.what() << " in " << text;
    }
  }
}

}  // namespace

namespace {

// The format's ranges are stated once (scene_format.h): a scene built in code gets the reader's words.
TEST(JsonConformance, ScenesBuiltInCodeGetTheReadersRanges) {
  auto message_of = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const raster::SceneError& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string json_fov =
      message_of([] { raster::parse_scene(R"({"width": 4, "height": 4, "camera": {"fov": 200}})"); });
  raster::Scene scene = raster::parse_scene(R"({"width": 4, "height": 4})");
  scene.camera.fov_deg = 200;
  const std::string code_fov = message_of([&] { raster::validate(scene); });
  EXPECT_EQ(code_fov, json_fov.substr(0, code_fov.size())) << json_fov;  // the JSON one adds "; got 200"
  EXPECT_NE(code_fov, "accepted");

  scene = raster::parse_scene(
      R"({"width": 4, "height": 4, "primitives": [{"type": "line", "points": [[0, 0], [1, 1]]}]})");
  scene.primitives[0].width = 0;
  const std::string code_width = message_of([&] { raster::validate(scene); });
  const std::string json_width = message_of([] {
    raster::parse_scene(
        R"({"width": 4, "height": 4, "primitives": [{"type": "line", "points": [[0, 0], [1, 1]], "width": 0}]})");
  });
  EXPECT_NE(code_width, "accepted");
  EXPECT_EQ(code_width, json_width.substr(0, code_width.size())) << json_width;
}

}  // namespace
