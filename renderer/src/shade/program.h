// Programs: a shader primitive's compiled program (plan.h: ShaderPlan) run over its pixels in a tile, one
// 8x8 block at a time, and its colour written into the tile's storage: converted as GL converts a float
// to a byte (clamped to 0..1, times 255, rounded to nearest even), replacing the pixel or composited over
// it by the program's alpha. A multisampled pixel is the average of the program at each sample position.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "base/grid.h"
#include "base/masks.h"
#include "base/mip_chain.h"
#include "base/stop.h"
#include "framebuffer/surface.h"
#include "raster/plan.h"
#include "raster/scene.h"
#include "shader/engine.h"

namespace raster::detail {

/// A render's programs, ready to run: each one's channel images with their mipmaps, made once for the
/// render and read by every thread.
struct Programs {
  struct Ready {
    const ShaderPlan* plan = nullptr;
    std::deque<MipChain> mips;         ///< of the channels it samples
    shader::ChannelImage channels[4];  ///< views of `mips`, per iChannel; empty: reads zero
  };
  std::deque<Ready> ready;  ///< in RenderPlan::shaders' order (a deque: a Ready does not move)
  shader::Lanes lanes = shader::Lanes::sse2;  ///< the plan's instruction set (or the scalar reference)
  std::int64_t bytes() const;                 ///< the mipmaps made
};

/// The channels' mip chains of every program of `plan`. Counts their texels on `meter` and returns early,
/// incomplete, once it says the render must stop.
Programs prepare_programs(const Scene& scene, const RenderPlan& plan, StopMeter& meter);

/// Where a program went past its loop iteration bound: which program, the loop, the pixel (image
/// coordinates).
struct ProgramFault {
  std::int32_t shader = -1;
  std::uint32_t loop = 0;
  int x = 0, y = 0;
};

/// One thread's register files, one per program, each filled (constants, uniforms, prologue) on first use.
class ProgramThread {
 public:
  shader::Registers& registers(const Programs& programs, int index);
  std::int64_t bytes() const;  ///< allocated so far

 private:
  std::vector<std::unique_ptr<shader::Registers>> files_;
};

/// Runs program `index` over the pixels of `clip` (inside the tile and the image) that its rectangle holds
/// and writes them into `surface`; with `edges` (edge sampling's second pass) only the edge pixels. False
/// when the render must stop: the meter says so, or a pixel's loops passed their bound (`fault` filled).
bool draw_program(const Programs& programs, int index, ProgramThread& thread, const Surface& surface,
                  Rect clip, const BlockMasks* edges, StopMeter& meter, ProgramFault& fault);

}  // namespace raster::detail
