// The parser's declarations and statements; expressions are parse_expr.cpp.
#include <algorithm>
#include <array>
#include <iterator>

#include "shader/parser_impl.h"

namespace raster::shader {
namespace {

constexpr std::string_view kKeywords[] = {
    "const", "uniform", "layout",    "centroid",  "flat",   "smooth",    "break",   "continue",
    "do",    "for",     "while",     "switch",    "case",   "default",   "if",      "else",
    "in",    "out",     "inout",     "true",      "false",  "invariant", "discard", "return",
    "lowp",  "mediump", "highp",     "precision", "struct", "float",     "int",     "void",
    "bool",  "uint",    "attribute", "varying",   "sizeof"};

constexpr std::string_view kReserved[] = {"coherent",
                                          "volatile",
                                          "restrict",
                                          "readonly",
                                          "writeonly",
                                          "resource",
                                          "atomic_uint",
                                          "noperspective",
                                          "patch",
                                          "sample",
                                          "subroutine",
                                          "common",
                                          "partition",
                                          "active",
                                          "asm",
                                          "class",
                                          "union",
                                          "enum",
                                          "typedef",
                                          "template",
                                          "this",
                                          "goto",
                                          "inline",
                                          "noinline",
                                          "public",
                                          "static",
                                          "extern",
                                          "external",
                                          "interface",
                                          "long",
                                          "short",
                                          "double",
                                          "half",
                                          "fixed",
                                          "unsigned",
                                          "superp",
                                          "input",
                                          "output",
                                          "hvec2",
                                          "hvec3",
                                          "hvec4",
                                          "dvec2",
                                          "dvec3",
                                          "dvec4",
                                          "fvec2",
                                          "fvec3",
                                          "fvec4",
                                          "sampler3DRect",
                                          "filter",
                                          "image1D",
                                          "image2D",
                                          "image3D",
                                          "imageCube",
                                          "iimage1D",
                                          "iimage2D",
                                          "iimage3D",
                                          "iimageCube",
                                          "uimage1D",
                                          "uimage2D",
                                          "uimage3D",
                                          "uimageCube",
                                          "image1DArray",
                                          "image2DArray",
                                          "iimage1DArray",
                                          "iimage2DArray",
                                          "uimage1DArray",
                                          "uimage2DArray",
                                          "imageBuffer",
                                          "iimageBuffer",
                                          "uimageBuffer",
                                          "sampler1D",
                                          "sampler1DShadow",
                                          "sampler1DArray",
                                          "sampler1DArrayShadow",
                                          "isampler1D",
                                          "usampler1D",
                                          "isampler1DArray",
                                          "usampler1DArray",
                                          "sampler2DRect",
                                          "sampler2DRectShadow",
                                          "isampler2DRect",
                                          "usampler2DRect",
                                          "samplerBuffer",
                                          "isamplerBuffer",
                                          "usamplerBuffer",
                                          "sampler2DMS",
                                          "isampler2DMS",
                                          "usampler2DMS",
                                          "sampler2DMSArray",
                                          "isampler2DMSArray",
                                          "usampler2DMSArray",
                                          "cast",
                                          "namespace",
                                          "using",
                                          "dmat2",
                                          "dmat3",
                                          "dmat4"};

}  // namespace

bool is_keyword(std::string_view word) {
  return std::find(std::begin(kKeywords), std::end(kKeywords), word) != std::end(kKeywords) ||
         !keyword_type(word).is_error();
}

bool is_reserved_word(std::string_view word) {
  return std::find(std::begin(kReserved), std::end(kReserved), word) != std::end(kReserved);
}

void parse(const std::vector<Token>& tokens, int max_depth, Ast& ast, Diagnostics& diagnostics) {
  Parser(tokens, max_depth, ast, diagnostics).run();
}

Parser::Parser(const std::vector<Token>& tokens, int max_depth, Ast& ast, Diagnostics& diagnostics)
    : tokens_(tokens), max_depth_(max_depth), ast_(ast), diagnostics_(diagnostics) {}

DepthGuard::DepthGuard(Parser& p) : parser_(p), ok_(++p.depth_ <= p.max_depth_ && !p.fatal_) {
  if (p.depth_ == p.max_depth_ + 1 && !p.fatal_) {
    p.error(p.peek().pos, std::string("the program nests more than ") + std::to_string(p.max_depth_) +
                              " levels deep (brackets, operators and statements inside each other)");
    p.fatal_ = true;
  }
}

void Parser::run() {
  while (!fatal_ && peek().kind != TokenKind::end) {
    const std::size_t before = i_;
    external();
    if (i_ == before) advance();  // never stand still on a token nothing accepts
  }
}

const Token& Parser::peek(std::size_t ahead) const {
  const std::size_t at = std::min(i_ + ahead, tokens_.size() - 1);
  return tokens_[at];
}

const Token& Parser::advance() {
  const Token& t = tokens_[i_];
  if (i_ + 1 < tokens_.size()) ++i_;
  return t;
}

bool Parser::accept(Punct p) {
  if (!at(p)) return false;
  advance();
  return true;
}

bool Parser::accept_word(std::string_view w) {
  if (!at_word(w)) return false;
  advance();
  return true;
}

std::string Parser::describe(const Token& t) const {
  switch (t.kind) {
    case TokenKind::end:
      return "the end of the program";
    case TokenKind::other:
      return std::string("the character '") + quote(t.text) + "'";
    default:
      return std::string("'") + quote(t.text) + "'";
  }
}

bool Parser::expect(Punct p, std::string_view where) {
  if (accept(p)) return true;
  error_at_token(std::string("expected '") + std::string(spelling(p)) + std::string("' ") +
                 std::string(where) + ", found " + describe(peek()));
  return false;
}

void Parser::error(SourcePos pos, std::string message) {
  if (fatal_) return;
  if (pos == last_error_) return;  // one error a place: recovery can stumble on the same token twice
  last_error_ = pos;
  diagnostics_.error(pos, std::move(message));
}

void Parser::error_at_token(std::string message) {
  error(peek().pos, std::move(message));
}

// Recovery: past the next `;` or to the `}` that closes the current block (not past it).
void Parser::skip_to_statement_end() {
  int depth = 0;
  while (peek().kind != TokenKind::end) {
    if (at(Punct::lbrace)) ++depth;
    if (at(Punct::rbrace)) {
      if (depth == 0) return;
      if (--depth == 0) {
        advance();
        return;
      }
    }
    if (at(Punct::semicolon) && depth == 0) {
      advance();
      return;
    }
    advance();
  }
}

bool Parser::is_type_name(const Token& t) const {
  if (t.kind != TokenKind::identifier) return false;
  if (!keyword_type(t.text).is_error()) return true;
  for (const auto& scope : type_scopes_)
    if (std::find(scope.begin(), scope.end(), t.text) != scope.end()) return true;
  return false;
}

bool Parser::is_precision(const Token& t) const {
  return t.is_identifier("highp") || t.is_identifier("mediump") || t.is_identifier("lowp");
}

bool Parser::is_qualifier(const Token& t) const {
  static constexpr std::array<std::string_view, 11> kQualifiers = {
      "const", "uniform", "in",       "out",    "inout",    "invariant",
      "flat",  "smooth",  "centroid", "layout", "attribute"};
  return t.kind == TokenKind::identifier &&
         (std::find(kQualifiers.begin(), kQualifiers.end(), t.text) != kQualifiers.end() ||
          t.text == "varying" || is_precision(t));
}

// A name being declared: an identifier that is not a keyword or reserved word.
bool Parser::name(std::string_view& out, SourcePos& pos, std::string_view what) {
  const Token& t = peek();
  pos = t.pos;
  if (t.kind != TokenKind::identifier) {
    error_at_token(std::string("expected ") + std::string(what) + std::string(", found ") + describe(t));
    return false;
  }
  if (is_keyword(t.text) || is_reserved_word(t.text)) {
    error_at_token(std::string("'") + quote(t.text) + std::string("' is a ") +
                   (is_keyword(t.text) ? "keyword" : "reserved word") + std::string(" and cannot be ") +
                   std::string(what));
    advance();
    return false;
  }
  out = t.text;
  advance();
  return true;
}

// Whether a declaration starts here (not an expression): qualifiers, `struct`, or a type followed by a
// name (after an optional `[...]`); a type followed by `(` is a constructor.
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
  return peek(k).kind == TokenKind::identifier;
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

TypeSpec* Parser::type_spec() {
  TypeSpec* spec = Ast::make(ast_.specs);
  spec->pos = peek().pos;
  while (is_precision(peek())) advance(), spec->precision = true;
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
  if (!expect(Punct::lbrace, "to open the struct's fields")) return nullptr;
  while (!at(Punct::rbrace) && peek().kind != TokenKind::end && !fatal_) {
    TypeSpec* type = type_spec();
    if (!type) return skip_to_statement_end(), nullptr;
    do {
      FieldDecl f{type, {}, {}};
      if (!name(f.name, f.pos, "a field's name") || !array_suffix(f.array, f.array_size)) {
        skip_to_statement_end();
        break;
      }
      s->fields.push_back(f);
    } while (accept(Punct::comma));
    if (!at(Punct::rbrace) && !expect(Punct::semicolon, "after a field")) skip_to_statement_end();
  }
  if (!expect(Punct::rbrace, "to close the struct")) return nullptr;
  return s;
}

void Parser::qualifiers(Declaration& d) {
  while (is_qualifier(peek()) && !is_precision(peek())) {
    const Token& t = advance();
    if (t.text == "layout") {
      d.layout = true;
      if (!expect(Punct::lparen, "after layout")) return;
      while (!at(Punct::rparen) && peek().kind != TokenKind::end) advance();
      expect(Punct::rparen, "to close layout");
      continue;
    }
    if (t.text == "invariant") {
      d.invariant = true;
    } else if (t.text == "flat" || t.text == "smooth") {
      d.interpolation = true;
    } else if (t.text == "centroid") {
      d.centroid = true;
    } else if (t.text == "attribute" || t.text == "varying") {
      error(t.pos,
            std::string("'") + std::string(t.text) + "' is not a qualifier of GLSL ES 3.00 (use in or out)");
    } else if (d.qualifier != Qualifier::none) {
      error(t.pos, "a declaration has at most one storage qualifier");
    } else {
      d.qualifier = t.text == "const"     ? Qualifier::const_
                    : t.text == "uniform" ? Qualifier::uniform
                    : t.text == "in"      ? Qualifier::in
                    : t.text == "out"     ? Qualifier::out
                                          : Qualifier::inout;
    }
  }
}

void Parser::external() {
  External e;
  e.pos = peek().pos;
  if (accept(Punct::semicolon)) return;
  if (at_word("precision")) {
    Stmt* s = declaration_statement();
    (void)s;
    e.kind = External::Kind::precision;
    ast_.externals.push_back(e);
    return;
  }
  Declaration* d = Ast::make(ast_.declarations);
  d->pos = e.pos;
  qualifiers(*d);
  if (d->invariant && d->qualifier == Qualifier::none && peek().kind == TokenKind::identifier &&
      !is_type_name(peek()) && !is_precision(peek())) {
    // `invariant name, ...;` re-declares outputs invariant.
    do {
      SourcePos pos;
      std::string_view n;
      if (!name(n, pos, "a name")) return skip_to_statement_end();
      d->invariant_names.push_back(n);
    } while (accept(Punct::comma));
    expect(Punct::semicolon, "after invariant");
    e.declaration = d;
    ast_.externals.push_back(e);
    return;
  }
  d->type = type_spec();
  if (!d->type) return skip_to_statement_end();
  if (accept(Punct::semicolon)) {  // a struct (or a type) declared alone
    e.declaration = d;
    ast_.externals.push_back(e);
    return;
  }
  std::string_view n;
  SourcePos pos;
  if (!name(n, pos, "a name")) return skip_to_statement_end();
  if (at(Punct::lparen)) {
    if (d->qualifier != Qualifier::none || d->invariant || d->layout)
      error(d->pos, "a function's return type takes no storage qualifier");
    return function_rest(d->type, n, pos);
  }
  if (!declaration_rest(d, n, pos)) return;
  e.declaration = d;
  ast_.externals.push_back(e);
}

void Parser::function_rest(TypeSpec* ret, std::string_view name, SourcePos pos) {
  FunctionDecl* f = Ast::make(ast_.functions);
  f->ret = ret, f->name = name, f->pos = pos;
  advance();  // `(`
  if (at_word("void") && peek(1).is(Punct::rparen)) advance();
  while (!at(Punct::rparen) && peek().kind != TokenKind::end) {
    ParamDecl p;
    if (!parameter(p)) return skip_to_statement_end();
    f->params.push_back(p);
    if (!at(Punct::rparen) && !expect(Punct::comma, "between parameters")) return skip_to_statement_end();
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

bool Parser::parameter(ParamDecl& p) {
  p.pos = peek().pos;
  bool is_const = false;
  Qualifier q = Qualifier::none;
  for (;;) {
    if (accept_word("const")) {
      if (is_const) error(p.pos, "a parameter is const at most once");
      is_const = true;
    } else if (at_word("in") || at_word("out") || at_word("inout")) {
      const Token& t = advance();
      if (q != Qualifier::none) error(t.pos, "a parameter has at most one of in, out and inout");
      q = t.text == "in" ? Qualifier::in : t.text == "out" ? Qualifier::out : Qualifier::inout;
    } else if (is_precision(peek())) {
      advance(), p.precision = true;
    } else {
      break;
    }
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

// The declarators after the first name: `first[n] = init, b, c[2];`.
Declaration* Parser::declaration_rest(Declaration* d, std::string_view first, SourcePos first_pos) {
  std::string_view n = first;
  SourcePos pos = first_pos;
  for (;;) {
    Declarator v;
    v.name = n, v.pos = pos;
    if (!array_suffix(v.array, v.array_size)) return skip_to_statement_end(), nullptr;
    if (accept(Punct::assign)) {
      v.init = assignment();
      if (!v.init) return skip_to_statement_end(), nullptr;
    }
    d->vars.push_back(v);
    if (!accept(Punct::comma)) break;
    if (!name(n, pos, "a name")) return skip_to_statement_end(), nullptr;
  }
  if (!expect(Punct::semicolon, "after a declaration")) return skip_to_statement_end(), nullptr;
  return d;
}

Stmt* Parser::declaration_statement() {
  Stmt* s = Ast::make(ast_.stmts);
  s->pos = peek().pos;
  if (accept_word("precision")) {
    if (!is_precision(peek()))
      error_at_token("expected highp, mediump or lowp after precision");
    else
      advance();
    TypeSpec* t = type_spec();
    if (t && !t->type.is_error() &&
        !(t->type.is_scalar() && (t->type.basic == Basic::float_ || t->type.basic == Basic::int_)) &&
        !t->type.is_sampler())
      error(t->pos, "precision applies to float, int and sampler types only");
    if (!expect(Punct::semicolon, "after a precision statement")) skip_to_statement_end();
    s->kind = StmtKind::empty;
    return s;
  }
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
