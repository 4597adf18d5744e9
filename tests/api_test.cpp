// Issue 16, parts 1 and 3, over real HTTP: the API documents, image URLs (GET /render?scene=), ETags,
// conditional requests and Cache-Control.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "etag.h"
#include "scene_url.h"
#include "scene_url_support.h"
#include "support.h"
#include "test_server.h"

namespace {

using test::base64url;
using test::deflate;
using test::TestServer;

std::string url_of(const std::string& scene, bool deflated = true) {
  return "/render?scene=" + base64url(deflated ? deflate(scene) : scene);
}

// The value of the sample line `name value` in a Prometheus text body, -1 when absent.
long metric(const std::string& metrics, const std::string& name) {
  const std::string needle = "\n" + name + " ";
  const auto at = metrics.find(needle);
  return at == std::string::npos ? -1 : std::stol(metrics.substr(at + needle.size()));
}

long renders(const TestServer& server) {
  auto m = server.client().Get("/metrics");
  return m ? metric(m->body, "rasterd_render_duration_seconds_count") : -2;
}

nlohmann::json problem_of(const httplib::Result& r) {
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  auto j = nlohmann::json::parse(r->body);
  EXPECT_EQ(j["status"], r->status);
  return j;
}

const std::string kScene =
    R"({"width": 24, "height": 16, "background": "#102030", "primitives": [{"type": "triangle",)"
    R"( "points": [[1,1],[22,3],[5,15]], "colors": ["#f00", "#0f0", "#00f"]}]})";

TEST(Api, SchemaAndOpenApiAreTheRepositoryFiles) {
  TestServer server;
  const std::pair<const char*, const char*> documents[] = {
      {"/schema/scene.json", RASTERD_SCHEMA_DIR "/scene.schema.json"},
      {"/openapi.json", RASTERD_SCHEMA_DIR "/openapi.json"},
  };
  for (const auto& [route, file] : documents) {
    auto r = server.client().Get(route);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << route;
    EXPECT_EQ(r->get_header_value("Content-Type"),
              std::string(route) == "/openapi.json" ? "application/json" : "application/schema+json");
    EXPECT_EQ(r->body, test::read_file(file)) << route << " is not the repository's " << file;
  }
  // The OpenAPI document names the scene schema where it is served.
  const auto openapi = nlohmann::json::parse(test::read_file(RASTERD_SCHEMA_DIR "/openapi.json"));
  EXPECT_EQ(openapi["components"]["schemas"]["Scene"]["$ref"], "/schema/scene.json");
  EXPECT_EQ(openapi["info"]["version"], RASTERD_VERSION)
      << "bump server/schema/openapi.json with the project";
}

// Every example: the GET URL, deflated or plain, answers exactly what the POST answers.
TEST(ImageUrl, GetEqualsPostForEveryExample) {
  TestServer server;
  int rendered = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RASTERD_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    const std::string scene = test::read_file(entry.path().string());
    const std::string name = entry.path().filename().string();
    auto post = server.client().Post("/render", scene, "application/json");
    ASSERT_TRUE(post) << name;
    for (const bool deflated : {true, false}) {
      auto get = server.client().Get(url_of(scene, deflated));
      ASSERT_TRUE(get) << name;
      EXPECT_EQ(get->status, post->status) << name << (deflated ? " deflated" : " plain");
      EXPECT_EQ(get->body, post->body) << name << (deflated ? " deflated" : " plain");
      EXPECT_EQ(get->get_header_value("ETag"), post->get_header_value("ETag")) << name;
      EXPECT_EQ(get->get_header_value("X-Render-Plan"), post->get_header_value("X-Render-Plan")) << name;
    }
    rendered += post->status == 200;
  }
  EXPECT_GE(rendered, 8) << "model-scene.json needs an upload; every other example renders";
}

TEST(ImageUrl, ObjModelsAndExplainWorkAsForPost) {
  TestServer server;
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  auto post = server.client().Post("/render?width=40&height=30&background=%23336699", obj, "model/obj");
  auto get = server.client().Get(url_of(obj) + "&width=40&height=30&background=%23336699");
  ASSERT_TRUE(post);
  ASSERT_TRUE(get);
  ASSERT_EQ(post->status, 200) << post->body;
  EXPECT_EQ(get->status, 200);
  EXPECT_EQ(get->body, post->body);
  EXPECT_EQ(test::decode_png(get->body).width, 40);

  auto explain = server.client().Get(url_of(kScene) + "&explain=1");
  ASSERT_TRUE(explain);
  EXPECT_EQ(explain->status, 200);
  EXPECT_EQ(explain->get_header_value("Content-Type"), "application/json");
  EXPECT_EQ(nlohmann::json::parse(explain->body)["width"], 24);
}

TEST(ImageUrl, UndecodableScenesAre400s) {
  TestServer server;
  const std::string deflated = deflate(kScene);
  const std::pair<std::string, std::string> cases[] = {
      {"/render", "missing-scene"},
      {"/render?scene=", "invalid-scene-url"},
      {"/render?scene=%25%25%25%25", "invalid-scene-url"},  // '%': not base64url
      {"/render?scene=ab+c", "invalid-scene-url"},          // '+' is a space once decoded
      {"/render?scene=abcde", "invalid-scene-url"},         // a length no base64 text has
      {"/render?scene=AAAA", "invalid-scene-url"},          // zeros: not a deflate stream
      {"/render?scene=" + base64url(deflated.substr(0, deflated.size() / 2)), "invalid-scene-url"},  // cut
      {"/render?scene=" + base64url(deflated + "xyz"), "invalid-scene-url"},  // bytes after the stream
      {"/render?scene=" + base64url("{\"width\": 4,"), "malformed-scene"},    // plain JSON, broken
      {"/render?scene=" + base64url(deflate(R"({"width": 4, "height": 4, "colour": 1})")), "invalid-scene"},
  };
  for (const auto& [url, type] : cases) {
    auto r = server.client().Get(url);
    ASSERT_TRUE(r) << url;
    EXPECT_EQ(r->status, 400) << url << "\n" << r->body;
    EXPECT_EQ(problem_of(r)["type"], "urn:rasterd:problem:" + type) << url;
    EXPECT_FALSE(r->has_header("ETag")) << url;
    EXPECT_FALSE(r->has_header("Cache-Control")) << url << ": an error must not be cached";
  }
  // Padding is optional, and the plain form works too.
  for (const std::string& url : {"/render?scene=" + base64url(deflated, true), url_of(kScene, false)}) {
    auto r = server.client().Get(url);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << url;
  }
}

// A few kilobytes of URL that would inflate to a thousand times more: refused while inflating, at the body
// limit, with the body limit's 413. Plain JSON over the limit too.
TEST(ImageUrl, InflateBombIsA413) {
  rasterd::ServiceConfig config;
  config.max_body_bytes = 4096;
  TestServer server(config);
  std::string bomb(4 << 20, ' ');  // 4 MiB of one byte: ~4 KiB deflated
  bomb[0] = '{';                   // (not "{" + std::string: GCC 12 warns falsely with -Wrestrict)
  const std::string url = url_of(bomb);
  ASSERT_LT(url.size(), 8000u);
  const std::string plain = R"({"width": 4, "height": 4, "background": ")" + std::string(5000, 'x') + "\"}";
  for (const std::string& u : {url, url_of(plain, false)}) {
    auto r = server.client().Get(u);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 413);
    EXPECT_EQ(problem_of(r)["type"], "urn:rasterd:problem:body-too-large");
  }
  // The decoder's own cap, directly: the output never grows past it.
  try {
    rasterd::decode_scene_param(base64url(deflate(std::string(1000, 'a'))), 999);
    ADD_FAILURE() << "1000 bytes passed a 999-byte cap";
  } catch (const rasterd::SceneUrlError& e) {
    EXPECT_EQ(e.status(), 413);
  }
  EXPECT_EQ(rasterd::decode_scene_param(base64url(deflate(std::string(1000, 'a'))), 1000).size(), 1000u);
}

// cpp-httplib itself answers a request line over 8192 bytes, before any route: the service's error
// handler still makes it a problem that says what to do instead, with a request id.
TEST(ImageUrl, TooLongUrlIsA414ProblemThatSaysToPost) {
  TestServer server;
  const std::string url = "/render?scene=" + std::string(9000, 'A');
  auto r = server.client().Get(url);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 414);
  const auto p = problem_of(r);
  EXPECT_EQ(p["type"], "urn:rasterd:problem:uri-too-long");
  EXPECT_NE(p["detail"].get<std::string>().find("POST"), std::string::npos) << p.dump();
  EXPECT_FALSE(r->get_header_value("X-Request-Id").empty());
  // Just under the limit is still a request the routes see (here: a bad scene, so a 400).
  auto under = server.client().Get("/render?scene=" + std::string(8000, 'A'));
  ASSERT_TRUE(under);
  EXPECT_EQ(under->status, 400);
}

TEST(ImageUrl, EtagNamesTheSceneNotItsSpelling) {
  TestServer server;
  auto tag_of = [&](const std::string& scene) {
    auto r = server.client().Post("/render", scene, "application/json");
    EXPECT_TRUE(r && r->status == 200) << scene << (r ? r->body : "");
    return r ? std::pair{r->get_header_value("ETag"), r->body} : std::pair<std::string, std::string>{};
  };
  // One scene, spelt five ways: layout, key order, 1 vs 1.0, colour notation, flat vs nested mesh arrays.
  const std::string a =
      R"({"width":32,"height":32,"background":"#fff","primitives":[{"type":"line","points":[[1,1],[30,20]],"color":"#ff0000"},)"
      R"({"type":"mesh","positions":[[0,0,0],[1,0,0],[0,1,0]],"indices":[[0,1,2]],"color":"#808080"}]})";
  const std::string same[] = {
      R"({ "primitives": [ { "color": [1, 0, 0], "points": [[1.0, 1], [30, 20.0]], "type": "line" },
           { "indices": [0, 1, 2], "type": "mesh", "positions": [0,0,0, 1,0,0, 0,1,0], "color": "#808080ff" } ],
         "height": 32.0, "background": [1, 1, 1, 1], "width": 32 })",
      R"({"width": 32, "height": 32, "background": "#FFFFFF", "primitives": [{"type": "line", "points": [[1,1],[30,20]], "color": "#f00"},)"
      R"( {"type": "mesh", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]], "color": "#808080", "shading": "smooth"}]})",
  };
  const std::string different[] = {
      R"({"width":32,"height":32,"background":"#fff","primitives":[{"type":"line","points":[[1,1],[30,21]],"color":"#ff0000"},)"
      R"({"type":"mesh","positions":[[0,0,0],[1,0,0],[0,1,0]],"indices":[[0,1,2]],"color":"#808080"}]})",
      R"({"width":32,"height":32,"background":"#fff","antialias":4,"primitives":[{"type":"line","points":[[1,1],[30,20]],"color":"#ff0000"},)"
      R"({"type":"mesh","positions":[[0,0,0],[1,0,0],[0,1,0]],"indices":[[0,1,2]],"color":"#808080"}]})",
      R"({"width":32,"height":32,"background":"#fff","primitives":[{"type":"mesh","positions":[[0,0,0],[1,0,0],[0,1,0]],"indices":[[0,1,2]],"color":"#808080"},)"
      R"({"type":"line","points":[[1,1],[30,20]],"color":"#ff0000"}]})",  // the same two, other order
  };
  const auto [tag, png] = tag_of(a);
  // 32 hex digits of the scene's hash, then the PNG's length (so a 304 can declare it), in quotes.
  ASSERT_EQ(tag.size(), 35u + std::to_string(png.size()).size()) << tag;
  EXPECT_EQ(tag.front(), '"');
  for (const std::string& s : same) {
    const auto [t, p] = tag_of(s);
    EXPECT_EQ(t, tag) << s;
    EXPECT_EQ(p, png) << "one tag, one picture";
  }
  for (const std::string& s : different) EXPECT_NE(tag_of(s).first, tag) << s;

  // An OBJ inline or uploaded is one scene too.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string inline_obj = R"({"width": 16, "height": 16, "primitives": [{"type": "obj", "data": )" +
                                 nlohmann::json(obj).dump() + "}]}";
  const std::string uploaded =
      R"({"width": 16, "height": 16, "primitives": [{"type": "obj", "source": "model"}]})";
  auto inline_r = server.client().Post("/render", inline_obj, "application/json");
  auto upload_r = server.client().Post(
      "/render", httplib::MultipartFormDataItems{{"scene", uploaded, "scene.json", "application/json"},
                                                 {"model", obj, "m.obj", "model/obj"}});
  ASSERT_TRUE(inline_r && upload_r);
  ASSERT_EQ(upload_r->status, 200) << upload_r->body;
  EXPECT_EQ(inline_r->get_header_value("ETag"), upload_r->get_header_value("ETag"));
  EXPECT_EQ(inline_r->body, upload_r->body);
}

// Sends `request` on a new connection and returns every byte answered until the server closes it.
std::string exchange(int port, const std::string& request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  timeval tv{20, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  std::string out;
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
      ::send(fd, request.data(), request.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(request.size())) {
    char buf[4096];
    for (ssize_t n; (n = ::recv(fd, buf, sizeof buf, 0)) > 0;) out.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return out;
}

// A matching If-None-Match is answered from the scene's tag alone: the render count in /metrics (taken
// before each response is sent) does not move. The 304 declares the length of the 200 it confirms, which
// the tag carries (RFC 9110 8.6), and no body byte follows its headers: read off the wire, as cpp-httplib's
// client reads a 304 as if a body of that length followed.
TEST(ImageUrl, IfNoneMatchGetsA304WithoutRendering) {
  TestServer server;
  const std::string url = url_of(kScene);
  auto first = server.client().Get(url);
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 200);
  const std::string tag = first->get_header_value("ETag");
  ASSERT_EQ(renders(server), 1);
  ASSERT_EQ(tag.substr(tag.size() - 2 - std::to_string(first->body.size()).size()),
            "-" + std::to_string(first->body.size()) + "\"")
      << "the tag ends in the PNG's length: " << tag;

  auto raw_304 = [&](const std::string& field) {
    return exchange(server.port(),
                    "GET " + url + " HTTP/1.1\r\nHost: x\r\nIf-None-Match: " + field + "\r\n\r\n");
  };
  for (const std::string& field : {tag, "W/" + tag, "\"0123\", " + tag, std::string("*")}) {
    const std::string answer = raw_304(field);
    const std::size_t head_end = answer.find("\r\n\r\n");
    ASSERT_NE(head_end, std::string::npos) << answer;
    EXPECT_TRUE(answer.starts_with("HTTP/1.1 304 ")) << field << "\n" << answer;
    EXPECT_EQ(answer.size(), head_end + 4) << "no body byte after a 304's headers: " << answer;
    const std::string head = answer.substr(0, head_end + 2);
    EXPECT_NE(head.find("\r\nETag: " + tag + "\r\n"), std::string::npos)
        << "it names what it confirms: " << head;
    EXPECT_NE(head.find("\r\nContent-Length: " + std::to_string(first->body.size()) + "\r\n"),
              std::string::npos)
        << "the 200's length, never 0: " << head;
    EXPECT_EQ(head.find("Transfer-Encoding"), std::string::npos) << head;
    EXPECT_NE(head.find("\r\nCache-Control: " + first->get_header_value("Cache-Control") + "\r\n"),
              std::string::npos)
        << head;
  }
  // "*" names no length: that one 304 had to render to learn it; the tags that carry it rendered nothing.
  EXPECT_EQ(renders(server), 2) << "only the \"*\" 304 rendered";
  // The scene's own tag without a length (what rasterd 0.2 sent) still hits, as "*" does.
  const std::string old_tag = tag.substr(0, tag.rfind('-')) + "\"";
  EXPECT_TRUE(raw_304(old_tag).starts_with("HTTP/1.1 304 "));
  EXPECT_EQ(renders(server), 3);

  auto stale = server.client().Get(url, {{"If-None-Match", "\"0123\""}});
  ASSERT_TRUE(stale);
  EXPECT_EQ(stale->status, 200);
  EXPECT_EQ(stale->body, first->body);
  EXPECT_EQ(renders(server), 4);

  // A POST is not performed when its precondition fails (RFC 9110 13.1.2): 412, and no render either.
  auto post = server.client().Post("/render", {{"If-None-Match", tag}}, kScene, "application/json");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 412);
  EXPECT_EQ(problem_of(post)["type"], "urn:rasterd:problem:precondition-failed");
  EXPECT_EQ(renders(server), 4);
}

TEST(ImageUrl, CacheControlOnGetImagesOnly) {
  rasterd::ServiceConfig config;
  config.cache_max_age = 600;
  TestServer server(config);
  auto get = server.client().Get(url_of(kScene));
  auto post = server.client().Post("/render", kScene, "application/json");
  auto explain = server.client().Get(url_of(kScene) + "&explain=1");
  ASSERT_TRUE(get && post && explain);
  EXPECT_EQ(get->get_header_value("Cache-Control"), "public, max-age=600, immutable");
  EXPECT_FALSE(post->has_header("Cache-Control")) << "POST responses are not cacheable";
  EXPECT_EQ(post->get_header_value("ETag"), get->get_header_value("ETag")) << "but they carry the tag";
  EXPECT_FALSE(explain->has_header("Cache-Control")) << "the plan depends on the thread count";
  EXPECT_FALSE(explain->has_header("ETag"));
}

TEST(ImageUrl, IfNoneMatchParsing) {
  auto hit = [](std::string_view field) { return rasterd::none_match(field, "\"a\"").hit; };
  EXPECT_TRUE(hit("\"a\""));
  EXPECT_TRUE(hit("W/\"a\""));
  EXPECT_TRUE(hit(" \"b\" ,\t\"a\" "));
  EXPECT_TRUE(hit("*"));
  EXPECT_FALSE(hit("\"ab\""));
  EXPECT_FALSE(hit("a"));
  EXPECT_FALSE(hit(""));
  // An image's tag carries its length: read back as it was written, anything else after the hash misses.
  EXPECT_EQ(rasterd::image_etag("\"a\"", 15340), "\"a-15340\"");
  EXPECT_EQ(rasterd::none_match("\"b\", W/\"a-15340\"", "\"a\"").png_bytes, 15340u);
  EXPECT_FALSE(rasterd::none_match("\"a\"", "\"a\"").png_bytes) << "the scene's tag alone has no length";
  for (const char* other : {"\"a-\"", "\"a-12x\"", "\"ab-12\"", "\"a-1234567890123456\"", "\"a12\""})
    EXPECT_FALSE(hit(other)) << other;
}

}  // namespace

namespace {

// Issue 39: image URLs as the web passes them on.

// A cache-buster and the parameters sharing tools append change nothing: the same picture and tag as the
// bare URL (were they read as scene parameters, the answer would be a 400).
TEST(ImageUrl, TheCacheBusterAndTrackingParametersAreIgnored) {
  TestServer server;
  auto bare = server.client().Get(url_of(kScene));
  ASSERT_TRUE(bare);
  ASSERT_EQ(bare->status, 200);
  for (const std::string extra :
       {"&v=2", "&utm_source=x&utm_medium=social", "&fbclid=IwAR0abc", "&gclid=1"}) {
    auto r = server.client().Get(url_of(kScene) + extra);
    ASSERT_TRUE(r) << extra;
    EXPECT_EQ(r->status, 200) << extra << "\n" << r->body;
    EXPECT_EQ(r->body, bare->body) << extra;
    EXPECT_EQ(r->get_header_value("ETag"), bare->get_header_value("ETag")) << extra;
  }
}

// A wrong parameter is the URL's fault, not the scene's: its own problem type, naming the parameter.
TEST(ImageUrl, ABadParameterIsAnInvalidQueryNamingIt) {
  TestServer server;
  const std::pair<std::string, std::string> cases[] = {
      {"&w=2", "w"}, {"&scale=0", "scale"}, {"&scale=big", "scale"}, {"&explain=maybe", "explain"}};
  for (const auto& [extra, name] : cases) {
    auto r = server.client().Get(url_of(kScene) + extra);
    ASSERT_TRUE(r) << extra;
    EXPECT_EQ(r->status, 400) << extra;
    const auto p = problem_of(r);
    EXPECT_EQ(p["type"], "urn:rasterd:problem:invalid-query") << r->body;
    EXPECT_EQ(p["parameter"], name) << r->body;
    EXPECT_FALSE(p.contains("pointer")) << "no scene document is at fault: " << r->body;
  }
}

// ?scale=2 is the scene drawn at twice the size: byte for byte the picture of the scene whose width, height,
// coordinates and line widths were doubled by hand (so srcset needs no second scene).
TEST(ImageUrl, ScaleDrawsTheSceneAtThatPixelRatio) {
  TestServer server;
  const std::string scene =
      R"({"width": 20, "height": 12, "background": "#ffffff", "primitives": [
           {"type": "triangle", "points": [[1, 1], [15.5, 2], [4, 11]], "colors": ["#ff0000", "#00ff00", "#0000ff"]},
           {"type": "line", "points": [[2, 9], [18, 3.25]], "width": 1.5, "color": "#000000"}]})";
  const std::string doubled =
      R"({"width": 40, "height": 24, "background": "#ffffff", "primitives": [
           {"type": "triangle", "points": [[2, 2], [31, 4], [8, 22]], "colors": ["#ff0000", "#00ff00", "#0000ff"]},
           {"type": "line", "points": [[4, 18], [36, 6.5]], "width": 3, "color": "#000000"}]})";
  auto scaled = server.client().Get(url_of(scene) + "&scale=2");
  auto by_hand = server.client().Get(url_of(doubled));
  ASSERT_TRUE(scaled && by_hand);
  ASSERT_EQ(scaled->status, 200) << scaled->body;
  EXPECT_EQ(scaled->body, by_hand->body);
  auto posted = server.client().Post("/render?scale=2", scene, "application/json");
  ASSERT_TRUE(posted);
  EXPECT_EQ(posted->body, by_hand->body) << "POST takes ?scale too";
  // A model's default scene: 512 x 512 becomes 1024 x 1024.
  auto model =
      server.client().Post("/render?scale=2&explain=1", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "model/obj");
  ASSERT_TRUE(model);
  EXPECT_EQ(nlohmann::json::parse(model->body)["width"], 1024) << model->body;
  // Past the size limit at that ratio: 422, naming scale.
  auto over = server.client().Get(url_of(R"({"width": 5000, "height": 10, "primitives": []})") + "&scale=2");
  ASSERT_TRUE(over);
  EXPECT_EQ(over->status, 422);
  EXPECT_NE(problem_of(over)["detail"].get<std::string>().find("scale"), std::string::npos) << over->body;
}

}  // namespace
