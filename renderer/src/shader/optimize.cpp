#include "shader/optimize.h"

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <tuple>
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
    case Op::fmuladd:
    case Op::fmulsub:
    case Op::fnmuladd:
    case Op::imuladd:
    case Op::shl_xor:
    case Op::shl_or:
    case Op::shl_add:
    case Op::ushr_xor:
    case Op::ushr_or:
    case Op::ushr_add:
      return Arity::three;
    default:
      return op >= Op::fadd && op <= Op::pack_half ? Arity::two : Arity::other;
  }
}

bool unpacks(Op op) {
  return op == Op::unpack_snorm || op == Op::unpack_unorm || op == Op::unpack_half;
}

}  // namespace

bool computable(Op op) {
  return is_pure(op) && op != Op::ddx && op != Op::ddy && op != Op::load_index && op < Op::tex_sample;
}

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
    case Op::leave_if:
    case Op::tex_size:
      return 1;
    case Op::load_index:
      return 2;
    case Op::store_index:
    case Op::store_if:
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

std::vector<bool> whole_groups(const Lowered& l) {
  std::vector<bool> whole(l.group_first.size(), false);
  for (const Instr& in : l.program.code) {
    if (in.op == Op::load_index) whole[l.group_of[in.a]] = true;
    if (in.op == Op::store_index) whole[l.group_of[in.d]] = true;
    if (in.op == Op::tex_sample && in.flags == static_cast<std::uint8_t>(TexMode::grad))
      whole[l.group_of[in.c]] = true;
    if (in.op == Op::tex_sample || in.op == Op::tex_fetch || unpacks(in.op)) whole[l.group_of[in.d]] = true;
  }
  return whole;
}

Slot Groups::add(bool pinned) {
  const auto s = static_cast<Slot>(l.group_of.size());
  l.group_of.push_back(static_cast<std::uint32_t>(l.group_first.size()));
  l.group_first.push_back(s);
  l.group_size.push_back(1);
  l.pinned.push_back(pinned);
  l.single_definition.push_back(true);
  return s;
}

bool commutes(Op op) {
  return op == Op::fadd || op == Op::fmul || op == Op::iadd || op == Op::imul || op == Op::band ||
         op == Op::bor || op == Op::bxor || op == Op::feq || op == Op::ieq || op == Op::ine;
}

Slot identity(const Instr& in, const std::function<bool(Slot, std::uint32_t)>& is) {
  constexpr std::uint32_t kZero = 0, kOne = 0x3f800000u;
  switch (in.op) {
    case Op::fadd:
      return is(in.b, kZero) ? in.a : is(in.a, kZero) ? in.b : kUnusedSlot;
    case Op::fsub:
      return is(in.b, kZero) ? in.a : kUnusedSlot;
    case Op::fmul:
      return is(in.b, kOne)    ? in.a
             : is(in.a, kOne)  ? in.b
             : is(in.b, kZero) ? in.b
             : is(in.a, kZero) ? in.a
                               : kUnusedSlot;
    case Op::iadd:
      return is(in.b, 0) ? in.a : is(in.a, 0) ? in.b : kUnusedSlot;
    case Op::imul:
      return is(in.b, 1) ? in.a : is(in.a, 1) ? in.b : kUnusedSlot;
    default:
      return kUnusedSlot;
  }
}

namespace {

// Common subexpressions in a run of straight-line code: the same operation of the same unchanging slots
// computed twice. Keys are (op, flags, a, b, c, imm), a and b ordered for the operations that commute
// exactly.
struct Expressions {
  std::map<std::tuple<Op, std::uint8_t, Slot, Slot, Slot, std::uint32_t>, Slot> seen;
  Slot find_or_add(const Instr& in) {
    Slot a = in.a, b = in.b;
    if (commutes(in.op) && b < a) std::swap(a, b);
    const auto [it, added] = seen.try_emplace({in.op, in.flags, a, b, in.c, in.imm}, in.d);
    return added ? kUnusedSlot : it->second;
  }
};

// 1 and 2: constants folded, then values of constants and uniforms moved to the prologue; on the way,
// identities and common subexpressions of unchanging values replaced by what they equal.
// Per slot, the instructions that write it.
std::vector<int> definitions(const Lowered& l) {
  std::vector<int> defs(l.group_of.size(), 0);
  for (const Instr& in : l.program.code) {
    const Operands o = operands(in);
    for (int k = 0; k < o.write_count; ++k) ++defs[o.writes[k]];
  }
  return defs;
}

void fold_and_hoist(Lowered& l, std::vector<bool>& removed) {
  Program& p = l.program;
  Groups groups{l};
  std::vector<int> defs = definitions(l);
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
  const std::vector<bool> whole = whole_groups(l);
  Expressions expressions;
  // The result of an operation of constants becomes a constant slot (one a value), which its readers read.
  const auto fold = [&](const Instr& in, const Operands& o, std::vector<bool>::reference gone) {
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
    gone = true;
  };
  for (std::size_t i = 0; i < p.code.size(); ++i) {
    Instr& in = p.code[i];
    substitute(in);
    if (ends_run(in.op)) expressions.seen.clear();  // a new run of straight-line code
    if (!computable(in.op)) continue;
    const Operands o = operands(in);
    bool single = true, all_known = true, all_invariant = true, fixed = true;
    for (int k = 0; k < o.write_count; ++k)
      single &= defs[o.writes[k]] == 1 && !whole[groups.of(o.writes[k])];
    for (int k = 0; k < o.read_count; ++k)
      all_known &= known[o.reads[k]], all_invariant &= invariant[o.reads[k]], fixed &= defs[o.reads[k]] <= 1;
    const bool replaceable = single && fixed && o.write_count == 1;
    Slot same = replaceable ? identity(in, [&](Slot s, std::uint32_t v) { return known[s] && bits[s] == v; })
                            : kUnusedSlot;
    if (same == kUnusedSlot && single && all_known) {  // fold: a constant, which its readers read
      fold(in, o, removed[i]);
      continue;
    }
    // Not before folding: a folded instruction is gone, and its slot with it.
    if (same == kUnusedSlot && replaceable) same = expressions.find_or_add(in);
    if (same != kUnusedSlot) {
      replace[in.d] = same;
      removed[i] = true;
      continue;
    }
    if (!single || !all_invariant) continue;
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
  // Reads of each slot, of each group's slots together, and of groups as a whole (run-time indices).
  std::vector<int> slot_reads(l.group_of.size(), 0), reads(l.group_first.size(), 0),
      whole_reads(l.group_first.size(), 0);
  const auto count = [&](const Instr& in, int delta) {
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k)
      slot_reads[o.reads[k]] += delta, reads[l.group_of[o.reads[k]]] += delta;
    if (o.reads_group) whole_reads[l.group_of[in.a]] += delta;
  };
  for (std::size_t i = 0; i < p.code.size(); ++i)
    if (!removed[i]) count(p.code[i], 1);
  for (const Instr& in : p.prologue) count(in, 1);
  for (const std::uint32_t g : forced) reads[g] += 1, whole_reads[g] += 1;
  const auto dead = [&](const Instr& in) {
    if (!is_pure(in.op) && in.op != Op::store && in.op != Op::store_if && in.op != Op::store_index)
      return false;
    const Operands o = operands(in);
    for (int k = 0; k < o.write_count; ++k) {
      const Slot s = o.writes[k];
      const std::uint32_t g = l.group_of[s];
      if (o.writes_group ? reads[g] > 0 : whole_reads[g] > 0 || slot_reads[s] > 0) return false;
    }
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

}  // namespace

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

bool is_pure(Op op) {
  return op < Op::if_begin && op != Op::store && op != Op::store_if && op != Op::store_index;
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
    case Op::store_if:
      w(in.d), r(in.a), r(in.b);
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
    case Op::leave_if:
      w(in.d), r(in.a);
      break;
    default:
      break;  // loop_back
  }
  return o;
}

// Slots whose writing instruction must stay where it is: pinned ones (inputs, uniforms, constants, the
// prologue's values), the output, and groups read or written as a whole.
std::vector<bool> keep_slots(const Lowered& l) {
  const std::vector<bool> whole = whole_groups(l);
  std::vector<bool> keep(l.group_of.size(), false);
  for (Slot s = 0; s < keep.size(); ++s) {
    const std::uint32_t g = l.group_of[s];
    keep[s] = l.pinned[g] || whole[g] || (l.program.output_slots > 0 && g == l.group_of[l.program.output]);
  }
  return keep;
}

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
  number_values(l);
  remove_dead_stores(l);
  // What the dead stores read may be dead now too.
  removed.assign(p.code.size(), false), prologue_removed.assign(p.prologue.size(), false);
  remove_dead(l, removed, prologue_removed, forced);
  p.code = compact(p.code, removed);
  p.prologue = compact(p.prologue, prologue_removed);
  coalesce_copies(l, keep_slots(l));
  fuse_into_readers(l);
  mark_uniform_operands(l);
  return pack_slots(l, max_slots, out, diagnostics);
}

}  // namespace raster::shader
