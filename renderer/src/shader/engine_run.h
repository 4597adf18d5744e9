// The interpreter's handlers, written once over a lane type F (float, or FloatLanes for SSE2 and AVX2) and
// run by engine_loop.inc, which engine.cpp compiles once for each. Every handler reads and writes whole
// slots (64 lanes) in steps of F's width; the handlers that look at single lanes (engine_lane_ops.cpp) are
// compiled once. Each group is a switch on an operation its caller names as a constant, so a handler
// inlines to its one case.
#pragma once

#include <limits>

#include "shader/engine_lane_ops.h"
#include "shader/engine_lanes.h"
#include "shader/lane_transcendental.h"

namespace raster::shader::run {

// The handlers' shapes: d = expr of x (and y, z), the slots a, b, c read as the lane type.
#define RASTER_F1(expr) lanes1<F>(d, a, [](F x) RASTER_LANES_INLINE { return expr; })
#define RASTER_F2(expr) lanes2<F, kUniform>(d, a, b, [](F x, F y) RASTER_LANES_INLINE { return expr; })
#define RASTER_F3(expr) \
  lanes3<F, kUniform>(d, a, b, c, [](F x, F y, F z) RASTER_LANES_INLINE { return expr; })
#define RASTER_FX(expr) \
  compare<F, kUniform>(d, a, b, [](F x, [[maybe_unused]] F y) RASTER_LANES_INLINE { return expr; })
#define RASTER_T1(T, expr) lanes1<T>(d, a, [](T x) RASTER_LANES_INLINE { return expr; })
#define RASTER_T2(T, expr) lanes2<T, kUniform>(d, a, b, [](T x, T y) RASTER_LANES_INLINE { return expr; })
#define RASTER_T3(T, expr) \
  lanes3<T, kUniform>(d, a, b, c, [](T x, T y, T z) RASTER_LANES_INLINE { return expr; })
#define RASTER_TX(T, expr) compare<T, kUniform>(d, a, b, [](T x, T y) RASTER_LANES_INLINE { return expr; })

/// Float arithmetic and comparisons; kUniform: the operands that hold one value (lanes2, lanes3).
template <class F, int kUniform = 0>
[[gnu::always_inline]] inline void float_op(Op op, std::uint32_t* d, const std::uint32_t* a,
                                            const std::uint32_t* b, const std::uint32_t* c) {
  switch (op) {
    case Op::fadd:
      return RASTER_F2(x + y);
    case Op::fsub:
      return RASTER_F2(x - y);
    case Op::fmul:
      return RASTER_F2(x * y);
    case Op::fdiv:
      return RASTER_F2(x / y);
    case Op::fneg:
      return RASTER_F1(-x);
    case Op::fabs:
      return RASTER_F1(abs(x));
    case Op::fsign:
      return RASTER_F1(sign(x));
    case Op::ffloor:
      return RASTER_F1(floor(x));
    case Op::fceil:
      return RASTER_F1(ceil(x));
    case Op::ftrunc:
      return RASTER_F1(trunc(x));
    case Op::fround:
      return RASTER_F1(round(x));
    case Op::froundeven:
      return RASTER_F1(roundEven(x));
    case Op::ffract:
      return RASTER_F1(fract(x));
    case Op::fmod:
      return RASTER_F2(mod(x, y));
    case Op::fmin:
      return RASTER_F2(min(x, y));
    case Op::fmax:
      return RASTER_F2(max(x, y));
    case Op::fclamp:
      return RASTER_F3(clamp(x, y, z));
    case Op::fmix:
      return RASTER_F3(mix(x, y, z));
    case Op::fstep:
      return RASTER_F2(step(x, y));
    case Op::fsmoothstep:
      return RASTER_F3(smoothstep(x, y, z));
    case Op::fmuladd:
      return RASTER_F3(x * y + z);
    case Op::fmulsub:
      return RASTER_F3(x * y - z);
    case Op::fnmuladd:
      return RASTER_F3(z - x * y);
    case Op::fsqrt:
      return RASTER_F1(sqrt(x));
    case Op::frsqrt:
      return RASTER_F1(inversesqrt(x));
    case Op::flt:
      return RASTER_FX(lt(x, y));
    case Op::fle:
      return RASTER_FX(le(x, y));
    case Op::fgt:
      return RASTER_FX(gt(x, y));
    case Op::fge:
      return RASTER_FX(ge(x, y));
    case Op::feq:
      return RASTER_FX(eq(x, y));
    case Op::fne:
      return RASTER_FX(ne(x, y));
    case Op::fisnan:
      return RASTER_FX(isnan(x));
    case Op::fisinf:
      return RASTER_FX(isinf(x));
    default:
      return;
  }
}

/// The transcendental functions (lane_transcendental.h).
template <class F, int kUniform = 0>
[[gnu::always_inline]] inline void transcendental_op(Op op, std::uint32_t* d, const std::uint32_t* a,
                                                     const std::uint32_t* b) {
  switch (op) {
    case Op::fsin:
      return RASTER_F1(sin(x));
    case Op::fcos:
      return RASTER_F1(cos(x));
    case Op::ftan:
      return RASTER_F1(tan(x));
    case Op::fasin:
      return RASTER_F1(asin(x));
    case Op::facos:
      return RASTER_F1(acos(x));
    case Op::fatan:
      return RASTER_F1(atan(x));
    case Op::fatan2:
      return RASTER_F2(atan(x, y));
    case Op::fsinh:
      return RASTER_F1(sinh(x));
    case Op::fcosh:
      return RASTER_F1(cosh(x));
    case Op::ftanh:
      return RASTER_F1(tanh(x));
    case Op::fasinh:
      return RASTER_F1(asinh(x));
    case Op::facosh:
      return RASTER_F1(acosh(x));
    case Op::fatanh:
      return RASTER_F1(atanh(x));
    case Op::fexp:
      return RASTER_F1(exp(x));
    case Op::fexp2:
      return RASTER_F1(exp2(x));
    case Op::flog:
      return RASTER_F1(log(x));
    case Op::flog2:
      return RASTER_F1(log2(x));
    case Op::fpow:
      return RASTER_F2(pow(x, y));
    default:
      return;
  }
}

/// Conversions and integer arithmetic (wrapping, in unsigned lanes where the sign does not matter).
template <class F, int kUniform = 0>
[[gnu::always_inline]] inline void integer_op(Op op, std::uint32_t* d, const std::uint32_t* a,
                                              const std::uint32_t* b, const std::uint32_t* c) {
  using I = IntOf<F>;
  using U = UIntOf<F>;
  switch (op) {
    case Op::f2i:
      return convert1<F, I>(d, a, [](F x) RASTER_LANES_INLINE { return float_to_int(x); });
    case Op::f2u:
      return convert1<F, U>(d, a, [](F x) RASTER_LANES_INLINE { return float_to_uint(x); });
    case Op::i2f:
      return convert1<I, F>(d, a, [](I x) RASTER_LANES_INLINE { return int_to_float(x); });
    case Op::u2f:
      return convert1<U, F>(d, a, [](U x) RASTER_LANES_INLINE { return uint_to_float(x); });
    case Op::b2f:
      return RASTER_T1(I, x & splat<I>(0x3f800000));  // true (all ones) -> 1.0f
    case Op::b2i:
      return RASTER_T1(I, x & splat<I>(1));
    case Op::iadd:
      return RASTER_T2(U, x + y);
    case Op::isub:
      return RASTER_T2(U, x - y);
    case Op::imul:
      return RASTER_T2(U, x * y);
    case Op::ineg:
      return RASTER_T1(U, splat<U>(0) - x);
    case Op::iabs:
      return RASTER_T1(I, select(lt(x, splat<I>(0)), as_int(splat<U>(0) - as_uint(x)), x));
    case Op::isign:
      return RASTER_T1(I, (splat<I>(0) - gt(x, splat<I>(0))) + lt(x, splat<I>(0)));
    case Op::imin:
      return RASTER_T2(I, select(lt(y, x), y, x));
    case Op::imax:
      return RASTER_T2(I, select(lt(x, y), y, x));
    case Op::iclamp:
      return RASTER_T3(I, select(lt(z, select(lt(x, y), y, x)), z, select(lt(x, y), y, x)));
    case Op::umin:
      return RASTER_T2(U, select(lt(y, x), y, x));
    case Op::umax:
      return RASTER_T2(U, select(lt(x, y), y, x));
    case Op::uclamp:
      return RASTER_T3(U, select(lt(z, select(lt(x, y), y, x)), z, select(lt(x, y), y, x)));
    case Op::ilt:
      return RASTER_TX(I, lt(x, y));
    case Op::ile:
      return RASTER_TX(I, le(x, y));
    case Op::igt:
      return RASTER_TX(I, gt(x, y));
    case Op::ige:
      return RASTER_TX(I, ge(x, y));
    case Op::ieq:
      return RASTER_TX(I, eq(x, y));
    case Op::ine:
      return RASTER_TX(I, ne(x, y));
    case Op::ult:
      return RASTER_TX(U, lt(x, y));
    case Op::ule:
      return RASTER_TX(U, le(x, y));
    case Op::ugt:
      return RASTER_TX(U, gt(x, y));
    case Op::uge:
      return RASTER_TX(U, ge(x, y));
    case Op::shl:
      return RASTER_T2(U, x << (y & splat<U>(31)));  // counts modulo 32, as x86 and llvmpipe
    case Op::shr:
      return RASTER_T2(I, x >> (y & splat<I>(31)));
    case Op::ushr:
      return RASTER_T2(U, x >> (y & splat<U>(31)));
    case Op::band:
      return RASTER_T2(U, x & y);
    case Op::bor:
      return RASTER_T2(U, x | y);
    case Op::bxor:
      return RASTER_T2(U, x ^ y);
    case Op::imuladd:
      return RASTER_T3(U, x * y + z);
    case Op::shl_xor:
      return RASTER_T3(U, (x << (y & splat<U>(31))) ^ z);
    case Op::shl_or:
      return RASTER_T3(U, (x << (y & splat<U>(31))) | z);
    case Op::shl_add:
      return RASTER_T3(U, (x << (y & splat<U>(31))) + z);
    case Op::ushr_xor:
      return RASTER_T3(U, (x >> (y & splat<U>(31))) ^ z);
    case Op::ushr_or:
      return RASTER_T3(U, (x >> (y & splat<U>(31))) | z);
    case Op::ushr_add:
      return RASTER_T3(U, (x >> (y & splat<U>(31))) + z);
    case Op::bnot:
      return RASTER_T1(U, ~x);
    case Op::select:
      return RASTER_T3(I, select(x, y, z));
    default:
      return;
  }
}

/// Integer division and remainder, one answer for every input (ir.h; as llvmpipe): x / 0 is 0 for int and
/// 0xffffffff for uint, x % 0 is all ones, INT_MIN / -1 is INT_MIN and INT_MIN % -1 is 0; otherwise C's
/// quotient, truncated, and the remainder with the dividend's sign. The quotient of two 32-bit integers is
/// exact in doubles (it is at least 2^-32 of itself away from the next integer, far more than a double's
/// rounding), so eight lanes divide as two vectors of four doubles, not as eight integer divisions.
template <class F, bool kSigned, bool kRemainder>
[[gnu::always_inline]] inline UIntOf<F> divide(UIntOf<F> x, UIntOf<F> y) {
  using U = UIntOf<F>;
  using I = IntOf<F>;
  if constexpr (kOneLane<F>) {
    if (y == 0) return kRemainder || !kSigned ? ~0u : 0u;
    if constexpr (kSigned) {
      const auto sx = static_cast<std::int32_t>(x), sy = static_cast<std::int32_t>(y);
      if (sx == std::numeric_limits<std::int32_t>::min() && sy == -1) return kRemainder ? 0u : x;
      return static_cast<std::uint32_t>(kRemainder ? sx % sy : sx / sy);
    } else {
      return kRemainder ? x % y : x / y;
    }
  } else {
    using Doubles = detail::DoubleHalf;
    using Half = std::int32_t __attribute__((vector_size(16)));
    const U none = as_uint(eq(as_int(y), splat<I>(0)));
    U safe = select(none, splat<U>(1), y);
    if constexpr (kSigned)  // INT_MIN / -1 as INT_MIN / 1: the quotient INT_MIN, the remainder 0
      safe = select(as_uint(eq(as_int(x), splat<I>(std::numeric_limits<std::int32_t>::min())) &
                            eq(as_int(y), splat<I>(-1))),
                    splat<U>(1), safe);
    // Each half's quotient, truncated; unsigned ones moved into int range (exact in doubles) and back.
    const auto half = [](auto n, auto m) RASTER_LANES_INLINE {
      Doubles q;
      if constexpr (kSigned) {
        q = __builtin_convertvector(std::bit_cast<Half>(n), Doubles) /
            __builtin_convertvector(std::bit_cast<Half>(m), Doubles);
      } else {  // uint -> double as int + 2^31; the quotient's 2^31 taken off before it becomes an int
        const Doubles offset = Doubles{} + 2147483648.0;
        q = (__builtin_convertvector(std::bit_cast<Half>(n ^ 0x80000000u), Doubles) + offset) /
            (__builtin_convertvector(std::bit_cast<Half>(m ^ 0x80000000u), Doubles) + offset);
        const auto big = q >= offset;  // then q - 2^31 is exact, and truncates as q does
        return __builtin_convertvector(big ? q - offset : q, Half) ^
               (__builtin_convertvector(big, Half) & std::numeric_limits<std::int32_t>::min());
      }
      return __builtin_convertvector(q, Half);
    };
    const Half lo = half(lane_detail::low(x), lane_detail::low(safe));
    const Half hi = half(lane_detail::high(x), lane_detail::high(safe));
    const U q = std::bit_cast<U>(__builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7));
    if constexpr (kRemainder) return select(none, splat<U>(~0u), x - q * safe);
    return select(none, splat<U>(kSigned ? 0u : ~0u), q);
  }
}

/// The integer divisions (divide above).
template <class F>
[[gnu::always_inline]] inline void divide_op(Op op, std::uint32_t* d, const std::uint32_t* a,
                                             const std::uint32_t* b) {
  using U = UIntOf<F>;
  constexpr int kUniform = 0;
  switch (op) {
    case Op::idiv:
      return RASTER_T2(U, (divide<F, true, false>(x, y)));
    case Op::imod:
      return RASTER_T2(U, (divide<F, true, true>(x, y)));
    case Op::udiv:
      return RASTER_T2(U, (divide<F, false, false>(x, y)));
    case Op::umod:
      return RASTER_T2(U, (divide<F, false, true>(x, y)));
    default:
      return;
  }
}

#undef RASTER_F1
#undef RASTER_F2
#undef RASTER_F3
#undef RASTER_FX
#undef RASTER_T1
#undef RASTER_T2
#undef RASTER_T3
#undef RASTER_TX

/// Control flow: the mask operations, and the jumps they decide (the new pc, or the same one).
template <class F>
[[gnu::always_inline]] inline std::size_t control_op(const Instr& in, std::size_t pc, std::uint32_t* r,
                                                     BlockState& state) {
  using U = UIntOf<F>;
  std::uint32_t* exec = r + static_cast<std::size_t>(kExecSlot) * kBlockLanes;
  std::uint32_t* d = r + static_cast<std::size_t>(in.d) * kBlockLanes;
  const std::uint32_t* a = r + static_cast<std::size_t>(in.a) * kBlockLanes;
  const std::uint32_t* b = r + static_cast<std::size_t>(in.b) * kBlockLanes;
  const std::size_t jump = in.imm;
  switch (in.op) {
    case Op::if_begin:
      std::memcpy(d, exec, kBlockLanes * 4);
      return narrow<U>(exec, a, state) ? pc : jump - 1;
    case Op::if_else:
      std::memcpy(d, exec, kBlockLanes * 4);
      return mask<U>(exec, a, b, state, [](U s, U cond) RASTER_LANES_INLINE { return s & ~cond; }) ? pc
                                                                                                   : jump - 1;
    case Op::if_end:
    case Op::mask_or:
      widen<U>(exec, a, state);
      return pc;
    case Op::if_merge:
      widen_and_not<U>(exec, a, b, state);
      return pc;
    case Op::mask_or_and:
      widen_and<U>(exec, a, b, state);
      return pc;
    case Op::clear:
      std::memset(d, 0, kBlockLanes * 4);
      return pc;
    case Op::leave:
      leave<U>(d, exec, state);
      return pc;
    case Op::loop_test:
      return loop_test<U>(d, exec, a, state) ? pc : jump - 1;
    case Op::leave_if:
      leave_if<U>(d, exec, a, state);
      return pc;
    case Op::loop_end:
      std::memcpy(exec, a, kBlockLanes * 4);
      state.exec_full = all_lanes<U>(exec);
      return pc;
    default:
      return pc;
  }
}

}  // namespace raster::shader::run
