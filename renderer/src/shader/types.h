// Types of GLSL ES 3.00 (section 4.1): scalars, vectors, matrices (column-major, non-square too), samplers,
// structs and one-dimensional arrays of any of them. Every value a program computes is laid out as scalar
// slots: a vector's components in order, a matrix's columns in order, a struct's fields in order, an
// array's elements in order; a slot is 32 bits (bool: 0 or all ones).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "shader/token.h"

namespace raster::shader {

enum class Basic : std::uint8_t { error, void_, bool_, int_, uint_, float_, sampler, structure };

/// The sampler types; only sampler2D can be bound to an image (ShaderToy's channels), the rest are known so
/// that a program naming them gets the same verdict as from any GLSL compiler.
enum class SamplerKind : std::uint8_t {
  none,
  sampler2D,
  sampler3D,
  samplerCube,
  sampler2DShadow,
  samplerCubeShadow,
  sampler2DArray,
  sampler2DArrayShadow,
  isampler2D,
  isampler3D,
  isamplerCube,
  isampler2DArray,
  usampler2D,
  usampler3D,
  usamplerCube,
  usampler2DArray,
};

struct StructType;

struct Type {
  Basic basic = Basic::error;
  SamplerKind sampler = SamplerKind::none;
  std::uint8_t cols = 1;  ///< matrices: columns (2..4); everything else 1
  std::uint8_t rows = 1;  ///< vectors: components (2..4); matrices: rows; scalars 1
  std::int32_t array =
      0;  ///< elements of an array (> 0); 0, not an array; kUnsized, size from an initializer
  const StructType* structure = nullptr;  ///< Basic::structure: which

  static constexpr std::int32_t kUnsized = -1;

  static Type of(Basic basic, int rows = 1, int cols = 1) {
    Type t;
    t.basic = basic, t.rows = static_cast<std::uint8_t>(rows), t.cols = static_cast<std::uint8_t>(cols);
    return t;
  }
  static Type error() { return {}; }

  bool is_error() const { return basic == Basic::error; }
  bool is_void() const { return basic == Basic::void_ && array == 0; }
  bool is_array() const { return array != 0; }
  bool is_numeric() const { return basic == Basic::int_ || basic == Basic::uint_ || basic == Basic::float_; }
  bool is_integer() const { return basic == Basic::int_ || basic == Basic::uint_; }
  bool is_arithmetic_or_bool() const { return is_numeric() || basic == Basic::bool_; }
  /// A scalar, vector or matrix of bool, int, uint or float (not an array).
  bool is_plain() const { return !is_array() && is_arithmetic_or_bool(); }
  bool is_scalar() const { return is_plain() && rows == 1 && cols == 1; }
  bool is_vector() const { return is_plain() && rows > 1 && cols == 1; }
  bool is_matrix() const { return is_plain() && cols > 1; }
  bool is_sampler() const { return basic == Basic::sampler; }
  bool is_struct() const { return basic == Basic::structure; }
  /// Holds a sampler anywhere (a sampler, an array of them, a struct with one).
  bool has_sampler() const;
  /// Holds an array anywhere (an array, or a struct with one): such values have no == in GLSL ES 3.00.
  bool has_array() const;

  /// Components of one element: rows x cols for plain types, the slots of a struct, 0 for void.
  int components() const;
  /// Scalar slots of the whole value, arrays included.
  int slots() const;
  /// The type of one element of an array, one column of a matrix, one component of a vector.
  Type element() const;
  Type scalar() const { return Type::of(basic); }
  Type with_array(std::int32_t elements) const {
    Type t = *this;
    t.array = elements;
    return t;
  }

  friend bool operator==(const Type& a, const Type& b) {
    return a.basic == b.basic && a.sampler == b.sampler && a.cols == b.cols && a.rows == b.rows &&
           a.array == b.array && a.structure == b.structure;
  }
};

struct Field {
  std::string_view name;
  Type type;
  SourcePos pos;
};

struct StructType {
  std::string_view name;
  std::vector<Field> fields;
  SourcePos pos;
  int slots = 0;  ///< of one value, computed when the struct is declared
  /// A uniform block's members (its instance is a value of this type): no constructor, no ==, indexed by
  /// constants only, and its name is no type.
  bool block = false;
  /// Slot offset of field i within the struct.
  int offset(std::size_t field) const;
};

/// The GLSL spelling of a type, for messages: "vec3", "mat2x3", "float[4]", "S".
std::string type_name(const Type& t);

/// The type a keyword names (float, vec3, mat2x4, sampler2D...); Basic::error if it names none.
Type keyword_type(std::string_view word);

}  // namespace raster::shader
