// The parser's statements (section 6).
#include "shader/parser_impl.h"

namespace raster::shader {

Stmt* Parser::statement() {
  DepthGuard guard(*this);
  Stmt* s = Ast::make(ast_.stmts);
  s->pos = peek().pos;
  if (!guard.ok()) return s;
  if (at(Punct::lbrace)) return block(true);
  if (accept(Punct::semicolon)) return s;
  const Token& t = peek();
  if (t.kind == TokenKind::identifier) {
    if (t.text == "if") return if_statement();
    if (t.text == "for") return for_statement();
    if (t.text == "while") return while_statement();
    if (t.text == "do") return do_statement();
    if (t.text == "switch") return switch_statement();
    if (t.text == "break") return simple(StmtKind::break_);
    if (t.text == "continue") return simple(StmtKind::continue_);
    if (t.text == "discard") return simple(StmtKind::discard);
    if (t.text == "return") {
      advance();
      s->kind = StmtKind::return_;
      if (!at(Punct::semicolon)) s->expr = expression(), s->broken = !s->expr;
      if (!expect(Punct::semicolon, "after return")) skip_to_statement_end();
      return s;
    }
    if (t.text == "case") {
      advance();
      s->kind = StmtKind::case_;
      s->expr = expression();
      s->broken = !s->expr;
      if (!expect(Punct::colon, "after a case label")) skip_to_statement_end();
      return s;
    }
    if (t.text == "default") {
      advance();
      s->kind = StmtKind::default_;
      if (!expect(Punct::colon, "after default")) skip_to_statement_end();
      return s;
    }
    if (t.text == "else") {
      error_at_token("'else' without an 'if'");
      advance();
      return s;
    }
    if (declaration_ahead()) return declaration_statement();
  }
  s->kind = StmtKind::expression;
  s->expr = expression();
  if (!s->expr) return skip_to_statement_end(), s;
  if (!expect(Punct::semicolon, "after an expression")) skip_to_statement_end();
  return s;
}

Stmt* Parser::simple(StmtKind kind) {
  Stmt* s = Ast::make(ast_.stmts);
  s->kind = kind;
  s->pos = advance().pos;
  if (!expect(Punct::semicolon, std::string("after ") + std::string(tokens_[i_ - 1].text)))
    skip_to_statement_end();
  return s;
}

// `{ ... }`; `scope` false for a function's body (which shares its parameters' scope) and a loop's (which
// shares its init's).
Stmt* Parser::block(bool scope) {
  Stmt* s = Ast::make(ast_.stmts);
  s->kind = StmtKind::block;
  s->scope = scope;
  s->pos = advance().pos;  // `{`
  if (scope) open_scope();
  while (!at(Punct::rbrace) && peek().kind != TokenKind::end && !fatal_) {
    const std::size_t before = i_;
    s->list.push_back(statement());
    if (i_ == before) advance();
  }
  if (scope) close_scope();
  if (!fatal_ && !expect(Punct::rbrace, "to close the block")) return s;
  return s;
}

// A loop's or if's condition: an expression, or `type name = initializer` (while and for only).
Stmt* Parser::condition(Stmt* s) {
  if (declaration_ahead()) {
    Declaration* d = Ast::make(ast_.declarations);
    d->pos = peek().pos;
    qualifiers(*d);
    d->type = type_spec();
    Declarator v;
    if (!d->type || !name(v.name, v.pos, "a name")) return s;
    if (!expect(Punct::assign, "after a condition's name")) return s;
    v.init = assignment();
    d->vars.push_back(v);
    s->decl = d;
    return s;
  }
  s->expr = expression();
  return s;
}

Stmt* Parser::if_statement() {
  Stmt* s = Ast::make(ast_.stmts);
  s->kind = StmtKind::if_;
  s->pos = advance().pos;
  if (!expect(Punct::lparen, "after if")) return skip_to_statement_end(), s;
  s->expr = expression();
  if (!expect(Punct::rparen, "after if's condition")) return skip_to_statement_end(), s;
  s->body = statement();
  if (accept_word("else")) s->else_body = statement();
  return s;
}

// The body of a loop: a block shares the loop's scope (section 6.3: `for (int i;;) { int i; }` redeclares).
static bool body_is_block(const Token& t) {
  return t.is(Punct::lbrace);
}

Stmt* Parser::for_statement() {
  Stmt* s = Ast::make(ast_.stmts);
  s->kind = StmtKind::for_;
  s->pos = advance().pos;
  if (!expect(Punct::lparen, "after for")) return skip_to_statement_end(), s;
  open_scope();
  if (accept(Punct::semicolon)) {
    s->init = Ast::make(ast_.stmts);
  } else if (declaration_ahead()) {
    s->init = declaration_statement();
  } else {
    s->init = Ast::make(ast_.stmts);
    s->init->kind = StmtKind::expression, s->init->pos = peek().pos;
    s->init->expr = expression();
    if (!expect(Punct::semicolon, "after for's first part")) return close_scope(), skip_to_statement_end(), s;
  }
  if (!at(Punct::semicolon)) condition(s);
  if (!expect(Punct::semicolon, "after for's condition")) return close_scope(), skip_to_statement_end(), s;
  if (!at(Punct::rparen)) s->step = expression();
  if (!expect(Punct::rparen, "after for's last part")) return close_scope(), skip_to_statement_end(), s;
  s->body = body_is_block(peek()) ? block(false) : statement();
  close_scope();
  return s;
}

Stmt* Parser::while_statement() {
  Stmt* s = Ast::make(ast_.stmts);
  s->kind = StmtKind::while_;
  s->pos = advance().pos;
  if (!expect(Punct::lparen, "after while")) return skip_to_statement_end(), s;
  open_scope();
  condition(s);
  if (!expect(Punct::rparen, "after while's condition")) return close_scope(), skip_to_statement_end(), s;
  s->body = body_is_block(peek()) ? block(false) : statement();
  close_scope();
  return s;
}

Stmt* Parser::do_statement() {
  Stmt* s = Ast::make(ast_.stmts);
  s->kind = StmtKind::do_;
  s->pos = advance().pos;
  s->body = statement();
  if (!accept_word("while")) {
    error_at_token(std::string("expected 'while' after do's body, found ") + describe(peek()));
    return skip_to_statement_end(), s;
  }
  if (!expect(Punct::lparen, "after while")) return skip_to_statement_end(), s;
  s->expr = expression();
  if (!expect(Punct::rparen, "after do-while's condition") || !expect(Punct::semicolon, "after do-while"))
    skip_to_statement_end();
  return s;
}

Stmt* Parser::switch_statement() {
  Stmt* s = Ast::make(ast_.stmts);
  s->kind = StmtKind::switch_;
  s->pos = advance().pos;
  if (!expect(Punct::lparen, "after switch")) return skip_to_statement_end(), s;
  s->expr = expression();
  if (!expect(Punct::rparen, "after switch's value")) return skip_to_statement_end(), s;
  if (!at(Punct::lbrace)) {
    error_at_token(std::string("expected '{' after switch, found ") + describe(peek()));
    return skip_to_statement_end(), s;
  }
  s->body = block(true);
  return s;
}

}  // namespace raster::shader
