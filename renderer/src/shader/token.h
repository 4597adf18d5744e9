// Tokens: what the lexer cuts GLSL text into, the preprocessor expands and the parser reads. A token's
// text is a view into the source it came from or into the preprocessor's arena (pasted tokens, __LINE__),
// both alive as long as the compilation.
#pragma once

#include <cstdint>
#include <string_view>

namespace raster::shader {

/// A place in the shader's text: 1-based line and column (columns count bytes) of source string `string`
/// (0 the ShaderToy prelude, 1 the program, 2 the epilogue: shadertoy.h; `#line` may renumber both).
struct SourcePos {
  int line = 0, column = 0;
  int string = 0;
  friend bool operator==(const SourcePos&, const SourcePos&) = default;
};

enum class TokenKind : std::uint8_t {
  end,         ///< after the last token
  newline,     ///< preprocessing only: ends a directive
  identifier,  ///< also keywords, told apart by the parser's keyword table
  number,      ///< a preprocessing number (digits, letters, dots, exponent signs); typed by the parser
  punct,       ///< operator or punctuation, `punct` says which
  other,       ///< a character no token starts with ($, @, `, a lone \, a non-ASCII byte)
};

/// Operators and punctuation, longest first where one is a prefix of another (the lexer's table order).
enum class Punct : std::uint8_t {
  none,
  shl_assign,  // <<=
  shr_assign,  // >>=
  shl,         // <<
  shr,         // >>
  le,          // <=
  ge,          // >=
  eq,          // ==
  ne,          // !=
  and_and,     // &&
  or_or,       // ||
  xor_xor,     // ^^
  inc,         // ++
  dec,         // --
  add_assign,  // +=
  sub_assign,  // -=
  mul_assign,  // *=
  div_assign,  // /=
  mod_assign,  // %=
  and_assign,  // &=
  or_assign,   // |=
  xor_assign,  // ^=
  paste,       // ##
  lparen,
  rparen,
  lbracket,
  rbracket,
  lbrace,
  rbrace,
  dot,
  comma,
  colon,
  semicolon,
  question,
  plus,
  minus,
  star,
  slash,
  percent,
  less,
  greater,
  amp,
  pipe,
  caret,
  bang,
  tilde,
  assign,
  hash,
};

struct Token {
  TokenKind kind = TokenKind::end;
  Punct punct = Punct::none;
  bool space_before = false;  ///< whitespace or a comment precedes it (a macro's `(` must follow at once)
  /// Preprocessing: the macros this token may not expand (an index into the preprocessor's hide sets; 0,
  /// none): a token from a macro's replacement carries that macro's name, so no macro expands itself.
  std::uint32_t hide = 0;
  SourcePos pos;
  std::string_view text;

  bool is(Punct p) const { return kind == TokenKind::punct && punct == p; }
  bool is_identifier(std::string_view name) const { return kind == TokenKind::identifier && text == name; }
};

/// The spelling of a punctuator, for messages.
std::string_view spelling(Punct p);

}  // namespace raster::shader
