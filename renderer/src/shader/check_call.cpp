// The checker's calls and constructors (sections 5.4 and 6.1): overloads matched exactly, out arguments
// that are l-values, constructors' argument counts, and the constant offsets texture functions need.
#include "shader/checker_impl.h"
#include "shader/shadertoy.h"

namespace raster::shader {

std::string Checker::argument_types(const Expr* e) const {
  std::string s = "(";
  for (std::size_t i = 0; i < e->args.size(); ++i) s += (i ? ", " : "") + type_name(e->args[i]->type);
  return s + ")";
}

void Checker::call(Expr* e) {
  bool failed = false;
  for (Expr* a : e->args) {
    expr(a);
    failed |= a->type.is_error();
  }
  Symbol* s = lookup(e->name);
  if (s && s->type) {  // a struct's constructor
    if (failed) return;
    Type t = Type::of(Basic::structure);
    t.structure = s->type;
    return construct_type(e, t);
  }
  if (s && s->variable)
    return error(e->pos, std::string("'") + quote(e->name) + "' is a variable, not a function");
  if (s && s->block)
    return error(e->pos, std::string("'") + quote(e->name) + "' is a uniform block's name, not a function");
  const std::vector<const Builtin*>& builtins = builtin_overloads(e->name);
  if (!s && builtins.empty()) {
    if (e->pos.string == kEpilogueString)
      return error(e->pos, std::string("the program has no function '") + quote(e->name) +
                               "', which ShaderToy's frame calls with " + argument_types(e));
    return error(e->pos, std::string("no function '") + quote(e->name) + "' is declared");
  }
  if (failed) return;
  if (s && call_user(e, s->functions)) return;
  if (!s && call_builtin(e, builtins)) return;
  // ShaderToy's frame calling a function the program declares with other parameters: said at the program's.
  if (s && e->pos.string == kEpilogueString && s->functions.front()->pos.string == kProgramString)
    return error(s->functions.front()->pos, std::string("ShaderToy's frame calls '") + quote(e->name) +
                                                "' with " + argument_types(e) +
                                                ", which no declaration of it in the program takes");
  error(e->pos,
        std::string("no overload of '") + quote(e->name) + std::string("' takes ") + argument_types(e));
}

bool Checker::call_user(Expr* e, const std::vector<Function*>& overloads) {
  for (Function* f : overloads) {
    if (f->params.size() != e->args.size()) continue;
    bool match = true;
    for (std::size_t i = 0; i < f->params.size() && match; ++i) match = f->params[i] == e->args[i]->type;
    if (!match) continue;
    e->function = f;
    e->type = f->ret;
    out_arguments(e, f->qualifiers);
    if (function_) function_->calls.push_back(f), function_->call_positions.push_back(e->pos);
    return true;
  }
  return false;
}

bool Checker::call_builtin(Expr* e, const std::vector<const Builtin*>& overloads) {
  for (const Builtin* b : overloads) {
    if (b->params.size() != e->args.size()) continue;
    bool match = true;
    for (std::size_t i = 0; i < b->params.size() && match; ++i) match = b->params[i] == e->args[i]->type;
    if (!match) continue;
    e->builtin = b;
    e->type = b->ret;
    out_arguments(e, b->qualifiers);
    bool constant = b->constant;
    for (const Expr* a : e->args) constant &= a->constant;
    e->constant = constant;
    texture_offset(e);
    return true;
  }
  return false;
}

// out and inout arguments must be l-values (section 6.1.1); they are written by the call.
void Checker::out_arguments(Expr* e, const std::vector<Qualifier>& qualifiers) {
  for (std::size_t i = 0; i < qualifiers.size(); ++i)
    if (qualifiers[i] == Qualifier::out || qualifiers[i] == Qualifier::inout)
      lvalue(e->args[i], "pass as out");
}

// The offset of the *Offset texture functions is a constant expression within the texel offset range.
void Checker::texture_offset(Expr* e) {
  const BuiltinOp op = e->builtin->op;
  if (op != BuiltinOp::texture_offset && op != BuiltinOp::texel_fetch_offset &&
      op != BuiltinOp::texture_proj_offset && op != BuiltinOp::texture_lod_offset &&
      op != BuiltinOp::texture_proj_lod_offset && op != BuiltinOp::texture_grad_offset &&
      op != BuiltinOp::texture_proj_grad_offset)
    return;
  // The offset is the argument of ivec type (the last, or before a bias).
  for (Expr* a : e->args) {
    if (a->type.basic != Basic::int_ || !a->type.is_vector()) continue;
    if (op == BuiltinOp::texel_fetch_offset && a == e->args[1]) continue;  // the coordinate
    if (!a->constant) return error(a->pos, "a texture offset must be a constant expression");
    if (a->value.empty()) a->value = fold_(*a);
    for (const std::uint32_t v : a->value) {
      const int o = static_cast<std::int32_t>(v);
      if (o < -8 || o > 7) return error(a->pos, "a texture offset must be within -8 and 7");
    }
  }
}

void Checker::construct(Expr* e) {
  Type t = resolve(e->spec);  // no precision(): a constructor's type is not declared
  bool failed = t.is_error();
  for (Expr* a : e->args) {
    expr(a);
    failed |= a->type.is_error();
  }
  if (failed) return;
  if (t.array == Type::kUnsized) {
    if (e->args.empty()) return error(e->pos, "an array constructor needs at least one element");
    t.array = static_cast<std::int32_t>(e->args.size());
  }
  construct_type(e, t);
}

void Checker::construct_type(Expr* e, const Type& t) {
  bool constant = true;
  for (const Expr* a : e->args) constant &= a->constant;
  if (t.is_array() || t.is_struct()) {
    std::vector<Type> expected;
    if (t.is_array())
      expected.assign(static_cast<std::size_t>(t.array), t.element());
    else
      for (const Field& f : t.structure->fields) expected.push_back(f.type);
    if (e->args.size() != expected.size())
      return error(e->pos, type_name(t) + std::string("'s constructor takes ") +
                               std::to_string(expected.size()) + std::string(" argument") +
                               (expected.size() == 1 ? "" : "s") + ", given " +
                               std::to_string(e->args.size()));
    for (std::size_t i = 0; i < expected.size(); ++i)
      if (!(e->args[i]->type == expected[i]))
        return error(e->args[i]->pos, type_name(t) + std::string("'s constructor needs a ") +
                                          type_name(expected[i]) + std::string(" here, not ") +
                                          type_name(e->args[i]->type));
    e->type = t;
    e->constant = constant;
    return;
  }
  if (t.is_sampler() || t.is_void()) return error(e->pos, type_name(t) + " has no constructor");
  construct_plain(e, t);
  if (!e->type.is_error()) e->constant = constant;
}

// Scalars, vectors and matrices (section 5.4.1-2): from one scalar (spread, or a matrix's diagonal), one
// matrix (a matrix from a matrix), or components taken in order, every argument used.
void Checker::construct_plain(Expr* e, const Type& t) {
  const std::string name = type_name(t);
  if (e->args.empty()) return error(e->pos, name + "'s constructor needs arguments");
  int components = 0;
  for (std::size_t i = 0; i < e->args.size(); ++i) {
    const Type& a = e->args[i]->type;
    if (!a.is_plain())
      return error(e->args[i]->pos, name + std::string("'s constructor cannot take ") + type_name(a) +
                                        " (only scalars, vectors and matrices)");
    if (a.is_matrix() && t.is_matrix() && e->args.size() > 1)
      return error(e->args[i]->pos, "a matrix built from a matrix takes nothing else");
    if (components >= t.components())
      return error(e->args[i]->pos, name + "'s constructor is given more than it uses");
    components += a.components();
  }
  const bool one = e->args.size() == 1 &&
                   (e->args[0]->type.is_scalar() || (t.is_matrix() && e->args[0]->type.is_matrix()));
  if (!one && !t.is_scalar() && components < t.components())
    return error(e->pos, name + std::string("'s constructor is given ") + std::to_string(components) +
                             std::string(" components of the ") + std::to_string(t.components()) +
                             " it needs");
  if (t.is_scalar() && e->args.size() != 1) return error(e->pos, name + "'s constructor takes one argument");
  e->type = t;
}

}  // namespace raster::shader
