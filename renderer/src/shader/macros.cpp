// Macro definition and expansion: Prosser's algorithm. Each token carries a hide set, the macros whose
// expansion made it; a macro name is not expanded inside its own expansion, and the replacement of a
// function-like macro is rescanned together with what follows it, as C and GLSL specify.
#include <algorithm>
#include <string>

#include "shader/preprocessor.h"

namespace raster::shader {
namespace {

// Two definitions of one macro are the same when their parameters and their bodies' tokens (and where
// whitespace separates them) are.
bool same_definition(const Macro& a, const Macro& b) {
  if (a.function_like != b.function_like || a.params != b.params || a.body.size() != b.body.size())
    return false;
  for (std::size_t i = 0; i < a.body.size(); ++i)
    if (a.body[i].text != b.body[i].text || (i > 0 && a.body[i].space_before != b.body[i].space_before))
      return false;
  return true;
}

int param_index(const Macro& m, const Token& t) {
  if (t.kind != TokenKind::identifier) return -1;
  for (std::size_t i = 0; i < m.params.size(); ++i)
    if (m.params[i] == t.text) return static_cast<int>(i);
  return -1;
}

}  // namespace

void Preprocessor::define(const std::vector<Token>& line, SourcePos at) {
  if (line.size() < 2) return diagnostics_.error(at, "#define needs a macro name");
  const Token& name = line[1];
  if (reserved_name(name, "#define")) return;
  Macro m;
  std::size_t i = 2;
  if (i < line.size() && line[i].is(Punct::lparen) && !line[i].space_before) {
    m.function_like = true;
    ++i;
    for (bool first = true; i < line.size() && !line[i].is(Punct::rparen); first = false) {
      if (!first && !line[i].is(Punct::comma)) break;  // `(a b)`: reported below
      if (!first) ++i;
      if (i >= line.size() || line[i].kind != TokenKind::identifier)
        return diagnostics_.error(
            at, std::string("#define ") + quote(name.text) + ": a parameter must be a name");
      if (std::find(m.params.begin(), m.params.end(), line[i].text) != m.params.end())
        return diagnostics_.error(line[i].pos, std::string("#define ") + quote(name.text) + ": parameter '" +
                                                   quote(line[i].text) + "' named twice");
      m.params.push_back(line[i++].text);
    }
    if (i >= line.size() || !line[i].is(Punct::rparen))
      return diagnostics_.error(at, std::string("#define ") + quote(name.text) + ": parameters without ')'");
    ++i;
  }
  m.body.assign(line.begin() + static_cast<std::ptrdiff_t>(i), line.end());
  if (!m.body.empty() && (m.body.front().is(Punct::paste) || m.body.back().is(Punct::paste)))
    return diagnostics_.error(
        at, std::string("#define ") + quote(name.text) + ": '##' needs a token on each side");
  const auto it = macros_.find(name.text);
  if (it != macros_.end() && !same_definition(it->second, m))
    return diagnostics_.error(name.pos,
                              std::string("macro '") + quote(name.text) + "' redefined differently");
  macros_[name.text] = std::move(m);
}

bool Preprocessor::hidden(std::uint32_t set, std::string_view name) const {
  const std::vector<std::string_view>& s = hide_sets_[set];
  return std::find(s.begin(), s.end(), name) != s.end();
}

std::uint32_t Preprocessor::hide_union(std::uint32_t set, std::string_view name) {
  if (hidden(set, name)) return set;
  std::vector<std::string_view> s = hide_sets_[set];
  s.push_back(name);
  hide_sets_.push_back(std::move(s));
  return static_cast<std::uint32_t>(hide_sets_.size() - 1);
}

std::uint32_t Preprocessor::hide_union(std::uint32_t a, std::uint32_t b) {
  if (a == b || b == 0) return a;
  if (a == 0) return b;
  std::uint32_t s = a;
  for (std::size_t i = 0; i < hide_sets_[b].size(); ++i) s = hide_union(s, hide_sets_[b][i]);
  return s;
}

std::uint32_t Preprocessor::hide_intersection(std::uint32_t a, std::uint32_t b) {
  if (a == b) return a;
  std::vector<std::string_view> s;
  for (const std::string_view n : hide_sets_[a])
    if (hidden(b, n)) s.push_back(n);
  if (s.empty()) return 0;
  hide_sets_.push_back(std::move(s));
  return static_cast<std::uint32_t>(hide_sets_.size() - 1);
}

Token Preprocessor::builtin_value(Macro::Builtin builtin, const Token& use) {
  Token t = use;
  t.kind = TokenKind::number;
  switch (builtin) {
    case Macro::Builtin::line:
      t.text = arena_.keep(std::to_string(use.pos.line));
      break;
    case Macro::Builtin::file:
      t.text = arena_.keep(std::to_string(use.pos.string));
      break;
    case Macro::Builtin::version:
      t.text = "300";
      break;
    default:
      t.text = "1";
      break;  // GL_ES, GL_FRAGMENT_PRECISION_HIGH
  }
  return t;
}

// If `name` is a macro it may expand here, its replacement goes back onto `in` (to be rescanned with what
// follows) and the answer is true.
bool Preprocessor::expand(const Token& name, Input& in) {
  const auto it = macros_.find(name.text);
  if (it == macros_.end() || hidden(name.hide, name.text)) return false;
  const Macro& m = it->second;
  if (m.builtin != Macro::Builtin::none) {
    unread(in, builtin_value(m.builtin, name));
    return true;
  }
  std::vector<std::vector<Token>> args;
  std::uint32_t hide = name.hide;
  if (m.function_like) {
    Token close;
    if (!collect_arguments(name, in, args, close)) return fatal_;  // no `(`: just a name
    hide = hide_intersection(name.hide, close.hide);
  }
  const std::vector<Token> replacement = substitute(m, args, hide_union(hide, name.text), name.pos);
  if (!count(replacement.size(), name.pos)) return true;
  for (auto r = replacement.rbegin(); r != replacement.rend(); ++r) in.stack.push_back(*r);
  return true;
}

// A function-like macro's arguments, from the `(` after its name to the matching `)`, split at the commas
// outside inner parentheses. False (nothing read) when no `(` follows: the name is then an identifier.
bool Preprocessor::collect_arguments(const Token& name, Input& in, std::vector<std::vector<Token>>& args,
                                     Token& close) {
  std::vector<Token> newlines;
  Token t = next(in);
  for (; t.kind == TokenKind::newline; t = next(in)) newlines.push_back(t);
  if (!t.is(Punct::lparen)) {
    unread(in, t);
    for (auto n = newlines.rbegin(); n != newlines.rend(); ++n) unread(in, *n);
    return false;
  }
  const Macro& m = macros_.at(name.text);
  args.emplace_back();
  int depth = 0;
  for (;;) {
    t = next(in);
    if (t.kind == TokenKind::end) {
      fatal(name.pos, std::string("macro '") + quote(name.text) + "' is called without its closing ')'");
      return false;
    }
    if (t.kind == TokenKind::newline) continue;
    if (!count(1, t.pos)) return false;
    if (t.is(Punct::lparen)) ++depth;
    if (t.is(Punct::rparen) && depth-- == 0) break;
    if (t.is(Punct::comma) && depth == 0) {
      args.emplace_back();
      continue;
    }
    args.back().push_back(t);
  }
  close = t;
  if (m.params.empty() && args.size() == 1 && args[0].empty()) args.clear();
  if (args.size() != m.params.size()) {
    diagnostics_.error(name.pos, std::string("macro '") + quote(name.text) + std::string("' takes ") +
                                     std::to_string(m.params.size()) + std::string(" argument") +
                                     (m.params.size() == 1 ? "" : "s") + ", given " +
                                     std::to_string(args.size()));
    args.assign(m.params.size(), {});
  }
  return true;
}

// Every macro in `tokens` expanded, as an argument is before it replaces its parameter.
std::vector<Token> Preprocessor::expand_all(std::vector<Token> tokens) {
  std::vector<Token> out;
  if (depth_ >= limits_.max_depth) {
    fatal(tokens.empty() ? lexer_.position() : tokens[0].pos,
          std::string("macro arguments nest more than ") + std::to_string(limits_.max_depth) + " deep");
    return out;
  }
  ++depth_;
  Input in;
  in.stack.assign(tokens.rbegin(), tokens.rend());
  while (!fatal_) {
    const Token t = next(in);
    if (t.kind == TokenKind::end) break;
    if (t.kind == TokenKind::identifier && expand(t, in)) continue;
    out.push_back(t);
  }
  --depth_;
  return out;
}

// The body with each parameter replaced by its argument (expanded, unless next to ##), `##` pasting its
// neighbours into one token, and every token given `hide` and the place of the macro's use.
std::vector<Token> Preprocessor::substitute(const Macro& macro, const std::vector<std::vector<Token>>& args,
                                            std::uint32_t hide, SourcePos at) {
  std::vector<std::vector<Token>> expanded(args.size());
  std::vector<bool> done(args.size(), false);
  std::vector<Token> out;
  bool paste_next = false;
  const std::vector<Token>& body = macro.body;
  for (std::size_t i = 0; i < body.size() && !fatal_; ++i) {
    if (body[i].is(Punct::paste)) {
      paste_next = true;
      continue;
    }
    std::vector<Token> piece;
    const int p = param_index(macro, body[i]);
    if (p < 0) {
      piece.push_back(body[i]);
    } else if (paste_next || (i + 1 < body.size() && body[i + 1].is(Punct::paste))) {
      piece = args[static_cast<std::size_t>(p)];
    } else {
      const auto k = static_cast<std::size_t>(p);
      if (!done[k]) expanded[k] = expand_all(args[k]), done[k] = true;
      piece = expanded[k];
    }
    if (!piece.empty()) piece[0].space_before = body[i].space_before;
    std::size_t from = 0;
    if (paste_next && !piece.empty() && !out.empty()) {
      if (!paste(out.back(), piece[0])) return {};
      from = 1;
    }
    paste_next = false;
    out.insert(out.end(), piece.begin() + static_cast<std::ptrdiff_t>(from), piece.end());
  }
  for (Token& t : out) t.hide = hide_union(t.hide, hide), t.pos = at;
  return out;
}

// `left ## right`: their spellings joined must be one token, which replaces `left`.
bool Preprocessor::paste(Token& left, const Token& right) {
  const std::string_view joined = arena_.keep(std::string(left.text) + std::string(right.text));
  Diagnostics quiet;
  Lexer lexer(joined, quiet, arena_);
  Token t = lexer.next();
  if (quiet.failed() || t.kind == TokenKind::end || t.text.size() != joined.size() ||
      lexer.next().kind != TokenKind::end) {
    diagnostics_.error(left.pos, std::string("pasting '") + quote(left.text) + std::string("' and '") +
                                     quote(right.text) + "' does not give one token");
    return false;
  }
  t.pos = left.pos, t.space_before = left.space_before, t.hide = left.hide;
  left = t;
  return true;
}

}  // namespace raster::shader
