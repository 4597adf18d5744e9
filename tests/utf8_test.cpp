// UTF-8 validation of client text: the validator against an independent one, and the typed errors of the
// scene and model readers (byte and line of the first bad byte).
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>

#include "raster/raster.h"

namespace {

// A literal reading of RFC 3629: decode each sequence to its code point and reject what the RFC excludes.
// Slow and obviously right; the validator must agree with it on every input.
std::size_t reference_first_invalid(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto b = static_cast<unsigned char>(s[i]);
    int n = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return i;
    std::uint32_t cp = n == 1 ? b : n == 2 ? (b & 0x1F) : n == 3 ? (b & 0x0F) : (b & 0x07);
    for (int k = 1; k < n; ++k) {
      const auto c = static_cast<unsigned char>(s[i + k]);
      if ((c & 0xC0) != 0x80) return i;
      cp = cp << 6 | (c & 0x3F);
    }
    const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < smallest[n] || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) return i;
    i += n;
  }
  return std::string::npos;
}

TEST(Utf8, AgreesWithALiteralDecoderOnRandomBytes) {
  std::mt19937 rng(12);
  // Bytes drawn mostly from the interesting ranges, so that valid multi-byte sequences occur too.
  const unsigned char pool[] = {'a',  ' ',  0x7F, 0x80, 0x8F, 0x90, 0x9F, 0xA0, 0xBF, 0xC0, 0xC1, 0xC2, 0xDF,
                                0xE0, 0xE1, 0xEC, 0xED, 0xEE, 0xEF, 0xF0, 0xF1, 0xF3, 0xF4, 0xF5, 0xFE, 0xFF};
  for (int round = 0; round < 200000; ++round) {
    std::string s(rng() % 12, '\0');
    for (char& c : s) c = static_cast<char>(pool[rng() % sizeof pool]);
    if (rng() % 4 == 0) s = std::string(rng() % 20, 'x') + s;  // exercise the 8-byte ASCII skip
    ASSERT_EQ(raster::first_invalid_utf8(s), reference_first_invalid(s)) << testing::PrintToString(s);
  }
}

TEST(Utf8, ValidTextPassesAndTheBoundariesAreExact) {
  for (const char* ok :
       {"", "plain ASCII", "\x7F", "\xC2\x80", "\xDF\xBF", "\xE0\xA0\x80", "\xED\x9F\xBF", "\xEE\x80\x80",
        "\xEF\xBF\xBF", "\xF0\x90\x80\x80", "\xF4\x8F\xBF\xBF", "gr\xC3\xBC\xC3\x9F"})
    EXPECT_EQ(raster::first_invalid_utf8(ok), std::string_view::npos) << ok;
  EXPECT_EQ(raster::first_invalid_utf8("0123456789\xFF"), 10u);
  EXPECT_EQ(raster::first_invalid_utf8("ab\xE2\x82"), 2u);
}

TEST(Utf8, EscapeForDisplayKeepsValidTextAndShowsTheRest) {
  EXPECT_EQ(raster::escape_for_display("gr\xC3\xBC\xC3\x9F"), "gr\xC3\xBC\xC3\x9F");
  EXPECT_EQ(raster::escape_for_display("a\xFF\xFE"
                                       "b\n"),
            "a\\xFF\\xFEb\\x0A");
  EXPECT_EQ(raster::escape_for_display("\xE2\x82"), "\\xE2\\x82");
}

raster::SceneError error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const raster::SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no SceneError";
  return raster::SceneError(raster::ErrorKind::syntax, "none");
}

TEST(Utf8, ASceneWithABadByteIsAnEncodingErrorAtThatByte) {
  const std::string scene = std::string(R"({"width": 4, "height": 4, "background": "#fff)") + "\xC0\xAF\"}";
  const auto e = error_of([&] { raster::parse_scene(scene); });
  EXPECT_EQ(e.kind(), raster::ErrorKind::encoding);
  EXPECT_EQ(e.where().byte, scene.find('\xC0') + 1);
  EXPECT_NE(std::string(e.what()).find("overlong"), std::string::npos) << e.what();
  EXPECT_EQ(raster::first_invalid_utf8(e.what()), std::string_view::npos) << "the message itself is UTF-8";
}

// The message says what is wrong with the byte, for each class of ill-formed sequence.
TEST(Utf8, TheMessageNamesWhyTheByteIsWrong) {
  const std::pair<const char*, const char*> cases[] = {
      {"\x80", "continuation byte"}, {"\xC0\xAF", "overlong"},         {"\xE0\x80\xAF", "overlong"},
      {"\xED\xA0\x80", "surrogate"}, {"\xF4\x90\x80\x80", "U+10FFFF"}, {"\xF5\x80", "U+10FFFF"},
      {"\xFF", "never occurs"},      {"\xE2\x82", "cut short"},        {"\xE2\x28\xA1", "cut short"},
  };
  for (const auto& [bytes, why] : cases) {
    const auto e = error_of([&] { raster::require_utf8(bytes, "the text"); });
    EXPECT_EQ(e.kind(), raster::ErrorKind::encoding);
    EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
  }
}

TEST(Utf8, AModelWithABadByteNamesItsLine) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\ng caf\xE9\nf 1 2 3\n";  // Latin-1, not UTF-8
  const auto e = error_of([&] { raster::parse_obj(obj); });
  EXPECT_EQ(e.kind(), raster::ErrorKind::encoding);
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_EQ(e.where().byte, obj.find('\xE9') + 1);
  const auto m =
      error_of([&] { raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "newmtl \xED\xA0\x80\n"); });
  EXPECT_EQ(m.kind(), raster::ErrorKind::encoding);
  EXPECT_NE(std::string(m.what()).find("MTL"), std::string::npos) << m.what();
  EXPECT_NE(std::string(m.what()).find("surrogate"), std::string::npos) << m.what();
}

}  // namespace
