// The lowering's expressions: operators component by component (a scalar operand spread over a vector or
// matrix), matrix products, swizzles and fields as slot choices, indices as slot choices (constant) or
// load_index / store_index (at run time, clamped), constructors with their conversions.
#include <algorithm>

#include "shader/lowerer.h"

namespace raster::shader {
namespace {

Op arithmetic_op(Punct op, Basic b) {
  const bool f = b == Basic::float_, u = b == Basic::uint_;
  switch (op) {
    case Punct::plus:
      return f ? Op::fadd : Op::iadd;
    case Punct::minus:
      return f ? Op::fsub : Op::isub;
    case Punct::star:
      return f ? Op::fmul : Op::imul;
    case Punct::slash:
      return f ? Op::fdiv : u ? Op::udiv : Op::idiv;
    case Punct::percent:
      return u ? Op::umod : Op::imod;
    case Punct::amp:
      return Op::band;
    case Punct::pipe:
      return Op::bor;
    case Punct::caret:
      return Op::bxor;
    case Punct::xor_xor:
      return Op::bxor;
    case Punct::shl:
      return Op::shl;
    case Punct::shr:
      return u ? Op::ushr : Op::shr;
    case Punct::less:
      return f ? Op::flt : u ? Op::ult : Op::ilt;
    case Punct::greater:
      return f ? Op::fgt : u ? Op::ugt : Op::igt;
    case Punct::le:
      return f ? Op::fle : u ? Op::ule : Op::ile;
    default:
      return f ? Op::fge : u ? Op::uge : Op::ige;  // Punct::ge
  }
}

// The basic type of each slot of t, in layout order.
void slot_basics(const Type& t, std::vector<Basic>& out) {
  const int elements = t.array > 0 ? t.array : 1;
  for (int e = 0; e < elements; ++e) {
    if (t.is_struct()) {
      for (const Field& f : t.structure->fields) slot_basics(f.type, out);
    } else {
      for (int i = 0; i < t.rows * t.cols; ++i) out.push_back(t.basic);
    }
  }
}

}  // namespace

Slot Lowerer::component(const Value& v, int i) const {
  return v.s.size() == 1 ? v.s[0] : v.s[static_cast<std::size_t>(i)];
}

// `op` on each component of the result, scalar arguments spread over it.
Value Lowerer::map(Op op, const Type& result, const std::vector<const Value*>& args) {
  Value r;
  r.type = result;
  const int n = result.slots();
  for (int i = 0; i < n; ++i) {
    const Slot a = component(*args[0], i);
    const Slot b = args.size() > 1 ? component(*args[1], i) : 0;
    const Slot c = args.size() > 2 ? component(*args[2], i) : 0;
    r.s.push_back(emit(op, a, b, c));
  }
  return r;
}

// Whether evaluating e can change anything (an assignment, ++, --, or a call of a user function, which
// may write globals): such operands of &&, || and ?: are evaluated under the condition; others eagerly.
bool Lowerer::pure(const Expr* e) const {
  if (!e) return true;
  if (e->kind == ExprKind::assign ||
      (e->kind == ExprKind::unary && (e->op == Punct::inc || e->op == Punct::dec)) ||
      e->kind == ExprKind::postfix || e->function)
    return false;
  if (e->builtin && e->builtin->op == BuiltinOp::modf) return false;
  for (const Expr* a : e->args)
    if (!pure(a)) return false;
  return true;
}

Value Lowerer::expr(const Expr* e) {
  if (!tick()) return fresh(e->type);
  if (e->constant && !e->value.empty() && e->value.size() == static_cast<std::size_t>(e->type.slots()) &&
      !e->type.has_sampler())
    return constant_value(e->type, e->value, false);
  switch (e->kind) {
    case ExprKind::literal:
      return Value{e->type, {constant(e->bits)}};
    case ExprKind::name:
      return variable(e->variable);
    case ExprKind::unary:
    case ExprKind::postfix:
      return unary(e);
    case ExprKind::binary:
      return binary(e);
    case ExprKind::assign:
      return assign(e);
    case ExprKind::ternary:
      return ternary(e);
    case ExprKind::call:
      if (e->function) return call(e);
      if (e->builtin) {
        std::vector<Value> args;
        for (const Expr* a : e->args)
          args.push_back(e->builtin->qualifiers.size() > args.size() &&
                                 e->builtin->qualifiers[args.size()] == Qualifier::out
                             ? Value{a->type, {}}
                             : expr(a));
        return builtin(e, std::move(args));
      }
      return construct(e, e->type);  // a struct's constructor
    case ExprKind::construct:
      return construct(e, e->type);
    case ExprKind::field:
      return field(e);
    case ExprKind::index:
      return index(e);
    case ExprKind::length:
      return Value{e->type, {iconst(e->args[0]->type.array)}};
    case ExprKind::sequence:
      expr(e->args[0]);
      return expr(e->args[1]);
  }
  return fresh(e->type);
}

Value Lowerer::unary(const Expr* e) {
  const Expr* a = e->args[0];
  const Type& t = e->type;
  if (e->op == Punct::inc || e->op == Punct::dec) {
    const Place p = place(a);
    const Value current = read(p);
    // x++ is the value before: a copy, which nothing reads (and dead code removes) when x++ is a statement.
    const Value old = e->kind == ExprKind::postfix ? contiguous_copy(current) : Value{};
    const Value one{t.scalar(), {t.basic == Basic::float_ ? fconst(1.0f) : iconst(1)}};
    const bool inc = e->op == Punct::inc;
    const Op op = t.basic == Basic::float_ ? (inc ? Op::fadd : Op::fsub) : (inc ? Op::iadd : Op::isub);
    const Value now = map(op, t, {&current, &one});
    write(p, now);
    return e->kind == ExprKind::postfix ? old : now;
  }
  const Value v = expr(a);
  switch (e->op) {
    case Punct::plus:
      return v;
    case Punct::minus:
      return map(t.basic == Basic::float_ ? Op::fneg : Op::ineg, t, {&v});
    default:
      return map(Op::bnot, t, {&v});  // ! on a bool, ~ on integers: both flip every bit
  }
}

Value Lowerer::binary(const Expr* e) {
  if (e->op == Punct::and_and || e->op == Punct::or_or) return logical(e);
  const Value a = expr(e->args[0]);
  const Value b = expr(e->args[1]);
  if (e->op == Punct::eq || e->op == Punct::ne) return equality(a, b, e->op == Punct::eq);
  return binary_values(e->op, a, b, e->type);
}

Value Lowerer::binary_values(Punct op, const Value& a, const Value& b, const Type& result) {
  if (op == Punct::star && (a.type.is_matrix() || b.type.is_matrix()) && !a.type.is_scalar() &&
      !b.type.is_scalar())
    return matrix_product(a, b, result);
  return map(arithmetic_op(op, a.type.basic), result, {&a, &b});
}

// Linear algebra (section 5.10): a matrix times a vector sums the columns scaled by the vector's
// components, in column order; a vector times a matrix is a dot product with each column.
Value Lowerer::matrix_product(const Value& a, const Value& b, const Type& result) {
  Value r;
  r.type = result;
  if (a.type.is_vector()) {
    const int rows = b.type.rows;
    for (int c = 0; c < b.type.cols; ++c) {
      Value column{Type::of(Basic::float_, rows), {}};
      for (int k = 0; k < rows; ++k) column.s.push_back(b.s[static_cast<std::size_t>(c * rows + k)]);
      r.s.push_back(dot(a, column));
    }
    return r;
  }
  const int rows = a.type.rows, inner = a.type.cols;
  const int columns = b.type.is_vector() ? 1 : b.type.cols;
  for (int c = 0; c < columns; ++c)
    for (int row = 0; row < rows; ++row) {
      std::vector<Slot> terms;
      for (int k = 0; k < inner; ++k)
        terms.push_back(emit(Op::fmul, a.s[static_cast<std::size_t>(k * rows + row)],
                             b.s[static_cast<std::size_t>(c * inner + k)]));
      r.s.push_back(sum(terms));
    }
  return r;
}

// == and != on any type: every component equal (floats by IEEE equality, so NaN is never equal).
Value Lowerer::equality(const Value& a, const Value& b, bool equal) {
  std::vector<Basic> basics;
  slot_basics(a.type, basics);
  Slot all = 0;
  for (std::size_t i = 0; i < a.s.size(); ++i) {
    const Slot same = emit(basics[i] == Basic::float_ ? Op::feq : Op::ieq, a.s[i], b.s[i]);
    all = i == 0 ? same : emit(Op::band, all, same);
  }
  return Value{Type::of(Basic::bool_), {equal ? all : emit(Op::bnot, all)}};
}

// && and ||: the right operand is evaluated only where the left does not decide (section 5.9), which
// matters only when it changes something; a pure one is evaluated everywhere and combined.
Value Lowerer::logical(const Expr* e) {
  const bool is_and = e->op == Punct::and_and;
  const Value a = expr(e->args[0]);
  if (pure(e->args[1])) {
    const Value b = expr(e->args[1]);
    return map(is_and ? Op::band : Op::bor, e->type, {&a, &b});
  }
  const Value result = fresh(e->type);
  emit_to(Op::mov, result.s[0], a.s[0]);
  const Slot take = is_and ? a.s[0] : emit(Op::bnot, a.s[0]);
  const Slot saved = group(1);
  const std::size_t begin = emit_to(Op::if_begin, saved, take);
  const bool was_uniform = uniform_;
  uniform_ = false;
  ++frames_.back().nesting;
  const Value b = expr(e->args[1]);
  emit_to(Op::store, result.s[0], b.s[0]);
  --frames_.back().nesting;
  uniform_ = was_uniform;
  out_.program.code[begin].imm = static_cast<std::uint32_t>(emit_to(Op::if_merge, 0, saved, take));
  return result;
}

Value Lowerer::ternary(const Expr* e) {
  const Value c = expr(e->args[0]);
  if (pure(e->args[1]) && pure(e->args[2])) {
    const Value x = expr(e->args[1]), y = expr(e->args[2]);
    Value r;
    r.type = e->type;
    r.channel = x.channel;
    for (std::size_t i = 0; i < x.s.size(); ++i) r.s.push_back(emit(Op::select, c.s[0], x.s[i], y.s[i]));
    return r;
  }
  // if (c) result = x; else result = y;
  const Value result = fresh(e->type);
  const Slot saved = group(1), after_then = group(1);
  const std::size_t begin = emit_to(Op::if_begin, saved, c.s[0]);
  const bool was_uniform = uniform_;
  uniform_ = false;
  ++frames_.back().nesting;
  const Value x = expr(e->args[1]);
  for (std::size_t i = 0; i < x.s.size(); ++i) emit_to(Op::store, result.s[i], x.s[i]);
  const std::size_t middle = emit_to(Op::if_else, after_then, saved, c.s[0]);
  out_.program.code[begin].imm = static_cast<std::uint32_t>(middle);
  const Value y = expr(e->args[2]);
  for (std::size_t i = 0; i < y.s.size(); ++i) emit_to(Op::store, result.s[i], y.s[i]);
  out_.program.code[middle].imm = static_cast<std::uint32_t>(emit_to(Op::if_end, 0, after_then));
  --frames_.back().nesting;
  uniform_ = was_uniform;
  return result;
}

Value Lowerer::assign(const Expr* e) {
  const Place p = place(e->args[0]);
  if (e->op == Punct::assign) {
    const Value v = expr(e->args[1]);
    write(p, v);
    return v;
  }
  static constexpr std::pair<Punct, Punct> kOps[] = {
      {Punct::add_assign, Punct::plus},    {Punct::sub_assign, Punct::minus},
      {Punct::mul_assign, Punct::star},    {Punct::div_assign, Punct::slash},
      {Punct::mod_assign, Punct::percent}, {Punct::shl_assign, Punct::shl},
      {Punct::shr_assign, Punct::shr},     {Punct::and_assign, Punct::amp},
      {Punct::or_assign, Punct::pipe},     {Punct::xor_assign, Punct::caret}};
  Punct op = Punct::none;
  for (const auto& [compound, plain] : kOps)
    if (compound == e->op) op = plain;
  const Value old = read(p);
  const Value rhs = expr(e->args[1]);
  const Value now = binary_values(op, old, rhs, e->type);
  write(p, now);
  return now;
}

Value Lowerer::field(const Expr* e) {
  const Value base = expr(e->args[0]);
  Value r;
  r.type = e->type;
  if (e->swizzle_count > 0) {
    for (int i = 0; i < e->swizzle_count; ++i) r.s.push_back(base.s[e->swizzle[i]]);
    return r;
  }
  const auto at = static_cast<std::size_t>(base.type.structure->offset(static_cast<std::size_t>(e->field)));
  r.s.assign(base.s.begin() + static_cast<std::ptrdiff_t>(at),
             base.s.begin() + static_cast<std::ptrdiff_t>(at + static_cast<std::size_t>(e->type.slots())));
  return r;
}

Value Lowerer::index(const Expr* e) {
  const Value base = expr(e->args[0]);
  const Type& t = e->args[0]->type;
  const auto element = static_cast<std::size_t>(e->type.slots());
  const int count = t.is_array() ? t.array : t.is_matrix() ? t.cols : t.rows;
  Value r;
  r.type = e->type;
  const Expr* i = e->args[1];
  if (i->constant) {
    const std::vector<std::uint32_t> k = i->value.empty() ? fold_constant(*i) : i->value;
    const std::size_t at =
        k.empty() ? 0 : std::min<std::size_t>(k[0], static_cast<std::size_t>(count - 1)) * element;
    r.s.assign(base.s.begin() + static_cast<std::ptrdiff_t>(at),
               base.s.begin() + static_cast<std::ptrdiff_t>(at + element));
    return r;
  }
  const Slot at = expr(i).s[0];
  const Value whole = contiguous(base) ? base : contiguous_copy(base);
  for (std::size_t j = 0; j < element; ++j)
    r.s.push_back(
        emit(Op::load_index, whole.s[j], at, static_cast<Slot>(element), static_cast<std::uint32_t>(count)));
  return r;
}

// A slot converted from one basic type to another (section 5.4.1).
Value Lowerer::convert(const Value& v, Basic to) {
  const Basic from = v.type.basic;
  Value r = v;
  r.type.basic = to;
  if (from == to) return r;
  const bool same_bits =
      (from == Basic::int_ || from == Basic::uint_) && (to == Basic::int_ || to == Basic::uint_);
  if (same_bits) return r;
  for (Slot& s : r.s) {
    if (to == Basic::bool_) {
      s = from == Basic::float_ ? emit(Op::fne, s, fconst(0.0f)) : emit(Op::ine, s, iconst(0));
    } else if (from == Basic::bool_) {
      s = emit(to == Basic::float_ ? Op::b2f : Op::b2i, s);
    } else if (from == Basic::float_) {
      s = emit(to == Basic::int_ ? Op::f2i : Op::f2u, s);
    } else {
      s = emit(from == Basic::int_ ? Op::i2f : Op::u2f, s);
    }
  }
  return r;
}

Value Lowerer::construct(const Expr* e, const Type& t) {
  std::vector<Value> args;
  for (const Expr* a : e->args) args.push_back(expr(a));
  Value r;
  r.type = t;
  if (t.is_array() || t.is_struct()) {
    for (const Value& a : args) r.s.insert(r.s.end(), a.s.begin(), a.s.end());
    return r;
  }
  const auto n = static_cast<std::size_t>(t.slots());
  if (args.size() == 1 && args[0].type.is_scalar() && n > 1) {
    const Slot s = convert(args[0], t.basic).s[0];
    for (int c = 0; c < t.cols; ++c)
      for (int row = 0; row < t.rows; ++row) r.s.push_back(!t.is_matrix() || c == row ? s : fconst(0.0f));
    return r;
  }
  if (args.size() == 1 && args[0].type.is_matrix() && t.is_matrix()) {
    const Value& m = args[0];
    for (int c = 0; c < t.cols; ++c)
      for (int row = 0; row < t.rows; ++row)
        r.s.push_back(c < m.type.cols && row < m.type.rows
                          ? m.s[static_cast<std::size_t>(c * m.type.rows + row)]
                          : fconst(c == row ? 1.0f : 0.0f));
    return r;
  }
  for (const Value& a : args) {
    const Value c = convert(a, t.basic);
    for (const Slot s : c.s)
      if (r.s.size() < n) r.s.push_back(s);
  }
  return r;
}

Place Lowerer::place(const Expr* e) {
  Place p;
  p.type = e->type;
  if (e->kind == ExprKind::name) {
    p.slots = variable(e->variable).s;
    return p;
  }
  if (e->kind != ExprKind::field && e->kind != ExprKind::index) {
    fail(e->pos, "this expression cannot be assigned to");
    return p;
  }
  const Place base = place(e->args[0]);
  std::vector<std::size_t> pick;  // which of the base's value slots the result takes
  if (e->kind == ExprKind::field) {
    if (e->swizzle_count > 0) {
      for (int i = 0; i < e->swizzle_count; ++i) pick.push_back(e->swizzle[i]);
    } else {
      const auto at =
          static_cast<std::size_t>(base.type.structure->offset(static_cast<std::size_t>(e->field)));
      for (int i = 0; i < e->type.slots(); ++i) pick.push_back(at + static_cast<std::size_t>(i));
    }
  } else if (e->args[1]->constant) {
    const Expr* i = e->args[1];
    const std::vector<std::uint32_t> k = i->value.empty() ? fold_constant(*i) : i->value;
    const auto element = static_cast<std::size_t>(e->type.slots());
    for (std::size_t j = 0; j < element; ++j) pick.push_back((k.empty() ? 0 : k[0]) * element + j);
  } else {
    const Type& t = e->args[0]->type;
    const auto element = static_cast<std::uint32_t>(e->type.slots());
    const auto count = static_cast<std::uint32_t>(t.is_array() ? t.array : t.is_matrix() ? t.cols : t.rows);
    const Slot at = expr(e->args[1]).s[0];
    Place d;
    d.type = e->type, d.dynamic = true;
    if (!base.dynamic) {
      if (!contiguous(Value{base.type, base.slots})) {
        fail(e->pos, "indexing this at run time to assign to it is not supported (assign to a variable)");
        return d;
      }
      d.base = base.slots[0], d.index = at, d.stride = element, d.count = count;
      for (std::uint32_t j = 0; j < element; ++j) d.offsets.push_back(j);
      return d;
    }
    // A second run-time index: one flat index, each part clamped to its own range.
    const Slot outer = emit(
        Op::imul, emit(Op::iclamp, base.index, iconst(0), iconst(static_cast<std::int32_t>(base.count) - 1)),
        iconst(static_cast<std::int32_t>(base.stride)));
    const Slot inner =
        emit(Op::imul, emit(Op::iclamp, at, iconst(0), iconst(static_cast<std::int32_t>(count) - 1)),
             iconst(static_cast<std::int32_t>(element)));
    d.base = base.base, d.index = emit(Op::iadd, outer, inner), d.stride = 1;
    d.count = out_.group_size[out_.group_of[base.base]];
    for (std::uint32_t j = 0; j < element; ++j) d.offsets.push_back(base.offsets[j]);
    return d;
  }
  Place r = base;
  r.type = e->type;
  r.slots.clear(), r.offsets.clear();
  for (const std::size_t k : pick)
    (base.dynamic ? r.offsets.push_back(base.offsets[k]) : r.slots.push_back(base.slots[k]));
  return r;
}

Value Lowerer::read(const Place& p) {
  Value v;
  v.type = p.type;
  if (!p.dynamic) {
    v.s = p.slots;
    return v;
  }
  for (const std::uint32_t o : p.offsets)
    v.s.push_back(emit(Op::load_index, p.base + o, p.index, p.stride, p.count));
  return v;
}

void Lowerer::write(const Place& p, const Value& value) {
  if (p.dynamic) {
    for (std::size_t j = 0; j < p.offsets.size(); ++j)
      emit_to(Op::store_index, p.base + p.offsets[j], value.s[j], p.index, p.stride, p.count);
    return;
  }
  // `v = v.yx`: a source slot written before it is read would be lost; such values are copied first.
  Value v = value;
  for (const Slot s : v.s)
    if (std::find(p.slots.begin(), p.slots.end(), s) != p.slots.end()) {
      v = contiguous_copy(value);
      break;
    }
  if (predicate_) {  // in a predicated if: where the condition holds
    for (std::size_t j = 0; j < p.slots.size(); ++j) emit_to(Op::store_if, p.slots[j], v.s[j], predicate_);
    return;
  }
  for (std::size_t j = 0; j < p.slots.size(); ++j) {
    const bool whole =
        uniform_ || std::find(step_slots_.begin(), step_slots_.end(), p.slots[j]) != step_slots_.end();
    emit_to(whole ? Op::mov : Op::store, p.slots[j], v.s[j]);
  }
}

}  // namespace raster::shader
