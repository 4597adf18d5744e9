// The lowering's built-in functions (chapter 8). Each is the formula its spec gives, in the order Mesa's
// GLSL compiler writes it (docs/shaders.md says which), so rasterd's pixels track llvmpipe's; functions of
// one component each are one instruction a component.
#include <cmath>

#include "shader/lowerer.h"

namespace raster::shader {
namespace {

// Built-ins that are one instruction a component: the operation for float arguments, then for int and
// uint ones where the built-in takes them.
struct SimpleOp {
  BuiltinOp builtin;
  Op f, i, u;
};
constexpr SimpleOp kSimpleOps[] = {
    {BuiltinOp::sin, Op::fsin, Op::fsin, Op::fsin},
    {BuiltinOp::cos, Op::fcos, Op::fcos, Op::fcos},
    {BuiltinOp::tan, Op::ftan, Op::ftan, Op::ftan},
    {BuiltinOp::asin, Op::fasin, Op::fasin, Op::fasin},
    {BuiltinOp::acos, Op::facos, Op::facos, Op::facos},
    {BuiltinOp::atan, Op::fatan, Op::fatan, Op::fatan},
    {BuiltinOp::atan2, Op::fatan2, Op::fatan2, Op::fatan2},
    {BuiltinOp::sinh, Op::fsinh, Op::fsinh, Op::fsinh},
    {BuiltinOp::cosh, Op::fcosh, Op::fcosh, Op::fcosh},
    {BuiltinOp::tanh, Op::ftanh, Op::ftanh, Op::ftanh},
    {BuiltinOp::asinh, Op::fasinh, Op::fasinh, Op::fasinh},
    {BuiltinOp::acosh, Op::facosh, Op::facosh, Op::facosh},
    {BuiltinOp::atanh, Op::fatanh, Op::fatanh, Op::fatanh},
    {BuiltinOp::pow, Op::fpow, Op::fpow, Op::fpow},
    {BuiltinOp::exp, Op::fexp, Op::fexp, Op::fexp},
    {BuiltinOp::log, Op::flog, Op::flog, Op::flog},
    {BuiltinOp::exp2, Op::fexp2, Op::fexp2, Op::fexp2},
    {BuiltinOp::log2, Op::flog2, Op::flog2, Op::flog2},
    {BuiltinOp::sqrt, Op::fsqrt, Op::fsqrt, Op::fsqrt},
    {BuiltinOp::inversesqrt, Op::frsqrt, Op::frsqrt, Op::frsqrt},
    {BuiltinOp::abs, Op::fabs, Op::iabs, Op::iabs},
    {BuiltinOp::sign, Op::fsign, Op::isign, Op::isign},
    {BuiltinOp::floor, Op::ffloor, Op::ffloor, Op::ffloor},
    {BuiltinOp::trunc, Op::ftrunc, Op::ftrunc, Op::ftrunc},
    {BuiltinOp::round, Op::fround, Op::fround, Op::fround},
    {BuiltinOp::round_even, Op::froundeven, Op::froundeven, Op::froundeven},
    {BuiltinOp::ceil, Op::fceil, Op::fceil, Op::fceil},
    {BuiltinOp::fract, Op::ffract, Op::ffract, Op::ffract},
    {BuiltinOp::mod, Op::fmod, Op::fmod, Op::fmod},
    {BuiltinOp::min, Op::fmin, Op::imin, Op::umin},
    {BuiltinOp::max, Op::fmax, Op::imax, Op::umax},
    {BuiltinOp::clamp, Op::fclamp, Op::iclamp, Op::uclamp},
    {BuiltinOp::mix, Op::fmix, Op::fmix, Op::fmix},
    {BuiltinOp::step, Op::fstep, Op::fstep, Op::fstep},
    {BuiltinOp::smoothstep, Op::fsmoothstep, Op::fsmoothstep, Op::fsmoothstep},
    {BuiltinOp::isnan, Op::fisnan, Op::fisnan, Op::fisnan},
    {BuiltinOp::isinf, Op::fisinf, Op::fisinf, Op::fisinf},
    {BuiltinOp::dfdx, Op::ddx, Op::ddx, Op::ddx},
    {BuiltinOp::dfdy, Op::ddy, Op::ddy, Op::ddy},
};

bool simple_op(BuiltinOp op, Basic b, Op& out) {
  for (const SimpleOp& s : kSimpleOps)
    if (s.builtin == op) {
      out = b == Basic::float_ ? s.f : b == Basic::uint_ ? s.u : s.i;
      return true;
    }
  return false;
}

// Whether e is a constant whose every component is +1 or -1.
bool unit_constant(const Expr* e) {
  if (!e->constant) return false;
  const std::vector<std::uint32_t> v = e->value.empty() ? fold_constant(*e) : e->value;
  if (v.empty()) return false;
  for (const std::uint32_t bits : v)
    if ((bits & 0x7fffffffu) != 0x3f800000u) return false;
  return true;
}

}  // namespace

// a0 b0 + a1 b1 + ..., summed from the last term, as Mesa scalarizes a dot product (and matrix products):
// ((a3 b3 + a2 b2) + a1 b1) + a0 b0.
Slot Lowerer::dot(const Value& a, const Value& b) {
  std::vector<Slot> terms;
  for (std::size_t i = 0; i < a.s.size(); ++i) terms.push_back(emit(Op::fmul, a.s[i], b.s[i]));
  return sum(terms);
}

Slot Lowerer::sum(const std::vector<Slot>& terms) {
  Slot s = terms.back();
  for (std::size_t i = terms.size() - 1; i-- > 0;) s = emit(Op::fadd, s, terms[i]);
  return s;
}

Value Lowerer::builtin(const Expr* e, std::vector<Value> a) {
  const BuiltinOp op = e->builtin->op;
  const Type& t = e->type;
  if (op == BuiltinOp::dfdx || op == BuiltinOp::dfdy || op == BuiltinOp::fwidth)
    out_.program.derivatives = true;
  Op simple;
  const Basic basic = a.empty() ? t.basic : a[0].type.basic;
  if (simple_op(op, basic, simple)) {
    std::vector<const Value*> args;
    for (const Value& v : a) args.push_back(&v);
    return map(simple, t, args);
  }
  const auto scaled = [&](float k) {
    const Value c{Type::of(Basic::float_), {fconst(k)}};
    return map(Op::fmul, t, {&a[0], &c});
  };
  if (op == BuiltinOp::mix && (e->args[2]->constant || unit_constant(e->args[1]))) return precise_mix(t, a);
  switch (op) {
    case BuiltinOp::radians:
      return scaled(static_cast<float>(M_PI / 180.0));
    case BuiltinOp::degrees:
      return scaled(static_cast<float>(180.0 / M_PI));
    case BuiltinOp::mix_bool:
      return map(Op::select, t, {&a[2], &a[1], &a[0]});
    case BuiltinOp::fwidth: {
      const Value dx = map(Op::ddx, t, {&a[0]}), dy = map(Op::ddy, t, {&a[0]});
      const Value ax = map(Op::fabs, t, {&dx}), ay = map(Op::fabs, t, {&dy});
      return map(Op::fadd, t, {&ax, &ay});
    }
    case BuiltinOp::modf: {  // the whole part to the out argument, the fraction (same sign) returned
      const Value x = a[0];
      const Value whole = map(Op::ftrunc, t, {&x});
      write(place(e->args[1]), whole);
      return map(Op::fsub, t, {&x, &whole});
    }
    case BuiltinOp::float_bits_to_int:
    case BuiltinOp::float_bits_to_uint:
    case BuiltinOp::int_bits_to_float:
    case BuiltinOp::uint_bits_to_float: {  // slots are 32 bits: only the type changes
      Value v = a[0];
      v.type = t;
      return v;
    }
    case BuiltinOp::pack_snorm:
    case BuiltinOp::pack_unorm:
    case BuiltinOp::pack_half:
    case BuiltinOp::unpack_snorm:
    case BuiltinOp::unpack_unorm:
    case BuiltinOp::unpack_half:
      return packing(op, t, a[0]);
    case BuiltinOp::length:
    case BuiltinOp::distance:
    case BuiltinOp::dot:
    case BuiltinOp::cross:
    case BuiltinOp::normalize:
    case BuiltinOp::faceforward:
    case BuiltinOp::reflect:
    case BuiltinOp::refract:
      return geometric(op, t, a);
    case BuiltinOp::matrix_comp_mult:
    case BuiltinOp::outer_product:
    case BuiltinOp::transpose:
    case BuiltinOp::determinant:
    case BuiltinOp::inverse:
      return matrix_builtin(op, t, a);
    case BuiltinOp::less_than:
    case BuiltinOp::less_than_equal:
    case BuiltinOp::greater_than:
    case BuiltinOp::greater_than_equal:
    case BuiltinOp::equal:
    case BuiltinOp::not_equal:
    case BuiltinOp::any:
    case BuiltinOp::all:
    case BuiltinOp::not_:
      return relational(op, t, a);
    default:
      return texture(op, t, a, e);
  }
}

// mix in Mesa's precise form, which it takes where the weight is a constant or y is +-1: x (1 - a) + y a.
Value Lowerer::precise_mix(const Type& t, const std::vector<Value>& a) {
  const Value one{Type::of(Basic::float_), {fconst(1.0f)}};
  const Value rest = map(Op::fsub, a[2].type, {&one, &a[2]});
  const Value xs = map(Op::fmul, t, {&a[0], &rest}), ys = map(Op::fmul, t, {&a[1], &a[2]});
  return map(Op::fadd, t, {&xs, &ys});
}

// Section 8.4: two floats in a uint's halves, and back.
Value Lowerer::packing(BuiltinOp op, const Type& t, const Value& a) {
  switch (op) {
    case BuiltinOp::pack_snorm:
      return Value{t, {emit(Op::pack_snorm, a.s[0], a.s[1])}};
    case BuiltinOp::pack_unorm:
      return Value{t, {emit(Op::pack_unorm, a.s[0], a.s[1])}};
    case BuiltinOp::pack_half:
      return Value{t, {emit(Op::pack_half, a.s[0], a.s[1])}};
    default: {
      const Op p = op == BuiltinOp::unpack_snorm   ? Op::unpack_snorm
                   : op == BuiltinOp::unpack_unorm ? Op::unpack_unorm
                                                   : Op::unpack_half;
      const Slot d = group(2);
      emit_to(p, d, a.s[0]);
      return Value{t, {d, d + 1}};
    }
  }
}

// Section 8.5, as Mesa writes them: length = sqrt(dot(v, v)); normalize = v * inversesqrt(dot(v, v));
// reflect = I - 2 dot(N, I) N; refract and faceforward as the spec states.
Value Lowerer::geometric(BuiltinOp op, const Type& t, const std::vector<Value>& a) {
  const Value scalar_type{Type::of(Basic::float_), {}};
  switch (op) {
    case BuiltinOp::dot:
      return Value{t, {dot(a[0], a[1])}};
    case BuiltinOp::length:
      return Value{t, {emit(Op::fsqrt, dot(a[0], a[0]))}};
    case BuiltinOp::distance: {
      const Value d = map(Op::fsub, a[0].type, {&a[0], &a[1]});
      if (d.s.size() == 1) return Value{t, {emit(Op::fabs, d.s[0])}};  // Mesa's scalar form: |a - b|
      return Value{t, {emit(Op::fsqrt, dot(d, d))}};
    }
    case BuiltinOp::normalize: {
      if (a[0].s.size() == 1) return Value{t, {emit(Op::fsign, a[0].s[0])}};  // Mesa's scalar form
      const Value k{Type::of(Basic::float_), {emit(Op::frsqrt, dot(a[0], a[0]))}};
      return map(Op::fmul, t, {&a[0], &k});
    }
    case BuiltinOp::cross: {
      const auto& x = a[0].s;
      const auto& y = a[1].s;
      Value r{t, {}};
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        r.s.push_back(emit(Op::fsub, emit(Op::fmul, x[j], y[k]), emit(Op::fmul, x[k], y[j])));
      }
      return r;
    }
    case BuiltinOp::faceforward: {  // dot(Nref, I) < 0 ? N : -N
      const Slot facing = emit(Op::flt, dot(a[2], a[1]), fconst(0.0f));
      const Value minus = map(Op::fneg, t, {&a[0]});
      Value r{t, {}};
      for (std::size_t i = 0; i < a[0].s.size(); ++i)
        r.s.push_back(emit(Op::select, facing, a[0].s[i], minus.s[i]));
      return r;
    }
    case BuiltinOp::reflect: {  // I - 2 (dot(N, I) N)
      const Slot d = dot(a[1], a[0]);
      Value r{t, {}};
      for (std::size_t i = 0; i < a[0].s.size(); ++i)
        r.s.push_back(emit(Op::fsub, a[0].s[i], emit(Op::fmul, fconst(2.0f), emit(Op::fmul, d, a[1].s[i]))));
      return r;
    }
    default: {  // refract: k = 1 - eta (eta (1 - d d)); k < 0 ? 0 : eta I - (eta d + sqrt(k)) N, d = dot(N,
                // I)
      const Slot eta = a[2].s[0], d = dot(a[1], a[0]);
      const Slot k =
          emit(Op::fsub, fconst(1.0f),
               emit(Op::fmul, eta, emit(Op::fmul, eta, emit(Op::fsub, fconst(1.0f), emit(Op::fmul, d, d)))));
      const Slot reflected = emit(Op::flt, k, fconst(0.0f));
      const Slot scale = emit(Op::fadd, emit(Op::fmul, eta, d), emit(Op::fsqrt, k));
      Value r{t, {}};
      for (std::size_t i = 0; i < a[0].s.size(); ++i) {
        const Slot v = emit(Op::fsub, emit(Op::fmul, eta, a[0].s[i]), emit(Op::fmul, scale, a[1].s[i]));
        r.s.push_back(emit(Op::select, reflected, fconst(0.0f), v));
      }
      (void)scalar_type;
      return r;
    }
  }
}

Value Lowerer::relational(BuiltinOp op, const Type& t, const std::vector<Value>& a) {
  const Basic b = a[0].type.basic;
  const bool f = b == Basic::float_, u = b == Basic::uint_;
  switch (op) {
    case BuiltinOp::any:
    case BuiltinOp::all: {
      Slot r = a[0].s[0];
      for (std::size_t i = 1; i < a[0].s.size(); ++i)
        r = emit(op == BuiltinOp::any ? Op::bor : Op::band, r, a[0].s[i]);
      return Value{t, {r}};
    }
    case BuiltinOp::not_:
      return map(Op::bnot, t, {&a[0]});
    default:
      break;
  }
  Op c = Op::feq;
  switch (op) {
    case BuiltinOp::less_than:
      c = f ? Op::flt : u ? Op::ult : Op::ilt;
      break;
    case BuiltinOp::less_than_equal:
      c = f ? Op::fle : u ? Op::ule : Op::ile;
      break;
    case BuiltinOp::greater_than:
      c = f ? Op::fgt : u ? Op::ugt : Op::igt;
      break;
    case BuiltinOp::greater_than_equal:
      c = f ? Op::fge : u ? Op::uge : Op::ige;
      break;
    case BuiltinOp::equal:
      c = f ? Op::feq : Op::ieq;
      break;
    default:
      c = f ? Op::fne : Op::ine;
      break;  // not_equal
  }
  return map(c, t, {&a[0], &a[1]});
}

}  // namespace raster::shader
