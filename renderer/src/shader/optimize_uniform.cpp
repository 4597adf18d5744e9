// Operands that hold one value in every lane (optimize.h step 6): constants, uniforms and what the prologue
// computes from them. A float or integer operation marks them (Instr::uniform), putting such an operand
// second where the operation allows it (commuted, or a comparison mirrored), so that the engine reads it
// once instead of once every step of the block's lanes; for an interpreter whose instructions read and
// write memory, a third of a binary operation's loads.
#include "shader/optimize.h"

namespace raster::shader {
namespace {

// The comparison that gives the same mask with its operands swapped; Op::mov for none.
Op mirrored(Op op) {
  switch (op) {
    case Op::flt:
      return Op::fgt;
    case Op::fgt:
      return Op::flt;
    case Op::fle:
      return Op::fge;
    case Op::fge:
      return Op::fle;
    case Op::ilt:
      return Op::igt;
    case Op::igt:
      return Op::ilt;
    case Op::ile:
      return Op::ige;
    case Op::ige:
      return Op::ile;
    case Op::ult:
      return Op::ugt;
    case Op::ugt:
      return Op::ult;
    case Op::ule:
      return Op::uge;
    case Op::uge:
      return Op::ule;
    default:
      return Op::mov;
  }
}

// a * b (+ c): the product's factors commute.
bool multiplies_first(Op op) {
  return op == Op::fmuladd || op == Op::fmulsub || op == Op::fnmuladd || op == Op::imuladd;
}

}  // namespace

void mark_uniform_operands(Lowered& l) {
  Program& p = l.program;
  std::vector<bool> uniform(l.group_of.size(), false);
  for (const auto& [s, bits] : p.constants) uniform[s] = true;
  for (const UniformSlots& u : p.uniforms)
    for (int k = 0; k < u.slots; ++k)
      if (u.first != kUnusedSlot) uniform[u.first + static_cast<Slot>(k)] = true;
  for (const Instr& in : p.prologue) {
    const Operands o = operands(in);
    for (int k = 0; k < o.write_count; ++k) uniform[o.writes[k]] = true;
  }
  for (Instr& in : p.code) {
    if (!has_uniform_handlers(in.op)) continue;
    const unsigned fields = read_fields(in);
    if (!(fields & 2)) continue;  // reads a alone
    if (uniform[in.a] && !uniform[in.b]) {
      if (commutes(in.op) || multiplies_first(in.op)) {
        std::swap(in.a, in.b);
      } else if (const Op m = mirrored(in.op); m != Op::mov) {
        std::swap(in.a, in.b);
        in.op = m;
      }
    }
    in.uniform =
        static_cast<std::uint8_t>((uniform[in.b] ? 1u : 0u) | ((fields & 4) && uniform[in.c] ? 2u : 0u));
  }
}

}  // namespace raster::shader
