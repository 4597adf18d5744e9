// The parser's driver, tokens, recovery and names; declarations are parse_decl.cpp, statements
// parse_stmt.cpp, expressions parse_expr.cpp.
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
    p.diagnostics_.stop();
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

}  // namespace raster::shader
