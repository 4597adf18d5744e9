#include "shader/types.h"

#include <array>

namespace raster::shader {
namespace {

struct SamplerName {
  std::string_view name;
  SamplerKind kind;
};

constexpr std::array<SamplerName, 15> kSamplers = {{
    {"sampler2D", SamplerKind::sampler2D},
    {"sampler3D", SamplerKind::sampler3D},
    {"samplerCube", SamplerKind::samplerCube},
    {"sampler2DShadow", SamplerKind::sampler2DShadow},
    {"samplerCubeShadow", SamplerKind::samplerCubeShadow},
    {"sampler2DArray", SamplerKind::sampler2DArray},
    {"sampler2DArrayShadow", SamplerKind::sampler2DArrayShadow},
    {"isampler2D", SamplerKind::isampler2D},
    {"isampler3D", SamplerKind::isampler3D},
    {"isamplerCube", SamplerKind::isamplerCube},
    {"isampler2DArray", SamplerKind::isampler2DArray},
    {"usampler2D", SamplerKind::usampler2D},
    {"usampler3D", SamplerKind::usampler3D},
    {"usamplerCube", SamplerKind::usamplerCube},
    {"usampler2DArray", SamplerKind::usampler2DArray},
}};

std::string_view basic_prefix(Basic b) {
  switch (b) {
    case Basic::bool_:
      return "b";
    case Basic::int_:
      return "i";
    case Basic::uint_:
      return "u";
    default:
      return "";
  }
}

std::string_view scalar_name(Basic b) {
  switch (b) {
    case Basic::void_:
      return "void";
    case Basic::bool_:
      return "bool";
    case Basic::int_:
      return "int";
    case Basic::uint_:
      return "uint";
    case Basic::float_:
      return "float";
    default:
      return "<error>";
  }
}

}  // namespace

bool Type::has_sampler() const {
  if (is_sampler()) return true;
  if (is_struct())
    for (const Field& f : structure->fields)
      if (f.type.has_sampler()) return true;
  return false;
}

bool Type::has_array() const {
  if (is_array()) return true;
  if (is_struct())
    for (const Field& f : structure->fields)
      if (f.type.has_array()) return true;
  return false;
}

int Type::components() const {
  switch (basic) {
    case Basic::bool_:
    case Basic::int_:
    case Basic::uint_:
    case Basic::float_:
      return rows * cols;
    case Basic::structure:
      return structure->slots;
    default:
      return 0;  // void, samplers (bound at compile time, no slots), error
  }
}

int Type::slots() const {
  return components() * (array > 0 ? array : 1);
}

Type Type::element() const {
  Type t = *this;
  if (array != 0) {
    t.array = 0;
  } else if (cols > 1) {
    t.cols = 1;
  } else {
    t.rows = 1;
  }
  return t;
}

int StructType::offset(std::size_t field) const {
  int at = 0;
  for (std::size_t i = 0; i < field; ++i) at += fields[i].type.slots();
  return at;
}

std::string type_name(const Type& t) {
  std::string name;
  if (t.basic == Basic::structure) {
    name = std::string(t.structure->name.empty() ? "struct" : t.structure->name);
  } else if (t.basic == Basic::sampler) {
    for (const SamplerName& s : kSamplers)
      if (s.kind == t.sampler) name = std::string(s.name);
  } else if (t.cols > 1) {
    name = std::string("mat") + std::to_string(t.cols);
    if (t.rows != t.cols) name += std::string("x") + std::to_string(t.rows);
  } else if (t.rows > 1) {
    name = std::string(basic_prefix(t.basic)) + std::string("vec") + std::to_string(t.rows);
  } else {
    name = std::string(scalar_name(t.basic));
  }
  if (t.array > 0) name += std::string("[") + std::to_string(t.array) + "]";
  if (t.array == Type::kUnsized) name += "[]";
  return name;
}

Type keyword_type(std::string_view w) {
  if (w == "void") return Type::of(Basic::void_);
  if (w == "bool") return Type::of(Basic::bool_);
  if (w == "int") return Type::of(Basic::int_);
  if (w == "uint") return Type::of(Basic::uint_);
  if (w == "float") return Type::of(Basic::float_);
  for (const SamplerName& s : kSamplers)
    if (w == s.name) {
      Type t = Type::of(Basic::sampler);
      t.sampler = s.kind;
      return t;
    }
  // vecN, ivecN, uvecN, bvecN
  const auto digit = [](char c) { return c >= '2' && c <= '4' ? c - '0' : 0; };
  if (w.size() == 4 && w.starts_with("vec") && digit(w[3])) return Type::of(Basic::float_, digit(w[3]));
  if (w.size() == 5 && w.substr(1, 3) == "vec" && digit(w[4])) {
    const Basic b = w[0] == 'i'   ? Basic::int_
                    : w[0] == 'u' ? Basic::uint_
                    : w[0] == 'b' ? Basic::bool_
                                  : Basic::error;
    if (b != Basic::error) return Type::of(b, digit(w[4]));
  }
  // matN, matNxM (N columns, M rows)
  if (w.size() == 4 && w.starts_with("mat") && digit(w[3]))
    return Type::of(Basic::float_, digit(w[3]), digit(w[3]));
  if (w.size() == 6 && w.starts_with("mat") && digit(w[3]) && w[4] == 'x' && digit(w[5]))
    return Type::of(Basic::float_, digit(w[5]), digit(w[3]));
  return Type::error();
}

}  // namespace raster::shader
