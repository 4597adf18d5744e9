// shader_verdict FILE: rasterd's verdict on a ShaderToy program (compile_shadertoy, as a "shader" primitive
// compiles it), for tests/glsl/differential to set beside glslang's. Prints "accept" or "reject", then each
// error as string:line:column: message. Exit status 0 accepted, 1 rejected, 2 the file cannot be read.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "raster/shader.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: shader_verdict FILE\n");
    return 2;
  }
  std::ifstream f(argv[1], std::ios::binary);
  if (!f) {
    std::fprintf(stderr, "shader_verdict: cannot read %s\n", argv[1]);
    return 2;
  }
  std::stringstream text;
  text << f.rdbuf();
  raster::ShaderLimits limits;
  limits.max_source_bytes =
      text.str().size() + 1;  // the verdict on the language, whatever the program's size
  const raster::ShaderCompileResult r = raster::compile_shadertoy(text.str(), limits);
  std::printf("%s\n", r.shader ? "accept" : "reject");
  for (const raster::ShaderMessage& m : r.errors)
    std::printf("%d:%d:%d: %s\n", m.string, m.line, m.column, m.text.c_str());
  if (r.more_errors > 0) std::printf("(%zu more errors)\n", r.more_errors);
  return r.shader ? 0 : 1;
}
