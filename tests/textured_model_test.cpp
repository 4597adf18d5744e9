// A textured OBJ as people bring it (the african_head case: model + MTL + diffuse PNG), end to end through
// each input the service has: multipart parts over HTTP, one JSON document with everything inline (base64),
// and the CLI's --part. All three must give the same picture, and it must show the texture.
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "model_files.h"
#include "support.h"
#include "test_server.h"

namespace {

// A file in the temporary folder that no other test process writes: the same test may run in two processes
// at once (make test beside make test-asan, a repeat loop), and a fixed name let one remove the other's PNG.
std::string own_temp(const std::string& name) {
  return testing::TempDir() + "rasterd-" + std::to_string(::getpid()) + "-" + name;
}

const std::string kDir = RASTERD_TESTS_DIR "/data/textured/";

struct Box {
  std::string obj = test::read_file(kDir + "box.obj");
  std::string mtl = test::read_file(kDir + "box.mtl");
  std::string png = test::read_file(kDir + "box_diffuse.png");
};

std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[n >> 18 & 63];
    out += kAlphabet[n >> 12 & 63];
    out += i + 1 < bytes.size() ? kAlphabet[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

// The box seen from +x+y+z shows its +x (red), +y (green) and +z (purple) faces, each checkered in two
// shades: a textured render has both shades of each; an untextured one is flat grey.
void expect_textured(const std::string& png_bytes) {
  const test::Decoded d = test::decode_png(png_bytes);
  ASSERT_EQ(d.width, 64);
  int reddish = 0, greenish = 0, purplish = 0;
  for (std::size_t i = 0; i + 2 < d.pixels.size(); i += d.channels) {
    const int r = d.pixels[i], g = d.pixels[i + 1], b = d.pixels[i + 2];
    reddish += r > 2 * g + 20 && r > 2 * b + 20;
    greenish += g > 2 * r + 20 && g > b + 20;
    purplish += r > g + 25 && b > g + 25;
  }
  EXPECT_GT(reddish, 100);
  EXPECT_GT(greenish, 100);
  EXPECT_GT(purplish, 100);
}

const char* kQuery = "/render?width=64&height=64&eye=3,2.5,4";

TEST(TexturedModel, MultipartPartsNamedByTheirFileNameRenderTheTexture) {
  test::TestServer server;
  const Box box;
  auto r = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "box_diffuse.png", "image/png"}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  expect_textured(r->body);

  // A folder in the file name (curl sends what -F names) is dropped, as the MTL's own folders are.
  auto folder = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "textures/box_diffuse.png", "image/png"}});
  ASSERT_TRUE(folder);
  EXPECT_EQ(folder->body, r->body);
}

// f3d#1973: a folder's files sent as they are, under any part name, as a browser's multi-file input does
// (curl -F files=@box.obj -F files=@box.mtl ...): the MTL is the one the model's `mtllib` names.
TEST(TexturedModel, AnMtlSentUnderItsFileNameIsTheOneMtllibNames) {
  test::TestServer server;
  const Box box;
  auto named = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "box_diffuse.png", "image/png"}});
  auto by_file = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"files", box.mtl, "box.mtl", "model/mtl"},
                                              {"files", box.png, "box_diffuse.png", "image/png"}});
  ASSERT_TRUE(named && by_file);
  ASSERT_EQ(by_file->status, 200) << by_file->body;
  expect_textured(by_file->body);
  EXPECT_EQ(by_file->body, named->body);
}

// rasterd 0.1's scenes name parts by their part name ("source", "mtl_source", a mesh texture's "source"),
// whatever file name curl sends with them; files are found by file name too. Both work in one request.
TEST(TexturedModel, ScenesStillNamePartsByTheirPartName) {
  test::TestServer server;
  const Box box;
  auto plain = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "box_diffuse.png", "image/png"}});
  const std::string scene =
      R"({"width": 64, "height": 64, )" + test::model_picture_fields() + R"(, "camera": {"eye": [3, 2.5, 4]},
          "primitives": [{"type": "obj", "source": "second", "mtl_source": "mymtl"}]})";
  auto named = server.client().Post(
      "/render", httplib::MultipartFormDataItems{{"scene", scene, "", "application/json"},
                                                 {"second", box.obj, "box.obj", "model/obj"},
                                                 {"mymtl", box.mtl, "box.mtl", "model/mtl"},
                                                 {"tex", box.png, "box_diffuse.png", "image/png"}});
  ASSERT_TRUE(plain && named);
  ASSERT_EQ(named->status, 200) << named->body;
  EXPECT_EQ(named->body, plain->body);

  // A mesh's texture by part name; the PNG's file name does not matter.
  const std::string quad =
      R"({"width": 8, "height": 8, "primitives": [{"type": "mesh", "shading": "unlit",
          "positions": [[-1,-1,0],[1,-1,0],[1,1,0],[-1,1,0]], "indices": [[0,1,2],[0,2,3]],
          "uvs": [[0,0],[1,0],[1,1],[0,1]], "texture": {"source": "tex"}}]})";
  auto mesh = server.client().Post(
      "/render", httplib::MultipartFormDataItems{{"scene", quad, "", "application/json"},
                                                 {"tex", box.png, "maps/anything.png", "image/png"}});
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->status, 200) << mesh->body;

  // A part name two parts share names neither: which one was meant is not knowable.
  auto shared = server.client().Post("/render",
                                     httplib::MultipartFormDataItems{{"scene", quad, "", "application/json"},
                                                                     {"tex", box.png, "a.png", "image/png"},
                                                                     {"tex", box.png, "b.png", "image/png"}});
  ASSERT_TRUE(shared);
  EXPECT_EQ(shared->status, 400) << shared->body;
  EXPECT_EQ(nlohmann::json::parse(shared->body).at("pointer"), "/primitives/0/texture/source")
      << shared->body;
}

TEST(TexturedModel, AMissingTextureIsA422NamingTheFileAndThePartsSent) {
  test::TestServer server;
  const Box box;
  auto r = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "other.png", "image/png"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  const auto problem = nlohmann::json::parse(r->body);
  const std::string detail = problem.at("detail");
  EXPECT_NE(detail.find("\"box_diffuse.png\""), std::string::npos) << detail;
  EXPECT_NE(detail.find("\"other.png\""), std::string::npos) << detail;
  EXPECT_NE(detail.find("line 3"), std::string::npos) << "the MTL line that asks for it: " << detail;
}

TEST(TexturedModel, TwoPartsUnderOneNameAreA400) {
  test::TestServer server;
  const Box box;
  auto r = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "box_diffuse.png", "image/png"},
                                              {"texture", box.png, "maps/box_diffuse.png", "image/png"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(nlohmann::json::parse(r->body).at("type"), "urn:rasterd:problem:duplicate-part") << r->body;
}

TEST(TexturedModel, HostileTextureHeaderIsA422BeforeDecoding) {
  test::TestServer server;
  const Box box;
  // A PNG signature and an IHDR claiming 100000 x 100000 (the CRC is not checked before the size is).
  std::string png = box.png.substr(0, 16);
  png += std::string("\x00\x01\x86\xa0\x00\x01\x86\xa0\x08\x02\x00\x00\x00", 13);
  auto r = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", png, "box_diffuse.png", "image/png"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422) << r->body;
  EXPECT_NE(r->body.find("100000"), std::string::npos) << r->body;
}

// One JSON document: the OBJ and MTL as strings, the texture as base64 under the name the MTL uses.
TEST(TexturedModel, InlineJsonGivesTheSamePictureAsMultipart) {
  test::TestServer server;
  const Box box;
  nlohmann::json scene = {{"width", 64},
                          {"height", 64},
                          {"camera", {{"eye", {3, 2.5, 4}}}},
                          {"primitives",
                           {{{"type", "obj"},
                             {"data", box.obj},
                             {"mtl", box.mtl},
                             {"textures", {{"box_diffuse.png", base64(box.png)}}}}}}};
  const std::string picture = test::model_picture_fields();  // the bare model's picture
  scene.update(nlohmann::json::parse("{" + picture + "}"));
  auto inline_r = server.client().Post("/render", scene.dump(), "application/json");
  auto multipart = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "box_diffuse.png", "image/png"}});
  ASSERT_TRUE(inline_r && multipart);
  ASSERT_EQ(inline_r->status, 200) << inline_r->body;
  expect_textured(inline_r->body);
  EXPECT_EQ(inline_r->body, multipart->body);

  nlohmann::json bad = scene;
  bad["primitives"][0]["textures"]["box_diffuse.png"] = "not base64!";
  auto r = server.client().Post("/render", bad.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400) << r->body;
  EXPECT_EQ(nlohmann::json::parse(r->body).at("pointer"), "/primitives/0/textures/box_diffuse.png")
      << r->body;
}

TEST(TexturedModel, CliPartsGiveTheSamePictureAsHttp) {
  test::TestServer server;
  const Box box;
  auto http = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "box_diffuse.png", "image/png"}});
  ASSERT_TRUE(http);
  const std::string out = own_temp("cli-box.png");
  const std::string command = std::string(RASTERD_BINARY) + " render " + kDir + "box.obj --part mtl=" + kDir +
                              "box.mtl --part texture=" + kDir +
                              "box_diffuse.png --width 64 --height 64 --eye 3,2.5,4 -o " + out;
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  EXPECT_EQ(test::read_file(out), http->body);
  std::remove(out.c_str());

  // A scene naming its parts by part name, as over HTTP.
  const std::string scene_file = own_temp("cli-box-scene.json");
  {
    std::FILE* f = std::fopen(scene_file.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs((R"({"width": 64, "height": 64, )" + test::model_picture_fields() +
                R"(, "camera": {"eye": [3, 2.5, 4]},
                  "primitives": [{"type": "obj", "source": "second", "mtl_source": "mymtl"}]})")
                   .c_str(),
               f);
    std::fclose(f);
  }
  const std::string named = std::string(RASTERD_BINARY) + " render " + scene_file + " --part second=" + kDir +
                            "box.obj --part mymtl=" + kDir + "box.mtl --part tex=" + kDir +
                            "box_diffuse.png -o " + out;
  ASSERT_EQ(std::system(named.c_str()), 0) << named;
  EXPECT_EQ(test::read_file(out), http->body);
  std::remove(out.c_str());
  std::remove(scene_file.c_str());
}

// The CLI given a model's path finds what it names beside it, as model viewers do: the same picture as the
// upload of all three files, with no --part; from a folder without the texture, an error naming it.
TEST(TexturedModel, CliFindsTheFilesTheModelNamesBesideIt) {
  test::TestServer server;
  const Box box;
  auto http = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"model", box.obj, "box.obj", "model/obj"},
                                              {"mtl", box.mtl, "box.mtl", "model/mtl"},
                                              {"texture", box.png, "box_diffuse.png", "image/png"}});
  ASSERT_TRUE(http);
  const std::string out = own_temp("cli-box-beside.png");
  const std::string args = " --width 64 --height 64 --eye 3,2.5,4 -o " + out + " 2>&1";
  ASSERT_EQ(std::system((std::string(RASTERD_BINARY) + " render " + kDir + "box.obj" + args).c_str()), 0);
  EXPECT_EQ(test::read_file(out), http->body);
  std::remove(out.c_str());

  // The model and its MTL alone in a folder: the texture the MTL names is missing, and said to be.
  const std::string folder = own_temp("cli-box-no-texture/");
  ASSERT_EQ(std::system(
                ("mkdir -p " + folder + " && cp " + kDir + "box.obj " + kDir + "box.mtl " + folder).c_str()),
            0);
  FILE* pipe = popen((std::string(RASTERD_BINARY) + " render " + folder + "box.obj" + args).c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string said;
  char buffer[512];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) said.append(buffer, n);
  EXPECT_NE(pclose(pipe), 0);
  EXPECT_NE(said.find("\"box_diffuse.png\""), std::string::npos) << said;
  std::system(("rm -rf " + folder).c_str());
}

}  // namespace
