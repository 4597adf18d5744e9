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

bool has_uniform_handlers(Op op) {
  // The groups whose handlers come in four (engine_loop.inc).
  constexpr bool kFloat = true, kInteger = true, kMove = false, kTranscendental = false, kDivide = false,
                 kLane = false, kControl = false, kLoop = false;
  static constexpr bool kHas[] = {
#define RASTER_SHADER_GROUP_float kFloat
#define RASTER_SHADER_GROUP_integer kInteger
#define RASTER_SHADER_GROUP_move kMove
#define RASTER_SHADER_GROUP_transcendental kTranscendental
#define RASTER_SHADER_GROUP_divide kDivide
#define RASTER_SHADER_GROUP_lane kLane
#define RASTER_SHADER_GROUP_control kControl
#define RASTER_SHADER_GROUP_loop kLoop
#define RASTER_SHADER_HAS(name, group) RASTER_SHADER_GROUP_##group,
      RASTER_SHADER_OPS(RASTER_SHADER_HAS)
#undef RASTER_SHADER_HAS
#undef RASTER_SHADER_GROUP_float
#undef RASTER_SHADER_GROUP_integer
#undef RASTER_SHADER_GROUP_move
#undef RASTER_SHADER_GROUP_transcendental
#undef RASTER_SHADER_GROUP_divide
#undef RASTER_SHADER_GROUP_lane
#undef RASTER_SHADER_GROUP_control
#undef RASTER_SHADER_GROUP_loop
  };
  const auto i = static_cast<std::size_t>(op);
  return i < std::size(kHas) && kHas[i];
}

std::string dump(const Program& p) {
  std::string s;
  const auto line = [&](const char* part, std::size_t i, const Instr& in) {
    s += part + std::to_string(i) + ": " + std::string(op_name(in.op)) + " d" + std::to_string(in.d) + " a" +
         std::to_string(in.a) + " b" + std::to_string(in.b) + " c" + std::to_string(in.c) + " #" +
         std::to_string(in.imm) + (in.flags ? " f" + std::to_string(in.flags) : "") +
         (in.uniform ? " u" + std::to_string(in.uniform) : "") + "\n";
  };
  for (std::size_t i = 0; i < p.prologue.size(); ++i) line("P", i, p.prologue[i]);
  for (std::size_t i = 0; i < p.code.size(); ++i) line("", i, p.code[i]);
  return s;
}

}  // namespace raster::shader
