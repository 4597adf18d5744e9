// Optimize: a Lowered program (virtual slots) -> the Program the engine runs. In order:
//  1. fold: an operation of constants is computed now (by the engine itself, so it is the same value);
//  2. hoist: an operation of constants and uniforms moves to the prologue, run once per render and thread;
//  3. dead code: what nothing reads is dropped;
//  4. values: through slots written many times, in runs of straight-line code, constants folded, copies
//     and repeated operations read from where their value already is (optimize_values.cpp), and dead
//     code dropped again;
//  5. fuse: a multiply into the add or subtract that alone uses it, a shift into its xor, or or add
//     (optimize_fuse.cpp);
//  6. uniform operands: those that hold one value in every lane are marked, for the engine to read once
//     (optimize_uniform.cpp);
//  7. pack: virtual slots get physical ones, reused once a value is dead (a loop keeps alive what crosses
//     its back-edge), each group contiguous as dynamic indexing needs.
#pragma once

#include <cstddef>
#include <functional>

#include "shader/diagnostics.h"
#include "shader/lower.h"

namespace raster::shader {

/// Optimizes `lowered` into `out`. False (with an error) when the packed program needs more than
/// `max_slots` slots.
bool optimize(Lowered& lowered, std::size_t max_slots, Program& out, Diagnostics& diagnostics);

/// Which slots an instruction reads and writes, for passes that follow data through the code.
struct Operands {
  Slot reads[8];
  Slot writes[4];
  int read_count = 0, write_count = 0;
  bool reads_group = false;   ///< load_index: reads any slot of a's group
  bool writes_group = false;  ///< store_index: writes any slot of d's group
};
Operands operands(const Instr& in);

/// Whether an instruction only computes its result from its operands (no mask, no jump, no side effect).
bool is_pure(Op op);

/// The code without the `removed` instructions, every jump moved to its target's new place.
std::vector<Instr> compact(const std::vector<Instr>& code, const std::vector<bool>& removed);

// What the passes share (optimize.cpp), and the passes of the other files.

/// Whether an instruction ends a run of straight-line code: the control operations, which change masks and
/// jump.
inline bool ends_run(Op op) {
  return op >= Op::if_begin;
}
/// Folded and hoisted: a pure operation of its operands' values alone (not of other lanes, not a texture).
bool computable(Op op);
/// Which of a, b, c (bits 0, 1, 2) an instruction reads as single slots (not a group's base).
unsigned read_fields(const Instr& in);
/// Groups whose slots are read or written together, not one by one: arrays indexed at run time, texture
/// gradients, and the results of instructions that write several slots.
std::vector<bool> whole_groups(const Lowered& l);
/// Whether a op b is b op a, bit for bit.
bool commutes(Op op);
/// NIR's identities, which llvmpipe applies too: x + 0 and x - 0 are x, x * 1 is x, x * 0 is 0 (for every
/// x: Mesa's rule, followed so the bits agree). The slot the result equals, or kUnusedSlot; `is(s, bits)`
/// says whether slot s holds the constant `bits`.
Slot identity(const Instr& in, const std::function<bool(Slot, std::uint32_t)>& is);

/// New slots of one, each its own group.
struct Groups {
  Lowered& l;
  std::uint32_t of(Slot s) const { return l.group_of[s]; }
  Slot add(bool pinned);
};

void number_values(Lowered& l);       // optimize_values.cpp
void remove_dead_stores(Lowered& l);  // optimize_fuse.cpp
void coalesce_copies(Lowered& l, const std::vector<bool>& keep);
void fuse_into_readers(Lowered& l);
void mark_uniform_operands(Lowered& l);  // optimize_uniform.cpp
bool pack_slots(Lowered& l, std::size_t max_slots, Program& out,
                Diagnostics& diagnostics);  // optimize_pack.cpp

}  // namespace raster::shader
