// The lowering's loops. A loop runs while a lane is live (ir.h): lanes leaving by break gather in an exit
// accumulator, lanes leaving an iteration by continue in a resume one, restored at the iteration's end. A
// counted loop small enough is written out instead, once per iteration.
#include <optional>
#include <unordered_map>

#include "shader/lowerer.h"

namespace raster::shader {
namespace {

// Whether a continue of this loop sits in `s` (then the loop needs a resume accumulator).
bool has_continue(const Stmt* s) {
  if (!s) return false;
  switch (s->kind) {
    case StmtKind::continue_:
      return true;
    case StmtKind::block:
      for (const Stmt* c : s->list)
        if (has_continue(c)) return true;
      return false;
    case StmtKind::if_:
      return has_continue(s->body) || has_continue(s->else_body);
    case StmtKind::switch_:
      return has_continue(s->body);
    default:
      return false;  // a nested loop's continue is its own
  }
}

// Whether `s` has a break or continue that leaves the loop whose body it is (not a nested loop's, not a
// nested switch's break).
bool leaves_loop(const Stmt* s, bool in_switch) {
  if (!s) return false;
  switch (s->kind) {
    case StmtKind::break_:
      return !in_switch;
    case StmtKind::continue_:
      return true;
    case StmtKind::block:
      for (const Stmt* c : s->list)
        if (leaves_loop(c, in_switch)) return true;
      return false;
    case StmtKind::if_:
      return leaves_loop(s->body, in_switch) || leaves_loop(s->else_body, in_switch);
    case StmtKind::switch_:
      return leaves_loop(s->body, true);
    default:
      return false;
  }
}

// The variable at the root of a place (`v`, `v.x`, `v[i].y`); null for anything else.
const Variable* root(const Expr* e) {
  while (e && (e->kind == ExprKind::field || e->kind == ExprKind::index)) e = e->args[0];
  return e && e->kind == ExprKind::name ? e->variable : nullptr;
}

// Whether `e` may change `v`: an assignment to it, ++ or --, or an out or inout argument naming it.
bool writes(const Expr* e, const Variable* v) {
  if (!e) return false;
  const bool steps = e->kind == ExprKind::postfix ||
                     (e->kind == ExprKind::unary && (e->op == Punct::inc || e->op == Punct::dec));
  if ((e->kind == ExprKind::assign || steps) && root(e->args[0]) == v) return true;
  if (e->kind == ExprKind::call) {
    const std::vector<Qualifier>* q = e->function  ? &e->function->qualifiers
                                      : e->builtin ? &e->builtin->qualifiers
                                                   : nullptr;
    for (std::size_t i = 0; q && i < e->args.size() && i < q->size(); ++i)
      if (((*q)[i] == Qualifier::out || (*q)[i] == Qualifier::inout) && root(e->args[i]) == v) return true;
  }
  for (const Expr* a : e->args)
    if (writes(a, v)) return true;
  return false;
}
bool writes(const Stmt* s, const Variable* v) {
  if (!s) return false;
  if (writes(s->expr, v) || writes(s->step, v) || writes(s->init, v) || writes(s->body, v) ||
      writes(s->else_body, v))
    return true;
  if (s->decl)
    for (const Declarator& d : s->decl->vars)
      if (writes(d.init, v)) return true;
  for (const Stmt* c : s->list)
    if (writes(c, v)) return true;
  return false;
}

// The one slot of a constant scalar expression (the checker folds some of them lazily); nullopt otherwise.
std::optional<std::uint32_t> constant_scalar(const Expr* e) {
  if (!e || !e->constant) return std::nullopt;
  const std::vector<std::uint32_t> v = e->value.empty() ? fold_constant(*e) : e->value;
  if (v.size() != 1) return std::nullopt;
  return v[0];
}

// The iterations of a counted loop, `for (int i = A; i < B; i++)` and its kin: i an int or uint declared
// by the loop, compared (<, <=, >, >=, !=) with a constant, stepped by ++, --, += or -= a constant, written
// nowhere in the body, which has no break or continue of its own. -1 for any other loop, and for one of
// more than `most` iterations.
int trip_count(const Stmt* s, int most, std::uint32_t* step = nullptr) {
  if (s->kind != StmtKind::for_ || !s->init || s->init->kind != StmtKind::declaration || !s->expr || !s->step)
    return -1;
  const Declaration* d = s->init->decl;
  if (d->vars.size() != 1 || !d->vars[0].variable || !constant_scalar(d->vars[0].init)) return -1;
  const Variable* v = d->vars[0].variable;
  if (v->type.is_array() || v->type.slots() != 1 ||
      (v->type.basic != Basic::int_ && v->type.basic != Basic::uint_))
    return -1;
  const bool is_signed = v->type.basic == Basic::int_;
  // The condition as `i op bound`.
  const Expr* c = s->expr;
  if (c->kind != ExprKind::binary || c->args.size() != 2) return -1;
  Punct op = c->op;
  const Expr* bound = c->args[1];
  if (root(c->args[1]) == v && c->args[1]->kind == ExprKind::name) {
    static constexpr std::pair<Punct, Punct> kMirror[] = {{Punct::less, Punct::greater},
                                                          {Punct::greater, Punct::less},
                                                          {Punct::le, Punct::ge},
                                                          {Punct::ge, Punct::le},
                                                          {Punct::ne, Punct::ne}};
    Punct mirrored = Punct::none;
    for (const auto& [from, to] : kMirror)
      if (from == op) mirrored = to;
    op = mirrored, bound = c->args[0];
  } else if (c->args[0]->kind != ExprKind::name || c->args[0]->variable != v) {
    return -1;
  }
  if (!constant_scalar(bound) || bound->type.basic != v->type.basic) return -1;
  // The step, in 32-bit wrapping arithmetic.
  const Expr* st = s->step;
  std::uint32_t delta = 0;
  if ((st->kind == ExprKind::postfix || st->kind == ExprKind::unary) &&
      (st->op == Punct::inc || st->op == Punct::dec)) {
    delta = st->op == Punct::inc ? 1u : ~0u;
  } else if (st->kind == ExprKind::assign && (st->op == Punct::add_assign || st->op == Punct::sub_assign) &&
             constant_scalar(st->args[1]) && st->args[1]->type.basic == v->type.basic) {
    const std::uint32_t k = *constant_scalar(st->args[1]);
    delta = st->op == Punct::add_assign ? k : 0u - k;
  } else {
    return -1;
  }
  if (st->args[0]->kind != ExprKind::name || st->args[0]->variable != v) return -1;
  if (leaves_loop(s->body, false) || writes(s->body, v)) return -1;
  const std::uint32_t b = *constant_scalar(bound);
  const auto holds = [&](std::uint32_t i) {
    const auto less = [&](std::uint32_t x, std::uint32_t y) {
      return is_signed ? static_cast<std::int32_t>(x) < static_cast<std::int32_t>(y) : x < y;
    };
    switch (op) {
      case Punct::less:
        return less(i, b);
      case Punct::greater:
        return less(b, i);
      case Punct::le:
        return !less(b, i);
      case Punct::ge:
        return !less(i, b);
      case Punct::ne:
        return i != b;
      default:
        return false;
    }
  };
  if (op != Punct::less && op != Punct::greater && op != Punct::le && op != Punct::ge && op != Punct::ne)
    return -1;
  int trips = 0;
  for (std::uint32_t i = *constant_scalar(d->vars[0].init); holds(i); i += delta)
    if (++trips > most) return -1;
  if (step) *step = delta;
  return trips;
}

// Roughly the operations a statement lowers to, its calls inlined and its counted loops written out: what
// writing out a loop costs.
struct Work {
  std::unordered_map<const Function*, std::size_t> functions;
  std::size_t of(const Expr* e) {
    if (!e) return 0;
    std::size_t n = 1;
    for (const Expr* a : e->args) n += of(a);
    if (e->function && e->function->definition) {
      auto it = functions.find(e->function);
      if (it == functions.end()) it = functions.emplace(e->function, of(e->function->definition->body)).first;
      n += it->second;
    }
    return n;
  }
  std::size_t of(const Stmt* s) {
    if (!s) return 0;
    std::size_t n = 1 + of(s->expr) + of(s->step) + of(s->init) + of(s->body) + of(s->else_body);
    if (s->decl)
      for (const Declarator& d : s->decl->vars) n += of(d.init);
    for (const Stmt* c : s->list) n += of(c);
    const int trips = s->kind == StmtKind::for_ ? trip_count(s, kMostTrips) : -1;
    return trips > 1 ? n * static_cast<std::size_t>(trips) : n;
  }
  static constexpr int kMostTrips = 64;
};

}  // namespace

// A counted loop (trip_count) small enough is written out, one copy of its body per iteration, each seeing
// the loop's variable as that iteration's constant: what depends on it alone folds, nothing is counted or
// tested at run time, and the optimizer sees one run of straight-line code (llvmpipe's compiler unrolls
// such loops too). Small: at most kMostTrips iterations and kMostWork operations written out.
bool Lowerer::unrolled(const Stmt* s) {
  constexpr int kMostTrips = 32;
  constexpr std::size_t kMostWork = 4096;
  std::uint32_t delta = 0;
  const int trips = trip_count(s, kMostTrips, &delta);
  if (trips < 0) return false;
  Work work;
  const std::size_t total = work.of(s->body) * static_cast<std::size_t>(trips);
  if (total > kMostWork || work_ + total > limits_.max_instructions / 2) return false;
  const Declarator& d = s->init->decl->vars[0];
  std::uint32_t i = *constant_scalar(d.init);
  for (int k = 0; k < trips && !terminated_ && !failed_; ++k, i += delta) {
    frames_.back().vars[d.variable] = constant_value(d.variable->type, {i}, false);
    statement(s->body);
  }
  return true;
}

// for, while and do-while: exits (the condition false, or break) gather in `exit`, lanes that continue in
// `resume` until the iteration's end; the loop goes round while any lane is live.
void Lowerer::loop(const Stmt* s) {
  if (unrolled(s)) return;
  if (s->kind == StmtKind::for_) statement(s->init);
  Breakable b;
  b.loop = true;
  b.exit = group(1);
  emit_to(Op::clear, b.exit);
  if (has_continue(s->body)) {
    b.resume = group(1);
    emit_to(Op::clear, b.resume);
  }
  const bool was_uniform = uniform_;
  uniform_ = false;
  ++frames_.back().nesting;
  breakables_.push_back(b);
  const auto index = static_cast<Slot>(out_.program.loops.size());
  out_.program.loops.push_back({s->pos});
  const auto top = static_cast<std::uint32_t>(patch_target());
  std::vector<std::size_t> tests;
  const auto test = [&] {
    Slot c = 0;
    if (s->decl) {
      declaration(s->decl);
      c = variable(s->decl->vars.front().variable).s.at(0);
    } else if (s->expr) {
      if (s->expr->constant && !s->expr->value.empty() && s->expr->value[0] != 0) return;  // while (true)
      c = expr(s->expr).s[0];
    } else {
      return;  // for (;;)
    }
    tests.push_back(emit_to(Op::loop_test, b.exit, c));
  };
  if (s->kind != StmtKind::do_) test();
  statement(s->body);
  if (b.resume) {
    emit_to(Op::mask_or, 0, b.resume);
    emit_to(Op::clear, b.resume);
  }
  if (s->step) {
    // The variables the loop declares are seen by no lane that has left it, and every other lane is live
    // again here: the step writes them whole.
    const std::vector<Slot> saved = step_slots_;
    if (s->init && s->init->kind == StmtKind::declaration)
      for (const Declarator& d : s->init->decl->vars)
        if (d.variable && !d.variable->constant && d.variable->written) {
          const Value& v = variable(d.variable);
          step_slots_.insert(step_slots_.end(), v.s.begin(), v.s.end());
        }
    expr(s->step);
    step_slots_ = saved;
  }
  if (s->kind == StmtKind::do_) test();
  emit_to(Op::loop_back, 0, 0, 0, index, top);
  const std::size_t end = emit_to(Op::loop_end, 0, b.exit);
  for (const std::size_t t : tests) out_.program.code[t].imm = static_cast<std::uint32_t>(end);
  breakables_.pop_back();
  --frames_.back().nesting;
  uniform_ = was_uniform && !frames_.back().returned;
}

}  // namespace raster::shader
