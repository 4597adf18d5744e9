// The lowering's statements and calls. Control flow becomes mask operations (ir.h): an if narrows `exec`
// to its condition and merges the lanes back; a loop runs while a lane is live, lanes leaving by break,
// continue and return gathered in accumulators and restored where their statement ends. A call is
// inlined, its parameters bound to the arguments' slots when the function never writes them.
#include <algorithm>
#include <functional>

#include "shader/engine.h"
#include "shader/lowerer.h"

namespace raster::shader {
namespace {

// Whether a return sits inside an if, loop or switch of `s` (then lanes can return at different times,
// and the function needs a return mask and a result to store into).
bool nested_return(const Stmt* s, int depth) {
  if (!s) return false;
  switch (s->kind) {
    case StmtKind::return_:
      return depth > 0;
    case StmtKind::block:
      for (const Stmt* c : s->list)
        if (nested_return(c, depth)) return true;
      return false;
    case StmtKind::if_:
      return nested_return(s->body, depth + 1) || nested_return(s->else_body, depth + 1);
    case StmtKind::for_:
    case StmtKind::while_:
    case StmtKind::do_:
    case StmtKind::switch_:
      return nested_return(s->body, depth + 1);
    default:
      return false;
  }
}

}  // namespace

void Lowerer::leave(Slot accumulator) {
  emit_to(Op::leave, accumulator);
}

void Lowerer::block(const Stmt* s) {
  for (const Stmt* c : s->list) {
    if (terminated_ || failed_) return;
    statement(c);
  }
}

void Lowerer::statement(const Stmt* s) {
  if (!s || terminated_ || !tick()) return;
  switch (s->kind) {
    case StmtKind::block:
      return block(s);
    case StmtKind::declaration:
      return declaration(s->decl);
    case StmtKind::expression:
      if (s->expr) expr(s->expr);
      return;
    case StmtKind::if_:
      return if_statement(s);
    case StmtKind::for_:
    case StmtKind::while_:
    case StmtKind::do_:
      return loop(s);
    case StmtKind::switch_:
      return switch_statement(s);
    case StmtKind::break_:
      return leave(breakables_.back().exit);
    case StmtKind::continue_:
      for (auto b = breakables_.rbegin(); b != breakables_.rend(); ++b)
        if (b->loop) return leave(b->resume);
      return;
    case StmtKind::return_:
      return return_statement(s);
    case StmtKind::discard:
      // Discarded lanes never matter again, so stores after it need no mask for them.
      leave(kDiscardSlot);
      if (frames_.size() == 1 && frames_.back().nesting == 0) terminated_ = true;
      return;
    default:
      return;  // empty; case labels are the switch's
  }
}

void Lowerer::declaration(const Declaration* d) {
  for (const Declarator& dv : d->vars) {
    const Variable* v = dv.variable;
    if (!v) continue;
    if (v->constant) {
      frames_.back().vars[v] = constant_value(v->type, v->value, v->type.is_array());
      continue;
    }
    const Value init = dv.init ? expr(dv.init) : Value{};
    auto& vars = frames_.back().vars;  // after the initializer, whose calls may have grown frames_
    if (!v->written) {                 // never assigned: the initializer's slots (or zeros) are the variable
      vars[v] =
          dv.init ? stable(init)
                  : constant_value(v->type,
                                   std::vector<std::uint32_t>(static_cast<std::size_t>(v->type.slots()), 0u),
                                   false);
      continue;
    }
    // A fresh variable: lanes not live here cannot read it within its scope, so the first store is whole.
    Value value = fresh(v->type);
    if (!value.s.empty()) {
      mutable_group_[out_.group_of[value.s[0]]] = true;
      frames_.back().locals.push_back(out_.group_of[value.s[0]]);
    }
    for (std::size_t i = 0; i < value.s.size(); ++i)
      emit_to(Op::mov, value.s[i], dv.init ? init.s[i] : constant(0));
    vars[v] = value;
  }
}

// The one statement of a branch (a block of one, or the statement itself); null otherwise.
const Stmt* only(const Stmt* s) {
  while (s && s->kind == StmtKind::block && s->list.size() == 1) s = s->list[0];
  return s && s->kind != StmtKind::block ? s : nullptr;
}

// Whether a branch can run as selects on every lane instead of under a mask: a few assignments (and
// declarations) of values without side effects or loops, to places without run-time indices. Cheaper than
// narrowing and widening the mask, and what compilers do with such an if.
bool Lowerer::predicable(const Stmt* s) const {
  if (!s) return true;
  return predicable(s->kind == StmtKind::block ? std::vector<const Stmt*>(s->list.begin(), s->list.end())
                                               : std::vector{s});
}
bool Lowerer::predicable(const std::vector<const Stmt*>& list) const {
  if (list.size() > 4) return false;
  for (const Stmt* c : list) {
    if (c->kind == StmtKind::declaration) {
      for (const Declarator& v : c->decl->vars)
        if (v.init && !pure(v.init)) return false;
      continue;
    }
    if (c->kind != StmtKind::expression || !c->expr) return false;
    const Expr* e = c->expr;
    const bool assigns = e->kind == ExprKind::assign || e->kind == ExprKind::postfix ||
                         (e->kind == ExprKind::unary && (e->op == Punct::inc || e->op == Punct::dec));
    if (!assigns || !static_place(e->args[0])) return false;
    if (e->kind == ExprKind::assign && !pure(e->args[1])) return false;
  }
  return true;
}

// A place without a run-time index on the way (a variable, its fields, swizzles, constant elements).
bool Lowerer::static_place(const Expr* e) const {
  if (e->kind == ExprKind::name) return true;
  if (e->kind == ExprKind::field) return static_place(e->args[0]);
  if (e->kind == ExprKind::index) return e->args[1]->constant && static_place(e->args[0]);
  return false;
}

// `if (c) break;` and its kind (continue, discard, return), maybe after a few assignments (`if (c) { found
// = true; break; }`): the assignments as selects by c, then the lanes for which c holds leave at once.
bool Lowerer::leave_if(const Stmt* s, Slot c) {
  if (s->else_body || !s->body) return false;
  const Stmt* b = s->body;
  std::vector<const Stmt*> before;
  if (b->kind == StmtKind::block) {
    if (b->list.empty()) return false;
    before.assign(b->list.begin(), b->list.end() - 1);
    b = only(b->list.back());
    if (!b || (!before.empty() && !predicable(before))) return false;
  }
  Slot acc = 0;
  const bool returns = b->kind == StmtKind::return_ && frames_.back().returns && (!b->expr || pure(b->expr));
  if (b->kind == StmtKind::break_) {
    acc = breakables_.back().exit;
  } else if (b->kind == StmtKind::continue_) {
    for (auto it = breakables_.rbegin(); it != breakables_.rend() && !acc; ++it)
      if (it->loop) acc = it->resume;
  } else if (b->kind == StmtKind::discard) {
    acc = kDiscardSlot;
  } else if (returns) {
    acc = frames_.back().returns;
  }
  if (!acc) return false;
  const Slot saved = predicate_;
  predicate_ = c;
  for (const Stmt* a : before) statement(a);
  predicate_ = saved;
  if (returns) {
    Frame& f = frames_.back();
    const Value v = b->expr ? expr(b->expr) : Value{};
    for (std::size_t i = 0; i < v.s.size() && i < frames_.back().result.s.size(); ++i)
      emit_to(Op::store_if, frames_.back().result.s[i], v.s[i], c);
    f.returned = true;
    uniform_ = false;
  }
  emit_to(Op::leave_if, acc, c);
  return true;
}

// A predicable if: both branches' assignments as selects, by the condition and by its negation.
void Lowerer::predicated_if(const Stmt* s, Slot c) {
  const Slot saved = predicate_;
  predicate_ = c;
  statement(s->body);
  if (s->else_body) {
    predicate_ = emit(Op::bnot, c);
    statement(s->else_body);
  }
  predicate_ = saved;
}

void Lowerer::if_statement(const Stmt* s) {
  const Value c = expr(s->expr);
  if (s->expr->constant) {  // a constant condition: only its branch exists
    const std::vector<std::uint32_t> k = s->expr->value.empty() ? fold_constant(*s->expr) : s->expr->value;
    if (!k.empty()) return statement(k[0] ? s->body : s->else_body);
  }
  if (leave_if(s, c.s[0])) return;
  if (predicate_ == 0 && predicable(s->body) && predicable(s->else_body)) return predicated_if(s, c.s[0]);
  const Slot saved = group(1);
  const std::size_t begin = emit_to(Op::if_begin, saved, c.s[0]);
  const bool was_uniform = uniform_;
  uniform_ = false;
  ++frames_.back().nesting;
  statement(s->body);
  if (s->else_body) {
    const Slot after_then = group(1);
    const std::size_t middle = emit_to(Op::if_else, after_then, saved, c.s[0]);
    out_.program.code[begin].imm = static_cast<std::uint32_t>(middle);
    statement(s->else_body);
    out_.program.code[middle].imm = static_cast<std::uint32_t>(emit_to(Op::if_end, 0, after_then));
  } else {
    out_.program.code[begin].imm = static_cast<std::uint32_t>(emit_to(Op::if_merge, 0, saved, c.s[0]));
  }
  --frames_.back().nesting;
  uniform_ = was_uniform && !frames_.back().returned;
}

// A switch: no lane runs until its label; a case adds the lanes whose value matches, default those no
// case matches, and lanes fall through to the next label's statements until they break.
void Lowerer::switch_statement(const Stmt* s) {
  const Slot value = expr(s->expr).s[0];
  const Slot entry = group(1);
  emit_to(Op::mov, entry, kExecSlot);
  Breakable b;
  b.exit = group(1);
  emit_to(Op::clear, b.exit);
  std::vector<Slot> labels;
  Slot none = 0;
  for (const Stmt* c : s->body->list) {
    if (c->kind != StmtKind::case_) continue;
    const std::vector<std::uint32_t> k = c->expr->value.empty() ? fold_constant(*c->expr) : c->expr->value;
    labels.push_back(emit(Op::ieq, value, constant(k.empty() ? 0 : k[0])));
  }
  Slot any = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) any = i == 0 ? labels[0] : emit(Op::bor, any, labels[i]);
  none = labels.empty() ? constant(~0u) : emit(Op::bnot, any);
  leave(group(1));  // exec = 0
  const bool was_uniform = uniform_;
  uniform_ = false;
  ++frames_.back().nesting;
  breakables_.push_back(b);
  std::size_t next_label = 0;
  for (const Stmt* c : s->body->list) {
    if (c->kind == StmtKind::case_) {
      emit_to(Op::mask_or_and, 0, entry, labels[next_label++]);
    } else if (c->kind == StmtKind::default_) {
      emit_to(Op::mask_or_and, 0, entry, none);
    } else {
      statement(c);
    }
  }
  emit_to(Op::mask_or, 0, b.exit);
  breakables_.pop_back();
  --frames_.back().nesting;
  uniform_ = was_uniform && !frames_.back().returned;
}

void Lowerer::return_statement(const Stmt* s) {
  Value v;
  if (s->expr) v = expr(s->expr);  // may inline calls, which grow frames_: look at the frame after
  Frame& f = frames_.back();
  if (f.nesting == 0 && !f.result_group) {  // the last return, on every live lane: the value is the result
    // A variable of the function itself ends with it, so it can be the result uncopied.
    if (s->expr) f.result = own(v, f) ? v : stable(v);
    terminated_ = true;
    return;
  }
  for (std::size_t i = 0; i < v.s.size() && i < f.result.s.size(); ++i)
    emit_to(uniform_ ? Op::mov : Op::store, f.result.s[i], v.s[i]);
  if (f.nesting == 0) {
    terminated_ = true;
    return;
  }
  leave(f.returns);
  f.returned = true;
  uniform_ = false;
}

// Whether every slot of `v` is a variable of frame `f` (which no code sees once the function returns).
bool Lowerer::own(const Value& v, const Frame& f) const {
  for (const Slot s : v.s)
    if (std::find(f.locals.begin(), f.locals.end(), out_.group_of[s]) == f.locals.end()) return false;
  return !v.s.empty();
}

// Runs `f`'s body in `frame`: the lanes that return early rejoin at its end.
void Lowerer::function_body(const FunctionDecl* f, Frame& frame) {
  const Type ret = frame.function ? frame.function->ret : Type::of(Basic::void_);
  if (nested_return(f->body, 0)) {
    frame.result_group = true;
    frame.returns = group(1);
    emit_to(Op::clear, frame.returns);
    if (!ret.is_void()) {
      frame.result = fresh(ret);
      for (const Slot r : frame.result.s) emit_to(Op::mov, r, constant(0));  // a lane that falls off the end
    }
  }
  const bool was_terminated = terminated_, was_uniform = uniform_;
  terminated_ = false;
  frames_.push_back(std::move(frame));
  block(f->body);
  frame = std::move(frames_.back());
  frames_.pop_back();
  if (frame.returns) emit_to(Op::mask_or, 0, frame.returns);
  terminated_ = was_terminated;
  uniform_ = was_uniform;
  if (!ret.is_void() && frame.result.s.size() != static_cast<std::size_t>(ret.slots()))
    frame.result =
        constant_value(ret, std::vector<std::uint32_t>(static_cast<std::size_t>(ret.slots()), 0u), false);
}

// Whether an out argument's place is a variable of the calling function, whole, that no other out argument
// of the call names (`taken`: the groups they name): then the parameter can be that variable, as copying
// in and out gives the same values when no other code can see it while the callee runs.
bool Lowerer::whole_local(const Place& p, std::vector<std::uint32_t>& taken) {
  if (p.dynamic || p.slots.empty()) return false;
  const std::uint32_t g = out_.group_of[p.slots[0]];
  const bool named = std::find(taken.begin(), taken.end(), g) != taken.end();
  taken.push_back(g);
  if (named || p.slots.size() != out_.group_size[g] || p.slots[0] != out_.group_first[g]) return false;
  for (std::size_t k = 0; k < p.slots.size(); ++k)
    if (p.slots[k] != p.slots[0] + k) return false;
  const std::vector<std::uint32_t>& locals = frames_.back().locals;
  return std::find(locals.begin(), locals.end(), g) != locals.end();
}

// Whether a function's result depends on its arguments alone: it and what it calls read no uniform, input,
// texture, derivative or global variable (constants aside), write no global, and do not discard.
bool Lowerer::reads_only_its_arguments(const Function* f) {
  if (!f || !f->definition) return false;
  if (const auto it = closed_.find(f); it != closed_.end()) return it->second;
  closed_[f] = false;  // no recursion reaches here (the checker refuses it); a cycle would read false
  bool closed = true;
  const std::function<void(const Expr*)> visit_expr = [&](const Expr* e) {
    if (!e || !closed) return;
    if (e->kind == ExprKind::name && e->variable) {
      const Variable::Kind k = e->variable->kind;
      if (k != Variable::Kind::local && k != Variable::Kind::parameter && !e->variable->constant)
        closed = false;
    }
    if (e->builtin && e->builtin->op >= BuiltinOp::texture_size && e->builtin->op <= BuiltinOp::fwidth)
      closed = false;
    if (e->function && !reads_only_its_arguments(e->function)) closed = false;
    for (const Expr* a : e->args) visit_expr(a);
  };
  const std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
    if (!s || !closed) return;
    if (s->kind == StmtKind::discard) closed = false;
    visit_expr(s->expr), visit_expr(s->step), visit(s->init), visit(s->body), visit(s->else_body);
    if (s->decl)
      for (const Declarator& d : s->decl->vars) visit_expr(d.init);
    for (const Stmt* c : s->list) visit(c);
  };
  visit(f->definition->body);
  return closed_[f] = closed;
}

// A call of constant arguments to a function of its arguments alone is computed now, by the engine's
// scalar reference (so it has the bits every lane width gives), and becomes its constant result: a loop of
// constants runs once, not once a pixel. Small: a few thousand values and loop iterations; past that
// (or on any error) the call is lowered as any other, and runs under the program's own bounds.
std::optional<Value> Lowerer::constant_call(const Expr* e) {
  const Function* fn = e->function;
  if (folding_ || !fn || fn->ret.is_void() || fn->ret.has_sampler()) return std::nullopt;
  for (std::size_t i = 0; i < e->args.size(); ++i)
    if (!e->args[i]->constant || fn->qualifiers[i] == Qualifier::out || fn->qualifiers[i] == Qualifier::inout)
      return std::nullopt;
  if (!reads_only_its_arguments(fn)) return std::nullopt;
  constexpr std::size_t kMostSlots = 4096, kMostInstructions = 16384;
  constexpr std::int64_t kMostIterations = 4096;
  Lowered lowered;
  Diagnostics quiet;
  Lowerer inner(lowered, {kMostInstructions, kMostSlots}, quiet);
  inner.folding_ = true;
  std::vector<Slot> result;
  if (!inner.expression_only(*e, result)) return std::nullopt;
  // The program's whole budget (fold_work_: instructions times iterations) bounds what all such calls cost
  // the compiler, each charged for its worst case.
  const auto size = static_cast<std::int64_t>(lowered.program.code.size()) + 1;
  const std::int64_t iterations = std::min(kMostIterations, fold_work_ / size);
  if (iterations < 1) return std::nullopt;
  fold_work_ -= iterations * size;
  const std::vector<std::uint32_t> bits = evaluate_once(lowered.program, result, iterations);
  if (bits.size() != static_cast<std::size_t>(fn->ret.slots())) return std::nullopt;
  return constant_value(fn->ret, bits, fn->ret.is_array() || fn->ret.basic == Basic::structure);
}

Value Lowerer::call(const Expr* e) {
  if (std::optional<Value> folded = constant_call(e)) return *std::move(folded);
  const Function* fn = e->function;
  Frame frame;
  frame.function = fn;
  std::vector<std::pair<Place, Value>> copy_back;
  std::vector<std::uint32_t> taken;  // groups out arguments name
  for (std::size_t i = 0; i < e->args.size(); ++i) {
    const Variable* param = fn->parameters[i];
    const Qualifier q = fn->qualifiers[i];
    Value bound;
    if (q == Qualifier::out || q == Qualifier::inout) {
      const Place p = place(e->args[i]);
      if (whole_local(p, taken)) {  // the caller's own variable: the callee writes it where it is
        frame.vars[param] = Value{param->type, p.slots};
        frame.locals.push_back(out_.group_of[p.slots[0]]);  // no one else sees it while the callee runs
        continue;
      }
      bound = fresh(param->type);
      const Value in = q == Qualifier::inout ? read(p) : Value{};
      for (std::size_t k = 0; k < bound.s.size(); ++k)
        emit_to(Op::mov, bound.s[k], q == Qualifier::inout ? in.s[k] : constant(0));
      copy_back.emplace_back(p, bound);
      mutable_group_[out_.group_of[bound.s[0]]] = true;
      frame.locals.push_back(out_.group_of[bound.s[0]]);
      frame.vars[param] = bound;
      continue;
    } else {
      const Value a = expr(e->args[i]);
      bound = param->written ? contiguous_copy(a) : stable(a);
      bound.channel = a.channel;
    }
    if (param->written && !bound.s.empty()) {
      mutable_group_[out_.group_of[bound.s[0]]] = true;
      frame.locals.push_back(out_.group_of[bound.s[0]]);
    }
    frame.vars[param] = bound;
  }
  function_body(fn->definition, frame);
  for (const auto& [p, v] : copy_back) write(p, v);
  Value result = frame.result;
  result.type = fn->ret;
  return result;
}

}  // namespace raster::shader
