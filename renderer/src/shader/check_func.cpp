// The checker's functions: signatures, prototypes and definitions, and the whole-program rules on calls
// (section 6.1: no recursion, static or through other functions; every function called has a body).
#include <functional>

#include "shader/checker_impl.h"

namespace raster::shader {

// The Function a declaration names: found (a prototype seen before, or the definition after one) or made.
Function* Checker::signature(FunctionDecl* f) {
  const Type ret = resolve(f->ret);
  bool ok = !ret.is_error();
  if (ok && ret.array == Type::kUnsized)
    error(f->ret->pos, "a function's return type needs an array size"), ok = false;
  if (ok && ret.has_sampler()) error(f->ret->pos, "a function cannot return a sampler"), ok = false;
  std::vector<Type> params;
  std::vector<Qualifier> qualifiers;
  for (ParamDecl& p : f->params) {
    Type t = resolve(p.type);
    if (t.is_error() || !sized(t, p.array, p.array_size, p.pos)) {
      ok = false;
      continue;
    }
    if (t.array == Type::kUnsized) error(p.pos, "a parameter needs an array size"), ok = false;
    if (t.is_void()) error(p.pos, "a parameter cannot be void"), ok = false;
    if (t.has_sampler() && (p.qualifier == Qualifier::out || p.qualifier == Qualifier::inout))
      error(p.pos, "a sampler parameter can only be in"), ok = false;
    params.push_back(t);
    qualifiers.push_back(p.qualifier == Qualifier::const_in ? Qualifier::const_in : p.qualifier);
  }
  if (!ok) return nullptr;
  Symbol* s = lookup(f->name);
  if (s && !s->functions.empty() && scopes_.back().count(f->name)) {
    for (Function* fn : s->functions) {
      if (fn->params != params) continue;
      if (!(fn->ret == ret)) {
        error(f->pos, std::string("'") + quote(f->name) + "' is declared again with a different return type");
        return nullptr;
      }
      for (std::size_t i = 0; i < params.size(); ++i) {
        const auto in = [](Qualifier q) { return q == Qualifier::const_in ? Qualifier::in : q; };
        if (in(fn->qualifiers[i]) != in(qualifiers[i])) {
          error(f->params[i].pos,
                std::string("'") + quote(f->name) + "' is declared again with other parameter qualifiers");
          return nullptr;
        }
      }
      return fn;
    }
  }
  if (!declarable(f->name, f->pos, true)) return nullptr;
  Function* fn = &out_.functions.emplace_back();
  fn->name = f->name, fn->ret = ret, fn->params = params, fn->qualifiers = qualifiers, fn->pos = f->pos;
  scopes_.back()[f->name].functions.push_back(fn);
  return fn;
}

void Checker::function(FunctionDecl* f) {
  Function* fn = signature(f);
  if (!fn || !f->body) return;
  if (fn->definition) {
    error(f->pos, std::string("'") + quote(f->name) + "' with these parameters already has a body");
    return;
  }
  fn->definition = f;
  function_ = fn;
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
  Symbol* main = lookup("main");
  if (!main || main->functions.empty()) return;
  std::unordered_map<const Function*, bool> seen;
  std::vector<Function*> todo = {main->functions.front()};
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
