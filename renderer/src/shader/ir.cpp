#include "shader/ir.h"

#include <string>

namespace raster::shader {

std::string_view op_name(Op op) {
  static constexpr std::string_view kNames[] = {
#define RASTER_SHADER_NAME(name, group) #name,
      RASTER_SHADER_OPS(RASTER_SHADER_NAME)
#undef RASTER_SHADER_NAME
  };

  const auto i = static_cast<std::size_t>(op);
  return i < std::size(kNames) ? kNames[i] : "?";
}

std::string dump(const Program& p) {
  std::string s;
  const auto line = [&](const char* part, std::size_t i, const Instr& in) {
    s += part + std::to_string(i) + ": " + std::string(op_name(in.op)) + " d" + std::to_string(in.d) + " a" +
         std::to_string(in.a) + " b" + std::to_string(in.b) + " c" + std::to_string(in.c) + " #" +
         std::to_string(in.imm) + (in.flags ? " f" + std::to_string(in.flags) : "") + "\n";
  };
  for (std::size_t i = 0; i < p.prologue.size(); ++i) line("P", i, p.prologue[i]);
  for (std::size_t i = 0; i < p.code.size(); ++i) line("", i, p.code[i]);
  return s;
}

}  // namespace raster::shader
