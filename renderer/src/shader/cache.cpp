// The compiled-program cache, and the public program's accessors that need the IR.
#include <list>
#include <mutex>
#include <string>
#include <unordered_map>

#include "raster/shader.h"
#include "shader/ir.h"

namespace raster {

bool is_shadertoy_uniform(std::string_view name) {
  static constexpr std::string_view kNames[] = {
      "iResolution", "iTime", "iTimeDelta",  "iFrameRate", "iFrame",    "iChannelTime", "iChannelResolution",
      "iMouse",      "iDate", "iSampleRate", "iChannel0",  "iChannel1", "iChannel2",    "iChannel3"};
  for (const std::string_view n : kNames)
    if (n == name) return true;
  return false;
}

std::size_t CompiledShader::bytes() const {
  const shader::Program& p = *program_;
  std::size_t n = sizeof(shader::Program) + (p.code.size() + p.prologue.size()) * sizeof(shader::Instr) +
                  p.constants.size() * sizeof(p.constants[0]) + p.loops.size() * sizeof(shader::LoopInfo);
  for (const shader::UniformSlots& u : p.uniforms) n += sizeof(u) + u.name.size() + u.type.size();
  return n;
}

struct ShaderCache::State {
  struct Entry {
    std::string key;
    std::shared_ptr<const CompiledShader> shader;
    std::size_t bytes = 0;
  };
  std::mutex mutex;
  std::size_t max_bytes = 0, bytes = 0, hits = 0, misses = 0;
  std::list<Entry> entries;                                                ///< most recently used first
  std::unordered_map<std::string_view, std::list<Entry>::iterator> index;  ///< keys view the entries' own
};

ShaderCache::ShaderCache(std::size_t max_bytes) : state_(std::make_unique<State>()) {
  state_->max_bytes = max_bytes;
}
ShaderCache::~ShaderCache() = default;

ShaderCompileResult ShaderCache::get(std::string_view source, const ShaderLimits& limits) {
  // The key is the whole source and the limits it was compiled under (a program within one set of limits
  // may be past another's), so no two programs can share an entry.
  std::string key(source);
  for (const std::int64_t v : {std::int64_t(limits.max_source_bytes), std::int64_t(limits.max_tokens),
                               std::int64_t(limits.max_nesting), std::int64_t(limits.max_instructions),
                               std::int64_t(limits.max_slots), limits.max_loop_iterations})
    key += '\0', key += std::to_string(v);
  State& s = *state_;
  {
    const std::lock_guard lock(s.mutex);
    const auto it = s.index.find(key);
    if (it != s.index.end()) {
      ++s.hits;
      s.entries.splice(s.entries.begin(), s.entries, it->second);
      ShaderCompileResult r;
      r.shader = it->second->shader;
      return r;
    }
    ++s.misses;
  }
  ShaderCompileResult r = compile_shadertoy(source, limits);  // outside the lock: compiling takes a while
  if (!r.shader) return r;
  const std::size_t bytes = r.shader->bytes() + key.size() * 2;
  if (bytes > s.max_bytes) return r;
  const std::lock_guard lock(s.mutex);
  if (s.index.count(key)) return r;  // another thread compiled it meanwhile
  s.entries.push_front({std::move(key), r.shader, bytes});
  s.index.emplace(s.entries.front().key, s.entries.begin());
  s.bytes += bytes;
  while (s.bytes > s.max_bytes) {
    s.bytes -= s.entries.back().bytes;
    s.index.erase(s.entries.back().key);
    s.entries.pop_back();
  }
  return r;
}

std::size_t ShaderCache::bytes() const {
  const std::lock_guard lock(state_->mutex);
  return state_->bytes;
}
std::size_t ShaderCache::hits() const {
  const std::lock_guard lock(state_->mutex);
  return state_->hits;
}
std::size_t ShaderCache::misses() const {
  const std::lock_guard lock(state_->mutex);
  return state_->misses;
}

}  // namespace raster
