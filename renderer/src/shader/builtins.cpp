// The overload table, written as the spec lists the functions: a signature is a return type and parameter
// types, where F, I, U, B stand for genType, genIType, genUType, genBType (scalar or vector of 2 to 4, the
// same size throughout one signature), V, IV, UV, BV for the vectors alone, and a leading g (gvec4,
// gsampler2D) for the float, int and uint families together. The table is expanded once, on first use.
#include "shader/builtins.h"

#include <string>
#include <unordered_map>

namespace raster::shader {
namespace {

struct Entry {
  std::string_view name;
  BuiltinOp op;
  std::string_view signature;  ///< "ret param param ...", out parameters as "out:T"
};

constexpr Entry kEntries[] = {
    {"radians", BuiltinOp::radians, "F F"},
    {"degrees", BuiltinOp::degrees, "F F"},
    {"sin", BuiltinOp::sin, "F F"},
    {"cos", BuiltinOp::cos, "F F"},
    {"tan", BuiltinOp::tan, "F F"},
    {"asin", BuiltinOp::asin, "F F"},
    {"acos", BuiltinOp::acos, "F F"},
    {"atan", BuiltinOp::atan2, "F F F"},
    {"atan", BuiltinOp::atan, "F F"},
    {"sinh", BuiltinOp::sinh, "F F"},
    {"cosh", BuiltinOp::cosh, "F F"},
    {"tanh", BuiltinOp::tanh, "F F"},
    {"asinh", BuiltinOp::asinh, "F F"},
    {"acosh", BuiltinOp::acosh, "F F"},
    {"atanh", BuiltinOp::atanh, "F F"},
    {"pow", BuiltinOp::pow, "F F F"},
    {"exp", BuiltinOp::exp, "F F"},
    {"log", BuiltinOp::log, "F F"},
    {"exp2", BuiltinOp::exp2, "F F"},
    {"log2", BuiltinOp::log2, "F F"},
    {"sqrt", BuiltinOp::sqrt, "F F"},
    {"inversesqrt", BuiltinOp::inversesqrt, "F F"},
    {"abs", BuiltinOp::abs, "F F"},
    {"abs", BuiltinOp::abs, "I I"},
    {"sign", BuiltinOp::sign, "F F"},
    {"sign", BuiltinOp::sign, "I I"},
    {"floor", BuiltinOp::floor, "F F"},
    {"trunc", BuiltinOp::trunc, "F F"},
    {"round", BuiltinOp::round, "F F"},
    {"roundEven", BuiltinOp::round_even, "F F"},
    {"ceil", BuiltinOp::ceil, "F F"},
    {"fract", BuiltinOp::fract, "F F"},
    {"mod", BuiltinOp::mod, "F F float"},
    {"mod", BuiltinOp::mod, "F F F"},
    {"modf", BuiltinOp::modf, "F F out:F"},
    {"min", BuiltinOp::min, "F F F"},
    {"min", BuiltinOp::min, "F F float"},
    {"min", BuiltinOp::min, "I I I"},
    {"min", BuiltinOp::min, "I I int"},
    {"min", BuiltinOp::min, "U U U"},
    {"min", BuiltinOp::min, "U U uint"},
    {"max", BuiltinOp::max, "F F F"},
    {"max", BuiltinOp::max, "F F float"},
    {"max", BuiltinOp::max, "I I I"},
    {"max", BuiltinOp::max, "I I int"},
    {"max", BuiltinOp::max, "U U U"},
    {"max", BuiltinOp::max, "U U uint"},
    {"clamp", BuiltinOp::clamp, "F F F F"},
    {"clamp", BuiltinOp::clamp, "F F float float"},
    {"clamp", BuiltinOp::clamp, "I I I I"},
    {"clamp", BuiltinOp::clamp, "I I int int"},
    {"clamp", BuiltinOp::clamp, "U U U U"},
    {"clamp", BuiltinOp::clamp, "U U uint uint"},
    {"mix", BuiltinOp::mix, "F F F F"},
    {"mix", BuiltinOp::mix, "F F F float"},
    {"mix", BuiltinOp::mix_bool, "F F F B"},
    {"step", BuiltinOp::step, "F F F"},
    {"step", BuiltinOp::step, "F float F"},
    {"smoothstep", BuiltinOp::smoothstep, "F F F F"},
    {"smoothstep", BuiltinOp::smoothstep, "F float float F"},
    {"isnan", BuiltinOp::isnan, "B F"},
    {"isinf", BuiltinOp::isinf, "B F"},
    {"floatBitsToInt", BuiltinOp::float_bits_to_int, "I F"},
    {"floatBitsToUint", BuiltinOp::float_bits_to_uint, "U F"},
    {"intBitsToFloat", BuiltinOp::int_bits_to_float, "F I"},
    {"uintBitsToFloat", BuiltinOp::uint_bits_to_float, "F U"},
    {"packSnorm2x16", BuiltinOp::pack_snorm, "uint vec2"},
    {"unpackSnorm2x16", BuiltinOp::unpack_snorm, "vec2 uint"},
    {"packUnorm2x16", BuiltinOp::pack_unorm, "uint vec2"},
    {"unpackUnorm2x16", BuiltinOp::unpack_unorm, "vec2 uint"},
    {"packHalf2x16", BuiltinOp::pack_half, "uint vec2"},
    {"unpackHalf2x16", BuiltinOp::unpack_half, "vec2 uint"},
    {"length", BuiltinOp::length, "float F"},
    {"distance", BuiltinOp::distance, "float F F"},
    {"dot", BuiltinOp::dot, "float F F"},
    {"cross", BuiltinOp::cross, "vec3 vec3 vec3"},
    {"normalize", BuiltinOp::normalize, "F F"},
    {"faceforward", BuiltinOp::faceforward, "F F F F"},
    {"reflect", BuiltinOp::reflect, "F F F"},
    {"refract", BuiltinOp::refract, "F F F float"},
    {"lessThan", BuiltinOp::less_than, "BV V V"},
    {"lessThan", BuiltinOp::less_than, "BV IV IV"},
    {"lessThan", BuiltinOp::less_than, "BV UV UV"},
    {"lessThanEqual", BuiltinOp::less_than_equal, "BV V V"},
    {"lessThanEqual", BuiltinOp::less_than_equal, "BV IV IV"},
    {"lessThanEqual", BuiltinOp::less_than_equal, "BV UV UV"},
    {"greaterThan", BuiltinOp::greater_than, "BV V V"},
    {"greaterThan", BuiltinOp::greater_than, "BV IV IV"},
    {"greaterThan", BuiltinOp::greater_than, "BV UV UV"},
    {"greaterThanEqual", BuiltinOp::greater_than_equal, "BV V V"},
    {"greaterThanEqual", BuiltinOp::greater_than_equal, "BV IV IV"},
    {"greaterThanEqual", BuiltinOp::greater_than_equal, "BV UV UV"},
    {"equal", BuiltinOp::equal, "BV V V"},
    {"equal", BuiltinOp::equal, "BV IV IV"},
    {"equal", BuiltinOp::equal, "BV UV UV"},
    {"equal", BuiltinOp::equal, "BV BV BV"},
    {"notEqual", BuiltinOp::not_equal, "BV V V"},
    {"notEqual", BuiltinOp::not_equal, "BV IV IV"},
    {"notEqual", BuiltinOp::not_equal, "BV UV UV"},
    {"notEqual", BuiltinOp::not_equal, "BV BV BV"},
    {"any", BuiltinOp::any, "bool BV"},
    {"all", BuiltinOp::all, "bool BV"},
    {"not", BuiltinOp::not_, "BV BV"},
    {"dFdx", BuiltinOp::dfdx, "F F"},
    {"dFdy", BuiltinOp::dfdy, "F F"},
    {"fwidth", BuiltinOp::fwidth, "F F"},
    // 8.8, as the spec's table lists them
    {"textureSize", BuiltinOp::texture_size, "ivec2 gsampler2D int"},
    {"textureSize", BuiltinOp::texture_size, "ivec3 gsampler3D int"},
    {"textureSize", BuiltinOp::texture_size, "ivec2 gsamplerCube int"},
    {"textureSize", BuiltinOp::texture_size, "ivec2 sampler2DShadow int"},
    {"textureSize", BuiltinOp::texture_size, "ivec2 samplerCubeShadow int"},
    {"textureSize", BuiltinOp::texture_size, "ivec3 gsampler2DArray int"},
    {"textureSize", BuiltinOp::texture_size, "ivec3 sampler2DArrayShadow int"},
    {"texture", BuiltinOp::texture, "gvec4 gsampler2D vec2"},
    {"texture", BuiltinOp::texture, "gvec4 gsampler2D vec2 float"},
    {"texture", BuiltinOp::texture, "gvec4 gsampler3D vec3"},
    {"texture", BuiltinOp::texture, "gvec4 gsampler3D vec3 float"},
    {"texture", BuiltinOp::texture, "gvec4 gsamplerCube vec3"},
    {"texture", BuiltinOp::texture, "gvec4 gsamplerCube vec3 float"},
    {"texture", BuiltinOp::texture, "float sampler2DShadow vec3"},
    {"texture", BuiltinOp::texture, "float sampler2DShadow vec3 float"},
    {"texture", BuiltinOp::texture, "float samplerCubeShadow vec4"},
    {"texture", BuiltinOp::texture, "float samplerCubeShadow vec4 float"},
    {"texture", BuiltinOp::texture, "gvec4 gsampler2DArray vec3"},
    {"texture", BuiltinOp::texture, "gvec4 gsampler2DArray vec3 float"},
    {"texture", BuiltinOp::texture, "float sampler2DArrayShadow vec4"},
    {"textureProj", BuiltinOp::texture_proj, "gvec4 gsampler2D vec3"},
    {"textureProj", BuiltinOp::texture_proj, "gvec4 gsampler2D vec3 float"},
    {"textureProj", BuiltinOp::texture_proj, "gvec4 gsampler2D vec4"},
    {"textureProj", BuiltinOp::texture_proj, "gvec4 gsampler2D vec4 float"},
    {"textureProj", BuiltinOp::texture_proj, "gvec4 gsampler3D vec4"},
    {"textureProj", BuiltinOp::texture_proj, "gvec4 gsampler3D vec4 float"},
    {"textureProj", BuiltinOp::texture_proj, "float sampler2DShadow vec4"},
    {"textureProj", BuiltinOp::texture_proj, "float sampler2DShadow vec4 float"},
    {"textureLod", BuiltinOp::texture_lod, "gvec4 gsampler2D vec2 float"},
    {"textureLod", BuiltinOp::texture_lod, "gvec4 gsampler3D vec3 float"},
    {"textureLod", BuiltinOp::texture_lod, "gvec4 gsamplerCube vec3 float"},
    {"textureLod", BuiltinOp::texture_lod, "float sampler2DShadow vec3 float"},
    {"textureLod", BuiltinOp::texture_lod, "gvec4 gsampler2DArray vec3 float"},
    {"textureOffset", BuiltinOp::texture_offset, "gvec4 gsampler2D vec2 ivec2"},
    {"textureOffset", BuiltinOp::texture_offset, "gvec4 gsampler2D vec2 ivec2 float"},
    {"textureOffset", BuiltinOp::texture_offset, "gvec4 gsampler3D vec3 ivec3"},
    {"textureOffset", BuiltinOp::texture_offset, "gvec4 gsampler3D vec3 ivec3 float"},
    {"textureOffset", BuiltinOp::texture_offset, "float sampler2DShadow vec3 ivec2"},
    {"textureOffset", BuiltinOp::texture_offset, "float sampler2DShadow vec3 ivec2 float"},
    {"textureOffset", BuiltinOp::texture_offset, "gvec4 gsampler2DArray vec3 ivec2"},
    {"textureOffset", BuiltinOp::texture_offset, "gvec4 gsampler2DArray vec3 ivec2 float"},
    {"texelFetch", BuiltinOp::texel_fetch, "gvec4 gsampler2D ivec2 int"},
    {"texelFetch", BuiltinOp::texel_fetch, "gvec4 gsampler3D ivec3 int"},
    {"texelFetch", BuiltinOp::texel_fetch, "gvec4 gsampler2DArray ivec3 int"},
    {"texelFetchOffset", BuiltinOp::texel_fetch_offset, "gvec4 gsampler2D ivec2 int ivec2"},
    {"texelFetchOffset", BuiltinOp::texel_fetch_offset, "gvec4 gsampler3D ivec3 int ivec3"},
    {"texelFetchOffset", BuiltinOp::texel_fetch_offset, "gvec4 gsampler2DArray ivec3 int ivec2"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "gvec4 gsampler2D vec3 ivec2"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "gvec4 gsampler2D vec3 ivec2 float"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "gvec4 gsampler2D vec4 ivec2"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "gvec4 gsampler2D vec4 ivec2 float"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "gvec4 gsampler3D vec4 ivec3"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "gvec4 gsampler3D vec4 ivec3 float"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "float sampler2DShadow vec4 ivec2"},
    {"textureProjOffset", BuiltinOp::texture_proj_offset, "float sampler2DShadow vec4 ivec2 float"},
    {"textureLodOffset", BuiltinOp::texture_lod_offset, "gvec4 gsampler2D vec2 float ivec2"},
    {"textureLodOffset", BuiltinOp::texture_lod_offset, "gvec4 gsampler3D vec3 float ivec3"},
    {"textureLodOffset", BuiltinOp::texture_lod_offset, "float sampler2DShadow vec3 float ivec2"},
    {"textureLodOffset", BuiltinOp::texture_lod_offset, "gvec4 gsampler2DArray vec3 float ivec2"},
    {"textureProjLod", BuiltinOp::texture_proj_lod, "gvec4 gsampler2D vec3 float"},
    {"textureProjLod", BuiltinOp::texture_proj_lod, "gvec4 gsampler2D vec4 float"},
    {"textureProjLod", BuiltinOp::texture_proj_lod, "gvec4 gsampler3D vec4 float"},
    {"textureProjLod", BuiltinOp::texture_proj_lod, "float sampler2DShadow vec4 float"},
    {"textureProjLodOffset", BuiltinOp::texture_proj_lod_offset, "gvec4 gsampler2D vec3 float ivec2"},
    {"textureProjLodOffset", BuiltinOp::texture_proj_lod_offset, "gvec4 gsampler2D vec4 float ivec2"},
    {"textureProjLodOffset", BuiltinOp::texture_proj_lod_offset, "gvec4 gsampler3D vec4 float ivec3"},
    {"textureProjLodOffset", BuiltinOp::texture_proj_lod_offset, "float sampler2DShadow vec4 float ivec2"},
    {"textureGrad", BuiltinOp::texture_grad, "gvec4 gsampler2D vec2 vec2 vec2"},
    {"textureGrad", BuiltinOp::texture_grad, "gvec4 gsampler3D vec3 vec3 vec3"},
    {"textureGrad", BuiltinOp::texture_grad, "gvec4 gsamplerCube vec3 vec3 vec3"},
    {"textureGrad", BuiltinOp::texture_grad, "float sampler2DShadow vec3 vec2 vec2"},
    {"textureGrad", BuiltinOp::texture_grad, "float samplerCubeShadow vec4 vec3 vec3"},
    {"textureGrad", BuiltinOp::texture_grad, "gvec4 gsampler2DArray vec3 vec2 vec2"},
    {"textureGrad", BuiltinOp::texture_grad, "float sampler2DArrayShadow vec4 vec2 vec2"},
    {"textureGradOffset", BuiltinOp::texture_grad_offset, "gvec4 gsampler2D vec2 vec2 vec2 ivec2"},
    {"textureGradOffset", BuiltinOp::texture_grad_offset, "gvec4 gsampler3D vec3 vec3 vec3 ivec3"},
    {"textureGradOffset", BuiltinOp::texture_grad_offset, "float sampler2DShadow vec3 vec2 vec2 ivec2"},
    {"textureGradOffset", BuiltinOp::texture_grad_offset, "gvec4 gsampler2DArray vec3 vec2 vec2 ivec2"},
    {"textureGradOffset", BuiltinOp::texture_grad_offset, "float sampler2DArrayShadow vec4 vec2 vec2 ivec2"},
    {"textureProjGrad", BuiltinOp::texture_proj_grad, "gvec4 gsampler2D vec3 vec2 vec2"},
    {"textureProjGrad", BuiltinOp::texture_proj_grad, "gvec4 gsampler2D vec4 vec2 vec2"},
    {"textureProjGrad", BuiltinOp::texture_proj_grad, "gvec4 gsampler3D vec4 vec3 vec3"},
    {"textureProjGrad", BuiltinOp::texture_proj_grad, "float sampler2DShadow vec4 vec2 vec2"},
    {"textureProjGradOffset", BuiltinOp::texture_proj_grad_offset, "gvec4 gsampler2D vec3 vec2 vec2 ivec2"},
    {"textureProjGradOffset", BuiltinOp::texture_proj_grad_offset, "gvec4 gsampler2D vec4 vec2 vec2 ivec2"},
    {"textureProjGradOffset", BuiltinOp::texture_proj_grad_offset, "gvec4 gsampler3D vec4 vec3 vec3 ivec3"},
    {"textureProjGradOffset", BuiltinOp::texture_proj_grad_offset,
     "float sampler2DShadow vec4 vec2 vec2 ivec2"},
};

bool is_texture(BuiltinOp op) {
  return op >= BuiltinOp::texture_size && op <= BuiltinOp::texture_proj_grad_offset;
}

// One signature token as a type, with generic size n and sampler family prefix g ("", "i" or "u").
Type token_type(std::string_view t, int n, std::string_view g) {
  const auto vec = [&](Basic b) { return Type::of(b, n); };
  if (t == "F" || t == "V") return vec(Basic::float_);
  if (t == "I" || t == "IV") return vec(Basic::int_);
  if (t == "U" || t == "UV") return vec(Basic::uint_);
  if (t == "B" || t == "BV") return vec(Basic::bool_);
  if (t.starts_with('g')) return keyword_type(std::string(g) + std::string(t.substr(1)));
  return keyword_type(t);
}

struct Table {
  std::deque<Builtin> builtins;
  std::unordered_map<std::string_view, std::vector<const Builtin*>> by_name;

  void add(Builtin b) {
    const Builtin* p = &builtins.emplace_back(std::move(b));
    by_name[p->name].push_back(p);
  }

  void expand(const Entry& e) {
    std::vector<std::string_view> tokens;
    for (std::size_t at = 0; at < e.signature.size();) {
      const std::size_t end = std::min(e.signature.find(' ', at), e.signature.size());
      tokens.push_back(e.signature.substr(at, end - at));
      at = end + 1;
    }
    bool generic = false, vectors_only = false, family = false;
    for (const std::string_view t : tokens) {
      const std::string_view bare = t.starts_with("out:") ? t.substr(4) : t;
      if (bare == "F" || bare == "I" || bare == "U" || bare == "B") generic = true;
      if (bare == "V" || bare == "IV" || bare == "UV" || bare == "BV") generic = vectors_only = true;
      if (bare.starts_with('g')) family = true;
    }
    for (const std::string_view g : {"", "i", "u"}) {
      if (!family && !g.empty()) break;
      for (int n = vectors_only ? 2 : 1; n <= (generic ? 4 : 1); ++n) {
        Builtin b;
        b.name = e.name, b.op = e.op,
        b.constant = !is_texture(e.op) && e.op != BuiltinOp::dfdx && e.op != BuiltinOp::dfdy &&
                     e.op != BuiltinOp::fwidth;
        b.ret = token_type(tokens[0], n, g);
        for (std::size_t i = 1; i < tokens.size(); ++i) {
          const bool out = tokens[i].starts_with("out:");
          b.params.push_back(token_type(out ? tokens[i].substr(4) : tokens[i], n, g));
          b.qualifiers.push_back(out ? Qualifier::out : Qualifier::in);
        }
        add(std::move(b));
      }
    }
  }

  // 8.6: the matrix functions, over every matrix shape each applies to.
  void matrices() {
    for (int c = 2; c <= 4; ++c)
      for (int r = 2; r <= 4; ++r) {
        const Type m = Type::of(Basic::float_, r, c), t = Type::of(Basic::float_, c, r);
        add({"matrixCompMult", BuiltinOp::matrix_comp_mult, m, {m, m}, {Qualifier::in, Qualifier::in}});
        add({"outerProduct",
             BuiltinOp::outer_product,
             m,
             {Type::of(Basic::float_, r), Type::of(Basic::float_, c)},
             {Qualifier::in, Qualifier::in}});
        add({"transpose", BuiltinOp::transpose, t, {m}, {Qualifier::in}});
        if (c == r) {
          add({"determinant", BuiltinOp::determinant, Type::of(Basic::float_), {m}, {Qualifier::in}});
          add({"inverse", BuiltinOp::inverse, m, {m}, {Qualifier::in}});
        }
      }
  }

  Table() {
    for (const Entry& e : kEntries) expand(e);
    matrices();
  }
};

}  // namespace

const std::vector<const Builtin*>& builtin_overloads(std::string_view name) {
  static const Table table;  // built once (thread-safe), read-only after
  static const std::vector<const Builtin*> none;
  const auto it = table.by_name.find(name);
  return it == table.by_name.end() ? none : it->second;
}

}  // namespace raster::shader
