// The GLSL corpus (tests/glsl/README.md) through rasterd's front end: every program compiled as ShaderToy's
// editor would send it (compile_shadertoy), with the verdict its folder states. accept/ and reject/ are
// glslangValidator's verdicts; glslang-differs/ are the programs where glslang departs from the GLSL ES 3.00
// specification, and there the specification's verdict is the expected one (the opposite of glslang's).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "raster/shader.h"

namespace {

namespace fs = std::filesystem;

struct Program {
  std::string name;  ///< folder/file, as a failure names it
  std::string text;
};

std::vector<Program> corpus(const std::string& folder) {
  std::vector<Program> out;
  const fs::path dir = fs::path(RASTERD_TESTS_DIR) / "glsl" / folder;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".glsl") continue;
    std::ifstream f(e.path(), std::ios::binary);
    std::stringstream text;
    text << f.rdbuf();
    out.push_back({folder + "/" + e.path().filename().string(), text.str()});
  }
  std::sort(out.begin(), out.end(), [](const Program& a, const Program& b) { return a.name < b.name; });
  return out;
}

std::string first_error(const raster::ShaderCompileResult& r) {
  if (r.errors.empty()) return "no error";
  const raster::ShaderMessage& m = r.errors.front();
  return std::to_string(m.string) + ":" + std::to_string(m.line) + ":" + std::to_string(m.column) + ": " +
         m.text;
}

// A rejected program's first error must say where: a line of the program (source string 1). The one place
// outside it is ShaderToy's own call of mainImage (string 2, the epilogue), when the program has no
// mainImage the call can use.
bool says_where(const raster::ShaderCompileResult& r) {
  if (r.errors.empty()) return false;
  const raster::ShaderMessage& m = r.errors.front();
  if (m.line < 1) return false;
  return m.string == 1 || (m.string == 2 && m.text.find("mainImage") != std::string::npos);
}

// Compiles every program of `folder`; `expect_accept(text)` says what the verdict must be. Reports each
// mismatch with rasterd's first error, and the count that came out as expected.
void check_folder(const std::string& folder, bool (*expect_accept)(const std::string&)) {
  const std::vector<Program> programs = corpus(folder);
  ASSERT_FALSE(programs.empty()) << "no programs in tests/glsl/" << folder;
  int matched = 0;
  for (const Program& p : programs) {
    const raster::ShaderCompileResult r = raster::compile_shadertoy(p.text);
    const bool accepted = r.shader != nullptr;
    const bool want = expect_accept(p.text);
    if (accepted != want) {
      ADD_FAILURE() << p.name << ": rasterd " << (accepted ? "accepts" : "rejects") << " it, expected "
                    << (want ? "accept" : "reject") << " (" << first_error(r) << ")";
    } else if (!accepted && !says_where(r)) {
      ADD_FAILURE() << p.name << ": rejected, but the first error does not name a line of the program ("
                    << first_error(r) << ")";
    } else {
      ++matched;
    }
  }
  std::printf("[ corpus   ] %s: %d of %zu as expected\n", folder.c_str(), matched, programs.size());
}

TEST(GlslCorpus, WhatGlslangAcceptsCompiles) {
  check_folder("accept", [](const std::string&) { return true; });
}

TEST(GlslCorpus, WhatGlslangRejectsFailsAndSaysWhere) {
  check_folder("reject", [](const std::string&) { return false; });
}

// Line 2 says what glslang does: "// glslang: accepts" or "// glslang: rejects"; the spec says the other.
TEST(GlslCorpus, WhereGlslangDiffersTheSpecDecides) {
  check_folder("glslang-differs", [](const std::string& text) {
    const std::size_t line2 = text.find('\n') + 1;
    return text.compare(line2, 19, "// glslang: rejects") == 0;
  });
}

// After an error rasterd goes on wherever the rest of the program stays readable (the next statement, the
// next declaration, the pass after the preprocessor), so one compile names every independent mistake, and
// a name whose declaration broke is not reported again where it is used.
TEST(GlslCorpus, IndependentErrorsInDifferentPlacesAreAllReported) {
  struct Case {
    const char* what;
    const char* source;
    std::vector<int> lines;  ///< of the errors, in order
  };
  const Case cases[] = {
      {"a type error in each of two functions",
       "float f() {\n  return 1;\n}\n"
       "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(f());\n  int i = 1.0;\n}\n",
       {2, 6}},
      {"two undeclared names in two statements",
       "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(a);\n  c.x = b;\n}\n",
       {2, 3}},
      {"a syntax error, then a type error in the next function",
       "float f() {\n  return 1.0 +;\n}\n"
       "void mainImage(out vec4 c, in vec2 p) {\n  c = vec3(1.0);\n}\n",
       {2, 5}},
      {"a missing semicolon, then an undeclared name in the next statement",
       "void mainImage(out vec4 c, in vec2 p) {\n  float x = 1.0\n  c = vec4(x);\n  c = vec4(y);\n}\n",
       {3, 4}},
      {"a declaration whose initializer does not parse, its name used after it, then an undeclared name",
       "void mainImage(out vec4 c, in vec2 p) {\n  float x = 1.0 +;\n  c = vec4(x);\n  c = vec4(y);\n}\n",
       {2, 4}},
      {"a statement that does not parse in each of two functions",
       "float f() {\n  return (1.0;\n}\n"
       "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(f()) +* 2.0;\n}\n",
       {2, 5}},
      {"a bad global declaration, then an error in a function",
       "uniform float u = 1.0;\n"
       "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(1.0) + 1;\n}\n",
       {1, 3}},
      {"two preprocessor errors and one in the program",
       "#if 1 +\n#endif\n#foo\n"
       "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(z);\n}\n",
       {1, 3, 5}},
  };
  for (const Case& c : cases) {
    const raster::ShaderCompileResult r = raster::compile_shadertoy(c.source);
    EXPECT_FALSE(r.shader) << c.what;
    std::vector<int> lines;
    std::string all;
    for (const raster::ShaderMessage& m : r.errors) {
      if (m.string == 1) lines.push_back(m.line);
      all += "\n  " + std::to_string(m.string) + ":" + std::to_string(m.line) + ":" +
             std::to_string(m.column) + ": " + m.text;
    }
    EXPECT_EQ(lines, c.lines) << c.what << ":" << all;
  }
}

}  // namespace
