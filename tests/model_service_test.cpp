// The model formats through the service (issue 32): raw bodies, multipart parts and scene references work
// for every format, told by the bytes, then the part's file name, then the Content-Type or ?format=; a body
// in no format is a 422 that names the formats.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model_files.h"
#include "support.h"
#include "test_server.h"

namespace {

const char* kQuery = "/render?width=64&height=64&view=iso";

std::string problem_detail(const httplib::Result& r) {
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  return nlohmann::json::parse(r->body).value("detail", "");
}

TEST(ModelService, EveryFormatAsARawBodyRendersTheSamePicture) {
  test::TestServer server;
  const test::TestMesh m = test::make_mesh(5);
  // STL is drawn flat, and so is a glTF without normals (glTF's rule); OBJ and PLY without normals are drawn
  // smooth: one picture for each group.
  // STL stands on +Z by default (the others on +Y): its rows ask for +Y so that all draw one mesh alike.
  struct Body {
    const char* name;
    std::string bytes;
    const char* type;
    bool flat;
    const char* up = "";
  };
  const Body bodies[] = {{"binary STL", test::write_stl_binary(m), "application/octet-stream", true, "&up=y"},
                         {"ASCII STL", test::write_stl_ascii(m), "text/plain", true, "&up=y"},
                         {"binary STL with no type", test::write_stl_binary(m), "", true, "&up=y"},
                         // A header that starts like a scene: the size tells a binary STL first.
                         {"binary STL, header \"{\"", test::write_stl_binary(m, "{ binary"),
                          "application/octet-stream", true, "&up=y"},
                         {"OBJ", test::write_obj(m), "model/obj", false},
                         {"PLY", test::write_ply_binary(m, false), "application/octet-stream", false},
                         {"GLB", test::write_glb(test::make_gltf(m, "", true)), "model/gltf-binary", true}};
  std::string flat, smooth;
  for (const Body& b : bodies) {
    SCOPED_TRACE(b.name);
    auto r = server.client().Post(std::string(kQuery) + b.up, b.bytes, b.type);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
    std::string& want = b.flat ? flat : smooth;
    if (want.empty()) want = r->body;
    EXPECT_EQ(r->body, want);
  }
  EXPECT_NE(flat, smooth);
}

// Issue 51: a 3MF (a slicer's ZIP package) as a raw body is a picture; a damaged one is a 422 that says what
// is wrong with the package.
TEST(ModelService, A3mfBodyRendersAndADamagedOneIsA422) {
  const std::string path = "/usr/share/assimp/models/3MF/box.3mf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "assimp-testmodels is not installed";
  test::TestServer server;
  const std::string bytes = test::read_file(path);
  auto r = server.client().Post(kQuery, bytes, "model/3mf");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
  auto damaged = server.client().Post(kQuery, bytes.substr(0, bytes.size() / 2), "application/octet-stream");
  ASSERT_TRUE(damaged);
  EXPECT_EQ(damaged->status, 422) << damaged->body;
  EXPECT_NE(problem_detail(damaged).find("3MF package"), std::string::npos) << damaged->body;
}

// Issue 42: each format stands on its own up axis (ModelFormatInfo::up): a post 1 unit long along Z and
// 0.25 wide, seen from the right, is upright from an STL (CAD's and 3D printing's +Z) and lies down from an
// OBJ (+Y); ?up= overrides the format's.
TEST(ModelService, EachFormatStandsOnItsUpAxis) {
  test::TestServer server;
  test::TestMesh post;  // a box: x and y in [0, 0.25], z in [0, 1]
  for (int k = 0; k < 8; ++k) post.v.push_back({0.25 * (k & 1), 0.25 * ((k >> 1) & 1), 1.0 * ((k >> 2) & 1)});
  post.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  // The box's extent in the picture: the rows and columns holding a pixel unlike the corner's (background).
  auto extent = [&](const std::string& png) {
    const test::Decoded image = test::decode_png(png);
    auto at = [&](int x, int y) { return image.pixels.data() + (y * image.width + x) * image.channels; };
    int left = image.width, right = -1, top = image.height, bottom = -1;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        if (std::memcmp(at(x, y), at(0, 0), static_cast<std::size_t>(image.channels)) != 0)
          left = std::min(left, x), right = std::max(right, x), top = std::min(top, y),
          bottom = std::max(bottom, y);
    return std::pair{right - left + 1, bottom - top + 1};  // width, height in pixels
  };
  auto draw = [&](const std::string& bytes, const char* type, const std::string& params) {
    auto r = server.client().Post("/render?width=96&height=96&view=right" + params, bytes, type);
    EXPECT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
    return r->body;
  };
  const std::string stl = test::write_stl_binary(post), obj = test::write_obj(post);
  const auto [stl_w, stl_h] = extent(draw(stl, "model/stl", ""));
  EXPECT_GT(stl_h, 2 * stl_w) << "an STL stands on +Z: the post is upright";
  const auto [obj_w, obj_h] = extent(draw(obj, "model/obj", ""));
  EXPECT_GT(obj_w, 2 * obj_h) << "an OBJ stands on +Y: the same post lies down";
  EXPECT_EQ(draw(stl, "model/stl", ""), draw(stl, "model/stl", "&up=%2Bz")) << "STL's default is +Z";
  EXPECT_EQ(draw(obj, "model/obj", ""), draw(obj, "model/obj", "&up=%2By")) << "OBJ's default is +Y";
  EXPECT_EQ(extent(draw(stl, "model/stl", "&up=y")), std::pair(obj_w, obj_h))
      << "?up= wins over the format's: the STL's post lies down as the OBJ's";
}

// Issue 42: a bare model takes ?antialias= with the scene field's values and words: the picture is the one
// the same model gets in a scene that says "antialias" (on the bare model's background), the default is
// raster::kModelPicture's level, and a bad value is a 400 naming the parameter.
TEST(ModelService, AntialiasIsAQueryParameterOfABareModel) {
  test::TestServer server;
  const std::string obj = test::write_obj(test::make_mesh(5));
  auto by_default = server.client().Post(kQuery, obj, "model/obj");
  ASSERT_TRUE(by_default);
  ASSERT_EQ(by_default->status, 200) << by_default->body;
  const test::Decoded picture = test::decode_png(by_default->body);
  const raster::Rgba8 background = raster::kModelPicture.background;
  EXPECT_EQ(picture.pixels[0], background.r) << "a bare model is drawn on kModelPicture's background";
  EXPECT_EQ(picture.pixels[picture.channels - 1], background.b);
  const std::string default_level = std::to_string(raster::sample_count(raster::kModelPicture.antialias));
  std::set<std::string> pictures;
  for (const char* level : {"1", "4", "16", "area"}) {
    SCOPED_TRACE(level);
    auto r = server.client().Post(std::string(kQuery) + "&antialias=" + level, obj, "model/obj");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    pictures.insert(r->body);
    EXPECT_EQ(r->body == by_default->body, level == default_level) << "the default is " << default_level;
    const std::string value = level == std::string("area") ? "\"area\"" : level;
    const std::string scene =
        R"({"width": 64, "height": 64, )" + test::model_picture_fields(false) + R"(, "antialias": )" + value +
        R"(, "camera": {"view": "iso", "fit": "vertices"}, "primitives": [{"type": "model", "source": "model"}]})";
    auto in_scene = server.client().Post(
        "/render", httplib::MultipartFormDataItems{{"scene", scene, "", ""}, {"model", obj, "m.obj", ""}});
    ASSERT_TRUE(in_scene);
    ASSERT_EQ(in_scene->status, 200) << in_scene->body;
    EXPECT_EQ(r->body, in_scene->body) << "the parameter is the scene field";
  }
  EXPECT_EQ(pictures.size(), 4u);
  auto bad = server.client().Post(std::string(kQuery) + "&antialias=3", obj, "model/obj");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  const std::string detail = problem_detail(bad);
  EXPECT_NE(
      detail.find(
          "query parameter \"antialias\": \"antialias\" is \"area\", \"auto\" or the samples per pixel"),
      std::string::npos)
      << detail;
}

// Issue 42: a bare point cloud takes ?point_size= (pixels, the scene field's range): larger points cover
// more of the picture; a size out of range is a 400 naming the parameter.
TEST(ModelService, PointSizeIsAQueryParameterOfABareModel) {
  test::TestServer server;
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  for (int i = 0; i < 9; ++i) ply += std::to_string(i % 3) + " " + std::to_string(i / 3) + " 0\n";
  auto covered = [&](const std::string& query) {
    auto r = server.client().Post("/render?width=64&height=64&antialias=1" + query, ply, "model/ply");
    EXPECT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
    const test::Decoded image = test::decode_png(r->body);
    int n = 0;
    for (int i = 0; i < image.width * image.height; ++i)
      n += std::memcmp(&image.pixels[i * image.channels], image.pixels.data(), image.channels) != 0;
    return n;
  };
  const int by_default = covered(""), large = covered("&point_size=8");
  EXPECT_GT(by_default, 0);
  EXPECT_GT(large, 4 * by_default) << "9 discs 8 px across against 2.5";
  auto bad = server.client().Post("/render?point_size=0", ply, "model/ply");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_NE(problem_detail(bad).find("query parameter \"point_size\""), std::string::npos)
      << problem_detail(bad);
}

// Issue 42: ?up= takes an axis by name, its '+' written as is (a URL's '+' arrives as a space) or as %2B,
// and the default view turns with it: the picture of the vector's.
TEST(ModelService, UpTakesAnAxisName) {
  test::TestServer server;
  const std::string obj = test::write_obj(test::make_mesh(5));
  auto post = [&](const std::string& up) {
    auto r = server.client().Post("/render?width=64&height=64&up=" + up, obj, "model/obj");
    EXPECT_TRUE(r);
    EXPECT_EQ(r->status, 200) << up << ": " << r->body;
    return r->body;
  };
  const std::string vector = post("0,0,1");
  EXPECT_EQ(post("+z"), vector);
  EXPECT_EQ(post("%2Bz"), vector);
  EXPECT_EQ(post("z"), vector);
  EXPECT_NE(post("-z"), vector);
  auto bad = server.client().Post("/render?up=+w", obj, "model/obj");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_NE(problem_detail(bad).find("\"+x\""), std::string::npos) << "names the axes";
}

// A glTF document is JSON, and model/gltf+json ends in "+json": it is still a model, not a scene.
TEST(ModelService, AGltfDocumentIsAModelWhateverItsJsonContentType) {
  test::TestServer server;
  const test::TestMesh m = test::make_mesh(5);
  const test::Gltf g = test::make_gltf(m, "data:application/octet-stream;base64,", false);
  const std::string doc =
      test::make_gltf(m, "data:application/octet-stream;base64," + test::base64(g.buffer), false).json;
  for (const char* type : {"model/gltf+json", "application/json", "text/plain"}) {
    SCOPED_TRACE(type);
    auto r = server.client().Post(kQuery, doc, type);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
  }
}

TEST(ModelService, MultipartPartsOfEveryFormatAreFoundByFileName) {
  test::TestServer server;
  const test::TestMesh m = test::make_mesh(5);
  const test::Gltf g = test::make_gltf(m, "torus.bin", true);
  // A .gltf and the buffer its URI names, sent as a folder's files are (no part named "model").
  auto gltf = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"files", g.json, "torus.gltf", "model/gltf+json"},
                                              {"files", g.buffer, "torus.bin", "application/octet-stream"}});
  ASSERT_TRUE(gltf);
  EXPECT_EQ(gltf->status, 200) << gltf->body;
  auto glb = server.client().Post(kQuery, test::write_glb(test::make_gltf(m, "", true)), "model/gltf-binary");
  ASSERT_TRUE(glb);
  EXPECT_EQ(gltf->body, glb->body);  // the same mesh, however its buffer travelled

  auto ply = server.client().Post(
      kQuery, httplib::MultipartFormDataItems{{"scan", test::write_ply_ascii(m), "scan.PLY", ""}});
  ASSERT_TRUE(ply);
  EXPECT_EQ(ply->status, 200) << ply->body;

  // A scene that names the part: "model" with or without a format, and the old "obj" type.
  const std::string scene =
      R"({"width": 64, "height": 64, )" + test::model_picture_fields() +
      R"(, "camera": {"view": "iso", "fit": "vertices"}, "primitives": [{"type": "model", "source": "part"}]})";
  auto referenced = server.client().Post(
      "/render", httplib::MultipartFormDataItems{{"scene", scene, "scene.json", "application/json"},
                                                 {"part", test::write_ply_ascii(m), "", ""}});
  ASSERT_TRUE(referenced);
  EXPECT_EQ(referenced->status, 200) << referenced->body;
  EXPECT_EQ(referenced->body, ply->body);
}

// Bytes that do not tell their format: the part's file name does, then the request's ?format=.
TEST(ModelService, TheFileNameThenTheFormatParameterNameWhatTheBytesDoNot) {
  test::TestServer server;
  const test::TestMesh m = test::make_mesh(5);
  std::string truncated = test::write_stl_binary(m);
  truncated.resize(truncated.size() - 7);  // no longer 84 + 50n bytes, so no format by its bytes
  auto unknown = server.client().Post(kQuery, truncated, "application/octet-stream");
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 422);
  const std::string words = problem_detail(unknown);
  for (const char* format : {"OBJ", "STL", "PLY", "glTF"})
    EXPECT_NE(words.find(format), std::string::npos) << words;

  auto by_name =
      server.client().Post(kQuery, httplib::MultipartFormDataItems{{"model", truncated, "part.stl", ""}});
  auto by_param =
      server.client().Post(std::string(kQuery) + "&format=stl", truncated, "application/octet-stream");
  auto by_type = server.client().Post(kQuery, truncated, "model/stl");
  for (const auto* r : {&by_name, &by_param, &by_type}) {
    ASSERT_TRUE(*r);
    EXPECT_EQ((*r)->status, 422);
    EXPECT_NE(problem_detail(*r).find("binary STL of"), std::string::npos) << (*r)->body;  // read as STL
  }
  auto bad =
      server.client().Post(std::string(kQuery) + "&format=step", truncated, "application/octet-stream");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_NE(problem_detail(bad).find("query parameter \"format\""), std::string::npos) << bad->body;
}

// A binary STL whose header starts like JSON and whose writer padded it (so its size tells nothing) is still
// the model the request names: by Content-Type, by a lone part's file name, by a scene's reference to
// "part.stl"; a GLB is a model even when the request calls it JSON.
TEST(ModelService, ANamedModelThatStartsLikeJsonIsStillTheModel) {
  test::TestServer server;
  const test::TestMesh m = test::make_mesh(5);
  const std::string exact = test::write_stl_binary(m, "{ binary");
  const std::string padded = exact + std::string(6, '\0');
  auto want = server.client().Post(kQuery, exact, "application/octet-stream");
  ASSERT_TRUE(want);
  ASSERT_EQ(want->status, 200) << want->body;
  const std::string scene =
      R"({"width": 64, "height": 64, )" + test::model_picture_fields() +
      R"(, "camera": {"view": "iso", "fit": "vertices", "up": "+z"}, "primitives": [{"type": "model", "source": "part.stl"}]})";
  auto by_type = server.client().Post(kQuery, padded, "model/stl");
  auto by_part =
      server.client().Post(kQuery, httplib::MultipartFormDataItems{{"file", padded, "part.stl", ""}});
  auto by_reference = server.client().Post(
      "/render", httplib::MultipartFormDataItems{{"scene", scene, "scene.json", "application/json"},
                                                 {"part.stl", padded, "part.stl", ""}});
  for (const auto* r : {&by_type, &by_part, &by_reference}) {
    ASSERT_TRUE(*r);
    EXPECT_EQ((*r)->status, 200) << (*r)->body;
    EXPECT_EQ((*r)->body, want->body);
  }
  // A scene beside a model part whose file name names glTF: the scene is the body, the GLB the model.
  const std::string glb = test::write_glb(test::make_gltf(m, "", true));
  auto scene_and_glb = server.client().Post(
      "/render",
      httplib::MultipartFormDataItems{{"scene",
                                       R"({"width": 64, "height": 64, )" + test::model_picture_fields() +
                                           R"(, "camera": {"view": "iso", "fit": "vertices"},
                                              "primitives": [{"type": "model", "source": "model"}]})",
                                       "scene.json", "application/json"},
                                      {"model", glb, "torus.glb", ""}});
  auto glb_alone = server.client().Post(kQuery, glb, "model/gltf-binary");
  ASSERT_TRUE(scene_and_glb);
  ASSERT_TRUE(glb_alone);
  EXPECT_EQ(scene_and_glb->status, 200) << scene_and_glb->body;
  EXPECT_EQ(scene_and_glb->body, glb_alone->body);
  auto glb_as_json =
      server.client().Post(kQuery, test::write_glb(test::make_gltf(m, "", true)), "application/json");
  ASSERT_TRUE(glb_as_json);
  EXPECT_EQ(glb_as_json->status, 200) << glb_as_json->body;
}

// Issue 32's corpus through the service: every OBJ, STL, PLY and glTF file of Debian's assimp-testmodels
// (real files from many exporters, broken ones among them), sent as a user would (the model as a part with
// its file name, the files it names beside it), renders or gets a 4xx with a problem body; never a 5xx.
// Deadlines are out of the question: 10 minutes, so a slow machine gives the same verdict.
TEST(ModelService, EveryCorpusModelRendersOrGetsA4xx) {
  const std::filesystem::path root = "/usr/share/assimp/models";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << "assimp-testmodels is not installed";
  rasterd::ServiceConfig config;
  config.render_deadline = config.body_deadline = std::chrono::minutes(10);
  test::TestServer server(config);
  int rendered = 0, refused = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const auto format = raster::format_of_file_name(entry.path().string());
    if (!entry.is_regular_file() || !format || entry.file_size() > (16 << 20)) continue;
    SCOPED_TRACE(entry.path().string());
    const std::string bytes = test::read_file(entry.path().string());
    httplib::MultipartFormDataItems items{{"model", bytes, entry.path().filename().string(), ""}};
    const bool gltf = *format == raster::ModelFormat::gltf || *format == raster::ModelFormat::glb;
    const bool obj = *format == raster::ModelFormat::obj;
    // The files it names, from its folder, as the CLI gathers them (OBJ: libraries, then their textures).
    raster::Uploads named;
    for (int round = 0; round < (obj ? 2 : 1); ++round)
      for (const std::string& name : gltf  ? raster::gltf_files(bytes)
                                     : obj ? raster::obj_files(bytes, {}, named)
                                           : std::vector<std::string>{}) {
        const std::filesystem::path file = entry.path().parent_path() / name;
        if (!named.contains(name) && std::filesystem::is_regular_file(file) &&
            std::filesystem::file_size(file) < (8 << 20))
          named[name] = test::read_file(file.string());
      }
    for (const auto& [name, file] : named) items.push_back({"files", file, name, ""});
    auto r = server.client().Post(kQuery, items);
    ASSERT_TRUE(r);
    if (r->status == 200) {
      ++rendered;
      EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
    } else {
      ++refused;
      EXPECT_GE(r->status, 400) << r->body;
      EXPECT_LT(r->status, 500) << r->body;
      EXPECT_FALSE(problem_detail(r).empty()) << r->body;
    }
  }
  EXPECT_GT(rendered, 60);
  EXPECT_GT(refused, 5);
}

}  // namespace
