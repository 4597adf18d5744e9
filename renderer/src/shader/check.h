// Check: Ast -> the same Ast with every rule of GLSL ES 3.00 applied (chapters 4 to 6): names resolved in
// their scopes, every expression typed (no implicit conversions), overloads chosen, l-values and constant
// expressions verified, control flow and recursion checked. What the lowering needs besides the tree is
// gathered in Checked.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include "shader/ast.h"
#include "shader/diagnostics.h"

namespace raster::shader {

/// The value of a constant expression (already checked and typed), as slots; empty if it cannot be
/// computed. The checker asks it for array sizes, constant initializers, case labels and constant
/// indices; the lowering provides it (fold.h), so constants are computed by the code that runs programs.
using Folder = std::function<std::vector<std::uint32_t>(const Expr&)>;

struct Checked {
  std::deque<Variable> variables;
  std::deque<Function> functions;
  std::deque<StructType> structs;
  /// Global declarations with storage, in program order (uniforms, globals with or without initializers).
  std::vector<const Declaration*> globals;
  std::vector<Variable*> uniforms;
  Function* main = nullptr;
  Variable* output = nullptr;  ///< the fragment colour (the one `out vec4`)
};

void check(Ast& ast, const Folder& fold, Checked& out, Diagnostics& diagnostics);

}  // namespace raster::shader
