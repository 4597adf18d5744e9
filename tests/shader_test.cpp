// Shader primitives (issue 61): programs compiled by rasterd's GLSL front end and drawn, pixel by pixel
// against values computed here with the same float operations, and the same bytes from every lane width and
// thread count.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "raster/plan.h"
#include "raster/render.h"
#include "raster/scene.h"
#include "raster/shader.h"

namespace {

using raster::Image;
using raster::Scene;

Scene shader_scene(const std::string& source, int width, int height) {
  Scene s;
  s.width = width, s.height = height;
  raster::ShaderPrimitive p;
  p.source = source;
  s.shaders.push_back(p);
  raster::Primitive prim;
  prim.kind = raster::PrimitiveKind::shader;
  s.primitives.push_back(prim);
  return s;
}

// With `threads`, exactly that many, whatever the plan's estimate of the work.
Image draw(const Scene& scene, const raster::PlanOptions& options = {}, int threads = 0) {
  raster::RenderPlan plan = raster::plan(scene, {}, options);
  if (threads > 0) plan.threads = threads;
  return raster::render(scene, plan);
}

Image draw(const std::string& source, int width = 16, int height = 16) {
  return draw(shader_scene(source, width, height));
}

// A float as GL writes it to a byte: clamped to 0..1, times 255, rounded to nearest even.
int gl_byte(float v) {
  v = v > 0 ? (v < 1 ? v : 1) : 0;
  return static_cast<int>(std::nearbyint(v * 255.0f));
}

int channel(const Image& im, int x, int y, int c) {
  return im.at(x, y)[c];
}

std::string program(const std::string& body) {
  return "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n" + body + "\n}\n";
}

TEST(Shader, FragCoordHasGlsOriginAtTheBottomLeftAndPixelCentres) {
  // Red is x / 16, green y / 16 of the pixel centre: the top-left pixel is (0.5, 15.5).
  const Image im = draw(program("fragColor = vec4(fragCoord / iResolution.xy, 0.25, 1.0);"));
  ASSERT_EQ(im.width, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      EXPECT_EQ(channel(im, x, y, 0), gl_byte((x + 0.5f) / 16.0f)) << x << "," << y;
      EXPECT_EQ(channel(im, x, y, 1), gl_byte((15 - y + 0.5f) / 16.0f)) << x << "," << y;
      EXPECT_EQ(channel(im, x, y, 2), gl_byte(0.25f));
    }
}

TEST(Shader, ARectangleHasItsOwnOriginAndResolution) {
  Scene s = shader_scene(
      program("fragColor = vec4(fragCoord.x / iResolution.x, iResolution.y / 255.0, 0, 1);"), 16, 16);
  s.background = {0, 0, 255, 255};
  s.shaders[0].whole = false;
  s.shaders[0].rect = {4, 2, 8, 10};
  const Image im = draw(s);
  EXPECT_EQ(channel(im, 3, 5, 2), 255) << "outside the rectangle: the background";
  EXPECT_EQ(channel(im, 4, 2, 0), gl_byte(0.5f / 8.0f));
  EXPECT_EQ(channel(im, 11, 11, 0), gl_byte(7.5f / 8.0f));
  EXPECT_EQ(channel(im, 11, 11, 1), 10);
  EXPECT_EQ(channel(im, 12, 11, 2), 255);
}

TEST(Shader, ControlFlowRunsEachPixelsOwnPath) {
  // Per pixel: a loop that breaks at a pixel-dependent count after an assignment, a continue, an early
  // return in a function after assignments, a switch with fall-through, and a dynamically indexed array.
  const std::string src = R"(
int steps(int n) {
  int k = 0;
  for (int i = 0; i < 100; i++) {
    if (i == n) {
      k *= 2;
      break;
    }
    if (i % 2 == 1) continue;
    k += 1;
  }
  return k;
}
float pick(int i) {
  if (i > 10) {
    float whole = 0.5;
    whole *= 2.0;
    return whole;
  }
  float a[4] = float[](0.1, 0.2, 0.3, 0.4);
  return a[i & 3];
}
int fall(int v) {
  int r = 0;
  switch (v) {
    case 0: r += 1;
    case 1: r += 2; break;
    case 2: r += 4;
    default: r += 8;
  }
  return r;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int x = int(fragCoord.x), y = int(fragCoord.y);
  fragColor = vec4(float(steps(x)) / 255.0, pick(y), float(fall(x % 4)) / 255.0, 1.0);
}
)";
  const Image im = draw(src, 16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const int gy = 15 - y;
      const int expect_steps = (x + 1) / 2 * 2;
      const float a[4] = {0.1f, 0.2f, 0.3f, 0.4f};
      const float expect_pick = gy > 10 ? 1.0f : a[gy & 3];
      const int v = x % 4;
      const int expect_fall = v == 0 ? 3 : v == 1 ? 2 : v == 2 ? 12 : 8;
      EXPECT_EQ(channel(im, x, y, 0), expect_steps) << x << "," << y;
      EXPECT_EQ(channel(im, x, y, 1), gl_byte(expect_pick)) << x << "," << y;
      EXPECT_EQ(channel(im, x, y, 2), expect_fall) << x << "," << y;
    }
}

TEST(Shader, DiscardedPixelsKeepWhatIsBelow) {
  Scene s = shader_scene(program("if (fragCoord.x < 8.0) discard; fragColor = vec4(1, 0, 0, 1);"), 16, 4);
  s.background = {0, 255, 0, 255};
  const Image im = draw(s);
  EXPECT_EQ(channel(im, 7, 0, 1), 255);
  EXPECT_EQ(channel(im, 8, 0, 0), 255);
  EXPECT_EQ(channel(im, 8, 0, 1), 0);
}

TEST(Shader, NotOpaqueCompositesByTheProgramsAlpha) {
  Scene s = shader_scene(program("fragColor = vec4(1.0, 0.0, 0.0, 0.5);"), 8, 8);
  s.background = {0, 0, 255, 255};
  const Image opaque = draw(s);
  EXPECT_EQ(channel(opaque, 0, 0, 0), 255);
  EXPECT_EQ(channel(opaque, 0, 0, 2), 0);
  s.shaders[0].opaque = false;
  const Image blended = draw(s);
  EXPECT_EQ(channel(blended, 0, 0, 0), 128);
  EXPECT_EQ(channel(blended, 0, 0, 2), 127);
}

TEST(Shader, UndefinedIntegerOperationsHaveOneAnswer) {
  // x / 0, x % 0, INT_MIN / -1, shifts past 31, and NaN and Inf colours: the answers the README states.
  const std::string src = program(R"(
  int zero = int(fragCoord.x) - int(fragCoord.x);
  int m = int(0x80000000u);
  int q = 7 / zero, r = 7 % zero, big = m / (zero - 1);
  uint uq = 7u / uint(zero);
  int s = 1 << (33 + zero);
  float nan = sqrt(-1.0 + float(zero)), inf = 1.0 / float(zero);
  fragColor = vec4(float(q == 0) * 0.5 + float(r == -1) * 0.25, float(big == m) * 0.5 + float(uq == 0xffffffffu) * 0.25,
                   float(s == 2), 1.0);
  if (fragCoord.x > 4.0) fragColor = vec4(nan, inf, -inf, 1.0);
)");
  const Image im = draw(src, 8, 1);
  EXPECT_EQ(channel(im, 0, 0, 0), gl_byte(0.75f));
  EXPECT_EQ(channel(im, 0, 0, 1), gl_byte(0.75f));
  EXPECT_EQ(channel(im, 0, 0, 2), 255);
  EXPECT_EQ(channel(im, 6, 0, 0), 0) << "NaN is 0";
  EXPECT_EQ(channel(im, 6, 0, 1), 255) << "+Inf is 1";
  EXPECT_EQ(channel(im, 6, 0, 2), 0) << "-Inf is 0";
}

TEST(Shader, UniformsAreSetByName) {
  Scene s = shader_scene(
      "uniform vec3 tint; uniform int level;\n" + program("fragColor = vec4(tint * float(level), 1.0);"), 8,
      8);
  s.shaders[0].uniforms = {{"tint", {0.25, 0.5, 0.125}}, {"level", {2}}};
  const Image im = draw(s);
  EXPECT_EQ(channel(im, 3, 3, 0), gl_byte(0.5f));
  EXPECT_EQ(channel(im, 3, 3, 1), 255);
  EXPECT_EQ(channel(im, 3, 3, 2), gl_byte(0.25f));
  s.shaders[0].uniforms = {{"tnit", {1, 2, 3}}};
  try {
    draw(s);
    FAIL() << "an undeclared uniform is an error";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::invalid);
    EXPECT_EQ(e.where().pointer, "/primitives/0/uniforms/tnit");
    EXPECT_NE(std::string(e.what()).find("tint"), std::string::npos)
        << "names what it declares: " << e.what();
  }
}

TEST(Shader, CompileErrorsSayWhereEachIs) {
  const raster::ShaderCompileResult r = raster::compile_shadertoy(
      "void mainImage(out vec4 c, in vec2 p) {\n  float x = 1;\n  c = vec4(y);\n}\n");
  ASSERT_FALSE(r.shader);
  ASSERT_EQ(r.errors.size(), 2u);
  EXPECT_EQ(r.errors[0].line, 2);
  EXPECT_EQ(r.errors[0].column, 13);
  EXPECT_EQ(r.errors[0].string, 1);
  EXPECT_EQ(r.errors[1].line, 3);
  EXPECT_NE(r.errors[1].text.find("'y'"), std::string::npos) << r.errors[1].text;
  // Through a scene, the first error's place and every message.
  try {
    draw(shader_scene("void mainImage(out vec4 c, in vec2 p) {\n  float x = 1;\n  c = vec4(y);\n}\n", 8, 8));
    FAIL() << "a program that does not compile cannot draw";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::shader);
    EXPECT_EQ(e.where().pointer, "/primitives/0/source");
    EXPECT_EQ(e.where().line, 2u);
    EXPECT_EQ(e.where().column, 13u);
    EXPECT_EQ(e.notes().size(), 2u);
  }
}

TEST(Shader, ALoopThatNeverEndsStopsAtItsBoundAndNamesTheLoop) {
  Scene s = shader_scene(
      program("float t = 0.0;\nwhile (iTime >= 0.0) {\n  t += 1.0;\n}\nfragColor = vec4(t);"), 8, 8);
  try {
    draw(s);
    FAIL() << "an endless loop must stop";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::program);
    EXPECT_EQ(e.where().line, 3u) << e.what();
    EXPECT_NE(std::string(e.what()).find("pixel ("), std::string::npos) << e.what();
  }
}

// A counted loop is written out (no loop left to count) and gives the values of the loop it was: each
// header shape against the same loop with its bound in a uniform, which stays a loop. A loop that writes its
// variable or continues stays a loop.
TEST(Shader, CountedLoopsAreWrittenOutWithTheLoopsValues) {
  struct Case {
    std::string type, init, op, bound, step;
    bool written_out;
    std::string body = "";
  };
  const Case cases[] = {
      {"int", "0", "<", "6", "i++", true},
      {"int", "5", ">=", "-3", "i -= 2", true},
      {"int", "-2", "<=", "2", "++i", true},
      {"int", "10", ">", "0", "i--", true},
      {"int", "0", "!=", "12", "i += 3", true},
      {"uint", "0u", "<", "5u", "i++", true},
      {"int", "0", "<", "6", "i++", false, "if (i == 2) continue;"},
      {"int", "0", "<", "6", "i++", false, "if (fragCoord.x > 4.0 && i == 1) i += 2;"},
  };
  const std::string helper =
      "void damp(inout float a, int k) { a = a * 0.9 + float(k); }\n"
      "uniform int bi; uniform uint bu;\n";
  for (const Case& c : cases) {
    const auto source = [&](const std::string& bound) {
      return helper +
             program("float acc = 0.0;\nfor (" + c.type + " i = " + c.init + "; i " + c.op + " " + bound +
                     "; " + c.step + ") {\n" + c.body +
                     "  acc += float(i) * fragCoord.x + sin(float(i) * fragCoord.y);\n"
                     "  switch (int(i)) { case 1: acc *= 0.5; break; default: break; }\n"
                     "  damp(acc, int(i));\n}\nfragColor = vec4(fract(acc * 0.01), fract(acc), 0.5, 1.0);");
    };
    const std::string counted = source(c.bound), hidden = source(c.type == "int" ? "bi" : "bu");
    const raster::ShaderCompileResult a = raster::compile_shadertoy(counted);
    ASSERT_TRUE(a.shader) << counted;
    EXPECT_EQ(a.shader->loops(), c.written_out ? 0u : 1u) << counted;
    Scene s = shader_scene(hidden, 12, 12);
    s.shaders[0].uniforms = {{c.type == "int" ? "bi" : "bu", {std::stod(c.bound)}}};
    EXPECT_EQ(raster::compile_shadertoy(hidden).shader->loops(), 1u);
    EXPECT_EQ(draw(counted, 12, 12).pixels, draw(s).pixels) << counted;
  }
}

// Values followed through variables written many times (a written-out loop's running product here) fold
// to constants, so nothing of the loop is left to run; a division by a power of two, made a multiply, keeps
// the division's bits (tiny and huge quotients included).
TEST(Shader, ConstantsFoldThroughVariablesWrittenManyTimes) {
  const std::string source = program(
      "float f = 1.0; int n = 3;\nfor (int i = 0; i < 4; i++) { f *= 2.0; n = n * 2 + i; }\n"
      "fragColor = vec4(f / 32.0, float(n) / 128.0, 0.0, 1.0);");
  const raster::ShaderCompileResult r = raster::compile_shadertoy(source);
  ASSERT_TRUE(r.shader);
  EXPECT_LE(r.shader->instructions(), 4u) << "the four output values, copied; nothing computed per block";
  const Image im = draw(source, 8, 8);
  EXPECT_EQ(channel(im, 2, 2, 0), gl_byte(0.5f));
  EXPECT_EQ(channel(im, 2, 2, 1), gl_byte(float(((((3 * 2 + 0) * 2 + 1) * 2 + 2) * 2 + 3)) / 128.0f));

  // x / 2^k for x spread over many binades: the bits of the two quotients, three bytes a draw (`part`).
  Scene s = shader_scene(
      "uniform float scale; uniform int part;\n" +
          program("float x = (fragCoord.x * 37.0 + fragCoord.y) * scale;\n"
                  "uint q = floatBitsToUint(x / 0.125), r = floatBitsToUint(x / 8.0);\n"
                  "uint w = part == 0 ? q : r;\n"
                  "fragColor = vec4(float(w >> 24u), float((w >> 16u) & 255u), float((w >> 8u) & 255u),"
                  " 255.0) / 255.0;\n"
                  "if (part == 2) fragColor = vec4(float(q & 255u), float(r & 255u), 0.0, 255.0) / 255.0;"),
      16, 16);
  for (const double scale : {1e-37, 3.1e-5, 1.0, 7.7e30})
    for (int part = 0; part < 3; ++part) {
      s.shaders[0].uniforms = {{"scale", {scale}}, {"part", {double(part)}}};
      const Image im2 = draw(s);
      for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
          const float v = ((x + 0.5f) * 37.0f + (15 - y + 0.5f)) * static_cast<float>(scale);
          const std::uint32_t q = std::bit_cast<std::uint32_t>(v / 0.125f),
                              r = std::bit_cast<std::uint32_t>(v / 8.0f), w = part == 0 ? q : r;
          const int want[3] = {part == 2 ? int(q & 255u) : int(w >> 24),
                               part == 2 ? int(r & 255u) : int((w >> 16) & 255u),
                               part == 2 ? 0 : int((w >> 8) & 255u)};
          for (int c = 0; c < 3; ++c)
            ASSERT_EQ(channel(im2, x, y, c), want[c]) << scale << " part " << part << " at " << x << "," << y;
        }
    }
}

// Integer division and remainder (eight lanes divide in doubles) against C's, with the defined answers
// where GLSL leaves them undefined, over seeded operands mixed with the edge values, in every lane width.
TEST(Shader, IntegerDivisionIsExactInEveryLaneWidth) {
  const std::string source = R"(
uniform int part; uniform uint seed;
uint hash(uint v) { v ^= v >> 16; v *= 0x7feb352du; v ^= v >> 15; v *= 0x846ca68bu; v ^= v >> 16; return v; }
uint pick(uint h) {
  const uint kEdge[8] = uint[8](0u, 1u, 0xffffffffu, 0x80000000u, 0x7fffffffu, 2u, 0xfffffffeu, 7u);
  uint kind = h & 7u;
  return kind < 3u ? kEdge[(h >> 3) & 7u] : kind < 5u ? (h >> 8) & 0xffu : h;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  uint i = uint(fragCoord.x) + 16u * uint(fragCoord.y) + 256u * seed;
  uint a = pick(hash(i * 2u)), b = pick(hash(i * 2u + 1u));
  uint w[4] = uint[4](uint(int(a) / int(b)), uint(int(a) % int(b)), a / b, a % b);
  uint word = w[part / 2];
  fragColor = part % 2 == 0 ? vec4(float(word >> 24), float((word >> 16) & 255u), float((word >> 8) & 255u), 255.0)
                            : vec4(float(word & 255u), 0.0, 0.0, 255.0);
  fragColor /= 255.0;
}
)";
  const auto hash = [](std::uint32_t v) {
    v ^= v >> 16, v *= 0x7feb352du, v ^= v >> 15, v *= 0x846ca68bu, v ^= v >> 16;
    return v;
  };
  const auto pick = [](std::uint32_t h) {
    const std::uint32_t edge[8] = {0u, 1u, 0xffffffffu, 0x80000000u, 0x7fffffffu, 2u, 0xfffffffeu, 7u};
    const std::uint32_t kind = h & 7u;
    return kind < 3u ? edge[(h >> 3) & 7u] : kind < 5u ? (h >> 8) & 0xffu : h;
  };
  const auto words = [](std::uint32_t a, std::uint32_t b) {
    const auto x = static_cast<std::int32_t>(a), y = static_cast<std::int32_t>(b);
    const bool overflow = x == std::numeric_limits<std::int32_t>::min() && y == -1;
    return std::array<std::uint32_t, 4>{y == 0     ? 0u
                                        : overflow ? a
                                                   : static_cast<std::uint32_t>(x / y),
                                        y == 0     ? ~0u
                                        : overflow ? 0u
                                                   : static_cast<std::uint32_t>(x % y),
                                        b == 0 ? ~0u : a / b, b == 0 ? ~0u : a % b};
  };
  Scene s = shader_scene(source, 16, 16);
  std::vector<raster::PlanOptions> widths(1);
  widths[0].scalar_shading = true;
  for (const raster::Simd simd : {raster::Simd::sse2, raster::Simd::avx2}) {
    if (simd == raster::Simd::avx2 && raster::best_simd() != raster::Simd::avx2) continue;
    widths.emplace_back().max_simd = simd;
  }
  for (std::uint32_t seed = 0; seed < 4; ++seed)
    for (int part = 0; part < 8; ++part) {
      s.shaders[0].uniforms = {{"part", {double(part)}}, {"seed", {double(seed)}}};
      for (const raster::PlanOptions& o : widths) {
        const Image im = draw(s, o);
        for (int y = 0; y < 16; ++y)
          for (int x = 0; x < 16; ++x) {
            const std::uint32_t i = static_cast<std::uint32_t>(x + 16 * (15 - y)) + 256u * seed;
            const std::uint32_t word = words(pick(hash(i * 2u)), pick(hash(i * 2u + 1u)))[part / 2];
            const int want[3] = {part % 2 == 0 ? int(word >> 24) : int(word & 255u),
                                 part % 2 == 0 ? int((word >> 16) & 255u) : 0,
                                 part % 2 == 0 ? int((word >> 8) & 255u) : 0};
            for (int c = 0; c < 3; ++c)
              ASSERT_EQ(channel(im, x, y, c), want[c])
                  << "part " << part << " seed " << seed << " at " << x << "," << y << " scalar "
                  << o.scalar_shading << " simd " << int(o.max_simd);
          }
      }
    }
}

// A call of constants to a function of its arguments alone is computed by the compiler (its loop is gone
// from the program), with the value the program would compute; a call that reads a uniform, or whose loop
// outruns the compiler's budget, stays a loop and gives the same value at run time.
TEST(Shader, CallsOfConstantsAreComputedOnceWhenCompiled) {
  const std::string steps =
      "int steps(int n) { int k = 0; while (n != 1) { n = n % 2 == 0 ? n / 2 : 3 * n + 1; k++; } return k; "
      "}\n"
      "int count(int n) { int k = 0; for (int i = 0; i < n; i++) k += i % 3; return k; }\n"
      "uniform int start;\n"
      "int stepsFromUniform() { return steps(start); }\n";
  const auto compiled = [&](const std::string& call) {
    const std::string source =
        steps + program("int v = " + call +
                        ";\nfragColor = vec4(float(v & 255) / 255.0, float(v >> 8) / 255.0, 0.0, 1.0);");
    raster::ShaderCompileResult r = raster::compile_shadertoy(source);
    EXPECT_TRUE(r.shader) << source;
    Scene s = shader_scene(source, 8, 8);
    s.shaders[0].uniforms = {{"start", {27}}};
    const Image im = draw(s);
    return std::make_pair(r.shader ? r.shader->loops() : 99u,
                          channel(im, 1, 1, 0) + 256 * channel(im, 1, 1, 1));
  };
  EXPECT_EQ(compiled("steps(27)"), std::make_pair(std::size_t{0}, 111)) << "folded: no loop left";
  EXPECT_EQ(compiled("stepsFromUniform()"), std::make_pair(std::size_t{1}, 111)) << "reads a uniform";
  EXPECT_EQ(compiled("count(30)"), std::make_pair(std::size_t{0}, 30));
  // 5000 iterations: past the compiler's budget, so the loop runs for every pixel, to the same value.
  int want = 0;
  for (int i = 0; i < 5000; i++) want += i % 3;
  EXPECT_EQ(compiled("count(5000)"), std::make_pair(std::size_t{1}, want & 0xffff));
}

// The bench programs (and this suite's) give one picture from the scalar reference, SSE2 and AVX2, and at
// 1, 2, 3 and 7 threads.
TEST(Shader, EveryLaneWidthAndThreadCountGivesTheSameBytes) {
  for (const char* name : {"gradient", "checker_aa", "mandelbrot", "raymarch_shadow", "fbm_noise",
                           "sine_hash", "voronoi", "features"}) {
    std::ifstream f(std::string(RASTERD_SOURCE_DIR) + "/bench/shaders/" + name + ".glsl");
    ASSERT_TRUE(f) << name;
    std::stringstream text;
    text << f.rdbuf();
    const Scene s = shader_scene(text.str(), 72, 40);
    raster::PlanOptions scalar;
    scalar.scalar_shading = true, scalar.max_threads = 1;
    const Image reference = draw(s, scalar);
    for (const raster::Simd simd : {raster::Simd::sse2, raster::Simd::avx2}) {
      if (simd == raster::Simd::avx2 && raster::best_simd() != raster::Simd::avx2) continue;
      for (const int threads : {1, 2, 3, 7}) {
        raster::PlanOptions o;
        o.max_simd = simd, o.max_threads = threads, o.tile = 16;
        EXPECT_EQ(draw(s, o, threads).pixels, reference.pixels)
            << name << " simd " << int(simd) << " threads " << threads;
      }
    }
  }
}

}  // namespace
