// The checker's names, types and declarations, and its driver.
#include <algorithm>
#include <functional>

#include "shader/checker_impl.h"
#include "shader/parser.h"
#include "shader/shadertoy.h"

namespace raster::shader {

void check(Ast& ast, const Folder& fold, Checked& out, Diagnostics& diagnostics) {
  Checker(ast, fold, out, diagnostics).run();
}

Checker::Checker(Ast& ast, const Folder& fold, Checked& out, Diagnostics& diagnostics)
    : ast_(ast), fold_(fold), out_(out), diagnostics_(diagnostics) {}

void Checker::error(SourcePos pos, std::string message) {
  if (pos == last_error_ && pos.line != 0) return;
  last_error_ = pos;
  diagnostics_.error(pos, std::move(message));
}

void Checker::run() {
  scopes_.emplace_back();  // the built-in names
  builtin_variables();
  scopes_.emplace_back();  // the program's globals
  for (const External& e : ast_.externals) {
    if (e.kind == External::Kind::function) function(e.function);
    if (e.kind == External::Kind::declaration) declaration(e.declaration, true);
    if (e.kind == External::Kind::precision) precision_statement(e.declaration);
  }
  recursion();
  undefined_calls();
  out_.main = entry();
  if (!out_.main && !diagnostics_.failed()) error({}, "the shader has no main()");
}

// The entry point: main() without parameters (a program may declare other overloads of main; section 6.1
// asks only that the one it runs take none).
Function* Checker::entry() {
  Symbol* main = lookup("main");
  if (main)
    for (Function* f : main->functions)
      if (f->params.empty() && f->definition) return f;
  return nullptr;
}

Checker::Symbol* Checker::lookup(std::string_view name) {
  for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
    const auto it = s->find(name);
    if (it != s->end()) return &it->second;
  }
  return nullptr;
}

// A new name in the innermost scope: not reserved (section 3.7: keywords, reserved words, the gl_ prefix),
// not a built-in function (ES 3.00 neither redefines nor overloads them), not declared in this scope
// already (functions may share a name with each other).
bool Checker::declarable(std::string_view name, SourcePos pos, bool function) {
  if (name.starts_with("gl_")) {
    error(pos, std::string("'") + quote(name) + "': names beginning with gl_ are reserved");
    return false;
  }
  if (!builtin_overloads(name).empty() && scopes_.size() <= 2) {
    error(pos, std::string("'") + quote(name) +
                   "' is a built-in function, which a shader cannot redefine or overload");
    return false;
  }
  const auto it = scopes_.back().find(name);
  if (it == scopes_.back().end() || (function && !it->second.functions.empty())) return true;
  const Symbol& s = it->second;
  const SourcePos before = s.variable ? s.variable->pos
                           : s.type   ? s.type->pos
                           : s.block  ? s.block->pos
                                      : s.functions.front()->pos;
  if (!frame_clash(name, before, pos))
    error(pos, std::string("'") + quote(name) + "' is already declared in this scope");
  return false;
}

Variable* Checker::make_variable(std::string_view name, const Type& type, SourcePos pos,
                                 Variable::Kind kind) {
  Variable* v = &out_.variables.emplace_back();
  v->name = name, v->type = type, v->pos = pos, v->kind = kind;
  return v;
}

// gl_FragCoord, gl_FrontFacing, gl_PointCoord, gl_FragDepth, and the constants of section 7.4.
void Checker::builtin_variables() {
  Scope& s = scopes_.back();
  const auto input = [&](std::string_view name, Type t, Variable::Kind kind) {
    Variable* v = make_variable(name, t, {}, kind);
    v->qualifier = Qualifier::in;
    s[name].variable = v;
  };
  input("gl_FragCoord", Type::of(Basic::float_, 4), Variable::Kind::frag_coord);
  input("gl_FrontFacing", Type::of(Basic::bool_), Variable::Kind::front_facing);
  input("gl_PointCoord", Type::of(Basic::float_, 2), Variable::Kind::point_coord);
  // gl_FragDepth is a global like the program's own (nothing reads the depth it writes): declared here so
  // that the lowering gives it slots as it does every global of Checked::globals.
  Declaration* depth = Ast::make(ast_.declarations);
  Declarator& d = depth->vars.emplace_back();
  d.name = "gl_FragDepth";
  d.variable = make_variable(d.name, Type::of(Basic::float_), {}, Variable::Kind::global);
  s[d.name].variable = d.variable;
  out_.globals.push_back(depth);
  const std::pair<std::string_view, int> constants[] = {
      {"gl_MaxVertexAttribs", 16},
      {"gl_MaxVertexUniformVectors", 256},
      {"gl_MaxVertexOutputVectors", 16},
      {"gl_MaxFragmentInputVectors", 15},
      {"gl_MaxVertexTextureImageUnits", 16},
      {"gl_MaxCombinedTextureImageUnits", 32},
      {"gl_MaxTextureImageUnits", 16},
      {"gl_MaxFragmentUniformVectors", 224},
      {"gl_MaxDrawBuffers", 4},
      {"gl_MinProgramTexelOffset", -8},
      {"gl_MaxProgramTexelOffset", 7},
  };
  for (const auto& [name, value] : constants) {
    Variable* v = make_variable(name, Type::of(Basic::int_), {}, Variable::Kind::global);
    v->qualifier = Qualifier::const_, v->constant = true;
    v->value = {static_cast<std::uint32_t>(value)};
    s[name].variable = v;
  }
  depth_range(s);
  // Section 4.5.4: a fragment shader's default precisions (float has none; the prelude gives it highp).
  s.precisions = {{precision_key(Type::of(Basic::int_)), Precision::mediump},
                  {precision_key(keyword_type("sampler2D")), Precision::lowp},
                  {precision_key(keyword_type("samplerCube")), Precision::lowp}};
}

// gl_DepthRange (section 7.4), a uniform whose value is GL's default range, near 0 and far 1: a value
// rasterd knows (Variable::constant, so the lowering has it) but not a constant expression (check_expr's
// name() keeps uniforms out of those).
void Checker::depth_range(Scope& s) {
  StructType* st = &out_.structs.emplace_back();
  st->name = "gl_DepthRangeParameters";
  s[st->name].type = st;  // a type a program may name (the parser knows it too)
  for (const std::string_view f : {"near", "far", "diff"})
    st->fields.push_back({f, Type::of(Basic::float_), {}});
  st->slots = 3;
  Type t = Type::of(Basic::structure);
  t.structure = st;
  Variable* v = make_variable("gl_DepthRange", t, {}, Variable::Kind::uniform);
  v->qualifier = Qualifier::uniform, v->constant = true;
  v->value = {0u, 0x3f800000u, 0x3f800000u};  // 0.0f, 1.0f, 1.0f
  s["gl_DepthRange"].variable = v;
}

// The size of an array: a constant integral expression greater than zero.
int Checker::array_size(Expr* size) {
  expr(size);
  if (size->type.is_error()) return 0;
  if (!size->type.is_scalar() || !size->type.is_integer()) {
    error(size->pos, std::string("an array size must be an int or uint, not ") + type_name(size->type));
    return 0;
  }
  std::int64_t n = 0;
  if (!constant_int(size, n)) {
    error(size->pos, "an array size must be a constant expression");
    return 0;
  }
  if (n <= 0 || n > (1 << 24)) {
    error(size->pos, n <= 0 ? "an array size must be greater than zero"
                            : std::string("an array of ") + std::to_string(n) + " elements is too large");
    return 0;
  }
  return static_cast<int>(n);
}

// `type` made an array of `size` elements (`array` false: left alone); an unsized `[]` gives kUnsized.
bool Checker::sized(Type& type, bool array, Expr* size, SourcePos pos) {
  if (!array) return true;
  if (type.is_array()) {
    error(pos, "arrays of arrays are not allowed in GLSL ES 3.00");
    return false;
  }
  if (!size) {
    type.array = Type::kUnsized;
    return true;
  }
  const int n = array_size(size);
  if (n == 0) return false;
  type.array = n;
  return true;
}

StructType* Checker::struct_type(StructDecl* decl) {
  if (decl->type) return decl->type;
  StructType* st = &out_.structs.emplace_back();
  st->name = decl->name, st->pos = decl->pos;
  decl->type = st;
  bool whole = true;
  for (FieldDecl& f : decl->fields) whole &= field(f, st);
  if (!whole) return st;
  if (decl->fields.empty()) error(decl->pos, "a struct needs at least one field");
  for (const Field& f : st->fields) st->slots += f.type.slots();
  if (!decl->name.empty() && declarable(decl->name, decl->pos)) scopes_.back()[decl->name].type = st;
  return st;
}

// One field of a struct or member of a block, added to `st` unless it is in error.
bool Checker::field(FieldDecl& f, StructType* st) {
  if (f.type->definition)
    error(f.type->pos, std::string("a struct cannot be defined inside another struct or a block"));
  Type t = resolve(f.type);
  if (t.is_error()) return false;
  precision(f.type, t);
  if (!sized(t, f.array, f.array_size, f.pos)) return false;
  const char* what = st->block ? "a block's member" : "a struct's field";
  if (t.array == Type::kUnsized) return error(f.pos, std::string(what) + " needs an array size"), false;
  if (t.is_void()) return error(f.pos, std::string(what) + " cannot be void"), false;
  for (const Field& other : st->fields)
    if (other.name == f.name)
      return error(f.pos, std::string("'") + quote(f.name) + "' is declared twice in " + quote(st->name)),
             false;
  if (f.name.starts_with("gl_"))
    error(f.pos, std::string("'") + quote(f.name) + "': names beginning with gl_ are reserved");
  st->fields.push_back({f.name, t, f.pos});
  return true;
}

// The type a TypeSpec names, array part included; Type::error() after reporting why not.
Type Checker::resolve(TypeSpec* spec) {
  Type t = spec->type;
  if (spec->definition) {
    t = Type::of(Basic::structure);
    t.structure = struct_type(spec->definition);
  } else if (!spec->struct_name.empty()) {
    Symbol* s = lookup(spec->struct_name);
    if (!s || !s->type) {
      error(spec->pos, std::string("'") + quote(spec->struct_name) + "' is not a type");
      return Type::error();
    }
    t = Type::of(Basic::structure);
    t.structure = s->type;
  }
  if (spec->precision != Precision::none &&
      !(t.basic == Basic::float_ || t.basic == Basic::int_ || t.basic == Basic::uint_ || t.is_sampler())) {
    error(spec->pos,
          std::string("a precision qualifier applies to float, int, uint and sampler types, not ") +
              type_name(t));
  }
  if (!sized(t, spec->array, spec->array_size, spec->pos)) return Type::error();
  return t;
}

void Checker::declaration(Declaration* d, bool global) {
  if (d->precision_statement) return precision_statement(d);
  if (d->block) return interface_block(d);
  if (!d->type) return qualifiers_alone(d);
  if (!d->invariant_names.empty()) {
    if (!global) error(d->pos, "invariant can only be declared at global scope");
    for (const std::string_view n : d->invariant_names) {
      Symbol* s = lookup(n);
      if (!s || !s->variable || s->variable->kind != Variable::Kind::output)
        error(d->pos, std::string("'") + quote(n) +
                          "' is not an output this shader declared, so it cannot be invariant");
    }
    return;
  }
  const Type base = resolve(d->type);
  if (!base.is_error()) precision(d->type, base);
  if (!global && (d->qualifier == Qualifier::uniform || d->qualifier == Qualifier::in ||
                  d->qualifier == Qualifier::out)) {
    error(d->pos, "in, out and uniform variables are declared at global scope only");
    return;
  }
  if (!global && (!d->layout.empty() || d->invariant || d->interpolation || d->centroid)) {
    error(d->pos, "layout, invariant and interpolation qualifiers apply to global inputs and outputs only");
    return;
  }
  if (global) layout(d->layout, d->qualifier == Qualifier::out ? LayoutUse::output : LayoutUse::none);
  // `float;` declares nothing, which the grammar allows (glslang too); `float[2];` is an error.
  if (d->vars.empty()) {
    if (d->type->array) error(d->pos, "an array declaration needs a name: 'type name[size];'");
    return;
  }
  if (base.is_error()) {
    for (Declarator& v : d->vars)
      if (v.init) expr(v.init);
    return;
  }
  for (Declarator& v : d->vars) declarator(d, base, v, global);
  if (global) out_.globals.push_back(d);
}

void Checker::declarator(Declaration* d, const Type& base, Declarator& v, bool global) {
  if (v.broken) {  // its initializer did not parse: declared without a type, so its uses are quiet
    if (declarable(v.name, v.pos))
      scopes_.back()[v.name].variable = make_variable(v.name, Type::error(), v.pos, Variable::Kind::local);
    return;
  }
  Type t = base;
  if (!sized(t, v.array, v.array_size, v.pos)) return;
  if (v.init) expr(v.init);
  if (t.array == Type::kUnsized) {
    if (!v.init || !v.init->type.is_array()) {
      if (!v.init || !v.init->type.is_error())
        error(v.pos, std::string("'") + quote(v.name) + "' needs an array size or an array to initialize it");
      return;
    }
    t.array = v.init->type.array;
  }
  const bool is_const = d->qualifier == Qualifier::const_;
  if (t.is_void()) return error(v.pos, std::string("'") + quote(v.name) + "' cannot be void");
  if (t.has_sampler() && d->qualifier != Qualifier::uniform)
    return error(v.pos, std::string("'") + quote(v.name) +
                            "': a sampler is declared as a uniform or a parameter only");
  if (is_const && !v.init)
    return error(v.pos, std::string("const '") + quote(v.name) + "' needs an initializer");
  if (v.init && !v.init->type.is_error()) {
    if (d->qualifier == Qualifier::uniform || d->qualifier == Qualifier::in || d->qualifier == Qualifier::out)
      return error(
          v.pos, std::string("'") + quote(v.name) + "': in, out and uniform variables cannot be initialized");
    if (!(v.init->type == t))
      return error(v.init->pos, std::string("cannot initialize '") + quote(v.name) + std::string("' (") +
                                    type_name(t) + ") with " + type_name(v.init->type));
    if ((is_const || global) && !v.init->constant)
      return error(v.init->pos, std::string(is_const ? "a const variable's" : "a global variable's") +
                                    " initializer must be a constant expression");
  }
  if (!declarable(v.name, v.pos)) return;
  Variable* var = make_variable(v.name, t, v.pos, global ? Variable::Kind::global : Variable::Kind::local);
  var->qualifier = d->qualifier;
  if (is_const && v.init && !v.init->type.is_error()) {
    var->value = fold_(*v.init);
    var->constant = var->value.size() == static_cast<std::size_t>(t.slots());
  }
  if (global) global_kind(d, var);
  scopes_.back()[v.name].variable = var;
  v.variable = var;
}

namespace {

// Whether `t` or a field of it (at any depth) is a type `is` picks.
template <class Pick>
bool holds(const Type& t, const Pick& is) {
  if (!t.is_struct()) return is(t);
  for (const Field& f : t.structure->fields)
    if (holds(f.type, is)) return true;
  return false;
}

}  // namespace

// What a global's storage qualifier makes it: a uniform (ShaderToy's iChannel0..3 are the sampler2D
// uniforms bound to images), an input, the fragment's output.
void Checker::global_kind(Declaration* d, Variable* v) {
  const Type& t = v->type;
  const bool in_or_out = d->qualifier == Qualifier::in || d->qualifier == Qualifier::out;
  if (d->invariant && d->qualifier != Qualifier::out)
    error(v->pos, "only outputs can be invariant");
  else if ((d->interpolation || d->centroid) && !in_or_out)
    error(v->pos, "flat, smooth and centroid qualify inputs and outputs only");
  if (d->qualifier == Qualifier::uniform) {
    v->kind = Variable::Kind::uniform;
    out_.uniforms.push_back(v);
    if (t.is_sampler() && t.sampler == SamplerKind::sampler2D && !t.is_array() && v->name.size() == 9 &&
        v->name.starts_with("iChannel") && v->name[8] >= '0' && v->name[8] <= '3')
      v->channel = v->name[8] - '0';
  } else if (d->qualifier == Qualifier::in) {
    v->kind = Variable::Kind::input;
    if (holds(t, [](const Type& f) { return f.basic == Basic::bool_ || f.is_sampler(); }))
      error(v->pos, "a fragment shader's input cannot be or hold a bool or a sampler");
    else if (holds(t, [](const Type& f) { return f.is_integer(); }) && !d->flat)
      error(v->pos, std::string("'") + quote(v->name) + "': an input that is or holds integers must be flat");
  } else if (d->qualifier == Qualifier::out) {
    v->kind = Variable::Kind::output;
    if (t.basic == Basic::bool_ || t.is_matrix() || t.is_struct() || t.is_sampler())
      error(v->pos, "a fragment shader's output must be a float, int or uint scalar or vector");
    else if (out_.output && out_.output->pos.string == kProgramString && v->pos.string == kEpilogueString)
      error(out_.output->pos, std::string("'") + quote(out_.output->name) +
                                  "': a ShaderToy program declares no output (ShaderToy's frame declares the "
                                  "fragment's one output, which mainImage's fragColor writes)");
    else if (out_.output)
      error(v->pos, std::string("this shader has one output, '") + quote(out_.output->name) + "', already");
    else
      out_.output = v;
  }
}

}  // namespace raster::shader
