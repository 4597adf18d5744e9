// The parser's expressions (section 5), by precedence climbing.
#include <bit>
#include <charconv>
#include <cstring>

#include "shader/parser_impl.h"

namespace raster::shader {
namespace {

// Binding strength of a binary operator (section 5.1; higher binds tighter), 0 for none.
int strength(const Token& t) {
  if (t.kind != TokenKind::punct) return 0;
  switch (t.punct) {
    case Punct::or_or:
      return 1;
    case Punct::xor_xor:
      return 2;
    case Punct::and_and:
      return 3;
    case Punct::pipe:
      return 4;
    case Punct::caret:
      return 5;
    case Punct::amp:
      return 6;
    case Punct::eq:
    case Punct::ne:
      return 7;
    case Punct::less:
    case Punct::greater:
    case Punct::le:
    case Punct::ge:
      return 8;
    case Punct::shl:
    case Punct::shr:
      return 9;
    case Punct::plus:
    case Punct::minus:
      return 10;
    case Punct::star:
    case Punct::slash:
    case Punct::percent:
      return 11;
    default:
      return 0;
  }
}

bool is_assignment(const Token& t) {
  if (t.kind != TokenKind::punct) return false;
  switch (t.punct) {
    case Punct::assign:
    case Punct::add_assign:
    case Punct::sub_assign:
    case Punct::mul_assign:
    case Punct::div_assign:
    case Punct::mod_assign:
    case Punct::shl_assign:
    case Punct::shr_assign:
    case Punct::and_assign:
    case Punct::or_assign:
    case Punct::xor_assign:
      return true;
    default:
      return false;
  }
}

bool is_float_literal(std::string_view text) {
  if (text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) return false;
  return text.find_first_of(".eEfF") != std::string_view::npos;
}

}  // namespace

Expr* Parser::make(ExprKind kind, SourcePos pos) {
  Expr* e = Ast::make(ast_.exprs);
  e->kind = kind, e->pos = pos;
  return e;
}

Expr* Parser::expression() {
  Expr* e = assignment();
  while (e && at(Punct::comma)) {
    const SourcePos pos = advance().pos;
    Expr* s = make(ExprKind::sequence, pos);
    s->args = {e, assignment()};
    if (!s->args[1]) return nullptr;
    e = s;
  }
  return e;
}

Expr* Parser::assignment() {
  DepthGuard guard(*this);
  if (!guard.ok()) return nullptr;
  Expr* left = conditional();
  if (!left || !is_assignment(peek())) return left;
  const Token& op = advance();
  Expr* e = make(ExprKind::assign, op.pos);
  e->op = op.punct;
  e->args = {left, assignment()};
  return e->args[1] ? e : nullptr;
}

Expr* Parser::conditional() {
  Expr* c = binary(0);
  if (!c || !at(Punct::question)) return c;
  const SourcePos pos = advance().pos;
  Expr* e = make(ExprKind::ternary, pos);
  Expr* a = expression();
  if (!a || !expect(Punct::colon, "in ?:")) return nullptr;
  Expr* b = assignment();
  if (!b) return nullptr;
  e->args = {c, a, b};
  return e;
}

Expr* Parser::binary(int min_strength) {
  Expr* left = unary();
  while (left) {
    const int s = strength(peek());
    if (s == 0 || s <= min_strength) break;
    DepthGuard guard(*this);
    if (!guard.ok()) return nullptr;
    const Token& op = advance();
    Expr* e = make(ExprKind::binary, op.pos);
    e->op = op.punct;
    Expr* right = binary(s);
    if (!right) return nullptr;
    e->args = {left, right};
    left = e;
  }
  return left;
}

Expr* Parser::unary() {
  DepthGuard guard(*this);
  if (!guard.ok()) return nullptr;
  const Token& t = peek();
  if (t.is(Punct::inc) || t.is(Punct::dec) || t.is(Punct::plus) || t.is(Punct::minus) || t.is(Punct::bang) ||
      t.is(Punct::tilde)) {
    advance();
    Expr* e = make(ExprKind::unary, t.pos);
    e->op = t.punct;
    Expr* operand = unary();
    if (!operand) return nullptr;
    e->args = {operand};
    return e;
  }
  return postfix();
}

Expr* Parser::postfix() {
  Expr* e = primary();
  while (e) {
    const Token& t = peek();
    if (t.is(Punct::lbracket)) {
      advance();
      Expr* i = make(ExprKind::index, t.pos);
      Expr* at = expression();
      if (!at || !expect(Punct::rbracket, "after an index")) return nullptr;
      i->args = {e, at};
      e = i;
    } else if (t.is(Punct::dot)) {
      advance();
      const Token& field = peek();
      if (field.kind != TokenKind::identifier) {
        error_at_token(std::string("expected a field or swizzle after '.', found ") + describe(field));
        return nullptr;
      }
      advance();
      if (field.text == "length" && at(Punct::lparen)) {
        advance();
        if (!expect(Punct::rparen, "after length(")) return nullptr;
        Expr* l = make(ExprKind::length, field.pos);
        l->args = {e};
        e = l;
        continue;
      }
      if (at(Punct::lparen)) {
        error(field.pos,
              std::string("'") + quote(field.text) + "' is not a method (length() is the only one)");
        return nullptr;
      }
      Expr* f = make(ExprKind::field, field.pos);
      f->name = field.text;
      f->args = {e};
      e = f;
    } else if (t.is(Punct::inc) || t.is(Punct::dec)) {
      advance();
      Expr* p = make(ExprKind::postfix, t.pos);
      p->op = t.punct;
      p->args = {e};
      e = p;
    } else {
      break;
    }
  }
  return e;
}

// `(a, b, ...)`, `()` or `(void)`: an argument after every comma.
Expr* Parser::call_arguments(Expr* call) {
  advance();  // `(`
  if (at_word("void") && peek(1).is(Punct::rparen)) advance();
  if (accept(Punct::rparen)) return call;
  do {
    Expr* a = assignment();
    if (!a) return nullptr;
    call->args.push_back(a);
  } while (accept(Punct::comma));
  if (accept(Punct::rparen)) return call;
  error_at_token(std::string("expected ',' or ')' after an argument, found ") + describe(peek()));
  return nullptr;
}

Expr* Parser::primary() {
  const Token& t = peek();
  if (t.kind == TokenKind::number) return literal(advance());
  if (t.is(Punct::lparen)) {
    advance();
    Expr* e = expression();
    if (!e || !expect(Punct::rparen, "to close '('")) return nullptr;
    return e;
  }
  if (t.kind != TokenKind::identifier) {
    error_at_token(std::string("expected an expression, found ") + describe(t));
    return nullptr;
  }
  if (t.text == "true" || t.text == "false") {
    advance();
    Expr* e = make(ExprKind::literal, t.pos);
    e->type = Type::of(Basic::bool_);
    e->bits = t.text == "true" ? ~0u : 0u;
    return e;
  }
  if (is_type_name(t)) {  // a constructor: `vec3(...)`, `S(...)`, `float[3](...)`, `float[](...)`
    Expr* e = make(ExprKind::construct, t.pos);
    e->spec = type_spec();
    if (!e->spec) return nullptr;
    if (!at(Punct::lparen)) {
      error_at_token(std::string("expected '(' after the type ") + quote(t.text) + std::string(", found ") +
                     describe(peek()));
      return nullptr;
    }
    return call_arguments(e);
  }
  if (is_keyword(t.text) || is_reserved_word(t.text)) {
    error_at_token(std::string("'") + quote(t.text) + std::string("' is a ") +
                   (is_keyword(t.text) ? "keyword" : "reserved word") + " and cannot start an expression");
    return nullptr;
  }
  advance();
  if (at(Punct::lparen)) {
    Expr* e = make(ExprKind::call, t.pos);
    e->name = t.text;
    return call_arguments(e);
  }
  Expr* e = make(ExprKind::name, t.pos);
  e->name = t.text;
  return e;
}

// A number's type and bits (section 4.1.3 and 4.1.4): a float with a dot, an exponent or an f suffix;
// else an int (uint with a u suffix) in decimal, octal (leading 0) or hex (0x), which must fit 32 bits
// (the bit pattern is kept: 0xffffffff is the int -1).
Expr* Parser::literal(const Token& t) {
  Expr* e = make(ExprKind::literal, t.pos);
  std::string_view text = t.text;
  const auto bad = [&](std::string why) {
    error(t.pos, std::string("'") + quote(t.text) + std::string("' ") + why);
    e->type = Type::of(Basic::int_);
    return e;
  };
  if (is_float_literal(text)) {
    if (text.back() == 'f' || text.back() == 'F') text.remove_suffix(1);
    // A float needs a dot or an exponent: "1f" is not one.
    if (text.find_first_of(".eE") == std::string_view::npos ||
        text.find_first_of("fFuUxX") != std::string_view::npos)
      return bad("is not a number");
    float v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec == std::errc::invalid_argument || end != text.data() + text.size()) return bad("is not a number");
    if (ec == std::errc::result_out_of_range) {
      // Past the largest float: +Inf as IEEE rounds it; below the smallest: 0.
      const bool big =
          text.find_first_of("eE") == std::string_view::npos || text[text.find_first_of("eE") + 1] != '-';
      v = big ? std::bit_cast<float>(0x7f800000u) : 0.0f;
    }
    e->type = Type::of(Basic::float_);
    e->bits = std::bit_cast<std::uint32_t>(v);
    return e;
  }
  bool is_unsigned = false;
  if (text.back() == 'u' || text.back() == 'U') text.remove_suffix(1), is_unsigned = true;
  int base = 10;
  if (text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    base = 16, text.remove_prefix(2);
    if (text.empty()) return bad("has no hexadecimal digits");
  } else if (text.size() > 1 && text[0] == '0') {
    base = 8, text.remove_prefix(1);
  }
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, base);
  if (ec == std::errc::result_out_of_range) return bad("does not fit in 32 bits");
  if (ec != std::errc{} || end != text.data() + text.size())
    return bad(base == 8 ? "is not an octal number" : "is not a number");
  if (v > 0xffffffffu) return bad("does not fit in 32 bits");
  e->type = Type::of(is_unsigned ? Basic::uint_ : Basic::int_);
  e->bits = static_cast<std::uint32_t>(v);
  return e;
}

}  // namespace raster::shader
