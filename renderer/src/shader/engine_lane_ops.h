// The handlers that look at single lanes: run-time indices, integer division, packing, derivatives,
// textures, and the loop counter. They are the same scalar code under every lane type, so they are
// compiled once (engine_lane_ops.cpp, engine_texture.cpp) and called from each instantiation.
#pragma once

#include <cstdint>

#include "shader/engine.h"

namespace raster::shader::run {

/// Where a block's run stands: each lane's loop count, how many back-edges the block has taken, and
/// whether exec holds every lane (then stores need no mask).
struct BlockState {
  std::int32_t counts[kBlockLanes] = {};
  std::int64_t iterations = 0;
  bool exec_full = true;
};

/// load_index, store_index, idiv, imod, udiv, umod, packing, ddx, ddy, tex_sample, tex_fetch, tex_size.
void lane_op(const Instr& in, std::uint32_t* registers, const RunContext& context);

/// A loop's back-edge taken by the live lanes: counts them, and says whether the block must stop (a lane
/// past the iteration limit, or the render's deadline).
RunResult count_iteration(std::uint32_t loop, std::uint32_t* registers, const RunContext& context,
                          BlockState& state);

// Textures (engine_texture.cpp).
void sample(const Instr& in, std::uint32_t* registers, const RunContext& context);
void fetch(const Instr& in, std::uint32_t* registers, const RunContext& context);
void texture_size(const Instr& in, std::uint32_t* registers, const RunContext& context);

}  // namespace raster::shader::run
