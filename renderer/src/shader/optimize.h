// Optimize: a Lowered program (virtual slots) -> the Program the engine runs. In order:
//  1. fold: an operation of constants is computed now (by the engine itself, so it is the same value);
//  2. hoist: an operation of constants and uniforms moves to the prologue, run once per render and thread;
//  3. dead code: what nothing reads is dropped;
//  4. fuse: a multiply into the add or subtract that alone uses it (optimize_fuse.cpp);
//  5. pack: virtual slots get physical ones, reused once a value is dead (a loop keeps alive what crosses
//     its back-edge), each group contiguous as dynamic indexing needs.
#pragma once

#include <cstddef>

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

}  // namespace raster::shader
