// The compiler's passes in order: preprocess -> parse -> check -> lower -> optimize (each a function from
// one plain representation to the next; a test can stop after any of them).
#include <string>

#include "raster/shader.h"
#include "shader/check.h"
#include "shader/ir.h"
#include "shader/lower.h"
#include "shader/optimize.h"
#include "shader/parser.h"
#include "shader/preprocess.h"
#include "shader/shadertoy.h"

namespace raster {

CompiledShader::CompiledShader(std::unique_ptr<const shader::Program> program)
    : program_(std::move(program)) {}
CompiledShader::~CompiledShader() = default;

std::size_t CompiledShader::instructions() const {
  return program_->code.size();
}
std::size_t CompiledShader::prologue_instructions() const {
  return program_->prologue.size();
}
std::size_t CompiledShader::slots() const {
  return program_->slots;
}
std::size_t CompiledShader::loops() const {
  return program_->loops.size();
}
bool CompiledShader::derivatives() const {
  return program_->derivatives;
}
std::uint8_t CompiledShader::channels_read() const {
  return program_->channels_read;
}
std::vector<ShaderUniform> CompiledShader::uniforms() const {
  std::vector<ShaderUniform> out;
  for (const shader::UniformSlots& u : program_->uniforms)
    out.push_back({u.name, u.type, u.slots, u.first != shader::kUnusedSlot});
  return out;
}

ShaderCompileResult compile_shadertoy(std::string_view source, const ShaderLimits& limits) {
  using namespace shader;
  ShaderCompileResult result;
  Diagnostics diagnostics;
  const auto finish = [&] {
    for (const Diagnostic& d : diagnostics.errors())
      result.errors.push_back({d.pos.line, d.pos.column, d.pos.string, d.message});
    result.more_errors = diagnostics.overflow();
    return result;
  };
  if (source.size() > limits.max_source_bytes) {
    diagnostics.error({1, 1, kProgramString}, std::string("the program is ") + std::to_string(source.size()) +
                                                  " bytes, more than the " +
                                                  std::to_string(limits.max_source_bytes) + " allowed");
    return finish();
  }
  const std::string text = shadertoy_fragment_shader(source);
  TextArena arena;
  const std::vector<Token> tokens =
      preprocess(text, PreprocessLimits{limits.max_tokens, limits.max_nesting}, diagnostics, arena);
  // The parser and the checker run after errors too (on what the pass before could read), so one compile
  // names every independent mistake; only a pass that stopped at a bound ends the front end.
  Ast ast;
  if (!diagnostics.stopped()) parse(tokens, limits.max_nesting, ast, diagnostics);
  Checked checked;
  if (!diagnostics.stopped()) check(ast, fold_constant, checked, diagnostics);
  if (diagnostics.failed()) return finish();
  Lowered lowered;
  auto program = std::make_unique<Program>();
  if (!lower(checked, LowerLimits{limits.max_instructions, limits.max_instructions * 4}, lowered,
             diagnostics) ||
      !optimize(lowered, limits.max_slots, *program, diagnostics))
    return finish();
  result.shader = std::make_shared<const CompiledShader>(std::move(program));
  return finish();
}

}  // namespace raster
