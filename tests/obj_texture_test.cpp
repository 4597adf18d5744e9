// OBJ + MTL + texture files as people bring them: every quirk in tests/data/mtl/ is a fixture read with
// the same quad, and what each must give is asserted (texture found, options, colour, a rendered pixel).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "raster/raster.h"
#include "support.h"

namespace {

using raster::ErrorKind;
using raster::Mesh;
using raster::SceneError;

const std::string kDir = RASTERD_TESTS_DIR "/data/mtl/";

// A 4x4 PNG: a red-green-blue-yellow 2x2 checker of 2-texel cells (top-left red), or all white.
std::string texture_png(bool white) {
  raster::Image image;
  image.width = image.height = 4, image.format = raster::PixelFormat::rgb8;
  const raster::Rgba8 cells[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const raster::Rgba8 c = white ? test::kWhite : cells[(y / 2) * 2 + x / 2];
      image.pixels.insert(image.pixels.end(), {c.r, c.g, c.b});
    }
  const auto png = raster::encode_png(image);
  return std::string(png.begin(), png.end());
}

raster::Uploads images() {
  return {{"checker.png", texture_png(false)},
          {"my checker.png", texture_png(false)},
          {"white.png", texture_png(true)}};
}

Mesh read(const std::string& mtl_file) {
  return raster::parse_obj(test::read_file(kDir + "quad.obj"), test::read_file(kDir + mtl_file), {},
                           images());
}

// The quad filling a 4x4 image, unlit: each pixel centre is a texel centre of the 4x4 texture (lod 0).
raster::Image render(const Mesh& mesh) {
  raster::Scene s;
  s.width = s.height = 4;
  s.meshes.push_back(mesh);
  s.meshes[0].shading = raster::Shading::unlit;
  if (s.meshes[0].colors.empty()) s.meshes[0].colors = {test::kWhite};  // as the scene reader gives a model
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.primitives.push_back(p);
  s.camera.projection = raster::Projection::orthographic;
  s.camera.eye = {0, 0, 5}, s.camera.has_eye = true;
  s.camera.target = {0, 0, 0}, s.camera.has_target = true;
  s.camera.height = 2, s.camera.has_height = true;
  return test::render(s);
}

void expect_checker(const Mesh& m, const char* fixture) {
  ASSERT_EQ(m.textures.size(), 1u) << fixture;
  EXPECT_EQ(m.textures[0].width, 4) << fixture;
  ASSERT_EQ(m.face_textures.size(), 2u) << fixture;  // the quad's two triangles
  EXPECT_EQ(m.face_textures[0], 0) << fixture;
  const raster::Image image = render(m);
  EXPECT_EQ(test::pixel(image, 0, 0), (raster::Rgba8{255, 0, 0, 255})) << fixture;  // top-left: red
  EXPECT_EQ(test::pixel(image, 3, 0), (raster::Rgba8{0, 255, 0, 255})) << fixture;
  EXPECT_EQ(test::pixel(image, 0, 3), (raster::Rgba8{0, 0, 255, 255})) << fixture;
  EXPECT_EQ(test::pixel(image, 3, 3), (raster::Rgba8{255, 255, 0, 255})) << fixture;
}

TEST(ObjTexture, TheTextureTheMtlNamesIsUsed) {
  expect_checker(read("basic.mtl"), "basic.mtl");
}

TEST(ObjTexture, NameQuirksAllFindTheFile) {
  for (const char* fixture :
       {"trailing-blanks.mtl", "windows-path.mtl", "relative-path.mtl", "map-kd-capital.mtl"})
    expect_checker(read(fixture), fixture);
  const Mesh spaces = read("spaces.mtl");
  ASSERT_EQ(spaces.textures.size(), 1u);
  EXPECT_EQ(spaces.textures[0].name, "my checker.png");
}

TEST(ObjTexture, UpperCaseKeywordsAreRead) {
  const Mesh m = read("uppercase.mtl");
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].name, "checker.png");
  EXPECT_EQ(m.face_colors.at(0), (raster::Rgba8{255, 0, 0, 255}));  // KD 1 0 0
}

TEST(ObjTexture, OptionsBeforeTheNameAreParsedNotTakenForIt) {
  const Mesh m = read("options.mtl");
  ASSERT_EQ(m.textures.size(), 1u);
  const raster::Texture& t = m.textures[0];
  EXPECT_EQ(t.name, "checker.png");
  EXPECT_TRUE(t.clamp);
  EXPECT_EQ(t.scale, (std::array<float, 2>{2, 2}));
  EXPECT_EQ(t.offset, (std::array<float, 2>{0.5f, 0.25f}));
  const Mesh all = read("options-all.mtl");
  ASSERT_EQ(all.textures.size(), 1u);
  EXPECT_EQ(all.textures[0].name, "checker.png");
  EXPECT_FALSE(all.textures[0].clamp);
  expect_checker(all, "options-all.mtl");  // -s 1 1 1 -o 0: the identity
}

TEST(ObjTexture, ScaleAndOffsetMoveTheTexture) {
  // -o 0.5 0.25 shifts u by half the image: the top-left pixel shows the top-right cell (green); -s 2 2
  // with -clamp on then squeezes: u = 0.125 * 2 + 0.5 = 0.75.
  const raster::Image image = render(read("options.mtl"));
  EXPECT_EQ(test::pixel(image, 0, 0), (raster::Rgba8{0, 255, 0, 255}));
}

// -s 2 2 -o 0.5 0 with the image repeating: u' = 2u + 0.5, v' = 2v. Each pixel centre falls halfway between
// two texels of one cell, so the picture is the checker in 1-pixel cells with left and right swapped. Without
// -s the cells would be 2 pixels; without -o not swapped; without v's scale 2 rows tall.
TEST(ObjTexture, ScaleAndOffsetTogetherRepeatTheTexture) {
  const raster::Image image = render(read("scale-offset.mtl"));
  const raster::Rgba8 cells[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const raster::Rgba8 want = cells[(j % 2) * 2 + (i + 1) % 2], got = test::pixel(image, i, j);
      // Two texels a pixel: level 1 of the mipmaps, whose texels are the cells themselves.
      EXPECT_LE(std::max({std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b)}), 2)
          << i << "," << j;
    }
}

TEST(ObjTexture, KdMultipliesTheTextureAndItsAbsenceMeansWhite) {
  EXPECT_EQ(test::pixel(render(read("kd-multiplies.mtl")), 1, 1), (raster::Rgba8{255, 0, 0, 255}));
  EXPECT_EQ(test::pixel(render(read("no-kd.mtl")), 1, 1), test::kWhite);
  // Kd 1 0 1 times the checker, per channel: red stays, green goes black, blue stays, yellow turns red.
  const raster::Image image = render(read("kd-checker.mtl"));
  EXPECT_EQ(test::pixel(image, 0, 0), (raster::Rgba8{255, 0, 0, 255}));
  EXPECT_EQ(test::pixel(image, 3, 0), (raster::Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(test::pixel(image, 0, 3), (raster::Rgba8{0, 0, 255, 255}));
  EXPECT_EQ(test::pixel(image, 3, 3), (raster::Rgba8{255, 0, 0, 255}));
}

TEST(ObjTexture, AMissingTextureNamesTheFileAndWhatWasSent) {
  try {
    read("missing.mtl");
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::model);
    const std::string m = e.what();
    EXPECT_NE(m.find("\"absent.png\""), std::string::npos) << m;
    EXPECT_NE(m.find("line 3"), std::string::npos) << m;
    EXPECT_NE(m.find("\"checker.png\", \"my checker.png\", \"white.png\""), std::string::npos) << m;
  }
}

TEST(ObjTexture, AnUnknownOptionIsAnErrorWithItsLine) {
  try {
    read("bad-option.mtl");
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::model);
    EXPECT_NE(std::string(e.what()).find("line 3: map_Kd option -zoom"), std::string::npos) << e.what();
  }
}

// f3d#1973: the materials are the file `mtllib` names. Sent among the files (not as MTL text), it is found by
// its file name, folders dropped, like a texture; several on one line are all read; a name may hold spaces.
TEST(ObjTexture, MtllibFindsTheMaterialsAmongTheUploadedFiles) {
  const std::string quad = test::read_file(kDir + "quad.obj");  // "mtllib quad.mtl", faces "usemtl skin"
  raster::Uploads files = images();
  files["quad.mtl"] = test::read_file(kDir + "basic.mtl");
  expect_checker(raster::parse_obj(quad, {}, {}, files), "mtllib quad.mtl");

  std::string in_folder = quad;
  in_folder.replace(in_folder.find("mtllib quad.mtl"), 15, "mtllib ..\\materials\\quad.mtl\r");
  expect_checker(raster::parse_obj(in_folder, {}, {}, files), "mtllib with a Windows folder and a CR");

  // Two libraries on one line, each defining one of the two materials the faces use.
  const std::string two =
      "mtllib colours.mtl skin.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
      "usemtl skin\nf 1/1 2/2 3/3\nusemtl red\nf 1 3 4\n";
  raster::Uploads split = images();
  split["colours.mtl"] = "newmtl red\nKd 1 0 0\n";
  split["skin.mtl"] = test::read_file(kDir + "basic.mtl");
  const Mesh both = raster::parse_obj(two, {}, {}, split);
  ASSERT_EQ(both.textures.size(), 1u);
  ASSERT_EQ(both.face_colors.size(), 2u);
  EXPECT_EQ(both.face_textures, (std::vector<std::int32_t>{0, -1}));
  EXPECT_EQ(both.face_colors[1], (raster::Rgba8{255, 0, 0, 255}));

  std::string spaced = quad;
  spaced.replace(spaced.find("mtllib quad.mtl"), 15, "mtllib my materials.mtl");
  raster::Uploads spaced_files = images();
  spaced_files["my materials.mtl"] = test::read_file(kDir + "basic.mtl");
  expect_checker(raster::parse_obj(spaced, {}, {}, spaced_files), "mtllib my materials.mtl");
}

TEST(ObjTexture, GivenMtlTextWinsAndAnUnsentLibraryIsNoError) {
  const std::string quad = test::read_file(kDir + "quad.obj");
  raster::Uploads files = images();
  files["quad.mtl"] = test::read_file(kDir + "basic.mtl");
  // The MTL given as text (the "mtl" part) is the materials, whatever mtllib says.
  const Mesh red = raster::parse_obj(quad, test::read_file(kDir + "kd-multiplies.mtl"), {}, files);
  EXPECT_EQ(red.textures.at(0).name, "white.png");
  // A bare model that names a library nobody sent keeps the default grey and no texture.
  const Mesh bare = raster::parse_obj(quad, {}, {}, images());
  EXPECT_TRUE(bare.textures.empty());
  // No colour of its own (the scene's default grey is what it is drawn in).
  EXPECT_TRUE(bare.face_colors.empty());
  EXPECT_TRUE(bare.colors.empty());
  // And a library is looked up among the uploads only: never on this disk.
  std::string outside = quad;
  outside.replace(outside.find("mtllib quad.mtl"), 15, "mtllib /etc/passwd");
  EXPECT_TRUE(raster::parse_obj(outside, {}, {}, images()).textures.empty());
}

// What a model names, for a program with its folder at hand: the libraries, then the textures they name.
TEST(ObjTexture, ObjFilesNamesTheLibrariesAndThenTheTexturesTheyName) {
  const std::string quad = test::read_file(kDir + "quad.obj");
  EXPECT_EQ(raster::obj_files(quad), (std::vector<std::string>{"quad.mtl"}));
  const raster::Uploads with_library{{"quad.mtl", test::read_file(kDir + "basic.mtl")}};
  EXPECT_EQ(raster::obj_files(quad, {}, with_library), (std::vector<std::string>{"quad.mtl", "checker.png"}));
  // Given MTL text is the materials; folders are dropped; a line of names gives itself whole and each name.
  EXPECT_EQ(raster::obj_files(quad, test::read_file(kDir + "relative-path.mtl")),
            (std::vector<std::string>{"quad.mtl", "checker.png"}));
  EXPECT_EQ(raster::obj_files("mtllib ../m/a.mtl b.mtl\nv 0 0 0\n"),
            (std::vector<std::string>{"a.mtl b.mtl", "a.mtl", "b.mtl"}));
  EXPECT_EQ(raster::obj_files("mtllib my materials.mtl\n"),
            (std::vector<std::string>{"my materials.mtl", "my", "materials.mtl"}));
  // Only a line whose first word is mtllib names libraries, and each such line once, wherever else the word
  // appears (in a comment, a name, a longer word, a last line without its end).
  EXPECT_EQ(raster::obj_files("# mtllib no.mtl\n\t mtllib mtllib.mtl\nusemtl mtllib\nmtllibs x.mtl\nv 0 0 0\n"
                              "mtllib  last.mtl"),
            (std::vector<std::string>{"mtllib.mtl", "last.mtl"}));
  EXPECT_EQ(raster::obj_files("mtllib"), (std::vector<std::string>{}));
  // A broken MTL is parse_obj's to report, not this function's.
  EXPECT_NO_THROW(raster::obj_files(quad, test::read_file(kDir + "bad-option.mtl")));
}

TEST(ObjTexture, CaseOnlyDifferencesInTheFileNameAreForgiven) {
  raster::Uploads upper{{"CHECKER.PNG", texture_png(false)}};
  const Mesh m =
      raster::parse_obj(test::read_file(kDir + "quad.obj"), test::read_file(kDir + "basic.mtl"), {}, upper);
  EXPECT_EQ(m.textures.size(), 1u);
}

TEST(ObjTexture, FacesWithoutTextureCoordinatesAreDrawnUntextured) {
  // The quad's upper-left half has no texture coordinates; its lower-right half samples the checker.
  const std::string obj =
      "mtllib a.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
      "usemtl skin\nf 1/1 2/2 3/3\nf 1 3 4\n";
  const Mesh m = raster::parse_obj(obj, test::read_file(kDir + "basic.mtl"), {}, images());
  ASSERT_EQ(m.face_textures.size(), 2u);
  EXPECT_EQ(m.face_textures[0], 0);
  EXPECT_EQ(m.face_textures[1], -1);
  const raster::Image image = render(m);
  EXPECT_EQ(test::pixel(image, 0, 0), test::kWhite) << "untextured: the material's Kd 1 1 1 alone";
  const raster::Rgba8 textured = test::pixel(image, 3, 3);
  const raster::Rgba8 cells[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}};
  EXPECT_TRUE(std::find(std::begin(cells), std::end(cells), textured) != std::end(cells))
      << "textured: a checker texel, got " << int{textured.r} << "," << int{textured.g} << ","
      << int{textured.b};
}

// Two textures that each fit the scene's texel limit but together do not: the limit is for all of them.
TEST(ObjTexture, TexturesShareTheScenesTexelLimit) {
  const std::string obj =
      "mtllib ab.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
      "vt 0 1\nusemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n";
  const std::string mtl = "newmtl a\nmap_Kd checker.png\nnewmtl b\nmap_Kd white.png\n";
  raster::Limits limits;
  limits.max_texture_pixels = 32;  // two 4x4 textures: 16 + 16
  EXPECT_EQ(raster::parse_obj(obj, mtl, limits, images()).textures.size(), 2u);
  limits.max_texture_pixels = 31;  // each alone fits
  try {
    raster::parse_obj(obj, mtl, limits, images());
    FAIL() << "expected a limit error for the second texture";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::limit);
    EXPECT_NE(std::string(e.what()).find("what is left of the scene's texture limit (15 pixels)"),
              std::string::npos)
        << e.what();
  }
}

TEST(ObjTexture, BadTextureCoordinatesAreModelErrorsWithTheirLine) {
  // Not a number, and one a float cannot hold (it would become infinite and fail far from its line).
  for (const char* vt : {"vt 0 nan", "vt 1e39 0"}) {
    try {
      raster::parse_obj(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + vt + "\nf 1/1 2/1 3/1\n");
      ADD_FAILURE() << "expected an error for " << vt;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::model) << vt;
      EXPECT_EQ(e.where().line, 4u) << vt;
    }
  }
  try {
    raster::parse_obj(test::read_file(kDir + "quad.obj"), "newmtl skin\nmap_Kd -s 1e39 1 checker.png\n", {},
                      images());
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::model);
    EXPECT_NE(std::string(e.what()).find("line 2: map_Kd option -s takes numbers within +-1e30"),
              std::string::npos)
        << e.what();
  }
}

// Found by docs/lighting.md's run over Debian's assimp-testmodels: empty_mat.obj says `usemtl ` with no
// MTL, for which tinyobjloader makes a black material; number_formats.obj writes "+1".
TEST(ObjTexture, AMaterialTheMtlDoesNotDefineKeepsTheDefaultGrey) {
  // Beside a material with a colour, faces under an empty `usemtl` or an undefined material get the grey.
  const Mesh m = raster::parse_obj(
      "mtllib r.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \nf 1 2 3\nusemtl nowhere\nf 1 3 2\nusemtl r\nf 2 3 "
      "1\n",
      "newmtl r\nKd 1 0 0\n");
  ASSERT_EQ(m.face_colors.size(), 3u);
  EXPECT_EQ(m.face_colors[0], (raster::Rgba8{204, 204, 204, 255}));
  EXPECT_EQ(m.face_colors[1], (raster::Rgba8{204, 204, 204, 255}));
  EXPECT_EQ(m.face_colors[2], (raster::Rgba8{255, 0, 0, 255}));
  // With no colour anywhere the mesh carries none: the scene's default grey applies.
  EXPECT_TRUE(raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \nf 1 2 3\nusemtl nowhere\nf 1 3 2\n")
                  .face_colors.empty());
  const Mesh red = raster::parse_obj("mtllib r.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl r\nf 1 2 3\n",
                                     "newmtl r\nKd 1 0 0\n");
  ASSERT_EQ(red.face_colors.size(), 1u);
  EXPECT_EQ(red.face_colors[0], (raster::Rgba8{255, 0, 0, 255}));
}

TEST(ObjTexture, NumbersWithAPlusSignAreRead) {
  const Mesh m = raster::parse_obj("v +1 +2. +3.0\nv -1e2 +2.e1 0\nv 0 1 +1e+2\nvt +0.5 +1\nf 1/1 2/1 3/1\n");
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[0], (raster::Vec3{1, 2, 3}));
  EXPECT_EQ(m.positions[1], (raster::Vec3{-100, 20, 0}));
  EXPECT_EQ(m.positions[2], (raster::Vec3{0, 1, 100}));
  for (const char* bad : {"v ++1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "v +-1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                          "v + 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"})
    EXPECT_THROW(raster::parse_obj(bad), SceneError) << bad;
}

}  // namespace
