// The parser's declarations (chapter 4, and chapter 9's grammar): qualifiers in the order the grammar
// allows, types, structs and uniform blocks, functions and their parameters, variables, precision
// statements. What a declaration may mean (which layout names, which qualifiers for which variables) is
// the checker's; the parser keeps what is written.
#include <algorithm>

#include "shader/parser_impl.h"

namespace raster::shader {
namespace {

// Ranks of the qualifiers before a type, in the order chapter 9's grammar allows them: `layout(...)` then
// the storage qualifier; or `invariant`, then an interpolation qualifier, then the storage qualifier.
enum Rank : int { kNone, kLayout, kInvariant, kInterpolation, kStorage };

const char* out_of_order(int rank) {
  switch (rank) {
    case kLayout:
      return "layout(...) comes first, followed only by the storage qualifier";
    case kInvariant:
      return "invariant comes first, before the interpolation and storage qualifiers";
    default:
      return "an interpolation qualifier (flat, smooth) comes before the storage qualifier";
  }
}

const char* repeated(int rank) {
  switch (rank) {
    case kLayout:
      return "a declaration has one layout(...) at most (list its entries in one)";
    case kInvariant:
      return "invariant is written once";
    case kInterpolation:
      return "a declaration has one interpolation qualifier (flat or smooth) at most";
    default:
      return "a declaration has at most one storage qualifier";
  }
}

}  // namespace

// Whether a declaration starts here (not an expression): qualifiers, `struct`, or a type followed by a
// name or by `;` alone (after an optional `[...]`); a type followed by `(` is a constructor.
bool Parser::declaration_ahead() const {
  const Token& t = peek();
  if (is_qualifier(t) || t.is_identifier("precision") || t.is_identifier("struct")) return true;
  if (!is_type_name(t)) return false;
  std::size_t k = 1;
  if (peek(k).is(Punct::lbracket)) {
    int depth = 0;
    for (;; ++k) {
      if (peek(k).kind == TokenKind::end) return false;
      if (peek(k).is(Punct::lbracket)) ++depth;
      if (peek(k).is(Punct::rbracket) && --depth == 0) break;
    }
    ++k;
  }
  return peek(k).kind == TokenKind::identifier || peek(k).is(Punct::semicolon);
}

bool Parser::array_suffix(bool& array, Expr*& size) {
  if (!accept(Punct::lbracket)) return true;
  array = true;
  if (!at(Punct::rbracket)) size = conditional();
  if (!expect(Punct::rbracket, "after an array size")) return false;
  if (at(Punct::lbracket)) {
    error_at_token("arrays of arrays are not allowed in GLSL ES 3.00");
    return false;
  }
  return true;
}

// `highp`, `mediump` or `lowp`: one at most, and the last qualifier, right before the type.
Precision Parser::precision_qualifier() {
  Precision p = Precision::none;
  while (is_precision(peek())) {
    const Token& t = advance();
    if (p != Precision::none) {
      error(t.pos, "a type has one precision qualifier at most");
      continue;
    }
    p = t.text == "highp" ? Precision::highp : t.text == "mediump" ? Precision::mediump : Precision::lowp;
  }
  if (p != Precision::none && is_qualifier(peek()))
    error_at_token(std::string("'") + quote(peek().text) +
                   "' must come before the precision qualifier, which is last, right before the type");
  return p;
}

TypeSpec* Parser::type_spec() {
  TypeSpec* spec = Ast::make(ast_.specs);
  spec->pos = peek().pos;
  spec->precision = precision_qualifier();
  if (at_word("struct")) {
    spec->definition = struct_body();
    if (!spec->definition) return nullptr;
    spec->type.basic = Basic::structure;
  } else if (is_type_name(peek())) {
    const Token& t = advance();
    spec->type = keyword_type(t.text);
    if (spec->type.is_error()) spec->struct_name = t.text;
  } else {
    error_at_token(std::string("expected a type, found ") + describe(peek()));
    return nullptr;
  }
  if (!array_suffix(spec->array, spec->array_size)) return nullptr;
  return spec;
}

StructDecl* Parser::struct_body() {
  StructDecl* s = Ast::make(ast_.structs);
  s->pos = advance().pos;  // `struct`
  if (peek().kind == TokenKind::identifier && !at(Punct::lbrace)) {
    SourcePos pos;
    if (!name(s->name, pos, "a struct's name")) return nullptr;
    type_scopes_.back().push_back(s->name);
  }
  return fields(s) ? s : nullptr;
}

// `{ type name, name[n]; ... }`: a struct's fields or a block's members, every declaration ended by `;`. A
// block's members may have qualifiers of their own (layout(row_major), uniform), which the checker judges.
// False when a member could not be read (the rest are read, and the closing `}` too).
bool Parser::fields(StructDecl* s) {
  if (!expect(Punct::lbrace, s->block ? "to open the block's members" : "to open the struct's fields"))
    return false;
  bool whole = true;
  while (!at(Punct::rbrace) && peek().kind != TokenKind::end && !fatal_) {
    Declaration* qualified = nullptr;
    if (s->block && is_qualifier(peek()) && !is_precision(peek())) {
      qualified = Ast::make(ast_.declarations);
      qualified->pos = peek().pos;
      qualifiers(*qualified);
    }
    TypeSpec* type = type_spec();
    bool read = type != nullptr;
    while (read) {
      FieldDecl f{type, {}, {}};
      f.qualifiers = qualified;
      read = name(f.name, f.pos, s->block ? "a member's name" : "a field's name") &&
             array_suffix(f.array, f.array_size);
      if (read) s->fields.push_back(f);
      if (!read || !accept(Punct::comma)) break;
    }
    if (!read) {
      whole = false;
      skip_to_statement_end();
    } else if (!expect(Punct::semicolon, s->block ? "after a member" : "after a field")) {
      skip_to_statement_end();
    }
  }
  return expect(Punct::rbrace, s->block ? "to close the block" : "to close the struct") && whole;
}

// Whether `t`, of `rank`, may follow the qualifiers before it (`last`, the highest rank so far); reported if
// not. The grammar allows `layout(...) storage` and `invariant interpolation storage`, each part optional.
bool Parser::qualifier_in_order(const Token& t, int rank, int& last, bool& layout_seen) {
  const int before = last;
  last = std::max(last, rank);
  if (rank == kLayout) layout_seen = true;
  const char* why = rank == before                                       ? repeated(rank)
                    : rank < before                                      ? out_of_order(rank)
                    : layout_seen && rank != kLayout && rank != kStorage ? out_of_order(kLayout)
                                                                         : nullptr;
  if (why) error(t.pos, why);
  return why == nullptr;
}

// The qualifiers before a declaration's type: layout(...), invariant, flat or smooth, and one storage
// qualifier (const, in, out, centroid in, centroid out, uniform). Precision belongs to the type.
void Parser::qualifiers(Declaration& d) {
  int last = kNone;
  bool layout_seen = false;
  while (is_qualifier(peek()) && !is_precision(peek())) {
    const Token& t = advance();
    if (t.text == "layout") {
      qualifier_in_order(t, kLayout, last, layout_seen);
      layout(d.layout);
    } else if (t.text == "invariant") {
      qualifier_in_order(t, kInvariant, last, layout_seen);
      d.invariant = true;
    } else if (t.text == "flat" || t.text == "smooth") {
      qualifier_in_order(t, kInterpolation, last, layout_seen);
      d.interpolation = true, d.flat = d.flat || t.text == "flat";
    } else if (t.text == "attribute" || t.text == "varying") {
      error(t.pos,
            std::string("'") + std::string(t.text) + "' is not a qualifier of GLSL ES 3.00 (use in or out)");
    } else if (t.text == "centroid") {
      // `centroid in` and `centroid out` are storage qualifiers of their own (the grammar's).
      if (!at_word("in") && !at_word("out"))
        error(t.pos, "centroid is part of a storage qualifier: centroid in or centroid out");
      else
        d.centroid = true;
    } else {
      if (!qualifier_in_order(t, kStorage, last, layout_seen)) continue;
      if (t.text == "inout") error(t.pos, "inout qualifies function parameters only");
      d.qualifier = t.text == "const"     ? Qualifier::const_
                    : t.text == "uniform" ? Qualifier::uniform
                    : t.text == "in"      ? Qualifier::in
                                          : Qualifier::out;
    }
  }
}

// `(name, name = integer, ...)` after `layout`, kept as written. On an error the rest of the list is
// skipped.
void Parser::layout(std::vector<LayoutId>& ids) {
  if (!expect(Punct::lparen, "after layout")) return;
  do {
    LayoutId id;
    id.pos = peek().pos;
    if (peek().kind != TokenKind::identifier) {
      error_at_token(std::string("expected a layout qualifier's name, found ") + describe(peek()));
      break;
    }
    id.name = advance().text;
    if (accept(Punct::assign)) {
      const Token& v = peek();
      const Expr* value = v.kind == TokenKind::number ? literal(advance()) : nullptr;
      if (!value || !value->type.is_integer() || !(at(Punct::comma) || at(Punct::rparen))) {
        error(v.pos, "a layout qualifier's value is an integer literal in GLSL ES 3.00");
        break;
      }
      id.has_value = true, id.value = static_cast<std::int32_t>(value->bits);
    }
    ids.push_back(id);
  } while (accept(Punct::comma));
  while (!at(Punct::rparen) && !at(Punct::semicolon) && peek().kind != TokenKind::end) advance();
  expect(Punct::rparen, "to close layout(...)");
}

void Parser::external() {
  External e;
  e.pos = peek().pos;
  if (at(Punct::semicolon)) {
    error_at_token("a ';' alone is not a declaration in GLSL ES (one too many, after a '}' or another ';'?)");
    advance();
    return;
  }
  if (at_word("precision")) {
    const Stmt* s = declaration_statement();
    e.kind = External::Kind::precision, e.declaration = s->decl;
    if (e.declaration) ast_.externals.push_back(e);
    return;
  }
  Declaration* d = Ast::make(ast_.declarations);
  d->pos = e.pos;
  const std::size_t start = i_;
  qualifiers(*d);
  e.declaration = d;
  if (d->invariant && d->qualifier == Qualifier::none && peek().kind == TokenKind::identifier &&
      !is_type_name(peek()) && !is_precision(peek()) && !peek(1).is(Punct::lbrace)) {
    // `invariant name, ...;` re-declares outputs invariant.
    do {
      SourcePos pos;
      std::string_view n;
      if (!name(n, pos, "a name")) return skip_to_statement_end();
      d->invariant_names.push_back(n);
    } while (accept(Punct::comma));
    expect(Punct::semicolon, "after invariant");
    ast_.externals.push_back(e);
    return;
  }
  if (peek().kind == TokenKind::identifier && !is_type_name(peek()) && !at_word("struct") &&
      peek(1).is(Punct::lbrace))
    return interface_block(d, e);
  if (at(Punct::semicolon) && i_ != start) {  // qualifiers alone: `layout(std140) uniform;`
    advance();
    ast_.externals.push_back(e);
    return;
  }
  d->type = type_spec();
  if (!d->type) return skip_to_statement_end();
  if (accept(Punct::semicolon)) {  // a struct (or a type) declared alone
    ast_.externals.push_back(e);
    return;
  }
  std::string_view n;
  SourcePos pos;
  if (!name(n, pos, "a name")) return skip_to_statement_end();
  if (at(Punct::lparen)) {
    if (d->qualifier != Qualifier::none || d->invariant || d->interpolation || !d->layout.empty())
      error(d->pos, "a function's return type takes no storage qualifier");
    return function_rest(d->type, n, pos);
  }
  if (!declaration_rest(d, n, pos)) return;
  ast_.externals.push_back(e);
}

// `Name { members } instance[size];` after a block's qualifiers (section 4.3.7; the instance optional).
void Parser::interface_block(Declaration* d, External& e) {
  StructDecl* s = Ast::make(ast_.structs);
  s->block = true;
  if (!name(s->name, s->pos, "a block's name")) return skip_to_statement_end();
  if (!fields(s)) return skip_to_statement_end();
  d->block = s;
  if (peek().kind == TokenKind::identifier) {
    Declarator v;
    if (!name(v.name, v.pos, "a block's instance name") || !array_suffix(v.array, v.array_size))
      return skip_to_statement_end();
    d->vars.push_back(v);
  }
  if (!expect(Punct::semicolon, "after a block")) skip_to_statement_end();
  ast_.externals.push_back(e);
}

void Parser::function_rest(TypeSpec* ret, std::string_view name, SourcePos pos) {
  FunctionDecl* f = Ast::make(ast_.functions);
  f->ret = ret, f->name = name, f->pos = pos;
  advance();  // `(`
  if (at_word("void") && peek(1).is(Punct::rparen)) advance();
  if (!at(Punct::rparen)) {
    do {  // a parameter after every comma
      ParamDecl p;
      if (!parameter(p)) return skip_to_statement_end();
      f->params.push_back(p);
    } while (accept(Punct::comma));
  }
  if (!expect(Punct::rparen, "after the parameters")) return skip_to_statement_end();
  if (!accept(Punct::semicolon)) {
    if (!at(Punct::lbrace)) {
      error_at_token(std::string("expected '{' or ';' after a function's parameters, found ") +
                     describe(peek()));
      return skip_to_statement_end();
    }
    open_scope();
    f->body = block(false);
    close_scope();
  }
  External e;
  e.kind = External::Kind::function, e.function = f, e.pos = pos;
  ast_.externals.push_back(e);
}

// `[const] [in | out | inout] [precision] type [name[size]]`, in that order (section 4.10).
bool Parser::parameter(ParamDecl& p) {
  p.pos = peek().pos;
  bool is_const = false;
  Qualifier q = Qualifier::none;
  for (;;) {
    const Token& t = peek();
    if (t.is_identifier("const")) {
      if (is_const) error(t.pos, "a parameter is const at most once");
      if (q != Qualifier::none) error(t.pos, "const comes before in, out or inout");
      is_const = true;
    } else if (t.is_identifier("in") || t.is_identifier("out") || t.is_identifier("inout")) {
      if (q != Qualifier::none) error(t.pos, "a parameter has at most one of in, out and inout");
      q = t.text == "in" ? Qualifier::in : t.text == "out" ? Qualifier::out : Qualifier::inout;
    } else if (is_qualifier(t) && !is_precision(t)) {
      error(t.pos, std::string("'") + quote(t.text) +
                       "' cannot qualify a parameter (const, in, out, inout and a precision can)");
    } else {
      break;
    }
    advance();
  }
  if (is_const && (q == Qualifier::out || q == Qualifier::inout)) {
    error(p.pos, "a const parameter cannot be out or inout");
  }
  p.qualifier = is_const ? Qualifier::const_in : q == Qualifier::none ? Qualifier::in : q;
  p.type = type_spec();
  if (!p.type) return false;
  if (peek().kind == TokenKind::identifier) {
    SourcePos pos;
    if (!name(p.name, pos, "a parameter's name")) return false;
    p.pos = pos;
    if (!array_suffix(p.array, p.array_size)) return false;
  }
  return true;
}

// The declarators after the first name: `first[n] = init, b, c[2];`. One whose initializer does not parse
// is still declared (broken), so the statements after it do not report its name as undeclared.
Declaration* Parser::declaration_rest(Declaration* d, std::string_view first, SourcePos first_pos) {
  std::string_view n = first;
  SourcePos pos = first_pos;
  for (;;) {
    Declarator v;
    v.name = n, v.pos = pos;
    if (!array_suffix(v.array, v.array_size)) return skip_to_statement_end(), nullptr;
    if (accept(Punct::assign)) {
      v.init = assignment();
      if (!v.init) {
        v.broken = true;
        d->vars.push_back(v);
        return skip_to_statement_end(), nullptr;
      }
    }
    d->vars.push_back(v);
    if (!accept(Punct::comma)) break;
    if (!name(n, pos, "a name")) return skip_to_statement_end(), nullptr;
  }
  if (!expect(Punct::semicolon, "after a declaration")) return skip_to_statement_end(), nullptr;
  return d;
}

// `precision highp float;` (section 4.5.3): a declaration of the type and its precision, judged by the
// checker, which keeps each scope's defaults.
Stmt* Parser::precision_statement(Stmt* s) {
  advance();  // `precision`
  if (!is_precision(peek())) {
    error_at_token(std::string("expected highp, mediump or lowp after precision, found ") + describe(peek()));
    return skip_to_statement_end(), s;
  }
  Declaration* d = Ast::make(ast_.declarations);
  d->pos = s->pos, d->precision_statement = true;
  d->type = type_spec();
  if (!d->type) return skip_to_statement_end(), s;
  if (!expect(Punct::semicolon, "after a precision statement")) skip_to_statement_end();
  s->kind = StmtKind::declaration, s->decl = d;
  return s;
}

Stmt* Parser::declaration_statement() {
  Stmt* s = Ast::make(ast_.stmts);
  s->pos = peek().pos;
  if (at_word("precision")) return precision_statement(s);
  Declaration* d = Ast::make(ast_.declarations);
  d->pos = s->pos;
  qualifiers(*d);
  d->type = type_spec();
  if (!d->type) return skip_to_statement_end(), s;
  s->kind = StmtKind::declaration, s->decl = d;
  if (accept(Punct::semicolon)) return s;
  std::string_view n;
  SourcePos pos;
  if (!name(n, pos, "a name")) return skip_to_statement_end(), s;
  if (at(Punct::lparen)) {
    error(pos, "functions cannot be declared inside a function");
    skip_to_statement_end();
    return s;
  }
  declaration_rest(d, n, pos);
  return s;
}

}  // namespace raster::shader
