#include "shader/lexer.h"

#include <array>
#include <string>

namespace raster::shader {
namespace {

struct PunctSpelling {
  std::string_view text;
  Punct punct;
};

// Longest first, so the first match is the longest (maximal munch).
constexpr std::array<PunctSpelling, 46> kPuncts = {{
    {"<<=", Punct::shl_assign}, {">>=", Punct::shr_assign}, {"<<", Punct::shl},
    {">>", Punct::shr},         {"<=", Punct::le},          {">=", Punct::ge},
    {"==", Punct::eq},          {"!=", Punct::ne},          {"&&", Punct::and_and},
    {"||", Punct::or_or},       {"^^", Punct::xor_xor},     {"++", Punct::inc},
    {"--", Punct::dec},         {"+=", Punct::add_assign},  {"-=", Punct::sub_assign},
    {"*=", Punct::mul_assign},  {"/=", Punct::div_assign},  {"%=", Punct::mod_assign},
    {"&=", Punct::and_assign},  {"|=", Punct::or_assign},   {"^=", Punct::xor_assign},
    {"##", Punct::paste},       {"(", Punct::lparen},       {")", Punct::rparen},
    {"[", Punct::lbracket},     {"]", Punct::rbracket},     {"{", Punct::lbrace},
    {"}", Punct::rbrace},       {".", Punct::dot},          {",", Punct::comma},
    {":", Punct::colon},        {";", Punct::semicolon},    {"?", Punct::question},
    {"+", Punct::plus},         {"-", Punct::minus},        {"*", Punct::star},
    {"/", Punct::slash},        {"%", Punct::percent},      {"<", Punct::less},
    {">", Punct::greater},      {"&", Punct::amp},          {"|", Punct::pipe},
    {"^", Punct::caret},        {"!", Punct::bang},         {"~", Punct::tilde},
    {"=", Punct::assign},
}};

bool is_alpha(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

std::string_view spelling(Punct p) {
  if (p == Punct::hash) return "#";
  for (const PunctSpelling& s : kPuncts)
    if (s.punct == p) return s.text;
  return "";
}

Lexer::Lexer(std::string_view text, Diagnostics& diagnostics, TextArena& arena)
    : text_(text), diagnostics_(diagnostics), arena_(arena) {}

// A backslash at a line's end joins it to the next: skipped wherever it stands, even inside a token.
void Lexer::skip_joins() {
  while (at_ + 1 < text_.size() && text_[at_] == '\\' && (text_[at_ + 1] == '\n' || text_[at_ + 1] == '\r')) {
    at_ += text_[at_ + 1] == '\r' && at_ + 2 < text_.size() && text_[at_ + 2] == '\n' ? 3 : 2;
    ++pos_.line, pos_.column = 1;
    joined_ = true;
  }
}

char Lexer::peek(std::size_t ahead) {
  skip_joins();
  std::size_t at = at_;
  for (; ahead > 0; --ahead) {
    ++at;
    // A join between the characters looked at: rare enough to look past it the slow way.
    while (at + 1 < text_.size() && text_[at] == '\\' && (text_[at + 1] == '\n' || text_[at + 1] == '\r')) {
      at += text_[at + 1] == '\r' && at + 2 < text_.size() && text_[at + 2] == '\n' ? 3 : 2;
    }
  }
  return at < text_.size() ? text_[at] : '\0';
}

void Lexer::advance() {
  skip_joins();
  if (at_ >= text_.size()) return;
  ++at_, ++pos_.column;
}

// Whitespace and comments up to the next token or line end; true if any were skipped.
bool Lexer::skip_space_and_comments() {
  bool skipped = false;
  for (;;) {
    const char c = peek();
    if (c == ' ' || c == '\t' || c == '\v' || c == '\f') {
      advance();
    } else if (c == '/' && peek(1) == '/') {
      while (at_ < text_.size() && peek() != '\n' && peek() != '\r' && at_ < text_.size()) advance();
    } else if (c == '/' && peek(1) == '*') {
      const SourcePos start = pos_;
      advance(), advance();
      for (;;) {
        if (at_ >= text_.size()) {
          diagnostics_.error(start, "unterminated comment: '/*' without '*/'");
          return true;
        }
        const char d = peek();
        if (d == '*' && peek(1) == '/') {
          advance(), advance();
          break;
        }
        if (d == '\n' || d == '\r') {
          at_ += d == '\r' && at_ + 1 < text_.size() && text_[at_ + 1] == '\n' ? 2 : 1;
          ++pos_.line, pos_.column = 1;
        } else {
          advance();
        }
      }
    } else {
      return skipped;
    }
    skipped = true;
  }
}

std::string_view Lexer::spelled(std::size_t start) {
  const std::string_view raw = text_.substr(start, at_ - start);
  if (!joined_) return raw;
  std::string clean;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '\\' && i + 1 < raw.size() && (raw[i + 1] == '\n' || raw[i + 1] == '\r')) {
      i += raw[i + 1] == '\r' && i + 2 < raw.size() && raw[i + 2] == '\n' ? 2 : 1;
      continue;
    }
    clean += raw[i];
  }
  return arena_.keep(std::move(clean));
}

Token Lexer::next() {
  Token t;
  t.space_before = skip_space_and_comments();
  skip_joins();
  t.pos = pos_;
  joined_ = false;
  if (at_ >= text_.size()) return t;  // end
  const std::size_t start = at_;
  const char c = text_[at_];
  if (c == '\n' || c == '\r') {
    at_ += c == '\r' && at_ + 1 < text_.size() && text_[at_ + 1] == '\n' ? 2 : 1;
    ++pos_.line, pos_.column = 1;
    t.kind = TokenKind::newline;
    return t;
  }
  if (is_alpha(c)) {
    while (is_alpha(peek()) || is_digit(peek())) advance();
    t.kind = TokenKind::identifier;
    t.text = spelled(start);
    return t;
  }
  if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return lex_number(t);
  return lex_punct(t);
}

// A preprocessing number: a digit (or a dot and a digit), then letters, digits, dots and an exponent's
// sign. Its meaning (and any error in it) is decided after preprocessing, where it becomes a literal.
Token Lexer::lex_number(Token t) {
  const std::size_t start = at_;
  char last = '\0';
  for (;;) {
    const char c = peek();
    const bool sign = (c == '+' || c == '-') && (last == 'e' || last == 'E');
    if (!(is_alpha(c) || is_digit(c) || c == '.' || sign)) break;
    // In 0x1e+5 the e is a hex digit, not an exponent: a hex number takes no sign.
    if (sign && at_ - start >= 2 && (text_[start + 1] == 'x' || text_[start + 1] == 'X')) break;
    last = c;
    advance();
  }
  t.kind = TokenKind::number;
  t.text = spelled(start);
  return t;
}

Token Lexer::lex_punct(Token t) {
  const std::size_t start = at_;
  const char c = peek();
  if (c == '#') {
    advance();
    if (peek() == '#') {
      advance();
      t.kind = TokenKind::punct, t.punct = Punct::paste;
    } else {
      t.kind = TokenKind::punct, t.punct = Punct::hash;
    }
    t.text = spelled(start);
    return t;
  }
  for (const PunctSpelling& s : kPuncts) {
    bool match = true;
    for (std::size_t i = 0; i < s.text.size() && match; ++i) match = peek(i) == s.text[i];
    if (!match) continue;
    for (std::size_t i = 0; i < s.text.size(); ++i) advance();
    t.kind = TokenKind::punct, t.punct = s.punct;
    t.text = spelled(start);
    return t;
  }
  advance();
  t.kind = TokenKind::other;
  t.text = text_.substr(start, 1);
  return t;
}

std::string_view Lexer::rest_of_line() {
  skip_space_and_comments();
  const std::size_t start = at_;
  joined_ = false;
  while (at_ < text_.size() && peek() != '\n' && peek() != '\r') advance();
  std::string_view line = spelled(start);
  while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
  return line;
}

void Lexer::renumber(int line, int string) {
  pos_.line = line, pos_.string = string;
}

}  // namespace raster::shader
