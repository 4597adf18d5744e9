// The lowering's state, shared by its parts: slots and the program (lower.cpp), expressions
// (lower_expr.cpp), built-in functions (lower_builtin.cpp, lower_texture.cpp), statements and calls
// (lower_stmt.cpp). Private to them.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "shader/builtins.h"
#include "shader/lower.h"

namespace raster::shader {

/// A value being computed: one slot per scalar (types.h layout). Samplers have no slots: they are bound at
/// compile time, to a channel (0..3) or to nothing (-1, reads zero).
struct Value {
  Type type;
  std::vector<Slot> s;
  int channel = -1;
};

/// Where an assignment writes. Static: `slots`. Dynamic (a run-time index on the way): value slot j is
/// slot base + offsets[j] + clamp(index, 0, count - 1) * stride, `index` an int slot.
struct Place {
  Type type;
  std::vector<Slot> slots;
  bool dynamic = false;
  Slot base = 0, index = 0;
  std::uint32_t stride = 1, count = 1;
  std::vector<std::uint32_t> offsets;
};

class Lowerer {
 public:
  Lowerer(Lowered& out, const LowerLimits& limits, Diagnostics& diagnostics);
  bool program(const Checked& checked);
  /// Fold mode: lowers `e` alone; its result slots in `result`.
  bool expression_only(const Expr& e, std::vector<Slot>& result);

 private:
  // Slots and instructions (lower.cpp).
  Slot group(std::size_t n, bool pinned = false);
  Value fresh(const Type& t);
  Slot constant(std::uint32_t bits);
  Slot fconst(float f);
  Slot iconst(std::int32_t i);
  Value constant_value(const Type& t, const std::vector<std::uint32_t>& bits, bool contiguous);
  Slot emit(Op op, Slot a = 0, Slot b = 0, Slot c = 0, std::uint32_t imm = 0, std::uint8_t flags = 0);
  std::size_t emit_to(Op op, Slot d, Slot a = 0, Slot b = 0, Slot c = 0, std::uint32_t imm = 0,
                      std::uint8_t flags = 0);
  bool tick();
  void fail(SourcePos pos, std::string message);
  bool contiguous(const Value& v) const;
  Value contiguous_copy(const Value& v);
  Value stable(const Value& v);
  void bind_globals(const Checked& checked);
  Value& variable(const Variable* v);

  // Expressions (lower_expr.cpp).
  Value expr(const Expr* e);
  Value unary(const Expr* e);
  Value binary(const Expr* e);
  Value binary_values(Punct op, const Value& a, const Value& b, const Type& result);
  Value matrix_product(const Value& a, const Value& b, const Type& result);
  Value equality(const Value& a, const Value& b, bool equal);
  Value logical(const Expr* e);
  Value ternary(const Expr* e);
  Value assign(const Expr* e);
  Value step_value(const Expr* e);
  Value field(const Expr* e);
  Value index(const Expr* e);
  Value construct(const Expr* e, const Type& t);
  Value convert(const Value& v, Basic to);
  Place place(const Expr* e);
  Value read(const Place& p);
  void write(const Place& p, const Value& v);
  Value map(Op op, const Type& result, const std::vector<const Value*>& args);
  Slot component(const Value& v, int i) const;
  bool pure(const Expr* e) const;

  // Built-in functions (lower_builtin.cpp, lower_texture.cpp).
  Value builtin(const Expr* e, std::vector<Value> args);
  Value packing(BuiltinOp op, const Type& t, const Value& a);
  Value precise_mix(const Type& t, const std::vector<Value>& a);
  Value geometric(BuiltinOp op, const Type& t, const std::vector<Value>& a);
  Value matrix_builtin(BuiltinOp op, const Type& t, const std::vector<Value>& a);
  Value relational(BuiltinOp op, const Type& t, const std::vector<Value>& a);
  Value texture(BuiltinOp op, const Type& t, const std::vector<Value>& a, const Expr* e);
  Slot dot(const Value& a, const Value& b);
  Slot sum(const std::vector<Slot>& terms);

  // Statements and calls (lower_stmt.cpp).
  void statement(const Stmt* s);
  void block(const Stmt* s);
  void declaration(const Declaration* d);
  void if_statement(const Stmt* s);
  void loop(const Stmt* s);
  bool unrolled(const Stmt* s);
  void switch_statement(const Stmt* s);
  void return_statement(const Stmt* s);
  void leave(Slot accumulator);
  Value call(const Expr* e);
  std::optional<Value> constant_call(const Expr* e);
  bool reads_only_its_arguments(const Function* f);
  bool whole_local(const Place& p, std::vector<std::uint32_t>& taken);
  std::size_t patch_target() const { return out_.program.code.size(); }

  struct Frame {
    const Function* function = nullptr;
    std::unordered_map<const Variable*, Value> vars;
    Value result;               ///< where returns store (a group), or the one top-level return's value
    bool result_group = false;  ///< returns store into `result` (some return is not the last statement)
    Slot returns = 0;           ///< lanes that returned early (0: none can)
    int nesting = 0;            ///< control structures open inside this function
    bool returned = false;      ///< some lanes have returned early: later stores need the mask
    std::vector<std::uint32_t> locals;  ///< groups of its own variables (no other frame can see them)
  };
  void function_body(const FunctionDecl* f, Frame& frame);
  bool own(const Value& v, const Frame& f) const;
  bool predicable(const Stmt* s) const;
  bool predicable(const std::vector<const Stmt*>& list) const;
  bool static_place(const Expr* e) const;
  bool leave_if(const Stmt* s, Slot condition);
  void predicated_if(const Stmt* s, Slot condition);

  struct Breakable {
    Slot exit = 0;    ///< lanes that left by break
    Slot resume = 0;  ///< loops: lanes that left this iteration by continue
    bool loop = false;
  };

  Lowered& out_;
  LowerLimits limits_;
  Diagnostics& diagnostics_;
  std::vector<Frame> frames_;
  std::unordered_map<const Variable*, Value> globals_;
  std::vector<Breakable> breakables_;
  std::unordered_map<std::uint32_t, Slot> constants_;
  std::vector<bool> mutable_group_;  ///< per group: a variable's slots that assignments change
  bool uniform_ = true;  ///< exec holds every lane that will read what is stored: stores need no mask
  Slot predicate_ = 0;   ///< in a predicated if's branch: its condition, which every assignment obeys
  std::vector<Slot> step_slots_;  ///< in a loop's step: its own variables' slots, which it writes whole
  bool terminated_ = false;       ///< the current function returned on every live lane: the rest is dead
  bool failed_ = false;
  bool folding_ = false;  ///< lowering a call of constants to evaluate now (constant_call): no nesting
  std::int64_t fold_work_ = std::int64_t{1} << 20;    ///< constant_call's budget: instructions x iterations
  std::unordered_map<const Function*, bool> closed_;  ///< reads_only_its_arguments, per function
  std::size_t work_ = 0;  ///< expressions and statements lowered, against the instruction limit
};

}  // namespace raster::shader
