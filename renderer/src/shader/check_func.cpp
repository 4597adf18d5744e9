// The checker's functions: signatures, prototypes and definitions, and the whole-program rules on calls
// (section 6.1: no recursion, static or through other functions; every function called has a body).
#include <functional>

#include "shader/checker_impl.h"

namespace raster::shader {

// The Function a declaration names: found (a prototype seen before, or the definition after one) or made.
Function* Checker::signature(FunctionDecl* f) {
  const Type ret = resolve(f->ret);
  bool ok = !ret.is_error();
  if (ok) precision(f->ret, ret);
  if (ok && ret.array == Type::kUnsized)
    error(f->ret->pos, "a function's return type needs an array size"), ok = false;
  // Samplers are parameters and uniforms only (section 4.1.7); a struct holding one may be returned.
  if (ok && ret.basic == Basic::sampler) error(f->ret->pos, "a function cannot return a sampler"), ok = false;
  std::vector<Type> params;
  std::vector<Qualifier> qualifiers;
  std::vector<Precision> precisions;
  for (ParamDecl& p : f->params) {
    Type t = resolve(p.type);
    if (t.is_error() || !sized(t, p.array, p.array_size, p.pos)) {
      ok = false;
      continue;
    }
    if (t.array == Type::kUnsized) error(p.pos, "a parameter needs an array size"), ok = false;
    if (t.is_void()) error(p.pos, "a parameter cannot be void"), ok = false;
    if (t.basic == Basic::sampler && (p.qualifier == Qualifier::out || p.qualifier == Qualifier::inout))
      error(p.pos, "a sampler parameter can only be in"), ok = false;
    params.push_back(t);
    qualifiers.push_back(p.qualifier);
    precisions.push_back(precision(p.type, t));
  }
  if (!ok) return nullptr;
  Symbol* s = lookup(f->name);
  if (s && !s->functions.empty() && scopes_.back().count(f->name)) {
    for (Function* fn : s->functions)
      if (fn->params == params) return same_signature(f, fn, ret, qualifiers, precisions) ? fn : nullptr;
  }
  if (!declarable(f->name, f->pos, true)) return nullptr;
  Function* fn = &out_.functions.emplace_back();
  fn->name = f->name, fn->ret = ret, fn->params = params, fn->qualifiers = qualifiers, fn->pos = f->pos;
  fn->precisions = precisions;
  scopes_.back()[f->name].functions.push_back(fn);
  return fn;
}

// A prototype and the definition (or another prototype) of one function agree on the return type and on
// every parameter's qualifiers, const and precision included (section 6.1).
bool Checker::same_signature(FunctionDecl* f, Function* fn, const Type& ret,
                             const std::vector<Qualifier>& qualifiers,
                             const std::vector<Precision>& precisions) {
  if (!(fn->ret == ret)) {
    if (!frame_clash(f->name, fn->pos, f->pos))
      error(f->pos, std::string("'") + quote(f->name) + "' is declared again with a different return type");
    return false;
  }
  for (std::size_t i = 0; i < qualifiers.size(); ++i) {
    const char* what = fn->qualifiers[i] != qualifiers[i]   ? "qualifiers (in, out, inout, const)"
                       : fn->precisions[i] != precisions[i] ? "precision"
                                                            : nullptr;
    if (what) {
      error(f->params[i].pos, std::string("'") + quote(f->name) + "' is declared again with another " + what +
                                  " for parameter " + std::to_string(i + 1));
      return false;
    }
  }
  return true;
}

// main (section 6.1 and 7): the entry point takes no parameters and returns nothing.
void Checker::entry_point(FunctionDecl* f, const Function* fn) {
  if (f->name != "main") return;
  if (!fn->params.empty()) error(f->pos, "main takes no parameters");
  if (!fn->ret.is_void()) error(f->ret->pos, "main returns void");
}

void Checker::function(FunctionDecl* f) {
  Function* fn = signature(f);
  if (!fn || !f->body) return;
  if (fn->definition) {
    if (!frame_clash(f->name, fn->definition->pos, f->pos))
      error(f->pos, std::string("'") + quote(f->name) + "' with these parameters already has a body");
    return;
  }
  entry_point(f, fn);
  fn->definition = f;
  function_ = fn;
  returned_ = false;
  scopes_.emplace_back();  // the parameters and the body's outermost statements share one scope
  for (std::size_t i = 0; i < f->params.size(); ++i) {
    const ParamDecl& p = f->params[i];
    Variable* v = make_variable(p.name, fn->params[i], p.pos, Variable::Kind::parameter);
    v->qualifier = fn->qualifiers[i];
    fn->parameters.push_back(v);
    if (!p.name.empty() && declarable(p.name, p.pos)) scopes_.back()[p.name].variable = v;
  }
  block(f->body);
  scopes_.pop_back();
  // As glslang has it: some return statement, not one on every path (those are undefined, not errors).
  if (!fn->ret.is_void() && !returned_)
    error(f->pos, std::string("'") + quote(f->name) + "' must return a " + type_name(fn->ret) +
                      ", but its body has no return statement");
  function_ = nullptr;
}

// A call cycle anywhere in the program is an error, reported once at a function of the cycle.
void Checker::recursion() {
  enum : char { fresh, open, done };
  std::unordered_map<const Function*, char> state;
  std::function<bool(Function*)> visit = [&](Function* f) {
    state[f] = open;
    for (std::size_t i = 0; i < f->calls.size(); ++i) {
      Function* g = f->calls[i];
      const char s = state[g];
      if (s == open) {
        error(f->call_positions[i],
              std::string("'") + quote(g->name) + std::string("' is called recursively (") + quote(f->name) +
                  std::string(" calls ") + quote(g->name) + "), which GLSL does not allow");
        return true;
      }
      if (s == fresh && visit(g)) return true;
    }
    state[f] = done;
    return false;
  };
  for (Function& f : out_.functions)
    if (state[&f] == fresh && visit(&f)) return;
}

// Every function reachable from main must have a body (a prototype alone cannot run).
void Checker::undefined_calls() {
  Function* main = entry();
  if (!main) return;
  std::unordered_map<const Function*, bool> seen;
  std::vector<Function*> todo = {main};
  while (!todo.empty()) {
    Function* f = todo.back();
    todo.pop_back();
    for (std::size_t i = 0; i < f->calls.size(); ++i) {
      Function* g = f->calls[i];
      if (!g->definition)
        error(f->call_positions[i], std::string("'") + quote(g->name) + "' is called but has no body");
      if (!seen[g]) seen[g] = true, todo.push_back(g);
    }
  }
}

}  // namespace raster::shader
