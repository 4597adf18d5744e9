// Issue 28: the service as a newcomer finds it. Each test is one of the issue's points, through real HTTP
// (or the CLI) as a person would meet it.
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "connection_threads.h"
#include "etag.h"
#include "raster/raster.h"
#include "scene_url_support.h"
#include "service_support.h"
#include "support.h"
#include "test_server.h"

namespace {

using test::base64url;
using test::deflate;
using test::TestServer;

const std::string kScene =
    R"({"width": 16, "height": 8, "primitives": [{"type": "triangle", "points": [[0,0],[16,0],[0,8]]}]})";
const std::string kObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

nlohmann::json problem_of(const httplib::Result& r) {
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  return nlohmann::json::parse(r->body);
}

// Runs `command` through the shell; returns its exit status and what it printed (stdout and stderr).
std::pair<int, std::string> run(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// 1. A second server on a taken port fails to bind, in the library and as `rasterd serve`.
TEST(Newcomer, ASecondServerOnATakenPortFails) {
  TestServer first;
  httplib::Server server;
  rasterd::Service service({});
  service.install(server);
  EXPECT_FALSE(server.bind_to_port("127.0.0.1", first.port())) << "bound a port another server listens on";
  // The CLI says so and exits 1 (`timeout` only keeps a regression from serving forever).
  const auto [status, out] =
      run("timeout 20 " RASTERD_BINARY " serve --host 127.0.0.1 --port " + std::to_string(first.port()));
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("Address already in use"), std::string::npos) << out;
}

// Issue 31: the tag is of the parsed scene, so one scene written two ways has one tag, and a change of any
// field (tests/scene_key_test.cpp goes through every one) gives another.
TEST(Newcomer, OneSceneWrittenTwoWaysHasOneTag) {
  const raster::Scene a = raster::parse_scene(
      R"({"width": 8, "height": 8, "background": "#fff", "primitives": [{"type": "line", "points": [[0, 0], [1, 1]], "width": 2}]})");
  const raster::Scene b = raster::parse_scene(
      "{ \"primitives\":[{\"width\":2.0,\"points\":[[0.0,0],[1,1e0]],\"type\":\"line\"}],\n"
      "  \"background\":[1,1,1],\"height\":8,\"width\":8 }");
  EXPECT_EQ(rasterd::scene_etag(a), rasterd::scene_etag(b));
  raster::Scene c = a;
  c.camera.has_view = true;  // a one-byte flag: once a field that fitted into padding and was not hashed
  EXPECT_NE(rasterd::scene_etag(c), rasterd::scene_etag(a));
}

// 2. Every tag carries the render version, and `rasterd --version` names it.
TEST(Newcomer, TagsAndVersionNameTheRenderVersion) {
  const raster::Scene scene = raster::parse_scene(kScene);
  EXPECT_NE(rasterd::scene_etag(scene, raster::kRenderVersion),
            rasterd::scene_etag(scene, raster::kRenderVersion + 1));
  EXPECT_EQ(rasterd::scene_etag(scene), rasterd::scene_etag(scene, raster::kRenderVersion));
  const auto [status, out] = run(RASTERD_BINARY " --version");
  EXPECT_EQ(status, 0);
  EXPECT_NE(out.find("(render " + std::to_string(raster::kRenderVersion) + ")"), std::string::npos) << out;
}

// 3. A POST with neither Content-Length nor chunked framing has an empty body: a 400, not a wait for a 408.
TEST(Newcomer, APostWithoutABodyIsA400) {
  TestServer server;
  RawClient raw(server.port());
  ASSERT_TRUE(raw.connected());
  raw.send("POST /render HTTP/1.1\r\nHost: x\r\n\r\n");
  const std::string answer = raw.receive_all();
  EXPECT_EQ(status_of(answer), 400) << answer;
  EXPECT_NE(answer.find("the request is empty"), std::string::npos) << answer;
}

// 4. JSON is JSON by its Content-Type or its first byte ('{' or '['), after a byte order mark.
TEST(Newcomer, JsonIsReadAsJsonWhateverItHolds) {
  TestServer server;
  for (const auto& [body, type] :
       std::vector<std::pair<std::string, std::string>>{{"[1, 2]", "application/x-www-form-urlencoded"},
                                                        {"null", "application/json"},
                                                        {"42", "application/json; charset=utf-8"},
                                                        {"\"text\"", "application/vnd.rasterd.scene+json"}}) {
    auto r = server.client().Post("/render", body, type);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << body;
    EXPECT_NE(problem_of(r)["detail"].get<std::string>().find("a scene is a JSON object"), std::string::npos)
        << body << ": " << r->body;
  }
  auto plain = server.client().Post("/render", kScene, "text/plain");
  auto bom = server.client().Post("/render", "\xEF\xBB\xBF" + kScene, "text/plain");
  ASSERT_TRUE(plain && bom);
  EXPECT_EQ(bom->status, 200) << bom->body;
  EXPECT_EQ(bom->body, plain->body);
  // The byte order mark still counts in byte offsets.
  auto bad = server.client().Post("/render", "\xEF\xBB\xBF{\"width\": }", "text/plain");
  ASSERT_TRUE(bad);
  EXPECT_EQ(problem_of(bad)["byte"], 14) << bad->body;
}

// 5. A multipart upload whose lone part is not called "model" is the model (or the scene).
TEST(Newcomer, ALonePartIsTheBodyWhateverItsName) {
  TestServer server;
  auto model = server.client().Post("/render", kObj, "model/obj");
  auto file = server.client().Post("/render", httplib::MultipartFormDataItems{{"file", kObj, "tri.obj", ""}});
  auto scene =
      server.client().Post("/render", httplib::MultipartFormDataItems{{"upload", kScene, "s.json", ""}});
  auto posted = server.client().Post("/render", kScene, "application/json");
  ASSERT_TRUE(model && file && scene && posted);
  EXPECT_EQ(file->status, 200) << file->body;
  EXPECT_EQ(file->body, model->body);
  EXPECT_EQ(scene->body, posted->body);
  // Among several parts, the one .obj file; with none, the error names what was sent.
  auto with_texture = server.client().Post(
      "/render", httplib::MultipartFormDataItems{{"a", kObj, "tri.OBJ", ""}, {"b", "xyz", "notes.txt", ""}});
  ASSERT_TRUE(with_texture);
  EXPECT_EQ(with_texture->body, model->body);
  auto unnamed = server.client().Post(
      "/render", httplib::MultipartFormDataItems{{"a", "x", "a.txt", ""}, {"b", "y", "b.txt", ""}});
  ASSERT_TRUE(unnamed);
  EXPECT_EQ(unnamed->status, 400);
  const std::string detail = problem_of(unnamed)["detail"];
  EXPECT_NE(detail.find("\"a\" (a.txt), \"b\" (b.txt)"), std::string::npos) << detail;
  EXPECT_NE(detail.find("-F model=@"), std::string::npos) << detail;
}

// 6. Any OBJ sent with curl -d (line breaks stripped) gets the --data-binary hint, however short.
TEST(Newcomer, AFlattenedOneFaceObjGetsTheHint) {
  TestServer server;
  for (const char* body : {"v 0 0 0v 1 0 0v 0 1 0f 1 2 3", "v 0.5 0 0vn 0 0 1v 1 0 0v 0 1 0f 1 2 3"}) {
    auto r = server.client().Post("/render", body, "application/x-www-form-urlencoded");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << body;
    EXPECT_NE(problem_of(r)["detail"].get<std::string>().find("--data-binary"), std::string::npos) << r->body;
  }
}

// 7. Query parameters a scene cannot use are refused; explain takes the usual spellings of yes and no.
TEST(Newcomer, QueryParametersAreCheckedForScenesToo) {
  TestServer server;
  for (const char* query : {"?width=64", "?format=jpeg", "?foo=1", "?explain=maybe"}) {
    auto r = server.client().Post(std::string("/render") + query, kScene, "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << query;
    EXPECT_NE(problem_of(r)["detail"].get<std::string>().find("query parameter"), std::string::npos)
        << r->body;
  }
  for (const char* query :
       {"?explain", "?explain=", "?explain=1", "?explain=true", "?explain=Yes", "?explain=on"}) {
    auto r = server.client().Post(std::string("/render") + query, kScene, "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/json") << query;
  }
  for (const char* query : {"?explain=0", "?explain=false", "?explain=off"}) {
    auto r = server.client().Post(std::string("/render") + query, kScene, "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/png") << query;
  }
}

TEST(Newcomer, TheCliRefusesWhatItWouldIgnore) {
  const std::string dir = ::testing::TempDir();
  const std::string scene = dir + "/newcomer-scene.json", plan = dir + "/newcomer-plan.json";
  { std::ofstream(scene) << kScene; }
  auto [status, out] = run(RASTERD_BINARY " render " + scene + " --width 64 -o /dev/null");
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("\"width\""), std::string::npos) << out;
  std::tie(status, out) = run(RASTERD_BINARY " render " + scene + " --explain -o " + plan);
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(out, "") << "the plan goes to the file";
  EXPECT_EQ(nlohmann::json::parse(test::read_file(plan))["width"], 16);
  std::tie(status, out) = run(RASTERD_BINARY " render " + scene + " --background");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("--background needs a value"), std::string::npos) << out;
}

// Issue 42: --help on every subcommand prints its usage and exits 0, wherever it stands; a bad or unknown
// model flag is named as a flag (--antialias, --widht), not as a query parameter, and an unknown one is
// answered with render's flags.
TEST(Newcomer, EverySubcommandHelpsAndNamesItsFlags) {
  const std::pair<const char*, const char*> helps[] = {{" render --help", "rasterd render MODEL"},
                                                       {" render model.obj -h", "rasterd render MODEL"},
                                                       {" healthcheck --help", "rasterd healthcheck"},
                                                       {" serve --help", "rasterd serve [--flag value ...]"}};
  for (const auto& [line, says] : helps) {
    const auto [status, out] = run(RASTERD_BINARY + std::string(line));
    EXPECT_EQ(status, 0) << line << ": " << out;
    EXPECT_NE(out.find(says), std::string::npos) << line << ": " << out;
  }
  const std::string model = ::testing::TempDir() + "/newcomer-flags.obj";
  { std::ofstream(model) << kObj; }
  auto [status, out] = run(RASTERD_BINARY " render " + model + " --antialias 3 -o /dev/null");
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("--antialias: \"antialias\" is \"area\", \"auto\" or the samples per pixel"),
            std::string::npos)
      << out;
  EXPECT_EQ(out.find("query parameter"), std::string::npos) << out;
  std::tie(status, out) = run(RASTERD_BINARY " render " + model + " --widht 3 -o /dev/null");
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("--widht: not a flag of render"), std::string::npos) << out;
  EXPECT_NE(out.find("--antialias"), std::string::npos) << "the flags are listed: " << out;
  std::tie(status, out) = run(RASTERD_BINARY " render " + model + " --antialias area -o /dev/null");
  EXPECT_EQ(status, 0) << out;
}

// 8. A colour whose '#' the URL cut off: the error says how to send it, and hex without '#' works.
TEST(Newcomer, ABackgroundCutAtTheHashSaysHowToSendIt) {
  TestServer server;
  auto cut = server.client().Post("/render?background=", kObj, "model/obj");
  ASSERT_TRUE(cut);
  EXPECT_EQ(cut->status, 400);
  EXPECT_NE(problem_of(cut)["detail"].get<std::string>().find("%23"), std::string::npos) << cut->body;
  auto bare = server.client().Post("/render?background=ff8000", kObj, "model/obj");
  auto escaped = server.client().Post("/render?background=%23ff8000", kObj, "model/obj");
  ASSERT_TRUE(bare && escaped);
  EXPECT_EQ(bare->status, 200) << bare->body;
  EXPECT_EQ(bare->body, escaped->body);
}

// 9. One byte convention: the detail's byte is the problem's "byte" (counted from 1), in a scene and a model.
TEST(Newcomer, TheDetailAndTheProblemCountBytesAlike) {
  TestServer server;
  const std::pair<std::string, std::string> cases[] = {
      {"{\"width\": 4, \"height\": 4, \"background\": \"\xFF\"}", "application/json"},
      {"v 0 0 0\nv \xFF 0 0\n", "model/obj"},
  };
  for (const auto& [body, type] : cases) {
    auto r = server.client().Post("/render", body, type);
    ASSERT_TRUE(r);
    const auto p = problem_of(r);
    const std::size_t byte = p["byte"];
    EXPECT_EQ(static_cast<unsigned char>(body[byte - 1]), 0xFF) << r->body;
    EXPECT_NE(p["detail"].get<std::string>().find("byte " + std::to_string(byte) + " "), std::string::npos)
        << r->body;
  }
}

// 10. Hex is suggested only for components that look like 0..255 bytes.
TEST(Newcomer, HexIsSuggestedOnlyForByteComponents) {
  auto detail = [](const std::string& colour) {
    try {
      raster::parse_scene(R"({"width": 1, "height": 1, "background": )" + colour + "}");
    } catch (const raster::SceneError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(detail("[1, 1, 2]").find("did you mean"), std::string::npos) << detail("[1, 1, 2]");
  EXPECT_EQ(detail("[1, 0, 0, 255]").find("did you mean"), std::string::npos) << detail("[1, 0, 0, 255]");
  EXPECT_NE(detail("[255, 128, 0]").find("did you mean \"#ff8000\"?"), std::string::npos)
      << detail("[255, 128, 0]");
}

// 11. "$schema" and "$comment" at the top of a scene are what editors write; they draw nothing.
TEST(Newcomer, SchemaAndCommentKeysAreAccepted) {
  const raster::Scene plain = raster::parse_scene(kScene);
  const raster::Scene annotated = raster::parse_scene(
      R"({"$schema": "http://localhost:8080/schema/scene.json", "$comment": "a note",)" + kScene.substr(1));
  EXPECT_EQ(test::image_hash(raster::render(annotated)), test::image_hash(raster::render(plain)));
  EXPECT_EQ(rasterd::scene_etag(annotated), rasterd::scene_etag(plain));
  try {
    raster::parse_scene(R"({"$schema": 1,)" + kScene.substr(1));
    ADD_FAILURE() << "a number for $schema was accepted";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.where().pointer, "/$schema");
  }
}

// 12. ?scene= deflated as Kroki documents it (zlib-wrapped), raw, or gzip: the same picture.
TEST(Newcomer, ImageUrlsTakeEveryDeflateWrapping) {
  TestServer server;
  auto raw = server.client().Get("/render?scene=" + base64url(deflate(kScene, -15)));
  ASSERT_TRUE(raw);
  ASSERT_EQ(raw->status, 200) << raw->body;
  for (const int bits : {15, 31}) {
    auto r = server.client().Get("/render?scene=" + base64url(deflate(kScene, bits)));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << bits << ": " << r->body;
    EXPECT_EQ(r->body, raw->body) << bits;
  }
  // A broken zlib stream says how it was read.
  std::string broken = deflate(kScene, 15);
  broken.resize(broken.size() / 2);
  broken += "garbage!";
  auto r = server.client().Get("/render?scene=" + base64url(broken));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(problem_of(r)["detail"].get<std::string>().find("zlib"), std::string::npos) << r->body;
}

// 13. A key given twice is an error at the second one.
TEST(Newcomer, ARepeatedKeyIsA400AtItsPointer) {
  TestServer server;
  auto r = server.client().Post("/render", R"({"width": 8, "height": 8, "width": 16})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(problem_of(r)["pointer"], "/width");
}

// 14. CORS: any origin by default, with a preflight; a configured list echoes only its own origins.
TEST(Newcomer, PagesOnOtherOriginsMayReadAnswers) {
  TestServer server;
  const httplib::Headers origin{{"Origin", "https://pages.example"}};
  auto preflight = server.client().Options("/render", {{"Origin", "https://pages.example"},
                                                       {"Access-Control-Request-Method", "POST"},
                                                       {"Access-Control-Request-Headers", "content-type"}});
  ASSERT_TRUE(preflight);
  EXPECT_EQ(preflight->status, 204);
  EXPECT_EQ(preflight->get_header_value("Access-Control-Allow-Origin"), "*");
  EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Methods").find("POST"), std::string::npos);
  EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Headers").find("Content-Type"),
            std::string::npos);
  auto image = server.client().Post("/render", origin, kScene, "application/json");
  auto error = server.client().Post("/render", origin, "{", "application/json");
  ASSERT_TRUE(image && error);
  for (const auto* r : {&image, &error}) {
    EXPECT_EQ((*r)->get_header_value("Access-Control-Allow-Origin"), "*");
    EXPECT_NE((*r)->get_header_value("Access-Control-Expose-Headers").find("ETag"), std::string::npos);
  }

  rasterd::ServiceConfig config;
  config.cors_origins = {"https://pages.example"};
  TestServer listed(config);
  auto allowed = listed.client().Post("/render", origin, kScene, "application/json");
  auto other =
      listed.client().Post("/render", {{"Origin", "https://elsewhere.example"}}, kScene, "application/json");
  ASSERT_TRUE(allowed && other);
  EXPECT_EQ(allowed->get_header_value("Access-Control-Allow-Origin"), "https://pages.example");
  EXPECT_EQ(allowed->get_header_value("Vary"), "Origin");
  EXPECT_FALSE(other->has_header("Access-Control-Allow-Origin"));

  config.cors_origins = {};
  TestServer closed(config);
  auto none = closed.client().Post("/render", origin, kScene, "application/json");
  ASSERT_TRUE(none);
  EXPECT_FALSE(none->has_header("Access-Control-Allow-Origin"));
}

// 16. A client's plain request id is passed on; Range is ignored; a missing example says so; every
// route has its own metrics label.
TEST(Newcomer, SmallThingsAreRight) {
  TestServer server;
  auto kept = server.client().Get("/healthz", {{"X-Request-Id", "trace-42.a:b_c"}});
  auto replaced = server.client().Get("/healthz", {{"X-Request-Id", "two words"}});
  ASSERT_TRUE(kept && replaced);
  EXPECT_EQ(kept->get_header_value("X-Request-Id"), "trace-42.a:b_c");
  EXPECT_NE(replaced->get_header_value("X-Request-Id"), "two words");

  auto ranged = server.client().Get("/healthz", {{"Range", "bytes=0-9"}});
  ASSERT_TRUE(ranged);
  EXPECT_EQ(ranged->status, 200);
  EXPECT_EQ(ranged->body, "ok\n");
  EXPECT_FALSE(ranged->has_header("Content-Range"));
  auto head = server.client().Head("/healthz");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->get_header_value("Accept-Ranges"), "none");

  auto nope = server.client().Get("/examples/nope.json");
  ASSERT_TRUE(nope);
  EXPECT_EQ(nope->status, 404);
  EXPECT_EQ(problem_of(nope)["title"], "No such example");
  EXPECT_NE(problem_of(nope)["detail"].get<std::string>().find("gradient.json"), std::string::npos);

  ASSERT_TRUE(server.client().Get("/"));
  ASSERT_TRUE(server.client().Get("/examples"));
  // A request is counted by the logger, which runs after its answer is sent: wait for the count.
  std::string metrics;
  EXPECT_TRUE(eventually([&] {
    const auto m = server.client().Get("/metrics");
    metrics = m ? m->body : "";
    for (const char* label : {"route=\"/\",status=\"200\"", "route=\"/examples\",status=\"200\"",
                              "route=\"/examples/{name}\",status=\"404\""})
      if (metrics.find(label) == std::string::npos) return false;
    return true;
  })) << metrics;
}

// What people type next: a method no route has, a model sent as JSON, a query value the scene refuses.
TEST(Newcomer, MoreMistakesGetSpecificAnswers) {
  TestServer server;
  auto put = server.client().Put("/render", kScene, "application/json");
  ASSERT_TRUE(put);
  EXPECT_EQ(put->status, 405);
  EXPECT_EQ(put->get_header_value("Allow"), "GET, HEAD, POST, OPTIONS");
  EXPECT_EQ(problem_of(put)["type"], "urn:rasterd:problem:method-not-allowed");
  auto post_health = server.client().Post("/healthz", "x", "text/plain");
  ASSERT_TRUE(post_health);
  EXPECT_EQ(post_health->status, 405);
  EXPECT_EQ(post_health->get_header_value("Allow"), "GET, HEAD");
  auto nowhere = server.client().Put("/nowhere", "x", "text/plain");
  ASSERT_TRUE(nowhere);
  EXPECT_EQ(nowhere->status, 404) << "no route at all: not found, whatever the method";

  auto model_as_json = server.client().Post("/render", kObj, "application/json");
  ASSERT_TRUE(model_as_json);
  EXPECT_EQ(model_as_json->status, 400);
  EXPECT_NE(problem_of(model_as_json)["detail"].get<std::string>().find("looks like an OBJ model"),
            std::string::npos)
      << model_as_json->body;

  // A value the default scene refuses names its query parameter (the client sent no document of its own).
  for (const auto& [query, name] : std::vector<std::pair<std::string, std::string>>{
           {"?view=isometric", "view"}, {"?width=0", "width"}, {"?fov=500", "fov"}}) {
    auto r = server.client().Post("/render" + query, kObj, "model/obj");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << query;
    const auto p = problem_of(r);
    EXPECT_EQ(p["detail"].get<std::string>().rfind("query parameter \"" + name + "\": ", 0), 0u) << r->body;
    // The URL is at fault, not a document: invalid-query naming the parameter (issue 39), no pointer.
    EXPECT_EQ(p["type"], "urn:rasterd:problem:invalid-query") << r->body;
    EXPECT_EQ(p["parameter"], name) << r->body;
    EXPECT_FALSE(p.contains("pointer")) << r->body;
  }
  auto zero = server.client().Post("/render?width=0", kObj, "model/obj");
  EXPECT_TRUE(problem_of(zero)["detail"].get<std::string>().ends_with("got 0"))
      << "quoted as sent: " << zero->body;
}

// 17. A burst of requests waits for the workers instead of being refused; refusals come from the wait
// and the memory a queue would take, with how long to wait.
TEST(Newcomer, ABurstQueuesInsteadOfBeingRefused) {
  Gate gate;
  rasterd::ServiceConfig config;
  config.workers = 1;
  config.render_threads = 1;
  config.max_queue_wait = std::chrono::minutes(10);  // the gate, not the clock, decides here
  config.after_admission = [&gate] { gate.wait(); };
  TestServer server(config);
  std::vector<std::future<httplib::Result>> burst;
  for (int i = 0; i < 16; ++i)
    burst.push_back(std::async(std::launch::async,
                               [&] { return server.client().Post("/render", kScene, "application/json"); }));
  ASSERT_TRUE(eventually([&] {
    const auto m = server.client().Get("/metrics");
    return m && metric(m->body, "rasterd_render_queue_length") == 15;
  }));
  gate.open();
  for (auto& r : burst) {
    const auto result = r.get();
    ASSERT_TRUE(result);
    EXPECT_EQ(result->status, 200) << result->body;
  }
}

TEST(Newcomer, TheQueueRefusesPastItsMemoryAndItsWait) {
  Gate gate;
  rasterd::ServiceConfig config;
  config.workers = 1;
  config.render_threads = 1;
  config.max_queued_bytes = kScene.size() + 10;  // one waiting scene fits, a second does not
  config.max_queue_wait = std::chrono::minutes(10);
  config.after_admission = [&gate] { gate.wait(); };
  TestServer server(config);
  auto post = [&] {
    return std::async(std::launch::async,
                      [&] { return server.client().Post("/render", kScene, "application/json"); });
  };
  auto running = post();
  auto waiting = post();
  ASSERT_TRUE(eventually([&] {
    const auto m = server.client().Get("/metrics");
    return m && metric(m->body, "rasterd_render_queue_length") == 1;
  }));
  auto refused = server.client().Post("/render", kScene, "application/json");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 503);
  EXPECT_FALSE(refused->get_header_value("Retry-After").empty());
  gate.open();
  EXPECT_EQ(running.get()->status, 200);
  EXPECT_EQ(waiting.get()->status, 200);
  auto metrics = server.client().Get("/metrics");
  EXPECT_NE(metrics->body.find("rasterd_rejected_total{reason=\"queue_memory\"} 1"), std::string::npos)
      << metrics->body;

  // A render that cannot get a worker within the wait limit gives up with a 503 (the limit is 0 here).
  Gate held;
  config.max_queued_bytes = 1 << 20;
  config.max_queue_wait = std::chrono::milliseconds(0);
  config.after_admission = [&held] { held.wait(); };
  TestServer strict(config);
  auto first = std::async(std::launch::async,
                          [&] { return strict.client().Post("/render", kScene, "application/json"); });
  ASSERT_TRUE(eventually([&] {
    const auto m = strict.client().Get("/metrics");
    return m && metric(m->body, "rasterd_renders_in_flight") == 1;
  }));
  auto late = strict.client().Post("/render", kScene, "application/json");
  ASSERT_TRUE(late);
  EXPECT_EQ(late->status, 503);
  EXPECT_EQ(late->get_header_value("Retry-After"), "1");
  held.open();
  EXPECT_EQ(first.get()->status, 200);
}

}  // namespace

namespace {

// The connection threads behind every test above: made on demand, the last idle one reused, bounded.
// Jobs are held on gates, so no verdict depends on the machine's pace.
TEST(ConnectionThreads, MadeOnDemandReusedLastIdleFirstAndBounded) {
  rasterd::ConnectionThreads pool(2);
  EXPECT_EQ(pool.thread_count(), 0u) << "no thread before the first connection";
  std::mutex mutex;
  std::vector<std::thread::id> ran;
  auto record = [&] {
    std::lock_guard lock(mutex);
    ran.push_back(std::this_thread::get_id());
  };
  pool.enqueue(record);
  ASSERT_TRUE(eventually([&] { return pool.idle_count() == 1; }));
  pool.enqueue(record);
  ASSERT_TRUE(eventually([&] { return pool.idle_count() == 1; }));
  EXPECT_EQ(pool.thread_count(), 1u) << "one connection at a time needs one thread";
  ASSERT_EQ(ran.size(), 2u);
  EXPECT_EQ(ran[0], ran[1]);

  // Two held at once make the second thread; a third waits for whichever finishes first.
  Gate first, second;
  std::atomic<int> third_ran{0};
  pool.enqueue([&] { first.wait(), record(); });
  pool.enqueue([&] { second.wait(), record(); });
  pool.enqueue([&] { ++third_ran; });
  EXPECT_EQ(pool.thread_count(), 2u) << "bounded at 2";
  EXPECT_EQ(third_ran.load(), 0);
  first.open();
  ASSERT_TRUE(eventually([&] { return third_ran.load() == 1 && pool.idle_count() == 1; }));
  second.open();
  ASSERT_TRUE(eventually([&] { return pool.idle_count() == 2; }));
  // The thread that finished last takes the next connection.
  const std::thread::id last = ran.back();
  pool.enqueue(record);
  ASSERT_TRUE(eventually([&] { return pool.idle_count() == 2 && ran.size() == 5; }));
  EXPECT_EQ(ran.back(), last);

  // Shutdown runs what is queued before the threads end.
  Gate hold_a, hold_b;
  std::atomic<int> queued_ran{0};
  pool.enqueue([&] { hold_a.wait(); });
  pool.enqueue([&] { hold_b.wait(); });
  pool.enqueue([&] { ++queued_ran; });
  std::thread stopper([&] { pool.shutdown(); });
  hold_a.open(), hold_b.open();
  stopper.join();
  EXPECT_EQ(queued_ran.load(), 1);
}

}  // namespace
