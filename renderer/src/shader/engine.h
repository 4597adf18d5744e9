// Engine: runs a Program (ir.h) over 8x8 blocks. Every instruction's handler is written once over a lane
// type and compiled three times: one float at a time (the reference), eight in SSE2 registers, eight in
// AVX2 registers; all three give the same bits, because every operation is IEEE-exact or built from
// exact ones (lane_math.h) and nothing is fused or approximated.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "base/mip_chain.h"
#include "base/stop.h"
#include "shader/ir.h"

namespace raster::shader {

inline constexpr int kBlockLanes = 64;  ///< lane 8 y + x is the block's pixel (x, y), y counted downward

enum class Lanes : std::uint8_t { scalar, sse2, avx2 };

/// A program's slots for one thread: slots x 64 lanes of 32 bits, 32-byte aligned, constants and the
/// prologue's values filled once (prepare()), the rest rewritten by each block.
class Registers {
 public:
  explicit Registers(std::uint32_t slots);
  std::uint32_t* slot(Slot s) { return data_.get() + static_cast<std::size_t>(s) * kBlockLanes; }
  const std::uint32_t* slot(Slot s) const { return data_.get() + static_cast<std::size_t>(s) * kBlockLanes; }
  std::uint32_t* data() { return data_.get(); }
  std::size_t bytes() const { return bytes_; }

 private:
  struct Free {
    void operator()(std::uint32_t* p) const;
  };
  std::unique_ptr<std::uint32_t[], Free> data_;
  std::size_t bytes_ = 0;
};

/// An image a program samples: a channel's mip levels, rows from the image's top (level 0 first).
struct ChannelImage {
  std::vector<detail::MipLevel> levels;
};

/// What a block's run needs besides its registers.
struct RunContext {
  const ChannelImage* channels[4] = {nullptr, nullptr, nullptr, nullptr};
  std::int64_t max_iterations = 0;     ///< per lane, every loop together
  detail::StopMeter* meter = nullptr;  ///< asked at loop back-edges; null: never stops
  Lanes lanes = Lanes::sse2;
};

struct RunResult {
  enum class Status : std::uint8_t { done, stopped, iterations };
  Status status = Status::done;
  std::uint32_t loop = 0;  ///< iterations: the loop (Program::loops) whose back-edge passed the limit
  int lane = 0;            ///< iterations: the first lane past it
};

/// Fills the constants, then runs the prologue (uniforms must be written first).
void prepare(const Program& program, Registers& registers, Lanes lanes);

/// Runs the program for one block whose inputs (gl_FragCoord...) are in place.
RunResult run_block(const Program& program, Registers& registers, const RunContext& context);

/// A pure instruction (optimize.h: is_pure) on constant operands, as the scalar reference computes it: the
/// values of its result slots (two for the unpack operations, else one).
std::vector<std::uint32_t> evaluate_instruction(const Instr& in, std::uint32_t a, std::uint32_t b,
                                                std::uint32_t c);

/// Runs a program without inputs once (the scalar reference) and returns lane 0 of `result`'s slots: the
/// value of a constant expression, or of a call of constants; empty if its loops went round more than
/// `max_iterations` times.
std::vector<std::uint32_t> evaluate_once(const Program& program, const std::vector<Slot>& result,
                                         std::int64_t max_iterations = 1);

}  // namespace raster::shader
