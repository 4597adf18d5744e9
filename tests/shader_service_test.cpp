// Shader primitives through the service (issue 61), over real HTTP on an ephemeral port: a program renders
// by POST and by image URL, a program that does not compile is a 400 that says where every error is, a
// program that never ends is a 422 and the server answers the next request, the ETag follows the source and
// the uniforms, compiled programs are found in the service's cache, and the flags set the programs' bounds.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "flags.h"
#include "scene_url_support.h"
#include "support.h"
#include "test_server.h"

namespace {

using nlohmann::json;
using test::TestServer;

// Red is x / width, green y / height (GL's origin: the bottom row is y = 0.5), blue the uniform "k".
const char* kProgram =
    "uniform float k;\n"
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "  fragColor = vec4(fragCoord / iResolution.xy, k, 1.0);\n"
    "}\n";

std::string scene_of(const std::string& source, double k = 0.5, int width = 32, int height = 16) {
  return json{{"width", width},
              {"height", height},
              {"primitives", {{{"type", "shader"}, {"source", source}, {"uniforms", {{"k", k}}}}}}}
      .dump();
}

// A float as GL writes it to a byte: clamped, times 255, rounded to nearest even.
int gl_byte(float v) {
  return static_cast<int>(std::nearbyint(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255.0f));
}

json problem_of(const httplib::Result& r) {
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  const json j = json::parse(r->body);
  EXPECT_EQ(j["status"], r->status);
  return j;
}

httplib::Result post(const TestServer& server, const std::string& scene) {
  return server.client().Post("/render", scene, "application/json");
}

TEST(ShaderService, AShaderSceneRendersByPostAndByImageUrl) {
  TestServer server;
  const std::string scene = scene_of(kProgram);
  auto r = post(server, scene);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
  EXPECT_NE(r->get_header_value("X-Render-Plan").find(" shaders=1 "), std::string::npos)
      << r->get_header_value("X-Render-Plan");
  const test::Decoded png = test::decode_png(r->body);
  ASSERT_EQ(png.width, 32);
  ASSERT_EQ(png.height, 16);
  ASSERT_EQ(png.channels, 3);
  for (const auto& [x, y] : {std::pair{0, 0}, {31, 15}, {7, 3}, {20, 12}}) {
    const std::uint8_t* p = &png.pixels[static_cast<std::size_t>((y * 32 + x) * 3)];
    EXPECT_EQ(p[0], gl_byte((x + 0.5f) / 32)) << x << "," << y;
    EXPECT_EQ(p[1], gl_byte((15 - y + 0.5f) / 16)) << x << "," << y << ": the top row is GL's last";
    EXPECT_EQ(p[2], gl_byte(0.5f)) << "the uniform";
  }
  // The scene in the URL, deflated or plain: the same picture and tag.
  for (const bool deflated : {true, false}) {
    auto get =
        server.client().Get("/render?scene=" + test::base64url(deflated ? test::deflate(scene) : scene));
    ASSERT_TRUE(get);
    ASSERT_EQ(get->status, 200) << get->body;
    EXPECT_EQ(get->body, r->body);
    EXPECT_EQ(get->get_header_value("ETag"), r->get_header_value("ETag"));
    EXPECT_FALSE(get->get_header_value("Cache-Control").empty());
  }
  // And its plan: the program's size.
  auto explain = server.client().Post("/render?explain=1", scene, "application/json");
  ASSERT_TRUE(explain);
  ASSERT_EQ(explain->status, 200);
  const json plan = json::parse(explain->body);
  ASSERT_EQ(plan["shaders"].size(), 1u);
  EXPECT_GT(plan["shaders"][0]["instructions"].get<int>(), 0);
  EXPECT_GT(plan["shaders"][0]["slots"].get<int>(), 0);
  EXPECT_EQ(plan["primitives"]["shaders"], 1);
  EXPECT_GT(plan["memory_bytes"]["shaders"].get<long>(), 0);
}

TEST(ShaderService, ACompileErrorIsA400ThatSaysWhereEveryErrorIs) {
  TestServer server;
  // Line 2, column 13: an int where a float is declared; line 3: 'y' is not declared.
  const std::string source = "void mainImage(out vec4 c, in vec2 p) {\n  float x = 1;\n  c = vec4(y);\n}\n";
  auto r = post(server, scene_of(source));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  const json p = problem_of(r);
  EXPECT_EQ(p["type"], "urn:rasterd:problem:invalid-shader");
  EXPECT_EQ(p["pointer"], "/primitives/0/source");
  EXPECT_EQ(p["line"], 2);
  EXPECT_EQ(p["column"], 13);
  ASSERT_EQ(p["errors"].size(), 2u) << p.dump();
  EXPECT_EQ(p["errors"][0]["line"], 2);
  EXPECT_EQ(p["errors"][0]["column"], 13);
  EXPECT_EQ(p["errors"][1]["line"], 3);
  EXPECT_NE(p["errors"][1]["message"].get<std::string>().find("'y'"), std::string::npos) << p.dump();
  EXPECT_NE(p["detail"].get<std::string>().find("2:13"), std::string::npos) << p["detail"];
  EXPECT_FALSE(r->has_header("ETag")) << "errors carry no tag";
  // The second primitive's program: its own pointer.
  const json two = {
      {"width", 8},
      {"height", 8},
      {"primitives",
       {{{"type", "line"}, {"points", {{0, 0}, {7, 7}}}}, {{"type", "shader"}, {"source", source}}}}};
  auto second = post(server, two.dump());
  ASSERT_TRUE(second);
  EXPECT_EQ(problem_of(second)["pointer"], "/primitives/1/source");
}

// A loop that never ends at iTime = 0: with the default bound on loop iterations, a 422 shader-limit that
// names the loop's line; with no practical bound, the render deadline stops it (422 deadline-exceeded).
// Either way the server answers the next request.
TEST(ShaderService, AnEndlessLoopIsA422WithinTheDeadlineAndTheServerGoesOn) {
  const std::string endless =
      "void mainImage(out vec4 c, in vec2 p) {\n  float t = 0.0;\n  while (iTime >= 0.0) {\n    t += 1.0;\n"
      "  }\n  c = vec4(t);\n}\nuniform float k;\n";
  for (const bool bounded : {true, false}) {
    rasterd::ServiceConfig config;
    config.render_deadline = std::chrono::milliseconds(300);
    if (!bounded) config.limits.shader.max_loop_iterations = std::int64_t{1} << 40;
    TestServer server(config);
    const auto t0 = std::chrono::steady_clock::now();
    auto r = post(server, scene_of(endless, 0, 256, 256));
    const auto took = std::chrono::steady_clock::now() - t0;
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422) << r->body;
    const json p = problem_of(r);
    if (bounded) {
      EXPECT_EQ(p["type"], "urn:rasterd:problem:shader-limit") << p.dump();
      EXPECT_EQ(p["line"], 3) << "the loop: " << p.dump();
      EXPECT_EQ(p["pointer"], "/primitives/0/source");
    } else {
      EXPECT_EQ(p["type"], "urn:rasterd:problem:deadline-exceeded") << p.dump();
    }
    // A bound for a broken build only (the deadline is 300 ms; the render stops within ~10 ms of it).
    EXPECT_LT(took, std::chrono::seconds(20));
    auto health = server.client().Get("/healthz");
    ASSERT_TRUE(health);
    EXPECT_EQ(health->status, 200);
    auto next = post(server, scene_of(kProgram));
    ASSERT_TRUE(next);
    EXPECT_EQ(next->status, 200) << next->body;
  }
}

TEST(ShaderService, TheEtagFollowsTheSourceAndTheUniforms) {
  TestServer server;
  auto tag = [&](const std::string& scene) {
    auto r = post(server, scene);
    EXPECT_TRUE(r && r->status == 200) << (r ? r->body : "no answer");
    return r ? r->get_header_value("ETag") : std::string();
  };
  const std::string base = tag(scene_of(kProgram, 0.5));
  ASSERT_FALSE(base.empty());
  EXPECT_EQ(tag(scene_of(kProgram, 0.5)), base) << "one scene, one tag";
  // The same scene spelt otherwise: 0.5 as 5e-1, the keys in another order.
  EXPECT_EQ(tag(R"({"primitives": [{"uniforms": {"k": 5e-1}, "source": )" + json(kProgram).dump() +
                R"(, "type": "shader"}], "height": 16, "width": 32})"),
            base);
  EXPECT_NE(tag(scene_of(kProgram, 0.25)), base) << "a uniform differs";
  EXPECT_NE(tag(scene_of(std::string(kProgram) + "// a comment\n", 0.5)), base) << "the source differs";
  const json with_time = {
      {"width", 32},
      {"height", 16},
      {"primitives", {{{"type", "shader"}, {"source", kProgram}, {"uniforms", {{"k", 0.5}}}, {"time", 1}}}}};
  EXPECT_NE(tag(with_time.dump()), base) << "iTime differs";
}

// The value of the sample `name` in GET /metrics; -1 when absent.
long shader_metric(const TestServer& server, const std::string& name) {
  auto m = server.client().Get("/metrics");
  if (!m) return -2;
  const std::string needle = "\n" + name + " ";
  const auto at = m->body.find(needle);
  return at == std::string::npos ? -1 : std::stol(m->body.substr(at + needle.size()));
}

TEST(ShaderService, TheCacheCountsAHitOnTheSecondRequestOfAProgram) {
  TestServer server;
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_misses_total"), 0);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_bytes"), 0);
  auto first = post(server, scene_of(kProgram, 0.5));
  ASSERT_TRUE(first && first->status == 200);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_misses_total"), 1);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_hits_total"), 0);
  const long bytes = shader_metric(server, "rasterd_shader_cache_bytes");
  EXPECT_GT(bytes, 0);
  // The same program with another uniform and by image URL: found, not compiled again.
  auto second =
      server.client().Get("/render?scene=" + test::base64url(test::deflate(scene_of(kProgram, 0.75))));
  ASSERT_TRUE(second && second->status == 200);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_hits_total"), 1);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_misses_total"), 1);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_bytes"), bytes);
  // A program that does not compile is not kept.
  auto bad = post(server, scene_of("void mainImage(out vec4 c, in vec2 p) { c = y; }"));
  ASSERT_TRUE(bad && bad->status == 400);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_misses_total"), 2);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_bytes"), bytes);
}

TEST(ShaderService, ACacheOfZeroBytesKeepsNothingAndStillRenders) {
  rasterd::ServiceConfig config;
  config.shader_cache_bytes = 0;
  TestServer server(config);
  auto r = post(server, scene_of(kProgram));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(shader_metric(server, "rasterd_shader_cache_hits_total"), -1) << "no cache, no cache metrics";
}

// The cache's bytes are held by no request: the default memory budget sets them aside, as it does the
// process's own memory. What would break: a full cache pushing reserved memory past the container's limit.
TEST(ShaderService, TheDefaultMemoryBudgetSetsTheCacheAside) {
  rasterd::ServiceConfig with_cache, without;
  with_cache.shader_cache_bytes = std::size_t{32} << 20;
  without.shader_cache_bytes = 0;
  TestServer a(with_cache), b(without);
  const long budget = shader_metric(b, "rasterd_memory_budget_bytes");
  ASSERT_GT(budget, 0);
  if (budget < (128l << 20)) GTEST_SKIP() << "a machine this small gets the 64 MiB floor either way";
  EXPECT_EQ(shader_metric(a, "rasterd_memory_budget_bytes"), budget - (32l << 20));
  rasterd::ServiceConfig explicit_budget = with_cache;
  explicit_budget.memory_budget = std::int64_t{100} << 20;
  TestServer c(explicit_budget);
  EXPECT_EQ(shader_metric(c, "rasterd_memory_budget_bytes"), 100l << 20) << "a budget given is the budget";
}

// The bounds of ShaderLimits are the service's flags, and the service holds programs to them.
TEST(ShaderService, FlagsSetTheProgramsBoundsAndTheCache) {
  rasterd::ServiceConfig config;
  std::string host;
  int port = 0;
  const char* argv[] = {"--shader-max-source-bytes",
                        "1000",
                        "--shader-max-tokens=2000",
                        "--shader-max-nesting",
                        "30",
                        "--shader-max-instructions",
                        "4000",
                        "--shader-max-slots",
                        "500",
                        "--shader-max-loop-iterations",
                        "99",
                        "--shader-cache-bytes",
                        "0"};
  ASSERT_EQ(rasterd::parse_service_flags(13, argv, config, host, port), "");
  EXPECT_EQ(config.limits.shader.max_source_bytes, 1000u);
  EXPECT_EQ(config.limits.shader.max_tokens, 2000u);
  EXPECT_EQ(config.limits.shader.max_nesting, 30);
  EXPECT_EQ(config.limits.shader.max_instructions, 4000u);
  EXPECT_EQ(config.limits.shader.max_slots, 500u);
  EXPECT_EQ(config.limits.shader.max_loop_iterations, 99);
  EXPECT_EQ(config.shader_cache_bytes, 0u);
  ::setenv("RASTERD_SHADER_MAX_LOOP_ITERATIONS", "12345", 1);
  rasterd::ServiceConfig from_env;
  EXPECT_EQ(rasterd::parse_service_flags(0, nullptr, from_env, host, port), "");
  ::unsetenv("RASTERD_SHADER_MAX_LOOP_ITERATIONS");
  EXPECT_EQ(from_env.limits.shader.max_loop_iterations, 12345);
  EXPECT_EQ(from_env.shader_cache_bytes, std::size_t{64} << 20) << "64 MiB by default";
  const char* bad[] = {"--shader-max-nesting", "0"};
  EXPECT_NE(rasterd::parse_service_flags(2, bad, config, host, port).find("--shader-max-nesting"),
            std::string::npos);
  for (const char* flag :
       {"--shader-cache-bytes", "--shader-max-source-bytes", "--shader-max-tokens", "--shader-max-nesting",
        "--shader-max-instructions", "--shader-max-slots", "--shader-max-loop-iterations"})
    EXPECT_NE(rasterd::service_help().find(flag), std::string::npos) << flag << " is in --help";

  // Over HTTP: a program past --shader-max-source-bytes is a 400 that names the bound.
  rasterd::ServiceConfig small;
  small.limits.shader.max_source_bytes = 64;
  TestServer server(small);
  auto r = post(server, scene_of(kProgram));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  const json p = problem_of(r);
  EXPECT_EQ(p["type"], "urn:rasterd:problem:invalid-shader");
  EXPECT_NE(p["detail"].get<std::string>().find("64 allowed"), std::string::npos) << p["detail"];
}

}  // namespace
