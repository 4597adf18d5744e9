// The checker's statements (chapter 6).
#include <algorithm>

#include "shader/checker_impl.h"

namespace raster::shader {

void Checker::bool_condition(Expr* e, std::string_view where) {
  if (!e) return;
  expr(e);
  if (!e->type.is_error() && !(e->type.is_scalar() && e->type.basic == Basic::bool_))
    error(e->pos, std::string(where) + std::string("'s condition must be a bool, not ") + type_name(e->type));
}

// A condition of while or for: an expression, or `bool name = initializer` declared in the loop's scope.
void Checker::condition(Stmt* s) {
  if (!s->decl) return bool_condition(s->expr, s->kind == StmtKind::for_ ? "for" : "while");
  declaration(s->decl, false);
  const Declarator& v = s->decl->vars.front();
  if (v.variable && !(v.variable->type.is_scalar() && v.variable->type.basic == Basic::bool_))
    error(v.pos, std::string("a condition must be a bool, not ") + type_name(v.variable->type));
}

void Checker::block(Stmt* s) {
  if (s->scope) scopes_.emplace_back();
  for (Stmt* child : s->list) statement(child);
  if (s->scope) scopes_.pop_back();
}

void Checker::statement(Stmt* s) {
  if (!s) return;
  switch (s->kind) {
    case StmtKind::block:
      return block(s);
    case StmtKind::declaration:
      return declaration(s->decl, false);
    case StmtKind::expression:
      if (s->expr) expr(s->expr);
      return;
    case StmtKind::if_:
      bool_condition(s->expr, "if");
      scopes_.emplace_back();  // an if's branch is a scope even when it is not a block
      statement(s->body);
      scopes_.pop_back();
      scopes_.emplace_back();
      statement(s->else_body);
      scopes_.pop_back();
      return;
    case StmtKind::for_:
    case StmtKind::while_:
      scopes_.emplace_back();
      statement(s->init);
      condition(s);
      if (s->step) expr(s->step);
      breakable_.push_back('l');
      statement(s->body);
      breakable_.pop_back();
      scopes_.pop_back();
      return;
    case StmtKind::do_:
      breakable_.push_back('l');
      scopes_.emplace_back();
      statement(s->body);
      scopes_.pop_back();
      breakable_.pop_back();
      bool_condition(s->expr, "do-while");
      return;
    case StmtKind::switch_:
      return switch_statement(s);
    case StmtKind::case_:
    case StmtKind::default_:
      error(s->pos, std::string(s->kind == StmtKind::case_ ? "case" : "default") +
                        " belongs directly in a switch's body");
      return;
    case StmtKind::break_:
      if (breakable_.empty()) error(s->pos, "break is only allowed in a loop or a switch");
      return;
    case StmtKind::continue_:
      if (std::find(breakable_.begin(), breakable_.end(), 'l') == breakable_.end())
        error(s->pos, "continue is only allowed in a loop");
      return;
    case StmtKind::return_:
      return return_statement(s);
    case StmtKind::discard:
    case StmtKind::empty:
      return;
  }
}

void Checker::return_statement(Stmt* s) {
  returned_ = true;
  if (s->broken) return;  // its value did not parse (reported)
  if (s->expr) expr(s->expr);
  if (!function_) return;
  if (function_->ret.is_void()) {
    if (s->expr)
      error(s->pos, std::string("'") + quote(function_->name) + "' returns void, so return takes no value");
    return;
  }
  if (!s->expr) {
    error(s->pos, std::string("'") + quote(function_->name) + std::string("' must return a ") +
                      type_name(function_->ret));
    return;
  }
  if (!s->expr->type.is_error() && !(s->expr->type == function_->ret))
    error(s->expr->pos, std::string("'") + quote(function_->name) + std::string("' returns ") +
                            type_name(function_->ret) + ", not " + type_name(s->expr->type));
}

// A switch (section 6.2): an int or uint selector; its body's statements start with a label; labels are
// distinct constant expressions of the selector's type, one default at most, and the last label is
// followed by a statement.
void Checker::switch_statement(Stmt* s) {
  if (!s->expr || !s->body) return;  // did not parse (reported)
  expr(s->expr);
  const Type& t = s->expr->type;
  const bool ok = !t.is_error() && t.is_scalar() && t.is_integer();
  if (!t.is_error() && !ok)
    error(s->expr->pos, std::string("a switch's value must be an int or uint, not ") + type_name(t));
  std::vector<std::int64_t> seen;
  bool has_default = false;
  Stmt* body = s->body;
  scopes_.emplace_back();
  breakable_.push_back('s');
  for (std::size_t i = 0; i < body->list.size(); ++i) {
    Stmt* c = body->list[i];
    if (i == 0 && c->kind != StmtKind::case_ && c->kind != StmtKind::default_)
      error(c->pos, "a switch's body must start with a case or default label");
    if (c->kind == StmtKind::default_) {
      if (has_default) error(c->pos, "a switch has one default label at most");
      has_default = true;
    } else if (c->kind == StmtKind::case_) {
      if (c->broken) continue;
      expr(c->expr);
      std::int64_t v = 0;
      if (c->expr->type.is_error()) continue;
      if (ok && !(c->expr->type == t)) {
        error(c->expr->pos, std::string("a case label must be a ") + type_name(t) +
                                " like the switch's value, not " + type_name(c->expr->type));
      } else if (!constant_int(c->expr, v)) {
        error(c->expr->pos, "a case label must be a constant expression");
      } else if (std::find(seen.begin(), seen.end(), v) != seen.end()) {
        error(c->expr->pos, std::string("case ") + std::to_string(v) + " appears twice in this switch");
      } else {
        seen.push_back(v);
      }
    } else {
      statement(c);
    }
  }
  if (!body->list.empty()) {
    const StmtKind last = body->list.back()->kind;
    if (last == StmtKind::case_ || last == StmtKind::default_)
      error(body->list.back()->pos, "a switch's last label must be followed by a statement");
  }
  breakable_.pop_back();
  scopes_.pop_back();
}

}  // namespace raster::shader
