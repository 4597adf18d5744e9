// The HTTP service through real HTTP on an ephemeral loopback port, with the routes main() serves.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "request.h"
#include "support.h"
#include "test_server.h"

namespace {

using test::TestServer;

const char* kScene = R"({"width": 64, "height": 32, "background": "#102030",
  "primitives": [{"type": "triangle", "points": [[2,2],[60,4],[10,30]], "colors": ["#f00","#0f0","#00f"]}]})";

nlohmann::json problem_of(const httplib::Result& r) {
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  auto j = nlohmann::json::parse(r->body);
  EXPECT_EQ(j["status"], r->status) << "problem status equals the HTTP status";
  EXPECT_TRUE(j.contains("type") && j.contains("title") && j.contains("detail"));
  return j;
}

TEST(Server, RendersAScene) {
  TestServer server;
  auto r = server.client().Post("/render", kScene, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(r->get_header_value("X-Render-Plan"),
            "rgb8 depth=none samples=1 flat=0 smooth=1 blend=0 culled=0 threads=1");
  EXPECT_FALSE(r->get_header_value("X-Request-Id").empty());
  const auto png = test::decode_png(r->body);
  // The same bytes as the library gives: the server adds nothing of its own to the picture.
  const auto scene = raster::parse_scene(kScene);
  const auto plan = raster::plan(scene);
  const auto expect = raster::encode_png(raster::render(scene, plan), plan.png);
  EXPECT_EQ(std::string(expect.begin(), expect.end()), r->body);
  EXPECT_EQ(png.width, 64);
  EXPECT_GT(png.pixels[(3 * 64 + 4) * 3], 200) << "red corner";
  EXPECT_LT(png.pixels[(3 * 64 + 4) * 3 + 1], 60);
}

TEST(Server, AnyContentTypeIsTakenAsJson) {
  TestServer server;
  for (const char* type : {"text/plain", "application/octet-stream", "application/x-www-form-urlencoded"}) {
    auto r = server.client().Post("/render", kScene, type);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << type;
  }
}

// `curl -d @scene.json` sends application/x-www-form-urlencoded, which cpp-httplib 0.11 would refuse over
// 8 KiB unless the route reads through a ContentReader.
TEST(Server, OneMebibyteFormEncodedBodyRenders) {
  TestServer server;
  std::string scene = R"({"width": 128, "height": 128, "primitives": [)";
  int n = 0;
  while (scene.size() < (1u << 20)) {
    if (n++) scene += ",";
    scene += R"({"type":"line","points":[[)" + std::to_string(n % 128) + ",0],[127," +
             std::to_string(n % 128) + "]],\"color\":\"#fff\"}";
  }
  scene += "]}";
  ASSERT_GE(scene.size(), 1u << 20);
  auto r = server.client().Post("/render", scene, "application/x-www-form-urlencoded");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body.substr(0, 300);
  EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
}

TEST(Server, InvalidSceneIsA400ProblemWithAPointer) {
  TestServer server;
  auto r = server.client().Post(
      "/render", R"({"width": 8, "height": 8, "primitives": [{"type": "line", "points": [[0,0],[1,"x"]]}]})",
      "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  const auto j = problem_of(r);
  EXPECT_EQ(j["pointer"], "/primitives/0/points/1/1");
  EXPECT_EQ(j["type"], "urn:rasterd:problem:invalid-scene");
}

TEST(Server, MalformedJsonIsA400WithAByteOffset) {
  TestServer server;
  auto r = server.client().Post("/render", R"({"width": 8, "height": )", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  const auto j = problem_of(r);
  EXPECT_GT(j["byte"].get<int>(), 0);
  EXPECT_FALSE(j.contains("pointer"));
  auto empty = server.client().Post("/render", "", "application/json");
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty->status, 400);
  problem_of(empty);
}

TEST(Server, OverTheSizeLimitIsA422) {
  TestServer server;
  auto r = server.client().Post("/render", R"({"width": 9000, "height": 8})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_EQ(problem_of(r)["pointer"], "/width");
}

TEST(Server, BodyOverTheCapIsA413) {
  rasterd::ServiceConfig config;
  config.max_body_bytes = 1000;
  TestServer server(config);
  auto r = server.client().Post("/render", std::string(1001, ' '), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  problem_of(r);
  auto ok = server.client().Post("/render", R"({"width": 1, "height": 1})" + std::string(900, ' '),
                                 "application/json");
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->status, 200);
}

TEST(Server, CompressedBodiesAreRefused) {
  TestServer server;
  httplib::Headers headers = {{"Content-Encoding", "gzip"}};
  auto r = server.client().Post("/render", headers, "not really gzip", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 415);
  problem_of(r);
}

TEST(Server, ExplainReturnsThePlan) {
  TestServer server;
  auto r = server.client().Post("/render?explain=1", kScene, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  const auto j = nlohmann::json::parse(r->body);
  EXPECT_EQ(j["format"], "rgb8");
  EXPECT_EQ(j["memory_bytes"]["color"], 64 * 32 * 3);
}

TEST(Server, HealthAndUnknownRoutes) {
  TestServer server;
  auto h = server.client().Get("/healthz");
  ASSERT_TRUE(h);
  EXPECT_EQ(h->status, 200);
  auto nf = server.client().Get("/nope");
  ASSERT_TRUE(nf);
  EXPECT_EQ(nf->status, 404);
  problem_of(nf);
}

}  // namespace

// --- 3D uploads: the three forms of issue 3, with the Stanford bunny -------------------------------------

std::string bunny() {
  return test::read_file(RASTERD_MODELS_DIR "/bunny.obj");
}

TEST(ServerObj, MultipartSceneAndModel) {
  TestServer server;
  httplib::MultipartFormDataItems items = {
      {"scene",
       R"({"width": 200, "height": 150, "background": "#102030", "primitives": [{"type": "obj", "source": "model", "color": "#e0a060"}]})",
       "scene.json", "application/json"},
      {"model", bunny(), "bunny.obj", "text/plain"},
  };
  auto r = server.client().Post("/render", items);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto png = test::decode_png(r->body);
  EXPECT_EQ(png.width, 200);
  EXPECT_EQ(png.height, 150);
  EXPECT_EQ(png.channels, 3);
  EXPECT_NE(r->get_header_value("X-Render-Plan").find("depth=f32"), std::string::npos);
}

TEST(ServerObj, MultipartModelAloneUsesTheDefaultScene) {
  TestServer server;
  httplib::MultipartFormDataItems items = {{"model", bunny(), "bunny.obj", "text/plain"}};
  auto r = server.client().Post("/render?width=64&height=48", items);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(test::decode_png(r->body).width, 64);
}

TEST(ServerObj, RawObjBodyWithQueryParameters) {
  TestServer server;
  auto r = server.client().Post("/render?width=320&height=240&background=%23ffffff&projection=orthographic",
                                bunny(), "application/octet-stream");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto png = test::decode_png(r->body);
  EXPECT_EQ(png.width, 320);
  EXPECT_EQ(png.height, 240);
  EXPECT_EQ(png.pixels[0], 255) << "white background from the query";
  auto bad = server.client().Post("/render?width=abc", bunny(), "application/octet-stream");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_NE(problem_of(bad)["detail"].get<std::string>().find("width"), std::string::npos);
}

TEST(ServerObj, InlineObjInAScene) {
  TestServer server;
  const nlohmann::json scene = {{"width", 96},
                                {"height", 96},
                                {"primitives", {{{"type", "obj"}, {"data", bunny()}, {"shading", "flat"}}}}};
  auto r = server.client().Post("/render", scene.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
}

TEST(ServerObj, CurlDashDFlattenedObjGetsAHint) {
  TestServer server;
  std::string flat = bunny();
  std::erase(flat, '\n');  // what `curl -d @bunny.obj` sends
  auto r = server.client().Post("/render", flat, "application/x-www-form-urlencoded");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(problem_of(r)["detail"].get<std::string>().find("--data-binary"), std::string::npos);
}

TEST(ServerObj, BadModelIsA422NamingTheLine) {
  TestServer server;
  auto r = server.client().Post("/render", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -7\n", "text/plain");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  const auto j = problem_of(r);
  EXPECT_EQ(j["line"], 4);
  EXPECT_EQ(j["type"], "urn:rasterd:problem:invalid-model");
  auto empty = server.client().Post("/render", "# just a comment\n", "text/plain");
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty->status, 422);
}

TEST(Server, AntialiasThroughHttp) {
  TestServer server;
  auto r = server.client().Post("/render", test::read_file(std::string(RASTERD_EXAMPLES_DIR) + "/aa-16.json"),
                                "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  EXPECT_NE(r->get_header_value("X-Render-Plan").find("samples=16"), std::string::npos)
      << r->get_header_value("X-Render-Plan");
  auto bad =
      server.client().Post("/render", R"({"width": 8, "height": 8, "antialias": 3})", "application/json");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(problem_of(bad)["pointer"], "/antialias");
}

// Issue 52: a request is sniffed once, by sniff_request (its byte order mark blanked first, as the readers
// take it) or by adopt_main_part for a part it places, and the sniff a caller hands on is the one used.
TEST(Request, IsSniffedOnceAndTheSniffIsHandedOn) {
  std::string body = "\xEF\xBB\xBFsolid x\nendsolid x\n";
  EXPECT_EQ(rasterd::sniff_request(body, {}).format, raster::ModelFormat::stl);  // an ASCII STL, once blanked
  EXPECT_EQ(body.substr(0, 3), "   ");
  std::string empty;
  EXPECT_EQ(rasterd::sniff_request(empty, {{"model", "ply\nformat ascii 1.0\n"}}).format,
            raster::ModelFormat::ply);  // the body is empty: the model part's bytes

  std::string adopted;
  raster::Uploads uploads{{"part.bin", R"({"asset": {"version": "2.0"}})"}};
  std::optional<rasterd::Sniffed> told;
  EXPECT_EQ(rasterd::adopt_main_part(adopted, uploads, {{"file", "part.bin"}}, nullptr, &told), "");
  ASSERT_TRUE(told);
  EXPECT_EQ(told->format, raster::ModelFormat::gltf);
  EXPECT_TRUE(adopted.empty() && uploads.contains("model"));  // JSON, but a glTF document: the model

  // An OBJ said to be an STL is read as one: the sniff handed on is not made again.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_NO_THROW(rasterd::scene_from_request(obj, {}, {}, {}));
  try {
    rasterd::scene_from_request(obj, {}, {}, {}, false, std::nullopt,
                                rasterd::Sniffed{raster::ModelFormat::stl});
    ADD_FAILURE() << "read as the OBJ it is";
  } catch (const raster::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("STL:"), std::string::npos) << e.what();
  }
}
