// Whole renders: determinism across thread counts, PNG round trips, and the examples as golden images.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <random>
#include <string_view>

#include "raster/model.h"
#include "raster/scene_checks.h"
#include "support.h"

namespace {

using test::SceneBuilder;

raster::Scene random_scene(int w, int h, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-20, w + 20), y(-20, h + 20);
  std::uniform_int_distribution<int> byte(0, 255);
  SceneBuilder s(w, h, raster::Rgba8{20, 30, 40, 255});
  auto color = [&] {
    return raster::Rgba8{static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                         static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng) | 64)};
  };
  for (int i = 0; i < n; ++i) {
    if (i % 3 == 0)
      s.line({x(rng), y(rng)}, {x(rng), y(rng)}, color(), color());
    else
      s.triangle({x(rng), y(rng)}, {x(rng), y(rng)}, {x(rng), y(rng)}, color(), color(), color());
  }
  return s.scene;
}

// Bands split the image between threads; each applies every primitive in order, so the bytes match.
TEST(Render, SameBytesForAnyThreadCount) {
  const auto scene = random_scene(300, 257, 400, 5);
  const auto one = test::render(scene, 1);
  for (int threads : {2, 3, 7, 16}) {
    raster::PlanOptions o;
    o.max_threads = threads;
    auto p = raster::plan(scene, raster::Limits{}, o);
    p.threads = threads;  // force the split even where the plan would not
    EXPECT_EQ(raster::render(scene, p).pixels, one.pixels) << threads << " threads";
  }
}

TEST(Render, PngRoundTripsEveryFormat) {
  for (raster::Rgba8 bg : {raster::Rgba8{0, 0, 0, 255}, raster::Rgba8{0, 0, 0, 0}}) {
    const auto scene = random_scene(64, 48, 30, 9);
    auto s2 = scene;
    s2.background = bg;
    const auto plan = raster::plan(s2);
    const auto img = raster::render(s2, plan);
    const auto d = test::decode_png(raster::encode_png(img, plan.png));
    EXPECT_EQ(d.width, 64);
    EXPECT_EQ(d.height, 48);
    EXPECT_EQ(d.channels, img.channels());
    EXPECT_EQ(d.pixels, img.pixels);
  }
}

// CRC-32 of PNG (ISO 3309), bit by bit: an independent reference (stb_image's decoder skips CRCs).
std::uint32_t reference_crc32(const std::uint8_t* data, std::size_t size) {
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

TEST(Render, PngContainerIsWellFormed) {
  auto be32 = [](const std::uint8_t* p) {
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
  };
  for (raster::Rgba8 bg :
       {raster::Rgba8{0, 0, 0, 255}, raster::Rgba8{0, 0, 0, 0}, raster::Rgba8{9, 9, 9, 255}}) {
    auto scene = random_scene(37, 21, 12, 5);
    if (bg.r == 9) scene.primitives.clear();  // grey: nothing but the background
    scene.background = bg;
    const auto plan = raster::plan(scene);
    const auto png = raster::encode_png(raster::render(scene, plan), plan.png);
    const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    ASSERT_GT(png.size(), 8u);
    ASSERT_TRUE(std::equal(signature, signature + 8, png.begin()));
    std::vector<std::string> types;
    for (std::size_t at = 8; at < png.size();) {
      ASSERT_LE(at + 12, png.size());
      const std::uint32_t length = be32(&png[at]);
      ASSERT_LE(at + 12 + length, png.size());
      types.emplace_back(reinterpret_cast<const char*>(&png[at + 4]), 4);
      EXPECT_EQ(be32(&png[at + 8 + length]), reference_crc32(&png[at + 4], length + 4)) << types.back();
      if (types.back() == "IHDR") {
        EXPECT_EQ(be32(&png[at + 8]), 37u);
        EXPECT_EQ(be32(&png[at + 12]), 21u);
        EXPECT_EQ(png[at + 16], 8);  // bits per channel
        EXPECT_EQ(png[at + 17], plan.png.color_type);
      }
      at += 12 + length;
    }
    EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
  }
}

// A service prepares an encoder per worker at start: they are kept, and encoding afterwards takes one and
// gives it back (the count does not drop), with the same bytes as before.
TEST(Render, PreparedPngEncodersAreKeptForTheEncodesToCome) {
  raster::Image image;
  image.width = 40, image.height = 30, image.format = raster::PixelFormat::rgb8;
  image.pixels.resize(40 * 30 * 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<std::uint8_t>(i * 7);
  const auto before = raster::encode_png(image);
  const std::size_t kept = raster::kept_png_encoders(1);
  raster::prepare_png_encoders(static_cast<int>(kept) + 3);
  EXPECT_EQ(raster::kept_png_encoders(1), kept + 3);
  EXPECT_EQ(raster::encode_png(image), before);
  EXPECT_EQ(raster::kept_png_encoders(1), kept + 3) << "taken and given back";
  raster::prepare_png_encoders(2);
  EXPECT_EQ(raster::kept_png_encoders(1), kept + 3) << "enough kept already: none made";
}

TEST(Render, PngFilteredInPlaceEqualsTheCopyingEncoder) {
  std::mt19937 rng(3);
  for (auto format : {raster::PixelFormat::grey8, raster::PixelFormat::grey_alpha8, raster::PixelFormat::rgb8,
                      raster::PixelFormat::rgba8}) {
    for (auto [w, h] : {std::pair{1, 1}, {5, 3}, {6, 40}, {17, 9}, {64, 48}, {101, 7}}) {
      raster::Image image;
      image.width = w, image.height = h, image.format = format;
      image.pixels.resize(static_cast<std::size_t>(w) * h * image.channels());
      for (auto& b : image.pixels) b = static_cast<std::uint8_t>(rng() % 4 ? rng() & 7 : rng());
      const auto copied = raster::encode_png(image);
      const auto decoded = test::decode_png(copied);
      EXPECT_EQ(decoded.pixels, image.pixels) << w << "x" << h << " " << image.channels();
      raster::Image moved = image;  // no spare capacity: resize reallocates, still the same bytes
      EXPECT_EQ(raster::encode_png(std::move(moved)), copied) << w << "x" << h << " " << image.channels();
      raster::Image roomy = image;
      roomy.pixels.reserve(roomy.pixels.size() + h);  // as the framebuffer allocates: filtered in place
      EXPECT_EQ(raster::encode_png(std::move(roomy)), copied) << w << "x" << h << " " << image.channels();
    }
  }
}

TEST(Render, AsymmetricImageSurvivesEncodingUnflipped) {
  // Red top-left, green top-right, blue bottom-left: a flip or channel swap in the encoder fails.
  SceneBuilder s(40, 30);
  s.triangle({0, 0}, {10, 0}, {0, 10}, test::kRed)
      .triangle({30, 0}, {40, 0}, {40, 10}, test::kGreen)
      .triangle({0, 20}, {10, 30}, {0, 30}, test::kBlue);
  const auto p = raster::plan(s.scene);
  const auto d = test::decode_png(raster::encode_png(raster::render(s.scene, p), p.png));
  auto px = [&](int x, int y) {
    return std::vector<int>(d.pixels.begin() + (y * 40 + x) * 3, d.pixels.begin() + (y * 40 + x) * 3 + 3);
  };
  EXPECT_EQ(px(1, 1), (std::vector<int>{255, 0, 0}));
  EXPECT_EQ(px(38, 1), (std::vector<int>{0, 255, 0}));
  EXPECT_EQ(px(1, 28), (std::vector<int>{0, 0, 255}));
  EXPECT_EQ(px(38, 28), (std::vector<int>{0, 0, 0}));
}

TEST(Render, BlendingIsSourceOverInDrawOrder) {
  SceneBuilder s(4, 4, raster::Rgba8{0, 0, 255, 255});
  s.triangle({0, 0}, {4, 0}, {0, 4}, raster::Rgba8{255, 0, 0, 128})
      .triangle({0, 0}, {4, 0}, {0, 4}, raster::Rgba8{0, 255, 0, 64});
  const auto c = test::pixel(test::render(s.scene), 0, 0);
  // red over blue: (128, 0, 127); then green a=64: r = 128*191/255, g = 255*64/255, b = 127*191/255
  EXPECT_EQ(c.r, 96);
  EXPECT_EQ(c.g, 64);
  EXPECT_EQ(c.b, 95);
}

TEST(Render, BlendingOntoTransparentKeepsStraightAlpha) {
  SceneBuilder s(2, 2, raster::Rgba8{0, 0, 0, 0});
  s.triangle({0, 0}, {2, 0}, {0, 2}, raster::Rgba8{200, 100, 50, 128})
      .triangle({0, 0}, {2, 0}, {0, 2}, raster::Rgba8{0, 0, 250, 128});
  const auto c = test::pixel(test::render(s.scene), 0, 0);
  // first: exactly the source (nothing below); second over it: a = 128 + 128 * 127/255 = 192
  EXPECT_EQ(c.a, 192);
  EXPECT_EQ(c.r, 66);   // 200 * 128 * 127 / (128 * 255 + 128 * 127) = 66.49
  EXPECT_EQ(c.b, 184);  // (250 * 128 * 255 + 50 * 128 * 127) / ...
}

// The examples are golden images: a change of any pixel, or of a byte of its PNG, changes a hash.
// Regenerate the hashes only after looking at the new pictures (examples/README.md says how), and raise
// the render version with them (the next test).
struct Golden {
  const char* name;      // examples/<name>: a scene, or a model file under models/ drawn as a bare model
  std::uint64_t pixels;  // test::image_hash of the render
  std::uint64_t png;     // FNV-1a of the PNG that raster::encode_png makes of it
};
const Golden kGoldens[] = {
#include "golden_hashes.inc"
};

std::uint64_t fnv1a(const std::vector<std::uint8_t>& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint8_t b : bytes) h = (h ^ b) * 1099511628211ull;
  return h;
}

TEST(Render, ExamplesMatchTheirGoldenHashes) {
  for (const Golden& g : kGoldens) {
    const auto text = test::read_file(std::string(RASTERD_EXAMPLES_DIR) + "/" + g.name);
    // A model file (examples/models/) is drawn as the bare model's picture: read as the service reads it
    // (grey without colours of its own) and drawn in model_scene, as `rasterd render FILE` draws it.
    const bool model = std::string_view(g.name).starts_with("models/");
    const raster::ModelFormat format =
        model ? raster::model_format_of(text, std::nullopt) : raster::ModelFormat{};
    const raster::Scene scene =
        model ? raster::model_scene(raster::checks::model_mesh(text, format, {}, {}, {}, "", 0), format)
              : raster::parse_scene(text);
    const raster::RenderPlan plan = raster::plan(scene);
    raster::Image img = raster::render(scene, plan);
    const std::uint64_t pixels = test::image_hash(img);
    const std::uint64_t png = fnv1a(raster::encode_png(std::move(img), plan.png));
    EXPECT_EQ(pixels, g.pixels) << g.name << "'s pixels changed: 0x" << std::hex << pixels;
    EXPECT_EQ(png, g.png) << g.name << "'s PNG changed: 0x" << std::hex << png;
  }
}

// Every golden belongs to a render version, the one in every ETag: a change of pictures without a new
// version would let caches answer 304 with the old pictures. tests/render_versions.inc is the history,
// one row per version, never edited: each version's digest of the goldens.
TEST(Render, GoldensBelongToTheRenderVersion) {
  std::uint64_t digest = 1469598103934665603ull;
  auto mix = [&](std::uint64_t v) {
    for (int i = 0; i < 8; ++i) digest = (digest ^ (v >> (8 * i) & 0xff)) * 1099511628211ull;
  };
  for (const Golden& g : kGoldens) {
    for (const char* c = g.name; *c; ++c) mix(static_cast<unsigned char>(*c));
    mix(g.pixels), mix(g.png);
  }
  const std::pair<int, std::uint64_t> versions[] = {
#include "render_versions.inc"
  };
  for (std::size_t i = 0; i < std::size(versions); ++i) {
    EXPECT_EQ(versions[i].first, static_cast<int>(i) + 1) << "versions are numbered 1, 2, 3, ...";
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_NE(versions[i].second, versions[j].second)
          << "versions " << j + 1 << " and " << i + 1 << " draw the same";
  }
  const auto& [version, expected] = versions[std::size(versions) - 1];
  EXPECT_EQ(version, raster::kRenderVersion)
      << "the last row of tests/render_versions.inc is raster::kRenderVersion";
  EXPECT_EQ(digest, expected) << "the golden images changed but raster::kRenderVersion did not: raise it to "
                              << raster::kRenderVersion + 1
                              << " (renderer/include/raster/version.h) and append {"
                              << raster::kRenderVersion + 1 << ", 0x" << std::hex << digest
                              << "ull} to tests/render_versions.inc";
}

}  // namespace
