// Materials that follow their format (issue 42, point 4): glTF metallic-roughness shaded by the glTF BRDF
// (with its metallicRoughnessTexture), MTL Ks/Ns as a Blinn-Phong lobe, and Lambert left exactly as it was
// for every model that gives none of those fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model_files.h"
#include "raster/model.h"
#include "raster/plan.h"
#include "raster/png.h"
#include "raster/render.h"
#include "raster/scene.h"
#include "support.h"

namespace {

constexpr int kSide = 128;

// A UV sphere of radius 1 (n x n quads) with normals and texture coordinates, as a .gltf whose buffer is a
// data: URI; `material` is the document's "materials" array's text ("" for none) and `images` the text of
// its "images", "textures" and "samplers" members ("" for none).
std::string sphere_gltf(const std::string& material, const std::string& images = "", bool normals = true,
                        int n = 40) {
  std::string buffer;
  std::vector<std::array<float, 3>> p;
  std::vector<std::array<float, 2>> uv;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double theta = M_PI * i / n, phi = 2 * M_PI * j / n;
      p.push_back({static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                   static_cast<float>(-std::sin(theta) * std::sin(phi))});
      uv.push_back({static_cast<float>(j) / n, static_cast<float>(i) / n});
    }
  std::vector<std::uint32_t> idx;
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      idx.insert(idx.end(),
                 {at(i, j), at(i + 1, j), at(i, j + 1), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
  for (const auto& q : p)
    for (float c : q) test::put<float>(buffer, c);
  const std::size_t normal_at = buffer.size();
  for (const auto& q : p)
    for (float c : q) test::put<float>(buffer, c);  // a unit sphere's normals are its points
  const std::size_t uv_at = buffer.size();
  for (const auto& q : uv)
    for (float c : q) test::put<float>(buffer, c);
  const std::size_t index_at = buffer.size();
  for (std::uint32_t i : idx) test::put<std::uint32_t>(buffer, i);
  const std::string count = std::to_string(p.size());
  auto view = [&](std::size_t from, std::size_t to) {
    return "{\"buffer\": 0, \"byteOffset\": " + std::to_string(from) +
           ", \"byteLength\": " + std::to_string(to - from) + "}";
  };
  std::string attributes = R"("POSITION": 0, "TEXCOORD_0": 2)";
  if (normals) attributes += R"(, "NORMAL": 1)";
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {)" +
         attributes + R"(}, "indices": 3)" + (material.empty() ? "" : R"(, "material": 0)") + R"(}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
         count + R"(, "type": "VEC3", "min": [-1, -1, -1], "max": [1, 1, 1]},
    {"bufferView": 1, "componentType": 5126, "count": )" +
         count + R"(, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": )" +
         count + R"(, "type": "VEC2"},
    {"bufferView": 3, "componentType": 5125, "count": )" +
         std::to_string(idx.size()) + R"(, "type": "SCALAR"}],
  "bufferViews": [)" +
         view(0, normal_at) + ", " + view(normal_at, uv_at) + ", " + view(uv_at, index_at) + ", " +
         view(index_at, buffer.size()) + R"(],
  "buffers": [{"byteLength": )" +
         std::to_string(buffer.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
         test::base64(buffer) + "\"}]" + (material.empty() ? "" : ", \"materials\": " + material) +
         (images.empty() ? "" : ", " + images) + "}";
}

// The model alone in a kSide x kSide scene: the fitted camera and the default lights.
raster::Scene scene_of(raster::Mesh mesh) {
  raster::Scene s;
  s.width = s.height = kSide;
  s.background = {0, 0, 0, 255};
  if (mesh.colors.empty()) mesh.colors = {{204, 204, 204, 255}};  // what a scene gives an OBJ without Kd
  s.meshes.push_back(std::move(mesh));
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.primitives.push_back(p);
  return s;
}

raster::Image render_gltf(const std::string& document) {
  return test::render(scene_of(raster::parse_gltf(document)));
}

// A channel value of pixel (x, y), 0 for grey images' G and B as well as R.
int channel(const raster::Image& im, int x, int y, int c) {
  return im.at(x, y)[std::min(c, im.channels() - 1)];
}

// The pixel where `a` is brightest over `b` (the least of its channels' excess), and that excess.
struct Brighter {
  int x = 0, y = 0, by = -256;
};
Brighter most_brighter(const raster::Image& a, const raster::Image& b) {
  Brighter best;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      int least = 255;
      for (int c = 0; c < 3; ++c) least = std::min(least, channel(a, x, y, c) - channel(b, x, y, c));
      if (least > best.by) best = {x, y, least};
    }
  return best;
}

int brightest(const raster::Image& im) {
  int most = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      for (int c = 0; c < 3; ++c) most = std::max(most, channel(im, x, y, c));
  return most;
}

// A 2 x 2 texture of one colour, as a PNG data: URI image with its texture.
std::string one_colour_texture(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  raster::Image im;
  im.width = im.height = 2, im.format = raster::PixelFormat::rgb8;
  im.pixels = {r, g, b, r, g, b, r, g, b, r, g, b};
  const std::vector<std::uint8_t> png = raster::encode_png(im);
  return R"("images": [{"uri": "data:image/png;base64,)" + test::base64(std::string(png.begin(), png.end())) +
         R"("}], "textures": [{"source": 0}])";
}

const std::string kGrey = R"("baseColorFactor": [0.6, 0.6, 0.6, 1])";

TEST(Material, GltfMetalShowsAHighlightWhereLambertHasNone) {
  const raster::Image lambert = render_gltf(sphere_gltf("[{\"pbrMetallicRoughness\": {" + kGrey + "}}]"));
  const raster::Image metal = render_gltf(sphere_gltf("[{\"pbrMetallicRoughness\": {" + kGrey +
                                                      R"(, "metallicFactor": 1, "roughnessFactor": 0.2}}])"));
  ASSERT_GT(test::count_not(metal, test::kBlack), kSide * kSide / 5) << "the sphere is drawn";
  // Lambert under the default lights never reaches white on this grey; the metal's highlight does, at a
  // pixel where Lambert is much darker.
  EXPECT_LT(brightest(lambert), 235);
  const Brighter b = most_brighter(metal, lambert);
  EXPECT_GE(b.by, 40) << "at " << b.x << ", " << b.y;
  for (int c = 0; c < 3; ++c) EXPECT_GE(channel(metal, b.x, b.y, c), 245) << "channel " << c;
  // Away from the highlights a metal has no diffuse light: most of the sphere is darker than Lambert's.
  int darker = 0;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) darker += channel(metal, x, y, 0) + 10 < channel(lambert, x, y, 0);
  EXPECT_GT(darker, kSide * kSide / 8);
  // A rough metal spreads the highlight: no pixel as bright as the smooth one's peak.
  const raster::Image rough = render_gltf(sphere_gltf("[{\"pbrMetallicRoughness\": {" + kGrey +
                                                      R"(, "metallicFactor": 1, "roughnessFactor": 1}}])"));
  EXPECT_LT(brightest(rough), brightest(metal) - 40);
}

TEST(Material, GltfWithoutMaterialFieldsKeepsLambert) {
  // Neither factor nor texture: Lambert, decided by the reader (no material), so the plan takes today's
  // path and the bytes are the same as a mesh that never had a material.
  const raster::Mesh plain = raster::parse_gltf(sphere_gltf("[{\"pbrMetallicRoughness\": {" + kGrey + "}}]"));
  EXPECT_TRUE(plain.materials.empty());
  EXPECT_TRUE(plain.face_materials.empty());
  const raster::RenderPlan plan = raster::plan(scene_of(plain));
  ASSERT_EQ(plan.draws.size(), 1u);
  EXPECT_FALSE(plan.draws[0].mode.specular);
  // Either factor alone asks for the BRDF, the other taking glTF's default (1).
  const raster::Mesh metal =
      raster::parse_gltf(sphere_gltf("[{\"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}}]"));
  ASSERT_EQ(metal.materials.size(), 1u);
  EXPECT_EQ(metal.materials[0].model, raster::Material::Model::metallic_roughness);
  EXPECT_EQ(metal.materials[0].metallic, 1.0f);
  EXPECT_EQ(metal.materials[0].roughness, 0.5f);
  EXPECT_EQ(metal.face_materials, std::vector<std::int32_t>(metal.triangles.size(), 0));
  // A Lambert material (and a Blinn-Phong one without Ks) on a mesh changes no byte.
  raster::Mesh with = plain;
  with.materials.push_back({});
  raster::Material no_ks;
  no_ks.model = raster::Material::Model::blinn_phong, no_ks.shininess = 30;
  with.materials.push_back(no_ks);
  for (std::size_t t = 0; t < with.triangles.size(); ++t)
    with.face_materials.push_back(static_cast<std::int32_t>(t % 3) - 1);
  EXPECT_EQ(test::render(scene_of(with)).pixels, test::render(scene_of(plain)).pixels);
}

TEST(Material, MetallicRoughnessTextureIsRead) {
  auto with_texture = [&](std::uint8_t g, std::uint8_t b) {
    return render_gltf(sphere_gltf(
        "[{\"pbrMetallicRoughness\": {" + kGrey + R"(, "metallicRoughnessTexture": {"index": 0}}}])",
        one_colour_texture(0, g, b)));
  };
  const raster::Mesh read = raster::parse_gltf(
      sphere_gltf("[{\"pbrMetallicRoughness\": {\"metallicRoughnessTexture\": {\"index\": 0}}}]",
                  one_colour_texture(0, 51, 255)));
  ASSERT_EQ(read.materials.size(), 1u);
  EXPECT_EQ(read.materials[0].metallic_roughness_texture, 0);
  EXPECT_FALSE(read.uv_triangles.empty()) << "the texture's coordinates are kept";
  // B = 255, G = 51: metallic 1, roughness 0.2 (the factors default to 1), as the factors give it.
  const raster::Image textured = with_texture(51, 255);
  const raster::Image factors = render_gltf(sphere_gltf(
      "[{\"pbrMetallicRoughness\": {" + kGrey + R"(, "metallicFactor": 1, "roughnessFactor": 0.2}}])"));
  int most = 0;
  for (std::size_t i = 0; i < textured.pixels.size(); ++i)
    most = std::max(most, std::abs(textured.pixels[i] - factors.pixels[i]));
  EXPECT_LE(most, 2) << "the texture's B and G multiply the factors";
  // Each channel matters: no metal (B = 0) is a dielectric, rough (G = 255) has no sharp highlight.
  const raster::Image dielectric = with_texture(51, 0), rough = with_texture(255, 255);
  EXPECT_GT(most_brighter(dielectric, textured).by, 30) << "a dielectric keeps its diffuse light";
  EXPECT_LT(brightest(rough), brightest(textured) - 40);
  // R is not read (glTF keeps occlusion there).
  EXPECT_EQ(render_gltf(sphere_gltf("[{\"pbrMetallicRoughness\": {" + kGrey +
                                        R"(, "metallicRoughnessTexture": {"index": 0}}}])",
                                    one_colour_texture(200, 51, 255)))
                .pixels,
            textured.pixels);
}

// A UV sphere as OBJ text, with a material when `mtl` says so.
std::string sphere_obj(bool with_material, int n = 40) {
  std::string s = with_material ? "mtllib m.mtl\nusemtl shiny\n" : "";
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double theta = M_PI * i / n, phi = 2 * M_PI * j / n;
      s += "v " + std::to_string(std::sin(theta) * std::cos(phi)) + " " + std::to_string(std::cos(theta)) +
           " " + std::to_string(-std::sin(theta) * std::sin(phi)) + "\n";
    }
  auto at = [&](int i, int j) { return std::to_string(i * (n + 1) + j + 1); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      s += "f " + at(i, j) + " " + at(i + 1, j) + " " + at(i + 1, j + 1) + " " + at(i, j + 1) + "\n";
  return s;
}

TEST(Material, MtlKsAndNsShowAHighlight) {
  const std::string obj = sphere_obj(true);
  auto render = [&](const std::string& mtl) {
    return test::render(scene_of(raster::parse_obj(obj, "newmtl shiny\nKd 0.6 0.6 0.6\n" + mtl)));
  };
  const raster::Image lambert = render(""), shiny = render("Ks 0.8 0.8 0.8\nNs 60\n");
  EXPECT_EQ(raster::parse_obj(obj, "newmtl shiny\nKd 0.6 0.6 0.6\nKs 1 1 1\nNs 60\n").materials.size(), 1u);
  const Brighter b = most_brighter(shiny, lambert);
  EXPECT_GE(b.by, 40) << "at " << b.x << ", " << b.y;
  // Blinn-Phong adds to Lambert: no pixel is darker.
  EXPECT_LE(most_brighter(lambert, shiny).by, 0);
  // A larger exponent makes a smaller highlight.
  int wide = 0, narrow = 0;
  const raster::Image tight = render("Ks 0.8 0.8 0.8\nNs 400\n");
  for (std::size_t i = 0; i < lambert.pixels.size(); ++i)
    wide += shiny.pixels[i] > lambert.pixels[i] + 8, narrow += tight.pixels[i] > lambert.pixels[i] + 8;
  EXPECT_GT(wide, narrow);
  EXPECT_GT(narrow, 0);
  // Ks 0 (or none) is Lambert, byte for byte.
  EXPECT_EQ(render("Ks 0 0 0\nNs 60\n").pixels, lambert.pixels);
  EXPECT_EQ(render("Ns 60\n").pixels, lambert.pixels);
  EXPECT_TRUE(raster::parse_obj(obj, "newmtl shiny\nKd 0.6 0.6 0.6\nKs 0 0 0\n").materials.empty());
}

// Specular meshes, smooth and flat, with a texture, point lights and an orthographic camera: the same bytes
// with SSE2 and AVX2 kernels, on one thread and three, aliased and multisampled.
TEST(Material, SpecularMeshesGiveTheBytesOfSse2OnEverySimdTarget) {
  if (raster::best_simd() == raster::Simd::sse2) GTEST_SKIP() << "no AVX2 on this machine";
  std::vector<std::pair<std::string, raster::Scene>> cases;
  raster::Scene metal = scene_of(raster::parse_gltf(sphere_gltf(
      "[{\"pbrMetallicRoughness\": {\"baseColorFactor\": [0.9, 0.5, 0.2, 1], \"metallicFactor\": 0.7, "
      "\"roughnessFactor\": 0.3, \"metallicRoughnessTexture\": {\"index\": 0}}}]",
      one_colour_texture(0, 200, 230))));
  cases.emplace_back("glTF metallic-roughness, textured", metal);
  raster::Scene flat = scene_of(raster::parse_gltf(sphere_gltf(
      "[{\"pbrMetallicRoughness\": {\"metallicFactor\": 0, \"roughnessFactor\": 0.4}}]", "", false)));
  EXPECT_EQ(flat.meshes[0].shading, raster::Shading::flat);
  cases.emplace_back("flat, face normals", flat);
  raster::Scene phong = scene_of(
      raster::parse_obj(sphere_obj(true), "newmtl shiny\nKd 0.2 0.5 0.9\nKs 0.9 0.7 0.5\nNs 37.4\n"));
  cases.emplace_back("Blinn-Phong", phong);
  raster::Scene point = metal;
  raster::Light ambient, lamp, sun;
  ambient.kind = raster::LightKind::ambient, ambient.intensity = 0.2;
  lamp.kind = raster::LightKind::point, lamp.position = {0.6, 1.5, 2}, lamp.color = {1, 0.8, 0.6};
  sun.direction = {0.3, -0.4, -1}, sun.intensity = 0.6;
  point.lights = {ambient, lamp, sun};
  cases.emplace_back("point light", point);
  raster::Scene ortho = phong;
  ortho.lights = point.lights;
  ortho.camera.projection = raster::Projection::orthographic;
  cases.emplace_back("orthographic", ortho);
  auto render_at = [](const raster::Scene& scene, raster::Simd simd, int tile, int threads) {
    raster::PlanOptions options;
    options.max_simd = simd, options.tile = tile, options.max_threads = threads;
    raster::RenderPlan plan = raster::plan(scene, {}, options);
    EXPECT_TRUE(plan.draws[0].mode.specular);
    plan.threads = threads;
    return raster::render(scene, plan);
  };
  for (auto& [name, scene] : cases)
    for (int aa : {1, 4}) {
      scene.antialias = test::multisample(aa);
      const raster::Image expected = render_at(scene, raster::Simd::sse2, 64, 1);
      ASSERT_GT(test::count_not(expected, test::kBlack), kSide * kSide / 5) << name;
      for (raster::Simd simd : {raster::Simd::sse2, raster::Simd::avx2})
        for (int tile : {16, 64})
          for (int threads : {1, 3})
            ASSERT_EQ(render_at(scene, simd, tile, threads).pixels, expected.pixels)
                << name << ", antialias " << aa << ", " << (simd == raster::Simd::avx2 ? "AVX2" : "SSE2")
                << ", tile " << tile << ", " << threads << " threads";
    }
}

// Materials out of their ranges are refused by the plan's checks for scenes built in code, not drawn as
// NaN.
TEST(Material, OutOfRangeMaterialsAreRefused) {
  raster::Mesh mesh =
      raster::parse_gltf(sphere_gltf("[{\"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}}]"));
  mesh.materials[0].roughness = NAN;
  EXPECT_THROW(raster::plan(scene_of(mesh)), raster::SceneError);
  mesh.materials[0].roughness = 0.5f, mesh.face_materials[0] = 1;
  EXPECT_THROW(raster::plan(scene_of(mesh)), raster::SceneError);
}

}  // namespace
