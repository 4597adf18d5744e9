// Lexer: GLSL text -> preprocessing tokens, one at a time, with newlines kept (they end directives).
// Comments become whitespace; a backslash before a line end joins the lines (GLSL ES 3.00 section 3.2).
#pragma once

#include <cstddef>
#include <string_view>

#include "shader/diagnostics.h"
#include "shader/token.h"

namespace raster::shader {

class Lexer {
 public:
  Lexer(std::string_view text, Diagnostics& diagnostics, TextArena& arena);

  /// The next token: a newline at each line end, `end` (repeatedly) after the text.
  Token next();
  /// The rest of the current line as raw text (for #error and #pragma), up to but not including its end.
  std::string_view rest_of_line();
  /// `#line`, called once the directive's line end is read: the next line is `line` of source string
  /// `string`.
  void renumber(int line, int string);
  /// Where the next character is, for messages about the end of the text.
  SourcePos position() const { return pos_; }

 private:
  char peek(std::size_t ahead = 0);
  void advance();
  void skip_joins();
  bool skip_space_and_comments();
  Token lex_number(Token t);
  Token lex_punct(Token t);
  std::string_view spelled(std::size_t start);

  std::string_view text_;
  Diagnostics& diagnostics_;
  TextArena& arena_;
  std::size_t at_ = 0;
  SourcePos pos_{1, 1, 0};
  bool joined_ = false;  ///< the current token spans a line join, so its text must be re-spelled
};

}  // namespace raster::shader
