// The passes over runs of straight-line code (between control operations, where every instruction that
// runs runs after the one before it, for the same lanes):
//  - dead stores: a slot written whole (not under a mask) and written whole again before anything reads it
//    loses the first write (a variable's zero start, an output's, overwritten at once);
//  - copies: `d = a` where a was computed once, in this run, for this copy alone, and d is untouched since,
//    makes the computation write d (the chains of copies an assignment through an out parameter leaves);
//  - fusing (optimize.h step 5): `t = a * b` whose one reader is `d = t + c`, `d = t - c` or `d = c - t`
//    becomes one instruction computing a * b and then the add, each rounded as before, so the bits do not
//    change; what goes is a dispatch, and a slot written and read again. A shift into the xor, or or add
//    that alone reads it likewise (the steps of an integer hash).
#include "shader/optimize.h"

namespace raster::shader {
namespace {

// The fused form of `consumer` when its operand `first` (true: a, false: b) is the result of `producer`;
// Op::mov for none.
Op fused(Op producer, Op consumer, bool first) {
  switch (producer) {
    case Op::fmul:
      return consumer == Op::fadd   ? Op::fmuladd
             : consumer == Op::fsub ? (first ? Op::fmulsub : Op::fnmuladd)
                                    : Op::mov;
    case Op::imul:
      return consumer == Op::iadd ? Op::imuladd : Op::mov;
    case Op::shl:
      return consumer == Op::bxor   ? Op::shl_xor
             : consumer == Op::bor  ? Op::shl_or
             : consumer == Op::iadd ? Op::shl_add
                                    : Op::mov;
    case Op::ushr:
      return consumer == Op::bxor   ? Op::ushr_xor
             : consumer == Op::bor  ? Op::ushr_or
             : consumer == Op::iadd ? Op::ushr_add
                                    : Op::mov;
    default:
      return Op::mov;
  }
}

bool fusable(Op producer) {
  return producer == Op::fmul || producer == Op::imul || producer == Op::shl || producer == Op::ushr;
}

}  // namespace

void remove_dead_stores(Lowered& l) {
  Program& p = l.program;
  // Per slot, the instruction that last wrote it whole with no read since (-1: none in this run).
  std::vector<std::int64_t> unread(l.group_of.size(), -1);
  std::vector<std::size_t> touched;
  std::vector<bool> removed(p.code.size(), false);
  const auto read_group = [&](Slot s) {
    const std::uint32_t g = l.group_of[s];
    for (std::uint32_t k = 0; k < l.group_size[g]; ++k) unread[l.group_first[g] + k] = -1;
  };
  for (std::size_t i = 0; i < p.code.size(); ++i) {
    const Instr& in = p.code[i];
    if (ends_run(in.op)) {
      for (const std::size_t s : touched) unread[s] = -1;
      touched.clear();
      continue;
    }
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k) unread[o.reads[k]] = -1;
    if (o.reads_group) read_group(in.a);
    if (o.writes_group || in.op == Op::store ||
        in.op == Op::store_if) {  // keeps the lanes or elements it does not write: a read
      if (o.writes_group) read_group(in.d);
      unread[in.d] = -1;
      continue;
    }
    for (int k = 0; k < o.write_count; ++k) {
      const Slot s = o.writes[k];
      if (unread[s] >= 0 && o.write_count == 1) removed[static_cast<std::size_t>(unread[s])] = true;
      unread[s] = o.write_count == 1 && is_pure(in.op) ? static_cast<std::int64_t>(i) : -1;
      touched.push_back(s);
    }
  }
  p.code = compact(p.code, removed);
}

void coalesce_copies(Lowered& l, const std::vector<bool>& keep) {
  Program& p = l.program;
  const std::size_t slots = l.group_of.size();
  std::vector<int> reads(slots, 0), writes(slots, 0);
  for (const Instr& in : p.code) {
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k) ++reads[o.reads[k]];
    for (int k = 0; k < o.write_count; ++k) ++writes[o.writes[k]];
  }
  for (const Instr& in : p.prologue) {
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k) ++reads[o.reads[k]];
  }
  // In this run: where each slot was last read or written, and which instruction wrote it alone.
  std::vector<std::int64_t> touched_at(slots, -1), single_writer(slots, -1);
  std::vector<std::size_t> touched;
  std::vector<bool> removed(p.code.size(), false);
  for (std::size_t i = 0; i < p.code.size(); ++i) {
    Instr& in = p.code[i];
    if (ends_run(in.op)) {
      for (const std::size_t s : touched) touched_at[s] = single_writer[s] = -1;
      touched.clear();
      continue;
    }
    // d untouched since the computation, or read by it alone: a lane-by-lane operation reads each step's
    // operands before it writes that step's result, so it may write over what it reads (`i = i + 1`).
    if (in.op == Op::mov && single_writer[in.a] >= 0 && reads[in.a] == 1 && writes[in.a] == 1 &&
        !keep[in.a] &&
        (touched_at[in.d] < single_writer[in.a] ||
         (touched_at[in.d] == single_writer[in.a] &&
          computable(p.code[static_cast<std::size_t>(single_writer[in.a])].op)))) {
      const std::int64_t at = single_writer[in.a];
      p.code[static_cast<std::size_t>(at)].d = in.d;
      --reads[in.a], --writes[in.a];
      removed[i] = true;
      single_writer[in.d] = writes[in.d] == 1 ? at : -1;
      touched_at[in.d] = at;
      continue;
    }
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k)
      touched_at[o.reads[k]] = static_cast<std::int64_t>(i), touched.push_back(o.reads[k]);
    for (int k = 0; k < o.write_count; ++k) {
      const Slot s = o.writes[k];
      touched_at[s] = static_cast<std::int64_t>(i);
      single_writer[s] =
          o.write_count == 1 && is_pure(in.op) && !o.reads_group ? static_cast<std::int64_t>(i) : -1;
      touched.push_back(s);
    }
  }
  p.code = compact(p.code, removed);
}

void fuse_into_readers(Lowered& l) {
  Program& p = l.program;
  const std::size_t slots = l.group_of.size();
  std::vector<int> reads(slots, 0), writes(slots, 0);
  const auto count = [&](const Instr& in) {
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k) ++reads[o.reads[k]];
    for (int k = 0; k < o.write_count; ++k) ++writes[o.writes[k]];
    if (o.reads_group || o.writes_group) ++reads[in.a], ++reads[in.d];  // whole groups: never fused away
  };
  for (const Instr& in : p.code) count(in);
  for (const Instr& in : p.prologue) count(in);
  // Per slot, the instruction of this block that last wrote it (-1: none since the block began) and, for a
  // result that may be fused (a product or a shift), its instruction's index.
  std::vector<std::int64_t> written(slots, -1), product(slots, -1);
  std::vector<std::size_t> touched;
  std::vector<bool> removed(p.code.size(), false);
  for (std::size_t i = 0; i < p.code.size(); ++i) {
    Instr& in = p.code[i];
    if (ends_run(in.op) || in.op == Op::store_index) {
      for (const std::size_t s : touched) written[s] = product[s] = -1;
      touched.clear();
    }
    for (const bool first : {true, false}) {
      const Slot t = first ? in.a : in.b;
      if (product[t] < 0 || reads[t] != 1 || writes[t] != 1) continue;
      const Instr& m = p.code[static_cast<std::size_t>(product[t])];
      const Op op = fused(m.op, in.op, first);
      if (op == Op::mov) continue;
      // Its factors must still hold what the multiply read.
      if (written[m.a] > product[t] || written[m.b] > product[t]) continue;
      const Slot other = first ? in.b : in.a;
      in = Instr{.op = op, .d = in.d, .a = m.a, .b = m.b, .c = other};
      removed[static_cast<std::size_t>(product[t])] = true;
      break;
    }
    const Operands o = operands(in);
    for (int k = 0; k < o.write_count; ++k) {
      written[o.writes[k]] = static_cast<std::int64_t>(i), product[o.writes[k]] = -1;
      touched.push_back(o.writes[k]);
    }
    if (fusable(in.op) && o.write_count == 1) product[in.d] = static_cast<std::int64_t>(i);
  }
  p.code = compact(p.code, removed);
}

}  // namespace raster::shader
