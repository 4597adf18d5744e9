#include "shader/engine_lane_ops.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace raster::shader::run {
namespace {

std::uint32_t* slot(std::uint32_t* r, Slot s) {
  return r + static_cast<std::size_t>(s) * kBlockLanes;
}

std::int64_t clamp_index(std::int32_t i, std::uint32_t count) {
  return i < 0 ? 0 : static_cast<std::uint32_t>(i) >= count ? count - 1 : i;
}

float bits_float(std::uint32_t u) {
  return std::bit_cast<float>(u);
}
std::uint32_t float_bits(float f) {
  return std::bit_cast<std::uint32_t>(f);
}

// round-half-to-even of a float known to be within +-65535.
float round_even(float x) {
  return std::nearbyint(x);  // the default rounding mode: to nearest, ties to even
}

std::uint32_t to_half(float f) {
  const std::uint32_t u = float_bits(f);
  const std::uint32_t sign = u >> 16 & 0x8000u;
  const std::uint32_t e = u >> 23 & 0xffu, m = u & 0x7fffffu;
  if (e == 0xff) return sign | 0x7c00u | (m ? 0x200u : 0u);  // Inf, NaN
  const int exp = static_cast<int>(e) - 127 + 15;
  if (exp >= 31) return sign | 0x7c00u;  // overflow: Inf
  if (exp <= 0) {                        // a half denormal (or zero), rounded to nearest even
    if (exp < -10) return sign;
    const std::uint32_t mant = m | 0x800000u;
    const int shift = 14 - exp;
    const std::uint32_t half = mant >> shift, rest = mant & ((1u << shift) - 1), mid = 1u << (shift - 1);
    return sign | (half + (rest > mid || (rest == mid && (half & 1))));
  }
  const std::uint32_t half = static_cast<std::uint32_t>(exp) << 10 | m >> 13, rest = m & 0x1fffu;
  return sign | (half + (rest > 0x1000u || (rest == 0x1000u && (half & 1))));  // a carry may reach Inf
}

float from_half(std::uint32_t h) {
  const std::uint32_t sign = (h & 0x8000u) << 16, e = h >> 10 & 0x1fu, m = h & 0x3ffu;
  if (e == 0) {
    const float v = static_cast<float>(m) * 0x1p-24f;  // exact
    return sign ? -v : v;
  }
  if (e == 31) return bits_float(sign | 0x7f800000u | m << 13);
  return bits_float(sign | (e + 112) << 23 | m << 13);
}

void pack(Op op, std::uint32_t* d, const std::uint32_t* a, const std::uint32_t* b) {
  for (int l = 0; l < kBlockLanes; ++l) {
    std::uint32_t parts[2];
    const float v[2] = {bits_float(a[l]), bits_float(b[l])};
    for (int k = 0; k < 2; ++k) {
      const float x = v[k];
      if (op == Op::pack_half) {
        parts[k] = to_half(x);
      } else if (op == Op::pack_snorm) {
        const float c = std::isnan(x) ? 0.0f : x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
        parts[k] = static_cast<std::uint32_t>(static_cast<std::int32_t>(round_even(c * 32767.0f))) & 0xffffu;
      } else {
        const float c = std::isnan(x) ? 0.0f : x < 0.0f ? 0.0f : x > 1.0f ? 1.0f : x;
        parts[k] = static_cast<std::uint32_t>(round_even(c * 65535.0f));
      }
    }
    d[l] = parts[0] | parts[1] << 16;
  }
}

void unpack(Op op, std::uint32_t* d, const std::uint32_t* a) {
  std::uint32_t* d1 = d + kBlockLanes;
  for (int l = 0; l < kBlockLanes; ++l) {
    float v[2];
    for (int k = 0; k < 2; ++k) {
      const std::uint32_t part = a[l] >> (16 * k) & 0xffffu;
      if (op == Op::unpack_half) {
        v[k] = from_half(part);
      } else if (op == Op::unpack_snorm) {
        const float f = static_cast<float>(static_cast<std::int16_t>(part)) / 32767.0f;
        v[k] = f < -1.0f ? -1.0f : f;
      } else {
        v[k] = static_cast<float>(part) / 65535.0f;
      }
    }
    d[l] = float_bits(v[0]), d1[l] = float_bits(v[1]);
  }
}

// The difference across the lane's 2x2 quad: its right (step 1) or lower (step 8) partner minus its left
// or upper one, in each row or column of the quad (as llvmpipe's fine derivatives).
void derivative(std::uint32_t* d, const std::uint32_t* a, int step) {
  for (int l = 0; l < kBlockLanes; ++l) d[l] = float_bits(bits_float(a[l | step]) - bits_float(a[l & ~step]));
}

}  // namespace

void lane_op(const Instr& in, std::uint32_t* r, const RunContext& context) {
  std::uint32_t* d = slot(r, in.d);
  const std::uint32_t* a = slot(r, in.a);
  const std::uint32_t* b = slot(r, in.b);
  switch (in.op) {
    case Op::load_index:
      for (int l = 0; l < kBlockLanes; ++l)
        d[l] =
            slot(r, in.a + static_cast<Slot>(clamp_index(static_cast<std::int32_t>(b[l]), in.imm) * in.c))[l];
      return;
    case Op::store_index: {
      const std::uint32_t* exec = slot(r, kExecSlot);
      for (int l = 0; l < kBlockLanes; ++l)
        if (exec[l])
          slot(r, in.d + static_cast<Slot>(clamp_index(static_cast<std::int32_t>(b[l]), in.imm) * in.c))[l] =
              a[l];
      return;
    }
    case Op::pack_snorm:
    case Op::pack_unorm:
    case Op::pack_half:
      return pack(in.op, d, a, b);
    case Op::unpack_snorm:
    case Op::unpack_unorm:
    case Op::unpack_half:
      return unpack(in.op, d, a);
    case Op::ddx:
      return derivative(d, a, 1);
    case Op::ddy:
      return derivative(d, a, 8);
    case Op::tex_sample:
      return sample(in, r, context);
    case Op::tex_fetch:
      return fetch(in, r, context);
    case Op::tex_size:
      return texture_size(in, r, context);
    default:
      return;
  }
}

RunResult count_iteration(std::uint32_t loop, std::uint32_t* r, const RunContext& context,
                          BlockState& state) {
  const std::uint32_t* exec = slot(r, kExecSlot);
  for (int l = 0; l < kBlockLanes; ++l) state.counts[l] += static_cast<std::int32_t>(exec[l] & 1);
  if (++state.iterations > context.max_iterations)
    for (int l = 0; l < kBlockLanes; ++l)
      if (state.counts[l] > context.max_iterations) return {RunResult::Status::iterations, loop, l};
  if (context.meter && context.meter->add(kBlockLanes)) return {RunResult::Status::stopped, 0, 0};
  return {};
}

}  // namespace raster::shader::run
