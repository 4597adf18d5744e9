// The preprocessor's driver and directives; macro expansion is macros.cpp.
#include <charconv>
#include <cstdint>
#include <string>

#include "shader/preprocessor.h"

namespace raster::shader {
namespace {

// The integer expressions of #if and #line (section 3.4), by precedence climbing over the expanded line, in
// 64 bits and wrapped to 32 as GLSL's int is. A name that is not a macro is an error, except in an operand
// && or || does not evaluate (`#if 1 || NOT_DEFINED`), as glslang has it.
class IntExpression {
 public:
  IntExpression(const std::vector<Token>& tokens, std::string_view directive, Diagnostics& diagnostics,
                SourcePos at)
      : tokens_(tokens), directive_(directive), diagnostics_(diagnostics), at_(at) {}

  /// #if's value: one expression, the whole line.
  bool evaluate() {
    std::int64_t value = 0;
    if (!next(value)) return false;
    if (!done()) fail(tokens_[i_].pos, std::string("unexpected ") + describe(tokens_[i_]));
    return !failed_ && value != 0;
  }
  /// The next expression of the line into `value`; false (reported) if it is not one.
  bool next(std::int64_t& value) {
    value = binary(0);
    return !failed_;
  }
  bool done() const { return i_ >= tokens_.size(); }

 private:
  std::string describe(const Token& t) const {
    return std::string("'") + quote(t.text) + "' in #" + std::string(directive_);
  }
  void fail(SourcePos pos, std::string message) {
    if (!failed_) diagnostics_.error(pos, std::move(message));
    failed_ = true;
  }
  static std::int64_t wrap(std::int64_t v) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(v));
  }

  // Binding strength of a binary operator (higher binds tighter), 0 for none.
  static int strength(Punct p) {
    switch (p) {
      case Punct::or_or:
        return 1;
      case Punct::and_and:
        return 2;
      case Punct::pipe:
        return 3;
      case Punct::caret:
        return 4;
      case Punct::amp:
        return 5;
      case Punct::eq:
      case Punct::ne:
        return 6;
      case Punct::less:
      case Punct::greater:
      case Punct::le:
      case Punct::ge:
        return 7;
      case Punct::shl:
      case Punct::shr:
        return 8;
      case Punct::plus:
      case Punct::minus:
        return 9;
      case Punct::star:
      case Punct::slash:
      case Punct::percent:
        return 10;
      default:
        return 0;
    }
  }

  std::int64_t apply(Punct p, std::int64_t a, std::int64_t b, SourcePos pos) {
    switch (p) {
      case Punct::or_or:
        return a || b;
      case Punct::and_and:
        return a && b;
      case Punct::pipe:
        return a | b;
      case Punct::caret:
        return a ^ b;
      case Punct::amp:
        return a & b;
      case Punct::eq:
        return a == b;
      case Punct::ne:
        return a != b;
      case Punct::less:
        return a < b;
      case Punct::greater:
        return a > b;
      case Punct::le:
        return a <= b;
      case Punct::ge:
        return a >= b;
      case Punct::shl:
        return wrap(static_cast<std::int64_t>(static_cast<std::uint64_t>(a) << (b & 31)));
      case Punct::shr:
        return a >> (b & 31);
      case Punct::plus:
        return wrap(a + b);
      case Punct::minus:
        return wrap(a - b);
      case Punct::star:
        return wrap(a * b);
      default:
        if (b == 0) {
          fail(pos, std::string("division by zero in #").append(directive_));
          return 0;
        }
        return wrap(p == Punct::slash ? a / b : a % b);
    }
  }

  std::int64_t binary(int min_strength) {
    std::int64_t left = unary();
    while (!failed_ && i_ < tokens_.size() && tokens_[i_].kind == TokenKind::punct) {
      const Punct p = tokens_[i_].punct;
      const int s = strength(p);
      if (s == 0 || s <= min_strength) break;
      const SourcePos pos = tokens_[i_++].pos;
      const bool skip = (p == Punct::and_and && left == 0) || (p == Punct::or_or && left != 0);
      unevaluated_ += skip;
      const std::int64_t right = binary(s);
      unevaluated_ -= skip;
      left = apply(p, left, right, pos);
    }
    return left;
  }

  std::int64_t unary() {
    if (i_ >= tokens_.size()) {
      fail(at_, std::string("#").append(directive_) + " ends where a value was expected");
      return 0;
    }
    const Token& t = tokens_[i_++];
    if (t.is(Punct::plus)) return unary();
    if (t.is(Punct::minus)) return wrap(-unary());
    if (t.is(Punct::tilde)) return wrap(~unary());
    if (t.is(Punct::bang)) return !unary();
    if (t.is(Punct::lparen)) {
      const std::int64_t v = binary(0);
      if (i_ < tokens_.size() && tokens_[i_].is(Punct::rparen)) {
        ++i_;
      } else {
        fail(t.pos, std::string("'(' without ')' in #").append(directive_));
      }
      return v;
    }
    if (t.kind == TokenKind::number) return number(t);
    if (t.kind == TokenKind::identifier) {
      if (unevaluated_ == 0)
        fail(t.pos, std::string("'") + quote(t.text) + "' is not a macro: #" + std::string(directive_) +
                        " allows only defined macros in GLSL ES");
    } else {
      fail(t.pos, std::string("unexpected ") + describe(t));
    }
    return 0;
  }

  // An int literal: decimal, octal or hex. A `u` suffix is not taken (section 3.4 speaks of integer
  // constants, and glslang reads only int ones).
  std::int64_t number(const Token& t) {
    std::string_view text = t.text;
    int base = 10;
    if (text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
      base = 16, text.remove_prefix(2);
    } else if (text.size() > 1 && text[0] == '0') {
      base = 8, text.remove_prefix(1);
    }
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, base);
    if (ec != std::errc{} || end != text.data() + text.size() || v > 0xffffffffu) {
      fail(t.pos,
           std::string("'") + quote(t.text) + "' is not an integer #" + std::string(directive_) + " can use");
      return 0;
    }
    return wrap(static_cast<std::int64_t>(v));
  }

  const std::vector<Token>& tokens_;
  std::string_view directive_;  ///< "if" or "line", for messages
  Diagnostics& diagnostics_;
  SourcePos at_;
  std::size_t i_ = 0;
  int unevaluated_ = 0;  ///< inside operands && and || skip
  bool failed_ = false;
};

}  // namespace

std::vector<Token> preprocess(std::string_view text, const PreprocessLimits& limits, Diagnostics& diagnostics,
                              TextArena& arena) {
  return Preprocessor(text, limits, diagnostics, arena).run();
}

Preprocessor::Preprocessor(std::string_view text, const PreprocessLimits& limits, Diagnostics& diagnostics,
                           TextArena& arena)
    : lexer_(text, diagnostics, arena), limits_(limits), diagnostics_(diagnostics), arena_(arena) {
  macros_["__LINE__"].builtin = Macro::Builtin::line;
  macros_["__FILE__"].builtin = Macro::Builtin::file;
  macros_["__VERSION__"].builtin = Macro::Builtin::version;
  macros_["GL_ES"].builtin = Macro::Builtin::gl_es;
  macros_["GL_FRAGMENT_PRECISION_HIGH"].builtin = Macro::Builtin::precision_high;
}

Token Preprocessor::next(Input& in) {
  if (!in.stack.empty()) {
    Token t = in.stack.back();
    in.stack.pop_back();
    return t;
  }
  if (!in.lexer) return Token{};
  return lexer_.next();
}

void Preprocessor::unread(Input& in, const Token& t) {
  if (t.kind != TokenKind::end) in.stack.push_back(t);
}

// The rest of a directive's line, its line end read.
std::vector<Token> Preprocessor::line_tokens() {
  std::vector<Token> line;
  for (Token t = next(main_); t.kind != TokenKind::newline && t.kind != TokenKind::end; t = next(main_)) {
    if (!count(1, t.pos)) break;
    line.push_back(t);
  }
  return line;
}

std::vector<Token> Preprocessor::run() {
  std::vector<Token> out;
  bool line_start = true;
  while (!fatal_) {
    const Token t = next(main_);
    if (t.kind == TokenKind::end) break;
    if (t.kind == TokenKind::newline) {
      line_start = true;
      continue;
    }
    const bool first = line_start;
    line_start = false;
    if (first && t.is(Punct::hash) && t.hide == 0) {
      directive();
      line_start = true;
      continue;
    }
    if (!taking()) continue;
    seen_anything_ = seen_token_ = true;
    if (t.kind == TokenKind::identifier && expand(t, main_)) continue;
    if (!count(1, t.pos)) break;
    out.push_back(t);
  }
  if (!fatal_)
    for (const Conditional& c : conditionals_) diagnostics_.error(c.pos, "#if without #endif");
  Token end;
  end.pos = lexer_.position();
  out.push_back(end);
  return out;
}

bool Preprocessor::count(std::size_t tokens, SourcePos at) {
  made_ += tokens;
  if (made_ <= limits_.max_tokens) return true;
  fatal(at, std::string("the program is more than ") + std::to_string(limits_.max_tokens) +
                " tokens after macro expansion (the limit on preprocessing)");
  return false;
}

void Preprocessor::fatal(SourcePos at, std::string message) {
  if (!fatal_) diagnostics_.error(at, std::move(message));
  fatal_ = true;
  diagnostics_.stop();
}

void Preprocessor::directive() {
  const std::vector<Token> line = line_tokens();
  if (line.empty()) return;  // `#` alone is a null directive
  const Token& name = line[0];
  const std::string_view d = name.kind == TokenKind::identifier ? name.text : std::string_view{};
  if (d == "if" || d == "ifdef" || d == "ifndef" || d == "elif" || d == "else" || d == "endif") {
    conditional(d, line, name.pos);
    seen_anything_ = true;
    return;
  }
  if (!taking()) return;  // in a skipped group only the conditionals count
  if (d == "version") return version(line, name.pos);
  seen_anything_ = true;
  if (d == "define") return define(line, name.pos);
  if (d == "undef") return undef(line, name.pos);
  if (d == "line") return line_directive(line, name.pos);
  if (d == "extension") return extension(line, name.pos);
  if (d == "pragma") return pragma(line);
  if (d == "error") {
    std::string message = "#error";
    for (std::size_t i = 1; i < line.size(); ++i) {
      if (i == 1 || line[i].space_before) message += ' ';
      message.append(line[i].text);
    }
    diagnostics_.error(name.pos, quote(message, 200));
    return;
  }
  diagnostics_.error(name.pos, std::string("unknown directive '#") + quote(name.text) + "'");
}

void Preprocessor::version(const std::vector<Token>& line, SourcePos at) {
  if (seen_anything_) {
    diagnostics_.error(at, "#version must come before anything else in the shader");
    return;
  }
  seen_anything_ = true;
  if (line.size() != 3 || line[1].text != "300" || line[2].text != "es")
    diagnostics_.error(at, "only '#version 300 es' (GLSL ES 3.00) is supported");
}

bool Preprocessor::reserved_name(const Token& name, std::string_view what) {
  if (name.kind != TokenKind::identifier) {
    diagnostics_.error(name.pos, std::string(what) + " needs a macro name");
    return true;
  }
  if (name.text == "defined") {
    diagnostics_.error(name.pos, std::string(what) + " of 'defined', which is not a macro name");
    return true;
  }
  if (name.text.starts_with("GL_")) {
    diagnostics_.error(name.pos, std::string(what) + std::string(" of '") + quote(name.text) +
                                     "': names beginning with GL_ are reserved");
    return true;
  }
  const auto it = macros_.find(name.text);
  if (it != macros_.end() && it->second.builtin != Macro::Builtin::none) {
    diagnostics_.error(
        name.pos, std::string(what) + std::string(" of the predefined macro '") + quote(name.text) + "'");
    return true;
  }
  return false;
}

void Preprocessor::undef(const std::vector<Token>& line, SourcePos at) {
  if (line.size() < 2) return diagnostics_.error(at, "#undef needs a macro name");
  if (reserved_name(line[1], "#undef")) return;
  if (line.size() > 2)
    diagnostics_.error(line[2].pos, std::string("unexpected '") + quote(line[2].text) + "' after #undef");
  macros_.erase(line[1].text);
}

void Preprocessor::conditional(std::string_view name, const std::vector<Token>& line, SourcePos at) {
  const bool outer = taking();
  if (name == "if" || name == "ifdef" || name == "ifndef") {
    if (static_cast<int>(conditionals_.size()) >= limits_.max_depth)
      return fatal(at,
                   std::string("#if blocks nest more than ") + std::to_string(limits_.max_depth) + " deep");
    Conditional c;
    c.pos = at;
    if (!outer) {
      c.any_taken = true;  // a skipped group: nothing inside is taken
    } else if (name == "if") {
      c.taking = c.any_taken = evaluate(std::vector<Token>(line.begin() + 1, line.end()), at);
    } else {
      if (line.size() != 2 || line[1].kind != TokenKind::identifier) {
        diagnostics_.error(at, std::string("#") + std::string(name) + " needs exactly one macro name");
      } else {
        c.taking = c.any_taken = (macros_.count(line[1].text) != 0) == (name == "ifdef");
      }
    }
    conditionals_.push_back(c);
    return;
  }
  if (conditionals_.empty())
    return diagnostics_.error(at, std::string("#") + std::string(name) + " without #if");
  Conditional& c = conditionals_.back();
  const bool parent = conditionals_.size() < 2 || conditionals_[conditionals_.size() - 2].taking;
  if (name == "endif") {
    if (line.size() > 1)
      diagnostics_.error(line[1].pos, std::string("unexpected '") + quote(line[1].text) + "' after #endif");
    conditionals_.pop_back();
  } else if (c.seen_else) {
    diagnostics_.error(at, std::string("#") + std::string(name) + " after #else");
  } else if (name == "else") {
    if (line.size() > 1)
      diagnostics_.error(line[1].pos, std::string("unexpected '") + quote(line[1].text) + "' after #else");
    c.seen_else = true;
    c.taking = parent && !c.any_taken;
    c.any_taken = true;
  } else {  // elif
    c.taking = false;
    if (parent && !c.any_taken)
      c.taking = c.any_taken = evaluate(std::vector<Token>(line.begin() + 1, line.end()), at);
  }
}

// `defined NAME` and `defined ( NAME )` become 1 or 0 before the line is expanded, then the line is
// evaluated.
bool Preprocessor::evaluate(std::vector<Token> line, SourcePos at) {
  std::vector<Token> resolved;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (!line[i].is_identifier("defined")) {
      resolved.push_back(line[i]);
      continue;
    }
    const bool paren = i + 1 < line.size() && line[i + 1].is(Punct::lparen);
    const std::size_t n = i + (paren ? 2 : 1);
    if (n >= line.size() || line[n].kind != TokenKind::identifier ||
        (paren && (n + 1 >= line.size() || !line[n + 1].is(Punct::rparen)))) {
      diagnostics_.error(line[i].pos, "'defined' needs a macro name");
      return false;
    }
    Token value = line[i];
    value.kind = TokenKind::number;
    value.text = macros_.count(line[n].text) ? "1" : "0";
    resolved.push_back(value);
    i = n + (paren ? 1 : 0);
  }
  if (resolved.empty()) {
    diagnostics_.error(at, "#if needs an expression");
    return false;
  }
  const std::vector<Token> expanded = expand_all(std::move(resolved));
  if (fatal_) return false;
  return IntExpression(expanded, "if", diagnostics_, at).evaluate();
}

// `#line line` or `#line line string`, each a constant integer expression after macro expansion.
void Preprocessor::line_directive(const std::vector<Token>& line, SourcePos at) {
  const std::vector<Token> expanded = expand_all(std::vector<Token>(line.begin() + 1, line.end()));
  if (expanded.empty()) return diagnostics_.error(at, "#line needs a line number");
  IntExpression e(expanded, "line", diagnostics_, at);
  std::int64_t values[2] = {0, lexer_.position().string};
  for (std::size_t n = 0; n < 2 && !e.done(); ++n)
    if (!e.next(values[n])) return;
  if (!e.done() || values[0] < 0 || values[1] < 0)
    return diagnostics_.error(at, "#line needs a line number and, optionally, a source string number");
  lexer_.renumber(static_cast<int>(values[0]), static_cast<int>(values[1]));
}

// Nothing rasterd does depends on a pragma (section 3.4: an unknown one is ignored), but the two the spec
// defines are written `optimize(on|off)` and `debug(on|off)`, and glslang holds them to that shape.
void Preprocessor::pragma(const std::vector<Token>& line) {
  const std::string_view name = line.size() > 1 ? line[1].text : std::string_view{};
  if (name != "optimize" && name != "debug") return;
  if (line.size() != 5 || !line[2].is(Punct::lparen) || !line[4].is(Punct::rparen))
    diagnostics_.error(line[1].pos, std::string("#pragma ") + std::string(name) + " is written " +
                                        std::string(name) + "(on) or " + std::string(name) + "(off)");
}

void Preprocessor::extension(const std::vector<Token>& line, SourcePos at) {
  if (line.size() != 4 || line[1].kind != TokenKind::identifier || !line[2].is(Punct::colon))
    return diagnostics_.error(at, "#extension needs 'name : behavior'");
  const std::string_view behavior = line[3].text;
  if (behavior != "require" && behavior != "enable" && behavior != "warn" && behavior != "disable")
    return diagnostics_.error(line[3].pos, "#extension behavior must be require, enable, warn or disable");
  if (line[1].text == "all" && (behavior == "require" || behavior == "enable"))
    return diagnostics_.error(line[3].pos, "#extension all can only warn or disable");
  // No extension is supported: asking for one by name is an error only when it is required.
  if (behavior == "require" && line[1].text != "all")
    return diagnostics_.error(line[1].pos,
                              std::string("extension '") + quote(line[1].text) + "' is not supported");
  // Section 3.4 (and ANGLE, which runs ShaderToy's programs; glslang does not check it): so never in a
  // ShaderToy program, after the prelude's uniforms.
  if (seen_token_)
    diagnostics_.error(at,
                       "#extension must come before everything but other directives (a ShaderToy program "
                       "follows the declarations of ShaderToy's uniforms, so it cannot use #extension)");
}

}  // namespace raster::shader
