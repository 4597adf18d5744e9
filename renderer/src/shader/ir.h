// IR: the program the engine runs. Every value is scalar slots (types.h's layout), and every instruction
// computes one slot of results for a whole 8x8 block at once: 64 lanes, lane 8 y + x for the block's pixel
// (x, y). Control flow is structured and runs on masks: `exec` says which lanes are live; branches narrow
// it and merge it back, loops run while any lane is live, and stores to variables keep the lanes `exec`
// excludes. Nothing traps: every operation has one defined result for every input (README's rules).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "shader/token.h"

namespace raster::shader {

using Slot = std::uint32_t;

/// Fixed slots of every program.
inline constexpr Slot kExecSlot = 0;     ///< the live lanes: all ones or zero per lane
inline constexpr Slot kDiscardSlot = 1;  ///< lanes that ran `discard`
inline constexpr Slot kFirstFreeSlot = 2;
/// A slot no instruction uses: what an unused uniform or input is given in place of a register.
inline constexpr Slot kUnusedSlot = ~Slot{0};

/// Operations, each once with the group of handlers that runs it (engine_run.h). Operands name slots unless
/// said: d the result, a b c the inputs, `imm` an immediate; masks are all ones (true) or zero.
///  - move: mov d = a; store d = exec ? a : d (an assignment under control flow); store_if d = exec & b ?
///    a : d (an assignment in an if turned into a select: the if's condition b).
///  - index: load_index d = slot(a + clamp(i, 0, imm - 1) * c), i the int lanes of b; store_index writes a
///    there where exec. Run-time indices, clamped into the array.
///  - float: IEEE arithmetic and lane_math.h's functions, a (b, c) in order: fclamp d = min(max(a, b), c);
///    fmix d = mix(a, b, c); fstep d = step(a, b); fsmoothstep d = smoothstep(a, b, c); comparisons (flt
///    to fisinf) give masks. fmuladd d = a * b + c, fmulsub d = a * b - c, fnmuladd d = c - a * b: a
///    multiply and the add that uses it in one instruction, each rounded as before (optimize.h makes them).
///  - transcendental: lane_transcendental.h's functions (fatan2 is atan(a, b)).
///  - integer: conversions (float to int or uint truncated, NaN 0, saturated; bool to 1 or 1.0), wrapping
///    arithmetic (imuladd d = a * b + c), comparisons to masks, shifts by b modulo 32, bitwise operations;
///    a shift and the xor, or or add that alone reads it (ushr_xor d = (a >> b) ^ c, shl_add d = (a << b) +
///    c, and the other four: a hash's steps);
///    select d = a ? b : c.
///  - divide: idiv, imod, udiv, umod, defined for every input (engine_run.h).
///  - lane: packing (pack d = pack(a, b); unpack d, d + 1 = unpack(a)); ddx, ddy: the difference across
///    the lane's 2x2 quad; textures: channel imm & 0xff, tex_sample's texel offset (imm >> 8 & 0xff) - 8
///    across and (imm >> 16 & 0xff) - 8 up, results d .. d + 3 (tex_size: d, d + 1): tex_sample at u a,
///    v b, level of detail from c (TexMode in `flags`), tex_fetch at integer x a, y b, level c, tex_size of
///    level a.
///  - control, on exec: if_begin d = exec, exec &= a, no live lane: jump to imm (its if_else or if_merge);
///    if_else d = exec, exec = a & ~b (a the if's saved mask, b its condition), none: jump to imm (if_end);
///    if_end exec |= a; if_merge exec |= a & ~b (an if without else); clear d = 0 (an accumulator of lanes
///    that left by break, continue or return); leave d |= exec, exec = 0; mask_or exec |= a; mask_or_and
///    exec |= a & b (a switch's case); loop_test d |= exec & ~a, exec &= a, none: jump to imm (loop_end);
///    loop_end exec = a; leave_if d |= exec & a, exec &= ~a (`if (a) break;` and the like).
///  - loop: loop_back: while a lane is live, count the iteration (of loop c) and jump to imm.
// clang-format off
#define RASTER_SHADER_OPS(X)                                                                                 \
  X(mov, move) X(store, move) X(store_if, move) X(load_index, lane) X(store_index, lane)                      \
  X(select, integer)                                                                                          \
  X(fadd, float) X(fsub, float) X(fmul, float) X(fdiv, float) X(fneg, float) X(fabs, float)                  \
  X(fsign, float) X(ffloor, float) X(fceil, float) X(ftrunc, float) X(fround, float)                         \
  X(froundeven, float) X(ffract, float) X(fmod, float) X(fmin, float) X(fmax, float) X(fclamp, float)        \
  X(fmix, float) X(fstep, float) X(fsmoothstep, float) X(fsqrt, float) X(frsqrt, float)                      \
  X(fmuladd, float) X(fmulsub, float) X(fnmuladd, float)                                                      \
  X(fsin, transcendental) X(fcos, transcendental) X(ftan, transcendental) X(fasin, transcendental)           \
  X(facos, transcendental) X(fatan, transcendental) X(fatan2, transcendental) X(fsinh, transcendental)       \
  X(fcosh, transcendental) X(ftanh, transcendental) X(fasinh, transcendental) X(facosh, transcendental)      \
  X(fatanh, transcendental) X(fexp, transcendental) X(fexp2, transcendental) X(flog, transcendental)         \
  X(flog2, transcendental) X(fpow, transcendental) X(flt, float) X(fle, float) X(fgt, float)                 \
  X(fge, float) X(feq, float) X(fne, float) X(fisnan, float) X(fisinf, float) X(f2i, integer)                \
  X(f2u, integer) X(i2f, integer) X(u2f, integer) X(b2f, integer) X(b2i, integer) X(iadd, integer)           \
  X(isub, integer) X(imul, integer) X(idiv, divide) X(imod, divide) X(ineg, integer) X(iabs, integer)        \
  X(isign, integer) X(imin, integer) X(imax, integer) X(iclamp, integer) X(udiv, divide)                     \
  X(umod, divide) X(umin, integer) X(umax, integer) X(uclamp, integer) X(ilt, integer) X(ile, integer)       \
  X(igt, integer) X(ige, integer) X(ieq, integer) X(ine, integer) X(ult, integer) X(ule, integer)            \
  X(ugt, integer) X(uge, integer) X(shl, integer) X(shr, integer) X(ushr, integer) X(band, integer)          \
  X(bor, integer) X(bxor, integer) X(bnot, integer) X(imuladd, integer) X(shl_xor, integer)                  \
  X(shl_or, integer) X(shl_add, integer) X(ushr_xor, integer) X(ushr_or, integer) X(ushr_add, integer)       \
  X(pack_snorm, lane)                                                                                         \
  X(pack_unorm, lane)                                                                                         \
  X(pack_half, lane) X(unpack_snorm, lane) X(unpack_unorm, lane) X(unpack_half, lane) X(ddx, lane)           \
  X(ddy, lane) X(tex_sample, lane) X(tex_fetch, lane) X(tex_size, lane) X(if_begin, control)                 \
  X(if_else, control) X(if_end, control) X(if_merge, control) X(clear, control) X(leave, control)            \
  X(mask_or, control) X(mask_or_and, control) X(loop_test, control) X(loop_back, loop)                       \
  X(loop_end, control) X(leave_if, control)
// clang-format on

enum class Op : std::uint8_t {
#define RASTER_SHADER_ENUM(name, group) name,
  RASTER_SHADER_OPS(RASTER_SHADER_ENUM)
#undef RASTER_SHADER_ENUM
};

/// How tex_sample finds its level of detail.
enum class TexMode : std::uint8_t {
  implicit,  ///< from the quad's coordinate differences (texture, textureProj, textureOffset)
  bias,      ///< implicit plus c
  lod,       ///< c
  grad,      ///< from the gradients in slots c .. c + 3 (dx u, dx v, dy u, dy v)
};

struct Instr {
  Op op = Op::mov;
  std::uint8_t flags = 0;  ///< tex_sample: TexMode
  /// Which operands hold one value in all 64 lanes (a constant, a uniform, a prologue value): bit 0 b, bit
  /// 1 c. Set for float and integer operations only, by the optimizer (which puts such an operand second
  /// where the operation commutes); the engine then reads it once instead of once a step.
  std::uint8_t uniform = 0;
  std::uint8_t spare = 0;
  Slot d = 0, a = 0, b = 0, c = 0;
  std::uint32_t imm = 0;
};

/// A uniform the request sets by name, and where its slots are.
struct UniformSlots {
  std::string name;
  Slot first = 0;
  int slots = 0;           ///< its scalar slots (types.h layout)
  std::string type;        ///< its GLSL type, for messages
  std::uint8_t basic = 0;  ///< types.h Basic of its scalars
};

/// A loop of the program, for the error that names one.
struct LoopInfo {
  SourcePos pos;
};

struct Program {
  std::vector<Instr> code;      ///< run for every block
  std::vector<Instr> prologue;  ///< run once per register file, before any block: values of uniforms alone
  std::vector<std::pair<Slot, std::uint32_t>> constants;  ///< slots filled once with these bits
  std::vector<UniformSlots> uniforms;
  std::vector<LoopInfo> loops;
  Slot frag_coord = 0;  ///< 4 slots: x, y (GL's: origin bottom left, pixel centres at .5), z, w
  Slot front_facing = 0;
  Slot point_coord = 0;  ///< 2 slots
  Slot output = 0;       ///< the fragment colour, `output_slots` slots
  int output_slots = 0;
  std::uint32_t slots = kFirstFreeSlot;  ///< the register file: slots x 64 lanes x 4 bytes
  bool derivatives = false;        ///< uses ddx/ddy or implicit texture levels (so blocks need whole quads)
  std::uint8_t channels_read = 0;  ///< bit n: iChannel n is sampled
};

std::string_view op_name(Op op);
/// Whether the engine has a handler for each value of Instr::uniform (float and integer operations).
bool has_uniform_handlers(Op op);
/// The program as text, one instruction a line (tests and `--explain` read it).
std::string dump(const Program& p);

}  // namespace raster::shader
