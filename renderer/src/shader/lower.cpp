// The lowering's slots, instructions and driver.
#include <bit>

#include "shader/engine.h"
#include "shader/lowerer.h"

namespace raster::shader {

bool lower(const Checked& checked, const LowerLimits& limits, Lowered& out, Diagnostics& diagnostics) {
  return Lowerer(out, limits, diagnostics).program(checked);
}

std::vector<std::uint32_t> fold_constant(const Expr& e) {
  if (!e.constant || e.type.is_error() || e.type.has_sampler()) return {};
  Lowered lowered;
  Diagnostics quiet;
  std::vector<Slot> result;
  if (!Lowerer(lowered, {}, quiet).expression_only(e, result)) return {};
  return evaluate_once(lowered.program, result);
}

Lowerer::Lowerer(Lowered& out, const LowerLimits& limits, Diagnostics& diagnostics)
    : out_(out), limits_(limits), diagnostics_(diagnostics) {
  group(1, true);  // kExecSlot
  group(1, true);  // kDiscardSlot
}

void Lowerer::fail(SourcePos pos, std::string message) {
  if (!failed_) diagnostics_.error(pos, std::move(message));
  failed_ = true;
}

bool Lowerer::tick() {
  if (failed_) return false;
  if (++work_ <= limits_.max_instructions) return true;
  fail({}, std::string("the program is too large: more than ") + std::to_string(limits_.max_instructions) +
               " operations once its functions are inlined");
  return false;
}

Slot Lowerer::group(std::size_t n, bool pinned) {
  const auto first = static_cast<Slot>(out_.group_of.size());
  if (first + n > limits_.max_slots) {
    fail({}, std::string("the program needs more than ") + std::to_string(limits_.max_slots) + " values");
    n = 1;
  }
  const auto g = static_cast<std::uint32_t>(out_.group_first.size());
  out_.group_first.push_back(first);
  out_.group_size.push_back(static_cast<std::uint32_t>(n));
  out_.pinned.push_back(pinned);
  mutable_group_.push_back(false);
  for (std::size_t i = 0; i < n; ++i) {
    out_.group_of.push_back(g);
    out_.single_definition.push_back(true);
  }
  return first;
}

Value Lowerer::fresh(const Type& t) {
  Value v;
  v.type = t;
  const int n = t.slots();
  if (n == 0) return v;
  const Slot first = group(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v.s.push_back(first + static_cast<Slot>(i));
  return v;
}

Slot Lowerer::constant(std::uint32_t bits) {
  const auto it = constants_.find(bits);
  if (it != constants_.end()) return it->second;
  const Slot s = group(1, true);
  out_.program.constants.emplace_back(s, bits);
  constants_[bits] = s;
  return s;
}

Slot Lowerer::fconst(float f) {
  return constant(std::bit_cast<std::uint32_t>(f));
}

Slot Lowerer::iconst(std::int32_t i) {
  return constant(static_cast<std::uint32_t>(i));
}

// A constant of type t; `contiguous` (an array indexed at run time) gives it a group of its own.
Value Lowerer::constant_value(const Type& t, const std::vector<std::uint32_t>& bits, bool contiguous) {
  Value v;
  v.type = t;
  if (contiguous && bits.size() > 1) {
    const Slot first = group(bits.size(), true);
    for (std::size_t i = 0; i < bits.size(); ++i) {
      out_.program.constants.emplace_back(first + static_cast<Slot>(i), bits[i]);
      v.s.push_back(first + static_cast<Slot>(i));
    }
    return v;
  }
  for (const std::uint32_t b : bits) v.s.push_back(constant(b));
  return v;
}

std::size_t Lowerer::emit_to(Op op, Slot d, Slot a, Slot b, Slot c, std::uint32_t imm, std::uint8_t flags) {
  std::vector<Instr>& code = out_.program.code;
  if (failed_) return code.size();
  if (code.size() >= limits_.max_instructions) {
    fail({}, std::string("the program is too large: more than ") + std::to_string(limits_.max_instructions) +
                 " instructions once its functions are inlined");
    return code.size();
  }
  Instr in;
  in.op = op, in.flags = flags, in.d = d, in.a = a, in.b = b, in.c = c, in.imm = imm;
  code.push_back(in);
  return code.size() - 1;
}

Slot Lowerer::emit(Op op, Slot a, Slot b, Slot c, std::uint32_t imm, std::uint8_t flags) {
  const Slot d = group(1);
  emit_to(op, d, a, b, c, imm, flags);
  return d;
}

bool Lowerer::contiguous(const Value& v) const {
  if (v.s.empty()) return true;
  const std::uint32_t g = out_.group_of[v.s[0]];
  for (std::size_t i = 0; i < v.s.size(); ++i)
    if (v.s[i] != v.s[0] + i || out_.group_of[v.s[i]] != g) return false;
  return true;
}

Value Lowerer::contiguous_copy(const Value& v) {
  Value c = fresh(v.type);
  for (std::size_t i = 0; i < v.s.size(); ++i) emit_to(Op::mov, c.s[i], v.s[i]);
  return c;
}

// `v` as a value that nothing will change while it is used: v itself unless a slot of it belongs to a
// variable that is assigned (then a copy).
Value Lowerer::stable(const Value& v) {
  for (const Slot s : v.s)
    if (mutable_group_[out_.group_of[s]]) return contiguous_copy(v);
  return v;
}

Value& Lowerer::variable(const Variable* v) {
  if (!frames_.empty()) {
    const auto it = frames_.back().vars.find(v);
    if (it != frames_.back().vars.end()) return it->second;
  }
  const auto it = globals_.find(v);
  if (it != globals_.end()) return it->second;
  // A constant met first here (a built-in constant, or a local constant in fold mode).
  if (!v->constant) fail(v->pos, std::string("'") + quote(v->name) + "' has no value here");
  return globals_[v] = constant_value(v->type, v->value, v->type.is_array());
}

// Inputs, uniforms and globals: slots of their own for the whole program; globals start every block
// with their initial values (constant expressions).
void Lowerer::bind_globals(const Checked& checked) {
  Program& p = out_.program;
  for (const Variable& v : checked.variables) {
    Value value;
    value.type = v.type;
    switch (v.kind) {
      case Variable::Kind::frag_coord:
        value.s = {0, 1, 2, 3}, p.frag_coord = group(4, true);
        break;
      case Variable::Kind::front_facing:
        value.s = {0}, p.front_facing = group(1, true);
        break;
      case Variable::Kind::point_coord:
        value.s = {0, 1}, p.point_coord = group(2, true);
        break;
      default:
        continue;
    }
    const Slot first = v.kind == Variable::Kind::frag_coord     ? p.frag_coord
                       : v.kind == Variable::Kind::front_facing ? p.front_facing
                                                                : p.point_coord;
    for (Slot& s : value.s) s += first;
    globals_[&v] = value;
  }
  for (Variable* v : checked.uniforms) {
    Value value;
    value.type = v->type, value.channel = v->channel;
    const int n = v->type.slots();
    if (n > 0) {
      const Slot first = group(static_cast<std::size_t>(n), true);
      for (int i = 0; i < n; ++i) value.s.push_back(first + static_cast<Slot>(i));
      p.uniforms.push_back(
          {std::string(v->name), first, n, type_name(v->type), static_cast<std::uint8_t>(v->type.basic)});
    }
    globals_[v] = value;
  }
  for (const Declaration* d : checked.globals)
    for (const Declarator& dv : d->vars) {
      const Variable* v = dv.variable;
      if (!v || v->kind == Variable::Kind::uniform) continue;
      std::vector<std::uint32_t> init(static_cast<std::size_t>(v->type.slots()), 0u);
      if (dv.init) init = v->constant ? v->value : fold_constant(*dv.init);
      if (init.size() != static_cast<std::size_t>(v->type.slots())) init.assign(init.size(), 0u);
      if (!v->written && v->kind != Variable::Kind::output) {
        globals_[v] = constant_value(v->type, init, v->type.is_array());
        continue;
      }
      Value value = fresh(v->type);
      mutable_group_[out_.group_of[value.s[0]]] = true;
      for (std::size_t i = 0; i < value.s.size(); ++i) emit_to(Op::mov, value.s[i], constant(init[i]));
      globals_[v] = value;
    }
}

bool Lowerer::program(const Checked& checked) {
  bind_globals(checked);
  if (!checked.main || !checked.main->definition) {
    fail({}, "the shader has no main()");
    return false;
  }
  Frame frame;
  frame.function = checked.main;
  function_body(checked.main->definition, frame);
  Program& p = out_.program;
  if (checked.output) {
    const Value& o = globals_.at(checked.output);
    p.output = o.s.empty() ? 0 : o.s[0];
    p.output_slots = static_cast<int>(o.s.size());
  }
  p.slots = static_cast<std::uint32_t>(out_.group_of.size());
  return !failed_;
}

bool Lowerer::expression_only(const Expr& e, std::vector<Slot>& result) {
  frames_.emplace_back();
  const Value v = expr(&e);
  frames_.pop_back();
  result = v.s;
  out_.program.slots = static_cast<std::uint32_t>(out_.group_of.size());
  return !failed_;
}

}  // namespace raster::shader
