// Lower: the checked Ast -> IR (ir.h). main() with every function it calls inlined (GLSL has no
// recursion), vectors and matrices split into scalar slots (a swizzle or a transpose moves no data), control
// flow turned into mask operations. The slots it hands out are virtual; optimize.h folds, hoists and packs
// them. The same lowering evaluates constant expressions for the checker (fold_constant), so a constant
// is computed by the code that computes everything else.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "shader/check.h"
#include "shader/diagnostics.h"
#include "shader/ir.h"

namespace raster::shader {

struct LowerLimits {
  std::size_t max_instructions = 1 << 20;  ///< after inlining, before optimization
  std::size_t max_slots = 1 << 22;         ///< virtual slots handed out (before packing)
};

/// A lowered program with virtual slots: `groups` says which slots must stay contiguous (arrays and
/// vectors indexed at run time, and every variable) and where each lives in the code's numbering.
struct Lowered {
  Program program;
  std::vector<std::uint32_t> group_of;     ///< per virtual slot: its group
  std::vector<std::uint32_t> group_first;  ///< per group: its first virtual slot (slots are consecutive)
  std::vector<std::uint32_t> group_size;
  std::vector<bool> pinned;             ///< per group: lives for the whole program (inputs, uniforms...)
  std::vector<bool> single_definition;  ///< per virtual slot: written by one instruction only (a temp)
};

/// Lowers the program's main(). False (with errors) when a limit is reached.
bool lower(const Checked& checked, const LowerLimits& limits, Lowered& out, Diagnostics& diagnostics);

/// The value of a checked constant expression as slots (types.h layout); empty if it is not one.
std::vector<std::uint32_t> fold_constant(const Expr& e);

}  // namespace raster::shader
