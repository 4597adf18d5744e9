// Textures: decoding with limits, the mip chain, sampling (checked against references computed here, in
// double precision, from the definitions), perspective correctness, and how scenes give textures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <zlib.h>

#include "raster/raster.h"
#include "shade/texture.h"
#include "support.h"

// JPEGs made here, by stb's own writer (baseline: JFIF, DQT, SOF0, one DHT of four tables, SOS, EOI).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace {

using raster::ErrorKind;
using raster::Mesh;
using raster::Scene;
using raster::SceneError;
using raster::Texture;

double to_linear_exact(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double to_linear(int byte) {
  return to_linear_exact(byte / 255.0);
}
int to_byte(double linear) {
  const double c = linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(std::clamp(c, 0.0, 1.0) * 255));
}

// A texture from a function of the texel (x right, y down from the top row).
template <typename F>
Texture make_texture(int w, int h, F texel) {
  Texture t;
  t.width = w, t.height = h;
  t.rgba.resize(std::size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const raster::Rgba8 c = texel(x, y);
      std::uint8_t* p = &t.rgba[(std::size_t(y) * w + x) * 4];
      p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = c.a;
    }
  return t;
}

// The reference: bilinear filtering of level 0 in linear light at (u, v), v up, repeat or clamp.
raster::Rgba8 reference_bilinear(const Texture& t, double u, double v) {
  const double x = u * t.width - 0.5, y = (1 - v) * t.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  auto wrap = [&](double i, int n) {
    if (t.clamp) return static_cast<int>(std::clamp(i, 0.0, n - 1.0));
    return static_cast<int>(std::fmod(std::fmod(i, n) + n, n));
  };
  double acc[3] = {};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const double w = (i ? x - fx : 1 - (x - fx)) * (j ? y - fy : 1 - (y - fy));
      const std::uint8_t* p =
          &t.rgba[(std::size_t(wrap(fy + j, t.height)) * t.width + wrap(fx + i, t.width)) * 4];
      for (int c = 0; c < 3; ++c) acc[c] += w * to_linear(p[c]);
    }
  return {static_cast<std::uint8_t>(to_byte(acc[0])), static_cast<std::uint8_t>(to_byte(acc[1])),
          static_cast<std::uint8_t>(to_byte(acc[2])), 255};
}

// A unit quad [-1, 1]^2 at z = 0 (or as given), uv 0..1 over it, unlit white, textured.
Mesh textured_quad(Texture texture, const raster::Vec3 (&corners)[4]) {
  Mesh m;
  for (const raster::Vec3& c : corners) m.positions.push_back(raster::Vec3f(c));
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.uv_triangles = m.triangles;
  m.textures.push_back(std::move(texture));
  m.colors = {test::kWhite};
  m.shading = raster::Shading::unlit;
  return m;
}

Scene scene_of(Mesh mesh, int size) {
  Scene s;
  s.width = s.height = size;
  s.meshes.push_back(std::move(mesh));
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.primitives.push_back(p);
  return s;
}

// Orthographic, looking down -z at [-1, 1]^2 exactly.
void look_at_unit_square(Scene& s) {
  s.camera.projection = raster::Projection::orthographic;
  s.camera.eye = {0, 0, 5}, s.camera.has_eye = true;
  s.camera.target = {0, 0, 0}, s.camera.has_target = true;
  s.camera.height = 2, s.camera.has_height = true;
}

int max_channel_difference(raster::Rgba8 a, raster::Rgba8 b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

Texture checker(int size, int cell, raster::Rgba8 a, raster::Rgba8 b) {
  return make_texture(size, size, [&](int x, int y) { return ((x / cell + y / cell) & 1) ? a : b; });
}

TEST(Texture, CheckerboardMatchesTheAnalyticRender) {
  // 16 texels over 64 pixels: magnified 4x, so every pixel is bilinear on level 0 at its centre's uv.
  const Texture tex = checker(16, 4, {200, 30, 30, 255}, {20, 40, 220, 255});
  Scene s = scene_of(textured_quad(tex, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}), 64);
  look_at_unit_square(s);
  const raster::Image image = test::render(s);
  int worst = 0;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const double u = (i + 0.5) / 64, v = 1 - (j + 0.5) / 64;
      worst =
          std::max(worst, max_channel_difference(test::pixel(image, i, j), reference_bilinear(tex, u, v)));
    }
  EXPECT_LE(worst, 1);
  // And it is the texture, the right way up: texel (0, 0) is the image's top-left (v = 1 at the top).
  EXPECT_EQ(test::pixel(image, 5, 5), (raster::Rgba8{20, 40, 220, 255}));
  EXPECT_EQ(test::pixel(image, 21, 5), (raster::Rgba8{200, 30, 30, 255}));
}

TEST(Texture, PerspectiveCorrectOnARecedingPlane) {
  // A floor y = -1 from depth 1 to 4 seen from the origin; u runs along depth. Each pixel centre's ray is
  // intersected with the plane here, and its u looked up in an 8-texel ramp (magnified everywhere: at the
  // far edge, depth 4, a pixel spans 4^2 / 64 / 3 = 0.083 of u, 0.67 texels).
  Texture ramp = make_texture(8, 1, [](int x, int) {
    return raster::Rgba8{static_cast<std::uint8_t>(x * 36), static_cast<std::uint8_t>(255 - x * 36), 0, 255};
  });
  ramp.clamp = true;
  Mesh m = textured_quad(ramp, {{-1, -1, -1}, {-1, -1, -4}, {1, -1, -4}, {1, -1, -1}});
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Scene s = scene_of(std::move(m), 128);
  s.camera.eye = {0, 0, 0}, s.camera.has_eye = true;
  s.camera.target = {0, 0, -1}, s.camera.has_target = true;
  s.camera.fov_deg = 90;
  s.camera.near = 0.5, s.camera.has_near = true;
  s.camera.far = 10, s.camera.has_far = true;
  const raster::Image image = test::render(s);

  int worst = 0, checked = 0, affine_gap = 0;
  const double row_near = 64 * (1 + 1.0), row_far = 64 * (1 + 1 / 4.0);  // rows of depth 1 and 4
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const double x = (i + 0.5) / 64 - 1, y = 1 - (j + 0.5) / 64;  // tan(45) = 1
      if (!(y < 0)) continue;
      const double d = -1 / y, u = (d - 1) / 3, s_across = (x * d + 1) / 2;
      // Centres well inside the quad (a pixel from its edges), where coverage is not in question.
      if (!(u > 0.02 && u < 0.98 && s_across > 0.02 && s_across < 0.98)) continue;
      ++checked;
      const raster::Rgba8 want = reference_bilinear(ramp, u, 0.5);
      worst = std::max(worst, max_channel_difference(test::pixel(image, i, j), want));
      // What screen-affine interpolation would give: u linear in the row.
      const double u_affine = std::clamp((row_near - (j + 0.5)) / (row_near - row_far), 0.0, 1.0);
      affine_gap =
          std::max(affine_gap, max_channel_difference(reference_bilinear(ramp, u_affine, 0.5), want));
    }
  EXPECT_GT(checked, 1500);
  EXPECT_LE(worst, 1);
  EXPECT_GT(affine_gap, 60) << "the scene must tell perspective-correct from affine interpolation";
}

TEST(Texture, MipLevelFollowsThePixelFootprint) {
  using raster::detail::mip_lod;
  EXPECT_DOUBLE_EQ(mip_lod(1.0 / 16, 0, 0, 1.0 / 16, 256, 256), 4);     // 16 texels a pixel
  EXPECT_DOUBLE_EQ(mip_lod(1.0 / 256, 0, 0, 1.0 / 1024, 256, 256), 0);  // the longer axis decides
  EXPECT_DOUBLE_EQ(mip_lod(0, 1.0 / 64, 0, 0, 64, 256), 2);             // scaled by the side it runs along
  EXPECT_LT(mip_lod(1.0 / 1024, 0, 0, 1.0 / 1024, 256, 256), 0);        // magnified
  EXPECT_EQ(mip_lod(NAN, 0, 0, 0, 4, 4), 0);
}

// linear_to_srgb finds its byte through a table of buckets and one comparison; the definition is the
// number of thresholds decode((b + 1/2) / 255), b = 0..254, at or below the value (rounding in the encoded
// domain). Checked at each threshold and its float neighbours, and on a dense sweep of 0..1.
TEST(Texture, LinearToSrgbRoundsExactlyAtEveryThreshold) {
  std::vector<float> thresholds;
  for (int b = 0; b < 255; ++b) thresholds.push_back(static_cast<float>(to_linear_exact((b + 0.5) / 255)));
  auto definition = [&](float v) {
    return static_cast<int>(std::upper_bound(thresholds.begin(), thresholds.end(), v) - thresholds.begin());
  };
  int checked = 0;
  for (float t : thresholds)
    for (float v : {std::nextafter(t, 0.0f), t, std::nextafter(t, 2.0f)}) {
      ASSERT_EQ(raster::detail::linear_to_srgb(v), definition(v)) << "at " << v;
      ++checked;
    }
  for (int k = 0; k <= 1 << 20; ++k) {
    const float v = static_cast<float>(k) / (1 << 20);
    ASSERT_EQ(raster::detail::linear_to_srgb(v), definition(v)) << "at " << v;
  }
  EXPECT_EQ(checked, 3 * 255);
  EXPECT_EQ(raster::detail::linear_to_srgb(-1), 0);
  EXPECT_EQ(raster::detail::linear_to_srgb(2), 255);
  EXPECT_EQ(raster::detail::linear_to_srgb(NAN), 0);
  for (int b = 0; b < 256; ++b)
    EXPECT_EQ(raster::detail::linear_to_srgb(raster::detail::srgb_to_linear(b)), b);
}

TEST(Texture, MipmapsAverageInLinearLight) {
  const Texture tex = checker(64, 1, test::kWhite, test::kBlack);
  const raster::detail::MipChain chain = raster::detail::build_mips(tex);
  ASSERT_EQ(chain.levels.size(), 7u);  // 64, 32, ..., 1
  EXPECT_EQ(chain.levels[6].width, 1);
  for (std::size_t l = 1; l < chain.levels.size(); ++l)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(chain.levels[l].rgba[k], 188) << "level " << l;  // 50% light
  EXPECT_EQ(raster::detail::mip_bytes(64, 64), (32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1) * 4);
  EXPECT_EQ(raster::detail::mip_bytes(5, 1), (2 + 1) * 4);
}

TEST(Texture, MinifiedCheckerIsHalfLightNotAliased) {
  // A 1-texel checker of 64 texels on a 16-pixel quad (lod 2) is 50% light everywhere; the same on 64
  // pixels (lod 0, centres on texel centres) is the checker itself.
  const Texture tex = checker(64, 1, test::kWhite, test::kBlack);
  for (const int size : {16, 64}) {
    Scene s = scene_of(textured_quad(tex, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}), size);
    look_at_unit_square(s);
    const raster::Image image = test::render(s);
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const int want = size == 16 ? 188 : (((i + j) & 1) ? 255 : 0);
        ASSERT_NEAR(test::pixel(image, i, j).r, want, 1) << size << " px at " << i << "," << j;
      }
  }
}

// The level the renderer picks, seen in its pixels. Stripes of two black and two white texels, 64 wide, on
// a 32-pixel quad: two texels a pixel, level 1, whose texels are the stripes one texel wide. The coordinates
// are moved by a quarter of a level-1 texel so each level gives another picture: level 1 blends its texels
// 3:1 (sRGB 137 and 225, a quarter and three quarters of the light), level 0 would be sampled on its texel
// centres (0 and 255), level 2 is grey throughout (188).
TEST(Texture, TheRendererPicksTheMipLevelOfThePixelFootprint) {
  const Texture stripes =
      make_texture(64, 64, [](int x, int) { return (x / 2) % 2 ? test::kWhite : test::kBlack; });
  Mesh m = textured_quad(stripes, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  const float shift = -1.0f / 128;
  m.uvs = {{shift, 0}, {1 + shift, 0}, {1 + shift, 1}, {shift, 1}};
  Scene s = scene_of(std::move(m), 32);
  look_at_unit_square(s);
  const raster::Image image = test::render(s);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i)
      ASSERT_NEAR(test::pixel(image, i, j).r, to_byte(i % 2 ? 0.75 : 0.25), 1) << i << "," << j;
}

TEST(Texture, ColourMultipliesTheTextureAndLightingStillApplies) {
  const Texture white = make_texture(2, 2, [](int, int) { return test::kWhite; });
  Mesh m = textured_quad(white, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  m.colors = {{255, 128, 0, 255}};
  Scene s = scene_of(m, 8);
  look_at_unit_square(s);
  s.lights = raster::single_light(0.2, nullptr);  // the headlight, straight on: 0.2 + 0.8 = 1
  EXPECT_EQ(test::pixel(test::render(s), 4, 4), (raster::Rgba8{255, 128, 0, 255}));
  s.meshes[0].shading = raster::Shading::flat;
  EXPECT_EQ(test::pixel(test::render(s), 4, 4), (raster::Rgba8{255, 128, 0, 255}));
  const raster::Vec3 from_behind{0, 0, 1};
  s.lights = raster::single_light(0.2, &from_behind);  // lit from behind: ambient only, 0.2
  EXPECT_EQ(test::pixel(test::render(s), 4, 4), (raster::Rgba8{51, 26, 0, 255}));
}

TEST(Texture, PlanCountsTextureMemoryAndColour) {
  Scene s = scene_of(textured_quad(checker(64, 8, test::kWhite, test::kBlack),
                                   {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}),
                     32);
  const raster::RenderPlan grey = raster::plan(s);
  EXPECT_EQ(grey.memory.texture_bytes, 64 * 64 * 4 + raster::detail::mip_bytes(64, 64));
  EXPECT_EQ(grey.format, raster::PixelFormat::grey8);  // a grey texture on white keeps the image grey
  EXPECT_EQ(grey.textured_count, 1);
  s.meshes[0].textures[0].rgba[0] = 255, s.meshes[0].textures[0].rgba[1] = 0;
  EXPECT_EQ(raster::plan(s).format, raster::PixelFormat::rgb8);
  raster::Limits tight;
  tight.max_buffer_bytes = grey.memory.total() - 1;
  try {
    raster::plan(s, tight);
    FAIL() << "expected a limit error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::limit);
  }
}

TEST(Texture, RendersTheSameAtEveryThreadCountAndSampleCount) {
  Scene s = scene_of(textured_quad(checker(32, 3, {250, 200, 10, 255}, {10, 60, 90, 255}),
                                   {{-1, -1, 0}, {1, -1, -1}, {1, 1, -2}, {-1, 1, 0}}),
                     300);
  for (const int samples : {1, 4}) {
    s.antialias = test::multisample(samples);
    const auto one = test::render(s, 1), three = test::render(s, 3);
    EXPECT_EQ(one.pixels, three.pixels) << samples << " samples";
  }
}

// ---- decoding

std::string png_of(const Texture& t) {
  raster::Image image;
  image.width = t.width, image.height = t.height, image.format = raster::PixelFormat::rgba8;
  image.pixels = t.rgba;
  const auto bytes = raster::encode_png(image);
  return std::string(bytes.begin(), bytes.end());
}

SceneError decode_error(const std::string& bytes, std::int64_t budget = 1 << 24) {
  try {
    raster::decode_texture(bytes, "x.png", budget);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an error";
  return SceneError(ErrorKind::invalid, "none");
}

// A PNG signature and IHDR claiming w x h (the CRC is not checked by stb_image; a real one is not needed
// for the header to be read).
std::string png_header(std::uint32_t w, std::uint32_t h) {
  std::string s("\x89PNG\r\n\x1a\n", 8);
  auto be32 = [&](std::uint32_t v) {
    for (int k = 3; k >= 0; --k) s += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  be32(13), s += "IHDR", be32(w), be32(h);
  s += std::string("\x08\x06\x00\x00\x00", 5);
  be32(0);  // CRC
  return s;
}

TEST(TextureDecode, RoundTripsAPng) {
  const Texture t = checker(5, 2, {1, 2, 3, 255}, {250, 251, 252, 128});
  const Texture back = raster::decode_texture(png_of(t), "c.png", 1000);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.rgba, t.rgba);
  EXPECT_EQ(back.name, "c.png");
}

// Found by texture_fuzzer: an empty IDAT chunk first made stb_image memcpy from a null pointer (UB that
// make test-asan aborts on). Empty IDATs are legal and carry nothing: the image decodes as without them.
TEST(TextureDecode, EmptyIdatChunksAreHarmless) {
  const Texture t = checker(5, 2, {1, 2, 3, 255}, {250, 251, 252, 128});
  std::string png = png_of(t);
  const std::string empty_idat("\0\0\0\0IDAT\0\0\0\0", 12);  // length 0, type, CRC (not checked)
  png.insert(33, empty_idat + empty_idat);                   // after the signature (8) and IHDR (25)
  EXPECT_EQ(raster::decode_texture(png, "e.png", 1000).rgba, t.rgba);
  // And the fuzzer's own case: an empty IDAT that is the file's last, cut before its CRC.
  std::string cut = png_of(t).substr(0, 33) + std::string("\0\0\0\0IDATx", 9);
  EXPECT_EQ(decode_error(cut).kind(), ErrorKind::model);
  std::string lying = png_of(t);
  lying.insert(33, std::string("\x7f\xff\xff\xffIDAT", 8));  // a chunk longer than the file
  EXPECT_EQ(decode_error(lying).kind(), ErrorKind::model);
}

// Found by texture_fuzzer: stb_image sizes its compressed-data buffer from the IDAT lengths a file
// declares, before reading them: 336 bytes declaring a 2 GB IDAT allocated 2 GB. Chunks that do not fit
// in the file are refused first, so the buffer stays within twice the file.
TEST(TextureDecode, ChunkLengthsBeyondTheFileAreRefusedBeforeDecoding) {
  const Texture t = checker(5, 2, {1, 2, 3, 255}, {250, 251, 252, 128});
  std::string png = png_of(t);
  png.insert(33, std::string("\x7f\xff\xff\xf0IDAT", 8) + std::string(100, 'x'));
  const SceneError e = decode_error(png);
  EXPECT_EQ(e.kind(), ErrorKind::model);
  EXPECT_NE(std::string(e.what()).find("declares 2147483632 bytes"), std::string::npos) << e.what();
  // Bytes after IEND are not chunks: left alone, as decoders do.
  EXPECT_EQ(raster::decode_texture(png_of(t) + "trailing", "t.png", 1000).rgba, t.rgba);
}

TEST(TextureDecode, HugeHeadersAreLimitErrorsBeforeAnyAllocation) {
  // 33 bytes claiming 100,000 x 100,000 (40 GB decoded): refused from the header.
  const SceneError huge = decode_error(png_header(100000, 100000));
  EXPECT_EQ(huge.kind(), ErrorKind::limit);
  EXPECT_NE(std::string(huge.what()).find("x.png"), std::string::npos) << huge.what();
  // Within the side limit but over what the scene may still decode.
  const SceneError budget = decode_error(png_header(4000, 4000), 4000 * 3999);
  EXPECT_EQ(budget.kind(), ErrorKind::limit);
  EXPECT_NE(std::string(budget.what()).find("4000x4000"), std::string::npos) << budget.what();
}

// A PNG of one 1x1 RGBA image whose IDAT holds `raw` deflated (zlib), CRCs left 0 (stb_image does not read
// them).
std::string png_with_data(const std::string& raw) {
  uLongf size = compressBound(raw.size());
  std::string z(size, '\0');
  EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(z.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                      raw.size(), 9),
            Z_OK);
  z.resize(size);
  std::string png = png_header(1, 1);
  auto chunk = [&](const char* type, const std::string& data) {
    for (int k = 3; k >= 0; --k) png += static_cast<char>((data.size() >> (8 * k)) & 0xff);
    png += type + data + std::string(4, '\0');
  };
  chunk("IDAT", z);
  chunk("IEND", "");
  return png;
}

// stb_image 2.27 inflates PNG data into a buffer it doubles for as long as the data goes on, then keeps
// the rows the header asked for: a 1.4 MB PNG of deflated zeros behind a 1x1 header took 1.4 GB of memory
// and gave a 1x1 texture. Its allocations are capped by what the header claims, so such data is an error.
TEST(TextureDecode, DataThatInflatesBeyondTheHeaderIsRefused) {
  // What a 1x1 RGBA row is: a filter byte and four bytes; it decodes.
  const Texture one =
      raster::decode_texture(png_with_data(std::string("\0\x10\x20\x30\x40", 5)), "one.png", 1);
  EXPECT_EQ(one.rgba, (std::vector<std::uint8_t>{0x10, 0x20, 0x30, 0x40}));
  // 16 MiB of zeros (16 KB deflated) behind the same header.
  const std::string bomb = png_with_data(std::string(16 << 20, '\0'));
  ASSERT_LT(bomb.size(), 64u << 10);
  const SceneError e = decode_error(bomb);
  EXPECT_EQ(e.kind(), ErrorKind::model);
  EXPECT_NE(std::string(e.what()).find("inflates to more than a 1x1 image holds"), std::string::npos)
      << e.what();
  // The cap is per decode: a valid texture decoded after it is not limited by it.
  const Texture t = checker(300, 7, {1, 2, 3, 255}, {250, 251, 252, 128});
  EXPECT_EQ(raster::decode_texture(png_of(t), "big.png", 1 << 20).rgba, t.rgba);
}

TEST(TextureDecode, BrokenFilesAreModelErrors) {
  EXPECT_EQ(decode_error("").kind(), ErrorKind::model);
  EXPECT_EQ(decode_error("GIF89a....").kind(), ErrorKind::model);
  EXPECT_NE(std::string(decode_error("GIF89a....").what()).find("PNG or JPEG"), std::string::npos);
  const std::string png = png_of(checker(16, 2, test::kWhite, test::kBlack));
  EXPECT_EQ(decode_error(png.substr(0, png.size() / 2)).kind(), ErrorKind::model);  // truncated
  EXPECT_EQ(decode_error(png_header(4, 4)).kind(), ErrorKind::model);               // header only
}

std::string jpeg_of(const Texture& t) {
  std::string out;
  stbi_write_jpg_to_func(
      [](void* into, void* data, int size) {
        static_cast<std::string*>(into)->append(static_cast<char*>(data), size);
      },
      &out, t.width, t.height, 4, t.rgba.data(), 95);
  return out;
}

// Red on the left half, blue on the right: 16 x 8.
Texture two_halves() {
  return make_texture(16, 8, [](int x, int) {
    return x < 8 ? raster::Rgba8{200, 30, 30, 255} : raster::Rgba8{20, 40, 220, 255};
  });
}

// Where the first marker `code` (FF code) is, at or after `from`.
std::size_t marker_at(const std::string& jpeg, unsigned char code, std::size_t from = 2) {
  const std::size_t at = jpeg.find(std::string{'\xff', static_cast<char>(code)}, from);
  EXPECT_NE(at, std::string::npos) << "no marker " << int(code);
  return at;
}

TEST(TextureDecode, DecodesAJpeg) {
  const std::string jpeg = jpeg_of(two_halves());
  const Texture t = raster::decode_texture(jpeg, "halves.jpg", 1 << 20);
  ASSERT_EQ(t.width, 16);
  ASSERT_EQ(t.height, 8);
  auto at = [&](int x, int y) {
    const std::uint8_t* p = &t.rgba[(std::size_t(y) * 16 + x) * 4];
    return raster::Rgba8{p[0], p[1], p[2], p[3]};
  };
  EXPECT_LE(max_channel_difference(at(2, 4), {200, 30, 30, 255}), 12);  // lossy, but that colour
  EXPECT_LE(max_channel_difference(at(13, 4), {20, 40, 220, 255}), 12);
  EXPECT_EQ(at(2, 4).a, 255);
  EXPECT_EQ(raster::decode_texture(jpeg, "halves.jpg", 1 << 20).rgba, t.rgba);  // the same pixels every time
}

// stb_image 2.27 writes past its 257-entry arrays when a DHT's 16 counts add up to more than 256 (found by
// texture_fuzzer; stb issues #1289, #1291). Such a table is refused wherever stb_image could read it.
TEST(TextureDecode, JpegHuffmanTablesOfMoreThan256CodesAreRefused) {
  // texture_fuzzer's finding: a DHT before the frame declaring 0x23 + ... codes.
  const unsigned char finding[] = {0xff, 0xd8, 0xff, 0xff, 0xc4, 0x00, 0x23, 0x00, 0xff, 0xff, 0xff, 0xff,
                                   0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff,
                                   0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff,
                                   0xff, 0xff, 0xff, 0xff, 0xff, 0xc0, 0x0e, 0x20, 0x70, 0x00, 0x60, 0x00,
                                   0xd8, 0xff, 0xff, 0xff, 0xbe, 0x00, 0x00, 0x50};
  const SceneError found = decode_error(std::string(reinterpret_cast<const char*>(finding), sizeof finding));
  EXPECT_EQ(found.kind(), ErrorKind::model);
  EXPECT_NE(std::string(found.what()).find("Huffman table"), std::string::npos) << found.what();

  const std::string jpeg = jpeg_of(two_halves());
  // The writer's own DHT, its first table's counts raised to 255 for lengths 15 and 16.
  std::string inflated = jpeg;
  const std::size_t dht = marker_at(inflated, 0xc4);
  inflated[dht + 5 + 14] = inflated[dht + 5 + 15] = '\xff';
  EXPECT_NE(std::string(decode_error(inflated).what()).find("declares"), std::string::npos);

  // One between scans (where a progressive file has them), after the first scan's data.
  const std::string bad_dht = std::string("\xff\xc4\x00\x13\x00", 5) + std::string(16, '\x20');
  std::string late = jpeg;
  late.insert(late.size() - 2, bad_dht);  // before EOI
  EXPECT_EQ(decode_error(late).kind(), ErrorKind::model);

  // The same bytes inside an APP segment's payload are not a DHT: skipped by its length, as stb_image does.
  std::string in_app = jpeg;
  const std::string app = std::string("\xff\xe1\x00", 3) + static_cast<char>(2 + bad_dht.size()) + bad_dht;
  in_app.insert(2, app);
  EXPECT_EQ(raster::decode_texture(in_app, "app.jpg", 1 << 20).rgba,
            raster::decode_texture(jpeg, "plain.jpg", 1 << 20).rgba);
}

// A scan that selects a Huffman table no DHT defined: stb_image 2.27 decoded it from uninitialised memory.
TEST(TextureDecode, AJpegScanWithoutItsHuffmanTableIsRefused) {
  const std::string jpeg = jpeg_of(two_halves());
  std::string no_tables = jpeg;
  const std::size_t dht = marker_at(no_tables, 0xc4);
  const std::size_t length =
      static_cast<std::uint8_t>(no_tables[dht + 2]) << 8 | static_cast<std::uint8_t>(no_tables[dht + 3]);
  no_tables.erase(dht, 2 + length);
  const SceneError e = decode_error(no_tables);
  EXPECT_EQ(e.kind(), ErrorKind::model);
  EXPECT_NE(std::string(e.what()).find("no table segment (DHT)"), std::string::npos) << e.what();

  std::string other_table =
      jpeg;  // the first component's DC and AC tables: 2 and 2 (the writer defines 0 and 1)
  const std::size_t sos = marker_at(other_table, 0xda);
  other_table[sos + 6] = '\x22';
  EXPECT_NE(std::string(decode_error(other_table).what()).find("DC Huffman table 2"), std::string::npos);
}

// Found by texture_fuzzer: a JPEG whose scan a stray marker (FF 5E) cuts short. stb_image 2.27's bit reader
// then counts fewer than no bits and its next refill shifts by 32 (stb #1293), undefined behaviour that make
// test-asan aborts on. Past the cut the reader now takes zeros, as stb_image 2.28 does, the same every time.
TEST(TextureDecode, AJpegScanCutShortByAMarkerReadsZerosPastTheCut) {
  const std::string finding =
      test::read_file(RASTERD_TESTS_DIR "/data/textures/finding-scan-cut-by-marker.jpg");
  // Its marker is none stb_image knows: once the scan is read (past the cut, zeros), the file is refused.
  EXPECT_EQ(decode_error(finding).kind(), ErrorKind::model);
  // A valid file cut halfway through its scan data and ended there (EOI): the cut half decodes from zeros,
  // the same every time, and the first texels are the image's.
  const std::string jpeg = jpeg_of(two_halves());
  const std::size_t data = marker_at(jpeg, 0xda) + 2 + 12;  // after SOS and its 12-byte header (3 components)
  const std::string cut = jpeg.substr(0, data + (jpeg.size() - 2 - data) / 2) + "\xff\xd9";
  const Texture half = raster::decode_texture(cut, "cut.jpg", 1 << 20);
  EXPECT_EQ(half.rgba, raster::decode_texture(cut, "cut.jpg", 1 << 20).rgba);
  const Texture whole = raster::decode_texture(jpeg, "whole.jpg", 1 << 20);
  EXPECT_TRUE(std::equal(whole.rgba.begin(), whole.rgba.begin() + 4 * 4, half.rgba.begin()))
      << "the first texels, before the cut";
}

// A glTF MASK material's cut-out texels (alpha 0 after the cutoff) write neither colour nor depth: a quad
// drawn later behind a cut-out quad shows through the cut-out half, aliased and multisampled, and is hidden
// by the kept half. The same front quad with its cut-out half opaque hides it everywhere (depth works).
TEST(Texture, ACutOutTexelWritesNoDepth) {
  // Left half cut out (alpha 0, its colour red so that a drawn one would show), right half opaque green.
  auto front_texture = [](std::uint8_t left_alpha) {
    Texture t = make_texture(8, 8, [&](int x, int) {
      return x < 4 ? raster::Rgba8{255, 0, 0, left_alpha} : raster::Rgba8{0, 255, 0, 255};
    });
    t.clamp = true;  // repeating would mix the far edge's texels into the near one's
    return t;
  };
  auto scene = [&](std::uint8_t left_alpha, int samples) {
    Scene s = scene_of(
        textured_quad(front_texture(left_alpha), {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}), 64);
    Mesh back;  // drawn after the front quad, behind it (z = -1: farther from the eye at z = 5)
    back.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}};
    back.triangles = {{0, 1, 2}, {0, 2, 3}};
    back.colors = {test::kBlue};
    back.shading = raster::Shading::unlit;
    s.meshes.push_back(std::move(back));
    raster::Primitive p;
    p.kind = raster::PrimitiveKind::mesh;
    p.mesh = 1;
    s.primitives.push_back(p);
    look_at_unit_square(s);
    s.antialias = test::multisample(samples);
    return s;
  };
  for (const int samples : {1, 4}) {
    SCOPED_TRACE(samples == 1 ? "aliased" : "4x multisampled");
    const Scene cut = scene(0, samples);
    EXPECT_TRUE(raster::plan(cut).draw_of(0)->mode.cut_outs) << "the plan finds the alpha-0 texels";
    const raster::Image image = test::render(cut);
    // Away from the middle column (where bilinear filtering mixes the halves): the cut-out half shows the
    // blue quad behind it, the kept half is green.
    for (int y = 2; y < 62; y += 6) {
      for (int x = 1; x < 26; x += 3) EXPECT_EQ(test::pixel(image, x, y), test::kBlue) << x << ", " << y;
      for (int x = 36; x < 63; x += 3) EXPECT_EQ(test::pixel(image, x, y), test::kGreen) << x << ", " << y;
    }
    const Scene opaque = scene(255, samples);
    EXPECT_FALSE(raster::plan(opaque).draw_of(0)->mode.cut_outs) << "no alpha-0 texel: the depth-first path";
    const raster::Image hidden = test::render(opaque);
    for (int y = 2; y < 62; y += 6) {
      for (int x = 1; x < 26; x += 3) EXPECT_EQ(test::pixel(hidden, x, y), test::kRed) << x << ", " << y;
      for (int x = 36; x < 63; x += 3) EXPECT_EQ(test::pixel(hidden, x, y), test::kGreen) << x << ", " << y;
    }
  }
}

}  // namespace
