// The checker's expressions (chapter 5): each node's type, with no implicit conversion, and whether it is a
// constant expression (section 4.3.3).
#include "shader/checker_impl.h"

namespace raster::shader {
namespace {

bool is_bool_scalar(const Type& t) {
  return t.is_scalar() && t.basic == Basic::bool_;
}

// A uniform block's instance: a name for its members, not a value to compare.
bool is_block(const Type& t) {
  return t.is_struct() && t.structure->block;
}

// Swizzle letters (section 5.5): one of the three sets, component index or -1.
int swizzle_component(char c, int& set) {
  static constexpr std::string_view kSets[3] = {"xyzw", "rgba", "stpq"};
  for (int s = 0; s < 3; ++s) {
    const std::size_t i = kSets[s].find(c);
    if (i == std::string_view::npos) continue;
    if (set >= 0 && set != s) return -2;  // mixes sets
    set = s;
    return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

bool Checker::constant_int(Expr* e, std::int64_t& value) {
  if (!e->constant) return false;
  if (e->value.empty()) e->value = fold_(*e);
  if (e->value.size() != 1) return false;
  value = e->type.basic == Basic::uint_ ? static_cast<std::int64_t>(e->value[0])
                                        : static_cast<std::int64_t>(static_cast<std::int32_t>(e->value[0]));
  return true;
}

void Checker::expr(Expr* e) {
  switch (e->kind) {
    case ExprKind::literal:
      e->constant = true;
      e->value = {e->bits};
      return;
    case ExprKind::name:
      return name(e);
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
      return call(e);
    case ExprKind::construct:
      return construct(e);
    case ExprKind::field:
      return field(e);
    case ExprKind::index:
      return index(e);
    case ExprKind::length:
      return length(e);
    case ExprKind::sequence:
      expr(e->args[0]);
      expr(e->args[1]);
      e->type = e->args[1]->type;
      return;
  }
}

void Checker::name(Expr* e) {
  Symbol* s = lookup(e->name);
  if (!s) return error(e->pos, std::string("'") + quote(e->name) + "' is not declared");
  if (s->type) return error(e->pos, std::string("'") + quote(e->name) + "' is a type, not a value");
  if (s->block)
    return error(e->pos, std::string("'") + quote(e->name) +
                             "' is a uniform block's name, not a value (its instance name, or its members' "
                             "names, are)");
  if (!s->variable) return error(e->pos, std::string("'") + quote(e->name) + "' is a function, not a value");
  e->variable = s->variable;
  e->type = s->variable->type;
  // A uniform is never a constant expression, even one whose value rasterd knows (gl_DepthRange).
  e->constant = s->variable->constant && s->variable->kind != Variable::Kind::uniform;
  if (e->constant) e->value = s->variable->value;
}

// Marks what `e` writes as written, after checking that it is an l-value (section 5.8): a variable that
// is not const, a uniform or a shader input, or a field, element or swizzle (no component twice) of one.
bool Checker::lvalue(Expr* e, std::string_view action) {
  Expr* base = e;
  for (;;) {
    if (base->type.is_error()) return false;
    if (base->kind == ExprKind::field) {
      for (int i = 0; i < base->swizzle_count; ++i)
        for (int j = 0; j < i; ++j)
          if (base->swizzle[i] == base->swizzle[j]) {
            error(base->pos,
                  std::string("cannot ") + std::string(action) + " a swizzle that names a component twice");
            return false;
          }
      base = base->args[0];
    } else if (base->kind == ExprKind::index) {
      base = base->args[0];
    } else {
      break;
    }
  }
  if (base->kind != ExprKind::name || !base->variable) {
    error(e->pos, std::string("cannot ") + std::string(action) + " this expression: it is not a variable");
    return false;
  }
  Variable* v = base->variable;
  const char* why = v->qualifier == Qualifier::const_ || v->qualifier == Qualifier::const_in ? "const"
                    : v->kind == Variable::Kind::uniform                                     ? "a uniform"
                    : v->kind == Variable::Kind::input || v->kind == Variable::Kind::frag_coord ||
                            v->kind == Variable::Kind::front_facing || v->kind == Variable::Kind::point_coord
                        ? "an input"
                        : nullptr;
  if (why) {
    error(e->pos, std::string("cannot ") + std::string(action) + std::string(" '") + quote(v->name) +
                      std::string("': it is ") + why);
    return false;
  }
  v->written = true;
  return true;
}

void Checker::unary(Expr* e) {
  Expr* a = e->args[0];
  expr(a);
  const Type& t = a->type;
  if (t.is_error()) return;
  const std::string op(spelling(e->op));
  bool ok = false;
  switch (e->op) {
    case Punct::plus:
    case Punct::minus:
      ok = !t.is_array() && t.is_numeric();
      break;
    case Punct::bang:
      ok = is_bool_scalar(t);
      break;
    case Punct::tilde:
      ok = !t.is_array() && t.is_integer() && !t.is_matrix();
      break;
    default:  // ++ and --
      ok = !t.is_array() && t.is_numeric();
      if (ok && !lvalue(a, op == "++" ? "increment" : "decrement")) return;
      break;
  }
  if (!ok) return error(e->pos, std::string("'") + op + std::string("' cannot apply to ") + type_name(t));
  e->type = t;
  e->constant =
      a->constant &&
      (e->op == Punct::plus || e->op == Punct::minus || e->op == Punct::bang || e->op == Punct::tilde) &&
      e->kind == ExprKind::unary;
}

// The type of `a op b` (section 5.9), or error() with `why` set.
Type Checker::operation(Punct op, const Type& a, const Type& b, std::string& why) {
  const auto fail = [&](std::string w) {
    why = std::move(w);
    return Type::error();
  };
  if (a.is_array() || b.is_array() || a.is_struct() || b.is_struct() || a.is_sampler() || b.is_sampler() ||
      a.is_void() || b.is_void())
    return fail("no operand of it can be an array, struct, sampler or void");
  switch (op) {
    case Punct::and_and:
    case Punct::or_or:
    case Punct::xor_xor:
      if (!is_bool_scalar(a) || !is_bool_scalar(b)) return fail("it needs two bool operands");
      return a;
    case Punct::less:
    case Punct::greater:
    case Punct::le:
    case Punct::ge:
      if (!a.is_scalar() || !a.is_numeric() || !(a == b))
        return fail("it compares two scalars of one numeric type (lessThan and others compare vectors)");
      return Type::of(Basic::bool_);
    case Punct::eq:
    case Punct::ne:
      if (!(a == b)) return fail("it compares two values of one type");
      return Type::of(Basic::bool_);
    case Punct::shl:
    case Punct::shr:
      if (!a.is_integer() || !b.is_integer() || a.is_matrix() || b.is_matrix())
        return fail("shifts take integer scalars and vectors");
      if (a.is_scalar() ? !b.is_scalar() : !(b.is_scalar() || b.rows == a.rows))
        return fail("the shift count must be a scalar, or a vector the size of the value shifted");
      return a;
    default:
      break;
  }
  // Arithmetic (+ - * / %) and bitwise (& | ^): one basic type, scalars spread over vectors and matrices.
  const bool bitwise = op == Punct::amp || op == Punct::pipe || op == Punct::caret;
  if (a.basic != b.basic || !a.is_numeric()) return fail("both operands must be of one numeric type");
  if ((bitwise || op == Punct::percent) && !a.is_integer()) return fail("it needs integer operands");
  if (a.is_scalar()) return b;
  if (b.is_scalar()) return a;
  if (op == Punct::star && (a.is_matrix() || b.is_matrix())) {
    // Linear algebra: a row vector times a matrix takes the matrix's rows; otherwise the left's columns
    // must match the right's rows.
    if (a.is_vector()) {
      if (a.rows != b.rows) return fail("the vector's size must match the matrix's rows");
      return Type::of(Basic::float_, b.cols);
    }
    if (a.cols != b.rows) return fail("the left's columns must match the right's rows");
    return b.is_vector() ? Type::of(Basic::float_, a.rows) : Type::of(Basic::float_, a.rows, b.cols);
  }
  if (!(a == b)) return fail("vectors and matrices must be the same size");
  return a;
}

void Checker::binary(Expr* e) {
  expr(e->args[0]);
  expr(e->args[1]);
  const Type &a = e->args[0]->type, &b = e->args[1]->type;
  if (a.is_error() || b.is_error()) return;
  std::string why;
  if (is_block(a) || is_block(b))
    return error(e->pos, std::string("'") + std::string(spelling(e->op)) +
                             "' cannot apply to a uniform block (only to its members)");
  if ((e->op == Punct::eq || e->op == Punct::ne) && a == b && !a.has_sampler()) {
    e->type = Type::of(Basic::bool_);
  } else {
    e->type = operation(e->op, a, b, why);
    if (e->type.is_error())
      return error(e->pos, std::string("'") + std::string(spelling(e->op)) +
                               std::string("' cannot apply to ") + type_name(a) + std::string(" and ") +
                               type_name(b) + std::string(": ") + why);
  }
  // Integer division by zero, constant or not, is no error: its value is undefined (section 5.9).
  e->constant = e->args[0]->constant && e->args[1]->constant;
}

void Checker::assign(Expr* e) {
  expr(e->args[0]);
  expr(e->args[1]);
  const Type &a = e->args[0]->type, &b = e->args[1]->type;
  if (a.is_error() || b.is_error()) return;
  if (!lvalue(e->args[0], "assign to")) return;
  e->type = a;
  if (e->op == Punct::assign) {
    if (a.has_sampler()) return error(e->pos, "a sampler cannot be assigned"), void(e->type = Type::error());
    if (!(a == b))
      error(e->pos, std::string("cannot assign ") + type_name(b) + std::string(" to ") + type_name(a));
    return;
  }
  // a op= b is a = a op b, whose type must be a's.
  static constexpr std::pair<Punct, Punct> kOps[] = {
      {Punct::add_assign, Punct::plus},    {Punct::sub_assign, Punct::minus},
      {Punct::mul_assign, Punct::star},    {Punct::div_assign, Punct::slash},
      {Punct::mod_assign, Punct::percent}, {Punct::shl_assign, Punct::shl},
      {Punct::shr_assign, Punct::shr},     {Punct::and_assign, Punct::amp},
      {Punct::or_assign, Punct::pipe},     {Punct::xor_assign, Punct::caret}};
  Punct op = Punct::none;
  for (const auto& [compound, plain] : kOps)
    if (compound == e->op) op = plain;
  std::string why;
  const Type r = operation(op, a, b, why);
  if (r.is_error() || !(r == a))
    error(e->pos, std::string("'") + std::string(spelling(e->op)) + std::string("' cannot apply to ") +
                      type_name(a) + " and " + type_name(b) +
                      (why.empty() ? std::string(": the result would not be ") + type_name(a)
                                   : std::string(": ") + why));
}

void Checker::ternary(Expr* e) {
  for (Expr* a : e->args) expr(a);
  const Type &c = e->args[0]->type, &a = e->args[1]->type, &b = e->args[2]->type;
  if (c.is_error() || a.is_error() || b.is_error()) return;
  if (!is_bool_scalar(c))
    return error(e->args[0]->pos, std::string("?: needs a bool condition, not ") + type_name(c));
  if (!(a == b))
    return error(e->pos, std::string("?:'s two values must be of one type, not ") + type_name(a) +
                             std::string(" and ") + type_name(b));
  // Section 4.1.7 keeps samplers out of expressions; a struct holding one is a value like others (glslang
  // too), and rasterd binds only ShaderToy's channels, which no struct holds.
  if (a.is_sampler()) return error(e->pos, "?: cannot choose between samplers");
  e->type = a;
  e->constant = e->args[0]->constant && e->args[1]->constant && e->args[2]->constant;
}

void Checker::field(Expr* e) {
  Expr* a = e->args[0];
  expr(a);
  const Type& t = a->type;
  if (t.is_error()) return;
  if (t.is_struct()) {
    const auto& fields = t.structure->fields;
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (fields[i].name == e->name) {
        e->field = static_cast<int>(i);
        e->type = fields[i].type;
        e->constant = a->constant;
        return;
      }
    return error(e->pos, type_name(t) + std::string(" has no field '") + quote(e->name) + "'");
  }
  if (!t.is_vector() && !t.is_scalar()) return error(e->pos, type_name(t) + " has no fields or components");
  if (t.is_scalar()) return error(e->pos, "a scalar cannot be swizzled in GLSL ES 3.00");
  if (e->name.size() > 4) return error(e->pos, "a swizzle names at most four components");
  int set = -1;
  for (std::size_t i = 0; i < e->name.size(); ++i) {
    const int c = swizzle_component(e->name[i], set);
    if (c == -2)
      return error(e->pos, std::string("swizzle '") + quote(e->name) + "' mixes xyzw, rgba and stpq");
    if (c < 0)
      return error(e->pos,
                   std::string("'") + quote(e->name) + std::string("' is not a swizzle of ") + type_name(t));
    if (c >= t.rows)
      return error(e->pos, std::string("swizzle '") + quote(e->name) + std::string("' reaches past a ") +
                               type_name(t));
    e->swizzle[i] = static_cast<std::uint8_t>(c);
  }
  e->swizzle_count = static_cast<std::uint8_t>(e->name.size());
  e->type = Type::of(t.basic, e->swizzle_count);
  e->constant = a->constant;
}

void Checker::index(Expr* e) {
  Expr *a = e->args[0], *i = e->args[1];
  expr(a);
  expr(i);
  const Type& t = a->type;
  if (t.is_error() || i->type.is_error()) return;
  if (!t.is_array() && !t.is_vector() && !t.is_matrix())
    return error(e->pos, type_name(t) + " cannot be indexed (only arrays, vectors and matrices)");
  if (!i->type.is_scalar() || !i->type.is_integer())
    return error(i->pos, std::string("an index must be an int or uint, not ") + type_name(i->type));
  const int size = t.is_array() ? t.array : t.is_matrix() ? t.cols : t.rows;
  std::int64_t at = 0;
  if (constant_int(i, at) && (at < 0 || at >= size))
    return error(i->pos, std::string("index ") + std::to_string(at) + std::string(" is outside ") +
                             type_name(t) + " (0 to " + std::to_string(size - 1) + ")");
  if (t.is_array() && t.basic == Basic::sampler && !i->constant)
    return error(i->pos, "an array of samplers is indexed by constant expressions only");
  if (t.is_array() && is_block(t) && !i->constant)
    return error(i->pos, "an array of uniform blocks is indexed by constant expressions only");
  e->type = t.element();
  e->constant = a->constant && i->constant;
}

void Checker::length(Expr* e) {
  expr(e->args[0]);
  const Type& t = e->args[0]->type;
  if (t.is_error()) return;
  if (!t.is_array()) return error(e->pos, std::string("length() applies to arrays, not ") + type_name(t));
  e->type = Type::of(Basic::int_);
  e->constant = true;
  e->value = {static_cast<std::uint32_t>(t.array)};
}

}  // namespace raster::shader
