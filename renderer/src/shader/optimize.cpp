#include "shader/optimize.h"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "shader/engine.h"

namespace raster::shader {
namespace {

enum class Arity : std::uint8_t { other, one, two, three };

Arity arity(Op op) {
  switch (op) {
    case Op::mov:
    case Op::fneg:
    case Op::fabs:
    case Op::fsign:
    case Op::ffloor:
    case Op::fceil:
    case Op::ftrunc:
    case Op::fround:
    case Op::froundeven:
    case Op::ffract:
    case Op::fsqrt:
    case Op::frsqrt:
    case Op::fsin:
    case Op::fcos:
    case Op::ftan:
    case Op::fasin:
    case Op::facos:
    case Op::fatan:
    case Op::fsinh:
    case Op::fcosh:
    case Op::ftanh:
    case Op::fasinh:
    case Op::facosh:
    case Op::fatanh:
    case Op::fexp:
    case Op::fexp2:
    case Op::flog:
    case Op::flog2:
    case Op::fisnan:
    case Op::fisinf:
    case Op::f2i:
    case Op::f2u:
    case Op::i2f:
    case Op::u2f:
    case Op::b2f:
    case Op::b2i:
    case Op::ineg:
    case Op::iabs:
    case Op::isign:
    case Op::bnot:
    case Op::ddx:
    case Op::ddy:
    case Op::unpack_snorm:
    case Op::unpack_unorm:
    case Op::unpack_half:
      return Arity::one;
    case Op::select:
    case Op::fclamp:
    case Op::fmix:
    case Op::fsmoothstep:
    case Op::iclamp:
    case Op::uclamp:
      return Arity::three;
    default:
      return op >= Op::fadd && op <= Op::pack_half ? Arity::two : Arity::other;
  }
}

bool unpacks(Op op) {
  return op == Op::unpack_snorm || op == Op::unpack_unorm || op == Op::unpack_half;
}

// Folded and hoisted: a pure operation of its operands' values alone (not of other lanes, not a texture).
bool computable(Op op) {
  return is_pure(op) && op != Op::ddx && op != Op::ddy && op != Op::load_index && op < Op::tex_sample;
}

// Which of a, b, c (bits 0, 1, 2) an instruction reads as single slots (not a group's base).
unsigned read_fields(const Instr& in) {
  switch (arity(in.op)) {
    case Arity::one:
      return 1;
    case Arity::two:
      return 3;
    case Arity::three:
      return 7;
    default:
      break;
  }
  switch (in.op) {
    case Op::store:
    case Op::if_begin:
    case Op::if_end:
    case Op::mask_or:
    case Op::loop_end:
    case Op::loop_test:
    case Op::tex_size:
      return 1;
    case Op::load_index:
      return 2;
    case Op::store_index:
    case Op::if_else:
    case Op::if_merge:
    case Op::mask_or_and:
      return 3;
    case Op::tex_fetch:
      return 7;
    case Op::tex_sample:
      return in.flags == static_cast<std::uint8_t>(TexMode::lod) ||
                     in.flags == static_cast<std::uint8_t>(TexMode::bias)
                 ? 7
                 : 3;
    default:
      return 0;
  }
}

struct Groups {
  Lowered& l;
  std::uint32_t of(Slot s) const { return l.group_of[s]; }
  Slot add(bool pinned) {
    const auto s = static_cast<Slot>(l.group_of.size());
    l.group_of.push_back(static_cast<std::uint32_t>(l.group_first.size()));
    l.group_first.push_back(s);
    l.group_size.push_back(1);
    l.pinned.push_back(pinned);
    l.single_definition.push_back(true);
    return s;
  }
};

// 1 and 2: constants folded, then values of constants and uniforms moved to the prologue.
void fold_and_hoist(Lowered& l, std::vector<bool>& removed) {
  Program& p = l.program;
  Groups groups{l};
  std::vector<int> defs(l.group_of.size(), 0);
  for (const Instr& in : p.code) {
    const Operands o = operands(in);
    for (int k = 0; k < o.write_count; ++k) ++defs[o.writes[k]];
  }
  std::vector<bool> known(l.group_of.size(), false), invariant(l.group_of.size(), false);
  std::vector<std::uint32_t> bits(l.group_of.size(), 0);
  std::unordered_map<std::uint32_t, Slot> canonical;
  for (const auto& [s, b] : p.constants) {
    known[s] = invariant[s] = true, bits[s] = b;
    if (l.group_size[groups.of(s)] == 1) canonical.emplace(b, s);
  }
  for (const UniformSlots& u : p.uniforms)
    for (int k = 0; k < u.slots; ++k) invariant[u.first + static_cast<Slot>(k)] = true;
  std::vector<Slot> replace(l.group_of.size());
  for (Slot s = 0; s < replace.size(); ++s) replace[s] = s;
  const auto substitute = [&](Instr& in) {
    const unsigned fields = read_fields(in);
    if (fields & 1) in.a = replace[in.a];
    if (fields & 2) in.b = replace[in.b];
    if (fields & 4) in.c = replace[in.c];
  };
  // Slots read or written as a whole group (run-time indices, texture gradients) keep their instructions.
  std::vector<bool> whole(l.group_first.size(), false);
  for (const Instr& in : p.code) {
    if (in.op == Op::load_index) whole[groups.of(in.a)] = true;
    if (in.op == Op::store_index) whole[groups.of(in.d)] = true;
    if (in.op == Op::tex_sample && in.flags == static_cast<std::uint8_t>(TexMode::grad))
      whole[groups.of(in.c)] = true;
  }
  for (std::size_t i = 0; i < p.code.size(); ++i) {
    Instr& in = p.code[i];
    substitute(in);
    if (!computable(in.op)) continue;
    const Operands o = operands(in);
    bool single = true, all_known = true, all_invariant = true;
    for (int k = 0; k < o.write_count; ++k)
      single &= defs[o.writes[k]] == 1 && !whole[groups.of(o.writes[k])];
    for (int k = 0; k < o.read_count; ++k)
      all_known &= known[o.reads[k]], all_invariant &= invariant[o.reads[k]];
    if (!single || !all_invariant) continue;
    if (all_known) {  // fold: the result becomes a constant, and its readers read the constant
      const std::vector<std::uint32_t> v = evaluate_instruction(in, bits[in.a], bits[in.b], bits[in.c]);
      for (int k = 0; k < o.write_count; ++k) {
        auto it = canonical.find(v[static_cast<std::size_t>(k)]);
        if (it == canonical.end()) {
          const Slot c = groups.add(true);
          defs.push_back(0), known.push_back(true), invariant.push_back(true),
              bits.push_back(v[static_cast<std::size_t>(k)]);
          replace.push_back(c);
          p.constants.emplace_back(c, v[static_cast<std::size_t>(k)]);
          it = canonical.emplace(v[static_cast<std::size_t>(k)], c).first;
        }
        replace[o.writes[k]] = it->second;
      }
      removed[i] = true;
      continue;
    }
    // hoist: computed once per render, its result never overwritten by a block.
    p.prologue.push_back(in);
    removed[i] = true;
    for (int k = 0; k < o.write_count; ++k) {
      invariant[o.writes[k]] = true;
      l.pinned[groups.of(o.writes[k])] = true;
    }
  }
  for (Instr& in : p.prologue) substitute(in);
}

// 3: instructions whose results nothing reads (stores to variables nobody reads included), repeatedly.
void remove_dead(Lowered& l, std::vector<bool>& removed, std::vector<bool>& prologue_removed,
                 const std::vector<std::uint32_t>& forced) {
  Program& p = l.program;
  std::vector<int> reads(l.group_first.size(), 0);
  const auto count = [&](const Instr& in, int delta) {
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k) reads[l.group_of[o.reads[k]]] += delta;
  };
  for (std::size_t i = 0; i < p.code.size(); ++i)
    if (!removed[i]) count(p.code[i], 1);
  for (const Instr& in : p.prologue) count(in, 1);
  for (const std::uint32_t g : forced) reads[g] += 1;
  const auto dead = [&](const Instr& in) {
    if (!is_pure(in.op) && in.op != Op::store && in.op != Op::store_index) return false;
    const Operands o = operands(in);
    for (int k = 0; k < o.write_count; ++k)
      if (reads[l.group_of[o.writes[k]]] > 0) return false;
    return o.write_count > 0;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = p.code.size(); i-- > 0;)
      if (!removed[i] && dead(p.code[i])) removed[i] = true, count(p.code[i], -1), changed = true;
    for (std::size_t i = p.prologue.size(); i-- > 0;)
      if (!prologue_removed[i] && dead(p.prologue[i]))
        prologue_removed[i] = true, count(p.prologue[i], -1), changed = true;
  }
}

// The code without removed instructions, jumps moved to their targets' new places.
std::vector<Instr> compact(const std::vector<Instr>& code, const std::vector<bool>& removed) {
  std::vector<std::uint32_t> position(code.size() + 1, 0);
  std::uint32_t kept = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    position[i] = kept;
    if (!removed[i]) ++kept;
  }
  position[code.size()] = kept;
  std::vector<Instr> out;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (removed[i]) continue;
    Instr in = code[i];
    if (in.op == Op::if_begin || in.op == Op::if_else || in.op == Op::loop_test || in.op == Op::loop_back)
      in.imm = position[in.imm];
    out.push_back(in);
  }
  return out;
}

}  // namespace

bool is_pure(Op op) {
  return op < Op::if_begin && op != Op::store && op != Op::store_index;
}

Operands operands(const Instr& in) {
  Operands o;
  const auto r = [&](Slot s) { o.reads[o.read_count++] = s; };
  const auto w = [&](Slot s) { o.writes[o.write_count++] = s; };
  switch (arity(in.op)) {
    case Arity::one:
      w(in.d), r(in.a);
      if (unpacks(in.op)) w(in.d + 1);
      return o;
    case Arity::two:
      w(in.d), r(in.a), r(in.b);
      return o;
    case Arity::three:
      w(in.d), r(in.a), r(in.b), r(in.c);
      return o;
    default:
      break;
  }
  switch (in.op) {
    case Op::store:
      w(in.d), r(in.a);
      break;
    case Op::load_index:
      w(in.d), r(in.a), r(in.b), o.reads_group = true;
      break;
    case Op::store_index:
      w(in.d), r(in.a), r(in.b), o.writes_group = true;
      break;
    case Op::tex_sample:
      for (Slot k = 0; k < 4; ++k) w(in.d + k);
      r(in.a), r(in.b);
      if (in.flags == static_cast<std::uint8_t>(TexMode::lod) ||
          in.flags == static_cast<std::uint8_t>(TexMode::bias))
        r(in.c);
      if (in.flags == static_cast<std::uint8_t>(TexMode::grad))
        for (Slot k = 0; k < 4; ++k) r(in.c + k);
      break;
    case Op::tex_fetch:
      for (Slot k = 0; k < 4; ++k) w(in.d + k);
      r(in.a), r(in.b), r(in.c);
      break;
    case Op::tex_size:
      w(in.d), w(in.d + 1), r(in.a);
      break;
    case Op::if_begin:
      w(in.d), r(in.a);
      break;
    case Op::if_else:
      w(in.d), r(in.a), r(in.b);
      break;
    case Op::if_end:
    case Op::mask_or:
    case Op::loop_end:
      r(in.a);
      break;
    case Op::if_merge:
    case Op::mask_or_and:
      r(in.a), r(in.b);
      break;
    case Op::clear:
    case Op::leave:
      w(in.d);
      break;
    case Op::loop_test:
      w(in.d), r(in.a);
      break;
    default:
      break;  // loop_back
  }
  return o;
}

bool pack_slots(Lowered& l, std::size_t max_slots, Program& out, Diagnostics& diagnostics);

bool optimize(Lowered& l, std::size_t max_slots, Program& out, Diagnostics& diagnostics) {
  Program& p = l.program;
  std::vector<bool> removed(p.code.size(), false);
  fold_and_hoist(l, removed);
  std::vector<bool> prologue_removed(p.prologue.size(), false);
  std::vector<std::uint32_t> forced = {l.group_of[kExecSlot], l.group_of[kDiscardSlot]};
  if (p.output_slots > 0) forced.push_back(l.group_of[p.output]);
  remove_dead(l, removed, prologue_removed, forced);
  p.code = compact(p.code, removed);
  p.prologue = compact(p.prologue, prologue_removed);
  return pack_slots(l, max_slots, out, diagnostics);
}

}  // namespace raster::shader
