// The engine's entry points: the interpreter of engine_run.h compiled three times, and the register file.
#include "shader/engine.h"

#include <cstdlib>
#include <cstring>
#include <new>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

// Eight-lane values cross no call here, but GCC notes the ABI of every AVX function that could take one.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "shader/engine_run.h"

namespace raster::shader {
namespace {

// The reference: one float at a time, and not vectorised by the compiler either, so that it stands apart
// from the SIMD instantiations it checks.
__attribute__((optimize("no-tree-vectorize"))) RunResult run_scalar(const Instr* code, std::size_t n,
                                                                    std::uint32_t* r,
                                                                    const RunContext& context,
                                                                    run::BlockState& state) {
  using F = float;
  using namespace run;
#include "shader/engine_loop.inc"
}

RunResult run_sse2(const Instr* code, std::size_t n, std::uint32_t* r, const RunContext& context,
                   run::BlockState& state) {
  using F = FloatLanes;
  using namespace run;
#include "shader/engine_loop.inc"
}

__attribute__((target("avx2"))) RunResult run_avx2(const Instr* code, std::size_t n, std::uint32_t* r,
                                                   const RunContext& context, run::BlockState& state) {
  using F = FloatLanes;
  using namespace run;
#include "shader/engine_loop.inc"
}

RunResult dispatch(const std::vector<Instr>& code, Registers& registers, const RunContext& context,
                   run::BlockState& state) {
  if (code.empty()) return {};
  switch (context.lanes) {
    case Lanes::scalar:
      return run_scalar(code.data(), code.size(), registers.data(), context, state);
    case Lanes::avx2:
      return run_avx2(code.data(), code.size(), registers.data(), context, state);
    default:
      return run_sse2(code.data(), code.size(), registers.data(), context, state);
  }
}

void fill(std::uint32_t* slot, std::uint32_t bits) {
  for (int l = 0; l < kBlockLanes; ++l) slot[l] = bits;
}

}  // namespace

void Registers::Free::operator()(std::uint32_t* p) const {
  std::free(p);
}

Registers::Registers(std::uint32_t slots) {
  bytes_ = static_cast<std::size_t>(slots) * kBlockLanes * 4;
  void* p = std::aligned_alloc(64, bytes_ == 0 ? 64 : bytes_);
  if (!p) throw std::bad_alloc();
  std::memset(p, 0, bytes_);
  data_.reset(static_cast<std::uint32_t*>(p));
}

void prepare(const Program& program, Registers& registers, Lanes lanes) {
  for (const auto& [s, bits] : program.constants) fill(registers.slot(s), bits);
  fill(registers.slot(kExecSlot), ~0u);
  run::BlockState state;
  RunContext context;
  context.lanes = lanes;
  context.max_iterations = 0;  // a prologue has no loops: loops are never hoisted
  dispatch(program.prologue, registers, context, state);
}

RunResult run_block(const Program& program, Registers& registers, const RunContext& context) {
  fill(registers.slot(kExecSlot), ~0u);
  std::memset(registers.slot(kDiscardSlot), 0, kBlockLanes * 4);
  run::BlockState state;
  return dispatch(program.code, registers, context, state);
}

std::vector<std::uint32_t> evaluate_once(const Program& program, const std::vector<Slot>& result,
                                         std::int64_t max_iterations) {
  Registers registers(program.slots);
  prepare(program, registers, Lanes::scalar);
  RunContext context;
  context.lanes = Lanes::scalar;
  context.max_iterations = max_iterations;
  if (run_block(program, registers, context).status != RunResult::Status::done) return {};
  std::vector<std::uint32_t> value;
  for (const Slot s : result) value.push_back(registers.slot(s)[0]);
  return value;
}

std::vector<std::uint32_t> evaluate_instruction(const Instr& in, std::uint32_t a, std::uint32_t b,
                                                std::uint32_t c) {
  Registers registers(kFirstFreeSlot + 5);
  fill(registers.slot(kExecSlot), ~0u);
  const std::uint32_t values[3] = {a, b, c};
  for (Slot k = 0; k < 3; ++k) fill(registers.slot(kFirstFreeSlot + k), values[k]);
  Instr one = in;
  one.a = kFirstFreeSlot, one.b = kFirstFreeSlot + 1, one.c = kFirstFreeSlot + 2, one.d = kFirstFreeSlot + 3;
  const std::vector<Instr> code = {one};
  RunContext context;
  context.lanes = Lanes::scalar;
  run::BlockState state;
  dispatch(code, registers, context, state);
  const bool two = in.op == Op::unpack_snorm || in.op == Op::unpack_unorm || in.op == Op::unpack_half;
  std::vector<std::uint32_t> out = {registers.slot(kFirstFreeSlot + 3)[0]};
  if (two) out.push_back(registers.slot(kFirstFreeSlot + 4)[0]);
  return out;
}

}  // namespace raster::shader
