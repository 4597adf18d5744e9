// The built-in functions of GLSL ES 3.00 (chapter 8), one entry per overload: what the checker matches
// calls against (exactly: GLSL ES 3.00 converts no argument implicitly) and what the lowering expands.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "shader/ast.h"
#include "shader/types.h"

namespace raster::shader {

enum class BuiltinOp : std::uint8_t {
  // 8.1 angles and trigonometry
  radians,
  degrees,
  sin,
  cos,
  tan,
  asin,
  acos,
  atan,
  atan2,
  sinh,
  cosh,
  tanh,
  asinh,
  acosh,
  atanh,
  // 8.2 exponentials
  pow,
  exp,
  log,
  exp2,
  log2,
  sqrt,
  inversesqrt,
  // 8.3 common
  abs,
  sign,
  floor,
  trunc,
  round,
  round_even,
  ceil,
  fract,
  mod,
  modf,
  min,
  max,
  clamp,
  mix,
  mix_bool,
  step,
  smoothstep,
  isnan,
  isinf,
  float_bits_to_int,
  float_bits_to_uint,
  int_bits_to_float,
  uint_bits_to_float,
  // 8.4 packing
  pack_snorm,
  unpack_snorm,
  pack_unorm,
  unpack_unorm,
  pack_half,
  unpack_half,
  // 8.5 geometric
  length,
  distance,
  dot,
  cross,
  normalize,
  faceforward,
  reflect,
  refract,
  // 8.6 matrices
  matrix_comp_mult,
  outer_product,
  transpose,
  determinant,
  inverse,
  // 8.7 vector relational
  less_than,
  less_than_equal,
  greater_than,
  greater_than_equal,
  equal,
  not_equal,
  any,
  all,
  not_,
  // 8.8 textures
  texture_size,
  texture,
  texture_proj,
  texture_lod,
  texture_offset,
  texel_fetch,
  texel_fetch_offset,
  texture_proj_offset,
  texture_lod_offset,
  texture_proj_lod,
  texture_proj_lod_offset,
  texture_grad,
  texture_grad_offset,
  texture_proj_grad,
  texture_proj_grad_offset,
  // 8.9 derivatives
  dfdx,
  dfdy,
  fwidth,
};

struct Builtin {
  std::string_view name;
  BuiltinOp op;
  Type ret;
  std::vector<Type> params;
  std::vector<Qualifier> qualifiers;  ///< Qualifier::in, or out (modf's second parameter)
  bool constant = true;  ///< may be called in a constant expression (all but textures and derivatives)
};

/// Every overload of built-in `name`; empty when no built-in has that name.
const std::vector<const Builtin*>& builtin_overloads(std::string_view name);

}  // namespace raster::shader
