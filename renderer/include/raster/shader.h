// Shaders: GLSL ES 3.00 programs compiled by rasterd's own compiler (renderer/src/shader/) and run by its
// engine, 64 pixels an instruction. A ShaderToy program (a mainImage(out vec4, in vec2)) is compiled once
// and drawn by a scene's "shader" primitive (scene.h) or directly with draw_shader().
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace raster {

/// What a program may cost; every bound is checked before the work it bounds (docs/shaders.md).
struct ShaderLimits {
  std::size_t max_source_bytes = 64 * 1024;  ///< the program's text
  std::size_t max_tokens = 1 << 18;          ///< tokens after preprocessing, every macro expansion counted
  int max_nesting = 200;                     ///< brackets, operators, statements and #if blocks in each other
  std::size_t max_instructions = 1 << 20;    ///< operations once every function is inlined
  std::size_t max_slots = 1 << 14;           ///< 32-bit values a pixel holds at once (arrays included)
  std::int64_t max_loop_iterations = 1 << 16;  ///< per pixel (per sample), every loop's iterations together
};

/// One compile error: a place in the program (line and column from 1; `string` 1 is the program, 0 and 2
/// ShaderToy's frame around it) and a sentence.
struct ShaderMessage {
  int line = 0, column = 0;
  int string = 1;
  std::string text;
};

/// A uniform the program declares, which a scene sets by name (ShaderToy's own are set by the renderer).
struct ShaderUniform {
  std::string name;
  std::string type;   ///< GLSL spelling: "float", "vec3", "mat2", "int[4]"...
  int slots = 0;      ///< 32-bit values
  bool used = false;  ///< the program reads it
};

namespace shader {
struct Program;
}

/// A compiled program: immutable, shared by every render that draws it.
class CompiledShader {
 public:
  explicit CompiledShader(std::unique_ptr<const shader::Program> program);
  ~CompiledShader();
  const shader::Program& program() const { return *program_; }

  std::size_t bytes() const;                  ///< what the compiled program holds in memory
  std::size_t instructions() const;           ///< run for every 8x8 block
  std::size_t prologue_instructions() const;  ///< run once per render: values of uniforms and constants alone
  std::size_t slots() const;                  ///< 32-bit values a pixel holds (x 256 bytes a block)
  std::size_t loops() const;
  bool derivatives() const;            ///< reads neighbouring pixels (dFdx, fwidth, texture levels)
  std::uint8_t channels_read() const;  ///< bit n: iChannel n is sampled
  std::vector<ShaderUniform> uniforms() const;

 private:
  std::unique_ptr<const shader::Program> program_;
};

struct ShaderCompileResult {
  std::shared_ptr<const CompiledShader> shader;  ///< null when there are errors
  std::vector<ShaderMessage> errors;             ///< in the order found
  std::size_t more_errors = 0;                   ///< errors found past the ones kept
};

/// Whether `name` is one of the uniforms ShaderToy declares and sets itself (iTime, iResolution, ...).
bool is_shadertoy_uniform(std::string_view name);

/// Compiles a ShaderToy program: `source` is the text of ShaderToy's editor (mainImage and what it uses).
ShaderCompileResult compile_shadertoy(std::string_view source, const ShaderLimits& limits = {});

/// Compiled programs by their source (and the limits they were compiled under), for a service that sees
/// one program in many requests: at most `max_bytes` of programs are kept, the least recently used dropped.
/// Programs that do not compile are not kept. Thread-safe.
class ShaderCache {
 public:
  explicit ShaderCache(std::size_t max_bytes);
  ~ShaderCache();
  ShaderCompileResult get(std::string_view source, const ShaderLimits& limits);
  std::size_t bytes() const;
  std::size_t hits() const;
  std::size_t misses() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace raster
